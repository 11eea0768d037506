//! The right-hand side `ẏ = f(t, y)`, in stages (one concept per file, in the order of an
//! evaluation):
//!
//! 1. [`bodies`]: kinematics of the rings, the cage and every roller from `(t, y)`;
//! 2. contact detection per pair type, for all rollers in vector loops: roller ↔ raceway
//!    ([`raceways::detect`], SPEC §2.1–2.2), roller ↔ cage bar ([`cage::detect`]), roller end
//!    ↔ rib and pocket face ([`roller_ends::detect`]);
//! 3. contact forces: per roller the drag of the air–oil mixture, its bars, ribs and pocket
//!    faces, then the raceway slices of all rollers in one slot loop per raceway and their
//!    traction in one batch per raceway (SPEC §3.3), and the cage ↔ land contact and cage drag
//!    (§3.6);
//! 4. [`assembly`]: the Newton–Euler equations (seed 000 eqs. (2.1), (2.2)) with loads and
//!    gravity.
//!
//! Allocation-free: all scratch lives in [`Diagnostics`], allocated once.

pub(crate) mod assembly;
pub(crate) mod bodies;
mod cage;
mod diagnostics;
mod raceways;
mod roller_ends;

pub(crate) use cage::wall_overlap;
pub(crate) use diagnostics::{ContactTable, Diagnostics, Tables};

use crate::ends::ReachColumns;
use crate::model::Model;
use crate::vec3::{V3, add, axpy, dot, norm, perp, scale};
use bodies::{Bodies, RollerColumns};
use cage::PocketColumns;
use raceways::RacewayScratch;
use roller_ends::FaceBodies;

/// Force and moment on a body (the moment about its centre), N and N·m.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Wrench {
    pub force: V3,
    pub moment: V3,
}

/// The working arrays of the stages.
#[derive(Debug, Clone)]
pub(super) struct Scratch {
    rollers: RollerColumns,
    pockets: PocketColumns,
    /// per roller: the axial reach of its ends towards the inner ring, the outer ring, the cage
    reach: [ReachColumns; 3],
    raceways: RacewayScratch,
    /// per roller: the sum of its contact forces and gravity
    wrench: Vec<Wrench>,
}

impl Scratch {
    fn new(z: usize, slices: usize) -> Self {
        Self {
            rollers: RollerColumns::new(z),
            pockets: PocketColumns::new(z),
            reach: std::array::from_fn(|_| ReachColumns::new(z)),
            raceways: RacewayScratch::new(z, slices),
            wrench: vec![Wrench::default(); z],
        }
    }
}

/// Angular velocity of an axisymmetric body from its angular momentum `L` and unit axis `a`:
/// `ω = L/I_t + (1/I_a − 1/I_t)(a·L) a` (inverse of `L = I ω` with `I = I_t(E − aaᵀ) + I_a aaᵀ`).
#[inline]
pub fn axisymmetric_omega(l: V3, a: V3, ia: f64, it: f64) -> V3 {
    axpy(scale(l, 1.0 / it), (1.0 / ia - 1.0 / it) * dot(a, l), a)
}

/// Evaluates `dy = f(t, y)` and fills `diag` (its raceway contact tables only with
/// [`Tables::Fill`]).
pub(crate) fn rhs(
    model: &Model,
    t: f64,
    y: &[f64],
    dy: &mut [f64],
    diag: &mut Diagnostics,
    tables: Tables,
) {
    debug_assert_eq!(model.layout.len(), y.len());
    let bodies = bodies::bodies(model, t, y);
    diag.inner_speed = bodies.inner.spin;
    diag.outer_speed = bodies.outer.spin;
    diag.violation = None;
    let faces = roller_ends::face_bodies(model, &bodies);

    // detection for all rollers
    let sc = &mut diag.scratch;
    bodies::roller_columns(model, y, &mut sc.rollers);
    let (centre, axis) = (&sc.rollers.centre, &sc.rollers.axis);
    raceways::detect(model, &bodies, centre, axis, &mut sc.raceways);
    cage::detect(model, &bodies.cage, &sc.rollers, &mut sc.pockets);
    roller_ends::detect(model, &faces, &sc.rollers, &mut sc.reach);

    // contact forces: per roller its bars and ends, then the raceways of all rollers
    let (g, drag) = (
        model.conditions.gravity_m_s2,
        model.conditions.cage_drag_n_m_s,
    );
    let mut cage_wrench = Wrench {
        force: scale(g, model.m_c),
        moment: scale(bodies.cage.axis, -drag * bodies::cage_spin(&bodies.cage)),
    };
    let mut f_inner = [0.0; 3];
    for j in 0..model.z {
        roller_contacts(
            model,
            y,
            &bodies,
            &faces,
            j,
            diag,
            &mut cage_wrench,
            &mut f_inner,
        );
    }
    raceway_forces(model, &bodies, diag, &mut f_inner, tables);
    (diag.land_force, diag.land_power, diag.land_loads) = cage::land_contact(
        model,
        &bodies,
        &mut cage_wrench,
        &mut f_inner,
        &mut diag.violation,
    );

    let sc = &diag.scratch;
    assembly::roller_equations(model, y, dy, &sc.rollers, &sc.wrench);
    assembly::cage_equations(model, dy, &bodies.cage, &cage_wrench);
    assembly::inner_ring_equations(model, t, y, dy, f_inner);
}

/// Roller `j`: its kinematics, its slots prepared for the raceway slot loop, and its bar, rib
/// and pocket-face contacts. Gravity and these forces go into its wrench, their reactions into
/// the cage's (`cage_wrench`) and the inner ring's (`f_inner`).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn roller_contacts(
    model: &Model,
    y: &[f64],
    bodies: &Bodies,
    faces: &FaceBodies,
    j: usize,
    diag: &mut Diagnostics,
    cage_wrench: &mut Wrench,
    f_inner: &mut V3,
) {
    let sc = &mut diag.scratch;
    let rk = bodies::roller_kinematics(model, y, j, &mut sc.rollers);
    let azimuth = sc.rollers.theta[0][j];
    raceways::prepare_slots(model, bodies, j, &rk, azimuth, &mut sc.raceways);
    let mut roller = Wrench {
        force: add(
            scale(model.conditions.gravity_m_s2, model.m_r),
            roller_drag(model.conditions.roller_drag_kg_m, &rk),
        ),
        moment: [0.0; 3],
    };
    let violation = &mut diag.violation;
    let bar = cage::bar_contacts(
        model,
        &bodies.cage,
        j,
        &rk,
        &sc.pockets,
        (&mut roller, cage_wrench),
        violation,
    );
    diag.pocket_loads[j].bar = bar.points;
    diag.bar[j] = bar.normal;
    diag.bar_power[j] = bar.power;
    diag.bar_sliding[j] = if bar.normal > 0.0 {
        bar.sliding / bar.normal
    } else {
        0.0
    };
    let rib = roller_ends::rib_contacts(
        model,
        faces,
        j,
        &rk,
        &sc.reach,
        (&mut roller, f_inner),
        violation,
    );
    diag.rib[j] = rib.normal;
    diag.rib_power[j] = rib.power;
    diag.rib_regime[j] = rib.regime;
    if rib.normal > 0.0 {
        diag.rib_sliding[j] = rib.sliding / rib.normal;
        diag.rib_edge[j] = rib.edge / rib.normal;
        diag.rib_end_radius[j] = rib.end_radius / rib.normal;
        diag.rib_ring_radius[j] = rib.ring_radius / rib.normal;
        diag.rib_mu[j] = rib.mu / rib.normal;
    } else {
        diag.rib_sliding[j] = 0.0;
        diag.rib_edge[j] = f64::NAN;
        diag.rib_end_radius[j] = f64::NAN;
        diag.rib_ring_radius[j] = f64::NAN;
        diag.rib_mu[j] = 0.0;
    }
    let pocket = roller_ends::pocket_contacts(
        model,
        faces,
        j,
        &rk,
        &sc.reach,
        (&mut roller, cage_wrench),
        violation,
    );
    diag.pocket[j] = pocket.normal;
    diag.pocket_power[j] = pocket.power;
    diag.pocket_loads[j].end = pocket.points;
    sc.wrench[j] = roller;
}

/// Drag of the air–oil mixture (at rest) on a roller moving across its axis, F = −k |v| v
/// with k = ½ ρ_eff C_D D l (`rolldyn_lubrication::mixture::roller_drag_factor`), N.
#[inline(always)]
fn roller_drag(k: f64, rk: &crate::kinematics::RollerKinematics) -> V3 {
    if k == 0.0 {
        return [0.0; 3];
    }
    let v = perp(rk.v, rk.a);
    scale(v, -k * norm(v))
}

/// The raceway contacts of all rollers: slot loops, loaded slices, traction (added to the
/// rollers' wrenches and, reversed, to `f_inner`), then the contact tables' means.
fn raceway_forces(
    model: &Model,
    bodies: &Bodies,
    diag: &mut Diagnostics,
    f_inner: &mut V3,
    tables: Tables,
) {
    let sc = &mut diag.scratch;
    let contact_tables = (&mut diag.inner, &mut diag.outer);
    raceways::slice_contacts(
        model,
        bodies,
        &mut sc.raceways,
        contact_tables,
        &mut diag.violation,
        tables,
    );
    raceways::apply_traction(
        model,
        &mut sc.raceways,
        (&mut diag.inner, &mut diag.outer),
        &mut sc.wrench,
        f_inner,
        &sc.rollers.axis,
        tables,
    );
    if tables == Tables::Fill {
        for j in 0..model.z {
            diag.inner.finish(j);
            diag.outer.finish(j);
        }
    }
}
