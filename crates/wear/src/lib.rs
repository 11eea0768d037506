//! Wear of the contact surfaces of a roller bearing and its feedback into the geometry over the
//! bearing's life (seed 000 §2.4, §3.1.1.5–3.1.1.7; docs/theory.md §8).
//!
//! - [`law`]: Archard's law (seed 000 eq. 2.34), hardness conversions and the life conversion;
//! - [`coefficient`]: the wear coefficient as a function of the film parameter Λ;
//! - [`averaged`]: the averaged-parameter method (seed 000 eqs. 2.35–2.37).

pub mod averaged;
pub mod coefficient;
pub mod law;
