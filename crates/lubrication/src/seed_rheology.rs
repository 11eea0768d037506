//! The seeds' rheology of their oils (shear modulus Γ, Eyring stress τ0), used by the seed oils
//! themselves and, as the typical values of their class, by the database grades.

use crate::lubricant::TempLaw;

/// Γ of NVI 65 (seed 000 §2.3), Pa.
pub(crate) const NVI65_SHEAR_MODULUS_PA: f64 = 3e9;
/// Γ of VNII NP 50-1-4u (seed 000 §3.1.2), Pa.
pub(crate) const VNII_SHEAR_MODULUS_PA: f64 = 5e7;
/// τ0 of VNII NP 50-1-4u (seed 000 §3.1.2), Pa.
pub(crate) const VNII_EYRING_STRESS_PA: f64 = 3e5;
/// Γ(θ) of PAO1 (seed 000 §2.2): 7.444 + 0.0163θ − 0.002083θ² + 0.0000121θ³ GPa, θ in °C.
pub(crate) fn pao1_shear_modulus() -> TempLaw {
    TempLaw::PolynomialCelsius {
        coeffs: vec![7.444e9, 0.0163e9, -0.002083e9, 0.0000121e9],
    }
}

/// τ0(θ) of PAO1 (seed 000 §2.2): 8.46 − 0.054θ MPa, θ in °C.
pub(crate) fn pao1_eyring_stress() -> TempLaw {
    TempLaw::PolynomialCelsius {
        coeffs: vec![8.46e6, -0.054e6],
    }
}
