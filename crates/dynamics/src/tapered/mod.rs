//! # Double-row tapered roller bearing dynamics (seed 000 §3.2)
//!
//! Every roller of both rows moves with six degrees of freedom in the state layout of the
//! cylindrical engine ([`crate::layout`], about its centre of mass), each row has its
//! roller-guided cage (13 values), the inner-ring assembly (two cones and the spacer) translates
//! freely under its loads with a prescribed spin and misalignment; the cup is fixed.
//!
//! Contacts ([`rhs`]): every slice of a roller on the cone and on the cup — approach
//! `δ = r cos β − d`, `d` the distance of the slice's axis point from the raceway line in the
//! axial plane through it, normal along that line's normal (apex condition: the seated roller
//! touches both raceways along its whole length), slice law and STEP damping, EHL traction per
//! slice; the large end (sphere R) on the large rib and the small end on the small rib with the
//! end-face machinery of [`crate::ends`] (EHL while the contact spot stays inside the overlap of
//! end face and rib face, boundary friction otherwise, SPEC §6.7); the ends on the pocket faces
//! and the roller body on four bar edges per pocket (the cage is guided on the rollers);
//! polyamide contacts with constant μ = 0.06 (seed 000 §3.2.1).

mod columns;
mod contacts;
mod geometry;
mod layout;
mod model;
mod rhs;
mod run;
mod sample;
mod summary;

pub use columns::{SAMPLE_COLUMNS, sample_from_row, sample_row, summary_entries};
pub use contacts::{ContactRecorder, RibContact, RollerContacts, SliceContacts};
pub use layout::TaperedLayout;
pub use model::{TaperedModel, TaperedParameters, end_rib_film_limit_force};
/// The cassette of `examples/tapered-cassette.toml` for unit tests outside this module.
#[cfg(test)]
pub(crate) use rhs::tests::cassette;
pub use rhs::{RollerReport, TaperedSystem};
pub use run::{
    TaperedRun, TaperedRunSettings, TaperedSimulation, initial_state, run, run_recorded,
};
pub use sample::TaperedSample;
pub use summary::{TaperedSummary, axial_spectrum, spectrum_peaks, steady_window, summarise};
