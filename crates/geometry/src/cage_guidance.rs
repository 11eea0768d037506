//! What carries the cage: its guiding land or its rollers (docs/theory.md §1.6).
//!
//! A cage moving by `e` relative to its rollers closes a pocket when some roller touches a wall
//! of its pocket; with pockets all round the cage some pocket faces every direction, so the
//! smallest such `e` over all directions ([`PocketPlay::closing_displacement`], from the pocket
//! profile of [`crate::cage_pocket`]) is the cage displacement the rollers allow. If the land gap
//! (half the floating clearance) is smaller, the land catches the cage first: the cage is
//! land-guided; otherwise the rollers carry it.

use crate::cage_pocket::PocketPlay;
use crate::{CageGuidance, CylindricalRollerBearing};

/// Pocket play, pocket closing displacement and land gap of a land-guided cage, and which of
/// them centres the cage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageGuidanceCheck {
    /// Plays of a centred roller in its pocket.
    pub play: PocketPlay,
    /// Radial gap between the centred cage and its land, half the floating clearance [m].
    pub land_radial_gap: f64,
}

impl CageGuidanceCheck {
    /// True when the land stops the cage before any pocket closes on its roller.
    pub fn land_guided(&self) -> bool {
        self.land_radial_gap < self.play.closing_displacement
    }
}

impl CylindricalRollerBearing {
    /// Pocket plays and land gap of a land-guided cage; `None` for a bearing without a cage or
    /// with a roller-guided cage.
    pub fn cage_guidance_check(&self) -> Option<CageGuidanceCheck> {
        let cage = self.cage.as_ref()?;
        if cage.guidance == CageGuidance::Rollers {
            return None;
        }
        let play = cage.pocket.play(&self.pocket_context(cage)).ok()?;
        Some(CageGuidanceCheck {
            play,
            land_radial_gap: 0.5 * cage.floating_clearance,
        })
    }
}
