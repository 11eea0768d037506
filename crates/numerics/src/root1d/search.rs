//! Bracket searches of [`super::find_root`] ([`super::Bracket`]).

use super::{Bracketed, Evaluator, Iterate, Point, Root1dStatus, Start};

/// [`super::Bracket::Search`]: Newton/secant steps inside the hard limits.
pub(super) fn within_limits<S: Clone, E, F>(
    ev: &mut Evaluator<F>,
    x0: f64,
    limits: (f64, f64),
    fd_step: f64,
    max_first_step: f64,
    max_evaluations: usize,
) -> Result<Start<S>, E>
where
    F: FnMut(f64) -> Result<Point<S>, E>,
{
    let (limits, x0) = inside(limits, x0);
    let (lim_lo, lim_hi) = limits;
    let done = |it, evaluations, status| Start::done(it, evaluations, limits, status);
    let p0 = ev.at(x0)?;
    if p0.point.converged {
        return done(p0, ev.count, Root1dStatus::Converged);
    }
    // forward-difference slope
    let h = fd_step.abs().max(f64::MIN_POSITIVE);
    let x1 = if x0 + h <= lim_hi { x0 + h } else { x0 - h };
    let p1 = ev.at(x1)?;
    if p1.point.converged {
        return done(p1, ev.count, Root1dStatus::Converged);
    }
    let f0 = p0.value();
    if f0.signum() != p1.value().signum() {
        return Ok(Start::Bracketed(Bracketed::between(p0, p1)));
    }
    let slope = (p1.value() - f0) / (x1 - x0);
    let span = (lim_hi - lim_lo).max(h);
    let mut step = if slope.is_finite() && slope != 0.0 {
        -f0 / slope
    } else {
        0.01 * span
    };
    if !step.is_finite() || step == 0.0 {
        step = 0.01 * span;
    }
    let cap = max_first_step.abs().max(h);
    step = step.clamp(-cap, cap);
    // best point so far; the limits once seen with the sign of f0
    let mut best = p0.clone();
    let (mut seen_lo, mut seen_hi) = (None, None);
    loop {
        if ev.count >= max_evaluations {
            return done(best, ev.count, Root1dStatus::MaxEvaluations);
        }
        let xt = (best.x + step).clamp(lim_lo, lim_hi);
        if xt == best.x {
            // at a hard limit: look at the other one (every path below leaves the loop)
            let xo = if best.x >= lim_hi { lim_lo } else { lim_hi };
            let po = ev.at(xo)?;
            if po.point.converged {
                return done(po, ev.count, Root1dStatus::Converged);
            }
            if po.value().signum() != f0.signum() {
                return Ok(Start::Bracketed(Bracketed::between(po, p0)));
            }
            let smaller = if po.value().abs() < best.value().abs() {
                po
            } else {
                best
            };
            return done(smaller, ev.count, Root1dStatus::NoSignChange);
        }
        let pt = ev.at(xt)?;
        if pt.point.converged {
            return done(pt, ev.count, Root1dStatus::Converged);
        }
        if pt.value().signum() != best.value().signum() {
            return Ok(Start::Bracketed(Bracketed::between(pt, best)));
        }
        if xt == lim_lo {
            seen_lo = Some(pt.clone());
        }
        if xt == lim_hi {
            seen_hi = Some(pt.clone());
        }
        (seen_lo, seen_hi) = match (seen_lo, seen_hi) {
            (Some(a), Some(b)) => {
                // both limits seen with the sign of f0: no root inside the limits
                let smaller = if a.value().abs() < b.value().abs() {
                    a
                } else {
                    b
                };
                return done(smaller, ev.count, Root1dStatus::NoSignChange);
            }
            seen => seen,
        };
        if pt.value().abs() < best.value().abs() {
            let slope = (pt.value() - best.value()) / (xt - best.x);
            let newton = -pt.value() / slope;
            // accelerate: between 2× and 4× the previous step in the same direction
            step = if newton.is_finite() && newton.signum() == step.signum() {
                newton.abs().clamp(2.0 * step.abs(), 4.0 * step.abs()) * step.signum()
            } else {
                2.0 * step
            };
            best = pt;
        } else {
            // wrong direction or overshoot without sign change: turn round
            step *= -2.0;
        }
    }
}

/// [`super::Bracket::Expand`]: steps of doubling length against the sign of f.
pub(super) fn expand<S, E, F>(
    ev: &mut Evaluator<F>,
    x0: f64,
    first_step: f64,
    max_evaluations: usize,
) -> Result<Start<S>, E>
where
    F: FnMut(f64) -> Result<Point<S>, E>,
{
    let mut cur = ev.at(x0)?;
    // interval holding the root of a non-decreasing f, from the sign at `cur`
    let bounds = |cur: &Iterate<S>| {
        if cur.value() < 0.0 {
            (cur.x, f64::INFINITY)
        } else {
            (f64::NEG_INFINITY, cur.x)
        }
    };
    if cur.point.converged {
        return Start::done(
            cur,
            ev.count,
            (f64::NEG_INFINITY, f64::INFINITY),
            Root1dStatus::Converged,
        );
    }
    let dir = if cur.value() < 0.0 { 1.0 } else { -1.0 };
    let mut h = first_step;
    loop {
        if ev.count >= max_evaluations {
            let b = bounds(&cur);
            return Start::done(cur, ev.count, b, Root1dStatus::MaxEvaluations);
        }
        let next = ev.at(cur.x + dir * h)?;
        h *= 2.0;
        if next.point.converged {
            return Start::done(next, ev.count, bounds(&cur), Root1dStatus::Converged);
        }
        if (next.value() < 0.0) != (cur.value() < 0.0) {
            let current_is_lo = next.value() < 0.0;
            return Ok(Start::Bracketed(Bracketed {
                current: next,
                current_is_lo,
                other_x: cur.x,
                other: Some(cur.point),
                increasing: true,
            }));
        }
        cur = next;
    }
}

/// [`super::Bracket::Given`]: one evaluation at the clamped guess.
pub(super) fn given<S, E, F>(
    ev: &mut Evaluator<F>,
    x0: f64,
    lo: f64,
    hi: f64,
) -> Result<Start<S>, E>
where
    F: FnMut(f64) -> Result<Point<S>, E>,
{
    let ((lo, hi), x0) = inside((lo, hi), x0);
    let it = ev.at(x0)?;
    if it.point.converged {
        return Start::done(it, ev.count, (lo, hi), Root1dStatus::Converged);
    }
    let current_is_lo = it.value() < 0.0;
    Ok(Start::Bracketed(Bracketed {
        current: it,
        current_is_lo,
        other_x: if current_is_lo { hi } else { lo },
        other: None,
        increasing: true,
    }))
}

/// The limits in increasing order and the guess clamped to them (their midpoint if it is
/// not finite).
fn inside(limits: (f64, f64), x0: f64) -> ((f64, f64), f64) {
    let (lo, hi) = if limits.0 <= limits.1 {
        limits
    } else {
        (limits.1, limits.0)
    };
    let x0 = if x0.is_finite() {
        x0.clamp(lo, hi)
    } else {
        0.5 * (lo + hi)
    };
    ((lo, hi), x0)
}
