//! The last stage: the Newton–Euler equations of every body from the summed contact forces —
//! rollers in cylindrical coordinates (seed 000 (2.1)) with `L̇ = M` ((2.2) in the inertial
//! frame: the gyroscopic term is contained in `ω(L, a)`), the cage, and the inner ring with its
//! prescribed spin and tilt and free or fixed translation.

use super::Wrench;
use super::bodies::{CageKin, RollerColumns, cage_spin};
use crate::layout::{CAGE_DOF, ROLLER_DOF, cage, inner_ring, read3, roller, write3};
use crate::model::Model;
use crate::vec3::{V3, add, axpy, cross, dot, scale};

/// `ẏ` of every roller from its frame and its force and moment `wrench` (about its centre):
/// `θ̈ = (F_t/m − 2ṙθ̇)/r`, `r̈ = F_r/m + rθ̇²`, `z̈ = F_z/m`, `ȧ = ω × a`, `L̇ = M`.
pub(super) fn roller_equations(
    model: &Model,
    y: &[f64],
    dy: &mut [f64],
    rollers: &RollerColumns,
    wrench: &[Wrench],
) {
    let inv_mr = 1.0 / model.m_r;
    for (j, (frame, wrench)) in rollers.frame.iter().zip(wrench).enumerate() {
        let b = model.layout.roller(j);
        roller_rates(
            &y[b..b + ROLLER_DOF],
            &mut dy[b..b + ROLLER_DOF],
            *frame,
            wrench,
            inv_mr,
        );
    }
}

/// `ẏ` of one roller (its [`ROLLER_DOF`] components `y`, `dy`) from its frame
/// `(sin θ, cos θ, a, ω)`, its wrench about its centre and `1/m`: the equations of
/// [`roller_equations`].
pub(crate) fn roller_rates(
    y: &[f64],
    dy: &mut [f64],
    (s, c, a, w): (f64, f64, V3, V3),
    wrench: &Wrench,
    inv_m: f64,
) {
    let r = y[roller::RADIUS];
    let thd = y[roller::ORBITAL_SPEED];
    let rdot = y[roller::RADIAL_VELOCITY];
    let zd = y[roller::AXIAL_VELOCITY];
    let Wrench {
        force: f,
        moment: m,
    } = *wrench;
    let f_radial = dot(f, [c, s, 0.0]);
    let f_tangential = dot(f, [-s, c, 0.0]);
    dy[roller::AZIMUTH] = thd;
    dy[roller::RADIUS] = rdot;
    dy[roller::AXIAL] = zd;
    write3(dy, roller::AXIS, cross(w, a));
    dy[roller::ORBITAL_SPEED] = (f_tangential * inv_m - 2.0 * rdot * thd) / r;
    dy[roller::RADIAL_VELOCITY] = f_radial * inv_m + r * thd * thd;
    dy[roller::AXIAL_VELOCITY] = f[2] * inv_m;
    write3(dy, roller::MOMENTUM, m);
}

/// `ẏ` of the cage: `ċ = v`, `φ̇ = ω·a`, `ȧ = ω × a`, `v̇ = F/m`, `L̇ = M`.
pub(super) fn cage_equations(model: &Model, dy: &mut [f64], kin: &CageKin, wrench: &Wrench) {
    let ci = model.layout.cage();
    cage_rates(&mut dy[ci..ci + CAGE_DOF], kin, wrench, model.m_c);
}

/// `ẏ` of one cage (its [`CAGE_DOF`] components `dy`) of mass `m`: the equations of
/// [`cage_equations`].
pub(crate) fn cage_rates(dy: &mut [f64], kin: &CageKin, wrench: &Wrench, m: f64) {
    write3(dy, cage::CENTRE, kin.velocity);
    dy[cage::ANGLE] = cage_spin(kin);
    write3(dy, cage::AXIS, cross(kin.omega, kin.axis));
    write3(dy, cage::VELOCITY, scale(wrench.force, 1.0 / m));
    write3(dy, cage::MOMENTUM, wrench.moment);
}

/// `ẏ` of the inner ring under the contact force `f_inner`, the applied load at `t` and
/// gravity: each translation free or fixed by its support (SPEC §3.7).
pub(super) fn inner_ring_equations(model: &Model, t: f64, y: &[f64], dy: &mut [f64], f_inner: V3) {
    let cond = &model.conditions;
    let sup = cond.support;
    let load = cond.inner_ring_force(t);
    let acc = axpy(
        scale(add(f_inner, load), 1.0 / model.m_i),
        1.0,
        cond.gravity_m_s2,
    );
    let ii = model.layout.inner();
    let velocity = read3(y, ii + inner_ring::VELOCITY);
    for k in 0..3 {
        let free = if k < 2 {
            sup.radial_free
        } else {
            sup.axial_free
        };
        dy[ii + inner_ring::CENTRE + k] = if free { velocity[k] } else { 0.0 };
        dy[ii + inner_ring::VELOCITY + k] = if free { acc[k] } else { 0.0 };
    }
}
