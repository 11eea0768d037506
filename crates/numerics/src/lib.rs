//! Numerical kernels shared by the rolldyn solvers. No dependencies, no physics: callers
//! supply residuals and Jacobians in their own units.
//!
//! * [`newton2d`]: damped Newton (Levenberg–Marquardt + backtracking line search) for a
//!   system of two nonlinear equations.
//! * [`root1d`]: safeguarded Newton (bracket search, Newton/secant steps, bisection) for one
//!   equation in one unknown.
//! * [`dense_lu`]: dense LU factorisation with partial pivoting for small systems.
//! * [`brent`]: Brent's root finder for a caller that already holds a sign-change bracket
//!   and its end values ([`root1d`] searches the bracket itself and can use slopes).
//! * [`gauss_legendre`]: composite 8-point Gauss–Legendre quadrature.
//! * [`maximize1d`]: golden-section search and Brent's method for the maximum of a function
//!   of one variable.
//! * [`step`]: the ADAMS cubic STEP ramp (SPEC §3.4), with the degenerate span defined.
//! * [`hash`]: FNV-1a, the stable hash of fingerprints and checksums.
//! * [`sealed`]: the tag, version and checksum frame of the state files rolldyn reads back.
//! * [`fastmath`]: branch-free, vectorisable `exp`, `ln`, `sin_cos` for hot loops.
//! * [`avx512_twin!`]: a hot loop and its AVX-512F copy from one parameter list; [`vector_copies::LoopCopy`] for callers that dispatch themselves.

pub mod brent;
pub mod dense_lu;
pub mod fastmath;
pub mod gauss_legendre;
pub mod hash;
pub mod maximize1d;
pub mod newton2d;
pub mod root1d;
pub mod sealed;
pub mod skyline;
pub mod statistics;
pub mod step;
pub mod table;
pub mod vector_copies;

pub use newton2d::{Damping, Newton2dOptions, Newton2dOutcome, Newton2dStatus, Sample, solve_2d};
pub use root1d::{
    Bracket, Derivative, Point, Root1dOptions, Root1dOutcome, Root1dStatus, find_root,
};
