//! Frictionless load distribution among the rollers (SPEC §5.4 "F_в(i), F_н(i) from the
//! standard static load distribution", ⚠ F-43 proposal) with the slice model of
//! `rolldyn_contact::slices` (SPEC §2.1).
//!
//! Unknowns: the radial displacement (δx, δy) of the inner ring relative to the outer ring
//! (the ring tilt θ is imposed: misalignment) and, per roller j at angle ψ_j from the load,
//! its radial position u_j and tilt β_j between the raceways. With the diametral operating
//! clearance G and e_j = δy cos ψ_j + δx sin ψ_j − G/2, the slice approaches are
//!
//! * outer raceway: δ_s = u_j + x_s tan β_j − z_s;
//! * inner raceway: δ_s = (e_j − u_j) + x_s tan(θ_j − β_j) − z_s, θ_j = θ cos(ψ_j − ψ_θ).
//!
//! Roller equilibrium (seed 001: F_н = F_в + F_c, friction neglected):
//! `Q_o − Q_i − F_c = 0` and `M_o − M_i = 0` (moments of the slice forces about the roller
//! centre); ring equilibrium: `Σ Q_i,j (sin ψ_j, cos ψ_j) = (0, F_r)`. Both levels are solved
//! by Newton's method with the analytic slice Jacobians (bracketed bisection / backtracking
//! safeguards), to the tolerance [`crate::QuasiStaticOptions::load_tolerance`].
//!
//! Rollers whose inner raceway does not touch carry only the centrifugal force on the outer
//! ring (the unloaded zone, SPEC §5.4).
//!
//! Unloaded rollers without centrifugal force (F_c = 0) have no determined position: every
//! (u_j, β_j) at which neither raceway is pressed is an equilibrium. Such a roller is detected
//! geometrically (a tilt at which the roller fits between the raceways, see
//! `RollerContext::free_position`) and returned without iterating, by convention lying on
//! the outer raceway (u_j = first touch) and aligned with the outer ring (β_j = 0, the
//! F_c → 0⁺ limit) when it fits so, otherwise at the tilt with the largest free play (the tilt
//! at which it is first pinched when the interference grows, so that β_j is continuous at the
//! edge of the load zone).
//!
//! Convergence of a roller balance: `max(|Q_o − Q_i − F_c|, |M_o − M_i|/l_s) ≤ tol · S` with
//! `S = max(Q_o + Q_i + F_c, F_r/Z, S_ε)`. The floor F_r/Z (the mean roller share of the
//! applied load) keeps the absolute accuracy of a barely loaded roller at the level the ring
//! balance needs (its tolerance is `tol·(F_r + ΣQ_i)`), instead of demanding `tol` relative to
//! a load of 1e-17 N; `S_ε = 16ε·(P_o·(k_o + k_i) + P_i·k_i)/tol` is the rounding floor of the
//! residual itself (ε machine epsilon, P_o = |u_j| + l_s|tan β_j| and P_i = |e_j − u_j| +
//! l_s|tan(θ_j − β_j)| the magnitudes of the terms of the outer and inner slice approaches, k
//! the contact stiffnesses): the forces cannot be evaluated more accurately than a few ulps of
//! their approaches, and the rounding of the roller position moves both forces. (The rounding
//! of the inner terms does not multiply the outer stiffness: a roller far on the unloaded side
//! pinched only by the ring tilt has P_i ≫ P_o.)
//!
//! Safeguards with centrifugal force at light loads (F_c > 0, low speed). Two failures of the
//! Newton iterations are met, and both levels then fall back to nested bracketed 1-D solves
//! (cases the Newton iterations solve are not affected):
//!
//! * a roller step leaves the outer raceway: where neither raceway touches, the residual is
//!   (−F_c, 0) with a zero Jacobian. Fallback (`RollerContext::solve_nested`): for a tilt β the
//!   radial balance is non-decreasing in u and bracketed between the first touch of the outer
//!   raceway (Q_o = 0) and the approach at which the outer raceway carries F_c + Q_i; the
//!   moment balance along that u(β) is non-decreasing in β (the roller balance is the gradient
//!   of the convex elastic energy minus F_c·u) and bracketed between tilts beyond those of
//!   both raceways. Safeguarded Newton steps (Schur-complement slope) with bisection.
//! * with the discrete slices, a pinched roller loaded on one slice of each raceway (x_o,
//!   x_i) has Q_i = F_c·x_o/(x_i − x_o) fixed by statics, independent of e_j: Q_i(e_j) has
//!   plateaus of zero stiffness joined by steep ramps, and ring Newton steps jump between the
//!   plateaus on either side of the solution. Fallback (`nested_ring`): δy from the y balance
//!   at fixed δx, δx from the x balance along δy(δx), both non-decreasing (gradient of the
//!   convex reduced energy), by the same bracketed safeguarded Newton steps.

use crate::error::QsError;
use crate::options::QuasiStaticOptions;
use rolldyn_contact::roller_raceway::{RollerRacewayContact, SliceLawChoice};
use rolldyn_contact::slices::{SliceLoad, SlicedRoller, SolveOptions};
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use rolldyn_numerics::maximize1d::{GoldenSectionOptions, golden_section_max};
use rolldyn_numerics::{
    Bracket, Damping, Derivative, Newton2dOptions, Newton2dOutcome, Newton2dStatus, Point,
    Root1dOptions, Root1dStatus, Sample, find_root, solve_2d,
};
use serde::Serialize;
use std::convert::Infallible;

/// Slice models of the two raceway contacts of one roller (all rollers are identical).
#[derive(Debug, Clone)]
pub struct LoadModel {
    inner: SlicedRoller,
    outer: SlicedRoller,
    /// Contact data (R', E') of the inner raceway contact.
    pub inner_contact: RollerRacewayContact,
    /// Contact data (R', E') of the outer raceway contact.
    pub outer_contact: RollerRacewayContact,
    symmetric: bool,
    roller_count: usize,
    half_span: f64,
}

/// The load case of one distribution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadCase {
    /// Radial load on the inner ring F_r, N (along +y).
    pub radial_load_n: f64,
    /// Diametral operating clearance G, m (negative = preload).
    pub diametral_clearance_m: f64,
    /// Tilt of the inner ring relative to the outer ring θ, rad.
    pub misalignment_rad: f64,
    /// Azimuth ψ_θ of the tilt plane from the load direction, rad.
    pub misalignment_azimuth_rad: f64,
    /// Centrifugal force of each roller F_c, N (pressing it on the outer raceway).
    pub centrifugal_force_n: f64,
    /// Angle of roller 0 from the load direction, rad.
    pub roller_phase_rad: f64,
}

/// Loads of one roller.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollerLoad {
    /// Angle ψ_j from the load direction, rad.
    pub azimuth_rad: f64,
    /// Inner-raceway normal load F_в, N.
    pub inner_force_n: f64,
    /// Outer-raceway normal load F_н, N.
    pub outer_force_n: f64,
    /// Centrifugal force F_c, N.
    pub centrifugal_force_n: f64,
    /// Radial interference e_j = δ·e_r(ψ_j) − G/2 available to the roller, m.
    pub interference_m: f64,
    /// Approach of the inner contact at the roller centre section, m.
    pub inner_approach_m: f64,
    /// Approach of the outer contact at the roller centre section, m.
    pub outer_approach_m: f64,
    /// Roller tilt β_j between the raceways, rad.
    pub roller_tilt_rad: f64,
    /// Local ring tilt θ_j, rad.
    pub ring_tilt_rad: f64,
    /// Moment of the inner slice forces about the roller centre, N·m.
    pub inner_moment_n_m: f64,
    /// Effective line-contact length of the inner contact Q/max(Q_s/L_s), m (the length that
    /// gives the Hertz pressure of the most loaded slice).
    pub inner_effective_length_m: f64,
    /// Same for the outer contact, m.
    pub outer_effective_length_m: f64,
    /// Inner contact loaded (Q_i > 0).
    pub loaded: bool,
    /// dQ_i/de_j (series stiffness), N/m.
    #[serde(skip)]
    pub stiffness_n_m: f64,
}

/// Result of a load distribution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadDistribution {
    /// Per roller, in the order of the roller index.
    pub rollers: Vec<RollerLoad>,
    /// Displacement (δx, δy) of the inner ring relative to the outer ring, m.
    pub ring_displacement_m: [f64; 2],
    /// Force residual (ΣQ_i sin ψ, ΣQ_i cos ψ − F_r), N.
    pub force_residual_n: [f64; 2],
    /// Largest roller radial-balance residual |Q_o − Q_i − F_c|, N.
    pub roller_residual_n: f64,
    /// Moment the rollers exert on the inner ring about the tilt axis, N·m.
    pub ring_moment_n_m: f64,
    /// Ring Newton iterations.
    pub iterations: usize,
    /// Largest inner-raceway load, N.
    pub max_inner_load_n: f64,
    /// Largest outer-raceway load, N.
    pub max_outer_load_n: f64,
    /// Rollers with Q_i > 0.
    pub loaded_rollers: usize,
    /// Half angle of the load zone from the clearance and displacement, acos(G/(2δ)) (π if
    /// every roller is loaded), rad.
    pub load_zone_half_angle_rad: f64,
}

fn slice_opts(tol: f64) -> SolveOptions {
    SolveOptions {
        tolerance: tol,
        max_iterations: 200,
    }
}

impl LoadModel {
    /// Slice models of `bearing`'s roller on its inner and outer raceways.
    pub fn new(bearing: &CylindricalRollerBearing, law: SliceLawChoice) -> Result<Self, QsError> {
        let model = BearingModel::Cylindrical(bearing.clone());
        let ci = RollerRacewayContact::from_model(&model, true, 0.0)
            .map_err(|e| QsError::Contact(e.to_string()))?;
        let co = RollerRacewayContact::from_model(&model, false, 0.0)
            .map_err(|e| QsError::Contact(e.to_string()))?;
        let stack = bearing.roller.slices();
        let build = |c: &RollerRacewayContact, ring: &rolldyn_geometry::Ring| {
            let drops: Vec<f64> = stack
                .position
                .iter()
                .map(|&x| bearing.roller.profile.drop(x) + ring.raceway_drop(x))
                .collect();
            SlicedRoller::new(
                c.slice_law(law),
                stack.position.clone(),
                stack.length.clone(),
                drops,
            )
            .map_err(|e| QsError::Contact(e.to_string()))
        };
        let inner = build(&ci, &bearing.inner_ring)?;
        let outer = build(&co, &bearing.outer_ring)?;
        let sym = |r: &SlicedRoller| {
            let (x, z) = (r.positions(), r.drops());
            let n = x.len();
            (0..n).all(|k| {
                let m = n - 1 - k;
                (x[k] + x[m]).abs() <= 1e-12 * x[k].abs().max(1e-9)
                    && (z[k] - z[m]).abs() <= 1e-15 + 1e-12 * z[k].abs()
            })
        };
        let symmetric = sym(&inner) && sym(&outer);
        let half_span = stack
            .position
            .iter()
            .fold(0.0_f64, |a, &x| a.max(x.abs()))
            .max(1e-6);
        Ok(Self {
            inner,
            outer,
            inner_contact: ci,
            outer_contact: co,
            symmetric,
            roller_count: bearing.roller_count,
            half_span,
        })
    }

    /// Slice model of the inner contact.
    pub fn inner_slices(&self) -> &SlicedRoller {
        &self.inner
    }

    /// Slice model of the outer contact.
    pub fn outer_slices(&self) -> &SlicedRoller {
        &self.outer
    }

    /// Slice forces of `roller` (a roller of a solved distribution) on the inner and the outer
    /// raceway [N], in the order of the slices: the slice approaches of the module docs at its
    /// approaches and tilts (inner tilt θ_j − β_j, outer β_j).
    pub fn slice_loads(&self, roller: &RollerLoad) -> [Vec<f64>; 2] {
        let mut inner = vec![0.0; self.inner.len()];
        let mut outer = vec![0.0; self.outer.len()];
        self.inner.evaluate(
            roller.inner_approach_m,
            roller.ring_tilt_rad - roller.roller_tilt_rad,
            &mut inner,
        );
        self.outer
            .evaluate(roller.outer_approach_m, roller.roller_tilt_rad, &mut outer);
        [inner, outer]
    }

    /// Outer-contact approach carrying `force` at zero tilt.
    fn outer_approach(&self, force: f64, tol: f64) -> Result<f64, QsError> {
        self.outer
            .solve_approach(force, 0.0, &slice_opts(tol))
            .map(|s| s.approach)
            .map_err(|e| QsError::Contact(e.to_string()))
    }

    /// Radial interference e at which one untilted roller carries `q` on the inner raceway.
    fn interference_for_load(&self, q: f64, fc: f64, tol: f64) -> Result<f64, QsError> {
        let ai = self
            .inner
            .solve_approach(q, 0.0, &slice_opts(tol))
            .map_err(|e| QsError::Contact(e.to_string()))?
            .approach;
        Ok(ai + self.outer_approach(q + fc, tol)?)
    }

    /// Solves the load distribution (see module docs); `warm` is a previous solution used as
    /// the starting point (same roller count).
    pub fn solve(
        &self,
        case: &LoadCase,
        warm: Option<&LoadDistribution>,
        opts: &QuasiStaticOptions,
    ) -> Result<LoadDistribution, QsError> {
        let fr = case.radial_load_n;
        if !(fr.is_finite() && fr >= 0.0) {
            return Err(QsError::InvalidInput(format!(
                "radial load must be finite and ≥ 0, got {fr} N"
            )));
        }
        let fc = case.centrifugal_force_n.max(0.0);
        let tol = opts.load_tolerance.max(1e-15);
        let z = self.roller_count;
        let angles: Vec<f64> = (0..z)
            .map(|j| case.roller_phase_rad + 2.0 * std::f64::consts::PI * j as f64 / z as f64)
            .collect();
        let u_c = self.outer_approach(fc, tol * 0.1)?;
        let ctx = RollerContext {
            model: self,
            fc,
            u_c,
            tol: tol * 0.1,
            // mean roller share of the applied load (module docs); the absolute floor only
            // matters without radial load
            force_floor: (fr / z.max(1) as f64).max(1e-12),
        };
        let tilt_of =
            |psi: f64| case.misalignment_rad * (psi - case.misalignment_azimuth_rad).cos();
        let half_g = 0.5 * case.diametral_clearance_m;

        let (delta, states) = self.start_point(case, warm, &angles, tol)?;

        // nothing loaded: the fallback step moves the ring towards the load by the clearance
        let dead_zone_step = case.diametral_clearance_m.abs().max(1e-6);
        // residual (ΣQ_i sin ψ, ΣQ_i cos ψ − F_r) and Jacobian at `delta`; `warm` holds the
        // roller solutions at the current displacement (starting points of the roller solves)
        let eval = |delta: [f64; 2],
                    warm: &Vec<RollerState>|
         -> Result<Sample<Vec<RollerState>>, QsError> {
            let mut states = warm.clone();
            let (mut rx, mut ry, mut jxx, mut jxy, mut jyy, mut sum_q) =
                (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            for j in 0..z {
                let (s, c) = angles[j].sin_cos();
                let e = delta[1] * c + delta[0] * s - half_g;
                let th = tilt_of(angles[j]);
                // reuse a mirror roller's solution when the inputs coincide
                let mut reused = false;
                for k in 0..j {
                    let p = &states[k];
                    if (p.e - e).abs() <= 1e-14 * (e.abs() + 1e-12) && (p.theta - th).abs() <= 1e-15
                    {
                        states[j] = *p;
                        reused = true;
                        break;
                    }
                }
                if !reused {
                    let guess = states[j];
                    states[j] = ctx.solve_roller(e, th, guess)?;
                }
                let st = &states[j];
                rx += st.qi * s;
                ry += st.qi * c;
                jxx += st.k * s * s;
                jxy += st.k * s * c;
                jyy += st.k * c * c;
                sum_q += st.qi.abs();
            }
            ry -= fr;
            let towards_load = if ry < 0.0 {
                dead_zone_step
            } else {
                -dead_zone_step
            };
            Ok(Sample::new(
                [rx, ry],
                [[jxx, jxy], [jxy, jyy]],
                (fr + sum_q).max(1e-9),
                states,
            )
            .with_fallback_step([0.0, towards_load]))
        };
        let ring_newton = Newton2dOptions {
            tolerance: tol,
            stall_tolerance: 0.0,
            max_iterations: opts.max_load_iterations,
            max_halvings: 60,
            sufficient_decrease: 0.0,
            // Levenberg–Marquardt with a floor: a direction without stiffness (e.g. x with a
            // single loaded roller) gets no step unless it has a residual
            damping: Damping::Trace { floor: 1e-300 },
            min_damping: 1e-10,
            restart_damping: 1e-8,
            max_damping: f64::INFINITY,
            singular_tolerance: 0.0,
            ..Newton2dOptions::default()
        };
        let mut ring = solve_2d(&eval, delta, states.clone(), &ring_newton)?;
        if !ring.converged() {
            // plateaus of Q_i(e) (module docs): bracketed nested solve from the start point
            let step = case
                .diametral_clearance_m
                .abs()
                .max(delta[1].abs())
                .max(1e-6)
                * 1e-2;
            if let Some(nested) = nested_ring(&eval, delta, states, step, tol)? {
                ring = nested;
            }
        }
        let (delta, states, r, it) = (ring.x, &ring.state, ring.residual, ring.iterations);
        if !ring.converged() {
            return Err(QsError::not_converged(
                "load distribution",
                it,
                &[
                    ("force x / F_r", r[0] / ring.scale),
                    ("force y / F_r", r[1] / ring.scale),
                ],
            ));
        }

        Ok(self.distribution(case, &angles, states, delta, (r, it)))
    }

    /// Start of the ring iteration: the displacement and roller states of `warm` (same
    /// roller count), else the displacement at which the most loaded roller alone carries
    /// the radial load, rollers untilted.
    fn start_point(
        &self,
        case: &LoadCase,
        warm: Option<&LoadDistribution>,
        angles: &[f64],
        tol: f64,
    ) -> Result<([f64; 2], Vec<RollerState>), QsError> {
        let (fr, z) = (case.radial_load_n, self.roller_count);
        let fc = case.centrifugal_force_n.max(0.0);
        let half_g = 0.5 * case.diametral_clearance_m;
        // initial ring displacement
        let delta = match warm {
            Some(w) if w.rollers.len() == z => w.ring_displacement_m,
            _ => {
                if fr > 0.0 {
                    let c_min = angles
                        .iter()
                        .map(|p| p.cos())
                        .fold(f64::NEG_INFINITY, f64::max)
                        .max(0.1);
                    let e1 = self.interference_for_load(fr / c_min, fc, tol)?;
                    [0.0, (e1 + half_g) / c_min]
                } else {
                    [0.0, 0.0]
                }
            }
        };
        let states: Vec<RollerState> = match warm {
            Some(w) if w.rollers.len() == z => w
                .rollers
                .iter()
                .map(|r| RollerState {
                    u: r.outer_approach_m,
                    beta: r.roller_tilt_rad,
                    ..RollerState::default()
                })
                .collect(),
            _ => vec![RollerState::default(); z],
        };
        Ok((delta, states))
    }

    /// Loads, effective lengths and moments of every roller at the converged ring
    /// displacement `delta` with roller `states`; `(r, it)` are the ring residual and the
    /// iterations.
    fn distribution(
        &self,
        case: &LoadCase,
        angles: &[f64],
        states: &[RollerState],
        delta: [f64; 2],
        (r, it): ([f64; 2], usize),
    ) -> LoadDistribution {
        let z = self.roller_count;
        let fc = case.centrifugal_force_n.max(0.0);
        let half_g = 0.5 * case.diametral_clearance_m;
        let tilt_of =
            |psi: f64| case.misalignment_rad * (psi - case.misalignment_azimuth_rad).cos();
        // final pass: effective lengths, moments, residuals
        let mut fi = vec![0.0; self.inner.len()];
        let mut fo = vec![0.0; self.outer.len()];
        let eff_len = |forces: &[f64], lengths: &[f64], q: f64| {
            let peak = forces
                .iter()
                .zip(lengths)
                .map(|(f, l)| f / l)
                .fold(0.0, f64::max);
            if q > 0.0 && peak > 0.0 { q / peak } else { 0.0 }
        };
        let mut rollers = Vec::with_capacity(z);
        let mut roller_res = 0.0_f64;
        let mut ring_moment = 0.0;
        for j in 0..z {
            let st = &states[j];
            let th = tilt_of(angles[j]);
            let li = self.inner.evaluate(st.e - st.u, th - st.beta, &mut fi);
            let lo = self.outer.evaluate(st.u, st.beta, &mut fo);
            roller_res = roller_res.max((lo.force - li.force - fc).abs());
            ring_moment += li.moment * (angles[j] - case.misalignment_azimuth_rad).cos();
            rollers.push(RollerLoad {
                azimuth_rad: angles[j],
                inner_force_n: li.force,
                outer_force_n: lo.force,
                centrifugal_force_n: fc,
                interference_m: st.e,
                inner_approach_m: st.e - st.u,
                outer_approach_m: st.u,
                roller_tilt_rad: st.beta,
                ring_tilt_rad: th,
                inner_moment_n_m: li.moment,
                inner_effective_length_m: eff_len(&fi, self.inner.lengths(), li.force),
                outer_effective_length_m: eff_len(&fo, self.outer.lengths(), lo.force),
                loaded: li.force > 0.0,
                stiffness_n_m: st.k,
            });
        }
        let max_inner = rollers.iter().map(|r| r.inner_force_n).fold(0.0, f64::max);
        let max_outer = rollers.iter().map(|r| r.outer_force_n).fold(0.0, f64::max);
        let loaded = rollers.iter().filter(|r| r.loaded).count();
        let dmag = delta[0].hypot(delta[1]);
        let zone = if case.diametral_clearance_m <= 0.0 {
            std::f64::consts::PI
        } else if dmag > half_g {
            (half_g / dmag).acos()
        } else {
            0.0
        };
        LoadDistribution {
            rollers,
            ring_displacement_m: delta,
            force_residual_n: [r[0], r[1]],
            roller_residual_n: roller_res,
            ring_moment_n_m: ring_moment,
            iterations: it,
            max_inner_load_n: max_inner,
            max_outer_load_n: max_outer,
            loaded_rollers: loaded,
            load_zone_half_angle_rad: zone,
        }
    }
}

/// Bracketed evaluations of one level of [`nested_ring`].
const NESTED_ITERATIONS: usize = 200;

/// Fallback of the ring Newton iteration (module docs): δy from the y balance at fixed δx,
/// δx from the x balance along δy(δx), both by [`find_root`] (doubling bracket search,
/// analytic slopes; the ring residual is the gradient of a convex energy, so both are
/// non-decreasing). `None` if it does not converge.
fn nested_ring(
    eval: &impl Fn([f64; 2], &Vec<RollerState>) -> Result<Sample<Vec<RollerState>>, QsError>,
    start: [f64; 2],
    states: Vec<RollerState>,
    step: f64,
    tol: f64,
) -> Result<Option<Newton2dOutcome<Vec<RollerState>>>, QsError> {
    let converged = |s: &Sample<Vec<RollerState>>, k: usize| s.residual[k].abs() <= tol * s.scale;
    let options = Root1dOptions {
        bracket: Bracket::Expand { first_step: step },
        derivative: Derivative::Supplied,
        max_evaluations: NESTED_ITERATIONS,
        ..Root1dOptions::default()
    };
    let mut warm = states;
    let mut evals = 0;
    let mut y0 = start[1];
    let mut solve_y = |dx: f64,
                       warm: &mut Vec<RollerState>,
                       evals: &mut usize|
     -> Result<(f64, Sample<Vec<RollerState>>, bool), QsError> {
        let root = find_root(
            |dy| {
                let s = eval([dx, dy], warm)?;
                *warm = s.state.clone();
                let [[_, _], [_, jyy]] = s.jacobian;
                Ok::<_, QsError>(Point::new(s.residual[1], jyy, converged(&s, 1), s))
            },
            y0,
            &options,
        )?;
        *evals += root.evaluations;
        y0 = root.x;
        let ok = root.converged();
        Ok((root.x, root.state, ok))
    };
    let root = find_root(
        |dx| {
            let (dy, s, ok_y) = solve_y(dx, &mut warm, &mut evals)?;
            let [[jxx, jxy], [_, jyy]] = s.jacobian;
            let slope = if jyy > 0.0 {
                jxx - jxy * jxy / jyy
            } else {
                jxx
            };
            let ok = ok_y && converged(&s, 0);
            Ok::<_, QsError>(Point::new(s.residual[0], slope, ok, (dy, s)))
        },
        start[0],
        &options,
    )?;
    if !root.converged() {
        return Ok(None);
    }
    let (dy, sample) = root.state;
    Ok(Some(Newton2dOutcome {
        x: [root.x, dy],
        residual: sample.residual,
        scale: sample.scale,
        iterations: evals,
        status: Newton2dStatus::Converged,
        state: sample.state,
    }))
}

/// Iteration budget of one roller equilibrium (Newton iterations of a tilted roller,
/// evaluations of the radial balance of an untilted one).
const ROLLER_ITERATIONS: usize = 200;

/// Per-roller unknowns and results of one evaluation.
#[derive(Debug, Clone, Copy, Default)]
struct RollerState {
    e: f64,
    theta: f64,
    u: f64,
    beta: f64,
    qi: f64,
    k: f64,
}

/// Factor of the rounding floor of the roller residual (ulps of the approach terms).
const ROUNDOFF_ULPS: f64 = 8.0;

struct RollerContext<'a> {
    model: &'a LoadModel,
    fc: f64,
    u_c: f64,
    tol: f64,
    /// Least force scale of the roller convergence tests, N (module docs).
    force_floor: f64,
}

impl RollerContext<'_> {
    /// Roller equilibrium for interference `e` and local ring tilt `theta`.
    fn solve_roller(&self, e: f64, theta: f64, guess: RollerState) -> Result<RollerState, QsError> {
        if theta == 0.0 && self.model.symmetric {
            self.solve_1d(e, guess)
        } else {
            self.solve_tilted(e, theta, guess)
        }
    }

    fn solve_1d(&self, e: f64, guess: RollerState) -> Result<RollerState, QsError> {
        let m = self.model;
        let fc = self.fc;
        // upper end: the inner contact just touches
        let touch_i = m
            .inner
            .drops()
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        let lo = self.u_c;
        let hi = e - touch_i;
        let base = RollerState {
            e,
            theta: 0.0,
            u: self.u_c,
            beta: 0.0,
            qi: 0.0,
            k: 0.0,
        };
        if hi <= lo {
            return Ok(base);
        }
        let start = if guess.u > lo && guess.u < hi {
            guess.u
        } else {
            hi
        };
        let options = Root1dOptions {
            bracket: Bracket::Given { lo, hi },
            derivative: Derivative::Supplied,
            x_rel_tol: 4.0 * f64::EPSILON,
            halving_test: false,
            max_evaluations: ROLLER_ITERATIONS,
            ..Root1dOptions::default()
        };
        let Ok(root) = find_root(
            |u| {
                let lo_ = m.outer.evaluate_totals(u, 0.0);
                let li = m.inner.evaluate_totals(e - u, 0.0);
                let r = lo_.force - li.force - fc;
                let scale = self.scale(&li, &lo_, u.abs(), (e - u).abs());
                let slope = lo_.dforce_dapproach + li.dforce_dapproach;
                Ok::<_, Infallible>(Point::new(r, slope, r.abs() <= self.tol * scale, (li, lo_)))
            },
            start,
            &options,
        );
        if !matches!(root.status, Root1dStatus::Converged | Root1dStatus::Stalled) {
            return Err(QsError::not_converged(
                "roller radial balance",
                root.evaluations,
                &[("bracket width / m", root.bracket.1 - root.bracket.0)],
            ));
        }
        let (li, lo_) = root.state;
        let k = if li.force > 0.0 {
            let (ki, ko) = (li.dforce_dapproach, lo_.dforce_dapproach);
            ki * ko / (ki + ko)
        } else {
            0.0
        };
        Ok(RollerState {
            u: root.x,
            qi: li.force,
            k,
            ..base
        })
    }

    /// Force scale S of the roller convergence tests (module docs); `reach_o`, `reach_i` are
    /// the magnitudes of the approach and tilt terms of the outer and inner slice approaches
    /// δ_s = a + x_s tan φ − z_s, m. The drops z_s of the loaded slices (δ_s > 0) are below
    /// a + x_s tan φ, so the terms of a loaded slice's approach sum to at most 2·reach. The
    /// rounding of the inner terms only enters the inner force; that of the roller position
    /// (u, β) enters both.
    fn scale(&self, li: &SliceLoad, lo: &SliceLoad, reach_o: f64, reach_i: f64) -> f64 {
        let (ko, ki) = (lo.dforce_dapproach.max(0.0), li.dforce_dapproach.max(0.0));
        let noise = ROUNDOFF_ULPS * f64::EPSILON * 2.0 * (reach_o * (ko + ki) + reach_i * ki);
        (lo.force + li.force + self.fc)
            .max(self.force_floor)
            .max(noise / self.tol)
    }

    /// Free play of a roller between the raceways at tilt `beta` (fixed e, θ): the largest
    /// outer approach without outer contact, `U_o(β) = min_s(z_o,s − x_s tan β)`, and the
    /// play `U_o(β) + U_i(β) − e` (`U_i` likewise with the tilt θ − β); play ≥ 0 means that
    /// the roller fits without pressing either raceway.
    fn play(&self, e: f64, theta: f64, beta: f64) -> (f64, f64) {
        let touch = |r: &SlicedRoller, t: f64| {
            r.positions()
                .iter()
                .zip(r.drops())
                .fold(f64::INFINITY, |a, (&x, &z)| a.min(z - x * t))
        };
        let uo = touch(&self.model.outer, beta.tan());
        let ui = touch(&self.model.inner, (theta - beta).tan());
        (uo, uo + ui - e)
    }

    /// The position (u, β) of a roller without centrifugal force that touches neither raceway
    /// under load — tilt of the largest play, lying on the outer raceway — or `None` when it
    /// is pinched at every tilt. Golden-section search of the largest play over β between
    /// the tilts of the two raceways (0 and θ), widened by |θ| on each side (the play is a
    /// concave, piecewise smooth function of β for small angles; a missed maximum only leaves
    /// the case to the Newton solve).
    fn free_position(&self, e: f64, theta: f64) -> Option<(f64, f64)> {
        let w = theta.abs();
        let play = |beta: f64| self.play(e, theta, beta).1;
        // the bracket shrinks by 0.618 per step: 1e-9 |θ| after ≈ 45 steps
        let options = GoldenSectionOptions {
            max_iterations: 200,
            x_tolerance: 1e-9 * w,
        };
        let search = golden_section_max(play, theta.min(0.0) - w, theta.max(0.0) + w, &options);
        let beta = search.best.0;
        let (u, p) = self.play(e, theta, beta);
        (p >= 0.0).then_some((u, beta))
    }

    fn solve_tilted(&self, e: f64, theta: f64, guess: RollerState) -> Result<RollerState, QsError> {
        let m = self.model;
        let fc = self.fc;
        let ls = m.half_span;
        // quick unloaded test: inner contact at the outer-only position (β = 0)
        let li0 = m.inner.evaluate_totals(e - self.u_c, theta);
        let lo0 = m.outer.evaluate_totals(self.u_c, 0.0);
        let unloaded = |u: f64, beta: f64| RollerState {
            e,
            theta,
            u,
            beta,
            qi: 0.0,
            k: 0.0,
        };
        if li0.force <= 0.0 && (lo0.moment.abs() <= 1e-12 * (lo0.force + 1e-9) * ls) {
            return Ok(unloaded(self.u_c, 0.0));
        }
        // without centrifugal force a roller that fits between the raceways at some tilt is
        // unloaded, with an undetermined position (module docs for the convention)
        if fc <= 0.0
            && let Some((u, beta)) = self.free_position(e, theta)
        {
            return Ok(unloaded(u, beta));
        }
        // unknowns (u, β); Jacobian J = J_o + J_i in (u, ls β) (small angles: tan β ≈ β)
        let eval = |x: [f64; 2],
                    _: &(SliceLoad, SliceLoad)|
         -> Result<Sample<(SliceLoad, SliceLoad)>, Infallible> {
            let [u, b] = x;
            let lo_ = m.outer.evaluate_totals(u, b);
            let li = m.inner.evaluate_totals(e - u, theta - b);
            let j11 = lo_.dforce_dapproach + li.dforce_dapproach;
            let j12 = (lo_.dforce_dtilt + li.dforce_dtilt) / ls;
            let j21 = (lo_.dmoment_dapproach + li.dmoment_dapproach) / ls;
            let j22 = (lo_.dmoment_dtilt + li.dmoment_dtilt) / (ls * ls);
            let (reach_o, reach_i) = (
                u.abs() + ls * b.tan().abs(),
                (e - u).abs() + ls * (theta - b).tan().abs(),
            );
            Ok(Sample::new(
                [lo_.force - li.force - fc, (lo_.moment - li.moment) / ls],
                [[j11, j12], [j21, j22]],
                self.scale(&li, &lo_, reach_o, reach_i),
                (li, lo_),
            ))
        };
        let start = if guess.e != 0.0 || guess.u != 0.0 {
            [guess.u, guess.beta]
        } else {
            [0.5 * (e + self.u_c), 0.5 * theta]
        };
        let roller_newton = Newton2dOptions {
            tolerance: self.tol,
            // the scale holds the rounding floor: a stall above `tol·scale` is a failure (a
            // looser stall test would be multiplied by the floors and spoil the ring balance)
            stall_tolerance: 0.0,
            max_iterations: ROLLER_ITERATIONS,
            max_halvings: 40,
            sufficient_decrease: 0.0,
            damping: Damping::Trace { floor: 1e-12 },
            singular_damping: 1e-8,
            restart_damping: 1e-8,
            singular_tolerance: 1e-14,
            step_scale: [1.0, ls],
            ..Newton2dOptions::default()
        };
        let Ok(roller) = solve_2d(eval, start, (li0, lo0), &roller_newton);
        let [g1, g2] = roller.residual;
        match roller.status {
            Newton2dStatus::Converged | Newton2dStatus::Stalled => {
                let (li, lo_) = roller.state;
                Ok(RollerState {
                    e,
                    theta,
                    u: roller.x[0],
                    beta: roller.x[1],
                    qi: li.force,
                    k: implicit_stiffness(&li, &lo_, ls),
                })
            }
            // the bracketed nested solve is slower but cannot leave the contact region
            Newton2dStatus::NoDescent => self.solve_nested(e, theta).map_err(|_| {
                QsError::not_converged(
                    "roller radial/moment balance",
                    ROLLER_ITERATIONS,
                    &[("force / N", g1), ("moment / (N·m/half-length)", g2)],
                )
            }),
            Newton2dStatus::IterationLimit => self.solve_nested(e, theta).map_err(|_| {
                QsError::not_converged(
                    "roller radial/moment balance",
                    ROLLER_ITERATIONS,
                    &[("iterations", ROLLER_ITERATIONS as f64)],
                )
            }),
        }
    }

    /// Radial balance `Q_o − Q_i − F_c = 0` of a roller at fixed tilt `beta`: the outer
    /// approach u (non-decreasing residual in u) by safeguarded Newton steps in the bracket
    /// from the first touch of the outer raceway (`Q_o = 0`, residual ≤ 0) to an approach at
    /// which the outer raceway carries `F_c + Q_i` of the lower end (residual ≥ 0). Returns
    /// u, the inner and outer loads and whether the residual met the tolerance.
    fn balance_at_tilt(&self, e: f64, theta: f64, beta: f64) -> (f64, SliceLoad, SliceLoad, bool) {
        let m = self.model;
        let fc = self.fc;
        let ls = m.half_span;
        let (touch_o, _) = self.play(e, theta, beta);
        let eval = |u: f64| {
            let lo_ = m.outer.evaluate_totals(u, beta);
            let li = m.inner.evaluate_totals(e - u, theta - beta);
            let scale = self.scale(
                &li,
                &lo_,
                u.abs() + ls * beta.tan().abs(),
                (e - u).abs() + ls * (theta - beta).tan().abs(),
            );
            (lo_.force - li.force - fc, li, lo_, scale)
        };
        let lo = touch_o;
        let (r_lo, li_lo, lo_lo, scale_lo) = eval(lo);
        if r_lo >= -self.tol * scale_lo {
            return (lo, li_lo, lo_lo, true);
        }
        // first guess: the outer raceway alone carrying F_c + Q_i(first touch)
        let target = fc + li_lo.force;
        let hi = m
            .outer
            .solve_approach(target, beta, &slice_opts(1e-3))
            .map(|s| s.approach)
            .unwrap_or(lo + 1e-9)
            .max(lo);
        let options = Root1dOptions {
            bracket: Bracket::Expand {
                first_step: (hi - lo).max(1e-12),
            },
            derivative: Derivative::Supplied,
            x_rel_tol: 4.0 * f64::EPSILON,
            halving_test: false,
            max_evaluations: NESTED_ITERATIONS,
            ..Root1dOptions::default()
        };
        let Ok(root) = find_root(
            |u| {
                let (r, li, lo_, scale) = eval(u);
                let ok = r.abs() <= self.tol * scale;
                let slope = lo_.dforce_dapproach + li.dforce_dapproach;
                Ok::<_, Infallible>(Point::new(r, slope, ok, (li, lo_, ok)))
            },
            hi,
            &options,
        );
        let (li, lo_, ok) = root.state;
        (root.x, li, lo_, ok)
    }

    /// Fallback of [`Self::solve_tilted`] (module docs): the roller tilt β by safeguarded
    /// Newton steps on the moment balance `M_o − M_i` along the radial balance u(β)
    /// ([`Self::balance_at_tilt`]); the moment residual is non-decreasing in β (the balance is
    /// the gradient of the convex elastic energy minus `F_c u`), so the root is bracketed
    /// between tilts beyond those of both raceways.
    fn solve_nested(&self, e: f64, theta: f64) -> Result<RollerState, QsError> {
        let ls = self.model.half_span;
        let moment = |beta: f64| {
            let (u, li, lo_, ok) = self.balance_at_tilt(e, theta, beta);
            let scale = self.scale(
                &li,
                &lo_,
                u.abs() + ls * beta.tan().abs(),
                (e - u).abs() + ls * (theta - beta).tan().abs(),
            );
            let r2 = (lo_.moment - li.moment) / ls;
            let j11 = lo_.dforce_dapproach + li.dforce_dapproach;
            let j12 = (lo_.dforce_dtilt + li.dforce_dtilt) / ls;
            let j21 = (lo_.dmoment_dapproach + li.dmoment_dapproach) / ls;
            let j22 = (lo_.dmoment_dtilt + li.dmoment_dtilt) / (ls * ls);
            // d r2/d(ls β) along u(β) (Schur complement of the Jacobian)
            let slope = if j11 > 0.0 {
                j22 - j21 * j12 / j11
            } else {
                j22
            };
            (r2, slope, u, li, lo_, ok && r2.abs() <= self.tol * scale)
        };
        // β beyond the tilts of both raceways brackets the root; search outwards from between
        let w = theta.abs().max(1e-6);
        let options = Root1dOptions {
            bracket: Bracket::Expand { first_step: w },
            derivative: Derivative::Supplied,
            x_rel_tol: 4.0 * f64::EPSILON,
            max_evaluations: NESTED_ITERATIONS,
            ..Root1dOptions::default()
        };
        let Ok(root) = find_root(
            |beta| {
                let (r2, slope, u, li, lo_, ok) = moment(beta);
                Ok::<_, Infallible>(Point::new(r2, slope * ls, ok, (u, li, lo_)))
            },
            0.5 * theta,
            &options,
        );
        if !matches!(root.status, Root1dStatus::Converged | Root1dStatus::Stalled) {
            return Err(QsError::not_converged(
                "roller radial/moment balance",
                root.evaluations,
                &[("tilt bracket / rad", root.bracket.1 - root.bracket.0)],
            ));
        }
        let (u, li, lo_) = root.state;
        Ok(RollerState {
            e,
            theta,
            u,
            beta: root.x,
            qi: li.force,
            k: implicit_stiffness(&li, &lo_, ls),
        })
    }
}

/// dQ_i/de of a tilted roller by implicit differentiation of the roller equilibrium.
fn implicit_stiffness(li: &SliceLoad, lo: &SliceLoad, _ls: f64) -> f64 {
    if li.force <= 0.0 {
        return 0.0;
    }
    let j11 = lo.dforce_dapproach + li.dforce_dapproach;
    let j12 = lo.dforce_dtilt + li.dforce_dtilt;
    let j21 = lo.dmoment_dapproach + li.dmoment_dapproach;
    let j22 = lo.dmoment_dtilt + li.dmoment_dtilt;
    let det = j11 * j22 - j12 * j21;
    let (qa, qt) = (li.dforce_dapproach, li.dforce_dtilt);
    // Singular (relative to the rounding of det ≈ 1e-16·j11·j22): the roller pivots, e.g.
    // about one edge slice pressed by both raceways (J = K[1 x; x x²]). The tilt is then free
    // but the system J (du, dβ) = (dQ_i/da, dM_i/da) is consistent and every solution gives
    // the series stiffness of the two contacts, the exact limit of the formula below.
    if det.abs() <= 1e-9 * (j11 * j22).abs() || det.abs() <= 1e-300 {
        let (ki, ko) = (li.dforce_dapproach, lo.dforce_dapproach);
        return ki * ko / (ki + ko).max(1e-30);
    }
    // d(u, β)/de = J⁻¹ (dQi/da, dMi/da)
    let (ra, rm) = (li.dforce_dapproach, li.dmoment_dapproach);
    let du = (j22 * ra - j12 * rm) / det;
    let db = (j11 * rm - j21 * ra) / det;
    qa * (1.0 - du) - qt * db
}
