//! Viscosity models (SPEC §4.1): Walther/ASTM D341 two-point fit, Barus and Roelands
//! pressure–viscosity, Reynolds–Filonov exponential slope.

use crate::lubricant::TempLaw;
use rolldyn_numerics::fastmath;

/// Walther / ASTM D341 constants through two kinematic viscosities (standard form, not in the
/// seeds; SPEC §4.2.5): log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T, ν in mm²/s, T in K.
///
/// Arguments are SI: temperatures in K, viscosities in m²/s. Returns a [`TempLaw::Walther`].
/// Example: VG 220 (220 mm²/s at 40 °C, 19 mm²/s at 100 °C) → A = 8.8222, B = 3.3867.
pub fn walther_from_two_points(t1_k: f64, nu1_m2_s: f64, t2_k: f64, nu2_m2_s: f64) -> TempLaw {
    let w = |nu: f64| (nu * 1e6 + 0.7).log10().log10();
    let (w1, w2) = (w(nu1_m2_s), w(nu2_m2_s));
    let (l1, l2) = (t1_k.log10(), t2_k.log10());
    let b = (w1 - w2) / (l2 - l1);
    let a = w1 + b * l1;
    TempLaw::Walther { a, b }
}

/// Reynolds–Filonov viscosity–temperature slope Ω0 = ln(μ1/μ0)/(T0 − T1) ((002-3.6)), 1/K.
pub fn reynolds_slope(t0_k: f64, mu0: f64, t1_k: f64, mu1: f64) -> f64 {
    (mu1 / mu0).ln() / (t0_k - t1_k)
}

/// Pressure dependence of viscosity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PiezoViscosity {
    /// Barus η = η0 exp(ᾱ p) ((002-3.8), (1.5)). Default (the seeds' form).
    #[default]
    Barus,
    /// Roelands η = η0 exp{(ln η0 + 9.67)[(1 + p/1.96×10⁸)^Z − 1]} (standard form, not in the
    /// seeds); Z from the oil or from ᾱ = (ln η0 + 9.67) Z / 1.96×10⁸ ([`roelands`]).
    Roelands,
}

/// Barus viscosity η0·exp(ᾱp).
#[inline]
pub fn barus(eta0: f64, alpha: f64, p: f64) -> f64 {
    eta0 * fastmath::exp(alpha * p)
}

/// Roelands reference pressure p_r = 1.96×10⁸ Pa.
pub const ROELANDS_P_REF: f64 = 1.96e8;

/// Roelands' −ln η∞ = 9.67 (η∞ = 6.31×10⁻⁵ Pa·s).
const ROELANDS_LN_ETA_INF: f64 = 9.67;

/// Roelands index Z matching the initial slope ᾱ: Z = ᾱ p_r / (ln η0 + 9.67) (the often
/// printed 5.1×10⁻⁹ is 1/p_r rounded).
#[inline]
pub fn roelands_z_from_alpha(eta0: f64, alpha: f64) -> f64 {
    alpha * ROELANDS_P_REF / (eta0.ln() + ROELANDS_LN_ETA_INF)
}

/// Roelands viscosity η = η0 exp{(ln η0 + 9.67)[(1 + p/p_r)^Z − 1]} (η0 in Pa·s, p in Pa).
#[inline]
pub fn roelands(eta0: f64, z: f64, p: f64) -> f64 {
    let s = (1.0 + p / ROELANDS_P_REF).powf(z) - 1.0;
    eta0 * ((eta0.ln() + ROELANDS_LN_ETA_INF) * s).exp()
}

/// ∂ ln η/∂p of [`roelands`] = (ln η0 + 9.67) Z (1 + p/p_r)^(Z−1) / p_r, 1/Pa.
#[inline]
pub fn roelands_dln_dp(eta0: f64, z: f64, p: f64) -> f64 {
    (eta0.ln() + ROELANDS_LN_ETA_INF) * z * (1.0 + p / ROELANDS_P_REF).powf(z - 1.0)
        / ROELANDS_P_REF
}

/// Viscosity at pressure `p` with the selected law (`z` = Roelands index, used only for Roelands).
#[inline]
pub fn viscosity_at_pressure(
    model: PiezoViscosity,
    eta0: f64,
    alpha: f64,
    z: Option<f64>,
    p: f64,
) -> f64 {
    match model {
        PiezoViscosity::Barus => barus(eta0, alpha, p),
        PiezoViscosity::Roelands => {
            let z = z.unwrap_or_else(|| roelands_z_from_alpha(eta0, alpha));
            roelands(eta0, z, p)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn walther_vg220_matches_spec() {
        let law = walther_from_two_points(313.15, 220e-6, 373.15, 19e-6);
        let TempLaw::Walther { a, b } = law else {
            panic!()
        };
        // SPEC §4.2.5 (derived): A = 8.8222, B = 3.3867 (4 decimals printed → 1e-3 tolerance)
        assert!((a - 8.8222).abs() < 1e-3, "{a}");
        assert!((b - 3.3867).abs() < 1e-3, "{b}");
        // passes through both points exactly
        assert!((law.eval(313.15) / 220e-6 - 1.0).abs() < 1e-10);
        assert!((law.eval(373.15) / 19e-6 - 1.0).abs() < 1e-10);
        // SPEC: ν(60 °C) ≈ 78.8 mm²/s (3 significant digits printed)
        assert!((law.eval(333.15) * 1e6 - 78.8).abs() < 0.1);
    }

    #[test]
    fn roelands_initial_slope_equals_alpha() {
        let (eta0, alpha) = (0.05, 2e-8);
        let z = roelands_z_from_alpha(eta0, alpha);
        let p = 1e5;
        let slope = (roelands(eta0, z, p) / eta0).ln() / p;
        assert!((slope / alpha - 1.0).abs() < 1e-3);
        assert!((roelands_dln_dp(eta0, z, 0.0) / alpha - 1.0).abs() < 1e-14);
        assert!(roelands(eta0, z, 1e9) < barus(eta0, alpha, 1e9));
    }
}
