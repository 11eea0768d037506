//! SPEC §3.7 "operating clearance as a function of time": a scheduled clearance moves the outer
//! raceway by half its change against the bearing's clearance. A constant schedule G + ΔG on a
//! bearing with clearance G must give the same right-hand side as a bearing built with G + ΔG,
//! from the same state.

mod common;

use common::{b2002834, pao, rpm};
use rolldyn_dynamics::*;

fn derivative(
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    conditions: OperatingConditions,
    initial: &InitialState,
) -> Vec<f64> {
    let params = ContactParameters::for_bearing(bearing);
    let mut sim = Simulation::with_initial_state(
        bearing,
        conditions,
        params,
        DynamicsSettings::default(),
        RacewayTraction::same(pao()),
        initial,
    )
    .expect("valid model");
    let mut dy = vec![0.0; sim.state().len()];
    sim.evaluate_derivative(&mut dy);
    dy
}

#[test]
fn scheduled_clearance_equals_a_built_in_clearance() {
    let base = b2002834(5);
    let g = base.clearance.radial;
    let dg = -4e-6;
    let mut tighter = base.clone();
    tighter.clearance.radial = g + dg;
    let mut cond = OperatingConditions::new(rpm(6371.0), 1000.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    // the loaded start of the tighter bearing, so that the raceways carry load
    let initial = Simulation::default_initial_state(
        &tighter,
        cond.clone(),
        ContactParameters::for_bearing(&tighter),
        RacewayTraction::same(pao()),
    )
    .expect("static start");
    let built_in = derivative(&tighter, cond.clone(), &initial);
    let mut scheduled = cond.clone();
    scheduled.clearance_schedule = Some(vec![(0.0, g + dg), (1.0, g + dg)]);
    let from_schedule = derivative(&base, scheduled, &initial);
    let unscheduled = derivative(&base, cond, &initial);
    let scale = built_in.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let diff = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
    };
    // same geometry up to rounding of the raceway radius (1e-16 m in 0.1 m)
    assert!(
        diff(&built_in, &from_schedule) <= 1e-7 * scale,
        "schedule differs from the built-in clearance by {}",
        diff(&built_in, &from_schedule)
    );
    // and the schedule does change the forces: 4 µm less clearance is a large change
    assert!(diff(&built_in, &unscheduled) > 1e-3 * scale);
}
