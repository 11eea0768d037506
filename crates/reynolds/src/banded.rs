//! Banded direct solvers: LU with partial pivoting for general band matrices and Cholesky for
//! symmetric positive definite ones, plus the Schur-complement (bordered) solve used for periodic
//! wrap-around couplings and a few dense rows; the Schur complement is factorised by
//! [`rolldyn_numerics::dense_lu`].
//!
//! Unknowns of the 2-D Reynolds solver are ordered axial-fastest, so the bandwidth equals the
//! number of axial nodes and a factorisation costs n·b²/2 (Cholesky) or n·kl·(kl+ku) (LU).

use crate::error::{Result, ReynoldsError};
use rolldyn_numerics::dense_lu::DenseLu;

/// General band matrix with `kl` sub- and `ku` super-diagonals, stored by rows with room for the
/// fill-in of partial pivoting (row i holds columns i−kl … i+kl+ku).
#[derive(Debug, Clone)]
pub struct BandMatrix {
    n: usize,
    kl: usize,
    ku: usize,
    w: usize,
    a: Vec<f64>,
}

impl BandMatrix {
    /// Zero n×n matrix with the given bandwidths.
    pub fn new(n: usize, kl: usize, ku: usize) -> Self {
        let w = 2 * kl + ku + 1;
        Self {
            n,
            kl,
            ku,
            w,
            a: vec![0.0; n * w],
        }
    }

    /// Resets all entries to zero (keeps the allocation).
    pub fn clear(&mut self) {
        self.a.iter_mut().for_each(|v| *v = 0.0);
    }

    /// Order of the matrix.
    pub fn n(&self) -> usize {
        self.n
    }

    #[inline]
    fn idx(&self, i: usize, j: usize) -> usize {
        debug_assert!(
            j + self.kl >= i && j <= i + self.ku,
            "({i},{j}) outside band"
        );
        i * self.w + (j + self.kl - i)
    }

    /// Adds `v` to entry (i, j); (i, j) must lie inside the band.
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let k = self.idx(i, j);
        self.a[k] += v;
    }

    /// Sets entry (i, j).
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, v: f64) {
        let k = self.idx(i, j);
        self.a[k] = v;
    }

    /// Entry (i, j) (zero outside the band).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        if j + self.kl < i || j > i + self.ku {
            0.0
        } else {
            self.a[self.idx(i, j)]
        }
    }

    /// y = A x.
    pub fn matvec(&self, x: &[f64], y: &mut [f64]) {
        for i in 0..self.n {
            let lo = i.saturating_sub(self.kl);
            let hi = (i + self.ku).min(self.n - 1);
            let mut s = 0.0;
            for j in lo..=hi {
                s += self.a[i * self.w + (j + self.kl - i)] * x[j];
            }
            y[i] = s;
        }
    }

    /// LU factorisation with partial pivoting (consumes the matrix).
    pub fn factor(mut self) -> Result<BandLu> {
        let (n, kl, ku, w) = (self.n, self.kl, self.ku, self.w);
        let mut piv = vec![0usize; n];
        let mut mult = vec![0.0; n * kl.max(1)];
        let a = &mut self.a;
        for k in 0..n {
            let last_row = (k + kl).min(n - 1);
            let last_col = (k + kl + ku).min(n - 1);
            // pivot search in column k
            let mut p = k;
            let mut best = a[k * w + kl].abs();
            for i in k + 1..=last_row {
                let v = a[i * w + (k + kl - i)].abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
            if best == 0.0 || !best.is_finite() {
                return Err(ReynoldsError::Singular("band LU"));
            }
            piv[k] = p;
            if p != k {
                for j in k..=last_col {
                    let ik = k * w + (j + kl - k);
                    let ip = p * w + (j + kl - p);
                    a.swap(ik, ip);
                }
            }
            let pivot = a[k * w + kl];
            let inv = 1.0 / pivot;
            for i in k + 1..=last_row {
                let ik = i * w + (k + kl - i);
                let m = a[ik] * inv;
                a[ik] = 0.0;
                mult[k * kl + (i - k - 1)] = m;
                if m != 0.0 {
                    // row_i[k+1..=last_col] -= m * row_k[k+1..=last_col]
                    let len = last_col - k;
                    let (rk0, ri0) = (k * w + kl + 1, i * w + (k + 1 + kl - i));
                    if ri0 > rk0 {
                        let (head, tail) = a.split_at_mut(ri0);
                        let rk = &head[rk0..rk0 + len];
                        let ri = &mut tail[..len];
                        for (x, y) in ri.iter_mut().zip(rk) {
                            *x -= m * y;
                        }
                    }
                }
            }
        }
        Ok(BandLu {
            n,
            kl,
            ku,
            w,
            a: self.a,
            piv,
            mult,
        })
    }
}

/// LU factors of a [`BandMatrix`].
#[derive(Debug, Clone)]
pub struct BandLu {
    n: usize,
    kl: usize,
    ku: usize,
    w: usize,
    a: Vec<f64>,
    piv: Vec<usize>,
    mult: Vec<f64>,
}

impl BandLu {
    /// Solves A x = b in place.
    pub fn solve(&self, b: &mut [f64]) {
        let (n, kl, ku, w) = (self.n, self.kl, self.ku, self.w);
        for k in 0..n {
            let p = self.piv[k];
            if p != k {
                b.swap(k, p);
            }
            let bk = b[k];
            if bk != 0.0 {
                let last_row = (k + kl).min(n - 1);
                for i in k + 1..=last_row {
                    b[i] -= self.mult[k * kl + (i - k - 1)] * bk;
                }
            }
        }
        for k in (0..n).rev() {
            let last_col = (k + kl + ku).min(n - 1);
            let row = &self.a[k * w..(k + 1) * w];
            let mut s = b[k];
            for j in k + 1..=last_col {
                s -= row[j + kl - k] * b[j];
            }
            b[k] = s / row[kl];
        }
    }
}

/// Symmetric band matrix (lower triangle stored), bandwidth `b`.
#[derive(Debug, Clone)]
pub struct SymBandMatrix {
    n: usize,
    b: usize,
    a: Vec<f64>,
}

impl SymBandMatrix {
    /// Zero n×n matrix with half-bandwidth `b`.
    pub fn new(n: usize, b: usize) -> Self {
        Self {
            n,
            b,
            a: vec![0.0; n * (b + 1)],
        }
    }

    /// Order.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Resets to zero.
    pub fn clear(&mut self) {
        self.a.iter_mut().for_each(|v| *v = 0.0);
    }

    /// Adds `v` to (i, j) with j ≤ i ≤ j + b (the symmetric entry is implied).
    #[inline]
    pub fn add_lower(&mut self, i: usize, j: usize, v: f64) {
        debug_assert!(j <= i && i - j <= self.b);
        self.a[i * (self.b + 1) + (j + self.b - i)] += v;
    }

    /// Entry (i, j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if j > i { (j, i) } else { (i, j) };
        if i - j > self.b {
            0.0
        } else {
            self.a[i * (self.b + 1) + (j + self.b - i)]
        }
    }

    /// y = A x.
    pub fn matvec(&self, x: &[f64], y: &mut [f64]) {
        let (n, b) = (self.n, self.b);
        y[..n].iter_mut().for_each(|v| *v = 0.0);
        for i in 0..n {
            let lo = i.saturating_sub(b);
            let row = &self.a[i * (b + 1)..(i + 1) * (b + 1)];
            let mut s = row[b] * x[i];
            for j in lo..i {
                let v = row[j + b - i];
                s += v * x[j];
                y[j] += v * x[i];
            }
            y[i] += s;
        }
    }

    /// Cholesky factorisation A = L Lᵀ (row-oriented, inner loops are contiguous dot products).
    pub fn cholesky(mut self) -> Result<BandCholesky> {
        let (n, b) = (self.n, self.b);
        let bw = b + 1;
        let a = &mut self.a;
        for i in 0..n {
            let lo = i.saturating_sub(b);
            for j in lo..=i {
                // L_ij = (A_ij − Σ_k L_ik L_jk) / L_jj, k from max(lo, j−b) to j−1
                let klo = lo.max(j.saturating_sub(b));
                let mut s = a[i * bw + (j + b - i)];
                if klo < j {
                    let ri = i * bw + (klo + b - i);
                    let rj = j * bw + (klo + b - j);
                    let len = j - klo;
                    let mut acc = [0.0f64; 4];
                    let (xi, xj) = (&a[ri..ri + len], &a[rj..rj + len]);
                    let chunks = len / 4;
                    for c in 0..chunks {
                        for t in 0..4 {
                            acc[t] += xi[4 * c + t] * xj[4 * c + t];
                        }
                    }
                    let mut tail = 0.0;
                    for t in 4 * chunks..len {
                        tail += xi[t] * xj[t];
                    }
                    s -= (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail;
                }
                if j == i {
                    if s <= 0.0 || !s.is_finite() {
                        return Err(ReynoldsError::Singular("band Cholesky"));
                    }
                    a[i * bw + b] = s.sqrt();
                } else {
                    a[i * bw + (j + b - i)] = s / a[j * bw + b];
                }
            }
        }
        Ok(BandCholesky { n, b, l: self.a })
    }
}

/// Cholesky factor of a [`SymBandMatrix`].
#[derive(Debug, Clone)]
pub struct BandCholesky {
    n: usize,
    b: usize,
    l: Vec<f64>,
}

impl BandCholesky {
    /// Solves A x = rhs in place.
    pub fn solve(&self, x: &mut [f64]) {
        let (n, b) = (self.n, self.b);
        let bw = b + 1;
        for i in 0..n {
            let lo = i.saturating_sub(b);
            let row = &self.l[i * bw..(i + 1) * bw];
            let mut s = x[i];
            for j in lo..i {
                s -= row[j + b - i] * x[j];
            }
            x[i] = s / row[b];
        }
        for i in (0..n).rev() {
            let xi = x[i] / self.l[i * bw + b];
            x[i] = xi;
            let lo = i.saturating_sub(b);
            let row = &self.l[i * bw..(i + 1) * bw];
            for j in lo..i {
                x[j] -= row[j + b - i] * xi;
            }
        }
    }
}

/// A factorised square matrix that can solve in place.
pub trait Factor {
    /// Solves A x = b in place.
    fn solve_in_place(&self, b: &mut [f64]);
}

impl Factor for BandLu {
    fn solve_in_place(&self, b: &mut [f64]) {
        self.solve(b)
    }
}

impl Factor for BandCholesky {
    fn solve_in_place(&self, b: &mut [f64]) {
        self.solve(b)
    }
}

/// Bordered system [[A, E], [F, G]] [x; z] = [r; s] with A factorised (band) and a small border
/// of size m: E is n×m (column-major: `e[c]` is column c), F is m×n (row-major: `f[r]` is row r),
/// G is m×m row-major. Solved by the Schur complement S = G − F A⁻¹ E.
pub struct Bordered<'a, A: Factor> {
    /// Factorised interior block.
    pub a: &'a A,
    /// Border columns (each of length n).
    pub e: &'a [Vec<f64>],
    /// Border rows (each of length n).
    pub f: &'a [Vec<f64>],
    /// Corner block, m×m row-major.
    pub g: &'a [f64],
}

/// Factorised bordered system, reusable for several right-hand sides.
pub struct BorderedFactor<'a, A: Factor> {
    sys: Bordered<'a, A>,
    aie: Vec<Vec<f64>>,
    schur: DenseLu,
}

impl<'a, A: Factor> Bordered<'a, A> {
    /// Computes A⁻¹E and the Schur complement.
    pub fn factor(self) -> Result<BorderedFactor<'a, A>> {
        let m = self.e.len();
        let mut aie = Vec::with_capacity(m);
        for c in 0..m {
            let mut col = self.e[c].clone();
            self.a.solve_in_place(&mut col);
            aie.push(col);
        }
        let mut s = self.g.to_vec();
        for r in 0..m {
            for c in 0..m {
                let fr = &self.f[r];
                let d: f64 = fr.iter().zip(&aie[c]).map(|(x, y)| x * y).sum();
                s[r * m + c] -= d;
            }
        }
        let schur = DenseLu::new(m, s).map_err(|_| ReynoldsError::Singular("dense LU"))?;
        Ok(BorderedFactor {
            sys: self,
            aie,
            schur,
        })
    }
}

impl<A: Factor> BorderedFactor<'_, A> {
    /// Solves for (x, z): `r` (length n) is overwritten by x, `s` (length m) by z.
    pub fn solve(&self, r: &mut [f64], s: &mut [f64]) {
        let m = s.len();
        self.sys.a.solve_in_place(r);
        for k in 0..m {
            let d: f64 = self.sys.f[k].iter().zip(r.iter()).map(|(x, y)| x * y).sum();
            s[k] -= d;
        }
        self.schur.solve(s);
        for k in 0..m {
            let zk = s[k];
            if zk != 0.0 {
                for (x, y) in r.iter_mut().zip(&self.aie[k]) {
                    *x -= zk * y;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rnd(seed: &mut u64) -> f64 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
    }

    #[test]
    fn band_lu_matches_dense() {
        let (n, kl, ku) = (40, 3, 5);
        let mut s = 7u64;
        let mut m = BandMatrix::new(n, kl, ku);
        let mut dense = vec![0.0; n * n];
        for i in 0..n {
            for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                // weak diagonal so that pivoting is exercised
                let v = rnd(&mut s) + if i == j { 0.05 } else { 0.0 };
                m.set(i, j, v);
                dense[i * n + j] = v;
            }
        }
        let b: Vec<f64> = (0..n).map(|_| rnd(&mut s)).collect();
        let mut x = b.clone();
        m.clone().factor().unwrap().solve(&mut x);
        let mut y = vec![0.0; n];
        m.matvec(&x, &mut y);
        let err = y
            .iter()
            .zip(&b)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-9, "residual {err}");
        let mut x2 = b.clone();
        DenseLu::new(n, dense).unwrap().solve(&mut x2);
        let err2 = x
            .iter()
            .zip(&x2)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err2 < 1e-8 * x2.iter().fold(1.0f64, |m, v| m.max(v.abs())));
    }

    #[test]
    fn band_cholesky_and_bordered() {
        let (n, b) = (50, 4);
        let mut s = 3u64;
        let mut m = SymBandMatrix::new(n, b);
        for i in 0..n {
            m.add_lower(i, i, 10.0);
            for j in i.saturating_sub(b)..i {
                m.add_lower(i, j, rnd(&mut s));
            }
        }
        let rhs: Vec<f64> = (0..n).map(|_| rnd(&mut s)).collect();
        let mut x = rhs.clone();
        let ch = m.clone().cholesky().unwrap();
        ch.solve(&mut x);
        let mut y = vec![0.0; n];
        m.matvec(&x, &mut y);
        let err = y
            .iter()
            .zip(&rhs)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-12);
        // bordered with 2 extra unknowns coupling to the first and last rows
        let mut e = vec![vec![0.0; n]; 2];
        e[0][0] = 1.0;
        e[1][n - 1] = -2.0;
        let mut f = vec![vec![0.0; n]; 2];
        f[0][1] = 0.5;
        f[1][n - 2] = 1.5;
        f[1][3] = 0.25;
        let g = vec![3.0, 0.1, 0.2, 4.0];
        let bf = Bordered {
            a: &ch,
            e: &e,
            f: &f,
            g: &g,
        }
        .factor()
        .unwrap();
        let mut r = rhs.clone();
        let mut z = vec![1.0, -1.0];
        bf.solve(&mut r, &mut z);
        // check: A r + E z = rhs, F r + G z = s
        let mut ar = vec![0.0; n];
        m.matvec(&r, &mut ar);
        for i in 0..n {
            let v = ar[i] + e[0][i] * z[0] + e[1][i] * z[1];
            assert!((v - rhs[i]).abs() < 1e-12);
        }
        for k in 0..2 {
            let v: f64 = f[k].iter().zip(&r).map(|(a, b)| a * b).sum::<f64>()
                + g[2 * k] * z[0]
                + g[2 * k + 1] * z[1];
            assert!((v - [1.0, -1.0][k]).abs() < 1e-12);
        }
    }
}
