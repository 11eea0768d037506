//! Linearly implicit Rosenbrock-W method ROS34PW2 (Rang & Angermann, *BIT* 45 (2005) 761–787:
//! 4 stages, order 3 for **any** approximation of the Jacobian, embedded order 2, A-stable,
//! stiffly accurate) with a block-structured finite-difference Jacobian that is reused over many
//! steps.
//!
//! W-methods (Steihaug & Wolfbrandt 1979; Hairer & Wanner, *Solving ODEs II*, §IV.7, "W-methods")
//! are Rosenbrock methods whose order conditions hold for an arbitrary matrix `A` in place of the
//! Jacobian `∂f/∂y`; only the stability depends on how well `A` describes the stiff modes. That
//! licenses three simplifications used here:
//!
//! * `A` is **block-diagonal per body**: a block for each roller (its own 12 state components),
//!   one for the cage and one for the inner ring. The stiff modes — a roller squeezed between
//!   the two raceways (radial), between two cage bars (circumferential/yaw), the steep
//!   traction-slip curves acting on its orbital speed and spin — live inside a roller's own
//!   block. Optionally ([`JacobianBorder`], [`RosenbrockW::with_border`]; the tapered bearing)
//!   `A` is **bordered**: each roller's block is also coupled both ways with the state of its
//!   cage and of the inner ring (the border), which is the whole Jacobian there (no roller acts
//!   on another roller, nor the cages on the ring, except through the rollers). The stage
//!   matrix `[[D, B], [C, R]]` (`D` the roller blocks, `R` the border blocks) is then solved by
//!   block elimination with the Schur complement `S = R − Σ_j C_j D_j⁻¹ B_j` on the border
//!   (32 unknowns for the tapered bearing's two cages and ring), factored with the roller
//!   blocks whenever `h` changes by more than a set ratio.
//! * `A` is obtained by forward differences of the full right-hand side with **column
//!   colouring**: a roller's derivative depends on no other roller's state, so perturbing
//!   component `k` of *all* rollers at once gives column `k` of every roller block in one
//!   evaluation (12 evaluations for all rollers, 13 for the cage, 6 for the inner ring). With a
//!   border the same evaluations give the couplings: a roller column changes each roller's
//!   share of its cage's and the ring's rates, which the system records
//!   ([`OdeSystem::border_shares`]), and a border column changes the rates of every roller that
//!   touches that body (each roller touches one of the two cages).
//! * `A` is **reused** for [`crate::IntegratorSettings::jacobian_interval`] accepted steps and
//!   optionally refreshed after a rejected step (unless it is already fresh; off by default —
//!   measured in `docs/dynamics-integrator.md`, most rejections here come from contact
//!   switching, which a Jacobian at the old state does not help). A non-finite trial always
//!   forces a new Jacobian unless it is fresh.
//!   Time dependence of `f` (speed ramps, rotating loads) enters only through the stage times:
//!   the autonomised system is integrated with an approximate Jacobian whose time column is
//!   zero, which a W-method allows without loss of order.
//!
//! The stages are computed in the transformed variables `u_i = Σ_j γ_ij k_j` of Hairer & Wanner
//! (§IV.7, eq. (7.4')), so no product with `A` is ever needed:
//! `(1/(γh) I − A) u_i = f(t + α_i h, y + Σ_j a_ij u_j) + Σ_j (c_ij/h) u_j`,
//! `y₁ = y + Σ m_j u_j`. Each stage solve is a set of small dense LU solves (12 × 12 per
//! roller; with a border also the Schur complement's), the LU is refactored when `h` changes by
//! more than [`crate::IntegratorSettings::refactor_step_ratio`] (kept factors stand for a
//! shifted `A`, see `RosenbrockW::needs_factor`). The first stage uses `f(t, y)` from the end of
//! the previous step, so an accepted step costs 4 right-hand sides (3 stages + the new state,
//! which is also what leaves the per-evaluation diagnostics describing the accepted state).
//! Dense output: cubic Hermite interpolation between `(y₀, f₀)` and `(y₁, f₁)` (Hairer, Nørsett
//! & Wanner, *Solving ODEs I*, §II.6, eq. (6.7)), third order like the method.
//!
//! Every buffer is allocated once; a step allocates nothing and is bit-for-bit deterministic.

// coefficients quoted with the digits of the publication; index loops mirror the formulas
#![allow(clippy::excessive_precision, clippy::needless_range_loop)]

use crate::integrator::{OdeSystem, StepError, StepStats};
use crate::settings::IntegratorSettings;
use rolldyn_numerics::dense_lu;

const STAGES: usize = 4;
/// Diagonal γ of ROS34PW2.
const GAMMA: f64 = 0.435866521508459;
/// α_ij (strictly lower triangular).
const ALPHA: [[f64; STAGES]; STAGES] = [
    [0.0, 0.0, 0.0, 0.0],
    [0.87173304301691801, 0.0, 0.0, 0.0],
    [0.84457060015369423, -0.11299064236484185, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
];
/// γ_ij (strictly lower part; the diagonal is [`GAMMA`]).
const GAMMA_IJ: [[f64; STAGES]; STAGES] = [
    [0.0, 0.0, 0.0, 0.0],
    [-0.87173304301691801, 0.0, 0.0, 0.0],
    [-0.90338057013044082, 0.054180672388095326, 0.0, 0.0],
    [
        0.24212380706095346,
        -1.2232505839045147,
        0.54526025533510214,
        0.0,
    ],
];
/// Weights of the 3rd-order solution.
const B: [f64; STAGES] = [
    0.24212380706095346,
    -1.2232505839045147,
    1.5452602553351020,
    0.435866521508459,
];
/// Weights of the embedded 2nd-order solution.
const BHAT: [f64; STAGES] = [
    0.37810903145819369,
    -0.096042292212423178,
    0.5,
    0.2179332607542295,
];

/// Coefficients of the transformed formulation (Hairer & Wanner §IV.7, eq. (7.4')):
/// `a = α Γ⁻¹`, `c = diag(1/γ) − Γ⁻¹`, `m = b Γ⁻¹`, `e = (b − b̂) Γ⁻¹`, `α_i = Σ_j α_ij`.
#[derive(Debug, Clone, Copy)]
struct Tableau {
    a: [[f64; STAGES]; STAGES],
    c: [[f64; STAGES]; STAGES],
    m: [f64; STAGES],
    e: [f64; STAGES],
    alpha: [f64; STAGES],
}

impl Tableau {
    fn new() -> Self {
        // Γ⁻¹ of the lower-triangular Γ by forward substitution
        let mut g = [[0.0; STAGES]; STAGES];
        for (i, row) in g.iter_mut().enumerate() {
            row[..i].copy_from_slice(&GAMMA_IJ[i][..i]);
            row[i] = GAMMA;
        }
        let mut gi = [[0.0; STAGES]; STAGES];
        for col in 0..STAGES {
            for i in 0..STAGES {
                let mut s = if i == col { 1.0 } else { 0.0 };
                for k in 0..i {
                    s -= g[i][k] * gi[k][col];
                }
                gi[i][col] = s / g[i][i];
            }
        }
        let mut t = Self {
            a: [[0.0; STAGES]; STAGES],
            c: [[0.0; STAGES]; STAGES],
            m: [0.0; STAGES],
            e: [0.0; STAGES],
            alpha: [0.0; STAGES],
        };
        for i in 0..STAGES {
            for j in 0..i {
                t.a[i][j] = (0..STAGES).map(|k| ALPHA[i][k] * gi[k][j]).sum();
                t.c[i][j] = -gi[i][j];
            }
            t.alpha[i] = ALPHA[i].iter().sum();
        }
        for j in 0..STAGES {
            t.m[j] = (0..STAGES).map(|i| B[i] * gi[i][j]).sum();
            t.e[j] = (0..STAGES).map(|i| (B[i] - BHAT[i]) * gi[i][j]).sum();
        }
        t
    }
}

/// One diagonal block of the approximate Jacobian: state components `start..start + n`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct JacobianBlock {
    /// first state component
    pub start: usize,
    /// number of components
    pub n: usize,
}

/// Couplings of a bordered Jacobian: every block of colour group `group` (the *coupled* blocks,
/// e.g. the rollers) is coupled both ways with some components of the blocks of the other groups
/// (the *border*, e.g. the cages and the inner ring). The border's own Jacobian stays
/// block-diagonal per block (its bodies act on each other only through the coupled blocks).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct JacobianBorder {
    /// the colour group of the coupled blocks
    pub group: usize,
    /// per block of `group`, in order: the border state components its rates depend on and
    /// whose rates depend on its state; of each other colour group it may touch one block only
    /// (one right-hand side per column then serves every coupled block). Its shares of the
    /// border rates come from [`OdeSystem::border_shares`] in this order.
    pub support: Vec<Vec<usize>>,
}

/// The coupling blocks of a bordered Jacobian and the factors of its Schur complement.
#[derive(Debug, Clone)]
pub(crate) struct Border {
    /// the colour group of the coupled blocks (their indices in `RosenbrockW::blocks`)
    group: usize,
    coupled: Vec<usize>,
    /// per coupled block: positions of its support in `comps`
    support: Vec<Vec<usize>>,
    /// the border's state components: the unknowns of the Schur complement
    comps: Vec<usize>,
    /// the blocks that make up the border, and the position of each in `comps`
    border_blocks: Vec<(usize, usize)>,
    /// per colour group: `(coupled block c, support index q, border block, its column k)` for
    /// every support component that lies in a block of the group
    columns: Vec<Vec<(usize, usize, usize, usize)>>,
    /// per coupled block: offset of its `n × s` matrices and of its `s` shares
    off: Vec<usize>,
    soff: Vec<usize>,
    /// `∂f_b/∂y_support` (`n × s`, row-major) and `∂f_support/∂y_b` (`s × n`) per coupled block
    pub(crate) jac_rows: Vec<f64>,
    pub(crate) jac_cols: Vec<f64>,
    /// `D_b⁻¹ B_b` per coupled block, `n × s` row-major like `jac_rows`
    x: Vec<f64>,
    /// scratch of `s` values (the largest support): a row of `C_b D_b⁻¹ B_b`, the border
    /// unknowns of a block's support
    schur_row: Vec<f64>,
    /// LU factors of the Schur complement `S` and its pivots
    schur: Vec<f64>,
    piv: Vec<usize>,
    /// `S` is factored (otherwise the border blocks are solved on their own)
    active: bool,
    /// the coupled blocks' shares of the border rates at `y` (valid flag), at the trial state,
    /// and scratch
    pub(crate) shares0: Vec<f64>,
    pub(crate) shares0_valid: bool,
    shares_new: Vec<f64>,
    shares_tmp: Vec<f64>,
    g: Vec<f64>,
}

/// The integrator state of the Rosenbrock-W method (everything needed to continue a run
/// bit-for-bit is listed in `Stepper::save` (`src/stepper.rs`)).
#[derive(Debug, Clone)]
pub struct RosenbrockW {
    /// current time, s
    pub t: f64,
    /// current state
    pub y: Vec<f64>,
    /// next step size to try, s
    pub h: f64,
    /// previous accepted error (PI memory)
    pub err_old: f64,
    /// size of the previous accepted step (0: none yet), memory of the predictive controller
    pub h_prev: f64,
    /// whether the last attempt was rejected
    pub last_rejected: bool,
    /// `f(t, y)` is in `f0`
    pub f0_valid: bool,
    /// step statistics
    pub stats: StepStats,
    /// per-component error scale `s_i`
    pub scale: Vec<f64>,
    /// per-component relative flag `ρ_i`
    pub relative: Vec<f64>,
    tab: Tableau,
    blocks: Vec<JacobianBlock>,
    /// colour groups: indices into `blocks`, all of one size, mutually independent
    groups: Vec<Vec<usize>>,
    /// components not in any block (their Jacobian approximation is zero)
    free: Vec<usize>,
    /// offset of each block in `jac`/`lu` (n² values) and in `piv` (n values)
    off: Vec<usize>,
    poff: Vec<usize>,
    pub(crate) jac: Vec<f64>,
    lu: Vec<f64>,
    piv: Vec<usize>,
    delta: Vec<f64>,
    /// `A` holds a Jacobian evaluated at an earlier accepted state
    pub(crate) jac_valid: bool,
    /// accepted steps since the Jacobian evaluation
    pub(crate) jac_age: u64,
    /// step size of the current LU factors (0: none)
    lu_h: f64,
    pub(crate) f0: Vec<f64>,
    u: [Vec<f64>; STAGES],
    ytmp: Vec<f64>,
    ftmp: Vec<f64>,
    ynew: Vec<f64>,
    /// the couplings of a bordered Jacobian ([`RosenbrockW::with_border`]; `None`: block-diagonal)
    pub(crate) border: Option<Border>,
    /// dense output of the last accepted step: `[dense_t, dense_t + dense_h]`, `y₀`, `f₀`
    /// (the end values are `y`, `f0`)
    pub(crate) dense_t: f64,
    pub(crate) dense_h: f64,
    pub(crate) dense_y0: Vec<f64>,
    pub(crate) dense_f0: Vec<f64>,
}

impl RosenbrockW {
    /// New integrator at `(t, y)` with error scales and the block structure of the approximate
    /// Jacobian: `groups` lists colour groups of blocks; all blocks of a group must have the
    /// same size, and the derivative of a block's components must not depend on the state of
    /// another block of the same group (one right-hand side per column then serves the whole
    /// group). Blocks must not overlap; components outside every block get a zero Jacobian.
    pub fn new(
        t: f64,
        y: Vec<f64>,
        scale: Vec<f64>,
        relative: Vec<f64>,
        h0: f64,
        groups: &[Vec<JacobianBlock>],
    ) -> Self {
        let n = y.len();
        let z = || vec![0.0; n];
        let mut blocks = Vec::new();
        let mut gidx = Vec::new();
        let mut covered = vec![false; n];
        for g in groups {
            let mut ids = Vec::new();
            for b in g {
                assert!(
                    b.n == g[0].n && b.start + b.n <= n,
                    "Jacobian blocks of a group must have equal size and lie inside the state"
                );
                for c in &mut covered[b.start..b.start + b.n] {
                    assert!(!*c, "Jacobian blocks overlap");
                    *c = true;
                }
                ids.push(blocks.len());
                blocks.push(*b);
            }
            gidx.push(ids);
        }
        let free = (0..n).filter(|&i| !covered[i]).collect();
        let mut off = Vec::with_capacity(blocks.len());
        let mut poff = Vec::with_capacity(blocks.len());
        let (mut o, mut p) = (0, 0);
        for b in &blocks {
            off.push(o);
            poff.push(p);
            o += b.n * b.n;
            p += b.n;
        }
        Self {
            t,
            h: h0,
            err_old: 1e-4,
            h_prev: 0.0,
            last_rejected: false,
            f0_valid: false,
            stats: StepStats {
                limiting: vec![0; n],
                ..StepStats::default()
            },
            scale,
            relative,
            tab: Tableau::new(),
            delta: vec![0.0; blocks.len()],
            blocks,
            groups: gidx,
            free,
            off,
            poff,
            jac: vec![0.0; o],
            lu: vec![0.0; o],
            piv: vec![0; p],
            jac_valid: false,
            jac_age: 0,
            lu_h: 0.0,
            f0: z(),
            u: [z(), z(), z(), z()],
            ytmp: z(),
            ftmp: z(),
            ynew: z(),
            border: None,
            dense_t: t,
            dense_h: 0.0,
            dense_y0: y.clone(),
            dense_f0: z(),
            y,
        }
    }

    /// Couples the blocks of `border.group` with the border (the blocks of the other groups):
    /// the Jacobian then also holds `∂f_b/∂y_border` (by the same coloured differences) and
    /// `∂f_border/∂y_b` (from the coupled blocks' shares of the border rates,
    /// [`OdeSystem::border_shares`], recorded in the same evaluations), and every stage is solved
    /// as one bordered block system by the Schur complement on the border.
    pub fn with_border(mut self, border: &JacobianBorder) -> Self {
        let n = self.y.len();
        let coupled = self.groups[border.group].clone();
        assert_eq!(
            coupled.len(),
            border.support.len(),
            "one support per coupled block"
        );
        let mut comps = Vec::new();
        let mut border_blocks = Vec::new();
        let mut owner = vec![None; n];
        for (g, ids) in self.groups.iter().enumerate() {
            if g == border.group {
                continue;
            }
            for &b in ids {
                let blk = self.blocks[b];
                border_blocks.push((b, comps.len()));
                for k in 0..blk.n {
                    owner[blk.start + k] = Some((g, b, k, comps.len()));
                    comps.push(blk.start + k);
                }
            }
        }
        let mut columns = vec![Vec::new(); self.groups.len()];
        let mut support = Vec::new();
        let (mut off, mut soff) = (Vec::new(), Vec::new());
        let (mut o, mut so) = (0, 0);
        for (c, sup) in border.support.iter().enumerate() {
            let nb = self.blocks[coupled[c]].n;
            let mut positions = Vec::with_capacity(sup.len());
            for (q, &i) in sup.iter().enumerate() {
                let (g, b, k, pos) = owner[i].expect("a support component lies in a border block");
                positions.push(pos);
                columns[g].push((c, q, b, k));
            }
            off.push(o);
            soff.push(so);
            o += nb * sup.len();
            so += sup.len();
            support.push(positions);
        }
        let m = comps.len();
        self.border = Some(Border {
            group: border.group,
            coupled,
            support,
            comps,
            border_blocks,
            columns,
            off,
            soff,
            jac_rows: vec![0.0; o],
            jac_cols: vec![0.0; o],
            x: vec![0.0; o],
            schur_row: vec![0.0; border.support.iter().map(Vec::len).max().unwrap_or(0)],
            schur: vec![0.0; m * m],
            piv: vec![0; m],
            active: false,
            shares0: vec![0.0; so],
            shares0_valid: false,
            shares_new: vec![0.0; so],
            shares_tmp: vec![0.0; so],
            g: vec![0.0; m],
        });
        self
    }

    /// Dimension.
    pub fn dim(&self) -> usize {
        self.y.len()
    }

    /// Forces a new Jacobian (and `f(t, y)`) before the next step (the system changed).
    pub fn invalidate(&mut self) {
        self.f0_valid = false;
        self.jac_valid = false;
    }

    /// Forward-difference Jacobian blocks at `(t, y)` with column colouring; needs `f0`. With a
    /// border, the same evaluations give the coupling blocks: perturbing column `k` of every
    /// coupled block changes each one's shares of the border rates (`∂f_border/∂y_b`), perturbing
    /// a border column changes the rates of the coupled blocks that touch it (`∂f_b/∂y_border`).
    fn evaluate_jacobian<S: OdeSystem + ?Sized>(&mut self, sys: &mut S) {
        let sq = f64::EPSILON.sqrt();
        if let Some(bd) = self.border.as_mut()
            && !bd.shares0_valid
        {
            sys.rhs(self.t, &self.y, &mut self.ftmp);
            self.stats.rhs_evaluations += 1;
            sys.border_shares(&mut bd.shares0);
            bd.shares0_valid = true;
        }
        for g in 0..self.groups.len() {
            let nb = self.blocks[self.groups[g][0]].n;
            for k in 0..nb {
                self.ytmp.copy_from_slice(&self.y);
                for &b in &self.groups[g] {
                    let i = self.blocks[b].start + k;
                    let d = sq * self.y[i].abs().max(self.scale[i]);
                    let yp = self.y[i] + d;
                    self.ytmp[i] = yp;
                    self.delta[b] = yp - self.y[i];
                }
                sys.rhs(self.t, &self.ytmp, &mut self.ftmp);
                self.stats.rhs_evaluations += 1;
                for &b in &self.groups[g] {
                    let blk = self.blocks[b];
                    let inv = 1.0 / self.delta[b];
                    for r in 0..nb {
                        let i = blk.start + r;
                        let v = (self.ftmp[i] - self.f0[i]) * inv;
                        self.jac[self.off[b] + r * nb + k] = if v.is_finite() { v } else { 0.0 };
                    }
                }
                if let Some(bd) = self.border.as_mut() {
                    if g == bd.group {
                        sys.border_shares(&mut bd.shares_tmp);
                        for (c, &b) in bd.coupled.iter().enumerate() {
                            let inv = 1.0 / self.delta[b];
                            for q in 0..bd.support[c].len() {
                                let i = bd.soff[c] + q;
                                let v = (bd.shares_tmp[i] - bd.shares0[i]) * inv;
                                bd.jac_cols[bd.off[c] + q * nb + k] =
                                    if v.is_finite() { v } else { 0.0 };
                            }
                        }
                    } else {
                        for &(c, q, b, kb) in &bd.columns[g] {
                            if kb != k {
                                continue;
                            }
                            let blk = self.blocks[bd.coupled[c]];
                            let s = bd.support[c].len();
                            let inv = 1.0 / self.delta[b];
                            for r in 0..blk.n {
                                let i = blk.start + r;
                                let v = (self.ftmp[i] - self.f0[i]) * inv;
                                bd.jac_rows[bd.off[c] + r * s + q] =
                                    if v.is_finite() { v } else { 0.0 };
                            }
                        }
                    }
                }
            }
        }
        self.stats.jacobian_evaluations += 1;
        self.jac_valid = true;
        self.jac_age = 0;
        self.lu_h = 0.0;
    }

    /// LU factors of `1/(γh) I − A` per block. A block whose matrix is singular falls back to
    /// a zero Jacobian (still a valid W-method, only less stable). With a border, also the
    /// Schur complement `S = R − Σ_b C_b D_b⁻¹ B_b` of the bordered matrix
    /// `[[D, B], [C, R]]` (`D` the coupled blocks, `R` the border blocks, `B`, `C` the
    /// couplings: minus the Jacobian's coupling blocks); a singular `S` leaves the border
    /// blocks uncoupled for this step size.
    fn factor(&mut self, h: f64) {
        let d = 1.0 / (GAMMA * h);
        for (b, blk) in self.blocks.iter().enumerate() {
            let n = blk.n;
            let (o, p) = (self.off[b], self.poff[b]);
            let lu = &mut self.lu[o..o + n * n];
            let jac = &mut self.jac[o..o + n * n];
            for (l, &j) in lu.iter_mut().zip(jac.iter()) {
                *l = -j;
            }
            for r in 0..n {
                lu[r * n + r] += d;
            }
            if dense_lu::factor_in_place(lu, &mut self.piv[p..p + n]).is_err() {
                jac.fill(0.0);
                lu.fill(0.0);
                for r in 0..n {
                    lu[r * n + r] = d;
                    self.piv[p + r] = r;
                }
            }
        }
        if let Some(bd) = self.border.as_mut() {
            let m = bd.comps.len();
            bd.schur.fill(0.0);
            for &(b, pos) in &bd.border_blocks {
                let n = self.blocks[b].n;
                let o = self.off[b];
                for r in 0..n {
                    for k in 0..n {
                        bd.schur[(pos + r) * m + pos + k] = -self.jac[o + r * n + k];
                    }
                    bd.schur[(pos + r) * m + pos + r] += d;
                }
            }
            for (c, &b) in bd.coupled.iter().enumerate() {
                let n = self.blocks[b].n;
                let (o, p) = (self.off[b], self.poff[b]);
                let sup = &bd.support[c];
                let s = sup.len();
                let oc = bd.off[c];
                // X = D_b⁻¹ B_b, B_b = −∂f_b/∂y_support, all s columns in one solve
                let xb = &mut bd.x[oc..oc + n * s];
                for (v, &j) in xb.iter_mut().zip(&bd.jac_rows[oc..oc + n * s]) {
                    *v = -j;
                }
                dense_lu::solve_columns_in_place(
                    &self.lu[o..o + n * n],
                    &self.piv[p..p + n],
                    xb,
                    s,
                );
                // S −= C_b X, C_b = −∂f_support/∂y_b (rows the block does not enter are zero),
                // one row of S at a time along the rows of X
                let product = &mut bd.schur_row[..s];
                for (qr, &pr) in sup.iter().enumerate() {
                    let crow = &bd.jac_cols[oc + qr * n..oc + (qr + 1) * n];
                    if crow.iter().all(|&v| v == 0.0) {
                        continue;
                    }
                    product.fill(0.0);
                    for (&c, xrow) in crow.iter().zip(xb.chunks_exact(s)) {
                        for (acc, &xv) in product.iter_mut().zip(xrow) {
                            *acc += c * xv;
                        }
                    }
                    for (&pc, &v) in sup.iter().zip(product.iter()) {
                        bd.schur[pr * m + pc] += v;
                    }
                }
            }
            bd.active = dense_lu::factor_in_place(&mut bd.schur, &mut bd.piv).is_ok();
        }
        self.lu_h = h;
    }

    /// Whether the factors must be rebuilt for a step of size `h`: none exist, or `h` differs
    /// from their step size `lu_h` by more than the ratio `max_ratio` (0: any difference).
    /// Kept factors are those of `I/(γ lu_h) − A = I/(γh) − A'` with
    /// `A' = A + (1/(γh) − 1/(γ lu_h)) I`, so a step with them is the W-method with the matrix
    /// `A'` at step size `h` (order kept, Hairer & Wanner II, §IV.7): in the transformed stages
    /// `(I/(γh) − A') u_i = f(t + α_i h, y + Σ_j a_ij u_j) + Σ_j (c_ij/h) u_j` only the matrix
    /// (and the zero-Jacobian components' `γ lu_h` in [`Self::solve`]) takes `lu_h`; the
    /// stage times, `a_ij`, `c_ij/h` and the weights take the actual `h`.
    fn needs_factor(&self, h: f64, max_ratio: f64) -> bool {
        if self.lu_h == 0.0 {
            true
        } else if max_ratio > 0.0 {
            (h / self.lu_h - 1.0).abs() > max_ratio
        } else {
            h != self.lu_h
        }
    }

    /// Solves `(1/(γh) I − A) x = rhs` in place: per block, or with a border by block
    /// elimination — `y_b = D_b⁻¹ x_b`, `S z = x_border − Σ_b C_b y_b`, `x_b = y_b − X_b z`.
    fn solve(&mut self, h: f64, x: &mut [f64]) {
        let coupled_border = self.border.as_ref().is_some_and(|bd| bd.active);
        for (b, blk) in self.blocks.iter().enumerate() {
            if coupled_border
                && let Some(bd) = &self.border
                && bd.border_blocks.iter().any(|&(bb, _)| bb == b)
            {
                continue;
            }
            let n = blk.n;
            let (o, p) = (self.off[b], self.poff[b]);
            dense_lu::solve_in_place(
                &self.lu[o..o + n * n],
                &self.piv[p..p + n],
                &mut x[blk.start..blk.start + n],
            );
        }
        if coupled_border && let Some(bd) = self.border.as_mut() {
            for (v, &i) in bd.g.iter_mut().zip(&bd.comps) {
                *v = x[i];
            }
            for (c, &b) in bd.coupled.iter().enumerate() {
                let blk = self.blocks[b];
                let yb = &x[blk.start..blk.start + blk.n];
                let oc = bd.off[c];
                for (q, &pos) in bd.support[c].iter().enumerate() {
                    let crow = &bd.jac_cols[oc + q * blk.n..oc + (q + 1) * blk.n];
                    bd.g[pos] += crow.iter().zip(yb).map(|(a, b)| a * b).sum::<f64>();
                }
            }
            dense_lu::solve_in_place(&bd.schur, &bd.piv, &mut bd.g);
            for (&i, &v) in bd.comps.iter().zip(&bd.g) {
                x[i] = v;
            }
            for (c, &b) in bd.coupled.iter().enumerate() {
                let blk = self.blocks[b];
                let oc = bd.off[c];
                let s = bd.support[c].len();
                let z = &mut bd.schur_row[..s];
                for (zq, &pos) in z.iter_mut().zip(&bd.support[c]) {
                    *zq = bd.g[pos];
                }
                let xb = &bd.x[oc..oc + blk.n * s];
                for (v, xrow) in x[blk.start..blk.start + blk.n]
                    .iter_mut()
                    .zip(xb.chunks_exact(s))
                {
                    *v = xrow
                        .iter()
                        .zip(z.iter())
                        .fold(*v, |acc, (&xv, &zq)| acc - xv * zq);
                }
            }
        }
        let gh = GAMMA * h;
        for &i in &self.free {
            x[i] *= gh;
        }
    }

    /// Evaluates `f(t, y)` (and the border shares there) unless it is already known.
    fn ensure_f0<S: OdeSystem + ?Sized>(&mut self, sys: &mut S) {
        if !self.f0_valid {
            sys.rhs_reported(self.t, &self.y, &mut self.f0);
            self.stats.rhs_evaluations += 1;
            self.f0_valid = true;
            if let Some(bd) = self.border.as_mut() {
                sys.border_shares(&mut bd.shares0);
                bd.shares0_valid = true;
            }
        }
    }

    /// The Jacobian approximation `A`, evaluated afresh at the current state, as a dense
    /// row-major `n × n` matrix (the diagonal blocks and, with a border, the coupling blocks;
    /// zero elsewhere) — for diagnostics and tests. The next step uses this evaluation.
    pub fn jacobian_approximation<S: OdeSystem + ?Sized>(&mut self, sys: &mut S) -> Vec<f64> {
        let n = self.y.len();
        self.ensure_f0(sys);
        self.evaluate_jacobian(sys);
        let mut a = vec![0.0; n * n];
        for (b, blk) in self.blocks.iter().enumerate() {
            for r in 0..blk.n {
                for k in 0..blk.n {
                    a[(blk.start + r) * n + blk.start + k] = self.jac[self.off[b] + r * blk.n + k];
                }
            }
        }
        if let Some(bd) = &self.border {
            for (c, &b) in bd.coupled.iter().enumerate() {
                let blk = self.blocks[b];
                let s = bd.support[c].len();
                let oc = bd.off[c];
                for (q, &pos) in bd.support[c].iter().enumerate() {
                    let i = bd.comps[pos];
                    for r in 0..blk.n {
                        a[(blk.start + r) * n + i] = bd.jac_rows[oc + r * s + q];
                        a[i * n + blk.start + r] = bd.jac_cols[oc + q * blk.n + r];
                    }
                }
            }
        }
        a
    }

    /// The test oracle of [`RosenbrockW::jacobian_approximation`]: the whole Jacobian by forward
    /// differences of the full right-hand side, one column at a time with the same increments
    /// (`n` evaluations; no structure assumed). Leaves the integrator's Jacobian untouched.
    pub fn dense_difference_jacobian<S: OdeSystem + ?Sized>(&mut self, sys: &mut S) -> Vec<f64> {
        let n = self.y.len();
        self.ensure_f0(sys);
        let sq = f64::EPSILON.sqrt();
        let mut a = vec![0.0; n * n];
        for k in 0..n {
            self.ytmp.copy_from_slice(&self.y);
            let yp = self.y[k] + sq * self.y[k].abs().max(self.scale[k]);
            self.ytmp[k] = yp;
            let inv = 1.0 / (yp - self.y[k]);
            sys.rhs(self.t, &self.ytmp, &mut self.ftmp);
            for r in 0..n {
                a[r * n + k] = (self.ftmp[r] - self.f0[r]) * inv;
            }
        }
        a
    }

    /// Takes one accepted step (retrying rejected ones). The last evaluation of `sys` is at the
    /// new accepted state, so per-evaluation side results of `sys` describe it when this
    /// returns `Ok`.
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        set: &IntegratorSettings,
    ) -> Result<(), StepError> {
        let n = self.y.len();
        self.ensure_f0(sys);
        // embedded order 2: error ∝ h³
        let expo1 = 1.0 / 3.0 - 0.75 * set.pi_beta;
        let tab = self.tab;
        loop {
            let h = self.h.min(set.max_step_s);
            let t = self.t;
            if !self.jac_valid {
                self.evaluate_jacobian(sys);
            }
            if self.needs_factor(h, set.refactor_step_ratio) {
                self.factor(h);
            }
            // the stage matrix is `I/(γ·lu_h) − A` (= `I/(γh) − A'`, see `needs_factor`)
            let h_matrix = self.lu_h;
            for s in 0..STAGES {
                let (done, rest) = self.u.split_at_mut(s);
                let us = &mut rest[0];
                if s == 0 {
                    us.copy_from_slice(&self.f0);
                } else {
                    for i in 0..n {
                        let mut acc = self.y[i];
                        for (j, uj) in done.iter().enumerate() {
                            acc += tab.a[s][j] * uj[i];
                        }
                        self.ytmp[i] = acc;
                    }
                    sys.rhs(t + tab.alpha[s] * h, &self.ytmp, us);
                    for i in 0..n {
                        let mut acc = us[i];
                        for (j, uj) in done.iter().enumerate() {
                            acc += (tab.c[s][j] / h) * uj[i];
                        }
                        us[i] = acc;
                    }
                }
                // `solve` borrows self; move the stage vector out meanwhile
                let mut v = std::mem::take(&mut self.u[s]);
                self.solve(h_matrix, &mut v);
                self.u[s] = v;
            }
            self.stats.rhs_evaluations += (STAGES - 1) as u64;
            let mut err = 0.0_f64;
            let mut arg = 0usize;
            let mut nonfinite_at = None;
            for i in 0..n {
                let mut yn = self.y[i];
                let mut e = 0.0;
                for j in 0..STAGES {
                    yn += tab.m[j] * self.u[j][i];
                    e += tab.e[j] * self.u[j][i];
                }
                self.ynew[i] = yn;
                let sc = set.tolerance
                    * (self.scale[i] + self.relative[i] * self.y[i].abs().max(yn.abs()));
                let r = (e / sc).abs();
                if !r.is_finite() || !yn.is_finite() {
                    if nonfinite_at.is_none() {
                        nonfinite_at = Some(i);
                    }
                } else if r > err {
                    err = r;
                    arg = i;
                }
            }
            if nonfinite_at.is_none() && err <= 1.0 {
                sys.rhs_reported(t + h, &self.ynew, &mut self.ftmp);
                self.stats.rhs_evaluations += 1;
                if let Some(bd) = self.border.as_mut() {
                    sys.border_shares(&mut bd.shares_new);
                }
                nonfinite_at = self.ftmp.iter().position(|v| !v.is_finite());
            }
            if let Some(i) = nonfinite_at {
                self.stats.rejected += 1;
                self.last_rejected = true;
                self.h = h * set.min_shrink;
                if self.jac_age > 0 {
                    self.jac_valid = false;
                }
                if self.h < set.min_step_s {
                    return Err(StepError::NonFinite { h, component: i });
                }
                continue;
            }
            self.stats.limiting[arg] += 1;
            if err <= 1.0 {
                std::mem::swap(&mut self.dense_y0, &mut self.y);
                std::mem::swap(&mut self.y, &mut self.ynew);
                std::mem::swap(&mut self.dense_f0, &mut self.f0);
                std::mem::swap(&mut self.f0, &mut self.ftmp);
                if let Some(bd) = self.border.as_mut() {
                    std::mem::swap(&mut bd.shares0, &mut bd.shares_new);
                }
                self.dense_t = t;
                self.dense_h = h;
                self.t = t + h;
                self.stats.accepted += 1;
                self.h = self.next_step(h, err, expo1, set);
                self.h_prev = h;
                self.err_old = err.max(1e-4);
                self.last_rejected = false;
                self.jac_age += 1;
                if self.jac_age >= u64::from(set.jacobian_interval.max(1)) {
                    self.jac_valid = false;
                }
                return Ok(());
            }
            self.stats.rejected += 1;
            self.last_rejected = true;
            let fac = (set.safety * err.powf(-1.0 / 3.0)).clamp(set.min_shrink, 1.0);
            self.h = h * fac;
            if self.jac_age > 0 && set.refresh_jacobian_on_reject {
                self.jac_valid = false;
            }
            if self.h < set.min_step_s {
                return Err(StepError::Collapse {
                    h: self.h,
                    component: arg,
                });
            }
        }
    }

    /// Next step size after an accepted step `h` with error `err`: the PI step
    /// ([`crate::integrator::accepted_step`]), bounded by Gustafsson's predictive step
    /// `h·safety·(h/h_prev)·(err_old/err²)^{1/3}` (Hairer & Wanner II, §IV.8, RODAS; exponent
    /// 1/3 for the order-2 error estimate) when `predictive_step` is set, then held at `h` when
    /// it would grow by less than `hold_step_ratio` (RADAU5), so the factors stay valid.
    fn next_step(&self, h: f64, err: f64, expo1: f64, set: &IntegratorSettings) -> f64 {
        let mut next =
            crate::integrator::accepted_step(h, err, self.err_old, self.last_rejected, expo1, set);
        if set.predictive_step && self.h_prev > 0.0 {
            let growth = (h / self.h_prev) * (self.err_old / err.max(1e-10).powi(2)).cbrt();
            next = next.min(h * (set.safety * growth).clamp(set.min_shrink, set.max_growth));
        }
        if next > h && next <= h * (1.0 + set.hold_step_ratio) {
            next = h;
        }
        next
    }

    /// Dense output at `t` inside the last accepted step (cubic Hermite), written to `out`.
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        let h = self.dense_h;
        let th = if h > 0.0 { (t - self.dense_t) / h } else { 1.0 };
        let th1 = th - 1.0;
        for (i, o) in out.iter_mut().enumerate() {
            let (y0, y1) = (self.dense_y0[i], self.y[i]);
            let dy = y1 - y0;
            *o = y0
                + th * dy
                + th * th1
                    * ((1.0 - 2.0 * th) * dy + th1 * h * self.dense_f0[i] + th * h * self.f0[i]);
        }
    }

    /// Start time of the last accepted step.
    pub fn dense_start(&self) -> f64 {
        self.dense_t
    }

    /// Step size of the current LU factors (0: none), saved in a checkpoint.
    pub(crate) fn factor_step(&self) -> f64 {
        self.lu_h
    }

    /// Recomputes derived data after the fields were restored from a checkpoint: the LU factors
    /// are a pure function of `jac` and their step size `factor_step`, so they are rebuilt here
    /// at that step size (the resumed run keeps them as long as the uninterrupted one would).
    pub(crate) fn after_restore(&mut self, factor_step: f64) {
        self.lu_h = 0.0;
        if self.jac_valid && factor_step > 0.0 {
            self.factor(factor_step);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Nonlinear test problem with a known solution: `y₀' = −y₁ − y₀(y₀² + y₁² − 1)`,
    /// `y₁' = y₀ − y₁(…)` (the unit circle is attracting; `y = (cos t, sin t)` from `(1, 0)`)
    /// plus a stiff linear component `y₂' = −λ(y₂ − cos t)` — exercises the W property and
    /// the time-dependent forcing without an `f_t` term.
    struct Prob {
        lambda: f64,
    }
    impl OdeSystem for Prob {
        fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
            let q = y[0] * y[0] + y[1] * y[1] - 1.0;
            dy[0] = -y[1] - y[0] * q;
            dy[1] = y[0] - y[1] * q;
            dy[2] = -self.lambda * (y[2] - t.cos());
        }
    }

    fn fixed_step_error(h: f64, groups: &[Vec<JacobianBlock>], lambda: f64, interval: u32) -> f64 {
        let set = IntegratorSettings {
            tolerance: 1e30,
            max_step_s: h,
            jacobian_interval: interval,
            ..IntegratorSettings::default()
        };
        let y0 = vec![1.0, 0.0, 1.0];
        let mut ig = RosenbrockW::new(0.0, y0, vec![1.0; 3], vec![0.0; 3], h, groups);
        let mut p = Prob { lambda };
        let t_end = 1.0;
        while ig.t < t_end - 1e-12 {
            ig.step(&mut p, &set).unwrap();
        }
        (ig.y[0] - ig.t.cos())
            .abs()
            .max((ig.y[1] - ig.t.sin()).abs())
    }

    #[test]
    fn order_three_for_exact_and_zero_jacobian() {
        // nonstiff (λ = 1): with the full Jacobian, with a stale one (refreshed every 7 steps)
        // and with A = 0 (explicit limit) the order is 3 — the W-method property
        let full = vec![vec![JacobianBlock { start: 0, n: 3 }]];
        for (groups, interval) in [(full.clone(), 1), (full, 7), (vec![], 1)] {
            let e1 = fixed_step_error(0.05, &groups, 1.0, interval);
            let e2 = fixed_step_error(0.025, &groups, 1.0, interval);
            let order = (e1 / e2).log2();
            // ≥ 3 (a stale Jacobian refreshed at different points for the two step sizes can
            // make the error constants differ, hence the loose upper bound)
            assert!(order > 2.7 && order < 4.5, "observed order {order}");
        }
    }

    #[test]
    fn the_step_is_held_predicted_ahead_of_a_growing_error_and_free_to_grow() {
        let set = IntegratorSettings::default();
        let groups = vec![vec![JacobianBlock { start: 0, n: 3 }]];
        let mut ig = RosenbrockW::new(0.0, vec![1.0; 3], vec![1.0; 3], vec![0.0; 3], 1e-6, &groups);
        let expo1 = 1.0 / 3.0 - 0.75 * set.pi_beta;
        let h = 1e-6;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * b;
        // first accepted step (no previous step): the PI controller proposes a growth of 1.3 %
        // (err 0.5 after 0.1), below `hold_step_ratio`: the step is held
        ig.err_old = 0.1;
        let pi = crate::integrator::accepted_step(h, 0.5, 0.1, false, expo1, &set);
        assert!(pi > h && pi < 1.2 * h, "PI step {pi:e}");
        assert_eq!(ig.next_step(h, 0.5, expo1, &set), h);
        // after an equal step the error has grown fivefold: the predictive bound
        // h·safety·(0.1/0.5²)^{1/3} = 0.66 h rules
        ig.h_prev = h;
        let predicted = h * set.safety * (0.1_f64 / 0.25).cbrt();
        assert!(close(ig.next_step(h, 0.5, expo1, &set), predicted));
        // a falling error (0.5 → 0.01): the predictive bound (clamped at 5 h) lies above the PI
        // step (3.5 h), which is taken
        ig.err_old = 0.5;
        let pi = crate::integrator::accepted_step(h, 0.01, 0.5, false, expo1, &set);
        assert!(pi > 3.0 * h && pi < 4.0 * h, "PI step {pi:e}");
        assert_eq!(ig.next_step(h, 0.01, expo1, &set), pi);
    }

    #[test]
    fn stiff_component_is_stable_with_large_steps() {
        // λ h = 1e4: explicit methods would explode, the W-method with the block Jacobian is
        // stable and accurate in the non-stiff components
        let groups = vec![
            vec![JacobianBlock { start: 0, n: 2 }],
            vec![JacobianBlock { start: 2, n: 1 }],
        ];
        let e = fixed_step_error(0.01, &groups, 1e6, 10);
        assert!(e < 1e-5, "error {e}");
    }

    #[test]
    fn adaptive_run_and_dense_output() {
        let set = IntegratorSettings {
            tolerance: 1e-8,
            max_step_s: 1.0,
            ..IntegratorSettings::default()
        };
        let groups = vec![vec![JacobianBlock { start: 0, n: 3 }]];
        let mut ig = RosenbrockW::new(
            0.0,
            vec![1.0, 0.0, 1.0],
            vec![1.0; 3],
            vec![0.0; 3],
            1e-3,
            &groups,
        );
        let mut p = Prob { lambda: 1e5 };
        let mut out = [0.0; 3];
        let mut worst: f64 = 0.0;
        while ig.t < 5.0 {
            ig.step(&mut p, &set).unwrap();
            let tm = ig.dense_start() + 0.37 * (ig.t - ig.dense_start());
            ig.interpolate(tm, &mut out);
            worst = worst.max((out[0] - tm.cos()).abs());
        }
        assert!((ig.y[0] - ig.t.cos()).abs() < 1e-6);
        assert!(worst < 1e-6, "dense output error {worst}");
        // stiff component (λ = 1e5) did not force explicit-size steps (h ≪ 2/λ = 2e-5)
        assert!(ig.stats.accepted < 5000, "{} steps", ig.stats.accepted);
        assert!(ig.stats.jacobian_evaluations >= 1);
    }

    /// A linear system `y' = M y + b` with the bordered structure: three coupled blocks of two
    /// components (0..6), a border block P (6..8, colour group 1) and Q (8, group 2); block 0
    /// touches P and Q, block 1 only P, block 2 only Q. The coupled blocks' shares of the
    /// border rates are `M[border, b] y_b`.
    struct Bordered {
        m: Vec<f64>,
        shares: Vec<f64>,
    }

    const BORDERED_N: usize = 9;
    /// per coupled block: its border support
    const BORDERED_SUPPORT: [&[usize]; 3] = [&[6, 7, 8], &[6, 7], &[8]];

    impl Bordered {
        fn new() -> Self {
            let n = BORDERED_N;
            let mut m = vec![0.0; n * n];
            let mut seed = 0.3_f64;
            let mut next = || {
                seed = (seed * 997.0 + 0.123).fract();
                seed - 0.5
            };
            let mut set = |r: usize, c: usize, v: f64| m[r * n + c] = v;
            // stiff own blocks (eigenvalues ≈ −1e4) and stiff couplings (≈ 2e3)
            for b in 0..3 {
                let o = 2 * b;
                set(o, o, -1e4);
                set(o + 1, o + 1, -5e3);
                set(o, o + 1, 3e3 * next());
                set(o + 1, o, 3e3 * next());
                for &i in BORDERED_SUPPORT[b] {
                    set(o, i, 2e3 * next());
                    set(o + 1, i, 2e3 * next());
                    set(i, o, 2e3 * next());
                    set(i, o + 1, 2e3 * next());
                }
            }
            set(6, 6, -2e3);
            set(7, 7, -1e3);
            set(6, 7, 500.0);
            set(7, 6, -500.0);
            set(8, 8, -3e3);
            Self {
                m,
                shares: vec![0.0; 6],
            }
        }
    }

    impl OdeSystem for Bordered {
        fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) {
            let n = BORDERED_N;
            for (r, d) in dy.iter_mut().enumerate() {
                *d = (r as f64 + 1.0) + (0..n).map(|c| self.m[r * n + c] * y[c]).sum::<f64>();
            }
            let mut k = 0;
            for (b, sup) in BORDERED_SUPPORT.iter().enumerate() {
                for &i in *sup {
                    self.shares[k] =
                        self.m[i * n + 2 * b] * y[2 * b] + self.m[i * n + 2 * b + 1] * y[2 * b + 1];
                    k += 1;
                }
            }
        }
        fn border_shares(&self, out: &mut [f64]) {
            out.copy_from_slice(&self.shares);
        }
    }

    fn bordered_groups() -> Vec<Vec<JacobianBlock>> {
        let block = |start, n| JacobianBlock { start, n };
        vec![
            vec![block(0, 2), block(2, 2), block(4, 2)],
            vec![block(6, 2)],
            vec![block(8, 1)],
        ]
    }

    fn bordered_run(ig: RosenbrockW) -> (Vec<f64>, RosenbrockW) {
        let set = IntegratorSettings {
            tolerance: 1e30,
            max_step_s: 2e-3,
            ..IntegratorSettings::default()
        };
        let mut ig = ig;
        let mut p = Bordered::new();
        for _ in 0..2 {
            ig.step(&mut p, &set).unwrap();
        }
        (ig.y.clone(), ig)
    }

    #[test]
    fn bordered_jacobian_is_the_full_jacobian_and_its_solve_the_full_solve() {
        let n = BORDERED_N;
        let y0: Vec<f64> = (0..n).map(|i| 0.1 * i as f64 - 0.3).collect();
        let new = |groups: &[Vec<JacobianBlock>]| {
            RosenbrockW::new(0.0, y0.clone(), vec![1.0; n], vec![0.0; n], 2e-3, groups)
        };
        let border = JacobianBorder {
            group: 0,
            support: BORDERED_SUPPORT.iter().map(|s| s.to_vec()).collect(),
        };
        // the assembled approximation is the whole matrix M (forward differences of a linear
        // map)
        let mut ig = new(&bordered_groups()).with_border(&border);
        let a = ig.jacobian_approximation(&mut Bordered::new());
        let m = Bordered::new().m;
        for (i, (x, e)) in a.iter().zip(&m).enumerate() {
            assert!(
                (x - e).abs() <= 1e-6 * e.abs().max(1.0),
                "entry {i}: {x} vs {e}"
            );
        }
        // two steps of h·λ ≈ 20 (before the steady state): the Schur-complement solve gives the
        // steps of one dense block
        let (bordered, ig) = bordered_run(new(&bordered_groups()).with_border(&border));
        let (full, _) = bordered_run(new(&[vec![JacobianBlock { start: 0, n }]]));
        let (diagonal, _) = bordered_run(new(&bordered_groups()));
        let scale = full.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let gap = |y: &[f64]| {
            y.iter()
                .zip(&full)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()))
                / scale
        };
        // equal up to the differences' rounding (≈ 1e-8 of the entries); the couplings matter
        // here: the block-diagonal Jacobian gives other steps
        let (g_bordered, g_diagonal) = (gap(&bordered), gap(&diagonal));
        assert!(
            g_bordered < 1e-6 && g_diagonal > 1e3 * g_bordered,
            "bordered vs full: {g_bordered:e}, block-diagonal vs full: {g_diagonal:e}"
        );
        // the FD Jacobian with shares costs one RHS per column of a group, as without a border
        assert_eq!(ig.stats.jacobian_evaluations, 1);
    }
}
