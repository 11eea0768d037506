//! Skidding model (SPEC §5.3–5.6): pure-rolling limit, power balance, both kinematic cases,
//! bad input and convergence failures.

mod common;

use rolldyn_quasistatic::studies::{self, NviTraction};
use rolldyn_quasistatic::*;

fn frictionless_resistances(c: &mut QuasiStaticConditions) {
    c.drag.enabled = false;
    c.cage_land.enabled = false;
    c.end_friction = EndFriction {
        ribs: false,
        pocket: false,
    };
    c.rolling_friction_m = 0.0;
    c.bar_friction = BarFriction::Constant(0.0);
}

#[test]
fn pure_rolling_limit_cage_runs_epicyclic() {
    // No drag, no land, no end films, no rolling resistance: nothing resists the roller set,
    // so the tractions vanish only at the epicyclic speed. Started 5 % away from it.
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let opts = QuasiStaticOptions {
        initial_cage_slip: 0.05,
        ..QuasiStaticOptions::default()
    };
    let mut c = studies::obrien_taylor_conditions(4000.0, 300.0, 0.0, NviTraction::Seed000Elastic);
    frictionless_resistances(&mut c);
    let r = solve(&ot, &c, &opts).unwrap();
    common::assert_finite(&r);
    // the cage equation is solved to 1e-6 of the moment scale at 5 % slip; the traction slope
    // makes the remaining slip orders of magnitude smaller — 1e-8 is a safe bound
    assert!(r.cage_slip.abs() < 1e-8, "ε₀ = {}", r.cage_slip);
    for x in &r.rollers {
        assert!(x.inner.sliding_speed_m_s.abs() < 1e-6 && x.outer.sliding_speed_m_s.abs() < 1e-6);
    }
    // intershaft: both rings rotating
    let b = studies::intershaft_bearing();
    let mut c = studies::intershaft_conditions(8152.0, 13_067.0, 200.0);
    frictionless_resistances(&mut c);
    let r = solve(&b, &c, &opts).unwrap();
    common::assert_finite(&r);
    assert!(r.cage_slip.abs() < 1e-8, "ε₀ = {}", r.cage_slip);
    assert!((r.cage_speed_rad_s - r.epicyclic_cage_speed_rad_s).abs() < 1e-8 * r.cage_speed_rad_s);
}

#[test]
fn power_balance_closes() {
    // Without rolling resistance (its ring reaction is not modelled) the power the rings
    // deliver equals the friction power of all contacts, land and drag. Residual sources: the
    // cage equation (1e-6 of its moment scale) and the roller-centre lever r_o − R_w used for
    // the inner contact (off by G/2, G/(2 r_i) ≈ 2e-4): 1e-3 relative.
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let mut c = studies::obrien_taylor_conditions(2500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    c.rolling_friction_m = 0.0;
    let r = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
    let rel = (r.power_input_w - r.power_loss_w).abs() / r.power_loss_w;
    println!(
        "O'Brien–Taylor: P_in = {:.4} W, P_loss = {:.4} W",
        r.power_input_w, r.power_loss_w
    );
    assert!(rel < 1e-3, "{rel}");
    let b = studies::intershaft_bearing();
    let mut c = studies::intershaft_conditions(8152.0, 13_067.0, 500.0);
    c.rolling_friction_m = 0.0;
    let r = solve(&b, &c, &QuasiStaticOptions::default()).unwrap();
    let rel = (r.power_input_w - r.power_loss_w).abs() / r.power_loss_w;
    println!(
        "intershaft: P_in = {:.4} W, P_loss = {:.4} W",
        r.power_input_w, r.power_loss_w
    );
    assert!(rel < 1e-3, "{rel}");
}

#[test]
fn ordinary_bearing_unloaded_rollers_brake_the_cage() {
    // SPEC §5.7: with the outer ring at rest the rollers of the unloaded zone are braking and
    // pushed by the cage; the loaded ones drive it; the cage lags (ε₀ > 0).
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let c = studies::obrien_taylor_conditions(4500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    let r = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
    common::assert_finite(&r);
    assert!(r.cage_slip > 0.0);
    assert_eq!(r.kinematic_case, KinematicCase::InnerRotating);
    for x in &r.rollers {
        match x.zone {
            Zone::Unloaded => assert!(x.bar.push_n < 0.0, "unloaded roller {} drives", x.index),
            Zone::Loaded => {}
        }
    }
    assert!(
        r.rollers
            .iter()
            .any(|x| x.zone == Zone::Loaded && x.bar.push_n > 0.0)
    );
    assert!(r.residuals.cage_moment_relative.abs() < 1e-6);
    assert!(r.residuals.roller_moment_relative < 1e-9);
    assert!(r.residuals.force_balance_relative < 1e-9);
}

#[test]
fn zero_and_equal_speeds() {
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    for (wi, wo) in [(0.0, 0.0), (100.0, 100.0)] {
        let mut c =
            studies::obrien_taylor_conditions(1500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
        c.inner_speed_rad_s = wi;
        c.outer_speed_rad_s = wo;
        let r = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
        common::assert_finite(&r);
        assert!((r.load_distribution.force_residual_n[1]).abs() < 1e-9 * 201.0);
        if wi == 0.0 {
            assert_eq!(r.cage_speed_rad_s, 0.0);
            assert_eq!(r.cage_slip, 0.0);
            assert_eq!(r.power_loss_w, 0.0);
        } else {
            // rings rotating together: the air–oil drag holds the cage back a little, the
            // rollers slide to balance it
            assert!(r.cage_speed_rad_s <= wi && r.cage_slip >= 0.0 && r.cage_slip < 1e-2);
            assert!(
                (r.power_input_w - r.power_loss_w).abs()
                    < 1e-2 * r.power_loss_w.max(1e-9) + (r.power.rolling_resistance_w)
            );
        }
    }
    // zero load: rollers held by the centrifugal force only
    let mut c = studies::obrien_taylor_conditions(1500.0, 0.0, 0.0, NviTraction::Seed000Elastic);
    c.radial_load_n = 0.0;
    let r = solve(&ot, &c, &QuasiStaticOptions::default());
    match r {
        Ok(r) => common::assert_finite(&r),
        Err(e) => assert!(matches!(e, QsError::NotConverged { .. }), "{e}"),
    }
}

#[test]
fn non_convergence_reports_residuals() {
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let c = studies::obrien_taylor_conditions(4500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    let opts = QuasiStaticOptions {
        max_cage_evaluations: 2,
        ..QuasiStaticOptions::default()
    };
    let e = solve(&ot, &c, &opts).unwrap_err();
    let msg = e.to_string();
    println!("{msg}");
    match &e {
        QsError::NotConverged { residuals, .. } => {
            assert!(!residuals.is_empty());
            assert!(residuals.iter().all(|r| r.value.is_finite()));
        }
        other => panic!("unexpected {other}"),
    }
    assert!(msg.contains("did not converge") && msg.contains("residuals"));
}

#[test]
fn bad_input_and_warnings() {
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let base = studies::obrien_taylor_conditions(1500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    // load above the static rating → warning, still solved
    let mut c = base.clone();
    let c0 = static_load_rating(&ot);
    c.radial_load_n = 1.5 * c0;
    let r = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
    assert!(
        r.warnings.iter().any(|w| w.contains("static load rating")),
        "{:?}",
        r.warnings
    );
    // NaN speed, negative load, absurd temperature
    for f in [
        |c: &mut QuasiStaticConditions| c.inner_speed_rad_s = f64::NAN,
        |c: &mut QuasiStaticConditions| c.radial_load_n = -1.0,
        |c: &mut QuasiStaticConditions| c.temperatures.cage = -5.0,
    ] {
        let mut c = base.clone();
        f(&mut c);
        assert!(matches!(
            solve(&ot, &c, &QuasiStaticOptions::default()),
            Err(QsError::InvalidInput(_))
        ));
    }
    // a housing fit that turns the clearance into an excessive preload
    let mut c = base.clone();
    c.mounting.housing_interference_m = 200e-6;
    let e = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap_err();
    assert!(e.to_string().contains("preload"), "{e}");
    // an oil without the properties the seed 001 model needs
    let mut c = base.clone();
    c.friction = FrictionModel::seed001();
    assert!(matches!(
        solve(&ot, &c, &QuasiStaticOptions::default()),
        Err(QsError::Lubrication(_))
    ));
}

#[test]
fn operating_geometry_contributions() {
    let ot = common::obrien_taylor();
    let base = studies::obrien_taylor_conditions(1500.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    // shaft fit 20 µm on a solid steel shaft: Δd_i = I d/d_i (Harris ring-thickness factor)
    let mut c = base.clone();
    c.temperatures = PartTemperatures::uniform(c.temperatures.assembly);
    c.inner_speed_rad_s = 0.0;
    c.mounting.shaft_interference_m = 20e-6;
    let g = operating_geometry(&ot, &c, 0.0);
    let expected = -20e-6 * ot.inner_ring.body_diameter / ot.inner_ring.raceway_diameter;
    assert!(
        (g.clearance.inner_fit_m - expected).abs() < 1e-9 * 20e-6,
        "{:?}",
        g.clearance
    );
    // uniform heating of an all-steel bearing changes the clearance by α ΔT (D_o − d_i − 2D_w)
    let mut c = base.clone();
    c.temperatures = PartTemperatures::uniform(c.temperatures.assembly + 50.0);
    c.inner_speed_rad_s = 0.0;
    let g = operating_geometry(&ot, &c, 0.0);
    let thermal = g.clearance.inner_ring_thermal_m
        + g.clearance.outer_ring_thermal_m
        + g.clearance.roller_thermal_m;
    assert!((thermal - 11.9e-6 * 50.0 * ot.geometric_clearance()).abs() < 1e-15);
    // a hotter inner ring closes the clearance
    let mut c = base.clone();
    c.temperatures.inner_ring += 20.0;
    let g2 = operating_geometry(&ot, &c, 0.0);
    assert!(g2.clearance.operating_m < ot.clearance.radial);
    // intershaft (seed 001): inner-ring speed closes, outer-ring speed opens the clearance
    let b = studies::intershaft_bearing();
    let g_at = |ni: f64, no: f64| {
        operating_geometry(&b, &studies::intershaft_conditions(ni, no, 50.0), 0.0).clearance
    };
    let (a, bb, cc) = (
        g_at(5000.0, 13_067.0),
        g_at(10_000.0, 13_067.0),
        g_at(5000.0, 16_000.0),
    );
    assert!(bb.operating_m < a.operating_m && cc.operating_m > a.operating_m);
    assert!(a.inner_ring_centrifugal_m < 0.0 && a.outer_ring_centrifugal_m > 0.0);
    let sum = a.mounting_m
        + a.inner_fit_m
        + a.outer_fit_m
        + a.inner_ring_thermal_m
        + a.outer_ring_thermal_m
        + a.roller_thermal_m
        + a.inner_ring_centrifugal_m
        + a.outer_ring_centrifugal_m;
    assert!((sum - a.operating_m).abs() < 1e-18);
    let full = operating_geometry(
        &b,
        &studies::intershaft_conditions(8152.0, 13_067.0, 50.0),
        1100.0,
    );
    assert!(full.cage.is_some() && full.roller_rib.is_some() && full.pocket_end.is_some());
}

#[test]
fn custom_cage_land_model_and_sweep_determinism() {
    struct NoLand;
    impl QuasiStaticLandModel for NoLand {
        fn evaluate(&self, i: &CageLandInput) -> CageLandOutput {
            CageLandOutput {
                pressing_force_n: i.roller_force_n,
                ..CageLandOutput::default()
            }
        }
        fn name(&self) -> &'static str {
            "none"
        }
    }
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let c = studies::obrien_taylor_conditions(4000.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    let with = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
    let without = solve_with_land_model(&ot, &c, &QuasiStaticOptions::default(), &NoLand).unwrap();
    assert_eq!(without.cage.land_torque_n_m, 0.0);
    assert!(
        without.cage_slip < with.cage_slip,
        "less resistance, less slip"
    );
    assert_eq!(without.cage_land_model, "none");
    let loads = [104.0, 201.0, 300.0];
    let a = sweep(
        &ot,
        &c,
        &QuasiStaticOptions::default(),
        &ShortBearing::default(),
        SweepVariable::RadialLoad,
        &loads,
    );
    let b = sweep(
        &ot,
        &c,
        &QuasiStaticOptions::default(),
        &ShortBearing::default(),
        SweepVariable::RadialLoad,
        &loads,
    );
    for (x, y) in a.iter().zip(&b) {
        let (x, y) = (x.result.as_ref().unwrap(), y.result.as_ref().unwrap());
        assert_eq!(x.cage_slip.to_bits(), y.cage_slip.to_bits());
    }
}

#[test]
fn result_serialises_to_json_with_the_cli_keys() {
    let ot = studies::obrien_taylor_bearing(&common::obrien_taylor());
    let c = studies::obrien_taylor_conditions(4000.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    let r = solve(&ot, &c, &QuasiStaticOptions::default()).unwrap();
    let v: serde_json::Value = serde_json::to_value(&r).unwrap();
    for key in [
        "cage_slip",
        "cage_speed_rad_s",
        "epicyclic_cage_speed_rad_s",
        "max_roller_load_n",
        "rollers",
        "operating_clearance_m",
        "power_loss_w",
        "min_scuffing_margin",
        "solve_time_s",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["rollers"].as_array().unwrap().len(), 13);
    assert!(v["cage_slip"].as_f64().unwrap().is_finite());
}
