//! Mean-stress corrections (theory §10.5, flag F-55): the fully reversed amplitude σ_ar that
//! does the damage of a cycle of amplitude σ_a and mean σ_m, to be read on the R = −1 S–N curve.
//!
//! Compressive means (σ_m < 0) under Goodman and Gerber are taken as zero: σ_ar = σ_a. This is
//! the common conservative practice (the benefit of a compressive mean is not counted, and
//! Gerber's parabola would otherwise penalise it like a tensile one).

use serde::{Deserialize, Serialize};

/// Which correction maps (σ_a, σ_m) to σ_ar.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MeanStressCorrection {
    /// σ_ar = σ_a (default: the seed states no correction, F-55)
    #[default]
    None,
    /// σ_ar = σ_a / (1 − σ_m/σ_u)
    Goodman,
    /// σ_ar = σ_a / (1 − (σ_m/σ_u)²)
    Gerber,
    /// Smith–Watson–Topper σ_ar = √(σ_max σ_a), σ_max = σ_m + σ_a; no damage when σ_max ≤ 0
    SmithWatsonTopper,
}

impl MeanStressCorrection {
    /// The equivalent fully reversed amplitude σ_ar [Pa] of a cycle of amplitude `amplitude` and
    /// mean `mean` [Pa]; `ultimate_strength` σ_u [Pa] enters Goodman and Gerber. 0 means no
    /// damage (SWT with σ_max ≤ 0); a tensile mean at or above σ_u gives ∞ (static failure).
    /// Dowling N. E., *Mechanical Behavior of Materials*, 4th ed., 2013, §9.7 (SWT: eq. 9.18).
    pub fn equivalent_amplitude(self, amplitude: f64, mean: f64, ultimate_strength: f64) -> f64 {
        let tensile_ratio = mean.max(0.0) / ultimate_strength;
        let divided_by = |denominator: f64| {
            if denominator > 0.0 {
                amplitude / denominator
            } else {
                f64::INFINITY
            }
        };
        match self {
            Self::None => amplitude,
            Self::Goodman => divided_by(1.0 - tensile_ratio),
            Self::Gerber => divided_by(1.0 - tensile_ratio * tensile_ratio),
            Self::SmithWatsonTopper => {
                let peak = mean + amplitude;
                if peak > 0.0 {
                    (peak * amplitude).sqrt()
                } else {
                    0.0
                }
            }
        }
    }
}
