#![allow(clippy::field_reassign_with_default)]
//! Roller ends ↔ ribs (pair 56) and ↔ cage pocket faces (pair 54), SPEC §3.3:
//! * an aligned roller pushed axially into a flat rib feels `K_p δⁿ` (force law and its
//!   exponent, on the roller and in the snapshot);
//! * a yawed roller gets a restoring moment from the two ribs;
//! * a convex rib (R 37.5 mm) moves the contact point away from the rib edge (seed 000
//!   §3.1.1.7);
//! * switches disable the contacts;
//! * in a 2002834 run at 6371 rpm with bars that push the rollers (contact line at Ø190.2 mm,
//!   0.125 mm pocket play per side) the ribs keep the roller skew far below the cage-bar bound
//!   (≈ 0.05 rad without ribs).

mod common;
use common::*;
use rolldyn_dynamics::*;
use rolldyn_geometry::{CylindricalRollerBearing, RibFace};

#[derive(Default)]
struct Last {
    rib: Vec<f64>,
    edge: Vec<f64>,
    pocket: Vec<f64>,
    regime: Vec<EndContactRegime>,
    max_yaw: f64,
}

impl OutputSink for Last {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        self.rib = s.rollers.rib_force_n.to_vec();
        self.edge = s.rollers.rib_edge_distance_m.to_vec();
        self.pocket = s.rollers.pocket_face_force_n.to_vec();
        self.regime = s.rollers.rib_regime.to_vec();
        for &y in s.rollers.yaw_rad {
            self.max_yaw = self.max_yaw.max(y.abs());
        }
    }
}

/// Standstill simulation with roller 0 displaced axially by `dz` and yawed by `yaw`; returns
/// the last sample and the derivative.
fn at_rest(
    b: &CylindricalRollerBearing,
    params: ContactParameters,
    dz: f64,
    yaw: f64,
) -> (Last, Vec<f64>, Layout) {
    let mut cond = OperatingConditions::new(0.0, 0.0);
    cond.gravity_m_s2 = [0.0; 3];
    let set = DynamicsSettings::default();
    let tr = RacewayTraction::same(pao());
    let mut init = Simulation::default_initial_state(b, cond.clone(), params, tr.clone()).unwrap();
    init.rollers[0].axial_m = dz;
    init.rollers[0].yaw_rad = yaw;
    let mut sim = Simulation::with_initial_state(b, cond, params, set, tr, &init).unwrap();
    let mut dy = vec![0.0; sim.state().len()];
    sim.evaluate_derivative(&mut dy);
    let mut last = Last::default();
    sim.sample_now(&mut last);
    (last, dy, sim.layout())
}

fn axial_gap(b: &CylindricalRollerBearing) -> f64 {
    0.5 * (b.inner_ring.rib_spacing.unwrap() - b.roller.length)
}

#[test]
fn axial_push_into_flat_rib_follows_the_power_law() {
    let b = b2002834(5);
    let params = ContactParameters::for_bearing(&b);
    let p = params.roller_end_rib.contact;
    let m = b.roller.mass_properties.mass;
    let gap = axial_gap(&b);
    let mut f = Vec::new();
    for delta in [1e-6, 2e-6, 4e-6] {
        let (last, dy, lay) = at_rest(&b, params, gap + delta, 0.0);
        let expect = p.k_p * f64::powf(delta, p.exponent);
        let fz = m * dy[lay.roller(0) + roller::AXIAL_VELOCITY];
        assert!(
            (fz + expect).abs() < 1e-6 * expect,
            "δ = {delta}: F_z = {fz}, K_p δⁿ = {expect}"
        );
        assert!((last.rib[0] - expect).abs() < 1e-6 * expect);
        assert_eq!(last.pocket[0], 0.0, "pocket faces are 0.125 mm away");
        assert_eq!(last.regime[0], EndContactRegime::Boundary);
        f.push(last.rib[0]);
    }
    // exponent 1.5: doubling δ multiplies the force by 2^1.5
    assert!((f[1] / f[0] - 2f64.powf(1.5)).abs() < 1e-6);
    assert!((f[2] / f[1] - 2f64.powf(1.5)).abs() < 1e-6);
    // no contact inside the clearance, none when switched off
    let (last, _, _) = at_rest(&b, params, gap - 1e-6, 0.0);
    assert_eq!(last.rib[0], 0.0);
    let mut off = params;
    off.roller_end_rib.enabled = false;
    let (last, _, _) = at_rest(&b, off, gap + 2e-6, 0.0);
    assert_eq!(last.rib[0], 0.0);
}

#[test]
fn pocket_face_contact_and_switch() {
    let b = b2002834(5);
    let params = ContactParameters::for_bearing(&b);
    let cage = b.cage.as_ref().unwrap();
    let pocket_gap = 0.5 * (cage.pocket.axial - b.roller.length);
    let mut no_ribs = params;
    no_ribs.roller_end_rib.enabled = false;
    let delta = 2e-6;
    let (last, _, _) = at_rest(&b, no_ribs, pocket_gap + delta, 0.0);
    let p = params.roller_end_cage.contact;
    let expect = p.k_p * f64::powf(delta, p.exponent);
    assert!((last.pocket[0] - expect).abs() < 1e-6 * expect);
    no_ribs.roller_end_cage.enabled = false;
    let (last, _, _) = at_rest(&b, no_ribs, pocket_gap + delta, 0.0);
    assert_eq!(last.pocket[0], 0.0);
}

#[test]
fn yawed_roller_is_restored_by_the_ribs() {
    let b = b2002834(5);
    let params = ContactParameters::for_bearing(&b);
    let yaw = 0.01;
    let (last, dy, lay) = at_rest(&b, params, 0.0, yaw);
    assert!(last.rib[0] > 0.0, "both ends touch their ribs");
    // roller 0 sits at azimuth θ₀; a positive yaw turns the axis toward +e_θ, the restoring
    // moment is about +e_r
    let i = lay.roller(0);
    let (last0, _, _) = at_rest(&b, params, 0.0, 0.0);
    assert_eq!(last0.rib[0], 0.0, "centred aligned roller is free");
    let init_theta = {
        let cond = OperatingConditions::new(0.0, 0.0);
        Simulation::default_initial_state(&b, cond, params, RacewayTraction::same(pao()))
            .unwrap()
            .rollers[0]
            .azimuth_rad
    };
    let e_r = [init_theta.cos(), init_theta.sin(), 0.0];
    let moment = i + roller::MOMENTUM;
    let m_r = dy[moment] * e_r[0] + dy[moment + 1] * e_r[1] + dy[moment + 2] * e_r[2];
    assert!(m_r > 0.0, "restoring moment about e_r: {m_r}");
    // the axial forces of the two ends cancel
    let fz = dy[i + roller::AXIAL_VELOCITY] * b.roller.mass_properties.mass;
    assert!(fz.abs() < 1e-6 * last.rib[0], "F_z = {fz}");
}

#[test]
fn convex_rib_moves_the_contact_away_from_the_rib_edge() {
    let flat = b2002834(5);
    let mut convex = flat.clone();
    for rib in &mut convex.inner_ring.ribs {
        rib.face = RibFace::ConvexTorus {
            radius: 37.5e-3,
            crest_offset: 0.0,
        };
    }
    // 0.01 rad: the corner of a flat end reaches 55 µm, the crest of the R 37.5 mm rib 38 µm —
    // both beyond the 25 µm axial gap per side
    let yaw = 0.01;
    let (lf, _, _) = at_rest(&flat, ContactParameters::for_bearing(&flat), 0.0, yaw);
    let (lc, _, _) = at_rest(&convex, ContactParameters::for_bearing(&convex), 0.0, yaw);
    assert!(lf.rib[0] > 0.0 && lc.rib[0] > 0.0);
    println!(
        "contact below the rib edge: flat {:.4} mm ({:.2} N), convex R 37.5 mm {:.4} mm ({:.2} N)",
        lf.edge[0] * 1e3,
        lf.rib[0],
        lc.edge[0] * 1e3,
        lc.rib[0]
    );
    assert!(
        lf.edge[0] < 1e-6,
        "flat rib: contact on the rib edge ({})",
        lf.edge[0]
    );
    assert!(
        lc.edge[0] > 1e-3,
        "convex rib: contact {} mm below the edge",
        lc.edge[0] * 1e3
    );
}

#[test]
fn ribs_bound_the_skew_in_a_2002834_run() {
    let mut b = b2002834(5);
    // bars close to the rollers, so that they drive skew into the ribs within 25 ms (with the
    // model's Ø192.5 mm line the rollers have 1.48 mm of play and barely skew)
    b.cage
        .as_mut()
        .unwrap()
        .pocket
        .outer_lip
        .as_mut()
        .unwrap()
        .diameter = 190.2e-3;
    let mut cond = OperatingConditions::new(rpm(6371.0), 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut set = DynamicsSettings::default();
    set.output_step_s = 2e-4;
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
    let mut last = Last::default();
    let r = sim.run_until(0.025, &mut last, &mut |_| {}).unwrap();
    println!(
        "25 ms: largest |yaw| {:.5} rad, max end–rib {:.2} N, max end–cage {:.2} N, inner sliding {:.3} m/s",
        last.max_yaw,
        r.max_roller_end_rib_force_n,
        r.max_roller_end_cage_force_n,
        r.max_inner_sliding_speed_m_s
    );
    assert!(
        last.max_yaw < 0.01,
        "largest yaw {} rad (bar bound ≈ 0.05 rad)",
        last.max_yaw
    );
    assert!(r.max_roller_end_rib_force_n > 0.0 && r.max_roller_end_rib_force_n < 1e3);
    assert!(r.max_roller_end_cage_force_n.is_finite());
    assert!(
        r.max_inner_sliding_speed_m_s < 1.0,
        "inner sliding {} m/s",
        r.max_inner_sliding_speed_m_s
    );
}
