//! Issue 6 "static equilibrium under radial load": the dynamics' static load distribution (its
//! start) against the quasi-static crate's load model on the same bearing — roller loads within
//! 2 % of the largest load, same loaded rollers (load-zone extent), same clearance.

use rolldyn_contact::roller_raceway::SliceLawChoice;
use rolldyn_dynamics::conditions::OperatingConditions;
use rolldyn_dynamics::parameters::ContactParameters;
use rolldyn_dynamics::settings::DynamicsSettings;
use rolldyn_dynamics::{RacewayTraction, Simulation};
use rolldyn_geometry::BearingModel;
use rolldyn_quasistatic::QuasiStaticOptions;
use rolldyn_quasistatic::load_distribution::{LoadCase, LoadModel};

#[test]
fn dynamics_start_matches_quasistatic_load_distribution() {
    let text = include_str!("../../../examples/obrien-taylor.toml");
    let model = rolldyn_model::parse(text, "obrien-taylor.toml").unwrap();
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        panic!()
    };
    let traction = model
        .lubrication
        .as_ref()
        .unwrap()
        .traction_model()
        .unwrap();
    // Slow (10 rpm) so that centrifugal forces are negligible in both models; no gravity in
    // the quasi-static model, so none here either.
    let speed = 10.0 * std::f64::consts::PI / 30.0;
    let load = 687.0;
    let mut conditions = OperatingConditions::new(speed, load);
    conditions.gravity_m_s2 = [0.0; 3];
    // Load pointing at roller 11 (azimuth 10·2π/13 from +x): the arrangement is symmetric about
    // the load line, so the ring moves along the load only. (The dynamics' start solves the
    // distribution along the load direction only; for an asymmetric arrangement its lateral
    // residual is removed by the run itself, not by the start.)
    let load_azimuth = 10.0 * std::f64::consts::TAU / 13.0;
    conditions.loads = vec![rolldyn_dynamics::conditions::InnerRingLoad::Fixed {
        force_n: [load * load_azimuth.cos(), load * load_azimuth.sin(), 0.0],
    }];
    let sim = Simulation::new(
        bearing,
        conditions,
        ContactParameters::for_bearing(bearing),
        DynamicsSettings::default(),
        RacewayTraction::same(traction),
    )
    .unwrap();
    let dynamic = sim.static_solution().unwrap();
    // The quasi-static model measures ψ from the load direction.
    let phase = dynamic.rollers[0].azimuth_rad - load_azimuth;
    let qs = LoadModel::new(bearing, SliceLawChoice::Seed)
        .unwrap()
        .solve(
            &LoadCase {
                radial_load_n: load,
                diametral_clearance_m: bearing.clearance.radial,
                misalignment_rad: 0.0,
                misalignment_azimuth_rad: 0.0,
                centrifugal_force_n: 0.0,
                roller_phase_rad: phase,
            },
            None,
            &QuasiStaticOptions::default(),
        )
        .unwrap();
    let q_max = qs
        .rollers
        .iter()
        .map(|r| r.inner_force_n)
        .fold(0.0, f64::max);
    assert!(q_max > 0.0);
    let mut worst = 0.0f64;
    for (d, q) in dynamic.rollers.iter().zip(&qs.rollers) {
        let diff = (d.inner_load_n - q.inner_force_n).abs() / q_max;
        worst = worst.max(diff);
        assert!(
            diff < 0.02,
            "roller at {:.3} rad: dynamics {:.2} N, quasi-static {:.2} N",
            q.azimuth_rad,
            d.inner_load_n,
            q.inner_force_n
        );
        assert_eq!(
            d.inner_load_n > 1e-6 * q_max,
            q.inner_force_n > 1e-6 * q_max,
            "load zone differs"
        );
    }
    println!(
        "largest roller-load difference: {:.3} % of Q_max = {q_max:.2} N",
        100.0 * worst
    );
}
