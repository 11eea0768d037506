//! Coupled Newton solver of the lubricated line contact (rigid to full EHL). See the module
//! documentation of [`super`] for the method.

use super::analytic;
use super::{Constraint, LineContactOptions, LineContactResult, LineGrid, LubricatedLineContact};
use crate::banded::{BandLu, BandMatrix, Bordered, BorderedFactor};
use crate::compliance::Influence;
use crate::error::{Result, ReynoldsError, finite, positive};
use crate::grid::Grid1d;
use crate::viscosity::Viscosity;
use rolldyn_contact::hertz::line_half_width;
use rolldyn_lubrication::film::{PAN_HAMROCK_CENTRAL, PAN_HAMROCK_MINIMUM};
use std::time::Instant;

/// Per-node lubricant quantities and their derivatives.
#[derive(Clone, Copy, Default)]
struct NodeQ {
    rho: f64,
    drho: f64,
    eps: f64,
    deps_dp: f64,
    deps_dh: f64,
    g: f64,
    dg_dp: f64,
    dg_dh: f64,
}

/// Discrete problem on a fixed grid.
struct Ehl<'a> {
    c: &'a LubricatedLineContact,
    visc: &'a dyn Viscosity,
    x: Vec<f64>,
    cell: Vec<f64>,
    geom: Vec<f64>,
    infl: Option<Influence>,
    /// Near band of L·D: ld_near[i·(2w+1) + (j − i + w)].
    ld_near: Vec<f64>,
    w: usize,
    vy: f64,
    pcav: f64,
    /// Relative tolerance of the inner GMRES solve.
    lin_tol: f64,
    // scales
    ps: f64,
    hs: f64,
    ls: f64,
    vref: f64,
}

/// Iterate: pressures, films, rigid approach and cavitated set.
#[derive(Clone)]
struct State {
    p: Vec<f64>,
    h: Vec<f64>,
    h0: f64,
    cav: Vec<bool>,
}

/// Column of an unknown in the bordered Jacobian: band block or border.
enum Col {
    A(usize),
    B(usize),
}

/// Scaled bordered Jacobian [[A, E], [F, G]] of a Newton step (see [`Bordered`]).
struct Jacobian {
    a: BandMatrix,
    e: Vec<Vec<f64>>,
    f: Vec<Vec<f64>>,
    g: [f64; 9],
}

struct Residual {
    /// Scaled residual in unknown layout: A rows then 3 border rows.
    r: Vec<f64>,
    /// Node quantities.
    q: Vec<NodeQ>,
}

impl<'a> Ehl<'a> {
    fn n(&self) -> usize {
        self.x.len()
    }

    /// Position of p_i / h_i in the band block (h₀ and h_{n−1} are border unknowns).
    #[inline]
    fn pos_p(&self, i: usize) -> usize {
        if i == 0 { 0 } else { 2 * i - 1 }
    }
    #[inline]
    fn pos_h(&self, i: usize) -> usize {
        debug_assert!(i > 0 && i + 1 < self.n());
        2 * i
    }
    fn na(&self) -> usize {
        2 * self.n() - 2
    }

    fn node(&self, p: f64, h: f64) -> NodeQ {
        let c = self.c;
        let pp = p.max(0.0);
        let rho = c.density.ratio(pp);
        let drho = c.density.derivative(pp);
        let mu = self.visc.viscosity(pp, c.temperature);
        let dlm = self.visc.dln_viscosity_dp(pp, c.temperature);
        let ps = c.slip.poiseuille(h);
        let eps = rho * ps / mu;
        let [u1, u2] = c.surface_speeds;
        let qc = c.slip.couette(h, u1, u2);
        NodeQ {
            rho,
            drho,
            eps,
            deps_dp: eps * (drho / rho - dlm),
            deps_dh: rho * c.slip.d_poiseuille(h) / mu,
            g: rho * qc,
            dg_dp: drho * qc,
            dg_dh: rho * c.slip.d_couette(h, u1, u2),
        }
    }

    /// Face k+½ (between nodes k and k+1) Couette flux as Σ wⱼ Gⱼ (second-order upwind).
    fn face(&self, k: usize) -> [(usize, f64); 2] {
        let n = self.n();
        let x = &self.x;
        let xf = 0.5 * (x[k] + x[k + 1]);
        if self.c.sum_speed() >= 0.0 {
            if k == 0 {
                [(0, 1.0), (0, 0.0)]
            } else {
                let r = (xf - x[k]) / (x[k] - x[k - 1]);
                [(k, 1.0 + r), (k - 1, -r)]
            }
        } else if k + 2 > n - 1 {
            [(k + 1, 1.0), (k + 1, 0.0)]
        } else {
            let r = (x[k + 1] - xf) / (x[k + 2] - x[k + 1]);
            [(k + 1, 1.0 + r), (k + 2, -r)]
        }
    }

    /// Second-difference coefficients at interior node i (for i−1, i, i+1).
    fn lap(&self, i: usize) -> [f64; 3] {
        let x = &self.x;
        let a = 2.0 / ((x[i + 1] - x[i - 1]) * (x[i] - x[i - 1]));
        let c = 2.0 / ((x[i + 1] - x[i - 1]) * (x[i + 1] - x[i]));
        [a, -(a + c), c]
    }

    fn deflection(&self, p: &[f64]) -> Vec<f64> {
        let n = self.n();
        let mut d = vec![0.0; n];
        if let Some(inf) = &self.infl {
            inf.apply(p, &mut d);
        }
        d
    }

    fn reynolds_row_scale(&self, i: usize) -> f64 {
        self.ls / (self.vref * self.hs * self.cell[i].max(1e-300))
    }

    /// Scale of the elastic rows, l_s²/h_s.
    fn elastic_row_scale(&self) -> f64 {
        self.ls * self.ls / self.hs
    }

    /// Spacings east and west of interior node i and the Poiseuille conductances of those
    /// faces: (Δx_e, Δx_w, a_e, a_w), a = ε̄/Δx with ε̄ the face mean.
    fn conductances(&self, q: &[NodeQ], i: usize) -> (f64, f64, f64, f64) {
        let x = &self.x;
        let (dxe, dxw) = (x[i + 1] - x[i], x[i] - x[i - 1]);
        let ae = 0.5 * (q[i].eps + q[i + 1].eps) / dxe;
        let aw = 0.5 * (q[i - 1].eps + q[i].eps) / dxw;
        (dxe, dxw, ae, aw)
    }

    /// Unscaled Reynolds residual of node i (1 ≤ i ≤ n−2).
    fn reynolds(&self, st: &State, q: &[NodeQ], i: usize) -> f64 {
        let (_, _, ae, aw) = self.conductances(q, i);
        let ge: f64 = self.face(i).iter().map(|&(k, w)| w * q[k].g).sum();
        let gw: f64 = self.face(i - 1).iter().map(|&(k, w)| w * q[k].g).sum();
        ae * (st.p[i + 1] - st.p[i])
            - aw * (st.p[i] - st.p[i - 1])
            - (ge - gw)
            - q[i].rho * self.vy * self.cell[i]
    }

    fn residual(&self, st: &State, con: Constraint) -> Residual {
        let n = self.n();
        let q: Vec<NodeQ> = (0..n).map(|i| self.node(st.p[i], st.h[i])).collect();
        let d = self.deflection(&st.p);
        let mut r = vec![0.0; self.na() + 3];
        // pressure rows
        for i in 0..n {
            let row = self.pos_p(i);
            r[row] = if i == 0 || i == n - 1 || st.cav[i] {
                (st.p[i] - if i == 0 || i == n - 1 { 0.0 } else { self.pcav }) / self.ps
            } else {
                self.reynolds(st, &q, i) * self.reynolds_row_scale(i)
            };
        }
        // elastic rows
        let se = self.elastic_row_scale();
        for i in 1..n - 1 {
            let l = self.lap(i);
            let mut v = 0.0;
            for (k, c) in l.iter().enumerate() {
                let j = i + k - 1;
                v += c * (st.h[j] - self.geom[j] - d[j]);
            }
            r[self.pos_h(i)] = v * se;
        }
        let na = self.na();
        r[na] = (st.h[0] - st.h0 - self.geom[0] - d[0]) / self.hs;
        r[na + 1] = (st.h[n - 1] - st.h0 - self.geom[n - 1] - d[n - 1]) / self.hs;
        r[na + 2] = match con {
            Constraint::RigidApproach(a) => (st.h0 - a) / self.hs,
            Constraint::MinFilm(hm) => {
                let k = argmin(&st.h);
                (st.h[k] - hm) / self.hs
            }
            Constraint::LoadPerLength(w) => {
                let s: f64 = st.p.iter().zip(&self.cell).map(|(p, c)| p * c).sum();
                (s - w) / (self.ps * self.ls)
            }
        };
        Residual { r, q }
    }

    /// Builds the scaled Jacobian and solves for the Newton step (unscaled).
    fn step(
        &self,
        st: &State,
        res: &Residual,
        con: Constraint,
    ) -> Result<(Vec<f64>, Vec<f64>, f64)> {
        let na = self.na();
        let bw = (2 * self.w + 2).max(6);
        let mut jac = Jacobian {
            a: BandMatrix::new(na, bw, bw),
            e: vec![vec![0.0; na]; 3],
            f: vec![vec![0.0; na]; 3],
            g: [0.0; 9],
        };
        self.reynolds_rows(st, &res.q, &mut jac);
        self.elastic_rows(&mut jac);
        self.border_rows(st, con, &mut jac);
        let Jacobian { a, e, f, g } = jac;
        let lu = a.factor()?;
        let bf = Bordered {
            a: &lu,
            e: &e,
            f: &f,
            g: &g,
        }
        .factor()?;
        let mut rhs: Vec<f64> = res.r[..na].iter().map(|v| -v).collect();
        let mut rb: Vec<f64> = res.r[na..].iter().map(|v| -v).collect();
        self.solve_linear(&bf, &mut rhs, &mut rb);
        let (n, ps, hs) = (self.n(), self.ps, self.hs);
        let mut dpv = vec![0.0; n];
        let mut dhv = vec![0.0; n];
        for i in 0..n {
            dpv[i] = rhs[self.pos_p(i)] * ps;
            dhv[i] = match self.col_h(i) {
                Col::A(c) => rhs[c] * hs,
                Col::B(b) => rb[b] * hs,
            };
        }
        Ok((dpv, dhv, rb[2] * hs))
    }

    /// Jacobian column of h_k: the band block, or border column 0 / 1 for the end films.
    fn col_h(&self, k: usize) -> Col {
        if k == 0 {
            Col::B(0)
        } else if k == self.n() - 1 {
            Col::B(1)
        } else {
            Col::A(self.pos_h(k))
        }
    }

    /// Unscaled derivatives dR/dp_k and dR/dh_k of the Reynolds residual of interior node i,
    /// k = i−2 … i+2 (index k + 2 − i).
    fn reynolds_derivatives(&self, st: &State, q: &[NodeQ], i: usize) -> ([f64; 5], [f64; 5]) {
        let (dxe, dxw, ae, aw) = self.conductances(q, i);
        let (gpe, gpw) = (st.p[i + 1] - st.p[i], st.p[i] - st.p[i - 1]);
        let mut dp = [0.0; 5];
        let mut dh = [0.0; 5];
        let o = |k: usize| k + 2 - i;
        dp[o(i + 1)] += ae + 0.5 * q[i + 1].deps_dp / dxe * gpe;
        dh[o(i + 1)] += 0.5 * q[i + 1].deps_dh / dxe * gpe;
        dp[o(i)] += -ae - aw + 0.5 * q[i].deps_dp * (gpe / dxe - gpw / dxw);
        dh[o(i)] += 0.5 * q[i].deps_dh * (gpe / dxe - gpw / dxw);
        dp[o(i - 1)] += aw - 0.5 * q[i - 1].deps_dp / dxw * gpw;
        dh[o(i - 1)] += -0.5 * q[i - 1].deps_dh / dxw * gpw;
        for (face, sign) in [(i, -1.0), (i - 1, 1.0)] {
            for (k, wgt) in self.face(face) {
                if wgt != 0.0 {
                    dp[o(k)] += sign * wgt * q[k].dg_dp;
                    dh[o(k)] += sign * wgt * q[k].dg_dh;
                }
            }
        }
        dp[o(i)] -= q[i].drho * self.vy * self.cell[i];
        (dp, dh)
    }

    /// Pressure rows: identity at the ends and cavitated nodes, the scaled Reynolds derivatives
    /// elsewhere.
    fn reynolds_rows(&self, st: &State, q: &[NodeQ], jac: &mut Jacobian) {
        let n = self.n();
        let (ps, hs) = (self.ps, self.hs);
        for i in 0..n {
            let row = self.pos_p(i);
            if i == 0 || i == n - 1 || st.cav[i] {
                jac.a.add(row, row, 1.0);
                continue;
            }
            let sr = self.reynolds_row_scale(i);
            let (dp, dh) = self.reynolds_derivatives(st, q, i);
            for t in 0..5 {
                let k = i + t;
                if k < 2 || k - 2 >= n {
                    continue;
                }
                let k = k - 2;
                if dp[t] != 0.0 {
                    jac.a.add(row, self.pos_p(k), sr * dp[t] * ps);
                }
                if dh[t] != 0.0 {
                    match self.col_h(k) {
                        Col::A(c) => jac.a.add(row, c, sr * dh[t] * hs),
                        Col::B(b) => jac.e[b][row] += sr * dh[t] * hs,
                    }
                }
            }
        }
    }

    /// Elastic rows: the second difference of the film and, within the near band, of the
    /// deflection (L·D); the far part is applied by [`Self::far_apply`].
    fn elastic_rows(&self, jac: &mut Jacobian) {
        let n = self.n();
        let (ps, hs) = (self.ps, self.hs);
        let se = self.elastic_row_scale();
        for i in 1..n - 1 {
            let row = self.pos_h(i);
            let l = self.lap(i);
            for (t, c) in l.iter().enumerate() {
                let k = i + t - 1;
                match self.col_h(k) {
                    Col::A(cc) => jac.a.add(row, cc, se * c * hs),
                    Col::B(b) => jac.e[b][row] += se * c * hs,
                }
            }
            if self.infl.is_some() {
                let lo = i.saturating_sub(self.w).max(1);
                let hi = (i + self.w).min(n - 2);
                let wb = 2 * self.w + 1;
                for j in lo..=hi {
                    let ldij = self.ld_near[i * wb + (j + self.w - i)];
                    jac.a.add(row, self.pos_p(j), -se * ldij * ps);
                }
            }
        }
    }

    /// Border rows: the film conditions at both ends and the constraint.
    fn border_rows(&self, st: &State, con: Constraint, jac: &mut Jacobian) {
        let n = self.n();
        let (ps, hs) = (self.ps, self.hs);
        let (f, g) = (&mut jac.f, &mut jac.g);
        if let Some(inf) = &self.infl {
            for j in 1..n - 1 {
                f[0][self.pos_p(j)] = -inf.get(0, j) * ps / hs;
                f[1][self.pos_p(j)] = -inf.get(n - 1, j) * ps / hs;
            }
        }
        g[0] = 1.0; // h_first
        g[2] = -1.0; // h0
        g[4] = 1.0; // h_last
        g[5] = -1.0;
        match con {
            Constraint::RigidApproach(_) => g[8] = 1.0,
            Constraint::MinFilm(_) => {
                let k = argmin(&st.h);
                match self.col_h(k) {
                    Col::A(c) => f[2][c] = 1.0,
                    Col::B(b) => g[6 + b] = 1.0,
                }
            }
            Constraint::LoadPerLength(_) => {
                for j in 0..n {
                    f[2][self.pos_p(j)] = self.cell[j] * ps / (ps * self.ls);
                }
            }
        }
    }

    /// Solves the scaled Newton system in place: directly when rigid; for elastic problems by
    /// GMRES preconditioned with the near-band factorisation `bf`.
    fn solve_linear(&self, bf: &BorderedFactor<'_, BandLu>, rhs: &mut [f64], rb: &mut [f64]) {
        if self.infl.is_none() {
            bf.solve(rhs, rb);
            return;
        }
        let na = self.na();
        // right-preconditioned GMRES: (J M⁻¹) y = −r with J = M + J_far, J_far the elastic
        // influence beyond the near band (dense, applied by a matrix–vector product)
        let mut b = rhs.to_vec();
        b.extend_from_slice(rb);
        let bn = Self::norm(&b);
        let tol = (self.lin_tol * bn).max(1e-14);
        let prec = |v: &[f64]| -> Vec<f64> {
            let mut va = v[..na].to_vec();
            let mut vb = v[na..].to_vec();
            bf.solve(&mut va, &mut vb);
            va.extend_from_slice(&vb);
            va
        };
        let (y, _, _) = crate::krylov::gmres(
            |v, out| {
                let z = prec(v);
                out.copy_from_slice(v);
                self.far_apply(&z, out);
            },
            &b,
            tol,
            40,
            400,
        );
        let z = prec(&y);
        rhs.copy_from_slice(&z[..na]);
        rb.copy_from_slice(&z[na..]);
    }

    /// Exit of the full film: first cavitated (or zero) node k after the pressure maximum `kmax`
    /// and the exit coordinate x_c. The mass flux Q is the same through every face of the full
    /// film (discrete conservation, minus the squeeze source); at the Reynolds exit p′ = 0, so
    /// x_c is where the Couette flux of the film equals Q — second-order accurate, unlike the
    /// node of the discrete free boundary. Fallback: p ∝ (x_c − x)² through the last two nodes.
    fn exit(&self, st: &State, kmax: usize) -> Option<(usize, f64)> {
        let n = self.n();
        let x = &self.x;
        let k = (kmax + 1..n).find(|&k| st.cav[k] || st.p[k] <= self.pcav)?;
        let mut xc = x[k - 1];
        let (a, bb) = (
            st.p[k - 1] - self.pcav,
            if k >= 2 { st.p[k - 2] - self.pcav } else { 0.0 },
        );
        if a > 0.0 && bb > a {
            let (sa, sb) = (a.sqrt(), bb.sqrt());
            xc = (x[k - 1] + sa * (x[k - 1] - x[k - 2]) / (sb - sa)).min(x[k]);
        }
        if k >= 3 && self.c.sum_speed() != 0.0 {
            let q = |i: usize| self.node(st.p[i], st.h[i]);
            let f = k - 2; // face between k−2 and k−1
            let ef = 0.5 * (q(f).eps + q(f + 1).eps);
            let gf: f64 = self.face(f).iter().map(|&(j, w)| w * q(j).g).sum();
            let qf = -ef * (st.p[f + 1] - st.p[f]) / (x[f + 1] - x[f]) + gf;
            let xf = 0.5 * (x[f] + x[f + 1]);
            let rho_c = self.c.density.ratio(self.pcav.max(0.0));
            let [u1, u2] = self.c.surface_speeds;
            let mismatch = |xx: f64, h: f64| {
                rho_c * self.c.slip.couette(h, u1, u2) - (qf - rho_c * self.vy * (xx - xf))
            };
            let sgn = self.c.sum_speed().signum();
            for j in f..n - 1 {
                let (m0, m1) = (mismatch(x[j], st.h[j]), mismatch(x[j + 1], st.h[j + 1]));
                if sgn * m0 <= 0.0 && sgn * m1 > 0.0 {
                    let t = m0 / (m0 - m1);
                    xc = x[j] + t * (x[j + 1] - x[j]);
                    break;
                }
            }
        }
        Some((k, xc))
    }

    /// out += J_far z (scaled): elastic rows get −s_e p_s Σ_{|i−j|>w} (LD)_ij z_pj.
    fn far_apply(&self, z: &[f64], out: &mut [f64]) {
        let n = self.n();
        let Some(inf) = &self.infl else { return };
        let mut zp = vec![0.0; n];
        for j in 1..n - 1 {
            zp[j] = z[self.pos_p(j)];
        }
        let mut u = vec![0.0; n];
        inf.apply(&zp, &mut u);
        let se = self.elastic_row_scale();
        let wb = 2 * self.w + 1;
        for i in 1..n - 1 {
            let l = self.lap(i);
            let full = l[0] * u[i - 1] + l[1] * u[i] + l[2] * u[i + 1];
            let lo = i.saturating_sub(self.w).max(1);
            let hi = (i + self.w).min(n - 2);
            let mut near = 0.0;
            for j in lo..=hi {
                near += self.ld_near[i * wb + (j + self.w - i)] * zp[j];
            }
            out[self.pos_h(i)] -= se * self.ps * (full - near);
        }
    }

    fn norm(r: &[f64]) -> f64 {
        r.iter().map(|v| v * v).sum::<f64>().sqrt()
    }

    /// Squeeze damping −∂W′/∂V_y by central differences ±ΔV_y at the converged rigid approach
    /// of `st`, N·s/m².
    fn squeeze_damping(
        &mut self,
        st: &State,
        options: &LineContactOptions,
        total_iters: &mut usize,
    ) -> Result<f64> {
        let (r, vabs) = (self.c.radius, self.c.sum_speed().abs().max(1e-300));
        let hm = st.h.iter().fold(f64::MAX, |a, &v| a.min(v));
        let dv = options.damping_perturbation * vabs * (hm / r).sqrt();
        let base_vy = self.vy;
        let mut w = [0.0; 2];
        for (k, s) in [1.0, -1.0].iter().enumerate() {
            self.vy = base_vy + s * dv;
            let mut s2 = st.clone();
            let (ok, it) = self.newton(&mut s2, Constraint::RigidApproach(st.h0), options)?;
            *total_iters += it;
            if !ok {
                let r = self.residual(&s2, Constraint::RigidApproach(st.h0));
                return Err(ReynoldsError::NotConverged {
                    what: "line-contact damping perturbation",
                    iterations: it,
                    residual: r.r.iter().fold(0.0f64, |a, &v| a.max(v.abs())),
                });
            }
            w[k] = s2.p.iter().zip(&self.cell).map(|(p, c)| p * c).sum();
        }
        self.vy = base_vy;
        Ok(-(w[0] - w[1]) / (2.0 * dv))
    }

    /// Newton iterations from `st`. Returns (converged, iterations).
    fn newton(
        &self,
        st: &mut State,
        con: Constraint,
        opt: &LineContactOptions,
    ) -> Result<(bool, usize)> {
        let n = self.n();
        let mut res = self.residual(st, con);
        let mut flips = vec![0u8; n];
        let mut small_steps = 0;
        for it in 0..opt.max_iterations {
            let (dp, dh, dh0) = self.step(st, &res, con)?;
            let (alpha, pmax, dpmax) = self.step_limit(st, &dp);
            let (trial, tres, alpha) = self.line_search(st, &res, con, (&dp, &dh, dh0), alpha);
            if !tres.r.iter().all(|v| v.is_finite()) {
                return Ok((false, it + 1));
            }
            // stalled globalisation: give up early (the caller continues in load)
            if alpha < 1e-3 {
                small_steps += 1;
                if small_steps >= 4 {
                    return Ok((false, it + 1));
                }
            } else {
                small_steps = 0;
            }
            *st = trial;
            let changed = self.update_active_set(st, &tres.q, &mut flips);
            res = if changed {
                self.residual(st, con)
            } else {
                tres
            };
            let rmax = res.r.iter().fold(0.0f64, |a, &v| a.max(v.abs()));
            let smax = (alpha * dpmax / pmax).max(
                dh.iter()
                    .zip(&st.h)
                    .fold(0.0f64, |a, (d, h)| a.max(alpha * d.abs() / h)),
            );
            // converged: residual below tolerance with a small last step, or a step at round-off
            // level with the residual at its floor
            if !changed
                && ((rmax < opt.tolerance && smax < 1e-6)
                    || (smax < 1e-11 && rmax < 1e3 * opt.tolerance))
            {
                return Ok((true, it + 1));
            }
        }
        Ok((false, opt.max_iterations))
    }

    /// Largest step length for the pressure change `dp`, with the pressure maximum (at least
    /// p_s) and the largest |dp|: (α, p_max, |dp|_max).
    fn step_limit(&self, st: &State, dp: &[f64]) -> (f64, f64, f64) {
        // step length: limit wild pressure changes; films are kept positive by clipping each
        // node at a tenth of its previous value (a projection, not a global step cut)
        let mut alpha: f64 = 1.0;
        let pmax = st.p.iter().fold(self.ps, |a, &v| a.max(v));
        let dpmax = dp.iter().fold(0.0f64, |a, &v| a.max(v.abs()));
        if dpmax > 2.0 * pmax {
            alpha = alpha.min(2.0 * pmax / dpmax);
        }
        // trust region on the pressure: no node changes by more than half its value (or 5 %
        // of the maximum) per iteration
        let floor = 0.05 * pmax;
        for i in 0..self.n() {
            let lim = 0.5 * st.p[i].max(floor);
            if dp[i].abs() > lim {
                alpha = alpha.min(lim / dp[i].abs());
            }
        }
        (alpha, pmax, dpmax)
    }

    /// Backtracking from the step length `alpha` (halved up to 6 times) until the residual norm
    /// decreases sufficiently: the trial state, its residual and the step length taken.
    fn line_search(
        &self,
        st: &State,
        res: &Residual,
        con: Constraint,
        (dp, dh, dh0): (&[f64], &[f64], f64),
        mut alpha: f64,
    ) -> (State, Residual, f64) {
        let f0 = Self::norm(&res.r);
        let mut trial = st.clone();
        let mut tries = 0;
        loop {
            for i in 0..self.n() {
                trial.p[i] = st.p[i] + alpha * dp[i];
                trial.h[i] = (st.h[i] + alpha * dh[i]).max(0.1 * st.h[i]);
            }
            trial.h0 = st.h0 + alpha * dh0;
            let tres = self.residual(&trial, con);
            let f1 = Self::norm(&tres.r);
            if f1.is_finite() && (f1 < f0 * (1.0 - 1e-4 * alpha) || tries >= 6) {
                return (trial, tres, alpha);
            }
            alpha *= 0.5;
            tries += 1;
        }
    }

    /// Complementarity update of the cavitated set (each node may flip at most 8 times), then
    /// the free-boundary jump. Returns whether the set changed.
    fn update_active_set(&self, st: &mut State, q: &[NodeQ], flips: &mut [u8]) -> bool {
        let n = self.n();
        let mut changed = false;
        for i in 1..n - 1 {
            if st.cav[i] {
                // release where the flow balance asks for pressure
                let lam = -self.reynolds(st, q, i);
                if lam < 0.0 && flips[i] < 8 {
                    st.cav[i] = false;
                    flips[i] += 1;
                    changed = true;
                }
            } else if st.p[i] < self.pcav && flips[i] < 8 {
                st.cav[i] = true;
                st.p[i] = self.pcav;
                flips[i] += 1;
                changed = true;
            }
        }
        // free-boundary jump: release the cavitated nodes between the discrete exit and the
        // flux-balance estimate of the exit at once (the active set alone moves one node per
        // iteration)
        let kmax = (0..n).fold(0, |k, i| if st.p[i] > st.p[k] { i } else { k });
        if let Some((k, xc)) = self.exit(st, kmax) {
            let mut j = k;
            while j + 1 < n && st.cav[j] && self.x[j] < xc && flips[j] < 8 {
                st.cav[j] = false;
                flips[j] += 1;
                changed = true;
                j += 1;
            }
        }
        changed
    }
}

fn argmin(v: &[f64]) -> usize {
    let mut k = 0;
    for (i, &x) in v.iter().enumerate() {
        if x < v[k] {
            k = i;
        }
    }
    k
}

/// Pan–Hamrock central film (standard form, not in the seeds), used only for initial guesses.
fn film_estimate(mu0: f64, alpha: f64, um: f64, w: f64, ep: f64, r: f64) -> f64 {
    let u = mu0 * um.abs() / (ep * r);
    let wd = w / (ep * r);
    let g = (alpha * ep).max(100.0);
    PAN_HAMROCK_CENTRAL.film(wd, u, g) * r
}

/// Solves the line contact for the given constraint.
pub fn solve(
    contact: &LubricatedLineContact,
    viscosity: &dyn Viscosity,
    constraint: Constraint,
    options: &LineContactOptions,
) -> Result<LineContactResult> {
    match constraint {
        Constraint::MinFilm(h) if !contact.compliance.is_rigid() && h > 0.0 && h.is_finite() => {
            solve_min_film_elastic(contact, viscosity, h, options)
        }
        _ => solve_direct(contact, viscosity, constraint, options),
    }
}

/// Elastic contact at a given minimum film: Brent search on ln W of the load-controlled
/// solution (h_min decreases monotonically with W; a direct Newton on the discrete minimum can
/// settle on spurious constricted states), on a domain fixed from the largest load bracketed.
fn solve_min_film_elastic(
    contact: &LubricatedLineContact,
    viscosity: &dyn Viscosity,
    h_target: f64,
    options: &LineContactOptions,
) -> Result<LineContactResult> {
    let t0 = Instant::now();
    // first a direct solve for the starting estimate of load and domain
    let est = solve_direct(
        contact,
        viscosity,
        Constraint::MinFilm(h_target),
        &LineContactOptions {
            damping: false,
            ..*options
        },
    )
    .map(|r| r.load_per_length_n_per_m)
    .unwrap_or(0.0);
    let mu0 = viscosity.viscosity(0.0, contact.temperature);
    let w_rigid = analytic::kapitsa(mu0, contact.sum_speed().abs(), contact.radius, h_target).1;
    let start = est.max(w_rigid).max(1e-12);
    let ep = contact.compliance.e_prime().unwrap_or(2.3e11);
    // fixed domain from a generous load bound (16× the start)
    let domain = |w: f64| {
        let b = line_half_width(w, contact.radius, ep);
        let lh = (contact.radius * h_target).sqrt();
        (-(4.5 * b).max(30.0 * lh), (1.5 * b).max(5.0 * lh))
    };
    let (mut xin, mut xout) = domain(16.0 * start);
    if let Some(v) = options.inlet {
        xin = v;
    }
    if let Some(v) = options.outlet {
        xout = v;
    }
    let mut search = FilmSearch {
        contact,
        viscosity,
        h_target,
        options: LineContactOptions {
            inlet: Some(xin),
            outlet: Some(xout),
            damping: false,
            ..*options
        },
        iters: 0,
    };
    let mut res = search.root(start)?;
    if options.damping {
        // damping at the converged rigid approach (same domain)
        let d = solve_direct(
            contact,
            viscosity,
            Constraint::RigidApproach(res.rigid_approach_m),
            &LineContactOptions {
                damping: true,
                ..search.options
            },
        )?;
        search.iters += d.iterations;
        res.damping_ns_per_m2 = d.damping_ns_per_m2;
    }
    res.iterations = search.iters;
    res.solve_time_s = t0.elapsed().as_secs_f64();
    Ok(res)
}

/// The load search of [`solve_min_film_elastic`]: ln(h_min(W)/h) on a fixed domain.
struct FilmSearch<'a> {
    contact: &'a LubricatedLineContact,
    viscosity: &'a dyn Viscosity,
    /// Target minimum film, m.
    h_target: f64,
    /// Options of the load-controlled solves (fixed domain, no damping).
    options: LineContactOptions,
    /// Newton iterations of all solves.
    iters: usize,
}

impl FilmSearch<'_> {
    /// ln(h_min/h) of the load-controlled solution at `w` (N/m), and that solution.
    fn eval(&mut self, w: f64) -> Result<(f64, LineContactResult)> {
        let r = solve_direct(
            self.contact,
            self.viscosity,
            Constraint::LoadPerLength(w),
            &self.options,
        )?;
        self.iters += r.iterations;
        Ok(((r.min_film_m / self.h_target).ln(), r))
    }

    /// Bracket of the load from `start` (N/m): lowered, then raised, fourfold (12 steps in
    /// all) until ln(h_min/h) changes sign: (lo, hi, f(lo), f(hi)).
    fn bracket(&mut self, start: f64) -> Result<(f64, f64, f64, f64)> {
        let (mut lo, mut hi) = (start, start);
        let (mut flo, _) = self.eval(lo)?;
        let mut fhi = flo;
        let mut guard = 0;
        while flo < 0.0 && guard < 12 {
            hi = lo;
            fhi = flo;
            lo *= 0.25;
            flo = self.eval(lo)?.0;
            guard += 1;
        }
        while fhi > 0.0 && guard < 12 {
            lo = hi;
            flo = fhi;
            hi *= 4.0;
            fhi = self.eval(hi)?.0;
            guard += 1;
        }
        if flo * fhi > 0.0 {
            return Err(ReynoldsError::NoSolution(format!(
                "no load gives the minimum film {} m within [{lo:.3e}, {hi:.3e}] N/m",
                self.h_target
            )));
        }
        Ok((lo, hi, flo, fhi))
    }

    /// Brent search on ln W of the bracket from `start`: the solution at the root.
    fn root(&mut self, start: f64) -> Result<LineContactResult> {
        let (lo, hi, flo, fhi) = self.bracket(start)?;
        let mut last = None;
        let (lw, _, _) = crate::roots::brent(
            |u| {
                let (f, r) = self.eval(u.exp())?;
                last = Some(r);
                Ok(f)
            },
            lo.ln(),
            hi.ln(),
            flo,
            fhi,
            1e-10,
            1e-7,
            60,
        )?;
        match last {
            Some(r) if (r.load_per_length_n_per_m.ln() - lw).abs() < 1e-9 => Ok(r),
            _ => Ok(self.eval(lw.exp())?.1),
        }
    }
}

/// Solves the line contact on one domain (the domain and grid from the film and load estimate
/// unless the options fix them), with nested grids for elastic problems.
fn solve_direct(
    contact: &LubricatedLineContact,
    viscosity: &dyn Viscosity,
    constraint: Constraint,
    options: &LineContactOptions,
) -> Result<LineContactResult> {
    let t0 = Instant::now();
    check_input(contact, constraint, options)?;
    let plan = Plan::new(contact, viscosity, constraint, options)?;
    let n = options.nodes;
    let (xin, xout, lh) = (plan.xin, plan.xout, plan.lh);
    let grid = match options.grid {
        LineGrid::Uniform => Grid1d::uniform(xin, xout, n)?,
        LineGrid::Clustered(s) => Grid1d::clustered(xin, xout, n, 0.0, s)?,
        LineGrid::Auto if plan.elastic => Grid1d::uniform(xin, xout, n)?,
        LineGrid::Auto => Grid1d::clustered(xin, xout, n, 0.0, lh / 50.0)?,
    };
    let mut prob = build(contact, viscosity, &grid, options, plan.scales);
    let mut total_iters = 0usize;
    let (st, converged) = plan.nested_solve(&prob, &mut total_iters)?;
    let mut damping = 0.0;
    if options.damping && contact.sum_speed() != 0.0 {
        damping = prob.squeeze_damping(&st, options, &mut total_iters)?;
    }
    Ok(finish(
        &prob,
        &st,
        converged,
        total_iters,
        damping,
        plan.b,
        plan.ph,
        t0,
    ))
}

/// Rejects inputs without a solution: non-finite data, too few nodes, nothing driving the film,
/// an invalid constraint value.
fn check_input(
    contact: &LubricatedLineContact,
    constraint: Constraint,
    options: &LineContactOptions,
) -> Result<()> {
    positive("radius", contact.radius)?;
    finite("surface speed", contact.surface_speeds[0])?;
    finite("surface speed", contact.surface_speeds[1])?;
    finite("squeeze velocity", options.squeeze_velocity)?;
    positive("temperature", contact.temperature)?;
    if options.nodes < 20 {
        return Err(ReynoldsError::InvalidInput {
            what: "nodes",
            reason: format!("{} < 20", options.nodes),
        });
    }
    if contact.sum_speed() == 0.0 && options.squeeze_velocity == 0.0 {
        return Err(ReynoldsError::InvalidInput {
            what: "speed",
            reason: "zero rolling speed with zero squeeze velocity: no hydrodynamic film".into(),
        });
    }
    match constraint {
        Constraint::RigidApproach(h) => finite("rigid approach", h).map(|_| ())?,
        Constraint::MinFilm(h) => positive("minimum film", h).map(|_| ())?,
        Constraint::LoadPerLength(w) => positive("load per length", w).map(|_| ())?,
    }
    Ok(())
}

/// Film and load estimate, domain and scales of a direct solve.
struct Plan<'a> {
    contact: &'a LubricatedLineContact,
    viscosity: &'a dyn Viscosity,
    constraint: Constraint,
    options: &'a LineContactOptions,
    elastic: bool,
    /// Film estimate, m.
    h_est: f64,
    /// Hertz half-width (0 when rigid), m.
    b: f64,
    /// Hertz pressure (0 when rigid), Pa.
    ph: f64,
    /// Rigid inlet length √(R h_est), m.
    lh: f64,
    /// Domain [x_in, x_out], m.
    xin: f64,
    xout: f64,
    /// Scales (p_s, h_s, l_s, V_ref).
    scales: (f64, f64, f64, f64),
}

impl<'a> Plan<'a> {
    fn new(
        contact: &'a LubricatedLineContact,
        viscosity: &'a dyn Viscosity,
        constraint: Constraint,
        options: &'a LineContactOptions,
    ) -> Result<Self> {
        let r = contact.radius;
        let mu0 = viscosity.viscosity(0.0, contact.temperature);
        positive("viscosity μ(0, T)", mu0)?;
        let alpha0 = viscosity.dln_viscosity_dp(0.0, contact.temperature);
        let elastic = !contact.compliance.is_rigid();
        let ep = contact.compliance.e_prime().unwrap_or(0.0);
        let vabs = contact.sum_speed().abs().max(1e-300);
        let (h_est, w_est) = film_and_load_estimate(constraint, mu0, alpha0, vabs, r, elastic, ep);
        let b = if elastic {
            line_half_width(w_est, r, ep)
        } else {
            0.0
        };
        let lh = (r * h_est).sqrt();
        let xin = options.inlet.unwrap_or(if elastic {
            -(4.5 * b).max(30.0 * lh)
        } else {
            -100.0 * lh
        });
        let xout = options.outlet.unwrap_or((1.5 * b).max(5.0 * lh));
        if !(xin < 0.0 && xout > 0.0) {
            return Err(ReynoldsError::InvalidInput {
                what: "domain",
                reason: format!("need inlet < 0 < outlet, got [{xin}, {xout}]"),
            });
        }
        let p0 = analytic::pressure_scale(mu0, vabs, r, h_est);
        let ph = if elastic { ep * b / (4.0 * r) } else { 0.0 };
        let ls = if elastic { b.max(lh) } else { lh };
        let vref = vabs.max(options.squeeze_velocity.abs() * ls / h_est);
        Ok(Self {
            contact,
            viscosity,
            constraint,
            options,
            elastic,
            h_est,
            b,
            ph,
            lh,
            xin,
            xout,
            scales: (p0.max(ph), h_est, ls, vref),
        })
    }

    /// Node counts of the nested iteration, coarsest first: for elastic problems on fine grids,
    /// halving the node count down to ≈ 150.
    fn levels(&self) -> Vec<usize> {
        let n = self.options.nodes;
        let mut levels = vec![n];
        while self.elastic && *levels.last().unwrap_or(&n) / 2 >= 150 {
            let m = levels.last().copied().unwrap_or(n) / 2;
            levels.push(m);
        }
        levels.reverse();
        levels
    }

    /// Nested iteration for elastic problems on fine grids: converge on coarser grids first
    /// and interpolate; on each finer grid the Newton phase is then short and the pressure spike
    /// is resolved progressively. `prob` is the finest level.
    fn nested_solve(&self, prob: &Ehl, total_iters: &mut usize) -> Result<(State, bool)> {
        let (constraint, h_est, b, ph) = (self.constraint, self.h_est, self.b, self.ph);
        let levels = self.levels();
        let mut state: Option<(State, bool)> = None;
        let mut prev: Option<Ehl> = None;
        for (li, &m) in levels.iter().enumerate() {
            let last = li + 1 == levels.len();
            let pl = if last {
                None
            } else {
                Some(build(
                    self.contact,
                    self.viscosity,
                    &Grid1d::uniform(self.xin, self.xout, m)?,
                    self.options,
                    self.scales,
                ))
            };
            let pr: &Ehl = pl.as_ref().unwrap_or(prob);
            // coarse levels only provide a start: a looser tolerance is enough
            let lopt = if last {
                *self.options
            } else {
                LineContactOptions {
                    tolerance: self.options.tolerance.max(1e-4),
                    ..*self.options
                }
            };
            let options = &lopt;
            let next = match (&state, &prev) {
                (Some((s0, true)), Some(pp)) => {
                    let mut s1 = interpolate(pp, s0, pr);
                    let (ok, it) = pr.newton(&mut s1, constraint, options)?;
                    *total_iters += it;
                    if ok {
                        (s1, true)
                    } else {
                        solve_with_fallback(pr, constraint, options, h_est, b, ph, total_iters)?
                    }
                }
                _ => solve_with_fallback(pr, constraint, options, h_est, b, ph, total_iters)?,
            };
            state = Some(next);
            if !last {
                prev = pl;
            }
        }
        state.ok_or(ReynoldsError::Singular("line contact"))
    }
}

/// Film and load estimates, (h, W′): from the constraint, the Kapitsa rigid load and, for
/// elastic contacts, the Pan–Hamrock fits.
fn film_and_load_estimate(
    constraint: Constraint,
    mu0: f64,
    alpha0: f64,
    vabs: f64,
    r: f64,
    elastic: bool,
    ep: f64,
) -> (f64, f64) {
    match constraint {
        Constraint::RigidApproach(h) | Constraint::MinFilm(h) => {
            let h = h.abs().max(1e-9);
            let mut w = analytic::kapitsa(mu0, vabs, r, h).1;
            if elastic && alpha0 > 0.0 {
                // EHL load for this minimum film from the Pan–Hamrock fit (inverted), so that the
                // automatic domain covers the Hertzian zone at heavy loads
                let u = mu0 * 0.5 * vabs / (ep * r);
                let g = alpha0 * ep;
                let wd = PAN_HAMROCK_MINIMUM.load(h / r, u, g);
                w = w.max(wd * ep * r);
            }
            (h, w)
        }
        Constraint::LoadPerLength(w) => {
            let hr = 2.45 * mu0 * vabs * r / w;
            let h = if elastic {
                film_estimate(mu0, alpha0, 0.5 * vabs, w, ep, r).min(hr.max(1e-9))
            } else {
                hr
            };
            (h.max(1e-10), w)
        }
    }
}

/// Builds the discrete problem on `grid` with scales (p_s, h_s, l_s, V_ref).
fn build<'a>(
    contact: &'a LubricatedLineContact,
    viscosity: &'a dyn Viscosity,
    grid: &Grid1d,
    options: &LineContactOptions,
    scales: (f64, f64, f64, f64),
) -> Ehl<'a> {
    let n = grid.len();
    let r = contact.radius;
    let x = grid.x.clone();
    let cell = grid.cell_widths();
    let geom: Vec<f64> = x
        .iter()
        .map(|&xi| xi * xi / (2.0 * r) + contact.waviness.value(xi))
        .collect();
    let infl = (!contact.compliance.is_rigid()).then(|| Influence::new(grid, &contact.compliance));
    let w = options.near_band.max(1);
    let mut ld_near = Vec::new();
    if let Some(inf) = &infl {
        let wb = 2 * w + 1;
        ld_near = vec![0.0; n * wb];
        for i in 1..n - 1 {
            let a = 2.0 / ((x[i + 1] - x[i - 1]) * (x[i] - x[i - 1]));
            let c = 2.0 / ((x[i + 1] - x[i - 1]) * (x[i + 1] - x[i]));
            let l = [a, -(a + c), c];
            for j in i.saturating_sub(w)..=(i + w).min(n - 1) {
                ld_near[i * wb + (j + w - i)] =
                    l[0] * inf.get(i - 1, j) + l[1] * inf.get(i, j) + l[2] * inf.get(i + 1, j);
            }
        }
    }
    let (ps, hs, ls, vref) = scales;
    Ehl {
        c: contact,
        visc: viscosity,
        x,
        cell,
        geom,
        infl,
        ld_near,
        w,
        lin_tol: 1e-6,
        vy: options.squeeze_velocity,
        pcav: options.cavitation_pressure,
        ps,
        hs,
        ls,
        vref,
    }
}

/// Linear interpolation of a state between grids (cavitated where the source is).
fn interpolate(from: &Ehl, st: &State, to: &Ehl) -> State {
    let n = to.n();
    let xs = &from.x;
    let mut out = State {
        p: vec![0.0; n],
        h: vec![0.0; n],
        h0: st.h0,
        cav: vec![false; n],
    };
    let mut k = 0;
    for i in 0..n {
        let x = to.x[i];
        while k + 2 < xs.len() && xs[k + 1] < x {
            k += 1;
        }
        let t = ((x - xs[k]) / (xs[k + 1] - xs[k])).clamp(0.0, 1.0);
        out.p[i] = st.p[k] + t * (st.p[k + 1] - st.p[k]);
        out.h[i] = st.h[k] + t * (st.h[k + 1] - st.h[k]);
        out.cav[i] = st.cav[k] && st.cav[k + 1] && i > 0 && i + 1 < n;
        if out.cav[i] {
            out.p[i] = to.pcav;
        }
    }
    out.p[0] = 0.0;
    out.p[n - 1] = 0.0;
    out
}

/// Newton from an initial guess on `prob`; for elastic problems under a load, with load
/// continuation when the direct attempt fails.
fn solve_with_fallback(
    prob: &Ehl,
    con: Constraint,
    opt: &LineContactOptions,
    h_est: f64,
    b: f64,
    ph: f64,
    iters: &mut usize,
) -> Result<(State, bool)> {
    let n = prob.n();
    match con {
        Constraint::LoadPerLength(w) if prob.infl.is_some() => {
            prob.load_continuation(w, opt, 0, iters, (h_est, b, ph))
        }
        Constraint::LoadPerLength(_) => {
            let mut st = prob.initial_state(con, h_est, 0.0, 0.0);
            let (ok, it) = prob.newton(&mut st, con, opt)?;
            *iters += it;
            Ok((st, ok))
        }
        Constraint::RigidApproach(h) | Constraint::MinFilm(h) => {
            let mut st = prob.initial_state(con, h.abs().max(1e-12), 0.0, 0.0);
            if let Constraint::RigidApproach(a) = con {
                st.h0 = a;
                let d = prob.deflection(&st.p);
                for i in 0..n {
                    st.h[i] = a + prob.geom[i] + d[i];
                }
            }
            let (ok, it) = prob.newton(&mut st, con, opt)?;
            *iters += it;
            Ok((st, ok))
        }
    }
}

impl Ehl<'_> {
    /// Direct attempt at the load `w` from the Hertz guess with `(h, b, p_h)`, then load
    /// continuation: solve at half the load (Hertz scaling of b and p_h) and return from there.
    fn load_continuation(
        &self,
        w: f64,
        opt: &LineContactOptions,
        depth: usize,
        iters: &mut usize,
        (h_est, b, ph): (f64, f64, f64),
    ) -> Result<(State, bool)> {
        let mut st = self.initial_state(Constraint::LoadPerLength(w), h_est, b, ph);
        let (ok, it) = self.newton(&mut st, Constraint::LoadPerLength(w), opt)?;
        *iters += it;
        if ok || depth >= opt.continuation_steps {
            return Ok((st, ok));
        }
        let lighter_guess = (
            h_est * 1.1,
            b * std::f64::consts::FRAC_1_SQRT_2,
            ph * std::f64::consts::FRAC_1_SQRT_2,
        );
        let (lighter, ok_l) =
            self.load_continuation(0.5 * w, opt, depth + 1, iters, lighter_guess)?;
        if !ok_l {
            return Ok((lighter, false));
        }
        let mut st = lighter;
        let (ok, it) = self.newton(&mut st, Constraint::LoadPerLength(w), opt)?;
        *iters += it;
        Ok((st, ok))
    }

    /// Initial guess: Hertz pressure with the film `hload` for elastic problems under a load
    /// (half-width `bb`, pressure `phh`); otherwise the rigid analytic (Martin, Barus-reduced)
    /// solution at the film `hload`. Ambient pressure, full film at both ends.
    fn initial_state(&self, con: Constraint, hload: f64, bb: f64, phh: f64) -> State {
        let n = self.n();
        let mut st =
            if self.infl.is_some() && matches!(con, Constraint::LoadPerLength(_)) && bb > 0.0 {
                self.hertz_start(hload, bb, phh)
            } else {
                self.martin_start(hload)
            };
        st.p[0] = 0.0;
        st.p[n - 1] = 0.0;
        st.cav[0] = false;
        st.cav[n - 1] = false;
        st
    }

    /// Hertz pressure over |x| < b, cavitated beyond 1.2 b, film `hload` at the centre.
    fn hertz_start(&self, hload: f64, bb: f64, phh: f64) -> State {
        let n = self.n();
        let mut st = State {
            p: vec![0.0; n],
            h: vec![0.0; n],
            h0: 0.0,
            cav: vec![false; n],
        };
        for i in 0..n {
            let xi = self.x[i];
            if xi.abs() < bb {
                st.p[i] = phh * (1.0 - (xi / bb).powi(2)).sqrt();
            }
            st.cav[i] = xi > 1.2 * bb;
        }
        let d = self.deflection(&st.p);
        let k0 = argmin(&self.x.iter().map(|v| v.abs()).collect::<Vec<_>>());
        st.h0 = hload - self.geom[k0] - d[k0];
        for i in 0..n {
            st.h[i] = st.h0 + self.geom[i] + d[i];
        }
        st
    }

    /// Rigid Martin solution with squeeze at the film `hm`, the pressure reduced by Barus with
    /// the initial pressure–viscosity slope.
    fn martin_start(&self, hm: f64) -> State {
        let n = self.n();
        let r = self.c.radius;
        let mut st = State {
            p: vec![0.0; n],
            h: vec![0.0; n],
            h0: 0.0,
            cav: vec![false; n],
        };
        let lh = (r * hm).sqrt();
        let v = self.c.sum_speed().abs().max(1e-300);
        let nu = self.vy / v * (r / hm).sqrt();
        let c = analytic::exit_parameter(nu.clamp(-0.2, 0.2)).unwrap_or(0.67);
        let mu0 = self.visc.viscosity(0.0, self.c.temperature);
        let p0 = analytic::pressure_scale(mu0, v, r, hm);
        let al = self.visc.dln_viscosity_dp(0.0, self.c.temperature) * p0;
        for i in 0..n {
            let xt = self.x[i] / lh;
            let q = if xt < c {
                analytic::q(xt, c, nu.clamp(-0.2, 0.2)).max(0.0)
            } else {
                0.0
            };
            let qq = if al > 0.0 && al * q < 0.95 {
                -(1.0 - al * q).ln() / al
            } else {
                q
            };
            st.p[i] = qq * p0;
            st.cav[i] = xt > 1.3 * c + 0.2;
        }
        st.h0 = hm;
        let d = self.deflection(&st.p);
        for i in 0..n {
            st.h[i] = hm + self.geom[i] + d[i];
        }
        st
    }
}

#[allow(clippy::too_many_arguments)]
fn finish(
    prob: &Ehl,
    st: &State,
    converged: bool,
    iterations: usize,
    damping: f64,
    b: f64,
    ph: f64,
    t0: Instant,
) -> LineContactResult {
    let n = prob.n();
    let x = &prob.x;
    let load: f64 = st.p.iter().zip(&prob.cell).map(|(p, c)| p * c).sum();
    let kmax = (0..n).fold(0, |k, i| if st.p[i] > st.p[k] { i } else { k });
    // minimum film with a parabolic refinement
    let km = argmin(&st.h);
    let mut hmin = st.h[km];
    if km > 0 && km + 1 < n {
        let (a, bb, c) = (st.h[km - 1], st.h[km], st.h[km + 1]);
        let den = a - 2.0 * bb + c;
        if den > 0.0 {
            hmin = bb - (c - a) * (c - a) / (8.0 * den);
        }
    }
    // central film: linear interpolation at x = 0
    let kc = x.iter().position(|&v| v >= 0.0).unwrap_or(n - 1).max(1);
    let t = (0.0 - x[kc - 1]) / (x[kc] - x[kc - 1]);
    let hc = st.h[kc - 1] + t * (st.h[kc] - st.h[kc - 1]);
    let xc = prob.exit(st, kmax).map(|(_, xc)| xc).unwrap_or(x[n - 1]);
    LineContactResult {
        load_per_length_n_per_m: load,
        max_pressure_pa: st.p[kmax],
        min_film_m: hmin,
        central_film_m: hc,
        outlet_position_m: xc,
        rigid_approach_m: st.h0,
        damping_ns_per_m2: damping,
        hertz_half_width_m: b,
        hertz_pressure_pa: ph,
        pressure: x.iter().zip(&st.p).map(|(a, b)| (*a, *b)).collect(),
        film: x.iter().zip(&st.h).map(|(a, b)| (*a, *b)).collect(),
        iterations,
        converged,
        solve_time_s: t0.elapsed().as_secs_f64(),
    }
}
