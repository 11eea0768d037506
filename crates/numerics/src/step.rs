//! The ADAMS cubic STEP function (SPEC §3.4), the one smoothing ramp of the project: contact
//! damping ramps, friction-level blends, the laminar–turbulent drag blend and the slice
//! kernel's damping all call it.

/// ADAMS STEP function (SPEC §3.4, standard ADAMS definition):
/// `h0` for `x ≤ x0`, `h1` for `x ≥ x1`, and `h0 + (h1−h0) Δ²(3 − 2Δ)`,
/// `Δ = (x − x0)/(x1 − x0)`, in between. Value and first derivative are continuous; the slope
/// is zero at both ends. If `x1 < x0` the same formula applies with `Δ` measured from `x0`
/// (`h0` for `x ≥ x0`, `h1` for `x ≤ x1`). If `x1 = x0` it degenerates to a jump at `x0`
/// (`h0` below, `h1` at and above) instead of returning NaN.
#[inline]
pub fn step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> f64 {
    step_with_derivative(x, x0, h0, x1, h1).0
}

/// [`step`] together with its derivative `d STEP/dx`.
#[inline]
pub fn step_with_derivative(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> (f64, f64) {
    let span = x1 - x0;
    if span == 0.0 {
        return (if x < x0 { h0 } else { h1 }, 0.0);
    }
    let d = (x - x0) / span;
    if d <= 0.0 {
        (h0, 0.0)
    } else if d >= 1.0 {
        (h1, 0.0)
    } else {
        let dh = h1 - h0;
        (
            h0 + dh * d * d * (3.0 - 2.0 * d),
            dh * 6.0 * d * (1.0 - d) / span,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::{step, step_with_derivative};

    #[test]
    fn ends_middle_and_reversed_abscissae() {
        assert_eq!(step(-1.0, 0.0, 2.0, 1.0, 5.0), 2.0);
        assert_eq!(step(2.0, 0.0, 2.0, 1.0, 5.0), 5.0);
        assert!((step(0.5, 0.0, 2.0, 1.0, 5.0) - 3.5).abs() < 1e-15);
        assert_eq!(step(2.0, 1.0, 0.0, 0.0, 1.0), 0.0);
        assert_eq!(step(-1.0, 1.0, 0.0, 0.0, 1.0), 1.0);
    }

    #[test]
    fn degenerate_span_is_a_jump_at_x0() {
        assert_eq!(step_with_derivative(0.999, 1.0, 2.0, 1.0, 5.0), (2.0, 0.0));
        assert_eq!(step_with_derivative(1.0, 1.0, 2.0, 1.0, 5.0), (5.0, 0.0));
        assert_eq!(step(1.5, 1.0, 2.0, 1.0, 5.0), 5.0);
    }
}
