//! Influence coefficients of a uniformly loaded rectangular cell (seed 004 eq. (5), SPEC §2.5).
//!
//! The normal surface displacement at `(x̄, ȳ)` (relative to the cell centre) due to a unit
//! uniform pressure on the rectangle `|x| ≤ b`, `|y| ≤ a` of an elastic half-space pair is
//! (Love 1929; Johnson, *Contact Mechanics*, eq. (3.25))
//!
//! `f(x̄, ȳ) = C · [H(x̄+b, ȳ+a) − H(x̄+b, ȳ−a) − H(x̄−b, ȳ+a) + H(x̄−b, ȳ−a)]`,
//!
//! with `∂²H/∂X∂Y = 1/√(X²+Y²)`. The seed writes `H(X, Y) = X ln(Y + r) + Y ln(X + r)`
//! ([`influence_coefficient_log`]); here the symmetric form
//! `H(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)` is used. Both differ only by terms depending
//! on `X` alone or `Y` alone, which cancel in the corner sum; the asinh form is odd in `X`
//! and `Y`, has no log of zero and gives `H = 0` on the axes, so the self term is finite.
//! `C = (1−ν₁²)/(πE₁) + (1−ν₂²)/(πE₂)` ([`combined_compliance`]). Flag F-07: `b` is half the
//! cell size along `x`, `a` half the cell size along `y`.

use super::Grid;

/// Combined compliance `C = (1−ν₁²)/(πE₁) + (1−ν₂²)/(πE₂)`, 1/Pa (seed 004 eq. (1), flag F-14).
pub fn combined_compliance(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    (1.0 - nu1 * nu1) / (std::f64::consts::PI * e1)
        + (1.0 - nu2 * nu2) / (std::f64::consts::PI * e2)
}

/// Corner antiderivative `H(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)` (limit 0 on the axes).
#[inline]
fn corner(x: f64, y: f64) -> f64 {
    let mut s = 0.0;
    if x != 0.0 {
        s += x * (y / x.abs()).asinh();
    }
    if y != 0.0 {
        s += y * (x / y.abs()).asinh();
    }
    s
}

/// Influence coefficient `f(x̄, ȳ)` (m/Pa) of seed 004 eq. (5) in the safe asinh form:
/// displacement at offset `(x̄, ȳ)` from the centre of a cell of half sizes `b` (along `x`)
/// and `a` (along `y`) loaded by unit pressure, times the combined compliance `compliance`.
///
/// `f` is even in `x̄` and `ȳ`; it is evaluated at `(|x̄|, |ȳ|)` so that the symmetry also holds
/// exactly in floating point.
pub fn influence_coefficient(xbar: f64, ybar: f64, b: f64, a: f64, compliance: f64) -> f64 {
    let (xbar, ybar) = (xbar.abs(), ybar.abs());
    compliance
        * (corner(xbar + b, ybar + a) - corner(xbar + b, ybar - a) - corner(xbar - b, ybar + a)
            + corner(xbar - b, ybar - a))
}

/// Seed 004 eq. (5) literally (logarithmic form). Only for verification: it is undefined where
/// a log argument vanishes (e.g. on cell edges on the negative side), use
/// [`influence_coefficient`] instead.
pub fn influence_coefficient_log(xbar: f64, ybar: f64, b: f64, a: f64, compliance: f64) -> f64 {
    let (xp, xm, yp, ym) = (xbar + b, xbar - b, ybar + a, ybar - a);
    let r = |x: f64, y: f64| (x * x + y * y).sqrt();
    compliance
        * (xp * ((yp + r(xp, yp)) / (ym + r(xp, ym))).ln()
            + yp * ((xp + r(xp, yp)) / (xm + r(xm, yp))).ln()
            + xm * ((ym + r(xm, ym)) / (yp + r(xm, yp))).ln()
            + ym * ((xm + r(xm, ym)) / (xp + r(xp, ym))).ln())
}

/// Kernel table `f(m·dx, d·dy)` for `m ∈ [−(nx−1), nx−1]`, `d ∈ [−(ny−1), ny−1]` (SPEC §2.5:
/// one `(2nx−1) × (2ny−1)` Toeplitz table per grid).
///
/// Storage: row-major, `m` fastest: entry `(m, d)` at `(d + ny − 1)·(2nx − 1) + (m + nx − 1)`.
#[derive(Debug, Clone)]
pub struct InfluenceTable {
    nx: usize,
    ny: usize,
    compliance: f64,
    data: Vec<f64>,
}

impl InfluenceTable {
    /// Build the table for `grid` (cells `dx × dy`, i.e. `b = dx/2`, `a = dy/2`).
    ///
    /// `H` is evaluated once on the `(nx+1) × (ny+1)` lattice of cell-edge offsets
    /// `X_k = (k − ½)dx`, `Y_l = (l − ½)dy` and the quarter table is mirrored (f is even in
    /// `x̄` and `ȳ`).
    pub fn new(grid: &Grid, compliance: f64) -> Self {
        let (nx, ny) = (grid.nx, grid.ny);
        let w = 2 * nx - 1;
        let mut h = vec![0.0; (nx + 1) * (ny + 1)];
        for l in 0..=ny {
            let y = (l as f64 - 0.5) * grid.dy;
            for k in 0..=nx {
                h[l * (nx + 1) + k] = corner((k as f64 - 0.5) * grid.dx, y);
            }
        }
        let mut data = vec![0.0; w * (2 * ny - 1)];
        for d in 0..ny {
            for m in 0..nx {
                let at = |k: usize, l: usize| h[l * (nx + 1) + k];
                let v = compliance * (at(m + 1, d + 1) - at(m + 1, d) - at(m, d + 1) + at(m, d));
                for jd in [ny - 1 + d, ny - 1 - d] {
                    data[jd * w + nx - 1 + m] = v;
                    data[jd * w + nx - 1 - m] = v;
                }
            }
        }
        Self {
            nx,
            ny,
            compliance,
            data,
        }
    }

    /// Cells along `x` of the grid the table was built for.
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Cells along `y` of the grid the table was built for.
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// Combined compliance used, 1/Pa.
    pub fn compliance(&self) -> f64 {
        self.compliance
    }

    /// `f(m·dx, d·dy)`, m/Pa, for `|m| < nx`, `|d| < ny`.
    #[inline]
    pub fn get(&self, m: isize, d: isize) -> f64 {
        let w = 2 * self.nx - 1;
        self.data[(d + self.ny as isize - 1) as usize * w + (m + self.nx as isize - 1) as usize]
    }

    /// Row `d` of the table: `f(m·dx, d·dy)` for `m = −(nx−1) ..= nx−1` (length `2nx − 1`).
    #[inline]
    pub fn row(&self, d: isize) -> &[f64] {
        let w = 2 * self.nx - 1;
        let s = (d + self.ny as isize - 1) as usize * w;
        &self.data[s..s + w]
    }

    /// Self coefficient `f(0, 0)` (displacement of a cell centre due to its own unit pressure).
    pub fn self_coefficient(&self) -> f64 {
        self.get(0, 0)
    }

    /// Raw table in storage order.
    pub fn as_slice(&self) -> &[f64] {
        &self.data
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn self_term_closed_form() {
        // Square cell, centre: f = C · 4·b·2·asinh(1) = 8 b asinh(1) C  (Johnson (3.25)).
        let f = influence_coefficient(0.0, 0.0, 1.0, 1.0, 1.0);
        assert!((f - 8.0 * 1f64.asinh()).abs() < 1e-14);
        let g = Grid::centered(3, 2, 2.0, 2.0).unwrap();
        let t = InfluenceTable::new(&g, 1.0);
        assert!((t.self_coefficient() - f).abs() < 1e-14);
        assert!((t.get(2, -1) - influence_coefficient(4.0, 2.0, 1.0, 1.0, 1.0)).abs() < 1e-14);
        assert!(influence_coefficient(-1.0, -1.0, 1.0, 1.0, 1.0).is_finite());
    }
}
