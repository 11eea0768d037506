//! Damped Newton iteration for two nonlinear equations `r(x) = 0`, `x ∈ ℝ²`.
//!
//! Every iteration evaluates a [`Sample`] (residual `r`, Jacobian `J`, residual scale) at the
//! current point and stops when `max_i |r_i| ≤ tolerance · scale`. Otherwise the step `s`
//! solves `(J + λ_eff D) s = −r`, `λ_eff = λ + min_damping`, with the damping scales `D`
//! of [`Damping`] (Levenberg–Marquardt). A singular damped matrix (`|det| ≤
//! singular_tolerance · D₁D₂`) raises `λ`, or uses the sample's fallback step when it has
//! one. The step is safeguarded by backtracking (`α = 1, ½, ¼, …`): a trial `x + α s` is
//! accepted when
//!
//! * the potential `Π` (if the samples carry one; `r` must then be `∇Π`) decreases by the
//!   Armijo condition `Π(x + α s) ≤ Π(x) + c α r·s`, or
//! * the residual norm decreases: `|r(x + α s)| < (1 − c α) |r(x)|`, or
//! * the trial meets the convergence test,
//!
//! with `c` = [`Newton2dOptions::sufficient_decrease`]. A full step (`α = 1`) divides `λ` by
//! 10 (down to 0); a failed search multiplies it by 10 and retries. When no damping gives an
//! acceptable step the search has stalled: the point is still accepted if
//! `max_i |r_i| ≤ max(tolerance, stall_tolerance) · scale`.
//!
//! Steps are taken in the scaled unknowns `y_i = step_scale_i · x_i`: the Jacobian of a
//! sample is `∂r/∂y` and the update is `x_i += α s_i / step_scale_i`.

mod damping;
mod options;
mod outcome;
mod sample;

pub use damping::Damping;
pub use options::Newton2dOptions;
pub use outcome::{Newton2dOutcome, Newton2dStatus};
pub use sample::Sample;

/// Damping attempts (new `λ`) per Newton iteration before the search counts as stalled.
const MAX_DAMPING_ATTEMPTS: usize = 40;

/// Solves `r(x) = 0` from `x0` (see the module docs).
///
/// `evaluate(x, state)` returns the [`Sample`] at `x`; `state` is the state of the current
/// point (`state0` for the first evaluation), e.g. a warm start for inner solvers, and the
/// state of the final point is returned in the outcome. Errors of `evaluate` are passed
/// through unchanged; failing to converge is not an error but a [`Newton2dStatus`].
pub fn solve_2d<T, E>(
    mut evaluate: impl FnMut([f64; 2], &T) -> Result<Sample<T>, E>,
    x0: [f64; 2],
    state0: T,
    options: &Newton2dOptions,
) -> Result<Newton2dOutcome<T>, E> {
    let converged = |s: &Sample<T>| max_abs(s.residual) <= options.tolerance * s.scale;
    let mut x = x0;
    let mut current = evaluate(x, &state0)?;
    let mut lambda = 0.0_f64;
    let mut iterations = 0;
    let status = loop {
        if converged(&current) {
            break Newton2dStatus::Converged;
        }
        if iterations >= options.max_iterations {
            break Newton2dStatus::IterationLimit;
        }
        iterations += 1;
        let r = current.residual;
        let norm0 = r[0].hypot(r[1]);
        let mut accepted = false;
        for _ in 0..MAX_DAMPING_ATTEMPTS {
            let Some(step) = damped_step(&current, lambda + options.min_damping, options) else {
                lambda = (10.0 * lambda).max(options.singular_damping);
                continue;
            };
            let slope = r[0] * step[0] + r[1] * step[1];
            let mut alpha = 1.0_f64;
            for _ in 0..options.max_halvings {
                let trial_x = [
                    x[0] + alpha * step[0] / options.step_scale[0],
                    x[1] + alpha * step[1] / options.step_scale[1],
                ];
                let trial = evaluate(trial_x, &current.state)?;
                let c = options.sufficient_decrease;
                let armijo = match (current.potential, trial.potential) {
                    (Some(p0), Some(p)) => p <= p0 + c * alpha * slope,
                    _ => false,
                };
                let norm = trial.residual[0].hypot(trial.residual[1]);
                if armijo || norm < (1.0 - c * alpha) * norm0 || converged(&trial) {
                    x = trial_x;
                    current = trial;
                    accepted = true;
                    break;
                }
                alpha *= 0.5;
            }
            if accepted {
                if alpha == 1.0 {
                    lambda *= 0.1;
                    if lambda < 1e-12 {
                        lambda = 0.0;
                    }
                }
                break;
            }
            lambda = (10.0 * lambda).max(options.restart_damping);
            if lambda > options.max_damping {
                break;
            }
        }
        if !accepted {
            let stall = options.tolerance.max(options.stall_tolerance);
            break if max_abs(current.residual) <= stall * current.scale {
                Newton2dStatus::Stalled
            } else {
                Newton2dStatus::NoDescent
            };
        }
    };
    Ok(Newton2dOutcome {
        x,
        residual: current.residual,
        scale: current.scale,
        iterations,
        status,
        state: current.state,
    })
}

/// Levenberg–Marquardt step `−(J + λ D)⁻¹ r`; the sample's fallback step (or `None`) when the
/// damped matrix is singular.
fn damped_step<T>(sample: &Sample<T>, lambda: f64, options: &Newton2dOptions) -> Option<[f64; 2]> {
    let [[j11, j12], [j21, j22]] = sample.jacobian;
    let [r1, r2] = sample.residual;
    let d = options.damping.scales(sample.jacobian);
    let a11 = j11 + lambda * d[0];
    let a22 = j22 + lambda * d[1];
    let det = a11 * a22 - j12 * j21;
    // written as `|det| > …` so that a NaN determinant counts as singular
    if det.abs() > options.singular_tolerance * d[0] * d[1] {
        Some([-(a22 * r1 - j12 * r2) / det, -(a11 * r2 - j21 * r1) / det])
    } else {
        sample.fallback_step
    }
}

/// `max(|r₁|, |r₂|)`.
fn max_abs(r: [f64; 2]) -> f64 {
    r[0].abs().max(r[1].abs())
}
