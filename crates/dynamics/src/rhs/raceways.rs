//! Stages 2–4 on the raceways: which rollers may touch each raceway (pass 1a, one vector loop),
//! the slot loop over the slices of those rollers (pass 1b, [`slice_kernel::evaluate`]), the
//! loaded slices collected per roller into one traction batch per raceway (pass 1c), and the
//! traction of the batch applied as normal and friction forces (pass 2) — SPEC §2.1–2.2, §3.3.

use super::Wrench;
use super::bodies::{Bodies, RingKin};
use super::diagnostics::{ContactTable, Tables, Violation};
use crate::kinematics::{RollerKinematics, split_sliding};
use crate::model::{Model, RacewaySlices};
use crate::slice_kernel::{self, LANES, LoadedRun, RingKinematics, RollerLanes, SliceOutputs};
use crate::vec3::{V3, add, axpy, cross, dot, scale, sub};
use rolldyn_lubrication::{BatchContact, ContactGeometry, ContactState, SliceBatch};

/// Scratch of the raceway contacts of one evaluation: per raceway the slot loop's inputs and
/// results and the loaded contacts whose traction is evaluated in one batch, and the roller
/// kinematics repeated over the slots (the same for both raceways, whose slots coincide).
#[derive(Debug, Clone)]
pub(super) struct RacewayScratch {
    inner: RacewayPass,
    outer: RacewayPass,
    /// the kinematics of every roller that may touch a raceway, repeated over its slots
    lanes: RollerLanes,
}

impl RacewayScratch {
    pub fn new(z: usize, slices: usize) -> Self {
        Self {
            inner: RacewayPass::new(z, slices),
            outer: RacewayPass::new(z, slices),
            lanes: RollerLanes::new(z * slices + LANES),
        }
    }
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

/// Pass 1a on both raceways: which rollers may touch them (`may_touch`), from the roller
/// centres and unit axes.
pub(super) fn detect(
    model: &Model,
    bodies: &Bodies,
    centre: &[Vec<f64>; 3],
    axis: &[Vec<f64>; 3],
    sc: &mut RacewayScratch,
) {
    sc.inner.loaded.clear();
    sc.outer.loaded.clear();
    raceway_pairs::<true>(
        model,
        &model.inner,
        &bodies.inner,
        centre,
        axis,
        &mut sc.inner,
    );
    raceway_pairs::<false>(
        model,
        &model.outer,
        &bodies.outer,
        centre,
        axis,
        &mut sc.outer,
    );
}

/// Prepares the slots of roller `j` (at azimuth `azimuth`, rad) for the slot loop: the raceway
/// drop under them and its kinematics repeated over them, on the raceways it may touch.
#[inline(always)]
pub(super) fn prepare_slots(
    model: &Model,
    bodies: &Bodies,
    j: usize,
    rk: &RollerKinematics,
    azimuth: f64,
    sc: &mut RacewayScratch,
) {
    let (touch_inner, touch_outer) = (sc.inner.may_touch[j], sc.outer.may_touch[j]);
    if touch_inner {
        raceway_drop(&model.inner, j, rk, azimuth, &bodies.inner, &mut sc.inner);
    }
    if touch_outer {
        raceway_drop(&model.outer, j, rk, azimuth, &bodies.outer, &mut sc.outer);
    }
    if touch_inner || touch_outer {
        sc.lanes.set(model.inner.lanes.slots(j), rk);
    }
}

/// Passes 1b and 1c on both raceways: the slot loops, then each roller's loaded slices into
/// the traction batches and its normal force into `inner` and `outer`.
pub(super) fn slice_contacts(
    model: &Model,
    bodies: &Bodies,
    sc: &mut RacewayScratch,
    (inner, outer): (&mut ContactTable, &mut ContactTable),
    violation: &mut Option<Violation>,
    tables: Tables,
) {
    raceway_kernel::<true>(model, &model.inner, &bodies.inner, &sc.lanes, &mut sc.inner);
    raceway_kernel::<false>(model, &model.outer, &bodies.outer, &sc.lanes, &mut sc.outer);
    let limit = model.div_limit;
    raceway_collect::<true>(
        model,
        &model.inner,
        inner,
        &mut sc.inner,
        limit,
        violation,
        tables,
    );
    raceway_collect::<false>(
        model,
        &model.outer,
        outer,
        &mut sc.outer,
        limit,
        violation,
        tables,
    );
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

/// The raceway drop under the slots of roller `j` (profiled or worn raceways only) for the slot
/// loop ([`raceway_kernel`]): the profile's drop at each slot's axial position ζ on the ring,
/// plus the wear map's depth at (ζ, ψ), ψ = `azimuth` − ring angle the roller centre's angle
/// in the ring's frame (the azimuth about the bearing axis: the inner ring's offset of a few µm
/// turns it by ~10⁻⁵ rad, far below a bin of the map).
fn raceway_drop(
    rs: &RacewaySlices,
    j: usize,
    rk: &RollerKinematics,
    azimuth: f64,
    ring: &RingKin,
    pass: &mut RacewayPass,
) {
    if rs.profile.is_none() && rs.wear.is_none() {
        return;
    }
    let zeta_c = dot(sub(rk.c, ring.o), ring.axis);
    let a_ax = dot(rk.a, ring.axis);
    let slots = rs.lanes.slots(j);
    let race_drop = &mut pass.race_drop[slots.clone()];
    let zetas = rs.lanes.x[slots].iter().map(|&x| zeta_c + x * a_ax);
    if let Some(map) = &rs.wear {
        let wear = map.at_angle(azimuth - ring.angle);
        for (d, zeta) in race_drop.iter_mut().zip(zetas) {
            *d = rs.profile.as_ref().map_or(0.0, |pr| pr.drop(zeta)) + wear.depth(zeta);
        }
    } else if let Some(pr) = &rs.profile {
        for (d, zeta) in race_drop.iter_mut().zip(zetas) {
            *d = pr.drop(zeta);
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
/// slice and their moment to its roller's `wrench`, their reaction to the inner ring
/// (`f_inner`) and, with [`Tables::Fill`], fills the per-roller contact tables (`axis`: the
/// rollers' unit axes, for the sliding split).
pub(super) fn apply_traction(
    model: &Model,
    sc: &mut RacewayScratch,
    (inner, outer): (&mut ContactTable, &mut ContactTable),
    wrench: &mut [Wrench],
    f_inner: &mut V3,
    axis: &[Vec<f64>; 3],
    tables: Tables,
) {
    for (pass, table, tmodel, is_inner) in [
        (&mut sc.inner, inner, &model.traction.inner, true),
        (&mut sc.outer, outer, &model.traction.outer, false),
    ] {
        pass.loaded.batch.evaluate(tmodel);
        for block in &pass.loaded.blocks {
            let (force, moment) = block_wrench(block, &pass.loaded, &pass.out);
            let w = &mut wrench[block.roller];
            w.force = add(w.force, force);
            w.moment = add(w.moment, moment);
            if is_inner {
                *f_inner = sub(*f_inner, force);
            }
        }
        if tables == Tables::Fill {
            fill_table(&pass.loaded, table);
            fill_slices(&pass.loaded, &pass.out, axis, table);
        }
    }
}

/// The normal and friction forces of the slices of `block` and their moment about the roller
/// centre, summed in registers (seed 000 (2.9): friction `−μ Q` along the sliding direction).
#[inline]
fn block_wrench(block: &LoadedBlock, loaded: &LoadedContacts, out: &SliceOutputs) -> (V3, V3) {
    let (q_all, mu_all) = loaded.batch.forces_and_coefficients();
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
    (force, moment)
}

/// The per-roller contact table of one raceway from its evaluated batch: load-weighted sums of
/// sliding and rolling speed, film, Λ and μ, the friction power and the most loaded slice.
fn fill_table(loaded: &LoadedContacts, table: &mut ContactTable) {
    let batch = &loaded.batch;
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

/// Every loaded slice's normal force and the load-weighted sums of its sliding velocity split
/// along the roller ([`split_sliding`]) into `table` (rolling-direction and axial components;
/// [`ContactTable::finish`] turns them into means).
fn fill_slices(
    loaded: &LoadedContacts,
    out: &SliceOutputs,
    axis: &[Vec<f64>; 3],
    table: &mut ContactTable,
) {
    for block in &loaded.blocks {
        let j = block.roller;
        let a = [axis[0][j], axis[1][j], axis[2][j]];
        for run in &loaded.runs[block.runs.clone()] {
            for s in run.slot..run.slot + run.batch.len() {
                let q = out.q[s];
                table.slice_force[s] = q;
                let n = scale([out.force[0][s], out.force[1][s], out.force[2][s]], 1.0 / q);
                let dir = [
                    out.slide_dir[0][s],
                    out.slide_dir[1][s],
                    out.slide_dir[2][s],
                ];
                let split = split_sliding(n, a, scale(dir, out.vs[s]));
                table.sliding_rolling[j] += q * split.rolling;
                table.sliding_axial[j] += q * split.axial;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::conditions::OperatingConditions;
    use crate::model::RacewayTraction;
    use crate::parameters::ContactParameters;
    use rolldyn_geometry::RacewayWearMap;

    /// A ring turned by 0.7 rad: the roller at azimuth 2.0 rad sits over ring angle 1.3 rad,
    /// and the drop under its slots is the map's depth there (plus the raceway profile), the
    /// value `Ring::raceway_drop_at` gives.
    #[test]
    fn the_drop_reads_the_map_at_the_roller_angle_in_the_ring_frame() {
        let mut b = rolldyn_model::default_cylindrical_bearing();
        let depth = (0..3)
            .flat_map(|i| (0..8).map(move |k| 1e-6 * (1 + i + 3 * k) as f64))
            .collect();
        let map = RacewayWearMap::new(vec![-5e-3, 0.0, 5e-3], 8, depth).unwrap();
        b.inner_ring.raceway_wear = Some(map);
        let traction = RacewayTraction::same(
            rolldyn_lubrication::TractionModel::muraki(
                rolldyn_lubrication::lubricant_by_name("pao1-vg320").unwrap(),
            )
            .unwrap(),
        );
        let cond = OperatingConditions::new(100.0, 1000.0);
        let model = Model::new(&b, cond, ContactParameters::for_bearing(&b), traction).unwrap();
        let ring = RingKin {
            o: [0.0; 3],
            v: [0.0; 3],
            axis: [0.0, 0.0, 1.0],
            spin: 100.0,
            angle: 0.7,
            raceway_radius: model.ri,
        };
        let (s, c) = 2.0_f64.sin_cos();
        let rk = RollerKinematics {
            c: [model.rm * c, model.rm * s, 1e-3],
            a: [0.0, 0.0, 1.0],
            v: [0.0; 3],
            w: [0.0; 3],
            orbit: 0.0,
        };
        let slices = model.slice_x.len();
        let mut pass = RacewayPass::new(model.z, slices);
        let j = 3;
        raceway_drop(&model.inner, j, &rk, 2.0, &ring, &mut pass);
        let slots = model.inner.lanes.slots(j);
        for (s, &x) in slots.clone().zip(&model.slice_x) {
            let expected = b.inner_ring.raceway_drop_at(1e-3 + x, 1.3);
            assert!((pass.race_drop[s] - expected).abs() < 1e-15, "{s}");
        }
        // the map varies with the angle: azimuth + ring angle (the wrong sign) or the azimuth
        // alone would read other depths
        let first = 1e-3 + model.slice_x[0];
        for wrong in [2.7, 2.0] {
            let other = b.inner_ring.raceway_drop_at(first, wrong);
            assert!(
                (pass.race_drop[slots.start] - other).abs() > 1e-6,
                "{wrong}"
            );
        }
    }
}
