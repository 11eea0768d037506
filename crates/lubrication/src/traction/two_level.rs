//! Two-level regularised friction law with the cubic STEP (SPEC §3.4, seed 000 Fig. 2.6, F-19).

use rolldyn_numerics::step::step;

/// Parameters μ_s, μ_d, v_s, v_d of the two-level law (0 < v_s < v_d).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoLevelLaw {
    /// static coefficient μ_s (reached at |v| = v_s)
    pub mu_s: f64,
    /// dynamic coefficient μ_d (|v| ≥ v_d)
    pub mu_d: f64,
    /// v_s, m/s
    pub v_s: f64,
    /// v_d, m/s
    pub v_d: f64,
}

impl TwoLevelLaw {
    /// μ(v) **with the SPEC §3.4 sign convention** (negative for v > 0: the force opposes sliding):
    /// |v| ≤ v_s: −STEP(v, −v_s, −μ_s, v_s, μ_s); v_s < |v| < v_d: −sign(v) STEP(|v|, v_s, μ_s, v_d, μ_d);
    /// |v| ≥ v_d: −sign(v) μ_d.
    #[inline]
    pub fn coefficient(&self, v: f64) -> f64 {
        let a = v.abs();
        if a <= self.v_s {
            // = −STEP(v, −v_s, −μ_s, v_s, μ_s) written as the odd cubic μ_s x(3 − x²)/2, x = v/v_s
            // (bit-exact oddness)
            let x = v / self.v_s;
            -self.mu_s * 0.5 * x * (3.0 - x * x)
        } else if a < self.v_d {
            -v.signum() * step(a, self.v_s, self.mu_s, self.v_d, self.mu_d)
        } else {
            -v.signum() * self.mu_d
        }
    }
}

/// Odd regularisation factor in [−1, 1]: STEP(v, −v_s, −1, v_s, 1) for |v| < v_s, sign(v) beyond
/// (the two-level law with μ_s = μ_d, used around v = 0 for raceway contacts, SPEC §3.4 proposal).
#[inline]
pub fn regularisation(v: f64, v_s: f64) -> f64 {
    if v.abs() < v_s {
        // STEP(v, −v_s, −1, v_s, 1) = x(3 − x²)/2, x = v/v_s (exactly odd)
        let x = v / v_s;
        0.5 * x * (3.0 - x * x)
    } else if v == 0.0 {
        0.0
    } else {
        v.signum()
    }
}
