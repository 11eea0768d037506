//! Property correlations for oils without measured data (each result is ESTIMATED and says so
//! in the oil's provenance): pressure–viscosity coefficient from the viscosity (Wooster),
//! thermal conductivity from the density (Cragoe), density from its 15 °C value.

use crate::lubricant::TempLaw;

/// Barus pressure–viscosity coefficient ᾱ = (0.6 + 0.965 log₁₀ η0) × 10⁻⁸ 1/Pa with η0 the
/// atmospheric dynamic viscosity in centipoise (mPa·s) — Wooster's correlation for mineral oils,
/// as given by Stachowiak & Batchelor, *Engineering Tribology* (4th ed., 2014), §2.6
/// "Viscosity–pressure relationship". Argument in Pa·s; result in 1/Pa.
pub fn wooster_pressure_viscosity(eta0_pa_s: f64) -> f64 {
    (0.6 + 0.965 * (eta0_pa_s * 1e3).log10()) * 1e-8
}

/// Thermal conductivity of a petroleum oil, K = (0.1172 / s15)(1 − 0.00054 θ) W/(m·K) with θ in
/// °C and s15 the specific gravity at 15 °C — Cragoe, *Miscellaneous Properties of Petroleum
/// Products*, US Bureau of Standards Misc. Publ. 97 (1929) (0.0677/s (1 − 0.0003(t − 32))
/// Btu/(h·ft·°F), t in °F, converted). Returned as a [`TempLaw::PolynomialCelsius`].
pub fn cragoe_thermal_conductivity(density_15c_kg_m3: f64) -> TempLaw {
    let k0 = 0.1172 / (density_15c_kg_m3 / WATER_DENSITY_15C);
    TempLaw::PolynomialCelsius {
        coeffs: vec![k0, -0.00054 * k0],
    }
}

/// Density of water at 15 °C, kg/m³ (the reference of the specific gravity s15).
const WATER_DENSITY_15C: f64 = 999.1;

/// Volumetric thermal expansion coefficient of lubricating oils near 15 °C, 1/K — ESTIMATED
/// class value (≈ 0.57 kg/m³ per K for an 880 kg/m³ oil, the slope the example oil files use);
/// one coefficient for every oil, where ASTM D1250 / API MPMS 11.1 tabulate it against density.
pub const OIL_THERMAL_EXPANSION_PER_K: f64 = 6.5e-4;

/// ρ(θ) = ρ15 [1 − γ (θ − 15)] with γ = [`OIL_THERMAL_EXPANSION_PER_K`], as a
/// [`TempLaw::PolynomialCelsius`].
pub fn density_from_15c(density_15c_kg_m3: f64) -> TempLaw {
    let slope = -density_15c_kg_m3 * OIL_THERMAL_EXPANSION_PER_K;
    TempLaw::PolynomialCelsius {
        coeffs: vec![density_15c_kg_m3 - 15.0 * slope, slope],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lubricant::CELSIUS_ZERO;

    #[test]
    fn correlations_give_their_defining_values() {
        // η0 = 100 cP → 0.6 + 0.965·2 = 2.53 × 10⁻⁸ 1/Pa
        assert!((wooster_pressure_viscosity(0.1) - 2.53e-8).abs() < 1e-20);
        let rho = density_from_15c(880.0);
        assert!((rho.eval(15.0 + CELSIUS_ZERO) - 880.0).abs() < 1e-9);
        assert!((rho.eval(115.0 + CELSIUS_ZERO) - 880.0 * (1.0 - 0.065)).abs() < 1e-9);
        let k = cragoe_thermal_conductivity(999.1);
        assert!((k.eval(CELSIUS_ZERO) - 0.1172).abs() < 1e-12);
        assert!((k.eval(100.0 + CELSIUS_ZERO) - 0.1172 * 0.946).abs() < 1e-12);
    }
}
