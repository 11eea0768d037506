//! Private ADAMS-style cubic STEP (SPEC §3.4). Deliberately not shared with `rolldyn_contact`.

/// STEP(x, x0, h0, x1, h1): h0 for x ≤ x0, h1 for x ≥ x1, cubic smoothstep in between
/// (continuous value and first derivative). Requires x1 ≠ x0; x1 < x0 is handled by symmetry.
#[inline]
pub(crate) fn step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> f64 {
    let d = ((x - x0) / (x1 - x0)).clamp(0.0, 1.0);
    h0 + (h1 - h0) * d * d * (3.0 - 2.0 * d)
}

#[cfg(test)]
mod tests {
    use super::step;
    #[test]
    fn step_ends_and_mid() {
        assert_eq!(step(-1.0, 0.0, 2.0, 1.0, 5.0), 2.0);
        assert_eq!(step(2.0, 0.0, 2.0, 1.0, 5.0), 5.0);
        assert!((step(0.5, 0.0, 2.0, 1.0, 5.0) - 3.5).abs() < 1e-15);
        // reversed abscissae
        assert_eq!(step(2.0, 1.0, 0.0, 0.0, 1.0), 0.0);
        assert_eq!(step(-1.0, 1.0, 0.0, 0.0, 1.0), 1.0);
    }
}
