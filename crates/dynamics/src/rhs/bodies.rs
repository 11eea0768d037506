//! Stage 1 of the right-hand side: the kinematics of every body at `(t, y)` — the rings (one
//! prescribed spin each, the inner ring free to translate), the cage, and every roller (its
//! centre and unit axis for all rollers in vector loops, then its velocities one by one).

use super::axisymmetric_omega;
use crate::ends::BodyKin;
use crate::kinematics::RollerKinematics;
use crate::layout::{CAGE_DOF, cage, inner_ring, read3, roller};
use crate::model::Model;
use crate::vec3::{V3, dot, scale, unit_or};
use rolldyn_numerics::fastmath;

/// Kinematics of a ring (centre, velocity, axis, spin, rotation angle) and its raceway radius
/// at this time.
pub(super) struct RingKin {
    pub o: V3,
    pub v: V3,
    pub axis: V3,
    pub spin: f64,
    /// rotation angle ∫ω dt, rad: a point at angle ψ in the ring's frame is at azimuth
    /// ψ + angle
    pub angle: f64,
    pub raceway_radius: f64,
}

impl RingKin {
    /// The ring as a body that carries faces (its ribs, its land).
    pub fn body(&self) -> BodyKin {
        BodyKin {
            o: self.o,
            v: self.v,
            axis: self.axis,
            omega: scale(self.axis, self.spin),
        }
    }
}

/// Kinematics of the cage: centre, unit axis, velocity, angular velocity and momentum, and the
/// sine and cosine of its angle φ.
pub(crate) struct CageKin {
    pub centre: V3,
    pub axis: V3,
    pub velocity: V3,
    pub omega: V3,
    pub sin_phi: f64,
    pub cos_phi: f64,
}

impl CageKin {
    /// The cage as a body that carries faces (its pocket faces).
    pub fn body(&self) -> BodyKin {
        BodyKin {
            o: self.centre,
            v: self.velocity,
            axis: self.axis,
            omega: self.omega,
        }
    }
}

/// The rings and the cage at one evaluation.
pub(super) struct Bodies {
    pub inner: RingKin,
    pub outer: RingKin,
    pub cage: CageKin,
}

/// The rings at time `t` (prescribed speeds and, SPEC §3.7, a scheduled operating clearance,
/// which moves the outer raceway by half its change) and the cage, from the state `y`.
pub(super) fn bodies(model: &Model, t: f64, y: &[f64]) -> Bodies {
    let lay = model.layout;
    let cond = &model.conditions;
    let ii = lay.inner();
    let inner = RingKin {
        o: read3(y, ii + inner_ring::CENTRE),
        v: read3(y, ii + inner_ring::VELOCITY),
        axis: model.axis_i,
        spin: cond.inner_speed.speed(t),
        angle: cond.inner_speed.angle(t),
        raceway_radius: model.ri,
    };
    let outer = RingKin {
        o: [0.0; 3],
        v: [0.0; 3],
        axis: [0.0, 0.0, 1.0],
        spin: cond.outer_speed.speed(t),
        angle: cond.outer_speed.angle(t),
        raceway_radius: model.ro
            + cond
                .clearance_at(t)
                .map_or(0.0, |g| 0.5 * (g - model.clearance)),
    };
    let cage = cage_kinematics(
        &y[lay.cage()..lay.cage() + CAGE_DOF],
        model.ia_c,
        model.it_c,
    );
    Bodies { inner, outer, cage }
}

/// Kinematics of a cage from its [`CAGE_DOF`] state components and its axial and transverse
/// moments of inertia.
pub(crate) fn cage_kinematics(y: &[f64], ia: f64, it: f64) -> CageKin {
    let axis = unit_or(read3(y, cage::AXIS), [0.0, 0.0, 1.0]);
    let momentum = read3(y, cage::MOMENTUM);
    let (sin_phi, cos_phi) = y[cage::ANGLE].sin_cos();
    CageKin {
        centre: read3(y, cage::CENTRE),
        axis,
        velocity: read3(y, cage::VELOCITY),
        omega: axisymmetric_omega(momentum, axis, ia, it),
        sin_phi,
        cos_phi,
    }
}

/// Per roller, as struct of arrays for the vector loops of the detection stages.
#[derive(Debug, Clone)]
pub(super) struct RollerColumns {
    /// azimuth θ, sin θ, cos θ (one vectorised `sin_cos` for all rollers)
    pub theta: [Vec<f64>; 3],
    /// centre and unit axis
    pub centre: [Vec<f64>; 3],
    pub axis: [Vec<f64>; 3],
    /// sin θ, cos θ, unit axis and angular velocity ([`roller_kinematics`], reused by the
    /// Newton–Euler equations)
    pub frame: Vec<(f64, f64, V3, V3)>,
}

impl RollerColumns {
    pub fn new(z: usize) -> Self {
        Self {
            theta: [vec![0.0; z], vec![0.0; z], vec![1.0; z]],
            centre: [vec![0.0; z], vec![0.0; z], vec![0.0; z]],
            axis: [vec![0.0; z], vec![0.0; z], vec![1.0; z]],
            frame: vec![(0.0, 1.0, [0.0, 0.0, 1.0], [0.0; 3]); z],
        }
    }
}

/// Every roller's azimuth, centre `(r cos θ, r sin θ, z)` and unit axis `unit_or(a, e_z)`
/// (with the same expressions), in vector loops.
pub(super) fn roller_columns(model: &Model, y: &[f64], cols: &mut RollerColumns) {
    let lay = model.layout;
    let z = model.z;
    let [theta, sin_theta, cos_theta] = &mut cols.theta;
    for (j, th) in theta.iter_mut().enumerate() {
        *th = y[lay.roller(j) + roller::AZIMUTH];
    }
    fastmath::sin_cos_many(theta, sin_theta, cos_theta);
    let [cx, cy, cz] = &mut cols.centre;
    let [ax, ay, az] = &mut cols.axis;
    for j in 0..z {
        let b = lay.roller(j);
        let r = y[b + roller::RADIUS];
        cx[j] = r * cols.theta[2][j];
        cy[j] = r * cols.theta[1][j];
        cz[j] = y[b + roller::AXIAL];
        [ax[j], ay[j], az[j]] = read3(y, b + roller::AXIS);
    }
    let (ax, ay, az) = (&mut ax[..z], &mut ay[..z], &mut az[..z]);
    for j in 0..z {
        let n = (ax[j] * ax[j] + ay[j] * ay[j] + az[j] * az[j]).sqrt();
        let inv = 1.0 / n;
        let some = n > 0.0;
        ax[j] = if some { ax[j] * inv } else { 0.0 };
        ay[j] = if some { ay[j] * inv } else { 0.0 };
        az[j] = if some { az[j] * inv } else { 1.0 };
    }
}

/// Roller `j`'s centre, axis, velocity `(ṙ cos θ − r θ̇ sin θ, ṙ sin θ + r θ̇ cos θ, ż)` and
/// angular velocity `ω(L, a)`; records its frame in `cols.frame[j]`.
#[inline(always)]
pub(super) fn roller_kinematics(
    model: &Model,
    y: &[f64],
    j: usize,
    cols: &mut RollerColumns,
) -> RollerKinematics {
    let b = model.layout.roller(j);
    let (r, zz) = (y[b + roller::RADIUS], y[b + roller::AXIAL]);
    let a = [cols.axis[0][j], cols.axis[1][j], cols.axis[2][j]];
    let thd = y[b + roller::ORBITAL_SPEED];
    let rdot = y[b + roller::RADIAL_VELOCITY];
    let zd = y[b + roller::AXIAL_VELOCITY];
    let w = axisymmetric_omega(read3(y, b + roller::MOMENTUM), a, model.ia_r, model.it_r);
    let (s, c) = (cols.theta[1][j], cols.theta[2][j]);
    cols.frame[j] = (s, c, a, w);
    RollerKinematics {
        c: [r * c, r * s, zz],
        a,
        v: [rdot * c - r * thd * s, rdot * s + r * thd * c, zd],
        w,
        orbit: thd,
    }
}

/// One roller's kinematics from its [`crate::layout::ROLLER_DOF`] state components `y` and its
/// axial and transverse inertia (the scalar form of [`roller_columns`] and
/// [`roller_kinematics`]), with its frame `(sin θ, cos θ, a, ω)` for [`super::assembly::roller_rates`].
pub(crate) fn single_roller_kinematics(
    y: &[f64],
    ia: f64,
    it: f64,
) -> (RollerKinematics, (f64, f64, V3, V3)) {
    let (s, c) = y[roller::AZIMUTH].sin_cos();
    let (r, zz) = (y[roller::RADIUS], y[roller::AXIAL]);
    let a = unit_or(read3(y, roller::AXIS), [0.0, 0.0, 1.0]);
    let thd = y[roller::ORBITAL_SPEED];
    let rdot = y[roller::RADIAL_VELOCITY];
    let w = axisymmetric_omega(read3(y, roller::MOMENTUM), a, ia, it);
    let kin = RollerKinematics {
        c: [r * c, r * s, zz],
        a,
        v: [
            rdot * c - r * thd * s,
            rdot * s + r * thd * c,
            y[roller::AXIAL_VELOCITY],
        ],
        w,
        orbit: thd,
    };
    (kin, (s, c, a, w))
}

/// Axial component of the cage's angular velocity, `ω_c · a_c` (its spin).
#[inline]
pub(crate) fn cage_spin(cage: &CageKin) -> f64 {
    dot(cage.omega, cage.axis)
}
