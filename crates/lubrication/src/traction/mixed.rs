//! Mixed friction by the film parameter, seed 000 (1.3), SPEC §4.4.

use crate::regime::FrictionRegime;

/// Λ_bd, Λ_hd of (1.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MixedLimits {
    /// Λ_bd
    pub lambda_bd: f64,
    /// Λ_hd
    pub lambda_hd: f64,
}

impl MixedLimits {
    /// literature recommendation quoted by seed 000 §1: 0.01 / 1.5
    pub const LITERATURE: MixedLimits = MixedLimits {
        lambda_bd: 0.01,
        lambda_hd: 1.5,
    };
    /// NVI 65 (seed 000 §2.3): 1.35 / 3.05
    pub const NVI65: MixedLimits = MixedLimits {
        lambda_bd: 1.35,
        lambda_hd: 3.05,
    };
    /// VNII NP 50-1-4u (seed 000 §3.1.2): 0.2 / 1.5
    pub const VNII_NP_50_1_4U: MixedLimits = MixedLimits {
        lambda_bd: 0.2,
        lambda_hd: 1.5,
    };

    /// The blend weight ((Λ − Λ_hd)/(Λ_bd − Λ_hd))⁶ of (1.3) in the mixed regime. It depends on
    /// the contact's Λ only, so a batch computes it once per contact.
    #[inline(always)]
    pub fn weight(&self, lambda: f64) -> f64 {
        let x = (lambda - self.lambda_hd) / (self.lambda_bd - self.lambda_hd);
        x.powi(6)
    }
}

/// (1.3): μ_bd for Λ < Λ_bd; (μ_bd − μ_hd)(Λ − Λ_hd)⁶/(Λ_bd − Λ_hd)⁶ + μ_hd for Λ_bd ≤ Λ < Λ_hd;
/// μ_hd for Λ ≥ Λ_hd. Continuous at both limits. Returns (μ_r, regime).
#[inline]
pub fn mixed_friction(
    mu_bd: f64,
    mu_hd: f64,
    lambda: f64,
    lim: &MixedLimits,
) -> (f64, FrictionRegime) {
    mixed_friction_weighted(mu_bd, mu_hd, lambda, lim.weight(lambda), lim)
}

/// [`mixed_friction`] with the weight [`MixedLimits::weight`]`(lambda)` given.
#[inline(always)]
pub fn mixed_friction_weighted(
    mu_bd: f64,
    mu_hd: f64,
    lambda: f64,
    weight: f64,
    lim: &MixedLimits,
) -> (f64, FrictionRegime) {
    if lambda < lim.lambda_bd {
        (mu_bd, FrictionRegime::Boundary)
    } else if lambda < lim.lambda_hd {
        ((mu_bd - mu_hd) * weight + mu_hd, FrictionRegime::Mixed)
    } else {
        (mu_hd, FrictionRegime::Hydrodynamic)
    }
}
