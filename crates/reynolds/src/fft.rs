//! Toeplitz matrix–vector products by FFT (`rustfft`) for the elastic influence matrices:
//! O(n log n) instead of O(n²). The n × n Toeplitz matrix `Dᵢⱼ = d(i − j)` is embedded in a
//! circulant of length `N ≥ 2n`, whose product is a cyclic convolution: `D p = IFFT(FFT(c) ·
//! FFT(p))`, first n entries, with `p` zero-padded.

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Planned FFT product with a fixed Toeplitz matrix.
#[derive(Clone)]
pub struct ToeplitzFft {
    n: usize,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
    /// FFT of the circulant's first column, scaled by 1/N (the inverse transform is unscaled).
    kernel: Vec<Complex<f64>>,
}

impl std::fmt::Debug for ToeplitzFft {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ToeplitzFft")
            .field("n", &self.n)
            .field("len", &self.kernel.len())
            .finish()
    }
}

impl ToeplitzFft {
    /// Plan for the n × n Toeplitz matrix with `lags[(i − j) + n − 1] = Dᵢⱼ` (2n − 1 values).
    pub fn new(lags: &[f64]) -> Self {
        let n = lags.len().div_ceil(2);
        let big = (2 * n).next_power_of_two();
        let mut planner = FftPlanner::new();
        let forward = planner.plan_fft_forward(big);
        let inverse = planner.plan_fft_inverse(big);
        // circulant column: c[m] = d for lag m (i − j = m mod N)
        let mut kernel = vec![Complex::new(0.0, 0.0); big];
        for m in 0..n {
            kernel[m].re = lags[m + n - 1];
            if m > 0 {
                kernel[big - m].re = lags[n - 1 - m];
            }
        }
        forward.process(&mut kernel);
        let scale = 1.0 / big as f64;
        kernel.iter_mut().for_each(|k| *k *= scale);
        Self {
            n,
            forward,
            inverse,
            kernel,
        }
    }

    /// `out = D p` (first n entries of `p` and `out`).
    pub fn apply(&self, p: &[f64], out: &mut [f64]) {
        let n = self.n;
        let mut work = vec![Complex::new(0.0, 0.0); self.kernel.len()];
        for (w, &pj) in work.iter_mut().zip(&p[..n]) {
            w.re = pj;
        }
        self.forward.process(&mut work);
        for (w, k) in work.iter_mut().zip(&self.kernel) {
            *w *= k;
        }
        self.inverse.process(&mut work);
        for (o, w) in out[..n].iter_mut().zip(&work) {
            *o = w.re;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::ToeplitzFft;

    #[test]
    fn matches_the_direct_toeplitz_product() {
        let n = 13;
        let lags: Vec<f64> = (0..2 * n - 1).map(|m| 1.0 / (1.0 + m as f64)).collect();
        let p: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin() + 0.1).collect();
        let mut out = vec![0.0; n];
        ToeplitzFft::new(&lags).apply(&p, &mut out);
        for (i, oi) in out.iter().enumerate() {
            let direct: f64 = (0..n).map(|j| lags[i + n - 1 - j] * p[j]).sum();
            assert!((oi - direct).abs() < 1e-13, "{i}: {oi} vs {direct}");
        }
    }
}
