//! Bearing geometry: rings, raceways, ribs, rollers and their profiles, cage (SPEC §1).
//!
//! Everything here is in SI units and free of file formats: the `rolldyn-model` crate reads
//! model files and builds these types; analyses consume them.

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod bearing;
mod cage;
mod cage_guidance;
pub mod cage_pocket;
mod envelope;
mod error;
mod kinematics;
mod mass;
mod material;
pub mod material_database;
mod model;
pub mod plausible;
pub mod profile;
mod ring;
mod roller;
pub mod tapered;
mod wear_map;

pub use bearing::{Clearance, CylindricalRollerBearing, Misalignment};
pub use cage::{Cage, CageGuidance, Plating};
pub use cage_guidance::CageGuidanceCheck;
pub use cage_pocket::{
    BarSection, CagePocket, PocketContext, PocketFaces, PocketPlay, PocketWalls, RetainingLip,
    WallPiece,
};
pub use envelope::DesignNote;
pub use error::{GeometryError, require_positive};
pub use kinematics::{cage_slip, epicyclic_cage_speed, epicyclic_roller_speed};
pub use mass::MassProperties;
pub use material::{
    FatigueStrength, MEYER_PER_VICKERS, Material, PA_PER_KGF_PER_MM2, first_invalid_sn_point,
    meyer_from_vickers, vickers_from_meyer,
};
pub use model::{BearingModel, RollerRacewayPair};
pub use profile::{Chamfer, Profile, ProfileShape};
pub use ring::{GuidingLand, Rib, RibFace, RibSide, Ring};
pub use roller::{EndFace, Roller, SliceStack};
pub use tapered::{
    Arrangement, DoubleRowTaperedBearing, LargeRib, LargeRibContact, RacewayLine, Rz, SmallRibFace,
    TaperedCage, TaperedRibFace, TaperedRoller, TaperedRow, TaperedSliceStack, TaperedWear,
};
pub use wear_map::{RacewayWearMap, WearAtAngle, angle_bin_centre_rad, angle_bin_of};
