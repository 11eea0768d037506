//! The cage's contacts: roller ↔ pocket walls (a broad phase for all rollers, then the sliced
//! roller against every face and lip of the pocket profile; SPEC §1.5, §3.3 pair 53,
//! docs/theory.md §3.4) and cage ↔ guiding land (SPEC §3.6).

use super::Wrench;
use super::bodies::{Bodies, CageKin, RollerColumns};
use super::diagnostics::{Violation, note};
use crate::kinematics::RollerKinematics;
use crate::land::LandKinematics;
use crate::model::Model;
use crate::output::PointForce;
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, scale, sub, unit_or};

/// Per pocket (struct of arrays): its frame in the cage plane and whether its roller can touch
/// a wall.
#[derive(Debug, Clone)]
pub(super) struct PocketColumns {
    /// radial and tangential unit vectors in the cage plane: e_x, e_y, e_z, t_x, t_y, t_z
    frame: [Vec<f64>; 6],
    /// a lower bound of the clearance of the roller's slices to the pocket walls, m
    clearance_bound: Vec<f64>,
}

impl PocketColumns {
    pub fn new(z: usize) -> Self {
        Self {
            frame: std::array::from_fn(|_| vec![0.0; z]),
            clearance_bound: vec![0.0; z],
        }
    }

    /// The radial and tangential unit vectors of pocket `j`.
    #[inline]
    fn frame(&self, j: usize) -> (V3, V3) {
        let f = &self.frame;
        ([f[0][j], f[1][j], f[2][j]], [f[3][j], f[4][j], f[5][j]])
    }
}

/// Pocket coordinates `(ρ, h)` of point `q` in the pocket frame `(e_p, t_p)` of a cage centred
/// at `cage_centre`.
#[inline]
fn pocket_coordinates(cage_centre: V3, (ep, tp): (V3, V3), q: V3) -> (f64, f64) {
    let d = sub(q, cage_centre);
    (dot(d, ep), dot(d, tp))
}

/// Overlap of a roller slice (centre `q`, radius `radius`) with the wall on `side` (±1) of its
/// pocket and the contact normal (from the wall towards the slice centre, in the cage plane):
/// [`rolldyn_geometry::PocketWalls::distance`].
#[inline]
pub(crate) fn wall_overlap(
    model: &Model,
    cage_centre: V3,
    (ep, tp): (V3, V3),
    side: f64,
    q: V3,
    radius: f64,
) -> (f64, V3) {
    let (rho, h) = pocket_coordinates(cage_centre, (ep, tp), q);
    let wall = model.pocket.distance(rho, side * h);
    let n = axpy(scale(ep, wall.normal[0]), side * wall.normal[1], tp);
    (radius - wall.distance, n)
}

/// Broad phase for all pockets at once: the pocket frames (radial unit vector of pocket `j` in
/// the cage plane at the angle φ_c + 2πj/Z by the angle-sum formulas, and the tangential one),
/// then a lower bound of the clearance of every slice of the roller: the clearance of the full
/// roller radius at the roller centre less the slices' largest offset from it in the cage plane
/// (the wall distance is 1-Lipschitz).
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
    for j in 0..z {
        let centre = [0, 1, 2].map(|k| rollers.centre[k][j]);
        let a = [0, 1, 2].map(|k| rollers.axis[k][j]);
        let (rho, h) = pocket_coordinates(cage.centre, pockets.frame(j), centre);
        let (g, _, _) = model.pocket.clearance(rho, h, model.rw);
        pockets.clearance_bound[j] = g - norm(perp(a, cage.axis)) * model.slice_reach;
    }
}

/// Roller `j` ↔ the walls of its pocket: every slice of the roller (its profiled radius) against
/// both walls, each wall the nearest of its faces and lips, the normal from the geometry. Each
/// slice of length `l_i` ([`Model::slice_length`]) carries its share of the pair's law
/// ([`rolldyn_contact::bar_force::BarForceLaw`]): elastic `Q = K_p' δⁿ + C(δ) δ̇` (seed 000
/// (2.5)–(2.8)), or the oil film's squeeze and wedge force within its reach plus that law on
/// touch; friction `μ(v_s) Q` against the sliding velocity. Adds the forces to the roller and
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
    let mut sums = BarSums::default();
    let law = &model.bar_law;
    if pockets.clearance_bound[j] > law.reach() {
        return sums;
    }
    let bar = &model.params.roller_cage;
    let frame = pockets.frame(j);
    let mut weighted_points = [[0.0; 3]; 4];
    let mut forces = [[0.0; 3]; 4];
    let mut normals = [0.0; 4];
    for (k, &side) in [-1.0, 1.0].iter().enumerate() {
        for (i, &x) in model.slice_x.iter().enumerate() {
            let q = axpy(rk.c, x, rk.a);
            let radius = model.rw - model.slice_drop[i];
            let (delta, n) = wall_overlap(model, cage.centre, frame, side, q, radius);
            if -delta >= law.reach() {
                continue;
            }
            note(violation, "roller ↔ cage pocket", j, delta, model.div_limit);
            let cp = axpy(q, -radius, n);
            let r_cp = sub(cp, rk.c);
            let v_roll = add(rk.v, cross(rk.w, r_cp));
            let v_cage = add(cage.velocity, cross(cage.omega, sub(cp, cage.centre)));
            let vrel = sub(v_roll, v_cage);
            // entrainment: half the roller's surface speed over the bar (fixed on the cage),
            // across the roller axis in the contact's tangent plane
            let rolling = unit_or(cross(rk.a, n), [0.0; 3]);
            let entrainment = 0.5 * dot(vrel, rolling);
            let qn = law.normal_force(-delta, dot(vrel, n), entrainment, model.slice_length[i]);
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
            let group = 2 * k + usize::from(x >= 0.0);
            forces[group] = sub(forces[group], fc);
            weighted_points[group] = axpy(weighted_points[group], qn, cp);
            normals[group] += qn;
            sums.normal += qn;
            sums.power += mu * qn * vs;
            sums.sliding += qn * vs;
        }
    }
    for g in 0..4 {
        if normals[g] > 0.0 {
            sums.points[g] = PointForce {
                force_n: forces[g],
                point_m: scale(weighted_points[g], 1.0 / normals[g]),
            };
        }
    }
    sums
}

/// Sums of one roller's pocket contacts: normal force, friction power and the force-weighted
/// sliding speed (the speed of the friction law), and the force on the cage of each quarter of
/// the contacts — pocket side (−, +) × roller half (x < 0, x ≥ 0) — at its force-weighted
/// point ([`PocketLoads::bar`](crate::output::PocketLoads)).
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
