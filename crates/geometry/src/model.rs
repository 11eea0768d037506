//! What a model file describes: a whole bearing, or a single roller on a raceway.

use crate::bearing::{CylindricalRollerBearing, Misalignment};
use crate::error::GeometryError;
use crate::ring::Ring;
use crate::roller::Roller;
use crate::tapered::DoubleRowTaperedBearing;

/// A roller on one raceway, for contact studies such as seed 004 (bearing 32206 roller on its
/// inner raceway), where the rest of the bearing is irrelevant or unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct RollerRacewayPair {
    pub name: String,
    pub roller: Roller,
    pub raceway: Ring,
    /// True for an inner (convex) raceway, false for an outer (concave) one.
    pub raceway_is_inner: bool,
    pub misalignment: Misalignment,
}

/// Everything a model file can describe. (One value per model file, so the size difference
/// between the variants does not matter.)
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum BearingModel {
    Cylindrical(CylindricalRollerBearing),
    RollerRaceway(RollerRacewayPair),
    Tapered(DoubleRowTaperedBearing),
}

impl BearingModel {
    pub fn name(&self) -> &str {
        match self {
            Self::Cylindrical(b) => &b.name,
            Self::RollerRaceway(p) => &p.name,
            Self::Tapered(b) => &b.name,
        }
    }

    /// The cylindrical roller (`None` for a tapered bearing, whose roller is a
    /// [`crate::TaperedRoller`]).
    pub fn roller(&self) -> Option<&Roller> {
        match self {
            Self::Cylindrical(b) => Some(&b.roller),
            Self::RollerRaceway(p) => Some(&p.roller),
            Self::Tapered(_) => None,
        }
    }

    pub fn misalignment(&self) -> Misalignment {
        match self {
            Self::Cylindrical(b) => b.misalignment,
            Self::RollerRaceway(p) => p.misalignment,
            Self::Tapered(b) => b.misalignment,
        }
    }

    /// The raceway a roller contact is evaluated on, and whether it is an inner raceway.
    /// A bearing offers both (`inner` chooses); a pair offers its only raceway; a tapered
    /// bearing has cone and cup lines instead ([`crate::TaperedRow`]): `None`.
    pub fn raceway(&self, inner: bool) -> Option<(&Ring, bool)> {
        match self {
            Self::Cylindrical(b) if inner => Some((&b.inner_ring, true)),
            Self::Cylindrical(b) => Some((&b.outer_ring, false)),
            Self::RollerRaceway(p) => Some((&p.raceway, p.raceway_is_inner)),
            Self::Tapered(_) => None,
        }
    }

    /// The complete cylindrical bearing, or the one-line reason why `command` cannot run this
    /// model.
    pub fn require_cylindrical(&self, command: &str) -> Result<&CylindricalRollerBearing, String> {
        match self {
            Self::Cylindrical(b) => Ok(b),
            Self::Tapered(_) => Err(format!(
                "{command} supports cylindrical bearings; for a double-row tapered bearing use \
                 `rolldyn check|loads|simulate`"
            )),
            Self::RollerRaceway(_) => Err(format!(
                "{command} needs a complete bearing (bearing.kind = \"cylindrical\")"
            )),
        }
    }

    pub fn validate(&self) -> Result<(), GeometryError> {
        match self {
            Self::Cylindrical(b) => b.validate(),
            Self::RollerRaceway(p) => {
                let key = if p.raceway_is_inner {
                    "inner_ring"
                } else {
                    "outer_ring"
                };
                p.raceway.validate(key, p.raceway_is_inner)?;
                p.roller.validate()
            }
            Self::Tapered(b) => b.validate(),
        }
    }
}
