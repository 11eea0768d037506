#![allow(clippy::field_reassign_with_default, clippy::needless_range_loop)]
//! Frictionless, undamped run (SPEC §3.9 / issue 6 validation): the mechanical energy of the
//! whole bearing (rollers, cage, inner ring, contact elastic energy, load potential) drifts by
//! ≤ 1e-6 of the kinetic energy per cage revolution.
//!
//! Tolerance: the figure. The run uses τ = 1e-9 (DOPRI5 is not symplectic; its energy
//! error is proportional to the local error, so the tolerance sets the drift).

mod common;
use common::*;
use rolldyn_dynamics::*;
use rolldyn_lubrication::TractionModel;
use rolldyn_lubrication::traction::{FrictionLaw, TractionConfig, TwoLevelLaw};

pub fn frictionless() -> TractionModel {
    TractionModel::new(TractionConfig {
        oil: None,
        law: FrictionLaw::TwoLevel(TwoLevelLaw {
            mu_s: 0.0,
            mu_d: 0.0,
            v_s: 1e-3,
            v_d: 1e-2,
        }),
        ..TractionConfig::default()
    })
    .unwrap()
}

#[test]
fn frictionless_undamped_run_conserves_energy() {
    let mut b = bearing("obrien-taylor");
    b.roller.slice_count = 5;
    let mut cond = OperatingConditions::new(rpm(4000.0), 200.0);
    cond.gravity_m_s2 = [0.0; 3];
    let params = ContactParameters::for_bearing(&b).conservative();
    let mut set = DynamicsSettings::default();
    set.integrator.tolerance = 1e-9;
    set.output_step_s = 0.0;
    set.scuffing_check = false;
    let mut sim =
        Simulation::new(&b, cond, params, set, RacewayTraction::same(frictionless())).unwrap();
    let e0 = sim.mechanical_energy();
    // kinetic energy ≈ total energy here (elastic energy is µJ)
    let t_rev = std::f64::consts::TAU / sim.epicyclic_cage_speed();
    sim.run_until(1.0 * t_rev, &mut NullSink, &mut |_| {})
        .unwrap();
    let e1 = sim.mechanical_energy();
    let revs = sim.time() / t_rev;
    let drift_per_rev = (e1 - e0).abs() / e0 / revs;
    eprintln!(
        "E0 = {e0:.6e} J, drift {:.3e} per revolution over {revs:.3} rev, {} steps",
        drift_per_rev,
        sim.stats().accepted
    );
    assert!(drift_per_rev <= 1e-6, "drift {drift_per_rev:e}");
}
