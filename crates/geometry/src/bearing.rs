//! A complete cylindrical roller bearing and its consistency checks (SPEC §1.1).

use crate::cage::Cage;
use crate::cage_pocket::{PocketContext, PocketWalls};
use crate::error::GeometryError;
use crate::ring::Ring;
use crate::roller::Roller;

/// Internal clearances (SPEC §1.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clearance {
    /// Radial internal clearance G_r, diametral (total radial play of one ring relative to the
    /// other, ISO 5753 convention) [m]; negative = preload.
    pub radial: f64,
    /// Total axial clearance between roller ends and the ribs [m] (2002834: 0.03…0.071 mm).
    pub roller_rib_axial: Option<f64>,
    /// Whether a negative radial clearance (preload) is intended.
    pub allow_preload: bool,
    /// `radial` is the operating clearance (seed 000 Table 3.1 gives operating clearances): the
    /// quasi-static model adds no fit, thermal or centrifugal change to it. Otherwise it is the
    /// mounted internal clearance and the quasi-static model derives the operating one (SPEC
    /// §5.2). The dynamics always runs on `radial`.
    pub radial_is_operating: bool,
}

/// Ring misalignment (SPEC §3.7).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Misalignment {
    /// Tilt of the inner-ring axis relative to the outer-ring axis [rad] (0′…12′ in seed 000).
    pub inner_ring_tilt: f64,
}

/// A single-row cylindrical roller bearing.
#[derive(Debug, Clone, PartialEq)]
pub struct CylindricalRollerBearing {
    pub name: String,
    pub inner_ring: Ring,
    pub outer_ring: Ring,
    pub roller: Roller,
    pub roller_count: usize,
    pub cage: Option<Cage>,
    pub clearance: Clearance,
    pub misalignment: Misalignment,
}

/// Largest mismatch between the raceway annulus and the roller diameter accepted as a
/// clearance (2 % of D_w); anything larger is a data error, not a clearance.
const MAX_ANNULUS_MISMATCH: f64 = 0.02;
/// Largest preload accepted, as a fraction of the roller diameter (0.2 % of D_w).
const MAX_PRELOAD: f64 = 0.002;

impl CylindricalRollerBearing {
    /// Pitch diameter d_m = (d_i + D_o)/2 [m].
    pub fn pitch_diameter(&self) -> f64 {
        0.5 * (self.inner_ring.raceway_diameter + self.outer_ring.raceway_diameter)
    }

    /// Clearance implied by the raceway and roller diameters, D_o − d_i − 2 D_w [m].
    pub fn geometric_clearance(&self) -> f64 {
        self.outer_ring.raceway_diameter
            - self.inner_ring.raceway_diameter
            - 2.0 * self.roller.diameter
    }

    /// Diameters (d_i, D_o) of the raceways the rollers roll on [m]: the inner raceway as given
    /// and the outer raceway placed by the radial clearance, D_o = d_i + 2 D_w + G_r. This is the
    /// contact geometry of the dynamics (a roller touching both raceways once the clearance is
    /// taken up at the outer one); the given outer raceway diameter may differ from it by the
    /// tolerated annulus mismatch.
    pub fn rolling_raceway_diameters(&self) -> (f64, f64) {
        let d_i = self.inner_ring.raceway_diameter;
        (
            d_i,
            d_i + 2.0 * self.roller.diameter + self.clearance.radial,
        )
    }

    /// Epicyclic (pure-rolling) cage speed for inner/outer ring speeds [rad/s] on the
    /// [`Self::rolling_raceway_diameters`]: [`crate::epicyclic_cage_speed`].
    pub fn epicyclic_cage_speed(&self, inner_speed: f64, outer_speed: f64) -> f64 {
        let (d_i, d_o) = self.rolling_raceway_diameters();
        crate::epicyclic_cage_speed(d_i, d_o, inner_speed, outer_speed)
    }

    /// Roller spin speed about its own axis under pure rolling [rad/s] (positive opposite to
    /// the inner ring) on the [`Self::rolling_raceway_diameters`]:
    /// [`crate::epicyclic_roller_speed`].
    pub fn epicyclic_roller_speed(&self, inner_speed: f64, outer_speed: f64) -> f64 {
        let (d_i, d_o) = self.rolling_raceway_diameters();
        crate::epicyclic_roller_speed(d_i, d_o, self.roller.diameter, inner_speed, outer_speed)
    }

    /// Total roller–rib axial clearance: from `clearance.roller_rib_axial`, else from the rib
    /// spacing of a ring with two ribs.
    pub fn roller_rib_axial_clearance(&self) -> Option<f64> {
        self.clearance.roller_rib_axial.or_else(|| {
            [&self.inner_ring, &self.outer_ring]
                .iter()
                .find_map(|r| r.rib_spacing)
                .map(|s| s - self.roller.length)
        })
    }

    /// Checks every part and their fit together.
    pub fn validate(&self) -> Result<(), GeometryError> {
        self.inner_ring.validate("inner_ring", true)?;
        self.outer_ring.validate("outer_ring", false)?;
        self.roller.validate()?;
        self.validate_fit()?;
        self.validate_clearances()?;
        if let Some(cage) = &self.cage {
            cage.validate()?;
            self.validate_cage(cage)?;
        }
        let tilt = self.misalignment.inner_ring_tilt;
        if !tilt.is_finite() || tilt.abs() > 1f64.to_radians() {
            return Err(GeometryError::new(
                "misalignment.inner_ring",
                format!(
                    "{:.1}′ is beyond the 1° a roller bearing can run with",
                    tilt.to_degrees() * 60.0
                ),
            ));
        }
        self.validate_plausibility()
    }

    fn validate_fit(&self) -> Result<(), GeometryError> {
        let (di, do_, dw) = (
            self.inner_ring.raceway_diameter,
            self.outer_ring.raceway_diameter,
            self.roller.diameter,
        );
        if do_ <= di {
            return Err(GeometryError::new(
                "outer_ring.raceway_diameter",
                "must be larger than inner_ring.raceway_diameter",
            ));
        }
        let mismatch = self.geometric_clearance();
        if mismatch.abs() > MAX_ANNULUS_MISMATCH * dw {
            return Err(GeometryError::new(
                "roller.diameter",
                format!(
                    "rollers Ø{:.3} mm do not fit between raceways Ø{:.3} and Ø{:.3} mm \
                     (radial space {:.3} mm per side)",
                    dw * 1e3,
                    di * 1e3,
                    do_ * 1e3,
                    0.5e3 * (do_ - di)
                ),
            ));
        }
        if self.roller_count < 3 {
            return Err(GeometryError::new(
                "roller.count",
                "a bearing needs at least 3 rollers",
            ));
        }
        let chord = self.pitch_diameter() * (std::f64::consts::PI / self.roller_count as f64).sin();
        if chord <= dw {
            let max = (std::f64::consts::PI / (dw / self.pitch_diameter()).asin()).floor();
            return Err(GeometryError::new(
                "roller.count",
                format!(
                    "{} rollers Ø{:.3} mm overlap on the pitch circle Ø{:.3} mm (at most {} fit)",
                    self.roller_count,
                    dw * 1e3,
                    self.pitch_diameter() * 1e3,
                    max
                ),
            ));
        }
        Ok(())
    }

    fn validate_clearances(&self) -> Result<(), GeometryError> {
        let gr = self.clearance.radial;
        if !gr.is_finite() {
            return Err(GeometryError::new(
                "clearance.radial",
                "must be a finite length",
            ));
        }
        if gr < 0.0 && !self.clearance.allow_preload {
            return Err(GeometryError::new(
                "clearance.radial",
                format!(
                    "negative clearance {:.4} mm is a preload: set clearance.preload = true if intended",
                    gr * 1e3
                ),
            ));
        }
        if gr < -MAX_PRELOAD * self.roller.diameter {
            return Err(GeometryError::new(
                "clearance.radial",
                format!(
                    "preload {:.4} mm exceeds {:.1} % of the roller diameter: an interference, not a preload",
                    -gr * 1e3,
                    MAX_PRELOAD * 100.0
                ),
            ));
        }
        if let Some(c) = self.clearance.roller_rib_axial
            && !(c >= 0.0)
        {
            return Err(GeometryError::new(
                "clearance.roller_rib_axial",
                "must not be negative",
            ));
        }
        for (key, ring) in [
            ("inner_ring", &self.inner_ring),
            ("outer_ring", &self.outer_ring),
        ] {
            let Some(spacing) = ring.rib_spacing else {
                continue;
            };
            if spacing < self.roller.length {
                return Err(GeometryError::new(
                    format!("{key}.rib_spacing"),
                    format!(
                        "roller length {:.3} mm is longer than the space between ribs {:.3} mm",
                        self.roller.length * 1e3,
                        spacing * 1e3
                    ),
                ));
            }
            if let Some(c) = self.clearance.roller_rib_axial {
                let implied = spacing - self.roller.length;
                if (implied - c).abs() > 1e-7 {
                    return Err(GeometryError::new(
                        "clearance.roller_rib_axial",
                        format!(
                            "{:.4} mm contradicts {key}.rib_spacing − roller.length = {:.4} mm (give one of them)",
                            c * 1e3,
                            implied * 1e3
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The cage's pocket resolved against this bearing ([`Cage::pocket_context`]).
    pub fn pocket_context(&self, cage: &Cage) -> PocketContext {
        cage.pocket_context(
            0.5 * self.roller.diameter,
            0.5 * self.pitch_diameter(),
            self.roller_count,
        )
    }

    /// The pocket walls of the cage in pocket coordinates; `None` without a cage.
    pub fn pocket_walls(&self) -> Option<PocketWalls> {
        let cage = self.cage.as_ref()?;
        cage.pocket.walls(&self.pocket_context(cage)).ok()
    }

    fn validate_cage(&self, cage: &Cage) -> Result<(), GeometryError> {
        self.validate_envelope(cage)?;
        let ctx = self.pocket_context(cage);
        cage.pocket
            .check_fit(&ctx, 0.5 * self.clearance.radial.max(0.0))?;
        cage.pocket.bar_section(&ctx)?;
        if cage.pocket.axial <= self.roller.length {
            return Err(GeometryError::new(
                "cage.pocket_axial",
                format!(
                    "pocket {:.3} mm is not longer than the roller {:.3} mm",
                    cage.pocket.axial * 1e3,
                    self.roller.length * 1e3
                ),
            ));
        }
        if cage.pocket.axial >= cage.width {
            return Err(GeometryError::new(
                "cage.pocket_axial",
                "pocket is wider than the cage",
            ));
        }
        if let Some(land) = cage.land_diameter() {
            let ok = match cage.guidance {
                crate::CageGuidance::InnerLand => land > self.inner_ring.raceway_diameter,
                _ => land < self.outer_ring.raceway_diameter,
            };
            if !ok {
                return Err(GeometryError::new(
                    "cage.inner_diameter",
                    format!(
                        "the guiding land Ø{:.3} mm implied by the cage and its floating clearance \
                         would cut into the raceway",
                        land * 1e3
                    ),
                ));
            }
        }
        Ok(())
    }
}
