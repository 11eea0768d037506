//! Dormand–Prince 5(4) embedded Runge–Kutta integrator with PI step-size control, FSAL and
//! 4th-order dense output (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4–II.6; coefficients
//! of `dopri5.f`). Written for this crate: every buffer is allocated once, a step allocates
//! nothing, and the result is bit-for-bit deterministic (no parallelism, fixed operation order).
//!
//! Error norm: max over components of `|e_i| / (τ (s_i + ρ_i max(|y_i|, |ŷ_i|)))` with
//! per-component scales `s_i` and relative flags `ρ_i` (see [`crate`] docs, "Error control"). The
//! component attaining the maximum is counted in [`StepStats::limiting`] — "which state limits
//! the step".

use crate::settings::IntegratorSettings;

/// A first-order ODE system `ẏ = f(t, y)`.
pub trait OdeSystem {
    /// Evaluates `dy = f(t, y)`. Must not allocate in hot use.
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]);

    /// Evaluates `dy = f(t, y)` at a state the integrator may accept (the start state and each
    /// step's new state). Systems that report per-evaluation side results (contact tables,
    /// powers) compute them here only; the intermediate stages call [`OdeSystem::rhs`].
    fn rhs_reported(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.rhs(t, y, dy);
    }

    /// For a bordered Rosenbrock-W Jacobian ([`crate::rosenbrock::JacobianBorder`]): writes the
    /// additive share of each coupled block's contacts in the border rates of the last
    /// evaluation, block after block, each in the order of its support. Systems without a
    /// border keep the default (nothing).
    fn border_shares(&self, _out: &mut [f64]) {}
}

/// Step statistics.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepStats {
    /// accepted steps
    pub accepted: u64,
    /// rejected steps
    pub rejected: u64,
    /// right-hand-side evaluations (incl. those of finite-difference Jacobians)
    pub rhs_evaluations: u64,
    /// Jacobian evaluations (Rosenbrock-W only)
    pub jacobian_evaluations: u64,
    /// per state component: how often it had the largest scaled error (accepted and rejected
    /// steps)
    pub limiting: Vec<u64>,
}

impl StepStats {
    /// Index of the component that limited the step most often.
    pub fn most_limiting(&self) -> Option<usize> {
        self.limiting
            .iter()
            .enumerate()
            .max_by_key(|(_, c)| **c)
            .filter(|(_, c)| **c > 0)
            .map(|(i, _)| i)
    }
}

/// Outcome of one attempted step sequence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepError {
    /// the step fell below the minimum; the component with the largest error
    Collapse { h: f64, component: usize },
    /// the state became non-finite at every step size down to the minimum
    NonFinite { h: f64, component: usize },
}

// Dormand–Prince 5(4) tableau
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// The integrator state (everything needed to continue a run bit-for-bit).
#[derive(Debug, Clone)]
pub struct Dopri5 {
    /// current time, s
    pub t: f64,
    /// current state
    pub y: Vec<f64>,
    /// next step size to try, s
    pub h: f64,
    /// previous accepted error (PI memory)
    pub err_old: f64,
    /// whether the last attempt was rejected (no growth right after a rejection)
    pub last_rejected: bool,
    /// `f(t, y)` is in `k[0]` (FSAL)
    pub k1_valid: bool,
    /// step statistics
    pub stats: StepStats,
    /// per-component error scale `s_i`
    pub scale: Vec<f64>,
    /// per-component relative flag `ρ_i`
    pub relative: Vec<f64>,
    pub(crate) k: [Vec<f64>; 7],
    ytmp: Vec<f64>,
    ynew: Vec<f64>,
    /// dense output of the last accepted step: t_old, h and 5 coefficient vectors
    pub(crate) dense_t: f64,
    pub(crate) dense_h: f64,
    dense: [Vec<f64>; 5],
}

impl Dopri5 {
    /// New integrator at `(t, y)` with error scales.
    pub fn new(t: f64, y: Vec<f64>, scale: Vec<f64>, relative: Vec<f64>, h0: f64) -> Self {
        let n = y.len();
        let z = || vec![0.0; n];
        Self {
            t,
            h: h0,
            err_old: 1e-4,
            last_rejected: false,
            k1_valid: false,
            stats: StepStats {
                limiting: vec![0; n],
                ..StepStats::default()
            },
            scale,
            relative,
            k: [z(), z(), z(), z(), z(), z(), z()],
            ytmp: z(),
            ynew: z(),
            dense_t: t,
            dense_h: 0.0,
            dense: [y.clone(), z(), z(), z(), z()],
            y,
        }
    }

    /// Dimension.
    pub fn dim(&self) -> usize {
        self.y.len()
    }

    /// `ytmp = y + h Σ a_s k_s` over the stages `coeffs` (a compile-time count, and every
    /// column cut to the dimension, so that the loop is vectorised).
    #[inline(always)]
    fn stage<const S: usize>(&mut self, h: f64, coeffs: [(usize, f64); S]) {
        let n = self.y.len();
        let (k, y, ytmp) = (&self.k, &self.y[..n], &mut self.ytmp[..n]);
        let columns = coeffs.map(|(s, _)| &k[s][..n]);
        for i in 0..n {
            let mut acc = 0.0;
            for (column, &(_, a)) in columns.iter().zip(&coeffs) {
                acc += a * column[i];
            }
            ytmp[i] = y[i] + h * acc;
        }
    }

    /// Takes one accepted step (retrying rejected ones). `sys` is evaluated at the stage points;
    /// its last evaluation is at the new accepted state `(t, y)` (FSAL), so per-evaluation side
    /// results of `sys` describe the accepted state when this returns `Ok`.
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        set: &IntegratorSettings,
    ) -> Result<(), StepError> {
        let n = self.y.len();
        if !self.k1_valid {
            let (k0, _) = self.k.split_at_mut(1);
            sys.rhs_reported(self.t, &self.y, &mut k0[0]);
            self.stats.rhs_evaluations += 1;
            self.k1_valid = true;
        }
        let expo1 = 0.2 - 0.75 * set.pi_beta;
        loop {
            let h = self.h.min(set.max_step_s);
            let t = self.t;
            let mut nonfinite_at = None;
            macro_rules! eval {
                ($dst:expr, $c:expr) => {{
                    let (ytmp, k) = (&self.ytmp, &mut self.k);
                    sys.rhs(t + $c * h, ytmp, &mut k[$dst]);
                }};
            }
            self.stage(h, [(0, A21)]);
            eval!(1, C2);
            self.stage(h, [(0, A31), (1, A32)]);
            eval!(2, C3);
            self.stage(h, [(0, A41), (1, A42), (2, A43)]);
            eval!(3, C4);
            self.stage(h, [(0, A51), (1, A52), (2, A53), (3, A54)]);
            eval!(4, C5);
            self.stage(h, [(0, A61), (1, A62), (2, A63), (3, A64), (4, A65)]);
            eval!(5, 1.0);
            self.stage(h, [(0, A71), (2, A73), (3, A74), (4, A75), (5, A76)]);
            std::mem::swap(&mut self.ytmp, &mut self.ynew);
            {
                let (ynew, k) = (&self.ynew, &mut self.k);
                sys.rhs_reported(t + h, ynew, &mut k[6]);
            }
            self.stats.rhs_evaluations += 6;
            // error estimate (every column cut to the dimension: no bounds checks)
            let [k0, _, k2, k3, k4, k5, k6] = self.k.each_ref().map(|c| &c[..n]);
            let (y, ynew) = (&self.y[..n], &self.ynew[..n]);
            let (scale, relative) = (&self.scale[..n], &self.relative[..n]);
            let mut err = 0.0_f64;
            let mut arg = 0usize;
            for i in 0..n {
                let e = h
                    * (E1 * k0[i] + E3 * k2[i] + E4 * k3[i] + E5 * k4[i] + E6 * k5[i] + E7 * k6[i]);
                let sc = set.tolerance * (scale[i] + relative[i] * y[i].abs().max(ynew[i].abs()));
                let r = (e / sc).abs();
                if !r.is_finite() || !ynew[i].is_finite() || !k6[i].is_finite() {
                    if nonfinite_at.is_none() {
                        nonfinite_at = Some(i);
                    }
                } else if r > err {
                    err = r;
                    arg = i;
                }
            }
            if let Some(i) = nonfinite_at {
                self.stats.rejected += 1;
                self.last_rejected = true;
                self.h = h * set.min_shrink;
                if self.h < set.min_step_s {
                    return Err(StepError::NonFinite { h, component: i });
                }
                continue;
            }
            self.stats.limiting[arg] += 1;
            if err <= 1.0 {
                // dense output coefficients (Hairer's contd5)
                let [k0, _, k2, k3, k4, k5, k6] = self.k.each_ref().map(|c| &c[..n]);
                let (y, ynew) = (&self.y[..n], &self.ynew[..n]);
                let [d0, d1, d2, d3, d4] = self.dense.each_mut().map(|c| &mut c[..n]);
                for i in 0..n {
                    let y0 = y[i];
                    let y1 = ynew[i];
                    let dy = y1 - y0;
                    let bspl = h * k0[i] - dy;
                    d0[i] = y0;
                    d1[i] = dy;
                    d2[i] = bspl;
                    d3[i] = dy - h * k6[i] - bspl;
                    d4[i] = h
                        * (D1 * k0[i]
                            + D3 * k2[i]
                            + D4 * k3[i]
                            + D5 * k4[i]
                            + D6 * k5[i]
                            + D7 * k6[i]);
                }
                self.dense_t = t;
                self.dense_h = h;
                std::mem::swap(&mut self.y, &mut self.ynew);
                self.k.swap(0, 6);
                self.t = t + h;
                self.stats.accepted += 1;
                self.h = accepted_step(h, err, self.err_old, self.last_rejected, expo1, set);
                self.err_old = err.max(1e-4);
                self.last_rejected = false;
                return Ok(());
            }
            self.stats.rejected += 1;
            self.last_rejected = true;
            let fac = (set.safety * err.powf(-expo1)).clamp(set.min_shrink, 1.0);
            self.h = h * fac;
            if self.h < set.min_step_s {
                return Err(StepError::Collapse {
                    h: self.h,
                    component: arg,
                });
            }
        }
    }

    /// Dense output at `t` inside the last accepted step, written to `out`.
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        let th = if self.dense_h > 0.0 {
            (t - self.dense_t) / self.dense_h
        } else {
            1.0
        };
        let th1 = 1.0 - th;
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.dense[0][i]
                + th * (self.dense[1][i]
                    + th1 * (self.dense[2][i] + th * (self.dense[3][i] + th1 * self.dense[4][i])));
        }
    }

    /// Start time of the last accepted step (dense output covers `[dense_start, t]`).
    pub fn dense_start(&self) -> f64 {
        self.dense_t
    }

    pub(crate) fn dense_parts(&self) -> &[Vec<f64>; 5] {
        &self.dense
    }

    pub(crate) fn dense_parts_mut(&mut self) -> &mut [Vec<f64>; 5] {
        &mut self.dense
    }
}

/// Next step size after an accepted step: PI controller (Hairer, Nørsett & Wanner I, §II.4;
/// Gustafsson) `h · safety · err^(−expo1) · err_old^β`, bounded by the shrink/growth limits,
/// no growth right after a rejection, at most `max_step_s`. Shared by DOPRI5 and the
/// Rosenbrock-W method (which pass their own `expo1`).
pub(crate) fn accepted_step(
    h: f64,
    err: f64,
    err_old: f64,
    last_rejected: bool,
    expo1: f64,
    set: &IntegratorSettings,
) -> f64 {
    let mut fac = set.safety * err.max(1e-10).powf(-expo1) * err_old.powf(set.pi_beta);
    fac = fac.clamp(set.min_shrink, set.max_growth);
    if last_rejected {
        fac = fac.min(1.0);
    }
    (h * fac).min(set.max_step_s)
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Osc;
    impl OdeSystem for Osc {
        fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -y[0];
        }
    }

    #[test]
    fn harmonic_oscillator_and_dense_output() {
        let set = IntegratorSettings {
            tolerance: 1e-9,
            max_step_s: 1.0,
            ..IntegratorSettings::default()
        };
        let mut ig = Dopri5::new(0.0, vec![1.0, 0.0], vec![1.0, 1.0], vec![0.0, 0.0], 1e-3);
        let mut out = [0.0; 2];
        let mut worst: f64 = 0.0;
        while ig.t < 10.0 {
            ig.step(&mut Osc, &set).unwrap();
            let tm = ig.dense_start() + 0.37 * (ig.t - ig.dense_start());
            ig.interpolate(tm, &mut out);
            worst = worst.max((out[0] - tm.cos()).abs());
        }
        assert!(
            (ig.y[0] - ig.t.cos()).abs() < 1e-7,
            "{}",
            ig.y[0] - ig.t.cos()
        );
        assert!(worst < 1e-7, "dense output error {worst}");
        assert!(ig.stats.rhs_evaluations == 1 + 6 * (ig.stats.accepted + ig.stats.rejected));
    }
}
