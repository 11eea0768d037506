//! Elastic and surface material data of a bearing part.

/// Material of a ring, roller or cage (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    pub name: String,
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio ν [-].
    pub poisson_ratio: f64,
    /// Density ρ [kg/m³]. Bearing steel 7830 kg/m³ (SPEC F-25).
    pub density: f64,
    /// Meyer hardness H [Pa], for wear (SPEC §6.1); optional.
    pub meyer_hardness: Option<f64>,
}

impl Material {
    /// Through-hardened bearing steel (AISI 52100 / ШХ15): E = 208 GPa, ν = 0.3,
    /// ρ = 7830 kg/m³ (SPEC F-25), Meyer hardness 7.6 GPa (≈ 62 HRC, SPEC §6.1 "777…895").
    pub fn bearing_steel() -> Self {
        Self {
            name: "bearing-steel".into(),
            youngs_modulus: 208e9,
            poisson_ratio: 0.3,
            density: 7830.0,
            meyer_hardness: Some(7.6e9),
        }
    }

    /// `(1 − ν²)/E`, the compliance factor of one body.
    pub fn compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}
