//! The raceway slice kernel: approach, slice law, damping, normal force and contact kinematics
//! of every slice of the rollers on one raceway (SPEC §2.1–2.2, §3.5), evaluated slot by slot
//! without branches so that the loop runs in vector lanes.
//!
//! The slots of a raceway are the slices of all rollers back to back (slot `j·S + s` is slice
//! `s` of roller `j`, [`SliceConstants::slots`]), so that one loop runs over the slices of many
//! rollers and no vector lane is spent on padding between rollers. The roller kinematics are
//! repeated over the roller's slots ([`RollerLanes::set`], once for both raceways); the ring's
//! are common ([`RingKinematics`]). [`evaluate`] writes one record per slot into
//! [`SliceOutputs`] (struct of arrays); slices that do not touch carry `q = 0`. The caller
//! collects the loaded slices of each roller in slice order into the traction batch
//! ([`SliceOutputs::collect_loaded`], used by [`crate::rhs`]) and later sums each slice's normal
//! and friction force in that order.
//! The loop is compiled for the build's target (AVX2, four lanes, in the x86-64-v3 build) and,
//! on x86-64, also for AVX-512F (eight lanes), chosen at run time; both give the same bits (no
//! fused multiply–add: Rust never contracts on its own, and `rolldyn_numerics::fastmath` is
//! written for that).

use crate::kinematics::RollerKinematics;
use crate::vec3::{V3, add, axpy, cross, dot, scale, sub};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_lubrication::SliceColumnsMut;
use rolldyn_numerics::fastmath;
use rolldyn_numerics::step::step;
use rolldyn_numerics::vector_copies::LoopCopy;
use std::ops::Range;

/// Vector width of the widest loop copy (AVX-512F: eight `f64`): the slot arrays have this
/// many padding slots at the end, so that a loop over whole vectors never runs out of them.
pub(crate) const LANES: usize = LoopCopy::MAX_LANES;

/// Per-slot constants of one raceway: the slices of every roller back to back, then [`LANES`]
/// padding slots, which never touch (their drop is +∞) and carry no stiffness, damping or
/// length.
#[derive(Debug, Clone)]
pub(crate) struct SliceConstants {
    /// slices per roller
    pub slices: usize,
    /// slice centre along the roller axis from the roller centre, m
    pub x: Vec<f64>,
    /// roller profile drop at the slice centre, m
    pub drop: Vec<f64>,
    /// `k_s` of the slice law `Q = k_s δⁿ`, N/mⁿ
    pub k: Vec<f64>,
    /// full damping `C_max` of the slice, N·s/m
    pub c_max: Vec<f64>,
    /// 1/δ* of the approach `δ*` at which the damping reaches `C_max`, 1/m (the slot loop
    /// multiplies instead of dividing)
    pub inv_delta_star: Vec<f64>,
    /// slice length, m
    pub len: Vec<f64>,
}

impl SliceConstants {
    /// Constants of `rollers` rollers whose slices are at `x` with roller drops `drop`, lengths
    /// `len`, slice-law coefficients `k` and damping ramps `damping` (viscous `C(δ)·δ̇`, as
    /// [`SliceDamping::new`] builds them).
    pub fn new(
        rollers: usize,
        x: &[f64],
        drop: &[f64],
        len: &[f64],
        k: &[f64],
        damping: &[SliceDamping],
    ) -> Self {
        let repeat = |v: &[f64], fill: f64| {
            let mut out: Vec<f64> = (0..rollers).flat_map(|_| v.iter().copied()).collect();
            out.resize(out.len() + LANES, fill);
            out
        };
        let c_max: Vec<f64> = damping.iter().map(|d| d.c_max).collect();
        let inv_delta_star: Vec<f64> = damping.iter().map(|d| 1.0 / d.delta_star).collect();
        debug_assert!(damping.iter().all(|d| d.uses_velocity));
        Self {
            slices: x.len(),
            x: repeat(x, 0.0),
            drop: repeat(drop, f64::INFINITY),
            k: repeat(k, 0.0),
            c_max: repeat(&c_max, 0.0),
            inv_delta_star: repeat(&inv_delta_star, 1.0),
            len: repeat(len, 0.0),
        }
    }

    /// The slots of roller `j`.
    #[inline]
    pub fn slots(&self, j: usize) -> Range<usize> {
        j * self.slices..(j + 1) * self.slices
    }
}

/// Kinematics of the ring, shared by all slots of a raceway.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RingKinematics {
    /// ring centre, velocity, axis (unit) and spin
    pub ring_o: V3,
    pub ring_v: V3,
    pub ring_axis: V3,
    pub ring_spin: f64,
    /// raceway radius and roller radius, m
    pub raceway_radius: f64,
    pub rw: f64,
    /// slice-law exponent n
    pub exponent: f64,
}

/// The values of [`RollerKinematics`] repeated over the roller's slots, in the column order of
/// [`RollerLanes`] and of the slot loop: c, a, v, w, θ̇.
fn lane_values(k: &RollerKinematics) -> [f64; ROLLER_COLUMNS] {
    let [c, a, v, w] = [k.c, k.a, k.v, k.w];
    [
        c[0], c[1], c[2], a[0], a[1], a[2], v[0], v[1], v[2], w[0], w[1], w[2], k.orbit,
    ]
}

/// Number of [`RollerKinematics`] values per slot.
const ROLLER_COLUMNS: usize = 13;

/// [`RollerKinematics`] repeated over each roller's slots (struct of arrays, slot layout of
/// [`SliceConstants`]); the same for both raceways, whose slots coincide.
#[derive(Debug, Clone)]
pub(crate) struct RollerLanes {
    /// one column per entry of [`lane_values`]
    columns: [Vec<f64>; ROLLER_COLUMNS],
}

impl RollerLanes {
    /// Lanes for `slots` slots (padding included), all zero.
    pub fn new(slots: usize) -> Self {
        Self {
            columns: std::array::from_fn(|_| vec![0.0; slots]),
        }
    }

    /// Repeats `k` over `slots`. Writes whole vectors from `slots.start`, i.e. up to
    /// [`LANES`]` − 1` slots beyond `slots.end`: set the rollers in slot order, so that the
    /// next roller's values replace those.
    pub fn set(&mut self, slots: Range<usize>, k: &RollerKinematics) {
        let vectors = slots.len().div_ceil(LANES);
        let values = lane_values(k);
        let columns = &mut self.columns;
        // a fixed number of stores per column for the common roller lengths (up to 24 slices)
        match vectors {
            1 => fill_columns::<1>(columns, slots.start, vectors, &values),
            2 => fill_columns::<2>(columns, slots.start, vectors, &values),
            3 => fill_columns::<3>(columns, slots.start, vectors, &values),
            _ => fill_columns::<0>(columns, slots.start, vectors, &values),
        }
    }
}

rolldyn_numerics::avx512_twin! {
    /// Writes `values[i]` into `vectors` whole vectors of [`LANES`] slots of `columns[i]` from
    /// slot `start` on (`VECTORS` of them when it is not 0): one vector store per [`LANES`]
    /// slots in the AVX-512F copy.
    fn fill_columns<const VECTORS: usize>(
        columns: &mut [Vec<f64>; ROLLER_COLUMNS],
        start: usize,
        vectors: usize,
        values: &[f64; ROLLER_COLUMNS],
    ) = fill_columns_portable / fill_columns_avx512 {
        let vectors = if VECTORS > 0 { VECTORS } else { vectors };
        for (column, &value) in columns.iter_mut().zip(values) {
            let slots = &mut column[start..start + vectors * LANES];
            for chunk in slots.as_chunks_mut::<LANES>().0 {
                *chunk = [value; LANES];
            }
        }
    }
}

/// Per-slot results of [`evaluate`] (struct of arrays, slot layout of [`SliceConstants`]).
#[derive(Debug, Clone, Default)]
pub(crate) struct SliceOutputs {
    /// approach δ, m (≤ 0: no contact)
    pub delta: Vec<f64>,
    /// normal force Q, N (0 where the slice does not press)
    pub q: Vec<f64>,
    /// normal force on the roller `Q n`, N
    pub force: [Vec<f64>; 3],
    /// contact point relative to the roller centre, m
    pub r_cp: [Vec<f64>; 3],
    /// direction of the tangential relative velocity v_t (roller − ring), unit (zero where
    /// v_t vanishes): the friction on the roller is `−μ Q` times it
    pub slide_dir: [Vec<f64>; 3],
    /// the sliding speed |v_t|, m/s
    pub vs: Vec<f64>,
    /// entrainment speed in the roller's orbital frame, m/s
    pub u: Vec<f64>,
}

impl SliceOutputs {
    /// Outputs for `slots` slots (padding included).
    pub fn new(slots: usize) -> Self {
        let v = || vec![0.0; slots];
        Self {
            delta: v(),
            q: v(),
            force: [v(), v(), v()],
            r_cp: [v(), v(), v()],
            slide_dir: [v(), v(), v()],
            vs: v(),
            u: v(),
        }
    }

    /// Pass 1 over the slots of one roller (`slots`, in slice order): sums the loads of the
    /// loaded slots and writes their traction inputs (Q, slice length from `lens`, u, |v_t|) to
    /// `columns` from index `to` on, one run of consecutive loaded slots after the other, each
    /// recorded in `runs`. Notes the first approach above `limit` (divergence check). The
    /// normal force, contact point and sliding direction of a slot stay where they are
    /// ([`LoadedRun::slot`] finds them): the traction pass adds the normal and friction forces
    /// of a slice and their moment together.
    pub fn collect_loaded(
        &self,
        slots: Range<usize>,
        lens: &[f64],
        limit: f64,
        to: usize,
        columns: &mut SliceColumnsMut,
        runs: &mut Vec<LoadedRun>,
    ) -> LoadedSlots {
        let Self {
            delta, q, vs, u, ..
        } = self;
        let mut sums = LoadedSlots::default();
        if let Some(s) = delta[slots.clone()].iter().position(|&d| d > limit) {
            sums.violation = Some(delta[slots.start + s]);
        }
        let first = to;
        let mut to = to;
        let mut s = slots.start;
        while s < slots.end {
            if q[s] <= 0.0 {
                s += 1;
                continue;
            }
            let (start, run_start) = (s, to);
            while s < slots.end && q[s] > 0.0 {
                let qs = q[s];
                sums.load += qs;
                sums.length += lens[s];
                sums.entrainment += qs * u[s];
                columns.normal_force_n[to] = qs;
                columns.length_m[to] = lens[s];
                columns.rolling_speed_m_s[to] = u[s];
                columns.sliding_speed_m_s[to] = vs[s];
                s += 1;
                to += 1;
            }
            runs.push(LoadedRun {
                batch: run_start..to,
                slot: start,
            });
        }
        sums.slots = first..to;
        sums
    }
}

/// A run of consecutive loaded slots of one roller, moved to the traction batch by
/// [`SliceOutputs::collect_loaded`].
#[derive(Debug, Clone)]
pub(crate) struct LoadedRun {
    /// the run's batch slices
    pub batch: Range<usize>,
    /// the slot of its first slice (the others follow)
    pub slot: usize,
}

/// Result of [`SliceOutputs::collect_loaded`].
#[derive(Debug, Clone, Default)]
pub(crate) struct LoadedSlots {
    /// total normal force, N; loaded length, m; Σ Q u (load-weighted entrainment × load)
    pub load: f64,
    pub length: f64,
    pub entrainment: f64,
    /// the batch slices that now hold the loaded slices (empty: none)
    pub slots: Range<usize>,
    /// first approach above the divergence limit, m
    pub violation: Option<f64>,
}

/// Evaluates the slots `slots` of `sc` (inner raceway when `INNER`) with the roller kinematics
/// of `rollers`, the raceway drop `race_drop` under each slot and the ring's `ring`. Every
/// roller whose slots overlap `slots` must have its lanes set; the loop runs over whole vectors from `slots.start`, so it may also evaluate up
/// to [`LANES`]` − 1` slots beyond `slots.end` (which are then overwritten or ignored).
pub(crate) fn evaluate<const INNER: bool>(
    sc: &SliceConstants,
    rollers: &RollerLanes,
    race_drop: &[f64],
    ring: &RingKinematics,
    slots: Range<usize>,
    out: &mut SliceOutputs,
) {
    // SAFETY: `LoopCopy::detect` names the widest copy this CPU supports.
    unsafe { evaluate_with::<INNER>(sc, rollers, race_drop, ring, slots, out, LoopCopy::detect()) };
}

/// The inputs of the slot loop, each cut to the loop's slots.
struct SlotInputs<'a> {
    x: &'a [f64],
    drop: &'a [f64],
    stiff: &'a [f64],
    c_max: &'a [f64],
    inv_delta_star: &'a [f64],
    race_drop: &'a [f64],
    /// the columns of [`RollerLanes`]
    roller: [&'a [f64]; ROLLER_COLUMNS],
}

/// [`evaluate`] with the compiled copy of the loop chosen by the caller.
///
/// # Safety
/// `copy` must be a copy this CPU supports: [`LoopCopy::detect`] or narrower (the AVX-512F
/// copy executes AVX-512F instructions).
unsafe fn evaluate_with<'a, const INNER: bool>(
    sc: &'a SliceConstants,
    rollers: &'a RollerLanes,
    race_drop: &'a [f64],
    ring: &RingKinematics,
    range: Range<usize>,
    out: &mut SliceOutputs,
    copy: LoopCopy,
) {
    if range.is_empty() {
        return;
    }
    // whole vectors from the first slot (the arrays end in LANES padding slots)
    let lanes = copy.lanes();
    let r = range.start..range.start + range.len().div_ceil(lanes) * lanes;
    let cut = |v: &'a [f64]| -> &'a [f64] { &v[r.clone()] };
    let inputs = SlotInputs {
        x: cut(&sc.x),
        drop: cut(&sc.drop),
        stiff: cut(&sc.k),
        c_max: cut(&sc.c_max),
        inv_delta_star: cut(&sc.inv_delta_star),
        race_drop: cut(race_drop),
        roller: rollers.columns.each_ref().map(|c| cut(c)),
    };
    let [fx, fy, fz] = &mut out.force;
    let [rx, ry, rz] = &mut out.r_cp;
    let [tx, ty, tz] = &mut out.slide_dir;
    // Every output array is a separate `&mut` argument of the loop, so the compiler knows that
    // they overlap neither each other nor the inputs and vectorises the loop without run-time
    // overlap checks.
    macro_rules! call {
        ($kernel:ident) => {
            $kernel::<INNER>(
                ring,
                &inputs,
                &mut out.delta[r.clone()],
                &mut out.q[r.clone()],
                &mut fx[r.clone()],
                &mut fy[r.clone()],
                &mut fz[r.clone()],
                &mut rx[r.clone()],
                &mut ry[r.clone()],
                &mut rz[r.clone()],
                &mut tx[r.clone()],
                &mut ty[r.clone()],
                &mut tz[r.clone()],
                &mut out.vs[r.clone()],
                &mut out.u[r.clone()],
            )
        };
    }
    match copy {
        // SAFETY: the CPU supports AVX-512F (the caller's contract).
        #[cfg(target_arch = "x86_64")]
        LoopCopy::Avx512 => unsafe { call!(slots_avx512) },
        _ => call!(slots),
    }
}

rolldyn_numerics::avx512_twin! {
    /// The loop over the slots. Per slot (SPEC §2.1–2.2): slice centre `p = c + x a`, its
    /// distance `ρ` from the ring axis, approach `δ = R_i + R_w − ρ − z_s −
    /// z_race` (inner) or `ρ + R_w − R_o − z_s − z_race` (outer, seed 000 (2.5)),
    /// `Q = max(0, k_s δⁿ + STEP(δ, 0, 0, δ*, C_max) δ̇)` for `δ > 0` (seed 000 (2.5)–(2.8)),
    /// contact point `p − R_w n`, relative velocity of roller and ring there, its tangential
    /// part and the orbital-frame entrainment speed (SPEC §3.5).
    fn slots<const INNER: bool>(
        ring: &RingKinematics,
        inputs: &SlotInputs,
        delta_out: &mut [f64],
        q_out: &mut [f64],
        fx: &mut [f64],
        fy: &mut [f64],
        fz: &mut [f64],
        rx: &mut [f64],
        ry: &mut [f64],
        rz: &mut [f64],
        tx: &mut [f64],
        ty: &mut [f64],
        tz: &mut [f64],
        vs_out: &mut [f64],
        u_out: &mut [f64],
    ) / slots_avx512 {
        // equal lengths, known to the compiler: no bounds checks in the loop
        let n = inputs.x.len();
        let (x, drop, stiff, c_max, inv_delta_star, race_drop) = (
            &inputs.x[..n],
            &inputs.drop[..n],
            &inputs.stiff[..n],
            &inputs.c_max[..n],
            &inputs.inv_delta_star[..n],
            &inputs.race_drop[..n],
        );
        let [cx, cy, cz, ax, ay, az, vx, vy, vz, wx, wy, wz, orbit] = inputs.roller.map(|c| &c[..n]);
        let (delta_out, q_out, vs_out, u_out) = (
            &mut delta_out[..n],
            &mut q_out[..n],
            &mut vs_out[..n],
            &mut u_out[..n],
        );
        let (fx, fy, fz) = (&mut fx[..n], &mut fy[..n], &mut fz[..n]);
        let (rx, ry, rz) = (&mut rx[..n], &mut ry[..n], &mut rz[..n]);
        let (tx, ty, tz) = (&mut tx[..n], &mut ty[..n], &mut tz[..n]);
        let ring_spin_axis = scale(ring.ring_axis, ring.ring_spin);
        for s in 0..n {
            let xs = x[s];
            let (c, a) = ([cx[s], cy[s], cz[s]], [ax[s], ay[s], az[s]]);
            // offset of the slice centre from the ring axis, perpendicular to it
            let d_c = sub(c, ring.ring_o);
            let dp_c = axpy(d_c, -dot(d_c, ring.ring_axis), ring.ring_axis);
            let a_perp = axpy(a, -dot(a, ring.ring_axis), ring.ring_axis);
            let offset = axpy(dp_c, xs, a_perp);
            let rho = dot(offset, offset).sqrt();
            let delta = if INNER {
                ring.raceway_radius + ring.rw - rho
            } else {
                rho + ring.rw - ring.raceway_radius
            } - drop[s]
                - race_drop[s];
            let inv_rho = if rho > 0.0 { 1.0 / rho } else { 0.0 };
            let touching = delta > 0.0 && rho > 0.0;
            // outward unit normal of the ring axis through the slice centre; n points from the
            // ring into the roller
            let n_out = scale(offset, inv_rho);
            let n = if INNER { n_out } else { scale(n_out, -1.0) };
            let r_cp = axpy(scale(a, xs), -ring.rw, n);
            let cp = add(c, r_cp);
            let v_roll = add([vx[s], vy[s], vz[s]], cross([wx[s], wy[s], wz[s]], r_cp));
            let v_ring = add(ring.ring_v, cross(ring_spin_axis, sub(cp, ring.ring_o)));
            let vrel = sub(v_roll, v_ring);
            let v_normal = dot(vrel, n);
            let delta_dot = -v_normal;
            // slice law k_s δⁿ (exp(n ln δ)); the damping ramp STEP(δ, 0, 0, δ*, C_max) of
            // rolldyn_contact::damping, written in the normalised approach δ·(1/δ*) (a
            // multiplication instead of a division per slot): STEP(δ/δ*, 0, 0, 1, C_max)
            let elastic = if touching {
                stiff[s] * fastmath::exp(ring.exponent * fastmath::ln(delta))
            } else {
                0.0
            };
            let damping = step(delta * inv_delta_star[s], 0.0, 0.0, 1.0, c_max[s]);
            let pressing = elastic + damping * delta_dot;
            let q = if touching && pressing > 0.0 {
                pressing
            } else {
                0.0
            };
            let normal = scale(n, q);
            let vt = axpy(vrel, -v_normal, n);
            // rolling direction and entrainment speed in the roller's orbital frame (SPEC §3.5)
            let t_dir = cross(ring.ring_axis, n_out);
            let w_frame = [-orbit[s] * cp[1], orbit[s] * cp[0], 0.0];
            let u = 0.5 * (dot(v_roll, t_dir) + dot(v_ring, t_dir)) - dot(w_frame, t_dir);
            delta_out[s] = delta;
            q_out[s] = q;
            fx[s] = normal[0];
            fy[s] = normal[1];
            fz[s] = normal[2];
            rx[s] = r_cp[0];
            ry[s] = r_cp[1];
            rz[s] = r_cp[2];
            let vs = dot(vt, vt).sqrt();
            let dir = scale(vt, if vs > 0.0 { 1.0 / vs } else { 0.0 });
            tx[s] = dir[0];
            ty[s] = dir[1];
            tz[s] = dir[2];
            vs_out[s] = vs;
            u_out[s] = u;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vec3::{norm, perp};

    /// Ten slices per roller, `rollers` rollers.
    fn constants(rollers: usize) -> SliceConstants {
        let x: Vec<f64> = (0..10).map(|s| -4.5e-3 + 1e-3 * s as f64).collect();
        let drop: Vec<f64> = x.iter().map(|x| 2e-6 * (x / 5e-3).powi(4)).collect();
        let len = vec![1e-3; 10];
        let k = vec![6e8; 10];
        let damping = vec![SliceDamping::new(30.0, 1e-6); 10];
        SliceConstants::new(rollers, &x, &drop, &len, &k, &damping)
    }

    fn ring(inner: bool) -> RingKinematics {
        RingKinematics {
            ring_o: [0.0; 3],
            ring_v: [0.0; 3],
            ring_axis: [0.0, 0.0, 1.0],
            ring_spin: if inner { 667.0 } else { 0.0 },
            raceway_radius: if inner { 0.0762 - 4e-6 } else { 0.0962 + 3e-6 },
            rw: 0.01,
            exponent: 10.0 / 9.0,
        }
    }

    /// A roller at the pitch radius, slightly tilted by `tilt`, its centre displaced radially
    /// by `shift`; ring axis z through the origin.
    fn roller(tilt: f64, shift: f64) -> RollerKinematics {
        let c = [0.0, 0.0862 + shift, 1e-5];
        let a = [1.5e-3 * tilt, -2e-3 * tilt, 1.0];
        let na = norm(a);
        let a = scale(a, 1.0 / na);
        RollerKinematics {
            c,
            a,
            v: [-25.0, 0.01, 0.0],
            w: [3.0, -2.0, -2900.0],
            orbit: 290.0,
        }
    }

    /// Evaluates every slot of `sc` for the rollers `rollers` with the loop copy `copy` (one
    /// this CPU supports).
    fn run(
        sc: &SliceConstants,
        rollers: &[RollerKinematics],
        inner: bool,
        copy: LoopCopy,
    ) -> SliceOutputs {
        let mut lanes = RollerLanes::new(sc.x.len());
        for (j, k) in rollers.iter().enumerate() {
            lanes.set(sc.slots(j), k);
        }
        let mut out = SliceOutputs::new(sc.x.len());
        let all = 0..rollers.len() * sc.slices;
        let race_drop = vec![0.0; sc.x.len()];
        assert!(copy <= LoopCopy::detect(), "{copy:?} on this CPU");
        // SAFETY: the CPU supports `copy` (asserted just above).
        unsafe {
            if inner {
                evaluate_with::<true>(sc, &lanes, &race_drop, &ring(true), all, &mut out, copy);
            } else {
                evaluate_with::<false>(sc, &lanes, &race_drop, &ring(false), all, &mut out, copy);
            }
        }
        out
    }

    /// Slice by slice with the library's own functions (`powf`, `SliceDamping`, `perp`).
    fn reference(
        sc: &SliceConstants,
        k: &RollerKinematics,
        inner: bool,
        s: usize,
    ) -> (f64, V3, f64) {
        let g = ring(inner);
        let x = sc.x[s];
        let p = axpy(k.c, x, k.a);
        // offset from the ring axis z through the origin
        let off = [p[0], p[1], 0.0];
        let rho = norm(off);
        let delta = if inner {
            g.raceway_radius + g.rw - rho
        } else {
            rho + g.rw - g.raceway_radius
        } - sc.drop[s];
        let n_out = scale(off, 1.0 / rho);
        let n = if inner { n_out } else { scale(n_out, -1.0) };
        let cp = axpy(p, -g.rw, n);
        let v_roll = add(k.v, cross(k.w, sub(cp, k.c)));
        let v_ring = add(
            g.ring_v,
            scale(cross(g.ring_axis, sub(cp, g.ring_o)), g.ring_spin),
        );
        let vrel = sub(v_roll, v_ring);
        let damping = SliceDamping::new(sc.c_max[s], 1.0 / sc.inv_delta_star[s]);
        let q = if delta > 0.0 {
            damping.normal_force(sc.k[s] * delta.powf(g.exponent), delta, -dot(vrel, n))
        } else {
            0.0
        };
        (q, perp(vrel, n), delta)
    }

    #[test]
    fn kernel_matches_slice_by_slice_evaluation() {
        let sc = constants(1);
        for inner in [true, false] {
            let k = roller(1.0, 0.0);
            let out = run(&sc, &[k], inner, LoopCopy::detect());
            let mut loaded = 0;
            for s in 0..10 {
                let (q, vt, delta) = reference(&sc, &k, inner, s);
                // ρ by √(A + 2Bx + Cx²) against |dp| differs by round-off of the pitch
                // radius (≈ 1e-17 m), i.e. ≈ 1e-11 of a micrometre approach
                assert!((out.delta[s] - delta).abs() < 1e-15, "δ slice {s}");
                assert!(
                    (out.q[s] - q).abs() <= 1e-8 * q.max(1.0),
                    "Q slice {s}: {} vs {q}",
                    out.q[s]
                );
                if q > 0.0 {
                    loaded += 1;
                    let got = scale(
                        [
                            out.slide_dir[0][s],
                            out.slide_dir[1][s],
                            out.slide_dir[2][s],
                        ],
                        out.vs[s],
                    );
                    assert!(
                        norm(sub(got, vt)) < 1e-12 * norm(vt).max(1.0),
                        "v_t slice {s}"
                    );
                    assert!((out.vs[s] - norm(vt)).abs() < 1e-12);
                }
            }
            assert!(
                (3..10).contains(&loaded),
                "inner {inner}: {loaded} loaded slices"
            );
            // padding never touches
            assert!(out.q[10..].iter().all(|&q| q == 0.0));
        }
    }

    /// The bits of every output of the slots `slots`.
    fn bits(o: &SliceOutputs, slots: Range<usize>) -> Vec<u64> {
        let mut all = vec![&o.delta, &o.q, &o.vs, &o.u];
        all.extend(o.force.iter().chain(&o.r_cp).chain(&o.slide_dir));
        all.iter()
            .flat_map(|v| v[slots.clone()].iter().map(|x| x.to_bits()))
            .collect()
    }

    /// Rollers evaluated back to back in one loop give each roller's own results, bit for bit,
    /// and the AVX-512F copy (if this CPU supports it) gives the bits of the portable
    /// loop.
    #[test]
    fn packed_rollers_and_loop_copies_agree() {
        let rollers = [roller(1.0, 0.0), roller(-2.0, 3e-6), roller(0.5, -2e-6)];
        let sc = constants(rollers.len());
        let all = 0..rollers.len() * sc.slices;
        for inner in [true, false] {
            let portable = run(&sc, &rollers, inner, LoopCopy::Portable);
            for (j, k) in rollers.iter().enumerate() {
                let alone = run(&constants(1), &[*k], inner, LoopCopy::Portable);
                assert_eq!(
                    bits(&portable, sc.slots(j)),
                    bits(&alone, 0..sc.slices),
                    "roller {j}, inner {inner}"
                );
            }
            for copy in [LoopCopy::Avx512] {
                if copy > LoopCopy::detect() {
                    continue;
                }
                assert_eq!(
                    bits(&run(&sc, &rollers, inner, copy), all.clone()),
                    bits(&portable, all.clone()),
                    "{copy:?}, inner {inner}"
                );
            }
        }
    }
}
