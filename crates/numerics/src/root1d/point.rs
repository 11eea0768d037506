//! One evaluation of the function of [`super::find_root`].

/// Value, slope, convergence test and caller state of the function at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Point<S> {
    /// Function value `f(x)`; NaN counts as +∞ (a failed step).
    pub value: f64,
    /// Slope `f′(x)`, used with [`super::Derivative::Supplied`] (NaN if unknown).
    pub slope: f64,
    /// True when `x` is accepted as the root (the caller's convergence test).
    pub converged: bool,
    /// Caller state at this point (e.g. results of an inner solve), returned with the root.
    pub state: S,
}

impl<S> Point<S> {
    /// Point with all fields given.
    pub fn new(value: f64, slope: f64, converged: bool, state: S) -> Self {
        Self {
            value,
            slope,
            converged,
            state,
        }
    }
}

impl Point<()> {
    /// Plain residual without slope or state, converged when `|value| ≤ f_tol`.
    pub fn residual(value: f64, f_tol: f64) -> Self {
        Self::new(value, f64::NAN, value.abs() <= f_tol, ())
    }
}
