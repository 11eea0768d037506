//! Result of [`super::solve_2d`].

/// How the iteration ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Newton2dStatus {
    /// `max_i |r_i| ≤ tolerance · scale`.
    Converged,
    /// No acceptable step, but the residual meets the stall tolerance.
    Stalled,
    /// No acceptable step and the residual is above the stall tolerance.
    NoDescent,
    /// `max_iterations` steps taken without convergence.
    IterationLimit,
}

/// Final point of [`super::solve_2d`].
#[derive(Debug, Clone, PartialEq)]
pub struct Newton2dOutcome<T> {
    /// Solution (last accepted point).
    pub x: [f64; 2],
    /// Residual at `x`.
    pub residual: [f64; 2],
    /// Residual scale at `x` (from its sample).
    pub scale: f64,
    /// Newton iterations: accepted steps, plus the failed one of a stalled search.
    pub iterations: usize,
    /// How the iteration ended.
    pub status: Newton2dStatus,
    /// Caller state at `x`.
    pub state: T,
}

impl<T> Newton2dOutcome<T> {
    /// True when `x` is accepted as a solution ([`Newton2dStatus::Converged`] or
    /// [`Newton2dStatus::Stalled`]).
    pub fn converged(&self) -> bool {
        matches!(
            self.status,
            Newton2dStatus::Converged | Newton2dStatus::Stalled
        )
    }
}
