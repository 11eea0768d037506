//! The right-hand side `ẏ = f(t, y)`: contact detection and forces for every roller slice on
//! both raceways (SPEC §2.1–2.2, §3.3), roller ↔ cage bars, cage ↔ land, cage drag (§3.6),
//! loads and gravity, and the Newton–Euler equations (seed 000 eqs. (2.1), (2.2)).
//!
//! Allocation-free: all scratch lives in [`Diagnostics`], allocated once.

use crate::ends::{BodyKin, EndContactRegime, EndForce, EndLubrication, ReachColumns, end_force};
use crate::kinematics::RollerKinematics;
use crate::land::LandKinematics;
use crate::layout::{CAGE_DOF, INNER_DOF, ROLLER_DOF};
use crate::model::{Model, RacewaySlices};
use crate::slice_kernel::{self, LANES, LoadedRun, RingKinematics, RollerLanes, SliceOutputs};
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, power, scale, sub, unit_or};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_lubrication::{BatchContact, ContactGeometry, ContactState, SliceBatch};
use rolldyn_numerics::fastmath;

/// Per-roller contact quantities of one raceway (struct of arrays). Speeds, film, Λ and μ are
/// load-weighted means over the loaded slices; force and power are sums.
#[derive(Debug, Clone, Default)]
pub(crate) struct ContactTable {
    pub force: Vec<f64>,
    pub sliding: Vec<f64>,
    pub rolling: Vec<f64>,
    pub film: Vec<f64>,
    pub lambda: Vec<f64>,
    pub mu: Vec<f64>,
    pub power: Vec<f64>,
    /// contact state of the most loaded slice (scuffing check)
    pub worst: Vec<Option<ContactState>>,
    worst_q: Vec<f64>,
}

impl ContactTable {
    fn new(z: usize) -> Self {
        Self {
            force: vec![0.0; z],
            sliding: vec![0.0; z],
            rolling: vec![0.0; z],
            film: vec![0.0; z],
            lambda: vec![0.0; z],
            mu: vec![0.0; z],
            power: vec![0.0; z],
            worst: vec![None; z],
            worst_q: vec![0.0; z],
        }
    }
    /// Zeroes roller `j`'s normal force and, with [`Tables::Fill`], the rest of its row.
    #[inline]
    fn reset(&mut self, j: usize, tables: Tables) {
        self.force[j] = 0.0;
        if tables == Tables::Skip {
            return;
        }
        self.sliding[j] = 0.0;
        self.rolling[j] = 0.0;
        self.film[j] = 0.0;
        self.lambda[j] = 0.0;
        self.mu[j] = 0.0;
        self.power[j] = 0.0;
        self.worst[j] = None;
        self.worst_q[j] = 0.0;
    }
    #[inline]
    fn finish(&mut self, j: usize) {
        let q = self.force[j];
        if q > 0.0 {
            let w = 1.0 / q;
            self.sliding[j] *= w;
            self.rolling[j] *= w;
            self.film[j] *= w;
            self.lambda[j] *= w;
            self.mu[j] *= w;
        } else {
            self.film[j] = f64::NAN;
            self.lambda[j] = f64::NAN;
        }
    }
}

/// Whether an evaluation fills the per-roller contact tables of [`Diagnostics`] (sliding and
/// rolling speeds, film, Λ, μ, friction power, worst slice). The forces, the divergence check
/// and the per-roller normal forces are always computed; the tables are needed only at states
/// that are reported (accepted steps, output samples), not at the integrator's inner stages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Tables {
    Fill,
    Skip,
}

/// Which body pierced what (divergence diagnosis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Violation {
    pub what: &'static str,
    pub index: usize,
    pub penetration: f64,
}

/// Scratch and per-evaluation results of the right-hand side.
#[derive(Debug, Clone)]
pub(crate) struct Diagnostics {
    pub inner: ContactTable,
    pub outer: ContactTable,
    /// roller–cage bar normal force per roller (sum of the evaluation points), N
    pub bar: Vec<f64>,
    pub bar_power: Vec<f64>,
    /// roller end ↔ rib normal force per roller (sum of both ends and all ribs), N
    pub rib: Vec<f64>,
    /// force-weighted sliding speed of the rib contacts per roller, m/s
    pub rib_sliding: Vec<f64>,
    /// force-weighted distance of the rib contact point from the rib edge (rim), m (NaN: none)
    pub rib_edge: Vec<f64>,
    /// force-weighted friction coefficient of the rib contacts per roller
    pub rib_mu: Vec<f64>,
    /// friction power of the rib contacts per roller, W
    pub rib_power: Vec<f64>,
    /// regime of the most loaded rib contact per roller
    pub rib_regime: Vec<EndContactRegime>,
    /// roller end ↔ cage pocket face normal force per roller, N
    pub pocket: Vec<f64>,
    /// friction power of the pocket-face contacts per roller, W
    pub pocket_power: Vec<f64>,
    /// cage–land normal force (sum of stations), N
    pub land_force: f64,
    pub land_power: f64,
    /// prescribed ring speeds at the evaluation time
    pub inner_speed: f64,
    pub outer_speed: f64,
    pub violation: Option<Violation>,
    /// scratch: loaded raceway slices of every roller, their traction batches and the roller
    /// forces and moments before traction
    slices: RacewayScratch,
}

/// Scratch of the raceway contacts of one evaluation: per raceway the slot loop's inputs and
/// results and the loaded contacts whose traction is evaluated in one batch, and the roller
/// forces and moments collected before the traction is applied.
#[derive(Debug, Clone)]
struct RacewayScratch {
    inner: RacewayPass,
    outer: RacewayPass,
    /// the kinematics of every roller that may touch a raceway, repeated over its slots
    rollers: RollerLanes,
    force: Vec<V3>,
    moment: Vec<V3>,
    /// per roller: sin θ, cos θ, axis and angular velocity (pass 1, reused by Newton–Euler)
    frame: Vec<(f64, f64, V3, V3)>,
    /// per roller: azimuth θ, sin θ, cos θ (one vectorised `sin_cos` for all rollers)
    theta: [Vec<f64>; 3],
    /// per roller: centre and unit axis (struct of arrays, for the vector loops of pass 1a)
    centre: [Vec<f64>; 3],
    axis: [Vec<f64>; 3],
    /// per pocket: radial and tangential unit vectors in the cage plane (struct of arrays:
    /// e_x, e_y, e_z, t_x, t_y, t_z)
    pockets: [Vec<f64>; 6],
    /// per roller: squared distance of its bar points (pocket sides −, + × roller ends −, +)
    /// from the bar edges, measured in the cage plane
    bar_dist_sq: [Vec<f64>; 4],
    /// per roller: the axial reach of its ends towards the faces of the inner ring, the outer
    /// ring and the cage
    reach: [ReachColumns; 3],
}

/// The contacts of one raceway in one evaluation (pass 1 of [`rhs`]): which rollers may touch
/// it, the raceway drop under their slots, the slot loop's results, and the loaded contacts of
/// the traction batch.
#[derive(Debug, Clone)]
struct RacewayPass {
    /// per roller: the pair bound allows a contact (the roller's lanes are then set)
    may_touch: Vec<bool>,
    /// raceway drop under each slot (profiled raceways), m
    race_drop: Vec<f64>,
    out: SliceOutputs,
    loaded: LoadedContacts,
}

impl RacewayPass {
    fn new(z: usize, slices: usize) -> Self {
        let slots = z * slices + LANES;
        Self {
            may_touch: vec![false; z],
            race_drop: vec![0.0; slots],
            out: SliceOutputs::new(slots),
            loaded: LoadedContacts::new(z, slots),
        }
    }
}

/// The loaded roller–raceway contacts of one raceway: one block of batch slices (the loaded
/// slices of the roller) per contact in the traction batch, and the runs of consecutive loaded
/// slots they came from, whose contact points and sliding directions stay in
/// [`SliceOutputs`].
#[derive(Debug, Clone)]
struct LoadedContacts {
    batch: SliceBatch,
    blocks: Vec<LoadedBlock>,
    /// the batch contact of each block
    contacts: Vec<BatchContact>,
    /// every run of consecutive loaded slots, in batch order
    runs: Vec<LoadedRun>,
}

/// The loaded slices of one roller on one raceway: one contact of the traction batch.
#[derive(Debug, Clone)]
struct LoadedBlock {
    roller: usize,
    /// its slices in the batch
    slices: std::ops::Range<usize>,
    /// its runs of consecutive loaded slots in [`LoadedContacts::runs`]
    runs: std::ops::Range<usize>,
    /// total normal force, N; loaded length, m; Σ Q u, N·m/s
    load: f64,
    length: f64,
    entrainment: f64,
}

impl LoadedContacts {
    fn new(rollers: usize, slots: usize) -> Self {
        let mut batch = SliceBatch::with_capacity(slots);
        batch.columns_mut(slots);
        Self {
            batch,
            blocks: Vec::with_capacity(rollers),
            contacts: Vec::with_capacity(rollers),
            runs: Vec::with_capacity(slots),
        }
    }

    fn clear(&mut self) {
        self.batch.clear();
        self.blocks.clear();
        self.contacts.clear();
        self.runs.clear();
    }
}

impl RacewayScratch {
    fn new(z: usize, slices: usize) -> Self {
        Self {
            inner: RacewayPass::new(z, slices),
            outer: RacewayPass::new(z, slices),
            rollers: RollerLanes::new(z * slices + LANES),
            force: vec![[0.0; 3]; z],
            moment: vec![[0.0; 3]; z],
            frame: vec![(0.0, 1.0, [0.0, 0.0, 1.0], [0.0; 3]); z],
            theta: [vec![0.0; z], vec![0.0; z], vec![1.0; z]],
            centre: [vec![0.0; z], vec![0.0; z], vec![0.0; z]],
            axis: [vec![0.0; z], vec![0.0; z], vec![1.0; z]],
            pockets: std::array::from_fn(|_| vec![0.0; z]),
            bar_dist_sq: std::array::from_fn(|_| vec![0.0; z]),
            reach: std::array::from_fn(|_| ReachColumns::new(z)),
        }
    }

    fn clear(&mut self) {
        self.inner.loaded.clear();
        self.outer.loaded.clear();
    }
}

impl Diagnostics {
    pub fn new(z: usize, slices: usize) -> Self {
        Self {
            inner: ContactTable::new(z),
            outer: ContactTable::new(z),
            bar: vec![0.0; z],
            bar_power: vec![0.0; z],
            rib: vec![0.0; z],
            rib_sliding: vec![0.0; z],
            rib_edge: vec![f64::NAN; z],
            rib_mu: vec![0.0; z],
            rib_power: vec![0.0; z],
            rib_regime: vec![EndContactRegime::None; z],
            pocket: vec![0.0; z],
            pocket_power: vec![0.0; z],
            land_force: 0.0,
            land_power: 0.0,
            inner_speed: 0.0,
            outer_speed: 0.0,
            violation: None,
            slices: RacewayScratch::new(z, slices),
        }
    }
}

/// Angular velocity of an axisymmetric body from its angular momentum `L` and unit axis `a`:
/// `ω = L/I_t + (1/I_a − 1/I_t)(a·L) a` (inverse of `L = I ω` with `I = I_t(E − aaᵀ) + I_a aaᵀ`).
#[inline]
pub fn axisymmetric_omega(l: V3, a: V3, ia: f64, it: f64) -> V3 {
    axpy(scale(l, 1.0 / it), (1.0 / ia - 1.0 / it) * dot(a, l), a)
}

#[inline]
fn rd(y: &[f64], i: usize) -> V3 {
    [y[i], y[i + 1], y[i + 2]]
}

#[inline]
fn wr(dy: &mut [f64], i: usize, v: V3) {
    dy[i] = v[0];
    dy[i + 1] = v[1];
    dy[i + 2] = v[2];
}

/// Kinematics of a ring (centre, velocity, axis, spin) and its raceway radius at this time.
struct RingKin {
    o: V3,
    v: V3,
    axis: V3,
    spin: f64,
    raceway_radius: f64,
}

/// Offset of the bar point `q` of a roller from the edge line of its pocket's bar on `side`
/// (±1), perpendicular to the cage axis `ac`: the edge runs along the cage axis at the bar
/// contact radius from the cage centre `cc`, in the pocket frame `(e_p, t_p)`.
#[inline]
fn bar_offset(model: &Model, cc: V3, ac: V3, (ep, tp): (V3, V3), side: f64, q: V3) -> V3 {
    let edge = axpy(axpy(cc, model.r_bar, ep), side * model.half_pocket, tp);
    perp(sub(q, edge), ac)
}

#[inline]
fn note(diag: &mut Diagnostics, what: &'static str, index: usize, penetration: f64, limit: f64) {
    if penetration > limit && diag.violation.is_none() {
        diag.violation = Some(Violation {
            what,
            index,
            penetration,
        });
    }
}

/// Pass 1a on one raceway (SPEC §2.1–2.2), for all rollers in one vector loop: whether any
/// slice of roller `j` can touch (`pass.may_touch[j]`), from the centres and unit axes in
/// `centre` and `axis`.
///
/// Slice centres p = c + x a: their offset from the ring axis is dp(x) = dp_c + x a⊥, so
/// ρ(x)² = A + 2Bx + Cx², a convex parabola in x. A slice can touch the inner raceway only if
/// ρ < T_i = R_i + R_w − min drops somewhere on the roller (|x| ≤ X), and the outer one only if
/// ρ > T_o = R_o − R_w + min drops: the minimum (at x = −B/C, clamped) and the maximum (at an
/// end) of ρ² decide, without a square root. Exact for the extent of the slice centres, so a
/// skewed roller (large C, B ≈ 0) is not taken for a touching one.
fn raceway_pairs<const INNER: bool>(
    model: &Model,
    rs: &RacewaySlices,
    ring: &RingKin,
    centre: &[Vec<f64>; 3],
    axis: &[Vec<f64>; 3],
    pass: &mut RacewayPass,
) {
    let z = model.z;
    let drops = model.min_slice_drop + rs.min_drop;
    let reach = model.slice_reach;
    let [cx, cy, cz] = centre.each_ref().map(|c| &c[..z]);
    let [ax, ay, az] = axis.each_ref().map(|c| &c[..z]);
    let may_touch = &mut pass.may_touch[..z];
    for j in 0..z {
        let d_c = sub([cx[j], cy[j], cz[j]], ring.o);
        let dp_c = axpy(d_c, -dot(d_c, ring.axis), ring.axis);
        let a = [ax[j], ay[j], az[j]];
        let a_perp = axpy(a, -dot(a, ring.axis), ring.axis);
        let (qa, qb, qc) = (dot(dp_c, dp_c), dot(dp_c, a_perp), dot(a_perp, a_perp));
        may_touch[j] = if INNER {
            let t = ring.raceway_radius + model.rw - drops;
            let x = if qc > 0.0 {
                (-qb / qc).clamp(-reach, reach)
            } else {
                -reach.copysign(qb)
            };
            qa + x * (2.0 * qb + x * qc) < t * t
        } else {
            let t = ring.raceway_radius - model.rw + drops;
            t <= 0.0 || qa + reach * (2.0 * qb.abs() + reach * qc) > t * t
        };
    }
}

/// The raceway drop under the slots of roller `j` (profiled raceways only) for the slot loop
/// ([`raceway_kernel`]).
fn raceway_drop(
    rs: &RacewaySlices,
    j: usize,
    rk: &RollerKinematics,
    ring: &RingKin,
    pass: &mut RacewayPass,
) {
    if let Some(pr) = &rs.profile {
        let zeta_c = dot(sub(rk.c, ring.o), ring.axis);
        let a_ax = dot(rk.a, ring.axis);
        let slots = rs.lanes.slots(j);
        let race_drop = &mut pass.race_drop[slots.clone()];
        for (d, &x) in race_drop.iter_mut().zip(&rs.lanes.x[slots]) {
            *d = pr.drop(zeta_c + x * a_ax);
        }
    }
}

/// Pass 1b on one raceway: the slot loop ([`slice_kernel::evaluate`]: approach, slice law,
/// damping, normal force and contact kinematics) over every run of consecutive rollers that may
/// touch it, the slices of a run back to back.
fn raceway_kernel<const INNER: bool>(
    model: &Model,
    rs: &RacewaySlices,
    ring: &RingKin,
    rollers: &RollerLanes,
    pass: &mut RacewayPass,
) {
    let kinematics = RingKinematics {
        ring_o: ring.o,
        ring_v: ring.v,
        ring_axis: ring.axis,
        ring_spin: ring.spin,
        raceway_radius: ring.raceway_radius,
        rw: model.rw,
        exponent: rs.n,
    };
    let mut j = 0;
    while j < model.z {
        if !pass.may_touch[j] {
            j += 1;
            continue;
        }
        let first = j;
        while j < model.z && pass.may_touch[j] {
            j += 1;
        }
        let slots = rs.lanes.slots(first).start..rs.lanes.slots(j - 1).end;
        slice_kernel::evaluate::<INNER>(
            &rs.lanes,
            rollers,
            &pass.race_drop,
            &kinematics,
            slots,
            &mut pass.out,
        );
    }
}

/// Pass 1c on one raceway: records the loaded slices of every roller for the traction pass
/// ([`apply_traction`], which applies their normal and friction forces), one batch contact per
/// loaded roller, and each roller's total normal force in `table`.
///
/// The EHL film is prepared once for the whole roller–raceway contact (its total load over the
/// loaded length and the load-weighted entrainment speed — the film of a line contact is set
/// in the common inlet and depends on the load only weakly, seed 000 (2.17)); the traction per
/// slice with its own pressure, half-width and sliding velocity (SPEC §3.3) follows in
/// [`apply_traction`], for all rollers in one batch.
#[allow(clippy::too_many_arguments)]
#[inline]
fn raceway_collect<const INNER: bool>(
    model: &Model,
    rs: &RacewaySlices,
    table: &mut ContactTable,
    pass: &mut RacewayPass,
    limit: f64,
    violation: &mut Option<Violation>,
    tables: Tables,
) {
    let loaded = &mut pass.loaded;
    // every roller's loaded slots into the batch's slice columns, one block per roller
    let mut columns = loaded.batch.columns_mut(0);
    let mut to = 0;
    for j in 0..model.z {
        table.reset(j, tables);
        if !pass.may_touch[j] {
            continue;
        }
        let first_run = loaded.runs.len();
        let sums = pass.out.collect_loaded(
            rs.lanes.slots(j),
            &rs.lanes.len,
            limit,
            to,
            &mut columns,
            &mut loaded.runs,
        );
        if let (Some(penetration), None) = (sums.violation, &violation) {
            *violation = Some(Violation {
                what: if INNER {
                    "roller ↔ inner raceway"
                } else {
                    "roller ↔ outer raceway"
                },
                index: j,
                penetration,
            });
        }
        if sums.slots.is_empty() {
            continue;
        }
        to = sums.slots.end;
        table.force[j] = sums.load;
        loaded.blocks.push(LoadedBlock {
            roller: j,
            slices: sums.slots,
            runs: first_run..loaded.runs.len(),
            load: sums.load,
            length: sums.length,
            entrainment: sums.entrainment,
        });
    }
    // then the contacts, in the order of their slices
    let tmodel = if INNER {
        &model.traction.inner
    } else {
        &model.traction.outer
    };
    for block in &loaded.blocks {
        let whole = ContactState {
            normal_force_n: block.load,
            geometry: ContactGeometry::Line {
                length_m: block.length,
            },
            reduced_radius_m: rs.reduced_radius,
            reduced_modulus_pa: rs.reduced_modulus,
            rolling_speed_m_s: block.entrainment / block.load,
            sliding_speed_m_s: 0.0,
            temperature_k: rs.temperature_k,
            roughness_ra_m: rs.roughness,
            film_thickness_m: None,
        };
        let contact = loaded.batch.add_contact(tmodel, &whole);
        loaded.batch.claim(contact, block.slices.len());
        loaded.contacts.push(contact);
    }
}

/// The `n` entries of `column` from `first` on (a slice of length `n`, so that a loop over
/// `0..n` indexing several such slices has no bounds checks).
#[inline]
fn cut(column: &[f64], first: usize, n: usize) -> &[f64] {
    &column[first..first + n]
}

/// Pass 2 of the raceway contacts: evaluates the traction of every loaded slice (one batch per
/// raceway, [`SliceBatch::evaluate`]) and adds the normal and friction force of each loaded
/// slice and their moment to its roller, their reaction to the inner ring (`f_inner`) and, with
/// [`Tables::Fill`], fills the per-roller contact tables.
fn apply_traction(model: &Model, diag: &mut Diagnostics, f_inner: &mut V3, tables: Tables) {
    let sc = &mut diag.slices;
    for (RacewayPass { loaded, out, .. }, table, tmodel, inner) in [
        (&mut sc.inner, &mut diag.inner, &model.traction.inner, true),
        (&mut sc.outer, &mut diag.outer, &model.traction.outer, false),
    ] {
        let batch = &mut loaded.batch;
        batch.evaluate(tmodel);
        let (q_all, mu_all) = batch.forces_and_coefficients();
        for block in &loaded.blocks {
            let j = block.roller;
            // the block's normal and friction forces and their moment are summed in registers,
            // then applied once
            let (mut force, mut moment) = ([0.0; 3], [0.0; 3]);
            for run in &loaded.runs[block.runs.clone()] {
                // the run's columns, cut to one length (no bounds checks in the loop)
                let n = run.batch.len();
                let (q, mu) = (
                    cut(q_all, run.batch.start, n),
                    cut(mu_all, run.batch.start, n),
                );
                let [nx, ny, nz] = out.force.each_ref().map(|c| cut(c, run.slot, n));
                let [dx, dy, dz] = out.slide_dir.each_ref().map(|c| cut(c, run.slot, n));
                let [rx, ry, rz] = out.r_cp.each_ref().map(|c| cut(c, run.slot, n));
                for i in 0..n {
                    let slice = axpy([nx[i], ny[i], nz[i]], -mu[i] * q[i], [dx[i], dy[i], dz[i]]);
                    force = add(force, slice);
                    moment = add(moment, cross([rx[i], ry[i], rz[i]], slice));
                }
            }
            sc.force[j] = add(sc.force[j], force);
            sc.moment[j] = add(sc.moment[j], moment);
            if inner {
                *f_inner = sub(*f_inner, force);
            }
        }
        if tables == Tables::Skip {
            continue;
        }
        for (block, &contact) in loaded.blocks.iter().zip(&loaded.contacts) {
            let j = block.roller;
            let (_, film_minimum, lambda) = batch.film(contact);
            for i in block.slices.clone() {
                let q = batch.normal_force(i);
                let mu = batch.coefficient(i);
                let vs = batch.sliding_speed(i);
                table.sliding[j] += q * vs;
                table.rolling[j] += q * batch.rolling_speed(i).abs();
                table.film[j] += q * film_minimum;
                table.lambda[j] += q * lambda.min(1e3);
                table.mu[j] += q * mu;
                table.power[j] += mu.abs() * q * vs;
                if q > table.worst_q[j] {
                    table.worst_q[j] = q;
                    table.worst[j] = Some(batch.state(i));
                }
            }
        }
    }
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
    let lay = model.layout;
    let cond = &model.conditions;
    let g = cond.gravity_m_s2;
    let wi = cond.inner_speed.speed(t);
    let wo = cond.outer_speed.speed(t);
    diag.inner_speed = wi;
    diag.outer_speed = wo;
    diag.violation = None;
    let div_limit = model.div_limit;

    // inner ring
    let ii = lay.inner();
    let inner = RingKin {
        o: rd(y, ii),
        v: rd(y, ii + 3),
        axis: model.axis_i,
        spin: wi,
        raceway_radius: model.ri,
    };
    let outer = RingKin {
        o: [0.0; 3],
        v: [0.0; 3],
        axis: [0.0, 0.0, 1.0],
        spin: wo,
        // SPEC §3.7: a scheduled operating clearance moves the outer raceway by half its change
        raceway_radius: model.ro
            + cond
                .clearance_at(t)
                .map_or(0.0, |g| 0.5 * (g - model.clearance)),
    };
    let mut f_inner = [0.0; 3];

    // cage
    let ci = lay.cage();
    let cc = rd(y, ci);
    let phi_c = y[ci + 3];
    let ac = unit_or(rd(y, ci + 4), [0.0, 0.0, 1.0]);
    let vcc = rd(y, ci + 7);
    let lc = rd(y, ci + 10);
    let wc = axisymmetric_omega(lc, ac, model.ia_c, model.it_c);
    let mut f_cage = scale(g, model.m_c);
    let mut m_cage = scale(ac, -cond.cage_drag_n_m_s * dot(wc, ac));

    let bar = &model.params.roller_cage;
    let bar_share = 0.5; // K_p and C_h split over the two evaluation points along the roller
    let bar_damping = SliceDamping::new(bar_share * bar.c_h, bar.d);
    let (sin_phi, cos_phi) = phi_c.sin_cos();
    diag.slices.clear();
    let [theta, sin_theta, cos_theta] = &mut diag.slices.theta;
    for (j, th) in theta.iter_mut().enumerate() {
        *th = y[lay.roller(j)];
    }
    fastmath::sin_cos_many(theta, sin_theta, cos_theta);
    // every roller's centre and unit axis (vector loops), then pass 1a on both raceways
    {
        let sc = &mut diag.slices;
        let [cx, cy, cz] = &mut sc.centre;
        let [ax, ay, az] = &mut sc.axis;
        for j in 0..model.z {
            let b = lay.roller(j);
            let r = y[b + 1];
            cx[j] = r * sc.theta[2][j];
            cy[j] = r * sc.theta[1][j];
            cz[j] = y[b + 2];
            ax[j] = y[b + 3];
            ay[j] = y[b + 4];
            az[j] = y[b + 5];
        }
        // unit axes as `unit_or(a, e_z)`, with the same expressions
        let (ax, ay, az) = (&mut ax[..model.z], &mut ay[..model.z], &mut az[..model.z]);
        for j in 0..model.z {
            let n = (ax[j] * ax[j] + ay[j] * ay[j] + az[j] * az[j]).sqrt();
            let inv = 1.0 / n;
            let some = n > 0.0;
            ax[j] = if some { ax[j] * inv } else { 0.0 };
            ay[j] = if some { ay[j] * inv } else { 0.0 };
            az[j] = if some { az[j] * inv } else { 1.0 };
        }
        raceway_pairs::<true>(
            model,
            &model.inner,
            &inner,
            &sc.centre,
            &sc.axis,
            &mut sc.inner,
        );
        raceway_pairs::<false>(
            model,
            &model.outer,
            &outer,
            &sc.centre,
            &sc.axis,
            &mut sc.outer,
        );
    }

    // pocket frames: radial unit vector of pocket j in the cage plane (centre angle
    // φ_c + 2πj/Z by the angle-sum formulas) and the tangential one, all pockets in one loop
    let [ex, ey, ez, tx, ty, tz] = diag.slices.pockets.each_mut().map(|c| &mut c[..model.z]);
    let pitch = &model.pocket_sin_cos[..model.z];
    for j in 0..model.z {
        let (sin_pitch, cos_pitch) = pitch[j];
        let sp = sin_phi * cos_pitch + cos_phi * sin_pitch;
        let cpp = cos_phi * cos_pitch - sin_phi * sin_pitch;
        let ep = unit_or(perp([cpp, sp, 0.0], ac), [cpp, sp, 0.0]);
        let tp = cross(ac, ep);
        [ex[j], ey[j], ez[j]] = ep;
        [tx[j], ty[j], tz[j]] = tp;
    }
    // roller ↔ cage bars, first for all rollers at once: the squared distance of each bar
    // point from its bar edge (the expressions of the contact loop below)
    {
        let sc = &mut diag.slices;
        let [cx, cy, cz] = sc.centre.each_ref().map(|c| &c[..model.z]);
        let [ax, ay, az] = sc.axis.each_ref().map(|c| &c[..model.z]);
        let [ex, ey, ez, tx, ty, tz] = sc.pockets.each_ref().map(|c| &c[..model.z]);
        let [d0, d1, d2, d3] = sc.bar_dist_sq.each_mut().map(|c| &mut c[..model.z]);
        for j in 0..model.z {
            let (ep, tp) = ([ex[j], ey[j], ez[j]], [tx[j], ty[j], tz[j]]);
            let (centre, a) = ([cx[j], cy[j], cz[j]], [ax[j], ay[j], az[j]]);
            let dist_sq = |side: f64, x: f64| {
                let d = bar_offset(model, cc, ac, (ep, tp), side, axpy(centre, x, a));
                dot(d, d)
            };
            let [x0, x1] = model.bar_x;
            d0[j] = dist_sq(-1.0, x0);
            d1[j] = dist_sq(-1.0, x1);
            d2[j] = dist_sq(1.0, x0);
            d3[j] = dist_sq(1.0, x1);
        }
    }

    // the bodies that carry end faces, the same for every roller: the rings with their ribs
    // (and the lubrication of their rib contacts) and the cage
    let ends = &model.ends;
    let rib_rings = [
        (&inner, &ends.inner_ribs, true),
        (&outer, &ends.outer_ribs, false),
    ]
    .map(|(ring, faces, inner_ring)| {
        let body = BodyKin {
            o: ring.o,
            v: ring.v,
            axis: ring.axis,
            omega: scale(ring.axis, ring.spin),
        };
        let (model, temperature_k) = if inner_ring {
            (&model.traction.inner, cond.temperatures.inner_raceway_k)
        } else {
            (&model.traction.outer, cond.temperatures.outer_raceway_k)
        };
        let lub = EndLubrication {
            model,
            reduced_radius: ends.rib_reduced_radius,
            reduced_modulus: ends.rib_reduced_modulus,
            roughness: ends.rib_roughness,
            temperature_k,
        };
        (body, lub, faces, inner_ring)
    });
    let cage_body = BodyKin {
        o: cc,
        v: vcc,
        axis: ac,
        omega: wc,
    };
    {
        let sc = &mut diag.slices;
        let [inner_reach, outer_reach, cage_reach] = &mut sc.reach;
        let (centre, axis) = (&sc.centre, &sc.axis);
        if model.params.roller_end_rib.enabled {
            for ((body, _, faces, _), reach) in rib_rings.iter().zip([inner_reach, outer_reach]) {
                if !faces.is_empty() {
                    reach.compute(body, &ends.end, centre, axis);
                }
            }
        }
        if model.params.roller_end_cage.enabled {
            cage_reach.compute(&cage_body, &ends.end, centre, axis);
        }
    }

    for j in 0..model.z {
        let b = lay.roller(j);
        let (r, zz) = (y[b + 1], y[b + 2]);
        let a = [
            diag.slices.axis[0][j],
            diag.slices.axis[1][j],
            diag.slices.axis[2][j],
        ];
        let (thd, rdot, zd) = (y[b + 6], y[b + 7], y[b + 8]);
        let w = axisymmetric_omega(rd(y, b + 9), a, model.ia_r, model.it_r);
        let (s, c) = (diag.slices.theta[1][j], diag.slices.theta[2][j]);
        diag.slices.frame[j] = (s, c, a, w);
        let centre = [r * c, r * s, zz];
        let v = [rdot * c - r * thd * s, rdot * s + r * thd * c, zd];
        let rk = RollerKinematics {
            c: centre,
            a,
            v,
            w,
            orbit: thd,
        };
        let mut f = scale(g, model.m_r);
        let mut m = [0.0; 3];
        let sc = &mut diag.slices;
        let (touch_inner, touch_outer) = (sc.inner.may_touch[j], sc.outer.may_touch[j]);
        if touch_inner {
            raceway_drop(&model.inner, j, &rk, &inner, &mut sc.inner);
        }
        if touch_outer {
            raceway_drop(&model.outer, j, &rk, &outer, &mut sc.outer);
        }
        if touch_inner || touch_outer {
            sc.rollers.set(model.inner.lanes.slots(j), &rk);
        }

        // roller ↔ cage bars: edge lines of pocket j at the bar contact radius, both pocket
        // sides, evaluated at both ends of the roller (SPEC §1.5 "bone-shaped" scar)
        let pk = &diag.slices.pockets;
        let (ep, tp) = (
            [pk[0][j], pk[1][j], pk[2][j]],
            [pk[3][j], pk[4][j], pk[5][j]],
        );
        let mut bar_q = 0.0;
        let mut bar_pw = 0.0;
        let bar_dist_sq = diag.slices.bar_dist_sq.each_ref().map(|c| c[j]);
        for (k, &side) in [-1.0, 1.0].iter().enumerate() {
            for (i, &x) in model.bar_x.iter().enumerate() {
                // the (many) points clear of the bar were settled by the vector loop
                let dist_sq = bar_dist_sq[2 * k + i];
                if dist_sq >= model.rw * model.rw || dist_sq == 0.0 {
                    continue;
                }
                let q = axpy(centre, x, a);
                let d = bar_offset(model, cc, ac, (ep, tp), side, q);
                let dist = dist_sq.sqrt();
                let delta = model.rw - dist;
                note(diag, "roller ↔ cage bar", j, delta, div_limit);
                let n = scale(d, 1.0 / dist);
                let cp = axpy(q, -model.rw, n);
                let r_cp = sub(cp, centre);
                let v_roll = add(v, cross(w, r_cp));
                let v_cage = add(vcc, cross(wc, sub(cp, cc)));
                let vrel = sub(v_roll, v_cage);
                let delta_dot = -dot(vrel, n);
                let elastic = bar_share * bar.k_p * power(delta, bar.exponent);
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
                f = add(f, fc);
                m = add(m, cross(r_cp, fc));
                f_cage = sub(f_cage, fc);
                m_cage = sub(m_cage, cross(sub(cp, cc), fc));
                bar_q += qn;
                bar_pw += mu * qn * vs;
            }
        }
        diag.bar[j] = bar_q;
        diag.bar_power[j] = bar_pw;

        // roller ends ↔ ribs of both rings (pair 56) and ↔ cage pocket faces (pair 54)
        let apply = |ef: &EndForce, f: &mut V3, m: &mut V3| {
            *f = add(*f, ef.force);
            *m = add(*m, ef.moment);
        };
        let (mut rib_q, mut rib_vs, mut rib_edge, mut rib_mu, mut rib_pw, mut rib_best) =
            (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        let mut rib_regime = EndContactRegime::None;
        if model.params.roller_end_rib.enabled {
            for (k, (body, lub, faces, inner_ring)) in rib_rings.iter().enumerate() {
                let inner_ring = *inner_ring;
                if faces.is_empty() {
                    continue;
                }
                let reach = diag.slices.reach[k].get(j);
                for face in faces.iter() {
                    if reach.bound(face, &ends.end) <= 0.0 {
                        continue;
                    }
                    let Some(ef) = end_force(
                        face,
                        &ends.end,
                        body,
                        &reach,
                        &rk,
                        &model.params.roller_end_rib,
                        &ends.rib_damping,
                        Some(lub),
                    ) else {
                        continue;
                    };
                    note(diag, "roller end ↔ rib", j, ef.delta, div_limit);
                    apply(&ef, &mut f, &mut m);
                    if inner_ring {
                        f_inner = sub(f_inner, ef.force);
                    }
                    rib_q += ef.normal;
                    rib_vs += ef.normal * ef.sliding;
                    rib_edge += ef.normal * ef.edge_distance;
                    rib_mu += ef.normal * ef.mu;
                    rib_pw += ef.mu * ef.normal * ef.sliding;
                    if ef.normal > rib_best {
                        rib_best = ef.normal;
                        rib_regime = ef.regime;
                    }
                }
            }
        }
        diag.rib[j] = rib_q;
        diag.rib_power[j] = rib_pw;
        diag.rib_regime[j] = rib_regime;
        if rib_q > 0.0 {
            diag.rib_sliding[j] = rib_vs / rib_q;
            diag.rib_edge[j] = rib_edge / rib_q;
            diag.rib_mu[j] = rib_mu / rib_q;
        } else {
            diag.rib_sliding[j] = 0.0;
            diag.rib_edge[j] = f64::NAN;
            diag.rib_mu[j] = 0.0;
        }
        let (mut pocket_q, mut pocket_pw) = (0.0, 0.0);
        if model.params.roller_end_cage.enabled {
            let reach = diag.slices.reach[2].get(j);
            for face in &ends.pocket {
                if reach.bound(face, &ends.end) <= 0.0 {
                    continue;
                }
                let Some(ef) = end_force(
                    face,
                    &ends.end,
                    &cage_body,
                    &reach,
                    &rk,
                    &model.params.roller_end_cage,
                    &ends.pocket_damping,
                    None,
                ) else {
                    continue;
                };
                note(
                    diag,
                    "roller end ↔ cage pocket face",
                    j,
                    ef.delta,
                    div_limit,
                );
                apply(&ef, &mut f, &mut m);
                f_cage = sub(f_cage, ef.force);
                m_cage = add(m_cage, ef.body_moment);
                pocket_q += ef.normal;
                pocket_pw += ef.mu * ef.normal * ef.sliding;
            }
        }
        diag.pocket[j] = pocket_q;
        diag.pocket_power[j] = pocket_pw;

        diag.slices.force[j] = f;
        diag.slices.moment[j] = m;
    }

    // the raceway slices of all rollers: slot loops, then each roller's loaded slices
    let sc = &mut diag.slices;
    raceway_kernel::<true>(model, &model.inner, &inner, &sc.rollers, &mut sc.inner);
    raceway_kernel::<false>(model, &model.outer, &outer, &sc.rollers, &mut sc.outer);
    raceway_collect::<true>(
        model,
        &model.inner,
        &mut diag.inner,
        &mut sc.inner,
        div_limit,
        &mut diag.violation,
        tables,
    );
    raceway_collect::<false>(
        model,
        &model.outer,
        &mut diag.outer,
        &mut sc.outer,
        div_limit,
        &mut diag.violation,
        tables,
    );

    // raceway traction of all rollers, then Newton–Euler in cylindrical coordinates (seed 000
    // (2.1)) and L̇ = M ((2.2) in the inertial frame: the gyroscopic term is contained in
    // ω(L, a))
    apply_traction(model, diag, &mut f_inner, tables);
    let inv_mr = 1.0 / model.m_r;
    for j in 0..model.z {
        if tables == Tables::Fill {
            diag.inner.finish(j);
            diag.outer.finish(j);
        }
        let b = lay.roller(j);
        let r = y[b + 1];
        let (thd, rdot, zd) = (y[b + 6], y[b + 7], y[b + 8]);
        let (s, c, a, w) = diag.slices.frame[j];
        let (f, m) = (diag.slices.force[j], diag.slices.moment[j]);
        let f_radial = dot(f, [c, s, 0.0]);
        let f_tangential = dot(f, [-s, c, 0.0]);
        dy[b] = thd;
        dy[b + 1] = rdot;
        dy[b + 2] = zd;
        wr(dy, b + 3, cross(w, a));
        dy[b + 6] = (f_tangential * inv_mr - 2.0 * rdot * thd) / r;
        dy[b + 7] = f_radial * inv_mr + r * thd * thd;
        dy[b + 8] = f[2] * inv_mr;
        wr(dy, b + 9, m);
    }

    // cage ↔ guiding land, two stations at the quarter points of the land width
    diag.land_force = 0.0;
    diag.land_power = 0.0;
    if let Some(land) = model.land {
        let (ring, ring_spin) = if land.inner {
            (&inner, wi)
        } else {
            (&outer, wo)
        };
        for zeta in [-0.25 * land.width, 0.25 * land.width] {
            let k = LandKinematics {
                land_axis: ring.axis,
                land_center: axpy(ring.o, zeta, ring.axis),
                land_velocity: ring.v,
                land_omega: scale(ring.axis, ring_spin),
                cage_center: axpy(cc, zeta, ac),
                cage_velocity: add(vcc, cross(wc, scale(ac, zeta))),
                cage_omega: wc,
                land_radius_m: land.radius,
                radial_gap_m: land.gap,
                inner_land: land.inner,
                width_m: 0.5 * land.width,
                stations: 2,
                temperature_k: cond.temperatures.cage_k,
            };
            let lf = model.land_model.force(&k);
            if lf.normal_force_n > 0.0 {
                note(diag, "cage ↔ guiding land", 0, lf.penetration_m, div_limit);
                f_cage = add(f_cage, lf.force_on_cage_n);
                m_cage = add(m_cage, cross(sub(lf.point_m, cc), lf.force_on_cage_n));
                m_cage = add(m_cage, lf.moment_on_cage_n_m);
                if land.inner {
                    f_inner = sub(f_inner, lf.force_on_cage_n);
                }
                diag.land_force += lf.normal_force_n;
                diag.land_power += lf.power_w;
            }
        }
    }

    // cage equations
    wr(dy, ci, vcc);
    dy[ci + 3] = dot(wc, ac);
    wr(dy, ci + 4, cross(wc, ac));
    wr(dy, ci + 7, scale(f_cage, 1.0 / model.m_c));
    wr(dy, ci + 10, m_cage);

    // inner ring: prescribed spin and tilt, free or fixed translation
    let sup = cond.support;
    let load = cond.inner_ring_force(t);
    let acc = axpy(scale(add(f_inner, load), 1.0 / model.m_i), 1.0, g);
    for k in 0..3 {
        let free = if k < 2 {
            sup.radial_free
        } else {
            sup.axial_free
        };
        dy[ii + k] = if free { y[ii + 3 + k] } else { 0.0 };
        dy[ii + 3 + k] = if free { acc[k] } else { 0.0 };
    }
    debug_assert_eq!(CAGE_DOF + INNER_DOF + ROLLER_DOF * model.z, y.len());
}
