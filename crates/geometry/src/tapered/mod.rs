//! Double-row tapered roller bearing (seed 000 §3.2): rollers as truncated cones with a
//! spherical large end, cones and cup from the apex condition, large and small ribs, two rows
//! in O or X arrangement, roller-guided polyamide cages (theory §"Double-row tapered bearing
//! geometry").

mod bearing;
mod cage;
mod plane;
mod rib;
mod roller;
mod row;
mod validate;
mod wear;

pub use bearing::{Arrangement, DoubleRowTaperedBearing};
pub use cage::TaperedCage;
pub use plane::{Rz, axis_crossing};
pub use rib::{LargeRib, TaperedRibFace, end_contact_angle};
pub use roller::{DEFAULT_TAPERED_SLICES, TaperedRoller, TaperedSliceStack};
pub use row::{LargeRibContact, RacewayLine, RowFrame, SmallRibFace, TaperedRow};
pub use wear::TaperedWear;

#[cfg(test)]
mod tests;
