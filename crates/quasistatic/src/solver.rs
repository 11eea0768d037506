//! Safeguarded Newton iteration for one unknown (SPEC §5.4–5.6, §9.2).
//!
//! Seed 001 solves the roller moment equation ΣT(ε_w) = 0 and the cage equation Φ(ε₀) = 0 "by
//! Newton's method with the derivative replaced by the ratio of the increments of the function
//! and the argument". [`solve_1d`] does exactly that — the first derivative is a forward
//! difference quotient, later ones the difference quotient of the last two iterates (secant) —
//! and adds the safeguards a production solver needs:
//!
//! * a sign-change **bracket** is searched first (Newton/secant steps, doubled while the residual
//!   keeps its sign, never leaving the hard limits);
//! * inside the bracket a Newton step that leaves the bracket, or fails to halve |f|, is replaced
//!   by a bisection step, so convergence is guaranteed for any continuous residual;
//! * the result always carries the last residual, never NaN: a NaN residual is treated as a
//!   failed step.

/// Tolerances of [`solve_1d`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RootOptions {
    /// Absolute tolerance on the residual: converged when |f| ≤ `f_tol`.
    pub f_tol: f64,
    /// Absolute tolerance on the unknown: converged when the bracket is narrower.
    pub x_tol: f64,
    /// Finite-difference step of the first derivative (absolute, > 0).
    pub fd_step: f64,
    /// Iteration budget (function evaluations).
    pub max_evaluations: usize,
    /// Largest first step of the bracket search (absolute); later steps grow at most 4× per
    /// iteration, so that the root nearest to the guess is bracketed first when the residual is
    /// not monotone (several equilibria).
    pub max_first_step: f64,
}

/// Result of [`solve_1d`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// Best estimate of the root (the iterate with the smallest |f| once converged).
    pub x: f64,
    /// Residual at `x`.
    pub f: f64,
    /// Function evaluations used.
    pub evaluations: usize,
    /// True when |f| ≤ f_tol or the bracket is narrower than x_tol.
    pub converged: bool,
    /// True when the residual keeps one sign over the whole search interval (no root inside
    /// the hard limits); `x` is then the limit with the smaller |f|.
    pub no_sign_change: bool,
}

/// Solves f(x) = 0 for x in `[limits.0, limits.1]` from the guess `x0` (see module docs).
pub fn solve_1d<F: FnMut(f64) -> f64>(
    mut f: F,
    x0: f64,
    limits: (f64, f64),
    opts: &RootOptions,
) -> Root {
    let (lim_lo, lim_hi) = if limits.0 <= limits.1 {
        limits
    } else {
        (limits.1, limits.0)
    };
    let mut evals = 0usize;
    let mut eval = |x: f64, evals: &mut usize| {
        *evals += 1;
        let v = f(x);
        if v.is_nan() { f64::INFINITY } else { v }
    };
    let x0 = if x0.is_finite() {
        x0.clamp(lim_lo, lim_hi)
    } else {
        0.5 * (lim_lo + lim_hi)
    };
    let f0 = eval(x0, &mut evals);
    let done = |x: f64, fx: f64, evals: usize, converged: bool| Root {
        x,
        f: fx,
        evaluations: evals,
        converged,
        no_sign_change: false,
    };
    if f0.abs() <= opts.f_tol {
        return done(x0, f0, evals, true);
    }
    // --- phase 1: bracket search with Newton / secant steps
    let h = opts.fd_step.abs().max(f64::MIN_POSITIVE);
    let x1 = if x0 + h <= lim_hi { x0 + h } else { x0 - h };
    let f1 = eval(x1, &mut evals);
    if f1.abs() <= opts.f_tol {
        return done(x1, f1, evals, true);
    }
    let (mut a, mut fa, mut b, mut fb);
    if f0.signum() != f1.signum() {
        (a, fa, b, fb) = if x0 < x1 {
            (x0, f0, x1, f1)
        } else {
            (x1, f1, x0, f0)
        };
    } else {
        let mut xp = x0;
        let mut fp = f0;
        let mut slope = (f1 - f0) / (x1 - x0);
        let span = (lim_hi - lim_lo).max(h);
        let mut step = if slope.is_finite() && slope != 0.0 {
            -fp / slope
        } else {
            0.01 * span
        };
        if !step.is_finite() || step == 0.0 {
            step = 0.01 * span;
        }
        let cap = opts.max_first_step.abs().max(h);
        step = step.clamp(-cap, cap);
        let (mut seen_lo, mut seen_hi) = (None, None);
        let found = loop {
            if evals >= opts.max_evaluations {
                return Root {
                    x: xp,
                    f: fp,
                    evaluations: evals,
                    converged: false,
                    no_sign_change: false,
                };
            }
            let xt = (xp + step).clamp(lim_lo, lim_hi);
            if xt == xp {
                // at a hard limit: look at the other one (every path below leaves the loop)
                let xo = if xp >= lim_hi { lim_lo } else { lim_hi };
                let fo = eval(xo, &mut evals);
                if fo.abs() <= opts.f_tol {
                    return done(xo, fo, evals, true);
                }
                if fo.signum() != f0.signum() {
                    break if xo < x0 {
                        (xo, fo, x0, f0)
                    } else {
                        (x0, f0, xo, fo)
                    };
                }
                let (xb, fbst) = if fo.abs() < fp.abs() {
                    (xo, fo)
                } else {
                    (xp, fp)
                };
                return Root {
                    x: xb,
                    f: fbst,
                    evaluations: evals,
                    converged: false,
                    no_sign_change: true,
                };
            }
            let ft = eval(xt, &mut evals);
            if ft.abs() <= opts.f_tol {
                return done(xt, ft, evals, true);
            }
            if ft.signum() != fp.signum() {
                break if xt < xp {
                    (xt, ft, xp, fp)
                } else {
                    (xp, fp, xt, ft)
                };
            }
            if xt == lim_lo {
                seen_lo = Some(ft);
            }
            if xt == lim_hi {
                seen_hi = Some(ft);
            }
            if let (Some(a), Some(b)) = (seen_lo, seen_hi) {
                // both limits seen with the sign of f0: no root inside the limits
                let (xb, fbst) = if a.abs() < b.abs() {
                    (lim_lo, a)
                } else {
                    (lim_hi, b)
                };
                return Root {
                    x: xb,
                    f: fbst,
                    evaluations: evals,
                    converged: false,
                    no_sign_change: true,
                };
            }
            if ft.abs() < fp.abs() {
                slope = (ft - fp) / (xt - xp);
                let newton = -ft / slope;
                // accelerate: between 2× and 4× the previous step in the same direction
                step = if newton.is_finite() && newton.signum() == step.signum() {
                    newton.abs().clamp(2.0 * step.abs(), 4.0 * step.abs()) * step.signum()
                } else {
                    2.0 * step
                };
                xp = xt;
                fp = ft;
            } else {
                // wrong direction or overshoot without sign change: turn round
                step *= -2.0;
            }
        };
        (a, fa, b, fb) = found;
    }
    // --- phase 2: Newton–secant inside the bracket with bisection safeguard
    let (mut x, mut fx) = if fa.abs() < fb.abs() {
        (a, fa)
    } else {
        (b, fb)
    };
    let mut x_prev = if x == a { b } else { a };
    let mut f_prev = if x == a { fb } else { fa };
    let mut last_abs = f64::INFINITY;
    loop {
        if fx.abs() <= opts.f_tol {
            return done(x, fx, evals, true);
        }
        if (b - a) <= opts.x_tol {
            let (xb, fbst) = [(a, fa), (b, fb)].into_iter().fold((x, fx), |best, p| {
                if p.1.abs() < best.1.abs() { p } else { best }
            });
            return done(xb, fbst, evals, true);
        }
        if evals >= opts.max_evaluations {
            return Root {
                x,
                f: fx,
                evaluations: evals,
                converged: false,
                no_sign_change: false,
            };
        }
        let slope = (fx - f_prev) / (x - x_prev);
        let mut xn = x - fx / slope;
        let progress = fx.abs() <= 0.5 * last_abs;
        if !(xn > a && xn < b && xn.is_finite() && progress) {
            xn = 0.5 * (a + b);
        }
        last_abs = fx.abs();
        let fnew = eval(xn, &mut evals);
        if fnew.signum() == fa.signum() {
            a = xn;
            fa = fnew;
        } else {
            b = xn;
            fb = fnew;
        }
        x_prev = x;
        f_prev = fx;
        x = xn;
        fx = fnew;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn opts() -> RootOptions {
        RootOptions {
            f_tol: 1e-13,
            x_tol: 1e-15,
            fd_step: 1e-7,
            max_evaluations: 100,
            max_first_step: 1.0,
        }
    }

    #[test]
    fn smooth_monotone_root() {
        let r = solve_1d(|x| 2.0 - x.exp(), 0.0, (-10.0, 10.0), &opts());
        assert!(r.converged);
        assert!((r.x - 2f64.ln()).abs() < 1e-12, "{r:?}");
        assert!(r.evaluations < 12, "{r:?}");
    }

    #[test]
    fn far_root_and_kink() {
        // piecewise linear with a kink, root far from the guess
        let f = |x: f64| {
            if x < 3.0 {
                1.0 - 0.01 * x
            } else {
                0.97 - 5.0 * (x - 3.0)
            }
        };
        let r = solve_1d(f, -50.0, (-100.0, 100.0), &opts());
        assert!(r.converged, "{r:?}");
        assert!((r.x - (3.0 + 0.97 / 5.0)).abs() < 1e-12);
    }

    #[test]
    fn discontinuous_sign_change_is_located() {
        let f = |x: f64| if x < 0.3 { 1.0 } else { -1.0 };
        let r = solve_1d(f, 0.0, (-1.0, 1.0), &opts());
        assert!(r.converged);
        assert!((r.x - 0.3).abs() < 1e-12);
    }

    #[test]
    fn no_root_reports_limit() {
        let r = solve_1d(|x| 1.0 + x * x, 0.0, (-1.0, 1.0), &opts());
        assert!(!r.converged);
        assert!(r.no_sign_change);
        assert!(r.f.is_finite());
    }
}
