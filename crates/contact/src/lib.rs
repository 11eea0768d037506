//! Elastic contact mechanics for roller bearings (SPEC §2, seed 004, seed 000 §2.2).
//!
//! * [`hertz`] — Hertz line, point and elliptical contact (SPEC §2.3).
//! * [`slices`] — slice force–deflection laws for a roller cut into slices (SPEC §2.1).
//! * [`damping`] — contact damping with the cubic STEP ramp (SPEC §2.2, §3.4).
//! * [`boussinesq`] — non-Hertzian pressure solver (modified Hartnett, seed 004 / SPEC §2.5),
//!   FFT-accelerated constrained conjugate gradient with a dense reference.
//! * [`cage_bar`] — the roller ↔ cage bar law (pair 34) derived from the bar's bending and
//!   shear, the line contact and the oil squeeze film (docs/theory.md §2.3.1).
//! * [`bar_force`] — the pair-34 force law per roller slice: elastic, or lubricated (squeeze
//!   and wedge film above the asperity film, the elastic law below it).
//! * [`squeeze_film`] — the oil squeeze film of a roller approaching a flat face (the cage
//!   bar), which both bar laws use.
//! * [`roller_raceway`] — a roller of a bearing model on its raceway, solved by any of the
//!   three methods and reported alike.

pub mod bar_force;
pub mod boussinesq;
pub mod cage_bar;
pub mod damping;
pub mod hertz;
pub mod roller_raceway;
pub mod slices;
pub mod squeeze_film;
