//! Tridiagonal and cyclic tridiagonal solvers (Thomas algorithm, "прогонка", seed 002 §4.3;
//! SPEC §8.6 ADI lines).

/// Solves a tridiagonal system in place: `lower[i]·x[i−1] + diag[i]·x[i] + upper[i]·x[i+1] = rhs[i]`
/// (`lower[0]` and `upper[n−1]` are ignored). The solution overwrites `rhs`; `diag` is used as
/// scratch. Returns `false` on a zero pivot (the system is then left partially reduced).
///
/// No pivoting: intended for diagonally dominant rows (Reynolds/Poiseuille operators).
pub fn thomas(lower: &[f64], diag: &mut [f64], upper: &[f64], rhs: &mut [f64]) -> bool {
    let n = diag.len();
    if n == 0 {
        return true;
    }
    debug_assert!(lower.len() >= n && upper.len() >= n && rhs.len() >= n);
    for i in 1..n {
        if diag[i - 1] == 0.0 {
            return false;
        }
        let m = lower[i] / diag[i - 1];
        diag[i] -= m * upper[i - 1];
        rhs[i] -= m * rhs[i - 1];
    }
    if diag[n - 1] == 0.0 {
        return false;
    }
    rhs[n - 1] /= diag[n - 1];
    for i in (0..n - 1).rev() {
        rhs[i] = (rhs[i] - upper[i] * rhs[i + 1]) / diag[i];
    }
    true
}

/// Solves a cyclic tridiagonal system (periodic coupling `lower[0]·x[n−1]` and `upper[n−1]·x[0]`)
/// by the Sherman–Morrison correction of two Thomas solves. The solution overwrites `rhs`.
/// Returns `false` on a zero pivot. Needs n ≥ 3.
pub fn cyclic_thomas(lower: &[f64], diag: &[f64], upper: &[f64], rhs: &mut [f64]) -> bool {
    let n = diag.len();
    if n < 3 {
        return false;
    }
    let alpha = upper[n - 1]; // A[n−1][0]
    let beta = lower[0]; // A[0][n−1]
    let gamma = if diag[0] != 0.0 { -diag[0] } else { -1.0 };
    let mut d1 = diag.to_vec();
    d1[0] -= gamma;
    d1[n - 1] -= alpha * beta / gamma;
    let mut d2 = d1.clone();
    if !thomas(lower, &mut d1, upper, rhs) {
        return false;
    }
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = alpha;
    if !thomas(lower, &mut d2, upper, &mut u) {
        return false;
    }
    let fact_den = 1.0 + u[0] + beta * u[n - 1] / gamma;
    if fact_den == 0.0 {
        return false;
    }
    let fact = (rhs[0] + beta * rhs[n - 1] / gamma) / fact_den;
    for i in 0..n {
        rhs[i] -= fact * u[i];
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn residual(
        lower: &[f64],
        diag: &[f64],
        upper: &[f64],
        x: &[f64],
        b: &[f64],
        cyclic: bool,
    ) -> f64 {
        let n = diag.len();
        let mut r: f64 = 0.0;
        for i in 0..n {
            let mut s = diag[i] * x[i];
            if i > 0 {
                s += lower[i] * x[i - 1];
            } else if cyclic {
                s += lower[0] * x[n - 1];
            }
            if i + 1 < n {
                s += upper[i] * x[i + 1];
            } else if cyclic {
                s += upper[n - 1] * x[0];
            }
            r = r.max((s - b[i]).abs());
        }
        r
    }

    #[test]
    fn thomas_and_cyclic_solve() {
        let n = 9;
        let lower: Vec<f64> = (0..n).map(|i| -1.0 - 0.1 * i as f64).collect();
        let upper: Vec<f64> = (0..n).map(|i| -0.5 - 0.05 * i as f64).collect();
        let diag: Vec<f64> = (0..n).map(|i| 4.0 + 0.3 * i as f64).collect();
        let b: Vec<f64> = (0..n).map(|i| (i as f64).sin()).collect();
        let mut x = b.clone();
        let mut d = diag.clone();
        assert!(thomas(&lower, &mut d, &upper, &mut x));
        assert!(residual(&lower, &diag, &upper, &x, &b, false) < 1e-13);
        let mut x = b.clone();
        assert!(cyclic_thomas(&lower, &diag, &upper, &mut x));
        assert!(residual(&lower, &diag, &upper, &x, &b, true) < 1e-13);
    }
}
