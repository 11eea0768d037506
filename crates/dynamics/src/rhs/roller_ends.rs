//! Roller ends ↔ ring ribs (SPEC §3.3 pair 56) and ↔ cage pocket faces (pair 54): the axial
//! reach of every roller towards each face-carrying body (detection, vector loops), then the
//! forces of the faces within reach ([`end_force`]).

use super::Wrench;
use super::bodies::{Bodies, RollerColumns};
use super::diagnostics::{Violation, note};
use crate::ends::{BodyKin, EndContactRegime, EndForce, EndLubrication, ReachColumns, end_force};
use crate::kinematics::RollerKinematics;
use crate::model::Model;
use crate::output::PointForce;
use crate::vec3::{V3, add, scale, sub};

/// A ring as a carrier of ribs: its kinematics, the lubrication of its rib contacts, and whether
/// it is the inner ring.
pub(super) struct RibRing<'a> {
    body: BodyKin,
    lubrication: EndLubrication<'a>,
    inner: bool,
}

/// The bodies that carry end faces, the same for every roller: both rings (with the
/// lubrication of their rib contacts) and the cage.
pub(super) struct FaceBodies<'a> {
    rings: [RibRing<'a>; 2],
    cage: BodyKin,
}

/// The face-carrying bodies of this evaluation.
pub(super) fn face_bodies<'a>(model: &'a Model, bodies: &Bodies) -> FaceBodies<'a> {
    let ends = &model.ends;
    let temperatures = &model.conditions.temperatures;
    let ring = |inner: bool| {
        let (kin, traction, temperature_k) = if inner {
            (
                &bodies.inner,
                &model.traction.inner,
                temperatures.inner_raceway_k,
            )
        } else {
            (
                &bodies.outer,
                &model.traction.outer,
                temperatures.outer_raceway_k,
            )
        };
        RibRing {
            body: kin.body(),
            lubrication: EndLubrication {
                model: traction,
                reduced_radius: ends.rib_reduced_radius,
                film_limit_radius: ends.rib_reduced_radius,
                reduced_modulus: ends.rib_reduced_modulus,
                roughness: ends.rib_roughness,
                temperature_k,
            },
            inner,
        }
    };
    FaceBodies {
        rings: [ring(true), ring(false)],
        cage: bodies.cage.body(),
    }
}

/// The rib faces of a ring.
fn ribs(model: &Model, inner: bool) -> &[crate::ends::FaceGeometry] {
    if inner {
        &model.ends.inner_ribs
    } else {
        &model.ends.outer_ribs
    }
}

/// Detection for all rollers: the axial reach of their ends towards the inner ring, the outer
/// ring and the cage (`reach`, in that order), for the pairs that are enabled.
pub(super) fn detect(
    model: &Model,
    faces: &FaceBodies,
    rollers: &RollerColumns,
    reach: &mut [ReachColumns; 3],
) {
    let end = &model.ends.end;
    let (centre, axis) = (&rollers.centre, &rollers.axis);
    let [inner_reach, outer_reach, cage_reach] = reach;
    if model.params.roller_end_rib.enabled {
        for (ring, reach) in faces.rings.iter().zip([inner_reach, outer_reach]) {
            if !ribs(model, ring.inner).is_empty() {
                reach.compute(&ring.body, end, centre, axis);
            }
        }
    }
    if model.params.roller_end_cage.enabled {
        cage_reach.compute(&faces.cage, end, centre, axis);
    }
}

/// Sums of one roller's rib contacts: normal force and the force-weighted sliding speed, edge
/// distance, contact radii (from the roller axis, from the ring axis) and friction
/// coefficient, the friction power and the regime of the most loaded.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct RibSums {
    pub normal: f64,
    pub sliding: f64,
    pub edge: f64,
    pub end_radius: f64,
    pub ring_radius: f64,
    pub mu: f64,
    pub power: f64,
    best: f64,
    pub regime: EndContactRegime,
}

impl RibSums {
    #[inline(always)]
    fn add(&mut self, ef: &EndForce) {
        self.normal += ef.normal;
        self.sliding += ef.normal * ef.sliding;
        self.edge += ef.normal * ef.edge_distance;
        self.end_radius += ef.normal * ef.end_radius;
        self.ring_radius += ef.normal * ef.body_radius;
        self.mu += ef.normal * ef.mu;
        self.power += ef.mu * ef.normal * ef.sliding;
        if ef.normal > self.best {
            self.best = ef.normal;
            self.regime = ef.regime;
        }
    }
}

/// Adds an end force to the roller.
#[inline]
fn apply(ef: &EndForce, roller: &mut Wrench) {
    roller.force = add(roller.force, ef.force);
    roller.moment = add(roller.moment, ef.moment);
}

/// Roller `j`'s ends ↔ the ribs of both rings: adds the forces to the roller and the reaction
/// to the inner ring (`f_inner`).
#[inline(always)]
pub(super) fn rib_contacts(
    model: &Model,
    faces: &FaceBodies,
    j: usize,
    rk: &RollerKinematics,
    reach: &[ReachColumns; 3],
    (roller, f_inner): (&mut Wrench, &mut V3),
    violation: &mut Option<Violation>,
) -> RibSums {
    let mut sums = RibSums::default();
    if !model.params.roller_end_rib.enabled {
        return sums;
    }
    let ends = &model.ends;
    for (k, ring) in faces.rings.iter().enumerate() {
        let ribs = ribs(model, ring.inner);
        if ribs.is_empty() {
            continue;
        }
        let reach = reach[k].get(j);
        for face in ribs {
            if reach.bound(face, &ends.end) <= 0.0 {
                continue;
            }
            let Some(ef) = end_force(
                face,
                &ends.end,
                &ring.body,
                &reach,
                rk,
                &model.params.roller_end_rib,
                &ends.rib_damping,
                Some(&ring.lubrication),
            ) else {
                continue;
            };
            note(violation, "roller end ↔ rib", j, ef.delta, model.div_limit);
            apply(&ef, roller);
            if ring.inner {
                *f_inner = sub(*f_inner, ef.force);
            }
            sums.add(&ef);
        }
    }
    sums
}

/// Roller `j`'s ends ↔ the faces of its cage pocket: adds the forces to the roller and their
/// reaction to the cage.
#[inline(always)]
pub(super) fn pocket_contacts(
    model: &Model,
    faces: &FaceBodies,
    j: usize,
    rk: &RollerKinematics,
    reach: &[ReachColumns; 3],
    (roller, cage): (&mut Wrench, &mut Wrench),
    violation: &mut Option<Violation>,
) -> PocketSums {
    let mut sums = PocketSums::default();
    if !model.params.roller_end_cage.enabled {
        return sums;
    }
    let ends = &model.ends;
    let reach = reach[2].get(j);
    for (k, face) in ends.pocket.iter().enumerate() {
        if reach.bound(face, &ends.end) <= 0.0 {
            continue;
        }
        let Some(ef) = end_force(
            face,
            &ends.end,
            &faces.cage,
            &reach,
            rk,
            &model.params.roller_end_cage,
            &ends.pocket_damping,
            None,
        ) else {
            continue;
        };
        let what = "roller end ↔ cage pocket face";
        note(violation, what, j, ef.delta, model.div_limit);
        apply(&ef, roller);
        cage.force = sub(cage.force, ef.force);
        cage.moment = add(cage.moment, ef.body_moment);
        sums.normal += ef.normal;
        sums.power += ef.mu * ef.normal * ef.sliding;
        sums.points[k] = PointForce {
            force_n: scale(ef.force, -1.0),
            point_m: ef.point,
        };
    }
    sums
}

/// One roller's pocket-face contacts: normal force, friction power and the force of each face's
/// contact on the cage.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct PocketSums {
    pub normal: f64,
    pub power: f64,
    pub points: [PointForce; 2],
}
