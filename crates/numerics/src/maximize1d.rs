//! Maximum of a function of one variable inside a bracket, without derivatives:
//!
//! * [`golden_section_max`]: golden-section search (Kiefer 1953), a fixed reduction of the
//!   bracket by `1/φ = 0.618…` per evaluation; robust for any unimodal function.
//! * [`brent_max`]: Brent's method (Brent 1973, ch. 5): parabolic interpolation through the
//!   three best points, with golden-section steps whenever the parabola is not trusted;
//!   superlinear for a smooth maximum.
//!
//! (A minimum of `g` is the maximum of `−g`.)

use std::cmp::Ordering;

/// `1/φ = (√5 − 1)/2`, the golden-section ratio (correctly rounded).
pub const INVERSE_GOLDEN_RATIO: f64 = 0.618_033_988_749_894_8;

/// Knobs of [`golden_section_max`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoldenSectionOptions {
    /// Largest number of bracket reductions (one evaluation each); the bracket is then
    /// `0.618^max_iterations` of its start. Default 40 (≈ 4·10⁻⁹ of the start).
    pub max_iterations: usize,
    /// Stop as soon as the bracket is no wider than this (absolute, units of x). Default 0:
    /// only `max_iterations` ends the search.
    pub x_tolerance: f64,
}

impl Default for GoldenSectionOptions {
    fn default() -> Self {
        Self {
            max_iterations: 40,
            x_tolerance: 0.0,
        }
    }
}

/// Final state of [`golden_section_max`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoldenSection {
    /// Final bracket `(lo, hi)` of the maximum.
    pub bracket: (f64, f64),
    /// Best evaluated interior point `(x, f(x))` (the left one on a tie).
    pub best: (f64, f64),
}

/// Golden-section search for the maximum of `f` on `[lo, hi]` (`lo ≤ hi`): two interior
/// points at `hi − 0.618 (hi − lo)` and `lo + 0.618 (hi − lo)`; the side beyond the smaller
/// value is dropped (the upper side on a tie) and one new point is evaluated. Ends after
/// [`GoldenSectionOptions::max_iterations`] reductions or when the bracket is no wider than
/// [`GoldenSectionOptions::x_tolerance`]. The ends themselves are never evaluated.
pub fn golden_section_max(
    mut f: impl FnMut(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
    options: &GoldenSectionOptions,
) -> GoldenSection {
    const G: f64 = INVERSE_GOLDEN_RATIO;
    let mut x1 = hi - G * (hi - lo);
    let mut x2 = lo + G * (hi - lo);
    let mut f1 = f(x1);
    let mut f2 = f(x2);
    for _ in 0..options.max_iterations {
        // a NaN width or tolerance ends the search
        let wider = (hi - lo).partial_cmp(&options.x_tolerance) == Some(Ordering::Greater);
        if !wider {
            break;
        }
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + G * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - G * (hi - lo);
            f1 = f(x1);
        }
    }
    GoldenSection {
        bracket: (lo, hi),
        best: if f1 >= f2 { (x1, f1) } else { (x2, f2) },
    }
}

/// Knobs of [`brent_max`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrentMaxOptions {
    /// Tolerance in x, relative to `max(|x|, 1)` (plus `1e-12` absolute).
    pub tolerance: f64,
    /// Largest number of evaluations.
    pub max_iterations: u32,
}

/// Brent's method (parabolic interpolation + golden section) maximising `f` on `[a, b]` from
/// an interior point `x` whose value `fx` exceeds both ends. Returns `(x, f(x))` of the best
/// point.
pub fn brent_max(
    mut f: impl FnMut(f64) -> f64,
    (mut a, mut b): (f64, f64),
    (x, fx): (f64, f64),
    options: &BrentMaxOptions,
) -> (f64, f64) {
    // (3 − √5)/2 = 1 − 1/φ, correctly rounded
    const CGOLD: f64 = 0.381_966_011_250_105_1;
    // minimise g = −f
    let (mut x, mut w, mut v) = (x, x, x);
    let (mut gx, mut gw, mut gv) = (-fx, -fx, -fx);
    let mut d: f64 = 0.0;
    let mut e: f64 = 0.0;
    for _ in 0..options.max_iterations {
        let xm = 0.5 * (a + b);
        let tol1 = options.tolerance * x.abs().max(1.0) + 1e-12;
        let tol2 = 2.0 * tol1;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            let r = (x - w) * (gx - gv);
            let mut q = (x - v) * (gx - gw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let etemp = e;
            e = d;
            if !(p.abs() >= (0.5 * q * etemp).abs() || p <= q * (a - x) || p >= q * (b - x)) {
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(xm - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= xm { a - x } else { b - x };
            d = CGOLD * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let gu = -f(u);
        if gu <= gx {
            if u >= x {
                a = x;
            } else {
                b = x;
            }
            (v, gv) = (w, gw);
            (w, gw) = (x, gx);
            (x, gx) = (u, gu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if gu <= gw || w == x {
                (v, gv) = (w, gw);
                (w, gw) = (u, gu);
            } else if gu <= gv || v == x || v == w {
                (v, gv) = (u, gu);
            }
        }
    }
    (x, -gx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golden_ratio_constant() {
        let exact = 0.5 * (5.0_f64.sqrt() - 1.0);
        assert!((INVERSE_GOLDEN_RATIO - exact).abs() <= f64::EPSILON);
    }

    #[test]
    fn golden_section_brackets_the_maximum() {
        let f = |x: f64| -(x - 0.3).powi(2);
        let g = golden_section_max(f, -1.0, 2.0, &GoldenSectionOptions::default());
        let (lo, hi) = g.bracket;
        assert!(lo <= 0.3 && 0.3 <= hi && hi - lo < 3e-8, "{lo} {hi}");
        let tolerant = GoldenSectionOptions {
            max_iterations: 1000,
            x_tolerance: 1e-3,
        };
        let g = golden_section_max(f, -1.0, 2.0, &tolerant);
        assert!(g.bracket.1 - g.bracket.0 <= 1e-3 && (g.best.0 - 0.3).abs() < 1e-3);
    }

    #[test]
    fn brent_finds_a_smooth_maximum() {
        let f = |x: f64| x.sin();
        let options = BrentMaxOptions {
            tolerance: 1e-10,
            max_iterations: 100,
        };
        let (x, fx) = brent_max(f, (0.0, 3.0), (1.0, 1.0_f64.sin()), &options);
        assert!((x - std::f64::consts::FRAC_PI_2).abs() < 1e-8 && (fx - 1.0).abs() < 1e-15);
    }
}
