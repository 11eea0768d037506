//! One evaluation of the system of [`super::solve_2d`].

/// Residual, Jacobian and bookkeeping of the system at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample<T> {
    /// Residual `r(x)`.
    pub residual: [f64; 2],
    /// Jacobian `∂r_i/∂y_j` with respect to the scaled unknowns `y = step_scale · x`.
    pub jacobian: [[f64; 2]; 2],
    /// Residual scale of the convergence test (> 0, units of `r`).
    pub scale: f64,
    /// Potential `Π` with `∇_y Π = r`, if the system has one (enables the Armijo test).
    pub potential: Option<f64>,
    /// Step in `y` tried when the damped Jacobian is singular (e.g. nothing loaded);
    /// without one the damping is raised instead.
    pub fallback_step: Option<[f64; 2]>,
    /// Caller state at this point (warm start of the next evaluation, final results).
    pub state: T,
}

impl<T> Sample<T> {
    /// Sample without potential and fallback step.
    pub fn new(residual: [f64; 2], jacobian: [[f64; 2]; 2], scale: f64, state: T) -> Self {
        Self {
            residual,
            jacobian,
            scale,
            potential: None,
            fallback_step: None,
            state,
        }
    }

    /// Adds the potential `Π` (the residual must be its gradient).
    pub fn with_potential(self, potential: f64) -> Self {
        Self {
            potential: Some(potential),
            ..self
        }
    }

    /// Adds the step used when the damped Jacobian is singular.
    pub fn with_fallback_step(self, step: [f64; 2]) -> Self {
        Self {
            fallback_step: Some(step),
            ..self
        }
    }
}
