//! Dense LU factorisation with partial pivoting (Doolittle, row interchanges) of a row-major
//! `n × n` matrix: `P A = L U`, `L` unit lower triangular, both stored in place of `A`.
//! For the small systems of the solvers (Schur complements, per-roller Rosenbrock blocks).

/// The matrix has a zero or non-finite pivot column: no factorisation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Singular;

impl std::fmt::Display for Singular {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("singular or non-finite matrix in dense LU")
    }
}

impl std::error::Error for Singular {}

/// Factorises the row-major `n × n` matrix `a` in place, `n = pivots.len()`: afterwards `a`
/// holds `L` (below the diagonal, unit diagonal implied) and `U`, and `pivots[k]` is the row
/// swapped with row `k` at step `k`. On [`Singular`] `a` and `pivots` are partly overwritten.
pub fn factor_in_place(a: &mut [f64], pivots: &mut [usize]) -> Result<(), Singular> {
    let n = pivots.len();
    debug_assert_eq!(a.len(), n * n);
    for k in 0..n {
        let mut p = k;
        let mut largest = a[k * n + k].abs();
        for i in k + 1..n {
            let v = a[i * n + k].abs();
            if v > largest {
                largest = v;
                p = i;
            }
        }
        if !(largest > 0.0 && largest.is_finite()) {
            return Err(Singular);
        }
        pivots[k] = p;
        if p != k {
            for j in 0..n {
                a.swap(k * n + j, p * n + j);
            }
        }
        let inverse_pivot = 1.0 / a[k * n + k];
        for i in k + 1..n {
            let l = a[i * n + k] * inverse_pivot;
            a[i * n + k] = l;
            if l != 0.0 {
                for j in k + 1..n {
                    a[i * n + j] -= l * a[k * n + j];
                }
            }
        }
    }
    Ok(())
}

/// Solves `A x = b` in place (`b` becomes `x`) with the factors of [`factor_in_place`]:
/// row interchanges, forward substitution with `L`, back substitution with `U`.
pub fn solve_in_place(lu: &[f64], pivots: &[usize], b: &mut [f64]) {
    let n = pivots.len();
    for (k, &p) in pivots.iter().enumerate() {
        if p != k {
            b.swap(k, p);
        }
    }
    for i in 0..n {
        let mut s = b[i];
        for j in 0..i {
            s -= lu[i * n + j] * b[j];
        }
        b[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for j in i + 1..n {
            s -= lu[i * n + j] * b[j];
        }
        b[i] = s / lu[i * n + i];
    }
}

/// Solves `A X = B` in place for `m` right-hand sides at once with the factors of
/// [`factor_in_place`]: `x` is row-major `n × m` (row `i` holds component `i` of every
/// column) and becomes `X`. Each column gets the very operations of [`solve_in_place`], in
/// the same order (bit-for-bit the same result); the inner loops run along the `m` contiguous
/// values of a row instead of along a dependency chain, which is what makes many columns fast.
/// For one column it is the slower of the two: a 12 × 12 solve took 2× the time of
/// [`solve_in_place`] (640 against 330 ns, same bits; 2026-12-08), so both are kept.
pub fn solve_columns_in_place(lu: &[f64], pivots: &[usize], x: &mut [f64], m: usize) {
    let n = pivots.len();
    debug_assert_eq!(x.len(), n * m);
    for (k, &p) in pivots.iter().enumerate() {
        if p != k {
            let (upper, lower) = x.split_at_mut(p * m);
            upper[k * m..(k + 1) * m].swap_with_slice(&mut lower[..m]);
        }
    }
    for i in 1..n {
        let (solved, rest) = x.split_at_mut(i * m);
        let row = &mut rest[..m];
        for (j, &l) in lu[i * n..i * n + i].iter().enumerate() {
            for (v, &w) in row.iter_mut().zip(&solved[j * m..(j + 1) * m]) {
                *v -= l * w;
            }
        }
    }
    for i in (0..n).rev() {
        let (head, solved) = x.split_at_mut((i + 1) * m);
        let row = &mut head[i * m..];
        for (j, &u) in lu[i * n + i + 1..(i + 1) * n].iter().enumerate() {
            for (v, &w) in row.iter_mut().zip(&solved[j * m..(j + 1) * m]) {
                *v -= u * w;
            }
        }
        let pivot = lu[i * n + i];
        for v in row {
            *v /= pivot;
        }
    }
}

/// Owned LU factors of a dense matrix.
#[derive(Debug, Clone)]
pub struct DenseLu {
    lu: Vec<f64>,
    pivots: Vec<usize>,
}

impl DenseLu {
    /// Factorises the row-major `n × n` matrix `a`.
    pub fn new(n: usize, mut a: Vec<f64>) -> Result<Self, Singular> {
        let mut pivots = vec![0; n];
        factor_in_place(&mut a, &mut pivots)?;
        Ok(Self { lu: a, pivots })
    }

    /// Solves `A x = b` in place.
    pub fn solve(&self, b: &mut [f64]) {
        solve_in_place(&self.lu, &self.pivots, b);
    }
}

#[cfg(test)]
mod tests {
    use super::{DenseLu, Singular, factor_in_place, solve_columns_in_place, solve_in_place};

    #[test]
    fn solves_a_system_that_needs_pivoting() {
        // zero leading entry: fails without row interchanges
        let a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let x = [1.0, -2.0, 0.5];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
            .collect();
        DenseLu::new(3, a).unwrap().solve(&mut b);
        for (bi, xi) in b.iter().zip(x) {
            assert!((bi - xi).abs() < 1e-14, "{bi} vs {xi}");
        }
    }

    #[test]
    fn many_columns_are_solved_as_each_column_alone() {
        let n = 5;
        let a: Vec<f64> = (0..n * n)
            .map(|k| {
                ((k * 7919 % 23) as f64 - 11.0) / 3.0 + if k % (n + 1) == 0 { 0.5 } else { 0.0 }
            })
            .collect();
        let mut lu = a.clone();
        let mut piv = vec![0; n];
        factor_in_place(&mut lu, &mut piv).unwrap();
        assert!(
            piv.iter().enumerate().any(|(k, &p)| p != k),
            "the test needs pivoting"
        );
        let m = 3;
        let rows: Vec<f64> = (0..n * m).map(|k| (k as f64 * 0.37).sin()).collect();
        let mut many = rows.clone();
        solve_columns_in_place(&lu, &piv, &mut many, m);
        for c in 0..m {
            let mut column: Vec<f64> = (0..n).map(|i| rows[i * m + c]).collect();
            solve_in_place(&lu, &piv, &mut column);
            for i in 0..n {
                assert_eq!(
                    many[i * m + c].to_bits(),
                    column[i].to_bits(),
                    "row {i} column {c}"
                );
            }
        }
    }

    #[test]
    fn singular_and_non_finite_matrices_are_refused() {
        assert_eq!(
            DenseLu::new(2, vec![1.0, 2.0, 2.0, 4.0]).err(),
            Some(Singular)
        );
        assert_eq!(DenseLu::new(1, vec![f64::NAN]).err(), Some(Singular));
    }
}
