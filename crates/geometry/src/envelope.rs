//! The checks a bearing designer makes on a drawing besides the fit of each part: the cage
//! inside the envelope the rings leave it, the rib heights against the roller, the stated
//! clearance against the one the raceway diameters imply. Contradictions that cannot be built
//! are errors ([`CylindricalRollerBearing::validate_envelope`]); differences a designer should
//! look at are notes ([`CylindricalRollerBearing::design_notes`]).

use crate::bearing::CylindricalRollerBearing;
use crate::cage::{Cage, CageGuidance};
use crate::error::GeometryError;
use crate::ring::Ring;

/// A stated clearance and the one implied by the raceway and roller diameters that differ by
/// more than this are named in a note, m (1 µm: the resolution of clearance data in catalogues
/// and of ISO 5753-1's tables).
const CLEARANCE_NOTE_TOLERANCE: f64 = 1e-6;
/// A guiding land that differs from the ring's rim by more than this is named in a note, m.
const LAND_NOTE_TOLERANCE: f64 = 10e-6;
/// Rib height above the raceway beyond which a note warns, as a fraction of D_w: a rib that
/// reaches the roller axis (0.5 D_w) or higher leaves no room for the cage bars and cannot be
/// passed by the roller at assembly (usual rib heights 0.2–0.35 D_w, Harris & Kotzalas,
/// *Essential Concepts of Bearing Technology*, 5th ed., 2006, §1.3).
const MAX_RIB_HEIGHT_PER_ROLLER_DIAMETER: f64 = 0.5;

/// A finding on a model that is built as given but that a designer should look at.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignNote {
    /// The model key the note is about.
    pub key: String,
    pub text: String,
}

/// The diameter up to which a ring reaches towards the cage: an inner ring's largest rim or an
/// outer ring's smallest, of its ribs and (with `land`) its guiding land.
fn rim_diameter(ring: &Ring, inner: bool, land: bool) -> Option<f64> {
    let lands = ring.guiding_land.iter().filter(|_| land);
    let rims = ring
        .ribs
        .iter()
        .map(|r| r.diameter)
        .chain(lands.map(|l| l.diameter));
    if inner {
        rims.reduce(f64::max)
    } else {
        rims.reduce(f64::min)
    }
}

impl CylindricalRollerBearing {
    /// The cage inside the rings' envelope: a cage wider than a ring's rib spacing overlaps its
    /// ribs axially and must clear their rims (bore above an inner ring's rims, outside diameter
    /// below an outer ring's); a cage between the ribs must clear the raceways.
    pub(crate) fn validate_envelope(&self, cage: &Cage) -> Result<(), GeometryError> {
        for (key, ring, inner) in [
            ("inner_ring", &self.inner_ring, true),
            ("outer_ring", &self.outer_ring, false),
        ] {
            let over_ribs = ring.rib_spacing.is_some_and(|s| cage.width > s);
            let (limit, what) = match rim_diameter(ring, inner, true) {
                Some(rim) if over_ribs => (rim, "rib rim"),
                _ => (ring.raceway_diameter, "raceway"),
            };
            let (cage_key, cage_diameter, clear) = if inner {
                (
                    "cage.inner_diameter",
                    cage.inner_diameter,
                    cage.inner_diameter > limit,
                )
            } else {
                (
                    "cage.outer_diameter",
                    cage.outer_diameter,
                    cage.outer_diameter < limit,
                )
            };
            if !clear {
                let width = match ring.rib_spacing {
                    Some(s) if over_ribs => format!(
                        ", and the cage ({:.3} mm wide) is wider than the rib spacing {:.3} mm \
                         so it overlaps the ribs",
                        cage.width * 1e3,
                        s * 1e3
                    ),
                    _ => String::new(),
                };
                return Err(GeometryError::new(
                    cage_key,
                    format!(
                        "Ø{:.3} mm reaches the {key} {what} Ø{:.3} mm{width}",
                        cage_diameter * 1e3,
                        limit * 1e3
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Findings that do not stop a run: a stated clearance other than the raceway diameters'
    /// (the dynamics places the outer raceway by the stated one), a guiding land the ring does
    /// not have at the land diameter, ribs higher than half the roller, a cage wider than the
    /// rings.
    pub fn design_notes(&self) -> Vec<DesignNote> {
        let mut notes = Vec::new();
        let implied = self.geometric_clearance();
        let stated = self.clearance.radial;
        if (implied - stated).abs() > CLEARANCE_NOTE_TOLERANCE {
            notes.push(DesignNote {
                key: "clearance.radial".into(),
                text: format!(
                    "the stated radial clearance {:.1} µm differs from the {:.1} µm the raceway \
                     diameters imply (outer_ring.raceway_diameter − inner_ring.raceway_diameter \
                     − 2 roller.diameter); the stated clearance is used: the outer raceway \
                     rolls at Ø{:.4} mm",
                    stated * 1e6,
                    implied * 1e6,
                    self.rolling_raceway_diameters().1 * 1e3
                ),
            });
        }
        if let Some(cage) = &self.cage {
            self.note_land(cage, &mut notes);
            let ring_width = self.inner_ring.width.max(self.outer_ring.width);
            if cage.width > ring_width {
                notes.push(DesignNote {
                    key: "cage.width".into(),
                    text: format!(
                        "the cage ({:.3} mm) is wider than the rings ({:.3} mm): it stands out \
                         of the bearing's side faces",
                        cage.width * 1e3,
                        ring_width * 1e3
                    ),
                });
            }
        }
        for (key, ring, inner) in [
            ("inner_ring", &self.inner_ring, true),
            ("outer_ring", &self.outer_ring, false),
        ] {
            for (i, rib) in ring.ribs.iter().enumerate() {
                let height = if inner {
                    0.5 * (rib.diameter - ring.raceway_diameter)
                } else {
                    0.5 * (ring.raceway_diameter - rib.diameter)
                };
                if height > MAX_RIB_HEIGHT_PER_ROLLER_DIAMETER * self.roller.diameter {
                    notes.push(DesignNote {
                        key: format!("{key}.ribs[{i}].diameter"),
                        text: format!(
                            "the rib stands {:.3} mm above the raceway, more than half the \
                             roller diameter ({:.3} mm): it reaches past the roller axis",
                            height * 1e3,
                            0.5 * self.roller.diameter * 1e3
                        ),
                    });
                }
            }
        }
        notes
    }

    /// A land-guided cage runs on a rim of its ring, usually its ribs' rims: a land the cage and
    /// its floating clearance put elsewhere is a surface of its own the drawing must have.
    fn note_land(&self, cage: &Cage, notes: &mut Vec<DesignNote>) {
        let Some(land) = cage.land_diameter() else {
            return;
        };
        let (ring, key, inner) = match cage.guidance {
            CageGuidance::InnerLand => (&self.inner_ring, "inner_ring", true),
            CageGuidance::OuterLand => (&self.outer_ring, "outer_ring", false),
            CageGuidance::Rollers => return,
        };
        let text = match rim_diameter(ring, inner, false) {
            None => format!(
                "the cage is guided on the {key}, which has no ribs: it runs on a land \
                 Ø{:.3} mm (cage diameter and cage.floating_clearance) the ring must have",
                land * 1e3
            ),
            Some(rim) if (rim - land).abs() > LAND_NOTE_TOLERANCE => format!(
                "the guiding land implied by the cage and cage.floating_clearance, Ø{:.3} mm, \
                 differs from the {key}'s rib rim Ø{:.3} mm (floating clearance on the rims \
                 {:.3} mm): the land is a surface of its own the drawing must have",
                land * 1e3,
                rim * 1e3,
                if inner {
                    cage.inner_diameter - rim
                } else {
                    rim - cage.outer_diameter
                } * 1e3
            ),
            Some(_) => return,
        };
        notes.push(DesignNote {
            key: "cage.floating_clearance".into(),
            text,
        });
    }
}
