//! Safeguarded Newton iteration for one unknown, `f(x) = 0`.
//!
//! [`find_root`] first finds a sign-change bracket ([`Bracket`]: a search inside hard
//! limits, an unbounded search by doubling steps, or a bracket given by the caller), then
//! refines it: a Newton step from the latest iterate (an end of the bracket), with the
//! slope of [`Derivative`] (secant through the previous iterate, or the point's own slope),
//! is taken when it lands strictly inside the bracket and, with
//! [`Root1dOptions::halving_test`], the previous step at least halved |f|; otherwise the
//! bracket is bisected. Convergence is thus guaranteed for any continuous f.
//!
//! The iteration ends ([`Root1dStatus`]) when a point meets its convergence test
//! ([`Point::converged`], e.g. `|f| ≤ f_tol` from [`Point::residual`], or any caller
//! predicate), when the bracket is narrower than the x tolerance (the end with the smaller
//! |f| is returned), when the next iterate would be an end of the bracket (stall), when f
//! keeps its sign over the hard limits, or when the evaluation budget is used up. NaN
//! values count as +∞ (a failed step), so the result never carries NaN. Each [`Point`]
//! carries a caller state (warm starts, results of inner solves), returned with the final
//! point; errors of the function are passed through unchanged.

mod options;
mod outcome;
mod point;
mod search;

pub use options::{Bracket, Derivative, Root1dOptions};
pub use outcome::{Root1dOutcome, Root1dStatus};
pub use point::Point;

/// Solves `f(x) = 0` from the guess `x0` (see the module docs).
///
/// `f` returns the [`Point`] at `x`; the state of a point may be kept twice by the
/// [`Bracket::Search`] search, hence `S: Clone`. Errors of `f` are returned at once;
/// failing to converge is not an error but a [`Root1dStatus`].
pub fn find_root<S: Clone, E>(
    f: impl FnMut(f64) -> Result<Point<S>, E>,
    x0: f64,
    options: &Root1dOptions,
) -> Result<Root1dOutcome<S>, E> {
    let mut ev = Evaluator { f, count: 0 };
    let start = match options.bracket {
        Bracket::Search {
            limits,
            fd_step,
            max_first_step,
        } => search::within_limits(
            &mut ev,
            x0,
            limits,
            fd_step,
            max_first_step,
            options.max_evaluations,
        )?,
        Bracket::Expand { first_step } => {
            search::expand(&mut ev, x0, first_step, options.max_evaluations)?
        }
        Bracket::Given { lo, hi } => search::given(&mut ev, x0, lo, hi)?,
    };
    match start {
        Start::Done(outcome) => Ok(outcome),
        Start::Bracketed(bracket) => refine(&mut ev, bracket, options),
    }
}

/// Counting evaluator of `f`; NaN values become +∞.
struct Evaluator<F> {
    f: F,
    count: usize,
}

impl<F> Evaluator<F> {
    fn at<S, E>(&mut self, x: f64) -> Result<Iterate<S>, E>
    where
        F: FnMut(f64) -> Result<Point<S>, E>,
    {
        self.count += 1;
        let mut point = (self.f)(x)?;
        if point.value.is_nan() {
            point.value = f64::INFINITY;
        }
        Ok(Iterate { x, point })
    }
}

/// An evaluated point.
#[derive(Clone)]
struct Iterate<S> {
    x: f64,
    point: Point<S>,
}

impl<S> Iterate<S> {
    fn value(&self) -> f64 {
        self.point.value
    }

    fn finish(
        self,
        evaluations: usize,
        bracket: (f64, f64),
        status: Root1dStatus,
    ) -> Root1dOutcome<S> {
        Root1dOutcome {
            x: self.x,
            value: self.point.value,
            state: self.point.state,
            evaluations,
            bracket,
            status,
        }
    }
}

/// Result of the bracket search.
enum Start<S> {
    /// Converged, or no bracket (no sign change, budget).
    Done(Root1dOutcome<S>),
    /// A bracket to refine.
    Bracketed(Bracketed<S>),
}

impl<S> Start<S> {
    /// Ends the search at `it`.
    fn done<E>(
        it: Iterate<S>,
        evaluations: usize,
        bracket: (f64, f64),
        status: Root1dStatus,
    ) -> Result<Self, E> {
        Ok(Self::Done(it.finish(evaluations, bracket, status)))
    }
}

/// Sign-change bracket: the latest iterate at one end, the other end evaluated or a limit.
struct Bracketed<S> {
    current: Iterate<S>,
    current_is_lo: bool,
    other_x: f64,
    other: Option<Point<S>>,
    /// f < 0 at the lower end.
    increasing: bool,
}

impl<S> Bracketed<S> {
    /// Bracket between two evaluated points of opposite signs; the one with the smaller |f|
    /// is the current iterate.
    fn between(p: Iterate<S>, q: Iterate<S>) -> Self {
        let (a, b) = if p.x < q.x { (p, q) } else { (q, p) };
        let increasing = a.value() < 0.0;
        let (current, other, current_is_lo) = if a.value().abs() < b.value().abs() {
            (a, b, true)
        } else {
            (b, a, false)
        };
        Self {
            current,
            current_is_lo,
            other_x: other.x,
            other: Some(other.point),
            increasing,
        }
    }

    fn bounds(&self) -> (f64, f64) {
        if self.current_is_lo {
            (self.current.x, self.other_x)
        } else {
            (self.other_x, self.current.x)
        }
    }

    /// Moves the end of the sign of `it` to `it`, which becomes the current iterate.
    fn update(&mut self, it: Iterate<S>) {
        let goes_lo = (it.value() < 0.0) == self.increasing;
        if goes_lo == self.current_is_lo {
            self.current = it;
        } else {
            let old = std::mem::replace(&mut self.current, it);
            self.other_x = old.x;
            self.other = Some(old.point);
            self.current_is_lo = goes_lo;
        }
    }

    /// The current iterate as the result.
    fn finish(self, evaluations: usize, status: Root1dStatus) -> Root1dOutcome<S> {
        let bounds = self.bounds();
        self.current.finish(evaluations, bounds, status)
    }

    /// The end with the smaller |f| (the current one on a tie) as the converged result.
    fn best(self, evaluations: usize) -> Root1dOutcome<S> {
        let bounds = self.bounds();
        let best = match self.other {
            Some(p) if p.value.abs() < self.current.value().abs() => Iterate {
                x: self.other_x,
                point: p,
            },
            _ => self.current,
        };
        best.finish(evaluations, bounds, Root1dStatus::Converged)
    }
}

/// Newton steps inside the bracket with bisection safeguard (module docs).
fn refine<S, E, F>(
    ev: &mut Evaluator<F>,
    mut bracket: Bracketed<S>,
    options: &Root1dOptions,
) -> Result<Root1dOutcome<S>, E>
where
    F: FnMut(f64) -> Result<Point<S>, E>,
{
    let mut previous = bracket.other.as_ref().map(|p| (bracket.other_x, p.value));
    let mut last = f64::INFINITY;
    loop {
        let (lo, hi) = bracket.bounds();
        if hi - lo <= options.x_tol + options.x_rel_tol * lo.abs().max(hi.abs()) {
            return Ok(bracket.best(ev.count));
        }
        let (x, v) = (bracket.current.x, bracket.current.value());
        let slope = match options.derivative {
            Derivative::Supplied => bracket.current.point.slope,
            Derivative::Secant => previous.map_or(f64::NAN, |(xp, vp)| (v - vp) / (x - xp)),
        };
        let newton = x - v / slope;
        let progress = !options.halving_test || v.abs() <= 0.5 * last;
        let next = if newton > lo && newton < hi && newton.is_finite() && progress {
            newton
        } else {
            0.5 * (lo + hi)
        };
        last = v.abs();
        if next == lo || next == hi {
            return Ok(bracket.finish(ev.count, Root1dStatus::Stalled));
        }
        if ev.count >= options.max_evaluations {
            return Ok(bracket.finish(ev.count, Root1dStatus::MaxEvaluations));
        }
        let it = ev.at(next)?;
        if it.point.converged {
            return Ok(it.finish(ev.count, (lo, hi), Root1dStatus::Converged));
        }
        previous = Some((x, v));
        bracket.update(it);
    }
}
