//! Sjövall's radial load integral of a row of rolling elements (Harris & Kotzalas, Essential
//! Concepts of Bearing Technology, 5th ed., ch. 7; Sjövall 1933).

/// `J_r(ε) = (1/2π) ∫ [1 − (1 − cos ψ)/(2ε)]^n cos ψ dψ` over the load zone
/// `|ψ| ≤ ψ_l = acos(1 − 2ε)` (ε ≤ 1), so that `F_r = Z Q_max J_r(ε) cos α`; `n` = 10/9 or 1.1
/// for line contact, 1.5 for point contact. Simpson's rule on 4000 intervals.
pub fn radial_load_integral(epsilon: f64, exponent: f64) -> f64 {
    use std::f64::consts::PI;
    let psi_l = (1.0 - 2.0 * epsilon).clamp(-1.0, 1.0).acos();
    let intervals = 4000;
    let h = 2.0 * psi_l / intervals as f64;
    let f = |p: f64| {
        let x = 1.0 - (1.0 - p.cos()) / (2.0 * epsilon);
        if x > 0.0 {
            x.powf(exponent) * p.cos()
        } else {
            0.0
        }
    };
    let mut s = f(-psi_l) + f(psi_l);
    for k in 1..intervals {
        let w = if k % 2 == 1 { 4.0 } else { 2.0 };
        s += w * f(-psi_l + k as f64 * h);
    }
    s * h / 3.0 / (2.0 * PI)
}
