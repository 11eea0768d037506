//! Error type of the Reynolds solvers.

use std::fmt;

/// Everything that can go wrong in this crate. Solvers never return NaN: bad input is rejected
/// up front and a failed iteration is reported with its count and last residual.
#[derive(Debug, Clone, PartialEq)]
pub enum ReynoldsError {
    /// An input is outside its physical or numerical range (`what` names the parameter).
    InvalidInput {
        /// Parameter name.
        what: &'static str,
        /// Why it was rejected.
        reason: String,
    },
    /// An iteration hit its limit before meeting its tolerance.
    NotConverged {
        /// Which iteration.
        what: &'static str,
        /// Iterations done.
        iterations: usize,
        /// Last relative residual or change.
        residual: f64,
    },
    /// The problem has no solution (e.g. piezoviscous rigid contact with α̃·q₀,max ≥ 1,
    /// seed 002 (3.65), Table 3.5 "no solution").
    NoSolution(String),
    /// A linear system was singular (zero pivot).
    Singular(&'static str),
    /// A solution left the range its model holds in (e.g. a transient film outside its table).
    OutOfRange(String),
}

impl fmt::Display for ReynoldsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReynoldsError::InvalidInput { what, reason } => write!(f, "invalid {what}: {reason}"),
            ReynoldsError::NotConverged {
                what,
                iterations,
                residual,
            } => write!(
                f,
                "{what} did not converge in {iterations} iterations (last residual {residual:.3e})"
            ),
            ReynoldsError::NoSolution(s) => write!(f, "no solution: {s}"),
            ReynoldsError::Singular(s) => write!(f, "singular linear system in {s}"),
            ReynoldsError::OutOfRange(s) => write!(f, "out of range: {s}"),
        }
    }
}

impl std::error::Error for ReynoldsError {}

/// Result alias.
pub type Result<T> = std::result::Result<T, ReynoldsError>;

/// Rejects a value that is not finite and strictly positive.
pub(crate) fn positive(what: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ReynoldsError::InvalidInput {
            what,
            reason: format!("must be finite and > 0, got {v}"),
        })
    }
}

/// Rejects a non-finite value.
pub(crate) fn finite(what: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(ReynoldsError::InvalidInput {
            what,
            reason: format!("must be finite, got {v}"),
        })
    }
}
