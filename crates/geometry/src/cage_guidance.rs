//! What carries the cage: its guiding land or its rollers (docs/theory.md §1.6).
//!
//! The bar of a window cage touches the roller along an edge line at the bar contact diameter
//! D_b, half a window W/2 from the pocket's mid-plane (the contact model of the dynamics). With
//! the roller at its nominal place (pitch radius r_m) the edge lies at `y₀ = D_b/2 − r_m` radially
//! and `W/2` circumferentially from the roller axis, so the roller has the circumferential play
//! `W/2 − √(R_w² − y₀²)` on each side. A cage moving by `e` in a direction at angle α to a
//! pocket's radial line moves that pocket's edges by `(e cos α, e sin α)`; the pocket closes when
//! an edge reaches the roller surface, `(y₀ + e cos α)² + (W/2 − e |sin α|)² = R_w²`. The
//! smallest such `e` over all directions, `√(y₀² + (W/2)²) − R_w`, is the cage displacement the
//! rollers allow. If the land gap (half the floating clearance) is smaller, the land catches the
//! cage first: the cage is land-guided; otherwise the rollers carry it.

use crate::{CageGuidance, CylindricalRollerBearing};

/// Pocket play and land gap of a land-guided cage, and which of them centres the cage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageGuidanceCheck {
    /// Circumferential play of a centred roller on each side of its pocket [m].
    pub pocket_play_per_side: f64,
    /// Smallest cage displacement, over all directions, that closes a pocket on its roller [m].
    pub pocket_closing_displacement: f64,
    /// Radial gap between the centred cage and its land, half the floating clearance [m].
    pub land_radial_gap: f64,
}

impl CageGuidanceCheck {
    /// True when the land stops the cage before any pocket closes on its roller.
    pub fn land_guided(&self) -> bool {
        self.land_radial_gap < self.pocket_closing_displacement
    }
}

impl CylindricalRollerBearing {
    /// Pocket play, pocket closing displacement and land gap of a land-guided cage; `None` for a
    /// bearing without a cage or with a roller-guided cage.
    pub fn cage_guidance_check(&self) -> Option<CageGuidanceCheck> {
        let cage = self.cage.as_ref()?;
        if cage.guidance == CageGuidance::Rollers {
            return None;
        }
        let rw = 0.5 * self.roller.diameter;
        let y0 = 0.5 * (cage.bar_contact_diameter - self.pitch_diameter());
        let half_window = 0.5 * cage.pocket_circumferential;
        let half_chord = (rw * rw - y0 * y0).max(0.0).sqrt();
        Some(CageGuidanceCheck {
            pocket_play_per_side: half_window - half_chord,
            pocket_closing_displacement: pocket_closing_displacement(y0, half_window, rw),
            land_radial_gap: 0.5 * cage.floating_clearance,
        })
    }
}

/// Distance the pocket edge at `(y₀, h)` from the roller axis must travel to reach the roller
/// surface of radius `R`: along the line towards the axis, `√(y₀² + h²) − R` (negative: the edge
/// already cuts the roller). With the pockets spread all round the cage some pocket faces every
/// direction of cage motion, so this is also the smallest cage displacement that closes a pocket
/// (exact for an edge line; the discrete pocket count only makes the true value larger).
fn pocket_closing_displacement(y0: f64, h: f64, r: f64) -> f64 {
    y0.hypot(h) - r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closing_displacement_of_an_edge_at_the_roller_centre_height_is_the_play() {
        // y₀ = 0: the edge faces the roller; a tangential move closes the play W/2 − R
        let e = pocket_closing_displacement(0.0, 8.0e-3, 7.5e-3);
        assert!((e - 0.5e-3).abs() < 1e-9, "{e}");
    }

    #[test]
    fn no_direction_closes_the_pocket_sooner_than_the_line_to_the_axis() {
        let (y0, h, r) = (6.25e-3, 5.625e-3, 7.5e-3);
        let e = pocket_closing_displacement(y0, h, r);
        for k in 0..=3600 {
            let alpha = std::f64::consts::PI * k as f64 / 3600.0;
            // (y₀ + s cos α)² + (h − s sin α)² = R²: smallest positive root s
            let b = y0 * alpha.cos() - h * alpha.sin();
            let disc = b * b - (y0 * y0 + h * h - r * r);
            if b < 0.0 && disc >= 0.0 {
                assert!(-b - disc.sqrt() >= e - 1e-12, "α = {alpha}");
            }
        }
    }
}
