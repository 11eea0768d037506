//! Analytic limits of the journal bearing (standard forms, not in the seeds), for validation:
//! the infinitely long bearing (Sommerfeld 1904; Gümbel half-Sommerfeld) and the short bearing
//! (Dubois–Ocvirk 1953). Journal speed ω, bush fixed, load components along (radial) and
//! perpendicular to (tangential) the line of centres, N.

/// Long bearing, full Sommerfeld: W = 12πμωR³Lε/(c²(2+ε²)√(1−ε²)), perpendicular to the line of
/// centres (attitude 90°).
pub fn long_full_sommerfeld(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> f64 {
    12.0 * std::f64::consts::PI * mu * omega * r.powi(3) * l * eps
        / (c * c * (2.0 + eps * eps) * (1.0 - eps * eps).sqrt())
}

/// Long bearing, half Sommerfeld (Gümbel): (radial, tangential) =
/// (12μωR³Lε²/(c²(2+ε²)(1−ε²)), 6πμωR³Lε/(c²(2+ε²)√(1−ε²))).
pub fn long_half_sommerfeld(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> (f64, f64) {
    let k = mu * omega * r.powi(3) * l / (c * c * (2.0 + eps * eps));
    (
        12.0 * k * eps * eps / (1.0 - eps * eps),
        6.0 * std::f64::consts::PI * k * eps / (1.0 - eps * eps).sqrt(),
    )
}

/// Short bearing (Ocvirk, half Sommerfeld): (radial, tangential) =
/// (μωRL³ε²/(c²(1−ε²)²), πμωRL³ε/(4c²(1−ε²)^{3/2})); attitude tan ψ = π√(1−ε²)/(4ε).
pub fn short_ocvirk(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> (f64, f64) {
    let k = mu * omega * r * l.powi(3) / (c * c);
    let q = 1.0 - eps * eps;
    (
        k * eps * eps / (q * q),
        std::f64::consts::PI * k * eps / (4.0 * q.powf(1.5)),
    )
}

/// Petroff friction torque of a concentric full film, 2πμωR³L/c, N·m: the
/// [`crate::cage_land::couette_land_torque`] at ε = 0.
pub fn petroff_torque(mu: f64, omega: f64, r: f64, l: f64, c: f64) -> f64 {
    crate::cage_land::couette_land_torque(mu, omega, r, l, c, 0.0)
}
