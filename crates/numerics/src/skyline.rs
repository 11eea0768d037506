//! Symmetric positive-definite systems in skyline (variable-band) storage, factored as `L D Lᵀ`
//! (Bathe, Finite Element Procedures, §8.2.3, the active-column solver). A row stores its
//! entries from its first non-zero column to the diagonal; fill-in stays inside that profile, so
//! a ring of beam elements numbered around the ring costs little beyond its band (only the rows
//! of the closing element reach back to the first columns).

/// Lower triangle of a symmetric matrix in skyline storage.
#[derive(Debug, Clone, PartialEq)]
pub struct Skyline {
    /// first stored column of each row
    first: Vec<usize>,
    /// start of each row in `values` (`start[i]..start[i+1]`, the diagonal last)
    start: Vec<usize>,
    values: Vec<f64>,
}

/// The matrix is not positive definite (a zero or negative pivot at `row`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NotPositiveDefinite {
    pub row: usize,
}

impl Skyline {
    /// An all-zero matrix whose row `i` may hold entries from column `first[i]` (≤ `i`).
    pub fn with_profile(first: Vec<usize>) -> Self {
        let mut start = Vec::with_capacity(first.len() + 1);
        start.push(0);
        for (i, &f) in first.iter().enumerate() {
            assert!(f <= i, "row {i}: first column {f} beyond the diagonal");
            start.push(start[i] + i - f + 1);
        }
        let values = vec![0.0; start[first.len()]];
        Self {
            first,
            start,
            values,
        }
    }

    /// Order of the matrix.
    pub fn size(&self) -> usize {
        self.first.len()
    }

    fn slot(&self, i: usize, j: usize) -> usize {
        debug_assert!(j <= i && j >= self.first[i]);
        self.start[i] + j - self.first[i]
    }

    /// Adds `v` to entry `(i, j)` (and its mirror); the entry must lie in the profile.
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let (i, j) = if j > i { (j, i) } else { (i, j) };
        assert!(j >= self.first[i], "entry ({i}, {j}) outside the profile");
        let s = self.slot(i, j);
        self.values[s] += v;
    }

    /// Entry `(i, j)` (0 outside the profile).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if j > i { (j, i) } else { (i, j) };
        if j < self.first[i] {
            0.0
        } else {
            self.values[self.slot(i, j)]
        }
    }

    /// Factors in place into `L D Lᵀ` (unit `L` below the diagonal, `D` on it).
    pub fn factor(mut self) -> Result<SkylineFactor, NotPositiveDefinite> {
        let n = self.size();
        for i in 0..n {
            let fi = self.first[i];
            // g_ij = a_ij − Σ_k l_ik g_jk for j < i, then l_ij = g_ij / d_j
            for j in fi..i {
                let fj = self.first[j];
                let lo = fi.max(fj);
                let mut sum = self.values[self.slot(i, j)];
                for k in lo..j {
                    sum -= self.values[self.slot(i, k)] * self.values[self.slot(j, k)];
                }
                let s = self.slot(i, j);
                self.values[s] = sum;
            }
            let mut diag = self.values[self.slot(i, i)];
            for k in fi..i {
                let g = self.values[self.slot(i, k)];
                let d = self.values[self.slot(k, k)];
                let l = g / d;
                let s = self.slot(i, k);
                self.values[s] = l;
                diag -= l * g;
            }
            if diag.is_nan() || diag <= 0.0 {
                return Err(NotPositiveDefinite { row: i });
            }
            let s = self.slot(i, i);
            self.values[s] = diag;
        }
        Ok(SkylineFactor(self))
    }
}

/// A factored [`Skyline`] matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct SkylineFactor(Skyline);

impl SkylineFactor {
    /// Solves `A x = b` in place.
    pub fn solve_in_place(&self, b: &mut [f64]) {
        let m = &self.0;
        let n = m.size();
        assert_eq!(b.len(), n);
        for i in 0..n {
            let (f, row) = (m.first[i], m.start[i]);
            let dot: f64 = m.values[row..row + i - f]
                .iter()
                .zip(&b[f..i])
                .map(|(l, x)| l * x)
                .sum();
            b[i] -= dot;
        }
        for (i, x) in b.iter_mut().enumerate() {
            *x /= m.values[m.slot(i, i)];
        }
        for i in (0..n).rev() {
            let (f, row, bi) = (m.first[i], m.start[i], b[i]);
            for (x, l) in b[f..i].iter_mut().zip(&m.values[row..row + i - f]) {
                *x -= l * bi;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_ring_like_profile() {
        // a cyclic tridiagonal SPD matrix: the last row reaches back to column 0
        let n = 7;
        let mut first: Vec<usize> = (0..n).map(|i: usize| i.saturating_sub(1)).collect();
        first[n - 1] = 0;
        let mut a = Skyline::with_profile(first);
        for i in 0..n {
            a.add(i, i, 4.0);
            a.add(i, (i + 1) % n, -1.0);
        }
        let x: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a.get(i, j) * x[j]).sum())
            .collect();
        a.factor().unwrap().solve_in_place(&mut b);
        for (got, want) in b.iter().zip(&x) {
            assert!((got - want).abs() < 1e-12);
        }
    }

    #[test]
    fn a_singular_matrix_is_reported() {
        let mut a = Skyline::with_profile(vec![0, 0]);
        a.add(0, 0, 1.0);
        a.add(1, 0, 1.0);
        a.add(1, 1, 1.0);
        assert_eq!(a.factor().unwrap_err(), NotPositiveDefinite { row: 1 });
    }
}
