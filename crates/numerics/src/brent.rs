//! Brent's root finder (R. P. Brent, *Algorithms for Minimization without Derivatives*, 1973,
//! ch. 4): inverse quadratic interpolation and secant steps inside a sign-change bracket, with
//! bisection whenever an interpolated step would not shrink the bracket fast enough.

/// Knobs of [`brent_root`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrentOptions {
    /// Converged when the bracket half-width is at most `2 ε |x| + x_tol / 2`.
    pub x_tol: f64,
    /// Converged when `|f(x)| ≤ f_tol`.
    pub f_tol: f64,
    /// Budget of function evaluations after the two supplied ends.
    pub max_iterations: usize,
}

/// Root found by [`brent_root`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrentRoot {
    /// Root estimate.
    pub x: f64,
    /// `f(x)`.
    pub value: f64,
    /// Function evaluations used (the two ends not counted).
    pub iterations: usize,
}

/// Why [`brent_root`] gave no root.
#[derive(Debug, Clone, PartialEq)]
pub enum BrentError<E> {
    /// `f(a) f(b) > 0`.
    NotBracketed {
        /// Ends and their values `(a, f(a), b, f(b))`.
        ends: (f64, f64, f64, f64),
    },
    /// `max_iterations` used up; `residual = |f|` at the last iterate.
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Last `|f|`.
        residual: f64,
    },
    /// The function failed.
    Function(E),
}

/// Root of `f` in the bracket `[a, b]` whose end values `fa = f(a)`, `fb = f(b)` the caller
/// supplies (`fa · fb ≤ 0`).
pub fn brent_root<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    options: &BrentOptions,
) -> Result<BrentRoot, BrentError<E>> {
    if fa * fb > 0.0 {
        return Err(BrentError::NotBracketed {
            ends: (a, fa, b, fb),
        });
    }
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa.abs() < fb.abs() {
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut fa, &mut fb);
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for iterations in 0..options.max_iterations {
        let done = |x, value| {
            Ok(BrentRoot {
                x,
                value,
                iterations,
            })
        };
        if fb.abs() <= options.f_tol {
            return done(b, fb);
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
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * options.x_tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol {
            return done(b, fb);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let (mut p, mut q) = interpolation_step(a, b, c, fa, fb, fc, m);
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
        fb = f(b).map_err(BrentError::Function)?;
    }
    Err(BrentError::NotConverged {
        iterations: options.max_iterations,
        residual: fb.abs(),
    })
}

/// Step `p/q` from `b`: secant through `a`, `b` when `a = c`, else inverse quadratic
/// interpolation through `a`, `b`, `c` (Brent 1973, §4.2); `m = (c − b)/2`.
fn interpolation_step(a: f64, b: f64, c: f64, fa: f64, fb: f64, fc: f64, m: f64) -> (f64, f64) {
    let s = fb / fa;
    if a == c {
        (2.0 * m * s, 1.0 - s)
    } else {
        let qq = fa / fc;
        let r = fb / fc;
        (
            s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0)),
            (qq - 1.0) * (r - 1.0) * (s - 1.0),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::{BrentError, BrentOptions, brent_root};
    use std::convert::Infallible;

    #[test]
    fn finds_the_root_of_a_cubic() {
        let f = |x: f64| Ok::<_, Infallible>(x * x * x - 2.0 * x - 5.0);
        let options = BrentOptions {
            x_tol: 1e-14,
            f_tol: 0.0,
            max_iterations: 100,
        };
        let root = brent_root(f, (2.0, -1.0), (3.0, 16.0), &options).unwrap();
        assert!((root.x - 2.094_551_481_542_327).abs() < 1e-12 && root.iterations < 12);
    }

    #[test]
    fn refuses_an_interval_without_sign_change() {
        let f = |x: f64| Ok::<_, Infallible>(x * x + 1.0);
        let options = BrentOptions {
            x_tol: 1e-12,
            f_tol: 0.0,
            max_iterations: 10,
        };
        let outcome = brent_root(f, (0.0, 1.0), (1.0, 2.0), &options);
        assert!(matches!(outcome, Err(BrentError::NotBracketed { .. })));
    }
}
