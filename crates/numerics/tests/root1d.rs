//! Safeguarded 1-D root finder: the three bracket searches, both slopes, the end states and
//! passed-through errors.

use rolldyn_numerics::{
    Bracket, Derivative, Point, Root1dOptions, Root1dOutcome, Root1dStatus, find_root,
};
use std::convert::Infallible;

/// Secant search inside `limits` with the tolerances of the quasi-static cage solve.
fn secant(limits: (f64, f64)) -> Root1dOptions {
    Root1dOptions {
        bracket: Bracket::Search {
            limits,
            fd_step: 1e-7,
            max_first_step: 1.0,
        },
        derivative: Derivative::Secant,
        x_tol: 1e-15,
        max_evaluations: 100,
        ..Root1dOptions::default()
    }
}

/// Solves a plain residual `f` to |f| ≤ 1e-13.
fn plain(f: impl Fn(f64) -> f64, x0: f64, options: &Root1dOptions) -> Root1dOutcome<()> {
    let Ok(root) = find_root(
        |x| Ok::<_, Infallible>(Point::residual(f(x), 1e-13)),
        x0,
        options,
    );
    root
}

#[test]
fn secant_smooth_monotone_root() {
    let r = plain(|x| 2.0 - x.exp(), 0.0, &secant((-10.0, 10.0)));
    assert!(r.converged());
    assert!((r.x - 2f64.ln()).abs() < 1e-12, "{r:?}");
    assert!(r.evaluations < 12, "{r:?}");
    assert!(r.value.abs() <= 1e-13);
}

#[test]
fn secant_far_root_and_kink() {
    // piecewise linear with a kink, root far from the guess
    let f = |x: f64| {
        if x < 3.0 {
            1.0 - 0.01 * x
        } else {
            0.97 - 5.0 * (x - 3.0)
        }
    };
    let r = plain(f, -50.0, &secant((-100.0, 100.0)));
    assert!(r.converged(), "{r:?}");
    assert!((r.x - (3.0 + 0.97 / 5.0)).abs() < 1e-12);
}

#[test]
fn discontinuous_sign_change_is_located() {
    let r = plain(
        |x| if x < 0.3 { 1.0 } else { -1.0 },
        0.0,
        &secant((-1.0, 1.0)),
    );
    assert!(r.converged());
    assert!((r.x - 0.3).abs() < 1e-12);
    assert!(r.bracket.1 - r.bracket.0 <= 1e-15);
}

#[test]
fn no_sign_change_reports_the_better_limit() {
    let r = plain(|x| 1.0 + x * x, 0.0, &secant((-1.0, 1.0)));
    assert!(!r.converged());
    assert_eq!(r.status, Root1dStatus::NoSignChange);
    assert!(r.value.is_finite());
    // f keeps its sign: the result is a limit (f = 2 at both) or the best search point
    assert!(r.value <= 2.0);
    // decreasing residual with its root beyond the upper limit: the upper limit
    let r = plain(|x| 5.0 - x, 0.0, &secant((-1.0, 2.0)));
    assert_eq!(r.status, Root1dStatus::NoSignChange);
    assert_eq!(r.x, 2.0);
    assert_eq!(r.value, 3.0);
}

#[test]
fn root_at_a_hard_limit() {
    // root exactly at the upper limit, guess at the lower one
    let r = plain(|x| x - 1.0, -1.0, &secant((-1.0, 1.0)));
    assert!(r.converged(), "{r:?}");
    assert!((r.x - 1.0).abs() < 1e-13);
}

#[test]
fn nan_counts_as_a_failed_step() {
    // NaN left of the root: never returned, the root is still found
    let f = |x: f64| if x < -0.5 { f64::NAN } else { x - 0.25 };
    let r = plain(f, 0.9, &secant((-1.0, 1.0)));
    assert!(r.converged(), "{r:?}");
    assert!((r.x - 0.25).abs() < 1e-13);
}

/// Monotone f = x³ + x − 10 (root 2) with its analytic slope and the point count as state.
fn cubic(x: f64, count: &mut usize) -> Result<Point<usize>, Infallible> {
    *count += 1;
    let v = x.powi(3) + x - 10.0;
    Ok(Point::new(v, 3.0 * x * x + 1.0, v.abs() <= 1e-12, *count))
}

#[test]
fn analytic_slope_with_expanding_search_and_state() {
    let mut count = 0;
    let options = Root1dOptions {
        bracket: Bracket::Expand { first_step: 0.1 },
        derivative: Derivative::Supplied,
        ..Root1dOptions::default()
    };
    let Ok(r) = find_root(|x| cubic(x, &mut count), -3.0, &options);
    assert!(r.converged(), "{r:?}");
    assert!((r.x - 2.0).abs() < 1e-13);
    // the state is that of the returned point, the last one evaluated
    assert_eq!(r.state, r.evaluations);
    assert_eq!(count, r.evaluations);
    assert!(r.evaluations < 30, "{r:?}");
}

#[test]
fn analytic_slope_in_a_given_bracket() {
    let mut count = 0;
    let options = Root1dOptions {
        bracket: Bracket::Given { lo: 0.0, hi: 5.0 },
        derivative: Derivative::Supplied,
        halving_test: false,
        ..Root1dOptions::default()
    };
    let Ok(r) = find_root(|x| cubic(x, &mut count), 5.0, &options);
    assert!(r.converged(), "{r:?}");
    assert!((r.x - 2.0).abs() < 1e-13);
    // Newton from the convex side: monotone quadratic convergence, no bisection
    assert!(r.evaluations <= 8, "{r:?}");
}

#[test]
fn unreachable_tolerance_stalls_at_the_root() {
    // never "converged": the bracket shrinks to adjacent floats around √2
    let options = Root1dOptions {
        bracket: Bracket::Given { lo: 0.0, hi: 2.0 },
        derivative: Derivative::Supplied,
        ..Root1dOptions::default()
    };
    let Ok(r) = find_root(
        |x| Ok::<_, Infallible>(Point::new(x * x - 2.0, 2.0 * x, false, ())),
        1.0,
        &options,
    );
    assert_eq!(r.status, Root1dStatus::Stalled);
    assert!((r.x - 2f64.sqrt()).abs() <= 4.0 * f64::EPSILON);
    // with a relative x tolerance the same bracket counts as converged
    let Ok(r) = find_root(
        |x| Ok::<_, Infallible>(Point::new(x * x - 2.0, 2.0 * x, false, ())),
        1.0,
        &Root1dOptions {
            x_rel_tol: 1e-12,
            ..options
        },
    );
    assert!(r.converged(), "{r:?}");
    assert!(r.bracket.1 - r.bracket.0 <= 1e-12 * 1.5);
}

#[test]
fn evaluation_budget_is_reported() {
    let options = Root1dOptions {
        max_evaluations: 5,
        ..secant((-1e6, 1e6))
    };
    let r = plain(|x| (x - 3e5).atan(), 0.0, &options);
    assert_eq!(r.status, Root1dStatus::MaxEvaluations);
    assert_eq!(r.evaluations, 5);
    assert!(r.value.is_finite());
}

#[test]
fn errors_of_the_function_pass_through() {
    let mut calls = 0;
    let options = Root1dOptions {
        bracket: Bracket::Expand { first_step: 1.0 },
        ..Root1dOptions::default()
    };
    let r = find_root(
        |x| {
            calls += 1;
            if x > 2.5 {
                Err(format!("out of range at {x}"))
            } else {
                Ok(Point::residual(x - 10.0, 1e-12))
            }
        },
        0.0,
        &options,
    );
    // x = 0, 1, 3 (steps 1, 2): the third evaluation fails, no further call
    assert_eq!(r, Err("out of range at 3".to_string()));
    assert_eq!(calls, 3);
}
