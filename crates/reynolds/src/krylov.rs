//! Restarted GMRES (modified Gram–Schmidt, Givens rotations) for the Newton systems whose
//! Jacobian is a banded part (factorised, used as preconditioner) plus a dense far field.

/// Solves A x = b from x = 0 for the linear operator `apply` (y ← A v). Stops when
/// ‖b − A x‖ ≤ `tol`. Returns (x, residual norm, iterations).
pub fn gmres(
    mut apply: impl FnMut(&[f64], &mut [f64]),
    b: &[f64],
    tol: f64,
    restart: usize,
    max_iter: usize,
) -> (Vec<f64>, f64, usize) {
    let n = b.len();
    let mut x = vec![0.0; n];
    let mut r = b.to_vec();
    let mut beta = norm(&r);
    let mut total = 0;
    let m = restart.max(1);
    let mut w = vec![0.0; n];
    while beta > tol && total < max_iter {
        let mut v: Vec<Vec<f64>> = Vec::with_capacity(m + 1);
        v.push(r.iter().map(|a| a / beta).collect());
        let mut h = vec![vec![0.0; m]; m + 1];
        let (mut cs, mut sn) = (vec![0.0; m], vec![0.0; m]);
        let mut g = vec![0.0; m + 1];
        g[0] = beta;
        let mut k_used = 0;
        for k in 0..m {
            apply(&v[k], &mut w);
            for i in 0..=k {
                let hik = dot(&w, &v[i]);
                h[i][k] = hik;
                for (a, b) in w.iter_mut().zip(&v[i]) {
                    *a -= hik * b;
                }
            }
            let hn = norm(&w);
            h[k + 1][k] = hn;
            for i in 0..k {
                let t = cs[i] * h[i][k] + sn[i] * h[i + 1][k];
                h[i + 1][k] = -sn[i] * h[i][k] + cs[i] * h[i + 1][k];
                h[i][k] = t;
            }
            let den = h[k][k].hypot(h[k + 1][k]);
            if den == 0.0 {
                k_used = k;
                break;
            }
            cs[k] = h[k][k] / den;
            sn[k] = h[k + 1][k] / den;
            h[k][k] = den;
            h[k + 1][k] = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] *= cs[k];
            total += 1;
            k_used = k + 1;
            if g[k + 1].abs() <= tol || total >= max_iter || hn == 0.0 {
                break;
            }
            v.push(w.iter().map(|a| a / hn).collect());
        }
        // back substitution
        let mut y = vec![0.0; k_used];
        for i in (0..k_used).rev() {
            let mut s = g[i];
            for j in i + 1..k_used {
                s -= h[i][j] * y[j];
            }
            y[i] = s / h[i][i];
        }
        for (j, yj) in y.iter().enumerate() {
            for (a, b) in x.iter_mut().zip(&v[j]) {
                *a += yj * b;
            }
        }
        apply(&x, &mut w);
        for i in 0..n {
            r[i] = b[i] - w[i];
        }
        let nb = norm(&r);
        if nb >= beta * (1.0 - 1e-12) && k_used == 0 {
            beta = nb;
            break;
        }
        beta = nb;
    }
    (x, beta, total)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gmres_solves_a_nonsymmetric_system() {
        let n = 30;
        let a = |i: usize, j: usize| -> f64 {
            if i == j {
                4.0
            } else if j == i + 1 {
                -1.5
            } else if i == j + 1 {
                -0.5
            } else {
                0.01 / (1.0 + (i as f64 - j as f64).abs())
            }
        };
        let b: Vec<f64> = (0..n).map(|i| (i as f64).cos()).collect();
        let (x, res, it) = gmres(
            |v, out| {
                for i in 0..n {
                    out[i] = (0..n).map(|j| a(i, j) * v[j]).sum();
                }
            },
            &b,
            1e-12,
            10,
            200,
        );
        assert!(res <= 1e-12 && it < 100);
        for i in 0..n {
            let s: f64 = (0..n).map(|j| a(i, j) * x[j]).sum();
            assert!((s - b[i]).abs() < 1e-10);
        }
    }
}
