//! Knobs of [`super::solve_2d`].

use super::Damping;

/// Options of [`super::solve_2d`]; the defaults suit a residual that is the gradient of a
/// convex potential (symmetric positive semi-definite Jacobian).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Newton2dOptions {
    /// Converged when `max_i |r_i| ≤ tolerance · scale` (scale from the [`super::Sample`]).
    /// Default `1e-12`.
    pub tolerance: f64,
    /// A stalled search (no acceptable step for any damping) still counts as a solution when
    /// `max_i |r_i| ≤ max(tolerance, stall_tolerance) · scale`. Default `1e-9`; `0` makes a
    /// stall a failure.
    pub stall_tolerance: f64,
    /// Maximum number of Newton iterations (accepted steps). Default 100.
    pub max_iterations: usize,
    /// Maximum number of trial steps of one backtracking line search (`α = 1, ½, …`).
    /// Default 30.
    pub max_halvings: usize,
    /// Sufficient-decrease constant `c` of the acceptance tests (Armijo on the potential,
    /// `(1 − cα)` on the residual norm; `0` accepts any strict decrease). Default `1e-4`.
    pub sufficient_decrease: f64,
    /// Scaling of the Levenberg–Marquardt term. Default
    /// `Damping::Diagonal { relative_floor: 1e-12 }`.
    pub damping: Damping,
    /// Damping always added to `λ` (keeps a direction without stiffness from getting an
    /// unbounded step). Default `0`.
    pub min_damping: f64,
    /// Least `λ` after a singular damped matrix without fallback step (`λ ← max(10λ, ·)`).
    /// Default `1e-10`.
    pub singular_damping: f64,
    /// Least `λ` after a failed line search (`λ ← max(10λ, ·)`). Default `1e-6`.
    pub restart_damping: f64,
    /// The search stalls once a failed line search raises `λ` above this. Default `1e12`.
    pub max_damping: f64,
    /// The damped matrix `A = J + λ_eff D` counts as singular when
    /// `|det A| ≤ singular_tolerance · D₁ D₂`. Default `1e-13`.
    pub singular_tolerance: f64,
    /// Scales `y_i = step_scale_i · x_i` of the unknowns in which the Jacobian and the steps
    /// are expressed (> 0). Default `[1, 1]`.
    pub step_scale: [f64; 2],
}

impl Default for Newton2dOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            stall_tolerance: 1e-9,
            max_iterations: 100,
            max_halvings: 30,
            sufficient_decrease: 1e-4,
            damping: Damping::Diagonal {
                relative_floor: 1e-12,
            },
            min_damping: 0.0,
            singular_damping: 1e-10,
            restart_damping: 1e-6,
            max_damping: 1e12,
            singular_tolerance: 1e-13,
            step_scale: [1.0, 1.0],
        }
    }
}
