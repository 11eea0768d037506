//! Elastic, surface and fatigue data of a bearing part's material.

use serde::{Deserialize, Serialize};

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
    /// Strength under cyclic stress, for cage fatigue (theory §10.5); `None` when not known.
    pub fatigue: Option<FatigueStrength>,
}

/// A material's fully reversed S–N curve and ultimate strength, with where they come from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FatigueStrength {
    /// Ultimate tensile strength σ_u [Pa] (Goodman and Gerber mean-stress corrections).
    pub ultimate_strength: f64,
    /// The base S–N curve at R = −1: `(N, σ_a [Pa])`, N increasing and σ_a decreasing; the last
    /// point is the knee.
    pub sn_curve: Vec<(f64, f64)>,
    /// The source of the curve and of σ_u; an estimate says `ESTIMATED` and its rule.
    pub source: String,
}

/// 1 kgf/mm² in Pa (standard gravity 9.80665 m/s², exact).
pub const PA_PER_KGF_PER_MM2: f64 = 9.806_65e6;

/// Meyer over Vickers hardness of the same indentation, seed 000 §3.1.1.5 (geometrically
/// 1/sin 68° = 1.0785: Meyer divides the force by the projected area d²/2 of the 136° pyramid,
/// Vickers by its surface area).
pub const MEYER_PER_VICKERS: f64 = 1.0787;

/// Meyer hardness [Pa] of a Vickers number HV (kgf/mm²).
pub fn meyer_from_vickers(vickers: f64) -> f64 {
    MEYER_PER_VICKERS * vickers * PA_PER_KGF_PER_MM2
}

/// Vickers number HV (kgf/mm²) of a Meyer hardness [Pa], the inverse of [`meyer_from_vickers`].
pub fn vickers_from_meyer(meyer_pa: f64) -> f64 {
    meyer_pa / (MEYER_PER_VICKERS * PA_PER_KGF_PER_MM2)
}

/// The first point of an S–N table `(N, σ_a)` (by index) that breaks its rules — finite and
/// positive values, N increasing and σ_a decreasing from point to point — and why.
pub fn first_invalid_sn_point(points: &[(f64, f64)]) -> Option<(usize, String)> {
    let usable = |&(n, s): &(f64, f64)| n.is_finite() && s.is_finite() && n > 0.0 && s > 0.0;
    if let Some(i) = points.iter().position(|p| !usable(p)) {
        let (n, s) = points[i];
        return Some((
            i,
            format!("N = {n} and σ_a = {s} Pa must be finite and positive"),
        ));
    }
    let i = (1..points.len())
        .find(|&i| points[i].0 <= points[i - 1].0 || points[i].1 >= points[i - 1].1)?;
    Some((
        i,
        "N must increase and σ_a decrease from point to point".into(),
    ))
}

impl Material {
    /// `(1 − ν²)/E`, the compliance factor of one body.
    pub fn compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}
