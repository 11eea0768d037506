//! Scalar root finding for the Reynolds solvers: [`rolldyn_numerics::brent`] with the errors
//! of this crate.

use crate::error::{Result, ReynoldsError};
use rolldyn_numerics::brent::{BrentError, BrentOptions, brent_root};

/// Brent's method on [a, b] with f(a)·f(b) ≤ 0 (values supplied). Stops when |f| ≤ `ftol` or the
/// bracket is shorter than `xtol`. Returns (x, f(x), evaluations).
#[allow(clippy::too_many_arguments)]
pub fn brent(
    f: impl FnMut(f64) -> Result<f64>,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    xtol: f64,
    ftol: f64,
    max_iter: usize,
) -> Result<(f64, f64, usize)> {
    let options = BrentOptions {
        x_tol: xtol,
        f_tol: ftol,
        max_iterations: max_iter,
    };
    match brent_root(f, (a, fa), (b, fb), &options) {
        Ok(root) => Ok((root.x, root.value, root.iterations)),
        Err(BrentError::NotBracketed {
            ends: (a, fa, b, fb),
        }) => Err(ReynoldsError::NoSolution(format!(
            "root not bracketed: f({a}) = {fa}, f({b}) = {fb}"
        ))),
        Err(BrentError::NotConverged {
            iterations,
            residual,
        }) => Err(ReynoldsError::NotConverged {
            what: "Brent root search",
            iterations,
            residual,
        }),
        Err(BrentError::Function(e)) => Err(e),
    }
}
