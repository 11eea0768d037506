//! The cage's contacts: roller ↔ cage bars (detection for all rollers in one vector loop, then
//! the force per roller; SPEC §1.5, §3.3 pair 53) and cage ↔ guiding land (SPEC §3.6).

use super::Wrench;
use super::bodies::{Bodies, CageKin, RollerColumns};
use super::diagnostics::{Violation, note};
use crate::kinematics::RollerKinematics;
use crate::land::LandKinematics;
use crate::model::Model;
use crate::output::PointForce;
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, power, scale, sub, unit_or};
use rolldyn_contact::damping::SliceDamping;

/// Per pocket (struct of arrays): its frame in the cage plane and the squared distances of its
/// roller's bar points from the bar edges.
#[derive(Debug, Clone)]
pub(super) struct PocketColumns {
    /// radial and tangential unit vectors in the cage plane: e_x, e_y, e_z, t_x, t_y, t_z
    frame: [Vec<f64>; 6],
    /// squared distance of the bar points (pocket sides −, + × roller ends −, +) from the bar
    /// edges, measured in the cage plane
    bar_dist_sq: [Vec<f64>; 4],
}

impl PocketColumns {
    pub fn new(z: usize) -> Self {
        Self {
            frame: std::array::from_fn(|_| vec![0.0; z]),
            bar_dist_sq: std::array::from_fn(|_| vec![0.0; z]),
        }
    }

    /// The radial and tangential unit vectors of pocket `j`.
    #[inline]
    fn frame(&self, j: usize) -> (V3, V3) {
        let f = &self.frame;
        ([f[0][j], f[1][j], f[2][j]], [f[3][j], f[4][j], f[5][j]])
    }
}

/// Offset of the bar point `q` of a roller from the edge line of its pocket's bar on `side`
/// (±1), perpendicular to the cage axis: the edge runs along the cage axis at the bar contact
/// radius from the cage centre, in the pocket frame `(e_p, t_p)`.
#[inline]
fn bar_offset(model: &Model, cage: &CageKin, (ep, tp): (V3, V3), side: f64, q: V3) -> V3 {
    let edge = axpy(
        axpy(cage.centre, model.r_bar, ep),
        side * model.half_pocket,
        tp,
    );
    perp(sub(q, edge), cage.axis)
}

/// Detection for all pockets at once: the pocket frames (radial unit vector of pocket `j` in
/// the cage plane at the angle φ_c + 2πj/Z by the angle-sum formulas, and the tangential one),
/// then the squared distance of each bar point from its bar edge (the expressions of
/// [`bar_contacts`]).
pub(super) fn detect(
    model: &Model,
    cage: &CageKin,
    rollers: &RollerColumns,
    pockets: &mut PocketColumns,
) {
    let z = model.z;
    let (sin_phi, cos_phi) = (cage.sin_phi, cage.cos_phi);
    let [ex, ey, ez, tx, ty, tz] = pockets.frame.each_mut().map(|c| &mut c[..z]);
    let pitch = &model.pocket_sin_cos[..z];
    for j in 0..z {
        let (sin_pitch, cos_pitch) = pitch[j];
        let sp = sin_phi * cos_pitch + cos_phi * sin_pitch;
        let cpp = cos_phi * cos_pitch - sin_phi * sin_pitch;
        let ep = unit_or(perp([cpp, sp, 0.0], cage.axis), [cpp, sp, 0.0]);
        let tp = cross(cage.axis, ep);
        [ex[j], ey[j], ez[j]] = ep;
        [tx[j], ty[j], tz[j]] = tp;
    }
    let [cx, cy, cz] = rollers.centre.each_ref().map(|c| &c[..z]);
    let [ax, ay, az] = rollers.axis.each_ref().map(|c| &c[..z]);
    let [ex, ey, ez, tx, ty, tz] = pockets.frame.each_ref().map(|c| &c[..z]);
    let [d0, d1, d2, d3] = pockets.bar_dist_sq.each_mut().map(|c| &mut c[..z]);
    for j in 0..z {
        let (ep, tp) = ([ex[j], ey[j], ez[j]], [tx[j], ty[j], tz[j]]);
        let (centre, a) = ([cx[j], cy[j], cz[j]], [ax[j], ay[j], az[j]]);
        let dist_sq = |side: f64, x: f64| {
            let d = bar_offset(model, cage, (ep, tp), side, axpy(centre, x, a));
            dot(d, d)
        };
        let [x0, x1] = model.bar_x;
        d0[j] = dist_sq(-1.0, x0);
        d1[j] = dist_sq(-1.0, x1);
        d2[j] = dist_sq(1.0, x0);
        d3[j] = dist_sq(1.0, x1);
    }
}

/// Roller `j` ↔ the bars of its pocket: both pocket sides, evaluated at both ends of the
/// roller's straight part (SPEC §1.5 "bone-shaped" scar). Each point carries
/// [`Model::bar_share`] of the pair's `K_p` and `C_h`: `Q = K_p' δⁿ + C(δ) δ̇` (seed 000 (2.5)–
/// (2.8)), friction `μ(v_s) Q` against the sliding velocity. Adds the forces to the roller and
/// their reaction to the cage.
#[inline(always)]
pub(super) fn bar_contacts(
    model: &Model,
    cage: &CageKin,
    j: usize,
    rk: &RollerKinematics,
    pockets: &PocketColumns,
    (roller, cage_wrench): (&mut Wrench, &mut Wrench),
    violation: &mut Option<Violation>,
) -> BarSums {
    let bar = &model.params.roller_cage;
    let bar_damping = SliceDamping::new(model.bar_share * bar.c_h, bar.d);
    let frame = pockets.frame(j);
    let mut sums = BarSums::default();
    for (k, &side) in [-1.0, 1.0].iter().enumerate() {
        for (i, &x) in model.bar_x.iter().enumerate() {
            // the (many) points clear of the bar were settled by the vector loop
            let dist_sq = pockets.bar_dist_sq[2 * k + i][j];
            if dist_sq >= model.rw * model.rw || dist_sq == 0.0 {
                continue;
            }
            let q = axpy(rk.c, x, rk.a);
            let d = bar_offset(model, cage, frame, side, q);
            let dist = dist_sq.sqrt();
            let delta = model.rw - dist;
            note(violation, "roller ↔ cage bar", j, delta, model.div_limit);
            let n = scale(d, 1.0 / dist);
            let cp = axpy(q, -model.rw, n);
            let r_cp = sub(cp, rk.c);
            let v_roll = add(rk.v, cross(rk.w, r_cp));
            let v_cage = add(cage.velocity, cross(cage.omega, sub(cp, cage.centre)));
            let vrel = sub(v_roll, v_cage);
            let delta_dot = -dot(vrel, n);
            let elastic = model.bar_share * bar.k_p * power(delta, bar.exponent);
            let qn = bar_damping.normal_force(elastic, delta, delta_dot);
            if qn <= 0.0 {
                continue;
            }
            let vt = perp(vrel, n);
            let vs = norm(vt);
            let mu = bar.friction.coefficient(vs);
            let mut fc = scale(n, qn);
            if vs > 0.0 {
                fc = axpy(fc, -mu * qn / vs, vt);
            }
            roller.force = add(roller.force, fc);
            roller.moment = add(roller.moment, cross(r_cp, fc));
            cage_wrench.force = sub(cage_wrench.force, fc);
            cage_wrench.moment = sub(cage_wrench.moment, cross(sub(cp, cage.centre), fc));
            sums.points[2 * k + i] = PointForce {
                force_n: scale(fc, -1.0),
                point_m: cp,
            };
            sums.normal += qn;
            sums.power += mu * qn * vs;
            sums.sliding += qn * vs;
        }
    }
    sums
}

/// Sums of one roller's bar contacts: normal force, friction power and the force-weighted
/// sliding speed (the speed of the friction law), and the force of each contact point on the
/// cage ([`PocketLoads::bar`](crate::output::PocketLoads)).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct BarSums {
    pub points: [PointForce; 4],
    pub normal: f64,
    pub power: f64,
    /// Σ Q v_s, N·m/s
    pub sliding: f64,
}

/// Cage ↔ guiding land ([`Model::land_model`]), two stations at the quarter points of the land
/// width. Adds the force and moment to the cage and, for an inner-ring land, the reaction to
/// the inner ring; returns the normal force, the power and the force of each station on the
/// cage.
pub(super) fn land_contact(
    model: &Model,
    bodies: &Bodies,
    cage_wrench: &mut Wrench,
    f_inner: &mut V3,
    violation: &mut Option<Violation>,
) -> (f64, f64, [PointForce; 2]) {
    let mut loads = [PointForce::default(); 2];
    let Some(land) = model.land else {
        return (0.0, 0.0, loads);
    };
    let ring = if land.inner {
        &bodies.inner
    } else {
        &bodies.outer
    };
    let cage = &bodies.cage;
    let (mut force, mut power) = (0.0, 0.0);
    for (station, zeta) in [-0.25 * land.width, 0.25 * land.width]
        .into_iter()
        .enumerate()
    {
        let k = LandKinematics {
            land_axis: ring.axis,
            land_center: axpy(ring.o, zeta, ring.axis),
            land_velocity: ring.v,
            land_omega: scale(ring.axis, ring.spin),
            cage_center: axpy(cage.centre, zeta, cage.axis),
            cage_velocity: add(cage.velocity, cross(cage.omega, scale(cage.axis, zeta))),
            cage_omega: cage.omega,
            land_radius_m: land.radius,
            radial_gap_m: land.gap,
            inner_land: land.inner,
            width_m: 0.5 * land.width,
            stations: 2,
            temperature_k: model.conditions.temperatures.cage_k,
        };
        let lf = model.land_model.force(&k);
        if lf.normal_force_n > 0.0 {
            note(
                violation,
                "cage ↔ guiding land",
                0,
                lf.penetration_m,
                model.div_limit,
            );
            let f = lf.force_on_cage_n;
            cage_wrench.force = add(cage_wrench.force, f);
            let arm = sub(lf.point_m, cage.centre);
            cage_wrench.moment = add(cage_wrench.moment, cross(arm, f));
            cage_wrench.moment = add(cage_wrench.moment, lf.moment_on_cage_n_m);
            if land.inner {
                *f_inner = sub(*f_inner, f);
            }
            force += lf.normal_force_n;
            power += lf.power_w;
            loads[station] = PointForce {
                force_n: f,
                point_m: lf.point_m,
            };
        }
    }
    (force, power, loads)
}
