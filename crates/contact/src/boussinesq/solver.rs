//! Constrained conjugate-gradient contact solver (Polonsky & Keer 1999, Wear 231:206–219)
//! for the discretised Boussinesq problem of seed 004 eqs. (4)–(6) (SPEC §2.5).
//!
//! Minimises the complementary energy `½ pᵀF p + pᵀ(K − α)` over `p ≥ 0`:
//! * approach-controlled: `α` given, gap `g = K − α + u(p)`;
//! * force-controlled: `ΔS Σ p = Q` given (seed 004 eq. (6)); `α` is the Lagrange multiplier,
//!   equal to the mean of `K + u` over the contact set (Polonsky–Keer step 2).
//!
//! `u = F p` is evaluated with the zero-padded FFT [`Convolver`]. Per iteration one
//! convolution (of the conjugate direction) is done; `u(p)` is updated linearly, the cells
//! changed by the projection (`p < 0 → 0`) or the overlap step are added by direct sums when
//! few, otherwise `u` is recomputed by FFT.
//!
//! The iteration stops on the relative gap residual ([`StopRule::RelativeGap`], the
//! complementarity conditions themselves) or, as before issue 40, on the relative pressure
//! change ([`StopRule::PressureChange`]).

use super::convolution::{ConvolutionMode, Convolver, accumulate_cells};
use super::influence::InfluenceTable;
use super::{BoussinesqError, Grid};

/// Default tolerance of [`StopRule::RelativeGap`]: the same approach and pressures as the
/// former pressure-change rule at `1e-10` to 1e-6 relative or better on the seed 004 grids and
/// at 4096 × 256 (crate test `gap_stop_rule_matches_pressure_change_rule`; docs/theory.md §2.6).
pub const DEFAULT_GAP_TOLERANCE: f64 = 1e-7;

/// When the Polonsky–Keer iteration stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StopRule {
    /// Relative gap residual of the complementarity conditions (seed 004 (1)–(3)) on the exact
    /// displacement `u = F p`:
    /// `r = max( max_{p>0} |g|, max_{p=0} max(−g, 0) ) / max u < tolerance`, with
    /// `g = K − α + u` (the [`ContactSolution::residual`] of the returned field).
    RelativeGap(f64),
    /// Relative pressure change of one iteration, `ε = Σ|p_k − p_{k−1}| / Σ p_k < tolerance`
    /// (Polonsky–Keer step 11; the rule before issue 40, with tolerance `1e-10`).
    PressureChange(f64),
}

impl StopRule {
    /// The tolerance of the rule.
    pub fn tolerance(self) -> f64 {
        match self {
            Self::RelativeGap(t) | Self::PressureChange(t) => t,
        }
    }
}

impl Default for StopRule {
    /// [`StopRule::RelativeGap`] with [`DEFAULT_GAP_TOLERANCE`].
    fn default() -> Self {
        Self::RelativeGap(DEFAULT_GAP_TOLERANCE)
    }
}

/// Every knob of [`BoussinesqSolver`].
#[derive(Debug, Clone, PartialEq)]
pub struct BoussinesqOptions {
    /// Stop rule and its tolerance. Default [`StopRule::RelativeGap`] with
    /// [`DEFAULT_GAP_TOLERANCE`].
    pub stop: StopRule,
    /// Iteration limit; on reaching it the result has `converged == false`. Default 5000.
    pub max_iterations: usize,
    /// Convolution evaluation along `y`. Default [`ConvolutionMode::Auto`].
    pub convolution: ConvolutionMode,
    /// Largest number of cells changed by the projection/overlap steps for which the
    /// displacement is corrected by direct sums instead of a full FFT convolution
    /// (`0`: always FFT). Default 32 (one cell costs `nx·ny` multiply-adds, one FFT
    /// convolution roughly 50–100 times that).
    pub sparse_update_max_cells: usize,
    /// Recompute `u = F p` by FFT every this many iterations to stop round-off drift of the
    /// linear update. Default 50.
    pub recompute_interval: usize,
}

impl Default for BoussinesqOptions {
    fn default() -> Self {
        Self {
            stop: StopRule::default(),
            max_iterations: 5000,
            convolution: ConvolutionMode::Auto,
            sparse_update_max_cells: 32,
            recompute_interval: 50,
        }
    }
}

/// Solution of one contact problem. Fields are in storage order (`j * nx + i`, x fastest).
#[derive(Debug, Clone)]
pub struct ContactSolution {
    /// Grid the fields live on.
    pub grid: Grid,
    /// Contact pressure per cell, Pa.
    pub pressure: Vec<f64>,
    /// Combined elastic surface displacement `u = F p` per cell, m.
    pub displacement: Vec<f64>,
    /// Rigid approach `α`, m (input in approach mode, Lagrange multiplier in force mode).
    pub approach_m: f64,
    /// Total force `ΔS Σ p`, N.
    pub force_n: f64,
    /// Largest cell pressure, Pa.
    pub max_pressure_pa: f64,
    /// Number of cells with `p > 0`.
    pub cells_in_contact: usize,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// FFT convolutions performed on this grid (about one per iteration plus full `u`
    /// recomputations).
    pub convolutions: usize,
    /// Whether the stop rule's test passed ([`BoussinesqOptions::stop`]).
    pub converged: bool,
    /// Relative pressure change `ε` of the last iteration (0 without iterations).
    pub pressure_change: f64,
    /// Relative gap (complementarity) residual of the returned fields:
    /// `max(|g| on p > 0, max(−g, 0) on p = 0) / max u` ([`StopRule::RelativeGap`]).
    pub residual: f64,
    /// Contact reaches the first or last column (candidate region too short along `x`).
    pub touches_edge_x: bool,
    /// Contact reaches the first or last row (candidate region too narrow along `y`, F-12).
    pub touches_edge_y: bool,
}

impl ContactSolution {
    /// Pressure of cell `(i, j)`, Pa.
    pub fn pressure_at(&self, i: usize, j: usize) -> f64 {
        self.pressure[self.grid.index(i, j)]
    }

    /// Pressure along the central line: the row of cells nearest `y = 0`, for each `x`
    /// (abscissae `grid.x(i)`), Pa.
    pub fn central_line(&self) -> &[f64] {
        let j = self.grid.central_row();
        &self.pressure[j * self.grid.nx..(j + 1) * self.grid.nx]
    }

    /// Pressure at the middle of the contact line (cell nearest `(0, 0)`), Pa.
    pub fn pressure_at_middle(&self) -> f64 {
        self.pressure_at(self.grid.central_column(), self.grid.central_row())
    }

    /// Contact area `ΔS · cells_in_contact`, m².
    pub fn contact_area_m2(&self) -> f64 {
        self.grid.cell_area() * self.cells_in_contact as f64
    }

    /// Mean pressure `force / contact area`, Pa (0 without contact).
    pub fn mean_pressure_pa(&self) -> f64 {
        if self.cells_in_contact == 0 {
            0.0
        } else {
            self.force_n / self.contact_area_m2()
        }
    }

    /// Stress concentration factor `p_max / p̄` (SPEC §2.5 "derived outputs").
    pub fn concentration_factor(&self) -> f64 {
        let m = self.mean_pressure_pa();
        if m > 0.0 {
            self.max_pressure_pa / m
        } else {
            0.0
        }
    }

    /// Contact length along `x`: extent of the columns containing contact cells, m.
    pub fn contact_length_m(&self) -> f64 {
        let (nx, ny) = (self.grid.nx, self.grid.ny);
        let cols: Vec<usize> = (0..nx)
            .filter(|&i| (0..ny).any(|j| self.pressure[j * nx + i] > 0.0))
            .collect();
        match (cols.first(), cols.last()) {
            (Some(a), Some(b)) => (b - a + 1) as f64 * self.grid.dx,
            _ => 0.0,
        }
    }

    /// Largest half-width along `y` over all columns: `max_i (extent of contact rows)/2`, m.
    pub fn max_half_width_m(&self) -> f64 {
        let (nx, ny) = (self.grid.nx, self.grid.ny);
        let mut w = 0usize;
        for i in 0..nx {
            let rows = (0..ny).filter(|&j| self.pressure[j * nx + i] > 0.0);
            let (mut lo, mut hi) = (usize::MAX, 0);
            for j in rows {
                lo = lo.min(j);
                hi = hi.max(j);
            }
            if lo != usize::MAX {
                w = w.max(hi - lo + 1);
            }
        }
        0.5 * w as f64 * self.grid.dy
    }
}

/// Lane width of the reductions: independent partial sums break the floating-point add
/// latency chain and let the compiler vectorise.
const L: usize = 8;

/// `for i in 0..n` with lane index `l = i % L` for partial sums (tail on lane 0).
macro_rules! for_lanes {
    ($n:expr, |$i:ident, $l:ident| $body:block) => {{
        let n = $n;
        let main = n - n % L;
        let mut b = 0;
        while b < main {
            for $l in 0..L {
                let $i = b + $l;
                $body
            }
            b += L;
        }
        for $i in main..n {
            let $l = 0;
            $body
        }
    }};
}

#[derive(Clone, Copy)]
enum Control {
    Force(f64),
    Approach(f64),
}

/// Steps 1–3 of one iteration: the contact set and the centred gap of the current pressure.
#[derive(Clone, Copy)]
struct GapState {
    /// Cells in contact `|I_c|`.
    nc: usize,
    /// `G = Σ_{I_c} g²`.
    gg: f64,
    /// Relative gap residual ([`StopRule::RelativeGap`]) with the current `u`.
    residual: f64,
}

/// How [`BoussinesqSolver::solve_in_place`] ended.
struct Outcome {
    iterations: usize,
    converged: bool,
    /// Relative pressure change of the last iteration.
    pressure_change: f64,
    /// `u = F p` exactly (last computed by FFT), not by the linear update.
    u_exact: bool,
}

/// Violation of the contact conditions by one cell of pressure `p` and gap `g`: `|g|` in
/// contact (`g = 0` required), `max(−g, 0)` out of contact (`g ≥ 0` required); seed 004 (1)–(3).
#[inline]
fn gap_violation(p: f64, g: f64) -> f64 {
    if p > 0.0 { g.abs() } else { (-g).max(0.0) }
}

/// Conjugate-gradient state carried from one iteration to the next.
struct CgState {
    /// `G = Σ_{I_c} g²` of the previous iteration.
    g_old: f64,
    /// `δ`: 1 keeps the conjugacy, 0 after an overlap step (restart along `g`).
    delta: f64,
    /// Iterations since the last full FFT recomputation of `u`.
    since_recompute: usize,
}

/// Step 10 applied, `p ← scale · p`, with `also(i)` run for each cell in the same pass;
/// returns `(Σ|p − p_old|, Σ p)` for the pressure change of step 11.
fn scale_pressure(
    p: &mut [f64],
    p_old: &[f64],
    scale: f64,
    mut also: impl FnMut(usize),
) -> (f64, f64) {
    let (mut dsl, mut psl) = ([0.0; L], [0.0; L]);
    for_lanes!(p.len(), |i, l| {
        let v = p[i] * scale;
        p[i] = v;
        dsl[l] += (v - p_old[i]).abs();
        psl[l] += v;
        also(i);
    });
    (dsl.iter().sum(), psl.iter().sum())
}

/// Reusable solver for one grid and material pair: kernel table and its FFT are computed once
/// in [`BoussinesqSolver::new`]; all iteration buffers are owned, so solves do not allocate
/// inside the iteration loop.
#[derive(Debug)]
pub struct BoussinesqSolver {
    grid: Grid,
    options: BoussinesqOptions,
    table: InfluenceTable,
    conv: Convolver,
    p: Vec<f64>,
    p_old: Vec<f64>,
    u: Vec<f64>,
    g: Vec<f64>,
    t: Vec<f64>,
    r: Vec<f64>,
    /// Cells whose pressure was changed by the projection / overlap step (index, amount).
    corr: Vec<(usize, f64)>,
    /// Convolutions of the current solve.
    n_conv: usize,
}

impl BoussinesqSolver {
    /// Solver for `grid` with combined compliance `compliance` (1/Pa, see
    /// [`super::combined_compliance`]).
    pub fn new(
        grid: Grid,
        compliance: f64,
        options: BoussinesqOptions,
    ) -> Result<Self, BoussinesqError> {
        let grid = Grid::new(grid.nx, grid.ny, grid.dx, grid.dy, grid.x_min, grid.y_min)?;
        if !(compliance.is_finite() && compliance > 0.0) {
            return Err(BoussinesqError::InvalidCompliance(compliance));
        }
        let tolerance = options.stop.tolerance();
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(BoussinesqError::InvalidOption(format!(
                "tolerance {tolerance}"
            )));
        }
        if options.max_iterations == 0 || options.recompute_interval == 0 {
            return Err(BoussinesqError::InvalidOption(
                "max_iterations and recompute_interval must be positive".into(),
            ));
        }
        let table = InfluenceTable::new(&grid, compliance);
        let conv = Convolver::new(&table, options.convolution);
        let n = grid.len();
        Ok(Self {
            grid,
            options,
            table,
            conv,
            p: vec![0.0; n],
            p_old: vec![0.0; n],
            u: vec![0.0; n],
            g: vec![0.0; n],
            t: vec![0.0; n],
            r: vec![0.0; n],
            corr: Vec::with_capacity(n),
            n_conv: 0,
        })
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The options.
    pub fn options(&self) -> &BoussinesqOptions {
        &self.options
    }

    /// The kernel table `f(m·dx, d·dy)`.
    pub fn influence_table(&self) -> &InfluenceTable {
        &self.table
    }

    /// Resolved convolution mode.
    pub fn convolution_mode(&self) -> ConvolutionMode {
        self.conv.mode()
    }

    /// `u = F p` (FFT), e.g. to evaluate displacements of a given pressure field.
    pub fn displacement(&mut self, p: &[f64], u: &mut [f64]) {
        self.conv.apply(p, u);
    }

    /// Force-controlled solve: total force `q` (N) on the initial gap `gap` (m, per cell).
    pub fn solve_force(&mut self, gap: &[f64], q: f64) -> Result<ContactSolution, BoussinesqError> {
        self.run(gap, Control::Force(q), None)
    }

    /// Approach-controlled solve: rigid approach `alpha` (m) on the initial gap `gap`.
    pub fn solve_approach(
        &mut self,
        gap: &[f64],
        alpha: f64,
    ) -> Result<ContactSolution, BoussinesqError> {
        self.run(gap, Control::Approach(alpha), None)
    }

    /// [`Self::solve_force`] starting from the pressure field `guess` (e.g. the previous time
    /// step; negative entries are clipped, it is rescaled to the force).
    pub fn solve_force_with_guess(
        &mut self,
        gap: &[f64],
        q: f64,
        guess: &[f64],
    ) -> Result<ContactSolution, BoussinesqError> {
        self.run(gap, Control::Force(q), Some(guess))
    }

    /// [`Self::solve_approach`] starting from the pressure field `guess`.
    pub fn solve_approach_with_guess(
        &mut self,
        gap: &[f64],
        alpha: f64,
        guess: &[f64],
    ) -> Result<ContactSolution, BoussinesqError> {
        self.run(gap, Control::Approach(alpha), Some(guess))
    }

    fn validate(
        &self,
        gap: &[f64],
        control: Control,
        guess: Option<&[f64]>,
    ) -> Result<(), BoussinesqError> {
        let n = self.grid.len();
        if gap.len() != n {
            return Err(BoussinesqError::LengthMismatch {
                expected: n,
                got: gap.len(),
            });
        }
        if let Some(i) = gap.iter().position(|v| !v.is_finite()) {
            return Err(BoussinesqError::NonFiniteGap(i));
        }
        match control {
            Control::Force(q) if !(q.is_finite() && q >= 0.0) => {
                return Err(BoussinesqError::InvalidLoad(q));
            }
            Control::Approach(a) if !a.is_finite() => return Err(BoussinesqError::InvalidLoad(a)),
            _ => {}
        }
        if let Some(g) = guess
            && g.len() != n
        {
            return Err(BoussinesqError::LengthMismatch {
                expected: n,
                got: g.len(),
            });
        }
        Ok(())
    }

    /// Initial pressure (before force scaling): `guess` if given and non-trivial, else a
    /// Hertz-like `√(c − K)` field (force mode) or a local estimate (approach mode).
    fn initial_pressure(&mut self, gap: &[f64], control: Control, guess: Option<&[f64]>) {
        if let Some(g) = guess {
            for (p, &v) in self.p.iter_mut().zip(g) {
                *p = if v.is_finite() && v > 0.0 { v } else { 0.0 };
            }
            if self.p.iter().any(|&v| v > 0.0) {
                return;
            }
        }
        let f00 = self.table.self_coefficient();
        match control {
            Control::Approach(alpha) => {
                // Local (Winkler-like) estimate; the CG fixes shape and level.
                for (p, &k) in self.p.iter_mut().zip(gap) {
                    *p = (alpha - k).max(0.0) / (4.0 * f00);
                }
            }
            Control::Force(q) => {
                let h_min = gap.iter().copied().fold(f64::INFINITY, f64::min);
                // Interference scale of the load spread over one cell, then a √ profile.
                let c = 0.25 * f00 * q / self.grid.cell_area();
                for (p, &k) in self.p.iter_mut().zip(gap) {
                    *p = (c - (k - h_min)).max(0.0).sqrt();
                }
            }
        }
    }

    fn run(
        &mut self,
        gap: &[f64],
        control: Control,
        guess: Option<&[f64]>,
    ) -> Result<ContactSolution, BoussinesqError> {
        self.validate(gap, control, guess)?;
        let outcome = self.solve_in_place(gap, control, guess)?;
        // Final exact displacement (unless it is exact already), approach, residual.
        if !outcome.u_exact {
            self.conv.apply(&self.p, &mut self.u);
            self.n_conv += 1;
        }
        Ok(self.finish(gap, control, &outcome))
    }

    /// Polonsky–Keer iteration; leaves the pressure in `self.p` and `u ≈ F p` in `self.u`.
    ///
    /// [`StopRule::RelativeGap`] is tested before each iteration; when it passes on a linearly
    /// updated `u`, `u` is recomputed by FFT and the test repeated, so that a converged result
    /// passes it on the exact displacement. [`StopRule::PressureChange`] is tested after each
    /// iteration (step 11).
    fn solve_in_place(
        &mut self,
        gap: &[f64],
        control: Control,
        guess: Option<&[f64]>,
    ) -> Result<Outcome, BoussinesqError> {
        self.n_conv = 0;
        self.initial_pressure(gap, control, guess);
        self.balance_initial_pressure(gap, control);
        self.conv.apply(&self.p, &mut self.u);
        self.n_conv += 1;

        let mut cg = CgState {
            g_old: 1.0,
            delta: 0.0,
            since_recompute: 0,
        };
        let mut pressure_change = 0.0;
        let outcome = |iterations, converged, pressure_change, cg: &CgState| Outcome {
            iterations,
            converged,
            pressure_change,
            u_exact: cg.since_recompute == 0,
        };
        if self.p.iter().all(|&v| v == 0.0) {
            // Nothing to iterate (q = 0 or no interference).
            return Ok(outcome(0, true, 0.0, &cg));
        }
        let max_iterations = self.options.max_iterations;
        for iteration in 1..=max_iterations + 1 {
            let mut state = self.centred_gap(gap, control);
            if let StopRule::RelativeGap(tolerance) = self.options.stop
                && state.residual < tolerance
            {
                if cg.since_recompute > 0 {
                    self.conv.apply(&self.p, &mut self.u);
                    self.n_conv += 1;
                    cg.since_recompute = 0;
                    state = self.centred_gap(gap, control);
                }
                if state.residual < tolerance {
                    return Ok(outcome(iteration - 1, true, pressure_change, &cg));
                }
            }
            if iteration > max_iterations {
                break;
            }
            pressure_change = self.iterate(control, iteration, state, &mut cg)?;
            if let StopRule::PressureChange(tolerance) = self.options.stop
                && pressure_change < tolerance
            {
                return Ok(outcome(iteration, true, pressure_change, &cg));
            }
        }
        Ok(outcome(max_iterations, false, pressure_change, &cg))
    }

    /// Brings the initial pressure to the load: force mode scales it to `ΔS Σ p = Q` (a zero
    /// field for `Q = 0`; the cells of smallest gap if the field is empty), approach mode clears
    /// it when nothing interferes.
    fn balance_initial_pressure(&mut self, gap: &[f64], control: Control) {
        let ds = self.grid.cell_area();
        match control {
            Control::Force(q) => {
                let sum: f64 = self.p.iter().sum();
                if q == 0.0 || sum <= 0.0 {
                    // q = 0 → no pressure; the surfaces just touch at min K.
                    self.p.fill(0.0);
                    if q > 0.0 {
                        // Degenerate guess: load the cell(s) of smallest gap.
                        let h_min = gap.iter().copied().fold(f64::INFINITY, f64::min);
                        for (p, &k) in self.p.iter_mut().zip(gap) {
                            if k == h_min {
                                *p = 1.0;
                            }
                        }
                        let s = q / (ds * self.p.iter().sum::<f64>());
                        self.p.iter_mut().for_each(|p| *p *= s);
                    }
                } else {
                    let s = q / (ds * sum);
                    self.p.iter_mut().for_each(|p| *p *= s);
                }
            }
            Control::Approach(alpha) => {
                if gap.iter().all(|&k| k - alpha >= 0.0) {
                    // No interference: no contact.
                    self.p.fill(0.0);
                }
            }
        }
    }

    /// One Polonsky–Keer iteration after steps 1–3 (`state`, [`Self::centred_gap`]): steps
    /// 4–10 and the pressure change of step 11; returns the relative pressure change `ε`.
    fn iterate(
        &mut self,
        control: Control,
        iteration: usize,
        GapState { nc, gg, .. }: GapState,
        cg: &mut CgState,
    ) -> Result<f64, BoussinesqError> {
        let breakdown = || BoussinesqError::NumericalBreakdown { iteration };
        // Step 4: conjugate direction t = g + δ (G/G_old) t on I_c, 0 elsewhere.
        let beta = if cg.g_old > 0.0 {
            cg.delta * gg / cg.g_old
        } else {
            0.0
        };
        for ((ti, &gi), &pi) in self.t.iter_mut().zip(&self.g).zip(&self.p) {
            *ti = if pi > 0.0 { gi + beta * *ti } else { 0.0 };
        }
        cg.g_old = gg;

        let tau = if nc > 0 && gg > 0.0 {
            self.step_length(nc, control).ok_or_else(breakdown)?
        } else {
            0.0
        };

        let (psum, overlap) = self.project_pressure(tau);
        cg.delta = if overlap { 0.0 } else { 1.0 };

        // Step 10: force balance p ← p Q / (ΔS Σ p).
        let scale = match control {
            Control::Force(q) => q / (self.grid.cell_area() * psum),
            Control::Approach(_) => 1.0,
        };
        if !scale.is_finite() {
            return Err(breakdown());
        }

        let (dsum, psum) = self.scale_and_update_displacement(scale, tau, cg);
        let eps = if psum > 0.0 { dsum / psum } else { 0.0 };
        if !eps.is_finite() {
            return Err(breakdown());
        }
        Ok(eps)
    }

    /// Steps 1–3: gap `g = K + u`, its mean `ḡ` on the contact set `I_c = {p > 0}` (force
    /// mode; `ḡ = α` in approach mode) and `g ← g − ḡ`; with `|I_c|`, `G = Σ_{I_c} g²` and the
    /// relative gap residual of [`StopRule::RelativeGap`].
    fn centred_gap(&mut self, gap: &[f64], control: Control) -> GapState {
        let n = self.grid.len();
        // Steps 1–2: gap g = K + u and its mean on the contact set I_c = {p > 0}.
        let (mut ncl, mut gsl, mut uml) = ([0.0; L], [0.0; L], [0.0_f64; L]);
        {
            let (g, u, h, p) = (&mut self.g[..n], &self.u[..n], &gap[..n], &self.p[..n]);
            for_lanes!(n, |i, l| {
                let v = u[i] + h[i];
                g[i] = v;
                let c = p[i] > 0.0;
                gsl[l] += if c { v } else { 0.0 };
                ncl[l] += if c { 1.0 } else { 0.0 };
                uml[l] = uml[l].max(u[i]);
            });
        }
        let nc = ncl.iter().sum::<f64>() as usize;
        let gsum: f64 = gsl.iter().sum();
        let gbar = match control {
            Control::Force(_) if nc > 0 => gsum / nc as f64,
            Control::Force(_) => 0.0,
            Control::Approach(alpha) => alpha,
        };
        // Step 3: g ← g − ḡ, G = Σ_{I_c} g².
        let (mut ggl, mut rl) = ([0.0; L], [0.0_f64; L]);
        {
            let (g, p) = (&mut self.g[..n], &self.p[..n]);
            for_lanes!(n, |i, l| {
                let v = g[i] - gbar;
                g[i] = v;
                ggl[l] += if p[i] > 0.0 { v * v } else { 0.0 };
                rl[l] = rl[l].max(gap_violation(p[i], v));
            });
        }
        let umax = uml.iter().copied().fold(0.0, f64::max);
        let violation = rl.iter().copied().fold(0.0, f64::max);
        GapState {
            nc,
            gg: ggl.iter().sum(),
            residual: if umax > 0.0 {
                violation / umax
            } else {
                violation
            },
        }
    }

    /// Steps 5–6 on a non-empty contact set of `nc` cells: `r = F t`, step length
    /// `τ = Σ g t / Σ (r − r̄) t` over `I_c` (`r̄` its mean on `I_c` in force mode, 0 in approach
    /// mode). `None` on a non-positive or non-finite denominator (numerical breakdown).
    fn step_length(&mut self, nc: usize, control: Control) -> Option<f64> {
        let n = self.grid.len();
        // Step 5: r = F t (minus its mean on I_c in force mode).
        self.conv.apply(&self.t, &mut self.r);
        self.n_conv += 1;
        // Step 6: τ = Σ g t / Σ (r − r̄) t over I_c (t = 0 outside I_c).
        let (mut rsl, mut tsl, mut gtl, mut rtl) = ([0.0; L], [0.0; L], [0.0; L], [0.0; L]);
        {
            let (r, t, g, p) = (&self.r[..n], &self.t[..n], &self.g[..n], &self.p[..n]);
            for_lanes!(n, |i, l| {
                let ti = t[i];
                gtl[l] += g[i] * ti;
                rtl[l] += r[i] * ti;
                tsl[l] += ti;
                rsl[l] += if p[i] > 0.0 { r[i] } else { 0.0 };
            });
        }
        let (rsum, tsum, gt) = (
            rsl.iter().sum::<f64>(),
            tsl.iter().sum::<f64>(),
            gtl.iter().sum::<f64>(),
        );
        let mut rt: f64 = rtl.iter().sum();
        if matches!(control, Control::Force(_)) {
            rt -= rsum / nc as f64 * tsum;
        }
        let tau = gt / rt;
        (tau.is_finite() && rt > 0.0).then_some(tau)
    }

    /// Steps 7–9: p ← p − τ t on I_c, projection onto p ≥ 0, overlap set
    /// I_ol = {p = 0, g < 0} gets p = −τ g. Keeps the previous pressure in `p_old` and the
    /// changed cells in `corr`; returns `(Σ p, whether an overlap cell was loaded)` (an overlap
    /// resets the conjugacy, δ = 0).
    fn project_pressure(&mut self, tau: f64) -> (f64, bool) {
        let n = self.grid.len();
        let f00 = self.table.self_coefficient();
        self.corr.clear();
        let mut overlap = false;
        let mut psl = [0.0; L];
        {
            let (p, p_old, g, t) = (
                &mut self.p[..n],
                &mut self.p_old[..n],
                &self.g[..n],
                &self.t[..n],
            );
            let corr = &mut self.corr;
            for_lanes!(n, |i, l| {
                let po = p[i];
                p_old[i] = po;
                let gi = g[i];
                let pn = if po > 0.0 {
                    let v = po - tau * t[i];
                    if v > 0.0 {
                        v
                    } else {
                        let pn = if gi < 0.0 && tau > 0.0 {
                            overlap = true;
                            -tau * gi
                        } else {
                            0.0
                        };
                        corr.push((i, pn - v));
                        pn
                    }
                } else if gi < 0.0 {
                    overlap = true;
                    // With an empty contact set (approach mode, first iteration) τ = 0:
                    // use a local estimate of the pressure closing the interference.
                    let pn = if tau > 0.0 {
                        -tau * gi
                    } else {
                        -gi / (4.0 * f00)
                    };
                    corr.push((i, pn));
                    pn
                } else {
                    0.0
                };
                p[i] = pn;
                psl[l] += pn;
            });
        }
        (psl.iter().sum(), overlap)
    }

    /// Scale `p ← scale · p`, displacement update (linear part `u ← scale (u − τ r)` plus
    /// direct sums over the cells in `corr`, or a full FFT recomputation every
    /// `recompute_interval` iterations, when many cells changed or with `τ = 0`), and the sums
    /// `(Σ|p − p_old|, Σ p)` of the pressure change of step 11.
    fn scale_and_update_displacement(
        &mut self,
        scale: f64,
        tau: f64,
        cg: &mut CgState,
    ) -> (f64, f64) {
        let n = self.grid.len();
        cg.since_recompute += 1;
        let full = cg.since_recompute >= self.options.recompute_interval
            || self.corr.len() > self.options.sparse_update_max_cells
            || tau == 0.0;
        let (p, p_old) = (&mut self.p[..n], &self.p_old[..n]);
        if full {
            let sums = scale_pressure(p, p_old, scale, |_| {});
            self.conv.apply(&self.p, &mut self.u);
            self.n_conv += 1;
            cg.since_recompute = 0;
            sums
        } else {
            let (u, r) = (&mut self.u[..n], &self.r[..n]);
            let sums = scale_pressure(p, p_old, scale, |i| u[i] = scale * (u[i] - tau * r[i]));
            accumulate_cells(&self.table, &self.corr, scale, &mut self.u);
            sums
        }
    }

    fn finish(&self, gap: &[f64], control: Control, outcome: &Outcome) -> ContactSolution {
        let grid = self.grid;
        let (nx, ny) = (grid.nx, grid.ny);
        let mut nc = 0usize;
        let mut psum = 0.0;
        let mut pmax = 0.0_f64;
        let mut gsum = 0.0;
        for ((&p, &h), &u) in self.p.iter().zip(gap).zip(&self.u) {
            if p > 0.0 {
                nc += 1;
                psum += p;
                pmax = pmax.max(p);
                gsum += h + u;
            }
        }
        let alpha = match control {
            Control::Approach(a) => a,
            Control::Force(_) if nc > 0 => gsum / nc as f64,
            Control::Force(_) => gap.iter().copied().fold(f64::INFINITY, f64::min),
        };
        let umax = self.u.iter().copied().fold(0.0_f64, f64::max);
        let mut res = 0.0_f64;
        for ((&p, &h), &u) in self.p.iter().zip(gap).zip(&self.u) {
            res = res.max(gap_violation(p, h - alpha + u));
        }
        let residual = if umax > 0.0 { res / umax } else { res };
        let in_contact = |i: usize, j: usize| self.p[j * nx + i] > 0.0;
        let touches_edge_x = (0..ny).any(|j| in_contact(0, j) || in_contact(nx - 1, j));
        let touches_edge_y = (0..nx).any(|i| in_contact(i, 0) || in_contact(i, ny - 1));
        ContactSolution {
            grid,
            pressure: self.p.clone(),
            displacement: self.u.clone(),
            approach_m: alpha,
            force_n: grid.cell_area() * psum,
            max_pressure_pa: pmax,
            cells_in_contact: nc,
            iterations: outcome.iterations,
            convolutions: self.n_conv,
            converged: outcome.converged,
            pressure_change: outcome.pressure_change,
            residual,
            touches_edge_x,
            touches_edge_y,
        }
    }
}
