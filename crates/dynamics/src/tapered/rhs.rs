//! The right-hand side of the double-row tapered bearing: per roller its slices on cone and cup
//! (normal along the raceway line's normal in the axial plane through the slice centre), its
//! large end on the large rib and its small end on the small rib ([`crate::ends`], SPEC §6.7
//! regime switch), its ends on the pocket faces and its body on the four bar edges of its pocket
//! (the cage rides on the rollers); then the Newton–Euler equations of every body.

use super::contacts::{RibContact, RollerContacts};
use super::geometry::HalfPlaneLine;
use super::layout::TaperedLayout;
use super::model::TaperedModel;
use crate::ends::{AxialReach, BodyKin, EndGeometry, EndLubrication, FaceGeometry, end_force};
use crate::integrator::OdeSystem;
use crate::kinematics::RollerKinematics;
use crate::layout::{CAGE_DOF, INNER_DOF, ROLLER_DOF, cage, inner_ring, read3, write3};
use crate::rhs::Wrench;
use crate::rhs::assembly::{cage_rates, roller_rates};
use crate::rhs::bodies::{CageKin, cage_kinematics, single_roller_kinematics};
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, power, scale, sub};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_lubrication::{
    BatchContact, ContactGeometry, ContactState, SliceBatch, TractionModel, traction,
};

/// Per-roller results of the last reported evaluation.
#[derive(Debug, Clone, Default)]
pub struct RollerReport {
    /// total normal force on cone and cup, N
    pub cone: f64,
    pub cup: f64,
    /// largest slice force on the cone, N
    pub cone_slice_max: f64,
    /// load-weighted sliding speed on cone and cup, m/s
    pub cone_sliding: f64,
    pub cup_sliding: f64,
    /// largest relative slip |v|/u of a loaded slice (both raceways)
    pub slip: f64,
    /// large-end ↔ large-rib and small-end ↔ small-rib normal forces, N
    pub large_rib: f64,
    pub small_rib: f64,
    /// large-end ↔ rib: sliding speed, m/s, and whether it ran in EHL (patch inside the overlap)
    pub rib_sliding: f64,
    pub rib_ehl: bool,
    /// roller ↔ cage bars and pocket faces, N
    pub cage: f64,
}

/// The system integrated: model, scratch and the report of the last reported evaluation.
pub struct TaperedSystem<'m> {
    pub model: &'m TaperedModel,
    pub layout: TaperedLayout,
    pub rollers: Vec<RollerReport>,
    /// net contact force of all rollers on the inner ring, N
    pub inner_contact_force: V3,
    wrench: Vec<Wrench>,
    /// scratch of the raceway slices of one roller
    pub(super) slices: SliceScratch,
    /// per roller: its contacts' share of its cage's wrench and of the force on the inner ring
    /// in the last evaluation (the coupling columns of the Rosenbrock-W Jacobian,
    /// [`TaperedSystem::border_support`])
    shares: Vec<RollerShare>,
    report: bool,
    /// the opt-in contact record of the last reported evaluation (see [`super::contacts`])
    pub(crate) contacts: Option<Vec<RollerContacts>>,
}

impl<'m> TaperedSystem<'m> {
    pub fn new(model: &'m TaperedModel) -> Self {
        let layout = TaperedLayout { z: model.z };
        Self {
            model,
            layout,
            rollers: vec![RollerReport::default(); 2 * model.z],
            inner_contact_force: [0.0; 3],
            wrench: vec![Wrench::default(); 2 * model.z],
            slices: SliceScratch::default(),
            shares: vec![RollerShare::default(); 2 * model.z],
            report: false,
            contacts: None,
        }
    }
}

impl TaperedSystem<'_> {
    /// Turns on the contact record of every reported evaluation.
    pub(crate) fn record_contacts(&mut self) {
        let slices = self.model.slices.x.len();
        self.contacts = Some(vec![RollerContacts::zeroed(slices); 2 * self.model.z]);
    }
}

impl OdeSystem for TaperedSystem<'_> {
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.report = false;
        evaluate(self, t, y, dy);
    }

    fn rhs_reported(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.report = true;
        evaluate(self, t, y, dy);
    }

    /// Per roller, in the order of [`TaperedSystem::border_support`]: its share of its cage's
    /// rates (`v̇ = F/m_c`, `L̇ = M`, the other components 0) and of the inner ring's
    /// (`v̇ = F/m_i`).
    fn border_shares(&self, out: &mut [f64]) {
        let (m_c, m_i) = (self.model.m_c, self.model.m_i);
        for (share, o) in self
            .shares
            .iter()
            .zip(out.chunks_exact_mut(CAGE_DOF + INNER_DOF))
        {
            o.fill(0.0);
            write3(o, cage::VELOCITY, scale(share.cage.force, 1.0 / m_c));
            write3(o, cage::MOMENTUM, share.cage.moment);
            write3(
                o,
                CAGE_DOF + inner_ring::VELOCITY,
                scale(share.inner, 1.0 / m_i),
            );
        }
    }
}

/// A roller's contacts' share of the wrench on its cage and of the force on the inner ring.
#[derive(Debug, Clone, Copy, Default)]
struct RollerShare {
    cage: Wrench,
    inner: V3,
}

impl RollerShare {
    /// The share as the change of the accumulated cage wrench and inner-ring force over the
    /// roller's contacts (`before` → `after`); the accumulation itself is left untouched.
    fn between(before: (&Wrench, V3), after: (&Wrench, V3)) -> Self {
        Self {
            cage: Wrench {
                force: sub(after.0.force, before.0.force),
                moment: sub(after.0.moment, before.0.moment),
            },
            inner: sub(after.1, before.1),
        }
    }
}

impl TaperedSystem<'_> {
    /// The state components roller `j`'s rates depend on beyond its own and whose rates its
    /// contacts enter: its row's cage and the inner ring (the border of the coupled
    /// Rosenbrock-W Jacobian, [`crate::rosenbrock::JacobianBorder`]).
    pub(crate) fn border_support(layout: &TaperedLayout, j: usize) -> Vec<usize> {
        let cage = layout.cage(j / layout.z);
        (cage..cage + CAGE_DOF)
            .chain(layout.inner()..layout.inner() + INNER_DOF)
            .collect()
    }
}

/// The inner ring (both cones and the spacer) as a body carrying faces.
fn inner_body(model: &TaperedModel, t: f64, y: &[f64], lay: &TaperedLayout) -> BodyKin {
    let ii = lay.inner();
    BodyKin {
        o: read3(y, ii + inner_ring::CENTRE),
        v: read3(y, ii + inner_ring::VELOCITY),
        axis: model.axis_i,
        omega: scale(model.axis_i, model.conditions.inner_speed.speed(t)),
    }
}

/// The cup: fixed, axis z.
const CUP: BodyKin = BodyKin {
    o: [0.0; 3],
    v: [0.0; 3],
    axis: [0.0, 0.0, 1.0],
    omega: [0.0; 3],
};

fn evaluate(sys: &mut TaperedSystem, t: f64, y: &[f64], dy: &mut [f64]) {
    let model = sys.model;
    let lay = sys.layout;
    let inner = inner_body(model, t, y, &lay);
    let cages: [CageKin; 2] = std::array::from_fn(|k| {
        let ci = lay.cage(k);
        cage_kinematics(&y[ci..ci + CAGE_DOF], model.ia_c, model.it_c)
    });
    let g = model.conditions.gravity_m_s2;
    let mut cage_wrench = [0, 1].map(|_| Wrench {
        force: scale(g, model.m_c),
        moment: [0.0; 3],
    });
    let mut f_inner = [0.0; 3];
    for j in 0..2 * model.z {
        let row = j / model.z;
        let b = lay.roller(j);
        let (rk, frame) = single_roller_kinematics(&y[b..b + ROLLER_DOF], model.ia_r, model.it_r);
        let mut report = RollerReport::default();
        let mut roller = Wrench {
            force: scale(g, model.m_r),
            moment: [0.0; 3],
        };
        let mut record = match (&mut sys.contacts, sys.report) {
            (Some(c), true) => Some(&mut c[j]),
            _ => None,
        };
        if let Some(r) = record.as_deref_mut() {
            (r.yaw_rad, r.pitch_rad) = yaw_and_pitch(&model.rows[row], &rk);
        }
        let before = (cage_wrench[row], f_inner);
        raceways(
            model,
            row,
            &rk,
            &inner,
            &mut roller,
            &mut f_inner,
            &mut sys.slices,
            (&mut report, record.as_deref_mut()),
        );
        ends(
            model,
            row,
            &rk,
            &inner,
            &cages[row],
            &mut roller,
            (&mut f_inner, &mut cage_wrench[row]),
            (&mut report, record),
        );
        bars(
            model,
            row,
            j % model.z,
            &rk,
            &cages[row],
            &mut roller,
            &mut cage_wrench[row],
            &mut report,
        );
        sys.shares[j] = RollerShare::between((&before.0, before.1), (&cage_wrench[row], f_inner));
        sys.wrench[j] = roller;
        roller_rates(
            &y[b..b + ROLLER_DOF],
            &mut dy[b..b + ROLLER_DOF],
            frame,
            &sys.wrench[j],
            1.0 / model.m_r,
        );
        if sys.report {
            sys.rollers[j] = report;
        }
    }
    for k in 0..2 {
        let ci = lay.cage(k);
        cage_rates(
            &mut dy[ci..ci + CAGE_DOF],
            &cages[k],
            &cage_wrench[k],
            model.m_c,
        );
    }
    if sys.report {
        sys.inner_contact_force = f_inner;
    }
    inner_ring_rates(model, t, y, dy, &lay, f_inner);
}

/// `ẏ` of the inner ring: free translation under contacts, the applied loads and gravity.
fn inner_ring_rates(
    model: &TaperedModel,
    t: f64,
    y: &[f64],
    dy: &mut [f64],
    lay: &TaperedLayout,
    f_inner: V3,
) {
    let cond = &model.conditions;
    let acc = axpy(
        scale(add(f_inner, cond.inner_ring_force(t)), 1.0 / model.m_i),
        1.0,
        cond.gravity_m_s2,
    );
    let ii = lay.inner();
    let v = read3(y, ii + inner_ring::VELOCITY);
    for k in 0..3 {
        dy[ii + inner_ring::CENTRE + k] = v[k];
        dy[ii + inner_ring::VELOCITY + k] = acc[k];
    }
}

/// Position of a point in a body's half-plane: `(ρ, ζ, e_ρ)`.
#[inline]
fn half_plane(body: &BodyKin, p: V3) -> (f64, f64, V3) {
    let rel = sub(p, body.o);
    let zeta = dot(rel, body.axis);
    let radial = axpy(rel, -zeta, body.axis);
    let rho = norm(radial);
    (rho, zeta, scale(radial, 1.0 / rho.max(1e-12)))
}

/// Velocity of the material point `p` of a body.
#[inline]
fn body_velocity(body: &BodyKin, p: V3) -> V3 {
    add(body.v, cross(body.omega, sub(p, body.o)))
}

/// Yaw (skew: the axis out of its axial plane) and pitch (tilt in the axial plane against the
/// seated axis) of a roller of `geo`, rad.
fn yaw_and_pitch(geo: &super::geometry::RowGeometry, rk: &RollerKinematics) -> (f64, f64) {
    let u = scale(rk.a, geo.sigma);
    let e_rho = [rk.c[0], rk.c[1], 0.0];
    let e_rho = scale(e_rho, 1.0 / norm(e_rho).max(1e-12));
    let e_t = cross([0.0, 0.0, 1.0], e_rho);
    let seated = add(scale(e_rho, geo.u.0), [0.0, 0.0, geo.u.1]);
    let across = add(scale(e_rho, geo.u.1), [0.0, 0.0, -geo.u.0]);
    let yaw = dot(u, e_t).clamp(-1.0, 1.0).asin();
    let pitch = dot(u, across).atan2(dot(u, seated));
    (yaw, pitch)
}

/// A loaded slice of a roller on the cone or cup, between its normal force and its traction.
#[derive(Debug, Clone, Copy)]
struct LoadedSlice {
    /// 0 cone, 1 cup; the slice's index along the roller
    race: usize,
    slice: usize,
    /// normal force, N; unit normal (ring → roller); contact point
    q: f64,
    n: V3,
    p: V3,
    /// tangential relative velocity (roller − ring) and its magnitude, m/s
    vt: V3,
    vs: f64,
    /// entrainment speed in the orbital frame, m/s
    u_roll: f64,
    /// distance of the slice centre from the ring axis, m; reduced radius across the line, m
    rho: f64,
    reduced_radius: f64,
    /// the slice's contact in the traction batch
    contact: BatchContact,
}

/// Scratch of [`raceways`]: the loaded slices of one roller and their traction batch.
#[derive(Debug, Clone, Default)]
pub(crate) struct SliceScratch {
    batch: SliceBatch,
    loaded: Vec<LoadedSlice>,
    /// the test oracle: each slice's traction by its own [`traction`] call on the slice's state
    /// (the path the batch replaced) instead of the batch's vector loop
    #[cfg(test)]
    pub(super) scalar: bool,
}

/// Friction coefficient of slice `k` of `batch`: the batch's, or with `scalar` (tests) the one
/// call of [`traction`] per slice that the batch replaced.
fn slice_coefficient(batch: &SliceBatch, k: usize, model: &TractionModel, scalar: bool) -> f64 {
    if scalar {
        traction(&batch.state(k), model).coefficient
    } else {
        batch.coefficient(k)
    }
}

/// Λ and Hertz half-width of slice `k` of `batch` for the contact record (`scalar` as in
/// [`slice_coefficient`]).
fn slice_film(
    batch: &SliceBatch,
    k: usize,
    contact: BatchContact,
    model: &TractionModel,
    scalar: bool,
) -> (f64, f64) {
    if scalar {
        let tr = traction(&batch.state(k), model);
        (tr.lambda, tr.half_width_m)
    } else {
        (batch.film(contact).2, batch.state(k).hertz().half_width_m)
    }
}

/// The slices of one roller on the cone (`race = 0`) and the cup (`race = 1`): pass 1 finds the
/// loaded slices (approach, slice law, damping) and their kinematics and adds each to the
/// traction batch as a line contact of its own (its own film: per-slice load, length, R' and
/// entrainment, SPEC §3.3); the batch evaluates every coefficient in one vector loop
/// ([`SliceBatch::evaluate`], the kernel of the cylindrical raceways); pass 2 applies each
/// slice's normal and friction force in slice order (seed 000 (2.9)).
#[allow(clippy::too_many_arguments)]
fn raceways(
    model: &TaperedModel,
    row: usize,
    rk: &RollerKinematics,
    inner: &BodyKin,
    roller: &mut Wrench,
    f_inner: &mut V3,
    scratch: &mut SliceScratch,
    (report, mut record): (&mut RollerReport, Option<&mut RollerContacts>),
) {
    #[cfg(test)]
    let scalar = scratch.scalar;
    #[cfg(not(test))]
    let scalar = false;
    let SliceScratch { batch, loaded, .. } = scratch;
    batch.clear();
    loaded.clear();
    loaded_slices(model, row, rk, inner, batch, loaded);
    batch.evaluate(&model.traction);
    if let Some(r) = record.as_deref_mut() {
        r.cone.clear();
        r.cup.clear();
    }
    let (mut total, mut sliding) = ([0.0; 2], [0.0; 2]);
    for (k, ls) in loaded.iter().enumerate() {
        let LoadedSlice { race, q, vs, .. } = *ls;
        let mu = slice_coefficient(batch, k, &model.traction, scalar).abs();
        if let Some(r) = record.as_deref_mut() {
            let c = if race == 0 { &mut r.cone } else { &mut r.cup };
            let i = ls.slice;
            c.force_n[i] = q;
            c.sliding_m_s[i] = vs;
            (c.lambda[i], c.half_width_m[i]) =
                slice_film(batch, k, ls.contact, &model.traction, scalar);
            c.reduced_radius_m[i] = ls.reduced_radius;
            c.ring_radius_m[i] = ls.rho;
        }
        let mut f = scale(ls.n, q);
        if vs > 0.0 {
            f = axpy(f, -mu * q / vs, ls.vt);
        }
        roller.force = add(roller.force, f);
        roller.moment = add(roller.moment, cross(sub(ls.p, rk.c), f));
        if race == 0 {
            *f_inner = sub(*f_inner, f);
            report.cone_slice_max = report.cone_slice_max.max(q);
        }
        total[race] += q;
        sliding[race] += q * vs;
        report.slip = report.slip.max(vs / ls.u_roll.max(1e-3));
    }
    let mean = |race: usize| {
        if total[race] > 0.0 {
            sliding[race] / total[race]
        } else {
            0.0
        }
    };
    (report.cone, report.cone_sliding) = (total[0], mean(0));
    (report.cup, report.cup_sliding) = (total[1], mean(1));
}

/// Pass 1 of [`raceways`]: every loaded slice of the roller on cone and cup, in slice order,
/// into `loaded`, and as a line contact of its own into `batch` (slice `k` of the batch is
/// `loaded[k]`).
fn loaded_slices(
    model: &TaperedModel,
    row: usize,
    rk: &RollerKinematics,
    inner: &BodyKin,
    batch: &mut SliceBatch,
    loaded: &mut Vec<LoadedSlice>,
) {
    let geo = &model.rows[row];
    let u = scale(rk.a, geo.sigma);
    let s = &model.slices;
    let temps = &model.conditions.temperatures;
    for (race, (body, line)) in [(inner, &geo.cone), (&CUP, &geo.cup)]
        .into_iter()
        .enumerate()
    {
        for i in 0..s.x.len() {
            let centre = axpy(rk.c, s.x[i], u);
            let (rho, zeta, e_rho) = half_plane(body, centre);
            let delta = s.reach[race][i] - line.distance(rho, zeta);
            if delta <= 0.0 {
                continue;
            }
            let n = contact_normal(line, e_rho, body.axis);
            let p = axpy(centre, -s.reach[race][i], n);
            let v_roll = add(rk.v, cross(rk.w, sub(p, rk.c)));
            let v_ring = body_velocity(body, p);
            let v_rel = sub(v_roll, v_ring);
            let elastic = s.k[race][i] * power(delta, s.n[race]);
            let q = s.damping[race][i].normal_force(elastic, delta, -dot(v_rel, n));
            if q <= 0.0 {
                continue;
            }
            let vt = perp(v_rel, n);
            let vs = norm(vt);
            let frame = [0.0, 0.0, rk.orbit];
            let mean = scale(
                add(sub(v_roll, cross(frame, p)), sub(v_ring, cross(frame, p))),
                0.5,
            );
            let u_roll = norm(perp(mean, n));
            let ring_curvature = line_curvature(model, race, rho);
            let reduced_radius = 1.0 / (model.half_angle.cos() / s.radius[i] + ring_curvature);
            let state = ContactState {
                normal_force_n: q,
                geometry: ContactGeometry::Line {
                    length_m: s.length[i],
                },
                reduced_radius_m: reduced_radius,
                reduced_modulus_pa: model.reduced_modulus,
                rolling_speed_m_s: u_roll,
                sliding_speed_m_s: vs,
                temperature_k: if race == 0 {
                    temps.inner_raceway_k
                } else {
                    temps.outer_raceway_k
                },
                roughness_ra_m: model.roughness,
                film_thickness_m: None,
            };
            let contact = batch.add_contact(&model.traction, &state);
            batch.push(contact, q, s.length[i], u_roll, vs);
            loaded.push(LoadedSlice {
                race,
                slice: i,
                q,
                n,
                p,
                vt,
                vs,
                u_roll,
                rho,
                reduced_radius,
                contact,
            });
        }
    }
}

/// The 3-D unit normal of a half-plane line at the azimuth of `e_ρ`.
#[inline]
fn contact_normal(line: &HalfPlaneLine, e_rho: V3, axis: V3) -> V3 {
    add(scale(e_rho, line.n_rho), scale(axis, line.n_zeta))
}

/// Normal curvature of the raceway cone across its generatrix at distance `ρ` from the axis:
/// `cos α/ρ`, convex (+) on the cone, concave (−) on the cup, 1/m.
#[inline]
fn line_curvature(model: &TaperedModel, race: usize, rho: f64) -> f64 {
    if race == 0 {
        model.cone_angle.cos() / rho
    } else {
        -model.cup_angle.cos() / rho
    }
}

/// The roller's ends on the ribs of the cone and on the faces of its pocket.
#[allow(clippy::too_many_arguments)]
fn ends(
    model: &TaperedModel,
    row: usize,
    rk: &RollerKinematics,
    inner: &BodyKin,
    cage: &CageKin,
    roller: &mut Wrench,
    (f_inner, cage_wrench): (&mut V3, &mut Wrench),
    (report, mut record): (&mut RollerReport, Option<&mut RollerContacts>),
) {
    if let Some(r) = record.as_deref_mut() {
        r.large_rib = RibContact::default();
    }
    let geo = &model.rows[row];
    let p = &model.parameters;
    let lub = EndLubrication {
        model: &model.traction,
        reduced_radius: model.rib_reduced_radius,
        film_limit_radius: model.rib_film_limit_radius,
        reduced_modulus: model.reduced_modulus,
        roughness: model.roughness,
        temperature_k: model.conditions.temperatures.inner_raceway_k,
    };
    let rib_damping = SliceDamping::new(p.end_rib.contact.c_h, p.end_rib.contact.d);
    let pocket_damping = SliceDamping::new(p.end_pocket.contact.c_h, p.end_pocket.contact.d);
    let cage_body = cage_body(cage);
    let contacts: [(&BodyKin, &FaceGeometry, &EndGeometry, bool); 4] = [
        (inner, &geo.large_rib, &model.large_end, true),
        (inner, &geo.small_rib, &model.small_end, true),
        (&cage_body, &geo.pocket_large, &model.large_end, false),
        (&cage_body, &geo.pocket_small, &model.small_end, false),
    ];
    for (k, (body, face, end, on_ring)) in contacts.into_iter().enumerate() {
        let reach = AxialReach::new(body, end, rk.c, rk.a);
        if reach.bound(face, end) <= 0.0 {
            continue;
        }
        let (params, damping, lub) = if on_ring {
            (&p.end_rib, &rib_damping, Some(&lub))
        } else {
            (&p.end_pocket, &pocket_damping, None)
        };
        let Some(ef) = end_force(face, end, body, &reach, rk, params, damping, lub) else {
            continue;
        };
        roller.force = add(roller.force, ef.force);
        roller.moment = add(roller.moment, ef.moment);
        if on_ring {
            *f_inner = sub(*f_inner, ef.force);
        } else {
            cage_wrench.force = sub(cage_wrench.force, ef.force);
            cage_wrench.moment = add(cage_wrench.moment, ef.body_moment);
            report.cage += ef.normal;
        }
        match k {
            0 => {
                report.large_rib = ef.normal;
                report.rib_sliding = ef.sliding;
                report.rib_ehl = ef.regime == crate::ends::EndContactRegime::Elastohydrodynamic;
                if let Some(r) = record.as_deref_mut() {
                    r.large_rib = RibContact {
                        force_n: ef.normal,
                        sliding_m_s: ef.sliding,
                        lambda: ef.lambda,
                        spot_radius_m: (model.rib_reduced_radius * ef.delta).sqrt(),
                        elastohydrodynamic: report.rib_ehl,
                        end_radius_m: ef.end_radius,
                        rib_radius_m: ef.body_radius,
                    };
                }
            }
            1 => report.small_rib = ef.normal,
            _ => {}
        }
    }
}

/// The cage as a body carrying faces.
#[inline]
fn cage_body(cage: &CageKin) -> BodyKin {
    BodyKin {
        o: cage.centre,
        v: cage.velocity,
        axis: cage.axis,
        omega: cage.omega,
    }
}

/// Stations along the roller at which the bar edges are tested, as fractions of the half
/// length from the mid-point (both ends of the roller: alternating yaw, SPEC §1.5).
const BAR_STATIONS: [f64; 2] = [-0.8, 0.8];

/// The roller against the four bar edges of its pocket (pocket `j` of its row's cage): edges
/// parallel to the nominal roller axis at `(±w, ±e)` in the pocket's cross-section, `e` the
/// edge height, `w = √((r + c/2)² − e²)` so that a centred roller clears every edge by `c/2`.
#[allow(clippy::too_many_arguments)]
fn bars(
    model: &TaperedModel,
    row: usize,
    j: usize,
    rk: &RollerKinematics,
    cage: &CageKin,
    roller: &mut Wrench,
    cage_wrench: &mut Wrench,
    report: &mut RollerReport,
) {
    let geo = &model.rows[row];
    let p = &model.parameters;
    let pp = &p.roller_cage;
    let psi = std::f64::consts::TAU * j as f64 / model.z as f64;
    let (sp, cp) = psi.sin_cos();
    // cage frame: e_x, e_y rotated by φ; a cage tilt is small, its axis is used as is
    let e_x = [cage.cos_phi, cage.sin_phi, 0.0];
    let e_y = [-cage.sin_phi, cage.cos_phi, 0.0];
    let e_rho = perp(add(scale(e_x, cp), scale(e_y, sp)), cage.axis);
    let e_rho = scale(e_rho, 1.0 / norm(e_rho));
    let e_t = cross(cage.axis, e_rho);
    let u_nom = add(scale(e_rho, geo.u.0), scale(cage.axis, geo.u.1));
    let e_n = add(
        scale(e_rho, geo.u.1 * geo.sigma),
        scale(cage.axis, -geo.u.0 * geo.sigma),
    );
    let mid = add(cage.centre, scale(e_rho, geo.mid.0));
    let u = scale(rk.a, geo.sigma);
    let half = 0.5 * model.bearing.roller.length;
    let damping = SliceDamping::new(pp.c_h, pp.d);
    for &frac in &BAR_STATIONS {
        let x = frac * half;
        let r = model.bearing.roller.radius_at(x);
        let nominal = axpy(mid, x, u_nom);
        let centre = axpy(rk.c, x - model.x_cm, u);
        let d = sub(centre, nominal);
        let (dt, dn) = (dot(d, e_t), dot(d, e_n));
        let e = p.bar_edge_height * r;
        let w = ((r + 0.5 * model.bearing.cage.pocket_clearance).powi(2) - e * e).sqrt();
        for (et, en) in [(w, e), (w, -e), (-w, e), (-w, -e)] {
            let (gt, gn) = (dt - et, dn - en);
            let dist = gt.hypot(gn);
            let delta = r - dist;
            if delta <= 0.0 {
                continue;
            }
            let n = scale(add(scale(e_t, gt), scale(e_n, gn)), 1.0 / dist);
            let edge = add(nominal, add(scale(e_t, et), scale(e_n, en)));
            let v_rel = sub(
                add(rk.v, cross(rk.w, sub(edge, rk.c))),
                add(cage.velocity, cross(cage.omega, sub(edge, cage.centre))),
            );
            let elastic = 0.5 * pp.k_p * power(delta, pp.exponent);
            let q = damping.normal_force(elastic, delta, -dot(v_rel, n));
            if q <= 0.0 {
                continue;
            }
            let vt = perp(v_rel, n);
            let vs = norm(vt);
            let mut f = scale(n, q);
            if vs > 0.0 {
                f = axpy(f, -pp.friction.coefficient(vs) * q / vs, vt);
            }
            roller.force = add(roller.force, f);
            roller.moment = add(roller.moment, cross(sub(edge, rk.c), f));
            cage_wrench.force = sub(cage_wrench.force, f);
            cage_wrench.moment = sub(cage_wrench.moment, cross(sub(edge, cage.centre), f));
            report.cage += q;
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::conditions::{ContactTemperatures, InnerRingSupport, OperatingConditions};
    use crate::integrator::Dopri5;
    use crate::settings::IntegratorSettings;
    use crate::tapered::{TaperedParameters, initial_state};
    use rolldyn_geometry::BearingModel;
    use std::path::Path;

    /// The cassette of `examples/tapered-cassette.toml` (load case 1: 663 rpm, 118 862 N, oil
    /// at 60 °C), its inner ring free, as `rolldyn simulate` sets it up.
    pub(crate) fn cassette() -> TaperedModel {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/tapered-cassette.toml");
        let file = rolldyn_model::load(&path).unwrap();
        let BearingModel::Tapered(bearing) = &file.bearing else {
            panic!("not a tapered bearing");
        };
        let traction = file.lubrication.as_ref().unwrap().traction_model().unwrap();
        let mut c = OperatingConditions::new(663.0 * std::f64::consts::TAU / 60.0, 118_862.0);
        c.temperatures = ContactTemperatures::uniform(333.15);
        c.support = InnerRingSupport {
            radial_free: true,
            axial_free: true,
            mass_kg: None,
        };
        TaperedModel::new(
            bearing,
            c,
            TaperedParameters::for_bearing(bearing),
            traction,
        )
        .unwrap()
    }

    /// The rates, the per-roller report and the contact record of one reported evaluation at
    /// `(t, y)`, with the slices evaluated by the batch or by the scalar oracle.
    fn evaluated(
        model: &TaperedModel,
        t: f64,
        y: &[f64],
        scalar: bool,
    ) -> (Vec<f64>, Vec<RollerReport>, Vec<RollerContacts>) {
        let mut sys = TaperedSystem::new(model);
        sys.record_contacts();
        sys.slices.scalar = scalar;
        let mut dy = vec![0.0; y.len()];
        sys.rhs_reported(t, y, &mut dy);
        (dy, sys.rollers, sys.contacts.unwrap())
    }

    fn assert_close(what: &str, batched: f64, scalar: f64, rel: f64) {
        assert!(
            batched.to_bits() == scalar.to_bits() || (batched - scalar).abs() <= rel * scalar.abs(),
            "{what}: batched {batched:e} vs scalar {scalar:e}"
        );
    }

    /// Issue 40 item 3: the batched slice traction gives the rates of the scalar path (one
    /// `traction` call per slice) bit for bit — the same arithmetic — at the seated start and
    /// at the states of the first Dormand–Prince steps (slices entering contact, the rollers
    /// spinning up); the contact record agrees bit for bit except the Hertz half-width, which
    /// the record now takes from the slice's state (to 1e-15).
    #[test]
    fn batched_slices_match_the_scalar_oracle() {
        let model = cassette();
        let y0 = initial_state(&model, 0.0);
        let n = y0.len();
        let mut dp = Dopri5::new(0.0, y0, vec![1e-3; n], vec![1.0; n], 1e-8);
        let mut sys = TaperedSystem::new(&model);
        let set = IntegratorSettings {
            tolerance: 1e-5,
            ..IntegratorSettings::default()
        };
        let mut loaded = 0;
        for step in 0..6 {
            let (t, y) = (dp.t, dp.y.clone());
            let (dy_b, rep_b, rec_b) = evaluated(&model, t, &y, false);
            let (dy_s, rep_s, rec_s) = evaluated(&model, t, &y, true);
            for (i, (b, s)) in dy_b.iter().zip(&dy_s).enumerate() {
                assert_eq!(
                    b.to_bits(),
                    s.to_bits(),
                    "step {step}, rate {i}: {b:e} vs {s:e}"
                );
            }
            for (j, (b, s)) in rep_b.iter().zip(&rep_s).enumerate() {
                let pairs = [
                    (b.cone, s.cone),
                    (b.cup, s.cup),
                    (b.cone_slice_max, s.cone_slice_max),
                    (b.cone_sliding, s.cone_sliding),
                    (b.cup_sliding, s.cup_sliding),
                    (b.slip, s.slip),
                ];
                for (k, (b, s)) in pairs.into_iter().enumerate() {
                    assert_eq!(
                        b.to_bits(),
                        s.to_bits(),
                        "step {step}, roller {j}, report {k}"
                    );
                }
            }
            for (j, (b, s)) in rec_b.iter().zip(&rec_s).enumerate() {
                for (bc, sc) in [(&b.cone, &s.cone), (&b.cup, &s.cup)] {
                    loaded += bc.force_n.iter().filter(|&&q| q > 0.0).count();
                    assert_eq!(bc.force_n, sc.force_n, "step {step}, roller {j}");
                    assert_eq!(bc.sliding_m_s, sc.sliding_m_s, "step {step}, roller {j}");
                    assert_eq!(bc.reduced_radius_m, sc.reduced_radius_m);
                    assert_eq!(bc.ring_radius_m, sc.ring_radius_m);
                    for i in 0..bc.lambda.len() {
                        assert_eq!(bc.lambda[i].to_bits(), sc.lambda[i].to_bits());
                        assert_close("half-width", bc.half_width_m[i], sc.half_width_m[i], 1e-15);
                    }
                }
            }
            for _ in 0..4 {
                dp.step(&mut sys, &set).unwrap();
            }
        }
        assert!(loaded > 1000, "{loaded} loaded slices compared");
    }
}
