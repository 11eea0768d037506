//! Slice force–deflection laws for a roller cut into slices (SPEC §2.1, seed 000 §2.2).
//!
//! * [`law`] — [`SliceLaw`]: seed 000 eqs. (2.3)/(2.4) (inner/outer ring), the generalised power
//!   law (2.9), the ISO/TS 16281 lamina law and general `K_p δ^n` power laws.
//! * [`roller`] — [`SlicedRoller`]: struct-of-arrays slice set, allocation-free evaluation of
//!   slice forces, total force, moment and their Jacobian for an approach/tilt pair.
//! * [`solve`] — inverse problems: approach for a given force and tilt (1-D), approach and tilt
//!   for a given force and moment (2-D Newton on the analytic Jacobian).
//! * [`tapered`] — the cone and cup laws of the double-row tapered bearing.
//!
//! Units: SI in the API (m, N, rad). The empirical seed formulas are evaluated internally in
//! their seed units (N, mm, MPa; ⚠ F-15) and converted.

pub mod law;
pub mod roller;
pub mod solve;
pub mod tapered;

pub use law::{PowerForm, SliceLaw, seed_eq_2_3_approach, seed_eq_2_4_approach};
pub use roller::{SliceLoad, SlicedRoller};
pub use solve::{SliceSolution, SolveOptions};
pub use tapered::tapered_raceway_laws;

use std::fmt;

/// Errors of the slice laws and of the inverse solvers. No solver returns NaN: every failure is
/// one of these.
#[derive(Debug, Clone, PartialEq)]
pub enum SliceError {
    /// A parameter or input is not finite or out of its valid range.
    InvalidInput(&'static str),
    /// Slice arrays have inconsistent lengths or no slices.
    InvalidGeometry(&'static str),
    /// The requested load eccentricity `e = M/Q` lies outside the span of the slice
    /// mid-points, so no tilt can carry the moment.
    MomentOutOfRange {
        /// Requested eccentricity `M/Q` (m).
        eccentricity: f64,
        /// Smallest slice mid-position (m).
        x_min: f64,
        /// Largest slice mid-position (m).
        x_max: f64,
    },
    /// A non-zero moment was requested with a non-positive force.
    MomentWithoutForce,
    /// The iteration did not reach the tolerance.
    NoConvergence {
        /// Iterations performed.
        iterations: usize,
        /// Final scaled residual `max(|ΔQ|, |ΔM|/L_h) / Q`.
        residual: f64,
    },
}

impl fmt::Display for SliceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SliceError::InvalidInput(w) => write!(f, "invalid slice input: {w}"),
            SliceError::InvalidGeometry(w) => write!(f, "invalid slice geometry: {w}"),
            SliceError::MomentOutOfRange {
                eccentricity,
                x_min,
                x_max,
            } => write!(
                f,
                "load eccentricity M/Q = {eccentricity:e} m lies outside the slice span [{x_min:e}, {x_max:e}] m: no tilt can carry this moment"
            ),
            SliceError::MomentWithoutForce => {
                write!(
                    f,
                    "a non-zero moment cannot be carried with zero normal force"
                )
            }
            SliceError::NoConvergence {
                iterations,
                residual,
            } => write!(
                f,
                "slice solver did not converge in {iterations} iterations (scaled residual {residual:e})"
            ),
        }
    }
}

impl std::error::Error for SliceError {}
