//! The raceway slice kernel: approach, slice law, damping, normal force and contact kinematics
//! of every slice of one roller on one raceway (SPEC §2.1–2.2, §3.5), evaluated slice by slice
//! without branches so that the loop runs in vector lanes.
//!
//! [`evaluate`] writes one record per slice into [`SliceOutputs`] (struct of arrays); slices that
//! do not touch carry `q = 0`. The caller sums the forces and collects the loaded slices in
//! slice order ([`crate::rhs`]), so the sums are the same as those of a slice-by-slice loop.
//! On x86-64 the loop is also compiled for AVX2 (four lanes) and AVX-512F (eight lanes) and the
//! widest copy the CPU supports is chosen at run time; all versions give the same bits (no
//! fused multiply–add: Rust never contracts on its own, and `rolldyn_numerics::fastmath` is
//! written for that).

use crate::vec3::{V3, add, axpy, cross, dot, scale, sub};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_numerics::avx2::LoopCopy;
use rolldyn_numerics::fastmath;

/// Vector width the slice arrays are padded to: the widest loop copy's (AVX-512F: eight `f64`).
pub(crate) const LANES: usize = LoopCopy::MAX_LANES;

/// Per-slice constants of one raceway, padded to a multiple of [`LANES`]. Padding slots never
/// touch (their drop is +∞) and carry no stiffness, damping or length.
#[derive(Debug, Clone)]
pub(crate) struct SliceConstants {
    /// slice centre along the roller axis from the roller centre, m
    pub x: Vec<f64>,
    /// roller profile drop at the slice centre, m
    pub drop: Vec<f64>,
    /// `k_s` of the slice law `Q = k_s δⁿ`, N/mⁿ
    pub k: Vec<f64>,
    /// full damping `C_max` of the slice, N·s/m
    pub c_max: Vec<f64>,
    /// approach `δ*` at which the damping reaches `C_max`, m
    pub delta_star: Vec<f64>,
    /// slice length, m
    pub len: Vec<f64>,
    /// raceway drop of a straight raceway (all zero)
    pub zero: Vec<f64>,
}

impl SliceConstants {
    /// Constants of the slices at `x` with roller drops `drop`, lengths `len`, slice-law
    /// coefficients `k` and damping ramps `damping` (viscous `C(δ)·δ̇`, as
    /// [`SliceDamping::new`] builds them).
    pub fn new(x: &[f64], drop: &[f64], len: &[f64], k: &[f64], damping: &[SliceDamping]) -> Self {
        let padded = x.len().div_ceil(LANES) * LANES;
        let pad = |v: &[f64], fill: f64| {
            let mut out = v.to_vec();
            out.resize(padded, fill);
            out
        };
        let c_max: Vec<f64> = damping.iter().map(|d| d.c_max).collect();
        let delta_star: Vec<f64> = damping.iter().map(|d| d.delta_star).collect();
        debug_assert!(damping.iter().all(|d| d.uses_velocity));
        Self {
            x: pad(x, 0.0),
            drop: pad(drop, f64::INFINITY),
            k: pad(k, 0.0),
            c_max: pad(&c_max, 0.0),
            delta_star: pad(&delta_star, 1.0),
            len: pad(len, 0.0),
            zero: vec![0.0; padded],
        }
    }
}

/// Kinematics shared by all slices of one roller–raceway pair.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PairKinematics {
    /// roller centre, axis (unit), velocity, angular velocity and orbital speed θ̇
    pub c: V3,
    pub a: V3,
    pub v: V3,
    pub w: V3,
    pub orbit: f64,
    /// ring centre, velocity, axis (unit) and spin
    pub ring_o: V3,
    pub ring_v: V3,
    pub ring_axis: V3,
    pub ring_spin: f64,
    /// raceway radius and roller radius, m
    pub raceway_radius: f64,
    pub rw: f64,
    /// offset of the roller centre from the ring axis (perpendicular to it) and the roller
    /// axis's component perpendicular to the ring axis: slice offset `dp_c + x a_perp`
    pub dp_c: V3,
    pub a_perp: V3,
    /// `ρ(x)² = qa + 2 qb x + qc x²`
    pub qa: f64,
    pub qb: f64,
    pub qc: f64,
    /// slice-law exponent n
    pub exponent: f64,
}

/// Per-slot results of [`evaluate`] (struct of arrays, one slot per padded slice).
#[derive(Debug, Clone, Default)]
pub(crate) struct SliceOutputs {
    /// approach δ, m (≤ 0: no contact)
    pub delta: Vec<f64>,
    /// normal force Q, N (0 where the slice does not press)
    pub q: Vec<f64>,
    /// normal force on the roller `Q n`, N
    pub force: [Vec<f64>; 3],
    /// its moment about the roller centre, N·m
    pub moment: [Vec<f64>; 3],
    /// contact point relative to the roller centre, m
    pub r_cp: [Vec<f64>; 3],
    /// tangential relative velocity (roller − ring), m/s
    pub vt: [Vec<f64>; 3],
    /// its magnitude, m/s
    pub vs: Vec<f64>,
    /// entrainment speed in the roller's orbital frame, m/s
    pub u: Vec<f64>,
    /// slice length of the compacted slots ([`SliceOutputs::compact`]), m
    pub len: Vec<f64>,
}

impl SliceOutputs {
    /// Outputs for `slots` padded slices.
    pub fn new(slots: usize) -> Self {
        let v = || vec![0.0; slots];
        Self {
            delta: v(),
            q: v(),
            force: [v(), v(), v()],
            moment: [v(), v(), v()],
            r_cp: [v(), v(), v()],
            vt: [v(), v(), v()],
            vs: v(),
            u: v(),
            len: v(),
        }
    }

    /// Pass 1 over the first `n` slots (the slices, in slot order): sums the normal forces and
    /// moments of the loaded slots and moves their traction inputs (q, u, vs, r_cp, vt, and
    /// the slice length from `lens`) to the front, in slot order; notes the first approach
    /// above `limit` (divergence check).
    pub fn collect_loaded(&mut self, n: usize, lens: &[f64], limit: f64) -> LoadedSlots {
        // every column cut to n: the loop has no bounds checks but the one on the
        // destination slot, which is the same for all columns
        let Self {
            delta,
            q,
            force: [fx, fy, fz],
            moment: [mx, my, mz],
            r_cp: [rx, ry, rz],
            vt: [tx, ty, tz],
            vs,
            u,
            len,
        } = self;
        let (delta, lens) = (&delta[..n], &lens[..n]);
        let (q, vs, u, len) = (&mut q[..n], &mut vs[..n], &mut u[..n], &mut len[..n]);
        let (fx, fy, fz) = (&fx[..n], &fy[..n], &fz[..n]);
        let (mx, my, mz) = (&mx[..n], &my[..n], &mz[..n]);
        let (rx, ry, rz) = (&mut rx[..n], &mut ry[..n], &mut rz[..n]);
        let (tx, ty, tz) = (&mut tx[..n], &mut ty[..n], &mut tz[..n]);
        let mut sums = LoadedSlots::default();
        for s in 0..n {
            if delta[s] > limit && sums.violation.is_none() {
                sums.violation = Some(delta[s]);
            }
            let qs = q[s];
            if qs <= 0.0 {
                continue;
            }
            sums.force = add(sums.force, [fx[s], fy[s], fz[s]]);
            sums.moment = add(sums.moment, [mx[s], my[s], mz[s]]);
            sums.load += qs;
            sums.length += lens[s];
            sums.entrainment += qs * u[s];
            let to = sums.count;
            q[to] = qs;
            u[to] = u[s];
            vs[to] = vs[s];
            len[to] = lens[s];
            rx[to] = rx[s];
            ry[to] = ry[s];
            rz[to] = rz[s];
            tx[to] = tx[s];
            ty[to] = ty[s];
            tz[to] = tz[s];
            sums.count += 1;
        }
        sums
    }
}

/// Result of [`SliceOutputs::collect_loaded`].
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LoadedSlots {
    /// sum of the normal forces on the roller and of their moments about its centre
    pub force: V3,
    pub moment: V3,
    /// total normal force, N; loaded length, m; Σ Q u (load-weighted entrainment × load)
    pub load: f64,
    pub length: f64,
    pub entrainment: f64,
    /// number of loaded slots (now at the front of the arrays)
    pub count: usize,
    /// first approach above the divergence limit, m
    pub violation: Option<f64>,
}

/// Evaluates every slot of `sc` for the pair `k` (inner raceway when `INNER`); `race_drop` is
/// the raceway drop under each slot (`sc.zero` for a straight raceway).
pub(crate) fn evaluate<const INNER: bool>(
    sc: &SliceConstants,
    k: &PairKinematics,
    race_drop: &[f64],
    out: &mut SliceOutputs,
) {
    evaluate_with::<INNER>(sc, k, race_drop, out, LoopCopy::detect());
}

/// [`evaluate`] with the compiled copy of the loops chosen by the caller (only one that the CPU
/// supports: [`LoopCopy::detect`] or narrower).
///
/// First the approach of every slot ([`approaches`], cheap); the full slot loop then runs only
/// over the whole vectors (groups of [`LoopCopy::lanes`] slots) from the first to the last touching
/// slot: a roller that is lightly loaded or tilted touches with a few slices only. The other
/// slots get `q = 0`; their remaining outputs are not written.
fn evaluate_with<const INNER: bool>(
    sc: &SliceConstants,
    k: &PairKinematics,
    race_drop: &[f64],
    out: &mut SliceOutputs,
    copy: LoopCopy,
) {
    let n = sc.x.len();
    macro_rules! approach {
        ($loop:ident) => {
            $loop::<INNER>(k, &sc.x, &sc.drop, race_drop, &mut out.delta)
        };
    }
    match copy {
        // SAFETY: `copy` names only copies the CPU supports ([`evaluate`], the tests below).
        #[cfg(target_arch = "x86_64")]
        LoopCopy::Avx512 => unsafe { approach!(approaches_avx512) },
        #[cfg(target_arch = "x86_64")]
        LoopCopy::Avx2 => unsafe { approach!(approaches_avx2) },
        _ => approach!(approaches),
    }
    let delta = &out.delta[..n];
    let Some(first) = delta.iter().position(|&d| d > 0.0) else {
        out.q[..n].fill(0.0);
        return;
    };
    let last = delta.iter().rposition(|&d| d > 0.0).unwrap_or(first);
    // the whole vectors from the first to the last touching slot
    let lanes = copy.lanes();
    let r = first / lanes * lanes..(last + 1).div_ceil(lanes) * lanes;
    out.q[..r.start].fill(0.0);
    out.q[r.end..n].fill(0.0);
    let [fx, fy, fz] = &mut out.force;
    let [mx, my, mz] = &mut out.moment;
    let [rx, ry, rz] = &mut out.r_cp;
    let [tx, ty, tz] = &mut out.vt;
    // Every array is a separate reference argument of the kernel, so the compiler knows that
    // they do not overlap and vectorises the loop without run-time overlap checks.
    macro_rules! call {
        ($kernel:ident) => {
            $kernel::<INNER>(
                k,
                &sc.x[r.clone()],
                &sc.drop[r.clone()],
                &sc.k[r.clone()],
                &sc.c_max[r.clone()],
                &sc.delta_star[r.clone()],
                &race_drop[r.clone()],
                &mut out.delta[r.clone()],
                &mut out.q[r.clone()],
                &mut fx[r.clone()],
                &mut fy[r.clone()],
                &mut fz[r.clone()],
                &mut mx[r.clone()],
                &mut my[r.clone()],
                &mut mz[r.clone()],
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
        // SAFETY: as above.
        #[cfg(target_arch = "x86_64")]
        LoopCopy::Avx512 => unsafe { call!(slots_avx512) },
        #[cfg(target_arch = "x86_64")]
        LoopCopy::Avx2 => unsafe { call!(slots_avx2) },
        _ => call!(slots),
    }
}

/// Distance `ρ` of the slice centre at `xs` from the ring axis and the approach `δ` of the
/// slice (seed 000 (2.5): `R_i + R_w − ρ − z_s − z_race` inner, `ρ + R_w − R_o − z_s − z_race`
/// outer), from `ρ(x)² = A + 2Bx + Cx²`.
#[inline(always)]
fn slot_approach<const INNER: bool>(
    k: &PairKinematics,
    xs: f64,
    drop: f64,
    race_drop: f64,
) -> (f64, f64) {
    let rho = (k.qa + xs * (2.0 * k.qb + xs * k.qc)).max(0.0).sqrt();
    let delta = if INNER {
        k.raceway_radius + k.rw - rho
    } else {
        rho + k.rw - k.raceway_radius
    } - drop
        - race_drop;
    (rho, delta)
}

rolldyn_numerics::avx2_twin! {
    /// The approach of every slot ([`slot_approach`]) into `delta_out`.
    fn approaches<const INNER: bool>(
        k: &PairKinematics,
        x: &[f64],
        drop: &[f64],
        race_drop: &[f64],
        delta_out: &mut [f64],
    ) / approaches_avx2 / approaches_avx512 {
        let n = x.len();
        let (drop, race_drop, delta_out) = (&drop[..n], &race_drop[..n], &mut delta_out[..n]);
        for s in 0..n {
            delta_out[s] = slot_approach::<INNER>(k, x[s], drop[s], race_drop[s]).1;
        }
    }
}

rolldyn_numerics::avx2_twin! {
    /// The loop over the slots. Per slot (SPEC §2.1–2.2): slice centre `p = c + x a`, distance
    /// from the ring axis `ρ`, approach `δ = R_i + R_w − ρ − z_s − z_race` (inner) or
    /// `ρ + R_w − R_o − z_s − z_race` (outer), `Q = max(0, k_s δⁿ + STEP(δ, 0, 0, δ*, C_max) δ̇)`
    /// for `δ > 0` (seed 000 (2.5)–(2.8)), contact point `p − R_w n`, relative velocity of roller
    /// and ring there, its tangential part and the orbital-frame entrainment speed (SPEC §3.5).
    fn slots<const INNER: bool>(
        k: &PairKinematics,
        x: &[f64],
        drop: &[f64],
        stiff: &[f64],
        c_max: &[f64],
        delta_star: &[f64],
        race_drop: &[f64],
        delta_out: &mut [f64],
        q_out: &mut [f64],
        fx: &mut [f64],
        fy: &mut [f64],
        fz: &mut [f64],
        mx: &mut [f64],
        my: &mut [f64],
        mz: &mut [f64],
        rx: &mut [f64],
        ry: &mut [f64],
        rz: &mut [f64],
        tx: &mut [f64],
        ty: &mut [f64],
        tz: &mut [f64],
        vs_out: &mut [f64],
        u_out: &mut [f64],
    ) / slots_avx2 / slots_avx512 {
        // equal lengths, known to the compiler: no bounds checks in the loop
        let n_slots = x.len();
        let (drop, stiff, c_max, delta_star, race_drop) = (
            &drop[..n_slots],
            &stiff[..n_slots],
            &c_max[..n_slots],
            &delta_star[..n_slots],
            &race_drop[..n_slots],
        );
        let (delta_out, q_out, vs_out, u_out) = (
            &mut delta_out[..n_slots],
            &mut q_out[..n_slots],
            &mut vs_out[..n_slots],
            &mut u_out[..n_slots],
        );
        let (fx, fy, fz) = (&mut fx[..n_slots], &mut fy[..n_slots], &mut fz[..n_slots]);
        let (mx, my, mz) = (&mut mx[..n_slots], &mut my[..n_slots], &mut mz[..n_slots]);
        let (rx, ry, rz) = (&mut rx[..n_slots], &mut ry[..n_slots], &mut rz[..n_slots]);
        let (tx, ty, tz) = (&mut tx[..n_slots], &mut ty[..n_slots], &mut tz[..n_slots]);
        let ring_spin_axis = scale(k.ring_axis, k.ring_spin);
        for s in 0..n_slots {
            let xs = x[s];
            let (rho, delta) = slot_approach::<INNER>(k, xs, drop[s], race_drop[s]);
            let inv_rho = if rho > 0.0 { 1.0 / rho } else { 0.0 };
            let touching = delta > 0.0 && rho > 0.0;
            // outward unit normal of the ring axis through the slice centre; n points from the
            // ring into the roller
            let n_out = scale(axpy(k.dp_c, xs, k.a_perp), inv_rho);
            let n = if INNER { n_out } else { scale(n_out, -1.0) };
            let r_cp = axpy(scale(k.a, xs), -k.rw, n);
            let cp = add(k.c, r_cp);
            let v_roll = add(k.v, cross(k.w, r_cp));
            let v_ring = add(k.ring_v, cross(ring_spin_axis, sub(cp, k.ring_o)));
            let vrel = sub(v_roll, v_ring);
            let v_normal = dot(vrel, n);
            let delta_dot = -v_normal;
            // slice law k_s δⁿ (exp(n ln δ)); the damping ramp STEP(δ, 0, 0, δ*, C_max) of
            // rolldyn_contact::damping with Δ = δ/δ* clamped to [0, 1]
            let elastic = if touching {
                stiff[s] * fastmath::exp(k.exponent * fastmath::ln(delta))
            } else {
                0.0
            };
            let ramp = (delta / delta_star[s]).clamp(0.0, 1.0);
            let damping = c_max[s] * ramp * ramp * (3.0 - 2.0 * ramp);
            let pressing = elastic + damping * delta_dot;
            let q = if touching && pressing > 0.0 {
                pressing
            } else {
                0.0
            };
            let normal = scale(n, q);
            let moment = cross(r_cp, normal);
            let vt = axpy(vrel, -v_normal, n);
            // rolling direction and entrainment speed in the roller's orbital frame (SPEC §3.5)
            let t_dir = cross(k.ring_axis, n_out);
            let w_frame = [-k.orbit * cp[1], k.orbit * cp[0], 0.0];
            let u = 0.5 * (dot(v_roll, t_dir) + dot(v_ring, t_dir)) - dot(w_frame, t_dir);
            delta_out[s] = delta;
            q_out[s] = q;
            fx[s] = normal[0];
            fy[s] = normal[1];
            fz[s] = normal[2];
            mx[s] = moment[0];
            my[s] = moment[1];
            mz[s] = moment[2];
            rx[s] = r_cp[0];
            ry[s] = r_cp[1];
            rz[s] = r_cp[2];
            tx[s] = vt[0];
            ty[s] = vt[1];
            tz[s] = vt[2];
            vs_out[s] = dot(vt, vt).sqrt();
            u_out[s] = u;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vec3::{norm, perp};

    fn constants() -> SliceConstants {
        let x: Vec<f64> = (0..10).map(|s| -4.5e-3 + 1e-3 * s as f64).collect();
        let drop: Vec<f64> = x.iter().map(|x| 2e-6 * (x / 5e-3).powi(4)).collect();
        let len = vec![1e-3; 10];
        let k = vec![6e8; 10];
        let damping = vec![SliceDamping::new(30.0, 1e-6); 10];
        SliceConstants::new(&x, &drop, &len, &k, &damping)
    }

    fn pair(inner: bool) -> PairKinematics {
        // roller centre at the pitch radius, slightly tilted; ring axis z through the origin
        let c = [0.0, 0.0862, 1e-5];
        let a = [1.5e-3, -2e-3, 1.0];
        let na = norm(a);
        let a = scale(a, 1.0 / na);
        let ring_axis = [0.0, 0.0, 1.0];
        let a_ax = dot(a, ring_axis);
        let dp_c = [c[0], c[1], 0.0];
        let a_perp = axpy(a, -a_ax, ring_axis);
        PairKinematics {
            c,
            a,
            v: [-25.0, 0.01, 0.0],
            w: [3.0, -2.0, -2900.0],
            orbit: 290.0,
            ring_o: [0.0; 3],
            ring_v: [0.0; 3],
            ring_axis,
            ring_spin: if inner { 667.0 } else { 0.0 },
            raceway_radius: if inner { 0.0762 - 4e-6 } else { 0.0962 + 3e-6 },
            rw: 0.01,
            dp_c,
            a_perp,
            qa: dot(dp_c, dp_c),
            qb: dot(dp_c, a_perp),
            qc: dot(a_perp, a_perp),
            exponent: 10.0 / 9.0,
        }
    }

    /// Slice by slice with the library's own functions (`powf`, `SliceDamping`, `perp`).
    fn reference(sc: &SliceConstants, k: &PairKinematics, inner: bool, s: usize) -> (f64, V3, f64) {
        let x = sc.x[s];
        let p = axpy(k.c, x, k.a);
        let off = axpy(k.dp_c, x, k.a_perp);
        let rho = norm(off);
        let delta = if inner {
            k.raceway_radius + k.rw - rho
        } else {
            rho + k.rw - k.raceway_radius
        } - sc.drop[s];
        let n_out = scale(off, 1.0 / rho);
        let n = if inner { n_out } else { scale(n_out, -1.0) };
        let cp = axpy(p, -k.rw, n);
        let v_roll = add(k.v, cross(k.w, sub(cp, k.c)));
        let v_ring = add(
            k.ring_v,
            scale(cross(k.ring_axis, sub(cp, k.ring_o)), k.ring_spin),
        );
        let vrel = sub(v_roll, v_ring);
        let damping = SliceDamping::new(sc.c_max[s], sc.delta_star[s]);
        let q = if delta > 0.0 {
            damping.normal_force(sc.k[s] * delta.powf(k.exponent), delta, -dot(vrel, n))
        } else {
            0.0
        };
        (q, perp(vrel, n), delta)
    }

    #[test]
    fn kernel_matches_slice_by_slice_evaluation() {
        let sc = constants();
        for inner in [true, false] {
            let k = pair(inner);
            let mut out = SliceOutputs::new(sc.x.len());
            if inner {
                evaluate::<true>(&sc, &k, &sc.zero, &mut out);
            } else {
                evaluate::<false>(&sc, &k, &sc.zero, &mut out);
            }
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
                    let got = [out.vt[0][s], out.vt[1][s], out.vt[2][s]];
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

    /// The AVX2 and AVX-512F copies (those this CPU supports) and the portable loop give the
    /// same bits.
    #[test]
    fn vector_and_portable_loops_agree() {
        let sc = constants();
        // every approach and force; the other outputs of the loaded slots (the loop leaves
        // those of slots outside its vectors unwritten, and the copies' vectors differ in width)
        let bits = |o: &SliceOutputs| {
            let mut all = vec![&o.vs, &o.u];
            all.extend(o.force.iter().chain(&o.moment).chain(&o.r_cp).chain(&o.vt));
            let loaded = (0..o.q.len()).filter(|&s| o.q[s] > 0.0);
            let mut bits: Vec<u64> = o.delta.iter().chain(&o.q).map(|x| x.to_bits()).collect();
            bits.extend(loaded.flat_map(|s| all.iter().map(move |v| v[s].to_bits())));
            bits
        };
        for copy in [LoopCopy::Avx2, LoopCopy::Avx512] {
            if copy > LoopCopy::detect() {
                continue;
            }
            for inner in [true, false] {
                let k = pair(inner);
                let run = |copy| {
                    let mut out = SliceOutputs::new(sc.x.len());
                    if inner {
                        evaluate_with::<true>(&sc, &k, &sc.zero, &mut out, copy);
                    } else {
                        evaluate_with::<false>(&sc, &k, &sc.zero, &mut out, copy);
                    }
                    bits(&out)
                };
                assert_eq!(
                    run(copy),
                    run(LoopCopy::Portable),
                    "{copy:?}, inner {inner}"
                );
            }
        }
    }
}
