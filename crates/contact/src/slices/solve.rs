//! Inverse slice problems (SPEC §2.1): approach for a given force at fixed tilt (1-D) and
//! approach + tilt for a given force and moment (2-D).
//!
//! The 2-D problem is the stationarity condition of the convex potential
//! `Π(δ0, θ) = Σ U_s(δ_s) − Q δ0 − (M/L_h) θ` with `θ = L_h tan φ` (`L_h = max |x_s|`),
//! `U_s' = Q_s`: its gradient is the residual `(Q(δ0,φ) − Q, (M(δ0,φ) − M)/L_h)` and its Hessian
//! the (scaled) Jacobian `Σ k_s' [1 ξ; ξ ξ²]`, `ξ = x_s/L_h`, which is positive semi-definite.
//! Newton steps are therefore descent directions of `Π`; near-singular Hessians (few loaded
//! slices) are regularised Levenberg–Marquardt style and every step is safeguarded by
//! backtracking (accepted when `Π` decreases sufficiently or the residual norm decreases), see
//! [`rolldyn_numerics::solve_2d`].

use super::SliceError;
use super::roller::{SliceLoad, SlicedRoller};
use rolldyn_numerics::{Newton2dOptions, Sample, solve_2d};

/// Options of the inverse solvers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Relative tolerance on the residual: `|ΔQ| ≤ tol·Q` and `|ΔM|/L_h ≤ tol·Q`
    /// (`L_h = max |x_s|`). Default `1e-12`.
    pub tolerance: f64,
    /// Maximum number of Newton iterations. Default 100.
    pub max_iterations: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            max_iterations: 100,
        }
    }
}

/// Solution of an inverse slice problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliceSolution {
    /// Approach `δ0` (m).
    pub approach: f64,
    /// Tilt `φ` (rad).
    pub tilt: f64,
    /// Resultants and Jacobian at the solution (with respect to `(δ0, φ)`).
    pub load: SliceLoad,
    /// Newton iterations used.
    pub iterations: usize,
}

impl SlicedRoller {
    fn check_tilt(tilt: f64) -> Result<f64, SliceError> {
        if tilt.is_finite() && tilt.abs() < std::f64::consts::FRAC_PI_2 {
            Ok(tilt.tan())
        } else {
            Err(SliceError::InvalidInput(
                "tilt must be finite with |φ| < π/2",
            ))
        }
    }

    /// Approach `δ0` (m) at which the total force equals `force` (N) for a fixed tilt `φ`
    /// (rad). `Q(δ0)` is continuous and non-decreasing (strictly increasing once any slice is
    /// loaded), so the root is bracketed by `[min_s(z_s − x_s tan φ), max_s(z_s − x_s tan φ) +
    /// (Q/Σk_s)^{1/n}]` and found by Newton steps from the upper end, with bisection whenever a
    /// step leaves the bracket.
    ///
    /// `force ≤ 0` returns the zero-force solution: the approach at which the first slice
    /// touches (all slices unloaded).
    pub fn solve_approach(
        &self,
        force: f64,
        tilt: f64,
        options: &SolveOptions,
    ) -> Result<SliceSolution, SliceError> {
        if force.is_nan() {
            return Err(SliceError::InvalidInput("force is NaN"));
        }
        let t = Self::check_tilt(tilt)?;
        let (approach, iterations) = self.solve_approach_tan(force, t, options)?;
        Ok(SliceSolution {
            approach,
            tilt,
            load: self.evaluate_totals(approach, tilt),
            iterations,
        })
    }

    /// 1-D solve in terms of `t = tan φ`. Returns `(δ0, iterations)`.
    pub(crate) fn solve_approach_tan(
        &self,
        force: f64,
        t: f64,
        options: &SolveOptions,
    ) -> Result<(f64, usize), SliceError> {
        let x = self.positions();
        let z = self.drops();
        let mut touch = f64::INFINITY;
        let mut deepest = f64::NEG_INFINITY;
        for i in 0..x.len() {
            let o = z[i] - x[i] * t;
            touch = touch.min(o);
            deepest = deepest.max(o);
        }
        if force <= 0.0 {
            return Ok((touch, 0));
        }
        if !force.is_finite() {
            return Err(SliceError::InvalidInput("force must be finite"));
        }
        let ksum: f64 = self.coefficients().iter().sum();
        let n = self.exponent();
        let mut lo = touch;
        // at δ0 = hi every slice has δ_s ≥ (Q/Σk)^{1/n}, hence Q(hi) ≥ Q
        let mut hi = deepest + (force / ksum).powf(1.0 / n);
        let mut d = hi;
        let tol = options.tolerance.max(0.0) * force;
        for it in 1..=options.max_iterations.max(1) {
            let (load, _) = self.eval_tan::<false, false>(d, t, &mut []);
            let f = load.force - force;
            if f.abs() <= tol {
                return Ok((d, it));
            }
            if f > 0.0 {
                hi = d;
            } else {
                lo = d;
            }
            let kq = load.dforce_dapproach;
            let newton = if kq > 0.0 { d - f / kq } else { f64::NAN };
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let width_tol = 4.0 * f64::EPSILON * lo.abs().max(hi.abs());
            if next == d || hi - lo <= width_tol {
                // bracket at machine resolution: the best representable approach
                return Ok((d, it));
            }
            d = next;
        }
        let (load, _) = self.eval_tan::<false, false>(d, t, &mut []);
        Err(SliceError::NoConvergence {
            iterations: options.max_iterations,
            residual: ((load.force - force) / force).abs(),
        })
    }

    /// Approach `δ0` (m) and tilt `φ` (rad) at which the slices carry force `force` (N) and
    /// moment `moment` (N·m, `M = Σ Q_s x_s`, see the sign convention of [`SlicedRoller`]).
    ///
    /// 2-D Newton on the analytic Jacobian, started from the uniform-load solution (`φ = 0`,
    /// `δ0` from [`SlicedRoller::solve_approach`]); Levenberg–Marquardt regularisation when the
    /// Jacobian is near-singular (only part of the roller loaded), backtracking on the potential
    /// / residual norm. With `M = 0` and a symmetric profile the start point is already the
    /// solution and `φ = 0` exactly.
    ///
    /// Errors: `force ≤ 0` with `moment ≠ 0` ([`SliceError::MomentWithoutForce`]; `force ≤ 0`
    /// with `moment = 0` returns the zero-force solution), eccentricity `M/Q` outside the span
    /// of the slice mid-points ([`SliceError::MomentOutOfRange`]), no convergence.
    pub fn solve_approach_tilt(
        &self,
        force: f64,
        moment: f64,
        options: &SolveOptions,
    ) -> Result<SliceSolution, SliceError> {
        if force.is_nan() || force == f64::INFINITY || !moment.is_finite() {
            return Err(SliceError::InvalidInput("force and moment must be finite"));
        }
        if force <= 0.0 {
            if moment != 0.0 {
                return Err(SliceError::MomentWithoutForce);
            }
            return self.solve_approach(0.0, 0.0, options);
        }
        let (x_min, x_max) = self.span();
        let ecc = moment / force;
        let ls = self.x_scale;
        if x_min == x_max {
            // a single slice position: M = Q x is the only reachable moment, tilt is free
            if (ecc - x_min).abs() <= options.tolerance.max(1e-15) * ls {
                return self.solve_approach(force, 0.0, options);
            }
            return Err(SliceError::MomentOutOfRange {
                eccentricity: ecc,
                x_min,
                x_max,
            });
        }
        if !(ecc > x_min && ecc < x_max) {
            return Err(SliceError::MomentOutOfRange {
                eccentricity: ecc,
                x_min,
                x_max,
            });
        }
        let tol = options.tolerance.max(0.0);
        let m_scaled = moment / ls;
        // unknowns u = (δ0, θ), θ = L_h tan φ
        let (d0, start_iterations) = self.solve_approach_tan(force, 0.0, options)?;
        let evaluate = |u: [f64; 2], _: &()| -> Result<Sample<()>, SliceError> {
            let [d0, theta] = u;
            let (load, energy) = self.eval_tan::<false, true>(d0, theta / ls, &mut []);
            let h11 = load.dforce_dapproach;
            let h12 = load.dforce_dtilt / ls;
            let h22 = load.dmoment_dtilt / (ls * ls);
            let sample = Sample::new(
                [load.force - force, load.moment / ls - m_scaled],
                [[h11, h12], [h12, h22]],
                force,
                (),
            )
            .with_potential(energy - force * d0 - m_scaled * theta);
            if h11.is_nan() || h11 <= 0.0 {
                // nothing loaded (cannot happen after an accepted step from a loaded state,
                // but be safe): reload at the current tilt
                let (d, _) = self.solve_approach_tan(force, theta / ls, options)?;
                return Ok(sample.with_fallback_step([d - d0, 0.0]));
            }
            Ok(sample)
        };
        let newton = Newton2dOptions {
            tolerance: tol,
            max_iterations: options.max_iterations.max(1),
            ..Newton2dOptions::default()
        };
        let outcome = solve_2d(evaluate, [d0, 0.0], (), &newton)?;
        let [d0, theta] = outcome.x;
        let iterations = start_iterations + outcome.iterations;
        if outcome.converged() {
            return Ok(self.finish(d0, theta, iterations));
        }
        Err(SliceError::NoConvergence {
            iterations,
            residual: outcome.residual[0].abs().max(outcome.residual[1].abs()) / force,
        })
    }

    fn finish(&self, d0: f64, theta: f64, iterations: usize) -> SliceSolution {
        let tilt = (theta / self.x_scale).atan();
        SliceSolution {
            approach: d0,
            tilt,
            load: self.evaluate_totals(d0, tilt),
            iterations,
        }
    }
}
