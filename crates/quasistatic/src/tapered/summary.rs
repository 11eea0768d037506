//! Start point of the ring iteration and the result tables.

use super::case::{TaperedLoadCase, TiltCondition};
use super::results::{TaperedLoads, TaperedRollerLoad, TaperedRowLoads, TaperedSumChecks};
use super::ring::{RingProblem, RingState, add_wrench};
use super::roller::{CONE, CUP, RowRoller};
use rolldyn_geometry::DoubleRowTaperedBearing;
use std::f64::consts::PI;

/// Stribeck's ratio Z Q_max / F_r of a line-contact row with half the rollers loaded
/// (Harris & Kotzalas, Essential Concepts, ch. 7: Q_max = 4.08 F_r / (Z cos α)).
const STRIBECK_LINE: f64 = 4.08;

/// A start for the ring iteration: each load closes the gap g = ½ c_a sin α_o of the row(s)
/// it loads and deflects the most loaded roller as a rigid-ring estimate would (radial load
/// shared by both rows, axial load by the Z rollers of one row).
pub(crate) fn start_point(
    b: &DoubleRowTaperedBearing,
    roller: &RowRoller,
    case: &TaperedLoadCase,
) -> [f64; 5] {
    let alpha = b.cup_angle();
    let z = b.rollers_per_row as f64;
    let gap = b.normal_gap();
    let mut x = [0.0; 5];
    if let TiltCondition::Imposed(tilt) = case.tilt {
        x[4] = tilt;
    }
    let fr = case.radial_load_n;
    if fr != 0.0 {
        let q = STRIBECK_LINE * 0.5 * fr.abs() / (z * alpha.cos());
        x[0] = fr.signum() * (gap + roller.approach_for_load(q)) / alpha.cos();
    }
    let fa = case.axial_load_n;
    if fa != 0.0 {
        let q = fa.abs() / (z * alpha.sin());
        x[2] = fa.signum() * (gap + roller.approach_for_load(q)) / alpha.sin();
    }
    x
}

/// Angle `a` wrapped to (−π, π].
fn wrapped(a: f64) -> f64 {
    let w = a.rem_euclid(2.0 * PI);
    if w > PI { w - 2.0 * PI } else { w }
}

/// The result tables of the converged `state`.
pub(crate) fn summarise(
    b: &DoubleRowTaperedBearing,
    problem: &RingProblem,
    state: &RingState,
    iterations: usize,
) -> TaperedLoads {
    let x = state.x;
    let z = problem.z;
    let mut applied = problem.applied;
    let mut inner = state.residual;
    if problem.free.len() == 3 {
        // imposed tilt: the moment that holds it is the reaction of the rollers' moment
        applied[3] = -inner[3];
        applied[4] = -inner[4];
        inner[3] = 0.0;
        inner[4] = 0.0;
    }
    let mut cup_side = applied;
    let mut rollers = Vec::with_capacity(2 * z);
    let mut slice_loads_n = Vec::with_capacity(2 * z);
    let mut rows = Vec::with_capacity(2);
    for k in 0..2 {
        let mut cup_force = [0.0; 5];
        for j in 0..z {
            let st = &state.rollers[k * z + j];
            let psi = problem.azimuth(k, j);
            let (motion, loading) = problem.loading(&x, k, j);
            let (f, m) = problem.cup_side_wrench(st, &loading, &motion);
            add_wrench(&mut cup_side, psi, f, m);
            let (f_cup, m_cup) =
                motion.wrench_to_bearing(st.q[CUP] * loading.cup.normal, st.moment[CUP]);
            add_wrench(&mut cup_force, psi, -f_cup, -m_cup);
            slice_loads_n.push(problem.rows[k].slice_loads(st.pose, &loading));
            rollers.push(TaperedRollerLoad {
                row: k,
                index: j,
                azimuth_rad: wrapped(psi),
                cone_n: st.q[CONE],
                cup_n: st.q[CUP],
                rib_n: st.rib,
                centrifugal_n: problem.centrifugal,
                cone_slice_max_n: st.slice_max[CONE],
                cup_slice_max_n: st.slice_max[CUP],
                lift_m: st.pose.v,
                tilt_rad: st.pose.phi,
            });
        }
        let cup = [cup_force[0], cup_force[1], cup_force[2]];
        rows.push(row_summary(b, k, &x, &rollers[k * z..], cup));
    }
    let scaled = |r: &[f64; 5]| {
        problem
            .scaled(r)
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()))
    };
    let checks = TaperedSumChecks {
        applied,
        inner_ring_residual: inner,
        cup_side_residual: cup_side,
        relative: scaled(&inner).max(scaled(&cup_side)),
    };
    TaperedLoads {
        converged: true,
        iterations,
        displacement: x,
        cage_speed_rad_s: problem.cage_speed,
        centrifugal_force_n: problem.centrifugal,
        rows: [rows.remove(0), rows.remove(0)],
        rollers,
        checks,
        slice_loads_n,
    }
}

/// Displacements, load zone and most loaded roller of row `k`.
fn row_summary(
    b: &DoubleRowTaperedBearing,
    k: usize,
    x: &[f64; 5],
    rollers: &[TaperedRollerLoad],
    cup_force: [f64; 3],
) -> TaperedRowLoads {
    let mid_z = b.row(k).mid_z;
    // θ × (0, 0, z) = (θy z, −θx z, 0)
    let radial = [x[0] + x[4] * mid_z, x[1] - x[3] * mid_z];
    let towards = radial[1].atan2(radial[0]);
    let loaded: Vec<&TaperedRollerLoad> = rollers.iter().filter(|r| r.cone_n > 0.0).collect();
    let zone = if loaded.len() == rollers.len() {
        PI
    } else {
        loaded
            .iter()
            .map(|r| wrapped(r.azimuth_rad - towards).abs())
            .fold(0.0, f64::max)
    };
    let max = rollers
        .iter()
        .max_by(|a, b| a.cup_n.total_cmp(&b.cup_n))
        .copied()
        .expect("a row has rollers");
    TaperedRowLoads {
        row: k,
        mid_z_m: mid_z,
        radial_displacement_m: radial,
        axial_displacement_m: x[2],
        tilt_rad: [x[3], x[4]],
        loaded_rollers: loaded.len(),
        load_zone_half_angle_rad: zone,
        max_roller: max.index,
        max_cup_n: max.cup_n,
        max_cone_n: max.cone_n,
        max_rib_n: max.rib_n,
        cup_force_n: cup_force,
    }
}
