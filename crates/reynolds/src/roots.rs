//! Scalar root finding (Brent's method) shared by the solvers.

use crate::error::{Result, ReynoldsError};

/// Brent's method on [a, b] with f(a)·f(b) ≤ 0 (values supplied). Stops when |f| ≤ `ftol` or the
/// bracket is shorter than `xtol`. Returns (x, f(x), evaluations).
#[allow(clippy::too_many_arguments)]
pub fn brent(
    mut f: impl FnMut(f64) -> Result<f64>,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    xtol: f64,
    ftol: f64,
    max_iter: usize,
) -> Result<(f64, f64, usize)> {
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa * fb > 0.0 {
        return Err(ReynoldsError::NoSolution(format!(
            "root not bracketed: f({a}) = {fa}, f({b}) = {fb}"
        )));
    }
    if fa.abs() < fb.abs() {
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut fa, &mut fb);
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for it in 0..max_iter {
        if fb.abs() <= ftol {
            return Ok((b, fb, it));
        }
        if fb * fc > 0.0 {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol {
            return Ok((b, fb, it));
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b)?;
    }
    Err(ReynoldsError::NotConverged {
        what: "Brent root search",
        iterations: max_iter,
        residual: fb.abs(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_roots() {
        let f = |x: f64| Ok(x * x * x - 2.0 * x - 5.0);
        let (x, _, n) = brent(f, 2.0, 3.0, -1.0, 16.0, 1e-14, 0.0, 100).unwrap();
        assert!((x - 2.094_551_481_542_327).abs() < 1e-12 && n < 12);
    }
}
