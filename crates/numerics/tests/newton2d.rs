//! Damped 2-D Newton: convergence, singular starts, fallback steps and reported failures.

use rolldyn_numerics::{Damping, Newton2dOptions, Newton2dStatus, Sample, solve_2d};
use std::convert::Infallible;

/// Gradient of the convex potential `Π = eˣ − 2x + xy/2 + y⁴/4 + y²/2 − 3y`.
fn convex(x: [f64; 2], _: &()) -> Result<Sample<()>, Infallible> {
    let [a, b] = x;
    let r = [a.exp() - 2.0 + 0.5 * b, 0.5 * a + b.powi(3) + b - 3.0];
    let j = [[a.exp(), 0.5], [0.5, 3.0 * b * b + 1.0]];
    let pi = a.exp() - 2.0 * a + 0.5 * a * b + 0.25 * b.powi(4) + 0.5 * b * b - 3.0 * b;
    Ok(Sample::new(r, j, 1.0, ()).with_potential(pi))
}

/// Sample of a system without potential, fallback step or state.
fn plain(r: [f64; 2], j: [[f64; 2]; 2], scale: f64) -> Result<Sample<()>, Infallible> {
    Ok(Sample::new(r, j, scale, ()))
}

#[test]
fn smooth_gradient_system_converges_quadratically() {
    let Ok(out) = solve_2d(convex, [3.0, -2.0], (), &Newton2dOptions::default());
    assert_eq!(out.status, Newton2dStatus::Converged);
    assert!(out.converged());
    assert!(out.residual[0].abs().max(out.residual[1].abs()) <= 1e-12);
    assert!(out.iterations <= 12, "{} iterations", out.iterations);
    let Ok(again) = convex(out.x, &());
    assert_eq!(again.residual, out.residual);
}

#[test]
fn non_symmetric_system_with_negative_determinant() {
    // circle x² + y² = 2 and line x = y: root (1, 1), det J = −2(x + y) < 0
    let f = |x: [f64; 2], _: &()| {
        let [a, b] = x;
        plain(
            [a * a + b * b - 2.0, a - b],
            [[2.0 * a, 2.0 * b], [1.0, -1.0]],
            2.0,
        )
    };
    let options = Newton2dOptions {
        sufficient_decrease: 0.0,
        damping: Damping::Trace { floor: 1e-12 },
        ..Newton2dOptions::default()
    };
    let Ok(out) = solve_2d(f, [2.0, 0.5], (), &options);
    assert_eq!(out.status, Newton2dStatus::Converged);
    assert!((out.x[0] - 1.0).abs() < 1e-12 && (out.x[1] - 1.0).abs() < 1e-12);
}

#[test]
fn step_scale_changes_the_variables_not_the_solution() {
    // the same convex system in x = (a, b/1000): Jacobian w.r.t. y = (a, 1000 x₂)
    let scaled = |x: [f64; 2], s: &()| convex([x[0], 1000.0 * x[1]], s);
    let options = Newton2dOptions {
        step_scale: [1.0, 1000.0],
        ..Newton2dOptions::default()
    };
    let Ok(out) = solve_2d(scaled, [3.0, -2e-3], (), &options);
    let Ok(reference) = solve_2d(convex, [3.0, -2.0], (), &Newton2dOptions::default());
    assert!(out.converged());
    assert!((out.x[0] - reference.x[0]).abs() < 1e-12);
    assert!((1000.0 * out.x[1] - reference.x[1]).abs() < 1e-12);
}

#[test]
fn singular_jacobian_at_the_start_is_damped() {
    // r = (a³ − 1, b − a): J = [[0, 0], [−1, 1]] at the origin
    let f = |x: [f64; 2], _: &()| {
        let [a, b] = x;
        plain(
            [a.powi(3) - 1.0, b - a],
            [[3.0 * a * a, 0.0], [-1.0, 1.0]],
            1.0,
        )
    };
    let options = Newton2dOptions {
        damping: Damping::Trace { floor: 1e-12 },
        ..Newton2dOptions::default()
    };
    let Ok(out) = solve_2d(f, [0.0, 0.0], (), &options);
    assert_eq!(out.status, Newton2dStatus::Converged);
    assert!((out.x[0] - 1.0).abs() < 1e-12 && (out.x[1] - 1.0).abs() < 1e-12);
}

#[test]
fn fallback_step_leaves_a_dead_zone() {
    // nothing "loaded" for a ≤ 0: zero Jacobian, the fallback step moves a to 1
    let f = |x: [f64; 2], calls: &usize| -> Result<Sample<usize>, Infallible> {
        let a = x[0].max(0.0);
        let loaded = x[0] > 0.0;
        let j = if loaded {
            [[2.0 * a, 0.0], [x[1] - 1.0, a]]
        } else {
            [[0.0; 2]; 2]
        };
        let sample = Sample::new([a * a - 1.0, a * (x[1] - 1.0)], j, 1.0, calls + 1);
        Ok(if loaded {
            sample
        } else {
            sample.with_fallback_step([1.0 - x[0], 0.0])
        })
    };
    let Ok(out) = solve_2d(f, [-1.0, 1.0], 0, &Newton2dOptions::default());
    assert_eq!(out.status, Newton2dStatus::Converged);
    assert_eq!(out.x[0], 1.0);
    assert_eq!(out.iterations, 1);
    // the state is threaded through the accepted evaluations: start + one trial
    assert_eq!(out.state, 2);
}

#[test]
fn system_without_root_reports_no_descent() {
    // a² + 1 > 0: the residual norm bottoms out at 1 (a = 0)
    let f = |x: [f64; 2], _: &()| {
        let [a, b] = x;
        plain([a * a + 1.0, b], [[2.0 * a, 0.0], [0.0, 1.0]], 1.0)
    };
    let Ok(out) = solve_2d(f, [2.0, 1.0], (), &Newton2dOptions::default());
    assert_eq!(out.status, Newton2dStatus::NoDescent);
    assert!(!out.converged());
    assert!(out.x[0].abs() < 1e-3, "{:?}", out.x);
    assert!((out.residual[0] - 1.0).abs() < 1e-6);
}

#[test]
fn unreachable_tolerance_stalls_within_the_stall_tolerance() {
    // a² = 2 has no floating-point root: Newton ends one ulp away
    let f = |x: [f64; 2], _: &()| {
        let [a, b] = x;
        plain([a * a - 2.0, b], [[2.0 * a, 0.0], [0.0, 1.0]], 2.0)
    };
    let options = Newton2dOptions {
        tolerance: 0.0,
        ..Newton2dOptions::default()
    };
    let Ok(out) = solve_2d(f, [1.0, 0.5], (), &options);
    assert_eq!(out.status, Newton2dStatus::Stalled);
    assert!(out.converged());
    assert!((out.x[0] - 2.0_f64.sqrt()).abs() <= 4.0 * f64::EPSILON);
    let strict = Newton2dOptions {
        stall_tolerance: 0.0,
        ..options
    };
    let Ok(out) = solve_2d(f, [1.0, 0.5], (), &strict);
    assert_eq!(out.status, Newton2dStatus::NoDescent);
}

#[test]
fn iteration_limit_and_errors_are_reported() {
    let options = Newton2dOptions {
        max_iterations: 1,
        ..Newton2dOptions::default()
    };
    let Ok(out) = solve_2d(convex, [3.0, -2.0], (), &options);
    assert_eq!(out.status, Newton2dStatus::IterationLimit);
    assert_eq!(out.iterations, 1);
    assert!(!out.converged());

    let failing = |x: [f64; 2], _: &()| {
        if x[0] > 2.5 {
            Ok(Sample::new(
                [x[0] - 2.0, x[1]],
                [[1.0, 0.0], [0.0, 1.0]],
                1.0,
                (),
            ))
        } else {
            Err("left the domain")
        }
    };
    assert_eq!(
        solve_2d(failing, [3.0, 0.0], (), &Newton2dOptions::default()),
        Err("left the domain")
    );
}
