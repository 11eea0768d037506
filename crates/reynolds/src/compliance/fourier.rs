//! Identification of a compliance function from one (pressure, deflection) pair by regularised
//! Fourier series, seed 002 eqs. (1.2)–(1.5), (2.27)–(2.32), (3.67)–(3.73), SPEC §8.3.
//!
//! With X_k = ∫P sin kφ, Y_k = ∫P cos kφ, C_k = ∫δ sin kφ, D_k = ∫δ cos kφ the convolution theorem
//! gives, per harmonic, M_k X_k + N_k Y_k = C_k/π and M_k Y_k − N_k X_k = D_k/π, i.e.
//! M_k = (X_kC_k + Y_kD_k)/(π(X_k² + Y_k²)), N_k = (Y_kC_k − X_kD_k)/(π(X_k² + Y_k²)),
//! M₀ = D₀/(2πY₀) on a circle; on a plane window of length l the factors are 2/l and 1/l
//! (flag F-61: the seed misplaces the sine sum and indices). Harmonics with X_k² + Y_k² ≈ 0 are
//! skipped. The identification is ill-posed; each harmonic k ≥ 1 is multiplied by the
//! regularising factor g_k = 1/(1 + γk⁴) (the multiplier form of (3.68)–(3.71), flag F-69),
//! optionally with a smaller γ in a central zone (3.76)–(3.77), blended linearly over a band.

use super::{LineKernel, gauss_panels};
use crate::error::{Result, ReynoldsError};

/// Regularisation of the identified series.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Smoothing {
    /// No smoothing (γ = 0).
    #[default]
    None,
    /// One γ everywhere (journal bearing: γ = 10⁻⁴ with n = 10, seed §4.4).
    Uniform {
        /// γ.
        gamma: f64,
    },
    /// γ_c for |x| < `half_width`, γ_o outside (seed (3.77): 0.0002 / 0.0008 with
    /// half_width = 0.03 L_y), blended linearly over ±`blend`·half_width (SPEC proposal 10 %).
    Zonal {
        /// γ in the central zone.
        gamma_centre: f64,
        /// γ outside.
        gamma_outer: f64,
        /// Half width of the central zone, in x units.
        half_width: f64,
        /// Relative half width of the blending band (0 = sharp switch as in the seed).
        blend: f64,
    },
}

/// A compliance function K(x) = Σ_{k=0}^{n} g_k(x)[M_k cos(2πkx/l) + N_k sin(2πkx/l)].
#[derive(Debug, Clone, PartialEq)]
pub struct FourierKernel {
    /// Period l (2π on a circle, in radians; the identification window on a plane, m).
    pub period: f64,
    /// Cosine coefficients M_k (k = 0..=n).
    pub cos: Vec<f64>,
    /// Sine coefficients N_k (N₀ = 0).
    pub sin: Vec<f64>,
    /// Regularisation applied when evaluating.
    pub smoothing: Smoothing,
}

fn trapz_moments(x: &[f64], f: &[f64], omega: f64, periodic: Option<f64>) -> (f64, f64) {
    // (∫ f sin ωx, ∫ f cos ωx) by the trapezoidal rule; periodic: wrap the last interval
    let n = x.len();
    let (mut s, mut c) = (0.0, 0.0);
    let mut add = |xa: f64, fa: f64, xb: f64, fb: f64| {
        let w = 0.5 * (xb - xa);
        s += w * (fa * (omega * xa).sin() + fb * (omega * xb).sin());
        c += w * (fa * (omega * xa).cos() + fb * (omega * xb).cos());
    };
    for i in 0..n - 1 {
        add(x[i], f[i], x[i + 1], f[i + 1]);
    }
    if let Some(p) = periodic {
        add(x[n - 1], f[n - 1], x[0] + p, f[0]);
    }
    (s, c)
}

impl FourierKernel {
    fn check(x: &[f64], p: &[f64], d: &[f64], n: usize) -> Result<()> {
        if x.len() < 2 * n + 2 || p.len() != x.len() || d.len() != x.len() {
            return Err(ReynoldsError::InvalidInput {
                what: "identification samples",
                reason: format!(
                    "need equal-length samples, at least 2n+2 = {} (got {}, {}, {})",
                    2 * n + 2,
                    x.len(),
                    p.len(),
                    d.len()
                ),
            });
        }
        if !x.windows(2).all(|w| w[1] > w[0]) {
            return Err(ReynoldsError::InvalidInput {
                what: "identification samples",
                reason: "coordinates must increase".into(),
            });
        }
        Ok(())
    }

    /// Identifies a periodic kernel on the circle from samples at angles `phi` ∈ [0, 2π)
    /// (increasing), pressure `p` and deflection `delta`, with `n` harmonics (seed (2.27)–(2.32)).
    pub fn identify_periodic(
        phi: &[f64],
        p: &[f64],
        delta: &[f64],
        n: usize,
        smoothing: Smoothing,
    ) -> Result<Self> {
        Self::check(phi, p, delta, n)?;
        let tau = std::f64::consts::TAU;
        let mut cos = vec![0.0; n + 1];
        let mut sin = vec![0.0; n + 1];
        let (_, y0) = trapz_moments(phi, p, 0.0, Some(tau));
        let (_, d0) = trapz_moments(phi, delta, 0.0, Some(tau));
        if y0.abs() < 1e-300 {
            return Err(ReynoldsError::InvalidInput {
                what: "identification pressure",
                reason: "zero mean pressure".into(),
            });
        }
        cos[0] = d0 / (tau * y0);
        let scale = y0 * y0;
        for k in 1..=n {
            let w = k as f64;
            let (xk, yk) = trapz_moments(phi, p, w, Some(tau));
            let (ck, dk) = trapz_moments(phi, delta, w, Some(tau));
            let den = xk * xk + yk * yk;
            if den <= 1e-14 * scale {
                continue;
            }
            cos[k] = (xk * ck + yk * dk) / (std::f64::consts::PI * den);
            sin[k] = (yk * ck - xk * dk) / (std::f64::consts::PI * den);
        }
        Ok(Self {
            period: tau,
            cos,
            sin,
            smoothing,
        })
    }

    /// Identifies a plane kernel from samples on the window [−l/2, l/2] (zero outside), seed
    /// (3.67)–(3.72): K(x) = D₀/(lY₀) + (2/l)Σ[(XC+YD)cos + (YC−XD)sin]/(X²+Y²).
    pub fn identify_plane(
        x: &[f64],
        p: &[f64],
        delta: &[f64],
        window: f64,
        n: usize,
        smoothing: Smoothing,
    ) -> Result<Self> {
        Self::check(x, p, delta, n)?;
        if window.is_nan()
            || window <= 0.0
            || x[0] < -0.5 * window - 1e-12 * window
            || *x.last().unwrap_or(&0.0) > 0.5 * window * (1.0 + 1e-12)
        {
            return Err(ReynoldsError::InvalidInput {
                what: "identification window",
                reason: format!("samples must lie in [−l/2, l/2], l = {window}"),
            });
        }
        let mut cos = vec![0.0; n + 1];
        let mut sin = vec![0.0; n + 1];
        let (_, y0) = trapz_moments(x, p, 0.0, None);
        let (_, d0) = trapz_moments(x, delta, 0.0, None);
        if y0.abs() < 1e-300 {
            return Err(ReynoldsError::InvalidInput {
                what: "identification pressure",
                reason: "zero load".into(),
            });
        }
        cos[0] = d0 / (window * y0);
        let scale = y0 * y0;
        for k in 1..=n {
            let w = std::f64::consts::TAU * k as f64 / window;
            let (xk, yk) = trapz_moments(x, p, w, None);
            let (ck, dk) = trapz_moments(x, delta, w, None);
            let den = xk * xk + yk * yk;
            if den <= 1e-14 * scale {
                continue;
            }
            cos[k] = 2.0 / window * (xk * ck + yk * dk) / den;
            sin[k] = 2.0 / window * (yk * ck - xk * dk) / den;
        }
        Ok(Self {
            period: window,
            cos,
            sin,
            smoothing,
        })
    }

    /// Regularisation factor of harmonic k at position x.
    pub fn factor(&self, k: usize, x: f64) -> f64 {
        let k4 = (k as f64).powi(4);
        let g = |gamma: f64| 1.0 / (1.0 + gamma * k4);
        match self.smoothing {
            Smoothing::None => 1.0,
            Smoothing::Uniform { gamma } => g(gamma),
            Smoothing::Zonal {
                gamma_centre,
                gamma_outer,
                half_width,
                blend,
            } => {
                let ax = x.abs();
                let (a, b) = (half_width * (1.0 - blend), half_width * (1.0 + blend));
                if ax < a || (blend == 0.0 && ax < half_width) {
                    g(gamma_centre)
                } else if ax >= b {
                    g(gamma_outer)
                } else {
                    let t = (ax - a) / (b - a);
                    (1.0 - t) * g(gamma_centre) + t * g(gamma_outer)
                }
            }
        }
    }

    fn zone_breaks(&self) -> Vec<f64> {
        match self.smoothing {
            Smoothing::Zonal {
                half_width, blend, ..
            } => {
                let (a, b) = (half_width * (1.0 - blend), half_width * (1.0 + blend));
                let mut v = vec![-b, -a, a, b];
                v.dedup();
                v
            }
            _ => Vec::new(),
        }
    }

    fn in_blend(&self, x: f64) -> bool {
        match self.smoothing {
            Smoothing::Zonal {
                half_width, blend, ..
            } if blend > 0.0 => {
                let ax = x.abs();
                ax > half_width * (1.0 - blend) && ax < half_width * (1.0 + blend)
            }
            _ => false,
        }
    }

    /// Number of harmonics n.
    pub fn harmonics(&self) -> usize {
        self.cos.len() - 1
    }

    fn segment(&self, u0: f64, u1: f64) -> f64 {
        let mid = 0.5 * (u0 + u1);
        if self.in_blend(mid) {
            return gauss_panels(|u| self.value(u), u0, u1, 4);
        }
        let mut s = self.cos[0] * self.factor(0, mid) * (u1 - u0);
        for k in 1..self.cos.len() {
            let w = std::f64::consts::TAU * k as f64 / self.period;
            let g = self.factor(k, mid);
            s += g / w
                * (self.cos[k] * ((w * u1).sin() - (w * u0).sin())
                    - self.sin[k] * ((w * u1).cos() - (w * u0).cos()));
        }
        s
    }
}

impl LineKernel for FourierKernel {
    fn value(&self, x: f64) -> f64 {
        let mut s = self.cos[0] * self.factor(0, x);
        for k in 1..self.cos.len() {
            let w = std::f64::consts::TAU * k as f64 / self.period;
            let (sn, cs) = (w * x).sin_cos();
            s += self.factor(k, x) * (self.cos[k] * cs + self.sin[k] * sn);
        }
        s
    }

    fn integral(&self, u0: f64, u1: f64) -> f64 {
        if u1 < u0 {
            return -self.integral(u1, u0);
        }
        let mut pts = vec![u0];
        pts.extend(self.zone_breaks().into_iter().filter(|&b| b > u0 && b < u1));
        pts.push(u1);
        pts.windows(2).map(|w| self.segment(w[0], w[1])).sum()
    }
}

/// Seed 002 Table 3.1 (plate) Fourier coefficients of the compliance function, 10⁻¹⁶ 1/Pa
/// (M_k, N_k for k = 0..=20), reproduced for V-31.
pub const SEED_PLATE_TABLE_3_1: ([f64; 21], [f64; 21]) = (
    [
        21.7, 5.88, 1.43, 1.82, 0.675, 1.13, 0.27, 0.823, -0.0384, 0.777, -0.219, 0.860, -17.6,
        -19.6, -0.925, 1.70, 73.3, 2.15, -3.24, 3.75, -0.710,
    ],
    [
        0.0, 0.0555, 0.129, 0.158, 0.109, 0.185, 0.0370, 0.240, -0.0642, 0.412, -0.0609, 0.473,
        -5.07, -5.22, -0.689, 0.379, 7.81, 0.764, -0.107, 1.17, 6.65,
    ],
);

/// Seed 002 Table 3.2 (roller) Fourier coefficients, 10⁻¹⁶ 1/Pa, for V-31.
pub const SEED_ROLLER_TABLE_3_2: ([f64; 21], [f64; 21]) = (
    [
        17.84, 8.02, 2.747, 2.495, 1.277, 1.505, 0.71, 1.111, 0.35, 0.887, 0.208, 0.795, -0.185,
        0.836, -0.606, 1.305, -1.079, 1.865, -2.779, 2.775, -2.301,
    ],
    [
        0.0, 0.7095, 0.3587, 0.5034, 0.3241, 0.5026, 0.3042, 0.5714, 0.2419, 0.618, 0.1402, 0.6316,
        0.0653, 0.6853, -0.276, 0.6684, 0.1297, 0.6569, 0.1541, 1.683, 2.17,
    ],
);

impl FourierKernel {
    /// Kernel from a seed table (coefficients ×10⁻¹⁶ 1/Pa), period `window` and smoothing.
    pub fn from_seed_table(
        table: &([f64; 21], [f64; 21]),
        window: f64,
        smoothing: Smoothing,
    ) -> Self {
        Self {
            period: window,
            cos: table.0.iter().map(|v| v * 1e-16).collect(),
            sin: table.1.iter().map(|v| v * 1e-16).collect(),
            smoothing,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compliance::liner::AnalyticLinerKernel;

    /// Exact data: deflection computed from a known periodic kernel by quadrature; the identified
    /// harmonics must equal the kernel's own Fourier coefficients (to the quadrature error).
    #[test]
    fn identification_recovers_a_known_kernel() {
        let k = AnalyticLinerKernel::seed(1e-12);
        let n = 720;
        let tau = std::f64::consts::TAU;
        let phi: Vec<f64> = (0..n).map(|i| tau * i as f64 / n as f64).collect();
        let p: Vec<f64> = phi
            .iter()
            .map(|&t| {
                let v = (t - 1.0).sin() * (1.0 + 0.5 * t.cos());
                v.max(0.0) + 0.1
            })
            .collect();
        let h = tau / n as f64;
        let delta: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| p[j] * k.value(phi[i] - phi[j]) * h).sum())
            .collect();
        let fk = FourierKernel::identify_periodic(&phi, &p, &delta, 8, Smoothing::None).unwrap();
        for m in 0..=8 {
            // Fourier coefficient of K (even function): a_m = (1/π)∫K cos mφ (a_0: 1/2π)
            let norm = if m == 0 {
                1.0 / tau
            } else {
                1.0 / std::f64::consts::PI
            };
            let am: f64 = phi
                .iter()
                .map(|&t| k.value(t) * (m as f64 * t).cos() * h)
                .sum::<f64>()
                * norm;
            assert!(
                (fk.cos[m] - am).abs() < 1e-6 * k.k0,
                "m={m} {} {am}",
                fk.cos[m]
            );
            assert!(fk.sin[m].abs() < 1e-6 * k.k0);
        }
    }

    /// V-31: the plate kernel of Table 3.1 with the central factor g₁ₖ = 1/(1 + 0.0002k⁴) peaks
    /// at Σ M_k g₁ₖ = 3.2667×10⁻¹⁵ 1/Pa (seed K_max1 = 3.267×10⁻¹⁵: exact). The roller table gives
    /// 3.58×10⁻¹⁵ with g₁ and 3.40×10⁻¹⁵ with g₂ against the seed's 3.45×10⁻¹⁵ (within 4 %).
    #[test]
    fn v31_seed_kernel_peaks() {
        let zonal = Smoothing::Zonal {
            gamma_centre: 0.0002,
            gamma_outer: 0.0008,
            half_width: 0.03 * 0.05,
            blend: 0.0,
        };
        let plate = FourierKernel::from_seed_table(&SEED_PLATE_TABLE_3_1, 0.05, zonal);
        let kmax = plate.value(0.0);
        assert!((kmax - 3.2667e-15).abs() < 1e-4 * 3.2667e-15, "{kmax}");
        let roller = FourierKernel::from_seed_table(&SEED_ROLLER_TABLE_3_2, 0.05, zonal);
        let r1 = roller.value(0.0);
        assert!(
            (r1 - 3.58e-15).abs() < 0.01 * 3.58e-15 && (r1 - 3.45e-15).abs() < 0.04 * 3.45e-15,
            "{r1}"
        );
        // analytic integral consistent with the value
        let i = plate.integral(0.001, 0.002);
        let q = gauss_panels(|u| plate.value(u), 0.001, 0.002, 8);
        assert!((i - q).abs() < 1e-9 * q.abs().max(1e-30));
    }
}
