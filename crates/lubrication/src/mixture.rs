//! Air–oil mixture properties (SPEC §4.10 seed 001; §3.6 seed 000).

/// seed 001 density of the air–oil medium in the bearing cavity:
/// γ_ср = γ_см O² / (0.4 + 0.6 O), O = volume fraction of oil (0…1), γ_см = oil density (kg/m³).
/// Use with the mixture temperature t_вм = (t_в + t_н)/2 ([`mixture_temperature`]).
#[inline]
pub fn air_oil_density_seed001(oil_density: f64, oil_volume_fraction: f64) -> f64 {
    let o = oil_volume_fraction.clamp(0.0, 1.0);
    oil_density * o * o / (0.4 + 0.6 * o)
}

/// seed 001 mixture temperature: mean of the inner- and outer-ring temperatures.
#[inline]
pub fn mixture_temperature(t_inner: f64, t_outer: f64) -> f64 {
    0.5 * (t_inner + t_outer)
}

/// seed 000 §3.6 linear mixture density ρ = ρ₁χ + ρ₂(1 − χ) (index 1 = oil, 2 = air).
#[inline]
pub fn mixture_density_linear(rho_oil: f64, rho_air: f64, chi: f64) -> f64 {
    rho_oil * chi + rho_air * (1.0 - chi)
}

/// seed 000 §3.6 mixture viscosity μ = μ₁ / [(μ₁/μ₂)(1 − χ) + χ].
#[inline]
pub fn mixture_viscosity(mu_oil: f64, mu_air: f64, chi: f64) -> f64 {
    mu_oil / ((mu_oil / mu_air) * (1.0 - chi) + chi)
}

/// Oil volume fraction of the bearing cavity used when the model gives none: the oil volume
/// concentration 0.05 of the seed 000 CFD of 2002834 (SPEC §3.6).
pub const SEED000_OIL_VOLUME_FRACTION: f64 = 0.05;

/// Drag factor k = ½ ρ_eff C_D D l of a roller of diameter D and length l moving broadside
/// through the air–oil mixture, N·s²/m² (kg/m): the drag force is F = −k |v| v with v the roller
/// centre's velocity across its axis relative to the mixture (form drag of a cylinder in cross
/// flow; Harris & Kotzalas, Advanced Concepts of Bearing Technology, 5th ed. 2007, §3.7 "fluid
/// drag" on the rolling elements, F = ½ ρ_eff C_D A v² with the projected area A = D l; Gupta,
/// Advanced Dynamics of Rolling Elements, 1984, the same drag in ADORE). ρ_eff is the mixture
/// density ([`air_oil_density_seed001`]), C_D ≈ 1.0–1.2 for 10³ < Re < 2·10⁵ (Hoerner,
/// Fluid-Dynamic Drag, 1965, ch. 3).
#[inline]
pub fn roller_drag_factor(density: f64, drag_coefficient: f64, diameter: f64, length: f64) -> f64 {
    0.5 * density * drag_coefficient * diameter * length
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn limits() {
        assert_eq!(air_oil_density_seed001(850.0, 0.0), 0.0);
        assert!((air_oil_density_seed001(850.0, 1.0) - 850.0).abs() < 1e-12);
        // hand value: O = 0.05 → 850·0.0025/0.43 = 4.9419 kg/m³
        assert!((air_oil_density_seed001(850.0, 0.05) - 4.941_860_465).abs() < 1e-8);
        assert!((mixture_viscosity(0.01, 1.8e-5, 1.0) - 0.01).abs() < 1e-15);
        assert!((mixture_viscosity(0.01, 1.8e-5, 0.0) - 1.8e-5).abs() < 1e-15);
        assert!((mixture_density_linear(850.0, 1.2, 0.05) - 43.64).abs() < 1e-9);
        // hand value: ½ · 4.9419 · 1.2 · 0.015 · 0.011 = 4.8924e-4 kg/m
        let k = roller_drag_factor(4.941_860_465, 1.2, 0.015, 0.011);
        assert!((k - 4.892_441_86e-4).abs() < 1e-12);
    }
}
