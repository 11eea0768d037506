#![allow(clippy::field_reassign_with_default)]
//! The Rosenbrock-W method agrees with Dormand–Prince 5(4) on a short 2002834 run (6371 rpm,
//! 500 N, 5 slices, 4 ms from the default start, whole run summarised).
//!
//! Tolerances of the comparison: both runs are held against each other at the level at which
//! DOPRI5 agrees with itself when its tolerance is halved (`tests/convergence.rs`, < 1 %) —
//! mean cage speed to 1e-4 relative, mean cage slip to 2e-5 absolute (it is ≈ 3e-4 here, a
//! difference of small numbers), largest inner/outer raceway forces to 2 %: the maxima are
//! taken at the step end points, and the W-method's steps are up to 3× longer, so a peak can
//! be sampled a few per cent low (measured in `docs/dynamics-integrator.md`).

mod common;
use common::*;
use rolldyn_dynamics::*;

fn run(method: IntegratorMethod, tol: f64) -> (RunSummary, StepStats) {
    let b = b2002834(5);
    let mut cond = OperatingConditions::new(rpm(6371.0), 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut set = DynamicsSettings::default();
    set.integrator.method = method;
    set.integrator.tolerance = tol;
    set.discard_revolutions = 0;
    set.output_step_s = 0.0;
    set.scuffing_check = false;
    let mut sim = Simulation::new(
        &b,
        cond,
        ContactParameters::for_bearing(&b),
        set,
        RacewayTraction::same(pao()),
    )
    .unwrap();
    let r = sim.run_until(4e-3, &mut NullSink, &mut |_| {}).unwrap();
    (r, sim.stats().clone())
}

#[test]
fn rosenbrock_w_agrees_with_dopri5() {
    let (a, _) = run(IntegratorMethod::Dopri5, 1e-6);
    let (b, st) = run(IntegratorMethod::RosenbrockW, 1e-5);
    eprintln!("{a:#?}\n{b:#?}\n{st:?}");
    let rel = |x: f64, y: f64| (x - y).abs() / x.abs();
    assert!(rel(a.cage_speed_mean_rad_s, b.cage_speed_mean_rad_s) < 1e-4);
    assert!((a.cage_slip_mean - b.cage_slip_mean).abs() < 2e-5);
    assert!(rel(a.max_inner_contact_force_n, b.max_inner_contact_force_n) < 0.02);
    assert!(rel(a.max_outer_contact_force_n, b.max_outer_contact_force_n) < 0.02);
    assert!(st.jacobian_evaluations > 0);
    assert_eq!(b.steps, st.accepted);
}
