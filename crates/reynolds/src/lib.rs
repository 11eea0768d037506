//! Reynolds-equation solvers of rolldyn (SPEC §8 "REYN", seed 002).
//!
//! * [`reynolds1d`], [`reynolds2d`] — general thin-film Reynolds solvers (finite volumes, wall
//!   slip, squeeze, cavitation by complementarity or mass-conserving JFO), SPEC §8.1.
//! * [`compliance`] — compliance (influence) functions: half-space, Winkler/Lamé liners and the
//!   analytic kernel (4.36), finite-thickness plate, Fourier identification (3.67)–(3.71), SPEC §8.3.
//! * [`line_contact`] — lubricated roller–plate line contact: analytic (Martin/Kapitsa) and
//!   numerical rigid, piezoviscous and elastic (full EHL, Newton) solutions, W₀(h), λ(h), transient
//!   load steps, SPEC §8.4–8.5.
//! * [`journal`] — finite journal bearing: pressure, load, attitude, Sommerfeld number, friction,
//!   flows, stiffness and damping; elastic liner and Fourier thermal model, SPEC §8.6.
//! * [`cage_land`] — fast hydrodynamic cage–guiding-land force model for the dynamics.
//!
//! All public inputs and outputs are SI (m, Pa, Pa·s, N, rad/s, K) unless a name says otherwise.

// Numerical kernels index several coupled arrays with the same loop counter (stencils, band
// storage, interleaved unknowns); explicit indices are clearer there than zipped iterators.
#![allow(clippy::needless_range_loop)]

pub mod banded;
pub mod cage_land;
pub mod cavitation;
pub mod compliance;
pub mod error;
pub mod fft;
pub mod grid;
pub mod journal;
pub mod krylov;
pub mod line_contact;
pub mod reynolds1d;
pub mod reynolds2d;
pub mod roots;
pub mod slip;
pub mod thermal;
pub mod viscosity;
pub mod waviness;

pub use cavitation::Cavitation;
pub use error::{Result, ReynoldsError};
pub use slip::SlipLengths;
pub use viscosity::{Barus, Density, Isoviscous, Petrusevich, Roelands, Viscosity};
pub use waviness::{WaveHarmonic, Waviness, WavySurface};
