//! Transient squeeze-film motion of the roller after load changes, SPEC §8.5 (seed 002 §3.2, §5):
//!
//! M ḧ + λ(h) ḣ − W₀(h) = −F(t)      (3.21), (5.7),
//!
//! integrated by an L-stable two-stage SDIRK method (γ = 1 − 1/√2) with step-doubling error
//! control (the problem is stiff: ε = MV²W₀′²/(W₁′²FR) ≈ 10⁻²…10⁻⁶), plus the rigid isoviscous
//! dimensionless form (3.25) ε ḧ′ + ḣ′/h′^{3/2} − 1/h′ + 1 = 0 and its matched-asymptotic
//! solution (corrected per flag F-67) for verification. The pressure history uses the
//! quasi-steady q_max(ν) of (3.15); flag F-68: with it a load doubling gives no overshoot above
//! the new static pressure (the seed's "≈ 17×" is not reproducible).

use super::analytic;
use super::load_damping::LoadDampingTable;
use crate::error::{Result, ReynoldsError, positive};

/// Film reaction of the contact (per unit length, or per roller when multiplied by a length).
pub trait FilmReaction {
    /// W₀(h), N.
    fn load(&self, h: f64) -> f64;
    /// λ(h), N·s/m.
    fn damping(&self, h: f64) -> f64;
    /// Maximum pressure at film h approaching at speed ḣ (quasi-steady), Pa.
    fn max_pressure(&self, h: f64, hdot: f64) -> f64;
}

/// Rigid isoviscous contact of length `length` (3.17)–(3.20): W₀ = 6W₀′μVRℓ/h,
/// λ = 6W₁′μR^{3/2}ℓ/h^{3/2}, p_max = P₀(h) q_max(ν), ν = (ḣ/V)√(R/h).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidIsoviscous {
    /// Viscosity, Pa·s.
    pub mu: f64,
    /// Sum speed V, m/s.
    pub v: f64,
    /// Radius R, m.
    pub r: f64,
    /// Contact length ℓ, m (1 for per-unit-length values).
    pub length: f64,
    /// W₀′ (exact 0.4079, seed 0.401).
    pub w0c: f64,
    /// W₁′ (exact 1.091, seed 1.125).
    pub w1c: f64,
}

impl FilmReaction for RigidIsoviscous {
    fn load(&self, h: f64) -> f64 {
        6.0 * self.w0c * self.mu * self.v * self.r * self.length / h
    }
    fn damping(&self, h: f64) -> f64 {
        6.0 * self.w1c * self.mu * self.r.powf(1.5) * self.length / h.powf(1.5)
    }
    fn max_pressure(&self, h: f64, hdot: f64) -> f64 {
        let nu = (hdot / self.v * (self.r / h).sqrt()).clamp(-0.49, 10.0);
        let q = analytic::q_max(nu).unwrap_or(0.0).max(0.0);
        q * analytic::pressure_scale(self.mu, self.v, self.r, h)
    }
}

/// A tabulated contact (per unit length) times a contact length. The pressure maximum under
/// squeeze scales the table's static value by the rigid ratio q_max(ν)/q_max(0) (approximation).
#[derive(Debug, Clone)]
pub struct Tabulated<'a> {
    /// Table W₀(h), λ(h), p_max(h).
    pub table: &'a LoadDampingTable,
    /// Contact length, m.
    pub length: f64,
    /// Sum speed V, m/s (for ν).
    pub v: f64,
    /// Radius R, m (for ν).
    pub r: f64,
}

impl FilmReaction for Tabulated<'_> {
    fn load(&self, h: f64) -> f64 {
        self.table.load(h) * self.length
    }
    fn damping(&self, h: f64) -> f64 {
        self.table.damping(h) * self.length
    }
    fn max_pressure(&self, h: f64, hdot: f64) -> f64 {
        let nu = (hdot / self.v * (self.r / h).sqrt()).clamp(-0.49, 10.0);
        let ratio =
            analytic::q_max(nu).unwrap_or(0.0).max(0.0) / analytic::q_max(0.0).unwrap_or(1.0);
        self.table.max_pressure(h) * ratio
    }
}

/// Integrator settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TransientOptions {
    /// Relative tolerance. Default 1e-6.
    pub rtol: f64,
    /// Maximum accepted + rejected steps. Default 200 000.
    pub max_steps: usize,
    /// Store every k-th accepted step (1 = all). Default 1.
    pub output_every: usize,
}

impl Default for TransientOptions {
    fn default() -> Self {
        Self {
            rtol: 1e-6,
            max_steps: 200_000,
            output_every: 1,
        }
    }
}

/// One output sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TransientSample {
    /// Time, s.
    pub t: f64,
    /// Film h_m, m.
    pub h: f64,
    /// ḣ_m, m/s.
    pub hdot: f64,
    /// Film reaction W₀(h) − λ(h)ḣ, N.
    pub reaction: f64,
    /// Quasi-steady maximum pressure, Pa.
    pub p_max: f64,
}

/// Generic adaptive L-stable SDIRK2 with step doubling for y′ = f(t, y), y ∈ ℝ², with absolute
/// error scales `scale` (per component). Returns the accepted (t, y).
pub fn integrate2(
    f: &dyn Fn(f64, [f64; 2]) -> [f64; 2],
    y0: [f64; 2],
    t0: f64,
    t_end: f64,
    first_step: f64,
    scale: [f64; 2],
    opt: &TransientOptions,
) -> Result<Vec<(f64, [f64; 2])>> {
    let g = 1.0 - std::f64::consts::FRAC_1_SQRT_2;
    let stage = |t: f64, y: [f64; 2], rhs: [f64; 2], tau: f64| -> Result<[f64; 2]> {
        // solve Y − τγ f(t, Y) = rhs by Newton with a finite-difference Jacobian
        let mut yv = rhs;
        for _ in 0..30 {
            let fy = f(t, yv);
            let r = [
                yv[0] - tau * g * fy[0] - rhs[0],
                yv[1] - tau * g * fy[1] - rhs[1],
            ];
            let mut jm = [[0.0; 2]; 2];
            for j in 0..2 {
                let d = 1e-7 * yv[j].abs().max(scale[j]);
                let mut yp = yv;
                yp[j] += d;
                let fp = f(t, yp);
                for i in 0..2 {
                    jm[i][j] = if i == j { 1.0 } else { 0.0 } - tau * g * (fp[i] - fy[i]) / d;
                }
            }
            let det = jm[0][0] * jm[1][1] - jm[0][1] * jm[1][0];
            if det == 0.0 || !det.is_finite() {
                return Err(ReynoldsError::Singular("transient stage"));
            }
            let dx = [
                -(jm[1][1] * r[0] - jm[0][1] * r[1]) / det,
                -(-jm[1][0] * r[0] + jm[0][0] * r[1]) / det,
            ];
            yv[0] += dx[0];
            yv[1] += dx[1];
            if dx[0].abs() < 1e-12 * scale[0] && dx[1].abs() < 1e-12 * scale[1] {
                return Ok(yv);
            }
        }
        let _ = y;
        Ok(yv)
    };
    let step = |t: f64, y: [f64; 2], tau: f64| -> Result<[f64; 2]> {
        let y1 = stage(t + g * tau, y, y, tau)?;
        let f1 = f(t + g * tau, y1);
        let rhs = [
            y[0] + tau * (1.0 - g) * f1[0],
            y[1] + tau * (1.0 - g) * f1[1],
        ];
        stage(t + tau, y, rhs, tau)
    };
    let mut out = vec![(t0, y0)];
    let (mut t, mut y, mut tau) = (t0, y0, first_step.min(t_end - t0));
    let mut n = 0usize;
    let mut accepted = 0usize;
    while t < t_end {
        n += 1;
        if n > opt.max_steps {
            return Err(ReynoldsError::NotConverged {
                what: "transient integration (step limit)",
                iterations: n,
                residual: t,
            });
        }
        tau = tau.min(t_end - t);
        let full = step(t, y, tau)?;
        let half = step(t, y, 0.5 * tau)?;
        let half2 = step(t + 0.5 * tau, half, 0.5 * tau)?;
        let mut err: f64 = 0.0;
        for i in 0..2 {
            let e = (half2[i] - full[i]).abs() / 3.0;
            err = err.max(e / (opt.rtol * (scale[i] + half2[i].abs())));
        }
        if !err.is_finite() {
            tau *= 0.25;
            continue;
        }
        if err <= 1.0 {
            t += tau;
            y = half2;
            accepted += 1;
            if accepted.is_multiple_of(opt.output_every.max(1)) || t >= t_end {
                out.push((t, y));
            }
        }
        let fac = if err == 0.0 {
            2.0
        } else {
            (0.9 * err.powf(-1.0 / 3.0)).clamp(0.2, 2.0)
        };
        tau *= fac;
        if tau < 1e-14 * (t_end - t0).abs() {
            return Err(ReynoldsError::NotConverged {
                what: "transient integration (step underflow)",
                iterations: n,
                residual: err,
            });
        }
    }
    Ok(out)
}

/// Integrates M ḧ + λ(h)ḣ − W₀(h) = −F(t) from (h₀, ḣ₀) to `t_end` (seed (5.7)).
pub fn simulate(
    film: &dyn FilmReaction,
    mass: f64,
    force: &dyn Fn(f64) -> f64,
    h0: f64,
    hdot0: f64,
    t_end: f64,
    opt: &TransientOptions,
) -> Result<Vec<TransientSample>> {
    positive("mass", mass)?;
    positive("initial film", h0)?;
    positive("end time", t_end)?;
    let rhs = |t: f64, y: [f64; 2]| -> [f64; 2] {
        let h = y[0].max(1e-3 * h0);
        [
            y[1],
            (film.load(h) - film.damping(h) * y[1] - force(t)) / mass,
        ]
    };
    // time scale: damping relaxation λ/(dW₀/dh) at the start
    let dw = (film.load(0.99 * h0) - film.load(1.01 * h0)).abs() / (0.02 * h0);
    let t_relax = film.damping(h0) / dw.max(1e-300);
    let t_inertia = mass / film.damping(h0).max(1e-300);
    let first = (0.01 * t_inertia.min(t_relax)).min(t_end);
    let traj = integrate2(
        &rhs,
        [h0, hdot0],
        0.0,
        t_end,
        first,
        [h0, h0 / t_relax.max(1e-300)],
        opt,
    )?;
    Ok(traj
        .into_iter()
        .map(|(t, y)| TransientSample {
            t,
            h: y[0],
            hdot: y[1],
            reaction: film.load(y[0]) - film.damping(y[0]) * y[1],
            p_max: film.max_pressure(y[0], y[1]),
        })
        .collect())
}

/// Scales of the rigid isoviscous problem (3.23)–(3.25): equilibrium gap h₀ = 6μVRW₀′/F (per
/// unit length: F in N/m), time t₀ = W₁′√(Rh₀)/(VW₀′), ε = MV²W₀′²/(W₁′²FR). Returns (h₀, t₀, ε).
pub fn rigid_scales(
    mu: f64,
    v: f64,
    r: f64,
    force_per_length: f64,
    mass_per_length: f64,
    w0c: f64,
    w1c: f64,
) -> (f64, f64, f64) {
    let h0 = 6.0 * mu * v * r * w0c / force_per_length;
    let t0 = w1c * (r * h0).sqrt() / (v * w0c);
    let eps = mass_per_length * v * v * w0c * w0c / (w1c * w1c * force_per_length * r);
    (h0, t0, eps)
}

/// Integrates the dimensionless equation (3.25) εḧ′ + ḣ′/h′^{3/2} − 1/h′ + 1 = 0 with
/// h′(0) = h*, ḣ′(0) = 0; returns (t′, h′, ḣ′).
pub fn dimensionless(
    eps: f64,
    h_star: f64,
    t_end: f64,
    opt: &TransientOptions,
) -> Result<Vec<(f64, f64, f64)>> {
    positive("ε", eps)?;
    positive("h*", h_star)?;
    let rhs = |_t: f64, y: [f64; 2]| -> [f64; 2] {
        let h = y[0].max(1e-6);
        [y[1], (1.0 / h - 1.0 - y[1] / h.powf(1.5)) / eps]
    };
    let traj = integrate2(&rhs, [h_star, 0.0], 0.0, t_end, 1e-3 * eps, [1.0, 1.0], opt)?;
    Ok(traj.into_iter().map(|(t, y)| (t, y[0], y[1])).collect())
}

/// Leading-order outer solution h̄₀(t′) of (3.34) (corrected per F-67 for h* < 1).
pub fn outer_h0(t: f64, h_star: f64) -> f64 {
    let u0 = h_star.sqrt();
    if (h_star - 1.0).abs() < 1e-15 {
        return 1.0;
    }
    let u = if h_star > 1.0 {
        let a = (u0 + 1.0) / (u0 - 1.0);
        (a * t.exp() + 1.0) / (a * t.exp() - 1.0)
    } else {
        let a = (1.0 + u0) / (1.0 - u0);
        (a * t.exp() - 1.0) / (a * t.exp() + 1.0)
    };
    u * u
}

/// First-order outer correction h̄₁(t′) (derived in SPEC §8.5, flag F-67).
pub fn outer_h1(t: f64, h_star: f64) -> f64 {
    let h0 = outer_h0(t, h_star);
    let (s, s0) = (h0.sqrt(), h_star.sqrt());
    let l = |u: f64| ((1.0 + u) / (1.0 - u)).abs().ln();
    (1.0 - h0) * s * (-h0 * s - 2.0 * s + 2.0 * s0 + l(s) - l(s0))
}

/// First-order boundary-layer term h̃₁(τ), τ = t′/ε (3.52): −(h*−1)h*² e^{−τ/h*^{3/2}}.
pub fn boundary_layer_h1(tau: f64, h_star: f64) -> f64 {
    -(h_star - 1.0) * h_star * h_star * (-tau / h_star.powf(1.5)).exp()
}

/// Composite asymptotic solution h′ ≈ h̄₀ + ε(h̄₁ + h̃₁(t′/ε)).
pub fn composite(t: f64, eps: f64, h_star: f64) -> f64 {
    outer_h0(t, h_star) + eps * (outer_h1(t, h_star) + boundary_layer_h1(t / eps, h_star))
}

/// Peak of the quasi-steady pressure after a sudden load change F₀ → F₁ = h*·F₀ (rigid
/// isoviscous, per unit length), relative to the new static pressure Q_S and to the old one
/// (flag F-68). Returns (max Q/Q_S,new, max Q/Q_S,old).
pub fn load_step_pressure_ratio(eps: f64, h_star: f64, w0c: f64, w1c: f64) -> Result<(f64, f64)> {
    let traj = dimensionless(eps, h_star, 8.0, &TransientOptions::default())?;
    let qs = analytic::q_max(0.0)?;
    let mut peak: f64 = 0.0;
    for (_, h, hd) in traj {
        // ν = (W₀′/W₁′) ḣ′/√h′; P/P_S,new = q_max(ν)/(q_max(0) h′^{3/2})
        let nu = w0c / w1c * hd / h.sqrt();
        let q = analytic::q_max(nu.clamp(-0.49, 10.0))?;
        peak = peak.max(q / (qs * h.powf(1.5)));
    }
    Ok((peak, peak * h_star.powf(1.5)))
}
