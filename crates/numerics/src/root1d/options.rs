//! Knobs of [`super::find_root`].

/// How the sign-change bracket of [`super::find_root`] is found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bracket {
    /// Search inside the finite hard limits `limits` (either order) from the guess: a
    /// forward-difference slope (step `fd_step`, > 0) gives the first Newton step, capped at
    /// `max_first_step`; later steps grow 2…4× (secant slope) while |f| decreases and turn
    /// round (−2×) when it does not, so the root nearest to the guess is bracketed first. At
    /// a limit the other limit is tried; [`super::Root1dStatus::NoSignChange`] when f keeps
    /// its sign over the limits. Any monotony.
    Search {
        /// Hard limits of the unknown.
        limits: (f64, f64),
        /// Step of the first (forward-difference) slope.
        fd_step: f64,
        /// Largest first step of the search (absolute).
        max_first_step: f64,
    },
    /// Unbounded search for a non-decreasing f: steps of doubling length from the guess
    /// (first `first_step`, > 0) against the sign of f until it changes.
    Expand {
        /// Length of the first step.
        first_step: f64,
    },
    /// The root of a non-decreasing f lies in `[lo, hi]`: no search, the limits are not
    /// evaluated. The guess is clamped to them.
    Given {
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
}

/// Slope of the Newton steps inside the bracket.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Derivative {
    /// Difference quotient of the last two iterates (secant); bisection while there is only
    /// one.
    Secant,
    /// [`super::Point::slope`] of the current iterate.
    Supplied,
}

/// Options of [`super::find_root`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root1dOptions {
    /// Bracket search. Default `Bracket::Expand { first_step: 1.0 }`.
    pub bracket: Bracket,
    /// Slope of the Newton steps. Default [`Derivative::Secant`].
    pub derivative: Derivative,
    /// Converged when the bracket `[lo, hi]` is narrower than
    /// `x_tol + x_rel_tol · max(|lo|, |hi|)`. Defaults `0`, `0` (only the convergence test of
    /// the points, or a stall).
    pub x_tol: f64,
    /// See [`Root1dOptions::x_tol`].
    pub x_rel_tol: f64,
    /// Accept a Newton step only when the last one at least halved |f| (otherwise bisect).
    /// Default `true`.
    pub halving_test: bool,
    /// Budget of function evaluations. Default 200.
    pub max_evaluations: usize,
}

impl Default for Root1dOptions {
    fn default() -> Self {
        Self {
            bracket: Bracket::Expand { first_step: 1.0 },
            derivative: Derivative::Secant,
            x_tol: 0.0,
            x_rel_tol: 0.0,
            halving_test: true,
            max_evaluations: 200,
        }
    }
}
