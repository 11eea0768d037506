//! Compliance (influence) functions, SPEC §8.3: the surface deflection is a linear functional of
//! the pressure, δ(x) = ∫ p(x′) K(x − x′) dx′ (plane) or δ(φ) = ∫ p(φ′) K(φ − φ′) dφ′ (cylinder),
//! seed 002 eqs. (1.1), (2.26), (3.2).
//!
//! * [`half_space`] — elastic half-space line-load kernel (3.3) and a roller-on-axis variant;
//! * [`layer`] — finite-thickness elastic layer (plate) on a rigid base, plane strain, by a
//!   Fourier integral (the seed identifies it from FE; here it is computed);
//! * [`liner`] — journal-bearing liner compliances: Winkler (2.2), exact clamped layer (2.25),
//!   free Lamé layer, two-material K₀ (4.15, F-73) and the analytic kernel (4.14)/(4.36);
//! * [`fourier`] — identification of a kernel from one (pressure, deflection) pair by regularised
//!   Fourier series (1.2)–(1.5), (2.27)–(2.32), (3.67)–(3.73), so FE deflections can be imported.

pub mod fourier;
pub mod half_space;
pub mod layer;
pub mod liner;

use crate::fft::ToeplitzFft;
use crate::grid::Grid1d;

/// A plane-strain line compliance kernel K(u) (m of deflection per Pa of pressure per m of
/// loaded length, i.e. 1/Pa), deflection positive away from the film (opening the gap).
pub trait LineKernel: Send + Sync {
    /// K(u).
    fn value(&self, u: f64) -> f64;

    /// ∫_{u0}^{u1} K(u) du. Default: 8-point Gauss–Legendre on 16 panels, with the panels graded
    /// towards u = 0 when the interval contains it (log-type singularity).
    fn integral(&self, u0: f64, u1: f64) -> f64 {
        if u1 < u0 {
            return -self.integral(u1, u0);
        }
        if u0 < 0.0 && u1 > 0.0 {
            return graded(self, -u0, -1.0) + graded(self, u1, 1.0);
        }
        if u0 == 0.0 {
            return graded(self, u1, 1.0);
        }
        if u1 == 0.0 {
            return graded(self, -u0, -1.0);
        }
        gauss_panels(|u| self.value(u), u0, u1, 16)
    }
}

/// ∫₀ᵃ K(sign·u) du (a > 0) with geometric panels towards u = 0 (integrable log singularity).
fn graded<K: LineKernel + ?Sized>(k: &K, a: f64, sign: f64) -> f64 {
    let f = |u: f64| k.value(sign * u);
    let mut total = 0.0;
    let mut hi = a;
    for _ in 0..24 {
        let lo = hi * 0.25;
        total += gauss_panels(f, lo, hi, 1);
        hi = lo;
    }
    total
}

/// Composite 8-point Gauss–Legendre (`rolldyn_numerics::gauss_legendre`).
pub(crate) use rolldyn_numerics::gauss_legendre::integrate as gauss_panels;

/// Sum of kernels (e.g. plate + roller).
pub struct KernelSum<'a>(pub Vec<&'a dyn LineKernel>);

impl LineKernel for KernelSum<'_> {
    fn value(&self, u: f64) -> f64 {
        self.0.iter().map(|k| k.value(u)).sum()
    }
    fn integral(&self, u0: f64, u1: f64) -> f64 {
        self.0.iter().map(|k| k.integral(u0, u1)).sum()
    }
}

/// Influence matrix D on a 1-D grid: δᵢ = Σⱼ Dᵢⱼ pⱼ with piecewise-constant pressure on the
/// control volumes, Dᵢⱼ = ∫_{cell j} K(xᵢ − s) ds. Toeplitz storage on uniform grids.
#[derive(Debug, Clone)]
pub struct Influence {
    n: usize,
    toeplitz: bool,
    /// Toeplitz: d[(i − j) + n − 1]; dense: row-major n×n.
    d: Vec<f64>,
    /// FFT product for Toeplitz matrices (n ≥ 64).
    fft: Option<ToeplitzFft>,
}

impl Influence {
    /// Builds D for `kernel` on `grid` (uniform grids: 2n − 1 kernel integrals; otherwise n²).
    pub fn new(grid: &Grid1d, kernel: &dyn LineKernel) -> Self {
        let n = grid.len();
        if grid.is_uniform() {
            let h = (grid.x[n - 1] - grid.x[0]) / (n - 1) as f64;
            let d = (0..2 * n - 1)
                .map(|m| {
                    let k = m as f64 - (n - 1) as f64; // i − j
                    kernel.integral(k * h - 0.5 * h, k * h + 0.5 * h)
                })
                .collect::<Vec<f64>>();
            let fft = (n >= 64).then(|| ToeplitzFft::new(&d));
            Self {
                n,
                toeplitz: true,
                d,
                fft,
            }
        } else {
            let f = grid.faces();
            let mut d = vec![0.0; n * n];
            for i in 0..n {
                for j in 0..n {
                    d[i * n + j] = kernel.integral(grid.x[i] - f[j + 1], grid.x[i] - f[j]);
                }
            }
            Self {
                n,
                toeplitz: false,
                d,
                fft: None,
            }
        }
    }

    /// Size.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Dᵢⱼ.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> f64 {
        if self.toeplitz {
            self.d[i + self.n - 1 - j]
        } else {
            self.d[i * self.n + j]
        }
    }

    /// δ = D p.
    pub fn apply(&self, p: &[f64], out: &mut [f64]) {
        let n = self.n;
        if let Some(fft) = &self.fft {
            fft.apply(p, out);
            return;
        }
        for i in 0..n {
            let mut s = 0.0;
            if self.toeplitz {
                // d index i − j + n − 1 runs from i + n − 1 down to i
                let row = &self.d[i..i + n];
                for (j, pj) in p.iter().enumerate() {
                    s += row[n - 1 - j] * pj;
                }
            } else {
                let row = &self.d[i * n..(i + 1) * n];
                for (a, b) in row.iter().zip(p) {
                    s += a * b;
                }
            }
            out[i] = s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compliance::half_space::HalfSpace;

    #[test]
    fn influence_matches_direct_quadrature() {
        let hs = HalfSpace::new(2.1e11, 0.3, 0.01);
        let g = Grid1d::uniform(-1e-3, 1e-3, 41).unwrap();
        let d = Influence::new(&g, &hs);
        let gn = Grid1d {
            x: g.x.iter().map(|v| v + 1e-9 * v * v * 1e6).collect(),
        };
        let dn = Influence::new(&gn, &hs);
        for (i, j) in [(3, 3), (10, 20), (39, 1)] {
            let a = d.get(i, j);
            let b = dn.get(i, j);
            assert!((a - b).abs() < 1e-3 * a.abs(), "{a} {b}");
        }
        // default graded quadrature of the log kernel vs the analytic integral
        struct Plain(HalfSpace);
        impl LineKernel for Plain {
            fn value(&self, u: f64) -> f64 {
                self.0.value(u)
            }
        }
        let p = Plain(hs);
        let (a, b) = (p.integral(-2e-5, 3e-5), hs.integral(-2e-5, 3e-5));
        assert!((a - b).abs() < 1e-9 * b.abs(), "{a} {b}");
        // FFT product equals the direct Toeplitz product
        let g2 = Grid1d::uniform(-1e-3, 1e-3, 100).unwrap();
        let d2 = Influence::new(&g2, &hs);
        let pv: Vec<f64> = (0..100).map(|i| ((i as f64) * 0.37).sin().abs()).collect();
        let mut out = vec![0.0; 100];
        d2.apply(&pv, &mut out);
        for i in 0..100 {
            let direct: f64 = (0..100).map(|j| d2.get(i, j) * pv[j]).sum();
            assert!(
                (direct - out[i]).abs() < 1e-12 * direct.abs().max(1e-20),
                "{i}"
            );
        }
    }
}
