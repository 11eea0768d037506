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
    }
}
