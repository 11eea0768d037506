//! The last stage: the Newton–Euler equations of every body from the summed contact forces —
//! rollers in cylindrical coordinates (seed 000 (2.1)) with `L̇ = M` ((2.2) in the inertial
//! frame: the gyroscopic term is contained in `ω(L, a)`), the cage, and the inner ring with its
//! prescribed spin and tilt and free or fixed translation.

use super::Wrench;
use super::bodies::{CageKin, RollerColumns, cage_spin};
use crate::layout::{cage, inner_ring, read3, roller, write3};
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
    for (j, (&(s, c, a, w), wrench)) in rollers.frame.iter().zip(wrench).enumerate() {
        let b = model.layout.roller(j);
        let r = y[b + roller::RADIUS];
        let thd = y[b + roller::ORBITAL_SPEED];
        let rdot = y[b + roller::RADIAL_VELOCITY];
        let zd = y[b + roller::AXIAL_VELOCITY];
        let Wrench {
            force: f,
            moment: m,
        } = *wrench;
        let f_radial = dot(f, [c, s, 0.0]);
        let f_tangential = dot(f, [-s, c, 0.0]);
        dy[b + roller::AZIMUTH] = thd;
        dy[b + roller::RADIUS] = rdot;
        dy[b + roller::AXIAL] = zd;
        write3(dy, b + roller::AXIS, cross(w, a));
        dy[b + roller::ORBITAL_SPEED] = (f_tangential * inv_mr - 2.0 * rdot * thd) / r;
        dy[b + roller::RADIAL_VELOCITY] = f_radial * inv_mr + r * thd * thd;
        dy[b + roller::AXIAL_VELOCITY] = f[2] * inv_mr;
        write3(dy, b + roller::MOMENTUM, m);
    }
}

/// `ẏ` of the cage: `ċ = v`, `φ̇ = ω·a`, `ȧ = ω × a`, `v̇ = F/m`, `L̇ = M`.
pub(super) fn cage_equations(model: &Model, dy: &mut [f64], kin: &CageKin, wrench: &Wrench) {
    let ci = model.layout.cage();
    write3(dy, ci + cage::CENTRE, kin.velocity);
    dy[ci + cage::ANGLE] = cage_spin(kin);
    write3(dy, ci + cage::AXIS, cross(kin.omega, kin.axis));
    write3(
        dy,
        ci + cage::VELOCITY,
        scale(wrench.force, 1.0 / model.m_c),
    );
    write3(dy, ci + cage::MOMENTUM, wrench.moment);
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
