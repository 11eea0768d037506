//! Minimal radix-2 complex FFT for Toeplitz (convolution) matrix–vector products of the elastic
//! influence matrices (O(n log n) instead of O(n²)).

/// Precomputed plan for transforms of length `n` (a power of two).
#[derive(Debug, Clone)]
pub struct Fft {
    n: usize,
    /// Twiddles e^{−2πik/n}, k < n/2 (re, im).
    tw: Vec<(f64, f64)>,
    rev: Vec<usize>,
}

impl Fft {
    /// Plan for length `n` (must be a power of two ≥ 2).
    pub fn new(n: usize) -> Self {
        assert!(n.is_power_of_two() && n >= 2);
        let bits = n.trailing_zeros();
        let rev = (0..n)
            .map(|i| i.reverse_bits() >> (usize::BITS - bits))
            .collect();
        let tw = (0..n / 2)
            .map(|k| {
                let a = -std::f64::consts::TAU * k as f64 / n as f64;
                (a.cos(), a.sin())
            })
            .collect();
        Self { n, tw, rev }
    }

    /// Length.
    pub fn len(&self) -> usize {
        self.n
    }

    /// True for a zero-length plan (never: lengths are ≥ 2).
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// In-place transform; `inverse` uses e^{+…} and scales by 1/n.
    pub fn transform(&self, re: &mut [f64], im: &mut [f64], inverse: bool) {
        let n = self.n;
        for i in 0..n {
            let j = self.rev[i];
            if j > i {
                re.swap(i, j);
                im.swap(i, j);
            }
        }
        let mut len = 2;
        while len <= n {
            let half = len / 2;
            let step = n / len;
            for start in (0..n).step_by(len) {
                for k in 0..half {
                    let (wr, wi0) = self.tw[k * step];
                    let wi = if inverse { -wi0 } else { wi0 };
                    let (a, b) = (start + k, start + k + half);
                    let (xr, xi) = (re[b] * wr - im[b] * wi, re[b] * wi + im[b] * wr);
                    re[b] = re[a] - xr;
                    im[b] = im[a] - xi;
                    re[a] += xr;
                    im[a] += xi;
                }
            }
            len *= 2;
        }
        if inverse {
            let s = 1.0 / n as f64;
            re.iter_mut().for_each(|v| *v *= s);
            im.iter_mut().for_each(|v| *v *= s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fft_round_trip_and_dft() {
        let n = 16;
        let f = Fft::new(n);
        let x: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.7).sin() + 0.1 * i as f64)
            .collect();
        let (mut re, mut im) = (x.clone(), vec![0.0; n]);
        f.transform(&mut re, &mut im, false);
        for k in 0..n {
            let (mut a, mut b) = (0.0, 0.0);
            for (j, xj) in x.iter().enumerate() {
                let t = -std::f64::consts::TAU * (k * j) as f64 / n as f64;
                a += xj * t.cos();
                b += xj * t.sin();
            }
            assert!((a - re[k]).abs() < 1e-12 && (b - im[k]).abs() < 1e-12);
        }
        f.transform(&mut re, &mut im, true);
        for j in 0..n {
            assert!((re[j] - x[j]).abs() < 1e-12 && im[j].abs() < 1e-12);
        }
    }
}
