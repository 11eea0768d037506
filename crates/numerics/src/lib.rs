//! Numerical kernels shared by the rolldyn solvers. No dependencies, no physics: callers
//! supply residuals and Jacobians in their own units.
//!
//! * [`newton2d`]: damped Newton (Levenberg–Marquardt + backtracking line search) for a
//!   system of two nonlinear equations.

pub mod newton2d;

pub use newton2d::{Damping, Newton2dOptions, Newton2dOutcome, Newton2dStatus, Sample, solve_2d};
