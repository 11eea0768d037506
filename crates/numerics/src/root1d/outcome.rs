//! Result of [`super::find_root`].

/// How the iteration ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Root1dStatus {
    /// A point met its convergence test, or the bracket met the x tolerance.
    Converged,
    /// The next iterate would be an end of the bracket: the root is located to the
    /// resolution of `f64` without meeting the convergence test.
    Stalled,
    /// f keeps its sign over the hard limits ([`super::Bracket::Search`]): no root inside
    /// them; `x` is the limit (or search point) with the smaller |f|.
    NoSignChange,
    /// `max_evaluations` used up.
    MaxEvaluations,
}

/// Final point of [`super::find_root`].
#[derive(Debug, Clone, PartialEq)]
pub struct Root1dOutcome<S> {
    /// Root estimate: the converged point, else the last iterate (see [`Root1dStatus`]).
    pub x: f64,
    /// f(x) (NaN reported as +∞).
    pub value: f64,
    /// Caller state at `x`.
    pub state: S,
    /// Function evaluations used.
    pub evaluations: usize,
    /// Interval `(lo, hi)` known to hold the root: the bracket once found, before that the
    /// hard limits (infinite for [`super::Bracket::Expand`]).
    pub bracket: (f64, f64),
    /// How the iteration ended.
    pub status: Root1dStatus,
}

impl<S> Root1dOutcome<S> {
    /// True for [`Root1dStatus::Converged`].
    pub fn converged(&self) -> bool {
        self.status == Root1dStatus::Converged
    }
}
