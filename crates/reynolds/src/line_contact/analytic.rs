//! Analytic rigid solutions of the roller–plate line contact, seed 002 §3.1–3.2 and §3.6,
//! SPEC §8.4 (with the corrections of flags F-63–F-66).
//!
//! Dimensionless variables (3.12): x̃ = (x − x_m)/√(h_m R), H = 1 + x̃²/2, q = P/P₀,
//! P₀ = 6μVR^{1/2}/h_m^{3/2}, ν = (V_y/V)√(R/h_m); V = sum of the surface speeds, V_y = dh_m/dt.
//! Flooded inlet (a = −∞), Reynolds exit at x̃ = c: q(c) = q′(c) = 0.

use crate::error::{Result, ReynoldsError};
use crate::roots::brent;
use std::f64::consts::{FRAC_PI_2, SQRT_2};

/// Seed constant W₀′ = 0.401 (fitted from its figure; exact 0.4079, flag F-66).
pub const SEED_W0: f64 = 0.401;
/// Seed constant W₁′ = 1.125 (exact ≈ 1.09, flag F-66).
pub const SEED_W1: f64 = 1.125;

/// q₀(x, c) of (3.15) (verified in SPEC §8.4).
pub fn q0(x: f64, c: f64) -> f64 {
    let k = 1.0 - 1.5 * c * c;
    let t = 2.0 + x * x;
    0.5 * (((x / SQRT_2).atan() + FRAC_PI_2) * SQRT_2 / 4.0 * k - (2.0 + c * c) * x / (t * t)
        + x / t * k * 0.5)
}

/// q₁(x, c) = ∫_{−∞}^{x} (c − x′)/H³ dx′ (derived form, flag F-63: the seed's printed q₁ does not
/// satisfy (3.14)).
pub fn q1(x: f64, c: f64) -> f64 {
    let t = 2.0 + x * x;
    2.0 / (t * t)
        + c * x / (t * t)
        + 0.75 * c * x / t
        + 3.0 * c / (4.0 * SQRT_2) * ((x / SQRT_2).atan() + FRAC_PI_2)
}

/// q(x) = q₀ − 2ν q₁ for exit c.
pub fn q(x: f64, c: f64, nu: f64) -> f64 {
    q0(x, c) - 2.0 * nu * q1(x, c)
}

/// Exit parameter c(ν): root of q(c, c, ν) = 0 (3.66); c(0) = 0.671935 (flag F-64: the seed
/// prints 0.67155).
pub fn exit_parameter(nu: f64) -> Result<f64> {
    let f = |c: f64| Ok(q(c, c, nu));
    let (a, b) = (1e-9, 20.0);
    let (fa, fb) = (q(a, a, nu), q(b, b, nu));
    if fa * fb > 0.0 {
        return Err(ReynoldsError::NoSolution(format!(
            "no Reynolds exit for ν = {nu} (squeeze too strong for a flooded inlet)"
        )));
    }
    Ok(brent(f, a, b, fa, fb, 1e-15, 0.0, 200)?.0)
}

/// Dimensionless pressure maximum q_max(ν) at x̃ = −c − 4ν (where dq/dx̃ = 0).
pub fn q_max(nu: f64) -> Result<f64> {
    let c = exit_parameter(nu)?;
    Ok(q(-c - 4.0 * nu, c, nu))
}

/// ∫_{−∞}^{c} f(x) dx by the substitution x = c − s/(1 − s) and 64-point composite Gauss.
fn integrate_to(c: f64, f: impl Fn(f64) -> f64) -> f64 {
    crate::compliance::gauss_panels(
        |s| {
            if s >= 1.0 {
                return 0.0;
            }
            let x = c - s / (1.0 - s);
            f(x) / ((1.0 - s) * (1.0 - s))
        },
        0.0,
        1.0,
        256,
    )
}

/// Dimensionless load W′(ν) = ∫ q dx̃ (3.16); W′(0) = 0.40791.
pub fn load(nu: f64) -> Result<f64> {
    let c = exit_parameter(nu)?;
    // ∫ q dx = −∫ x q′ dx (q(c) = 0, x q → 0 at −∞), smoother for the quadrature
    Ok(integrate_to(c, |x| {
        let h = 1.0 + 0.5 * x * x;
        -x * (0.5 * (x * x - c * c) + 2.0 * nu * (x - c)) / (h * h * h)
    }))
}

/// W₀′ = W′(0) and W₁′ = −dW′/dν at 0 (central difference, |Δν| = 10⁻⁴); exact ≈ 0.4079, 1.09
/// (flag F-66: the seed fitted 0.401 and 1.125).
pub fn load_coefficients() -> Result<(f64, f64)> {
    let d = 1e-4;
    let w0 = load(0.0)?;
    let w1 = -(load(d)? - load(-d)?) / (2.0 * d);
    Ok((w0, w1))
}

/// Pressure scale P₀ = 6μVR^{1/2}/h^{3/2}, Pa.
pub fn pressure_scale(mu: f64, v: f64, r: f64, h: f64) -> f64 {
    6.0 * mu * v * r.sqrt() / h.powf(1.5)
}

/// Kapitsa formulas (ν = 0), corrected reading (flag F-65): P_max = 1.52 μV√(R/(2h³)) and
/// W = 2.45 μVR/h per unit length. Returns (P_max, W).
pub fn kapitsa(mu: f64, v: f64, r: f64, h: f64) -> (f64, f64) {
    (
        1.52 * mu * v * (r / (2.0 * h * h * h)).sqrt(),
        2.45 * mu * v * r / h,
    )
}

/// Rigid piezoviscous (Barus) maximum pressure, seed (3.61)–(3.65): q = −ln(1 − α̃q₀)/α̃ with
/// α̃ = αP₀; errors ("no solution", Table 3.5) when α̃·q₀,max ≥ 1. Returns P_max in Pa.
pub fn piezoviscous_max_pressure(mu0: f64, alpha: f64, v: f64, r: f64, h: f64) -> Result<f64> {
    let p0 = pressure_scale(mu0, v, r, h);
    let qm = q_max(0.0)?;
    let at = alpha * p0;
    if at * qm >= 1.0 {
        return Err(ReynoldsError::NoSolution(format!(
            "rigid piezoviscous contact: α̃·q₀,max = {:.3} ≥ 1 (seed 002 (3.65), Table 3.5)",
            at * qm
        )));
    }
    Ok(if at == 0.0 {
        qm * p0
    } else {
        -(1.0 - at * qm).ln() / at * p0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_values_of_spec() {
        let c = exit_parameter(0.0).unwrap();
        assert!((c - 0.671935).abs() < 2e-6, "{c}");
        assert!((q_max(0.0).unwrap() - 0.17925).abs() < 2e-5);
        let (w0, w1) = load_coefficients().unwrap();
        assert!((w0 - 0.40791).abs() < 2e-5, "{w0}");
        assert!((w1 - 1.091).abs() < 5e-3, "{w1}");
        // SPEC §8.4 table for ν = −0.1 … 0.1
        for (nu, cc, qm, w) in [
            (-0.1, 0.9550, 0.2379, 0.5293),
            (-0.05, 0.8106, 0.2072, 0.4656),
            (0.05, 0.5391, 0.1541, 0.3564),
            (0.1, 0.4118, 0.1319, 0.3108),
        ] {
            assert!((exit_parameter(nu).unwrap() - cc).abs() < 1e-4);
            assert!((q_max(nu).unwrap() - qm).abs() < 1e-4);
            assert!((load(nu).unwrap() - w).abs() < 1e-4);
        }
        // dq/dx from q0 − 2νq1 matches the first integral (3.14)
        let (nu, c) = (0.05, exit_parameter(0.05).unwrap());
        for x in [-3.0, -0.7, 0.2] {
            let d = (q(x + 1e-6, c, nu) - q(x - 1e-6, c, nu)) / 2e-6;
            let h = 1.0 + 0.5 * x * x;
            let want = (0.5 * (x * x - c * c) + 2.0 * nu * (x - c)) / (h * h * h);
            assert!((d - want).abs() < 1e-7);
        }
    }
}
