#![allow(clippy::field_reassign_with_default, clippy::needless_range_loop)]
//! 2002834 at 6371 rpm with the model's bar contact line (Ø192.5 mm, 1.48 mm pocket play per
//! side, roller skew held by the ribs): a short run stays bounded. 5 slices, 500 N, PAO VG 320
//! Muraki traction, 25 ms.
//!
//! Checked at every 1 ms mark: no divergence stop; roller tilt (skew + pitch) below 0.06 rad (the
//! ribs' bound is ≈ 0.0505/15 rad; the bars alone would allow far more); roller radii within
//! the raceway annulus ± 0.1 mm; cage centre within its land clearance + 0.1 mm; run-summary
//! forces finite and below 10 kN (static maximum ≈ 200 N at 500 N radial load).
//! The ≥ 0.2 s run is recorded in docs/dynamics-integrator.md (release harness `examples/speed.rs`).

mod common;
use common::*;
use rolldyn_dynamics::*;

#[test]
fn short_2002834_run_stays_bounded() {
    let b = b2002834(5);
    let mut cond = OperatingConditions::new(rpm(6371.0), 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut set = DynamicsSettings::default();
    set.output_step_s = 0.0;
    set.scuffing_check = false;
    set.discard_revolutions = 0;
    let mut sim = Simulation::new(
        &b,
        cond,
        ContactParameters::for_bearing(&b),
        set,
        RacewayTraction::same(pao()),
    )
    .unwrap();
    let lay = sim.layout();
    let rm = 0.25 * (b.inner_ring.raceway_diameter + b.outer_ring.raceway_diameter);
    let half_land_clearance = 0.5
        * b.cage
            .as_ref()
            .expect("2002834 has a cage")
            .floating_clearance;
    let mut max_tilt = 0.0_f64;
    for ms in 1..=25 {
        sim.run_until(ms as f64 * 1e-3, &mut NullSink, &mut |_| {})
            .unwrap_or_else(|e| panic!("stopped before {ms} ms: {e}"));
        let y = sim.state();
        for j in 0..lay.rollers {
            let k = lay.roller(j);
            let a = &y[k + roller::AXIS..k + roller::AXIS + 3];
            let tilt = (a[0] * a[0] + a[1] * a[1]).sqrt().atan2(a[2]);
            max_tilt = max_tilt.max(tilt);
            assert!(
                (y[k + roller::RADIUS] - rm).abs() < 1e-4,
                "roller {j} radius {}",
                y[k + roller::RADIUS]
            );
        }
        let c = lay.cage() + cage::CENTRE;
        let e = (y[c] * y[c] + y[c + 1] * y[c + 1]).sqrt();
        assert!(e < half_land_clearance + 1e-4, "cage centre {e} m");
    }
    let r = sim.summary();
    eprintln!(
        "largest tilt {max_tilt:.4} rad; max forces inner {:.0} outer {:.0} bar {:.0} land {:.0} N; slip {:.5}",
        r.max_inner_contact_force_n,
        r.max_outer_contact_force_n,
        r.max_roller_cage_force_n,
        r.max_cage_land_force_n,
        r.cage_slip_mean
    );
    assert!(max_tilt < 0.06, "tilt {max_tilt}");
    for f in [
        r.max_inner_contact_force_n,
        r.max_outer_contact_force_n,
        r.max_roller_cage_force_n,
        r.max_cage_land_force_n,
    ] {
        assert!(f.is_finite() && f < 1e4, "{r:?}");
    }
}
