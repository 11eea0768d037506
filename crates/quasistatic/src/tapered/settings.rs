//! The numerical knobs of the tapered load distribution, each with its default.

/// Settings of [`super::solve_tapered_loads`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedLoadSettings {
    /// Ring residual test: every force residual ≤ `tolerance` × the force scale (the largest of
    /// |F_r|, |F_a|, |M|/ℓ and 1 N, ℓ = half the row spacing) and every moment residual ≤
    /// `tolerance` × force scale × ℓ. Default 1e-9 (the roller solves are accurate to 1e-10).
    pub tolerance: f64,
    /// Roller residual test: the generalised forces of one roller ≤ `roller_tolerance` × its
    /// load (at least the mean roller share of the applied load). Default 1e-10: a slice
    /// approach of ≈ 10 µm is the difference of lengths of ≈ 10 mm, so it carries a rounding
    /// error of ≈ 1e-12 relative, which the residuals of a converged roller reach.
    pub roller_tolerance: f64,
    /// Ring Newton iterations. Default 60 (a case takes 5–15).
    pub max_iterations: usize,
    /// Newton iterations of one roller. Default 100 (a roller takes 3–10).
    pub max_roller_iterations: usize,
    /// Forward-difference step of the ring Jacobian, relative to the current displacement
    /// scale (at least 1 µm). Default 1e-5: ≈ 1e-10 m on the 10 µm deflections of a loaded
    /// bearing, far above the roller solves' noise and far below a slice's load-zone kink.
    pub jacobian_step: f64,
    /// Angular offset of row 1's rollers against row 0's, as a fraction of the roller pitch
    /// 2π/Z. Default 0: a roller of each row on the load line (the largest roller loads; the
    /// dynamics settles with one row offset, seed 000 §3.2.1).
    pub row1_offset_pitch: f64,
}

impl Default for TaperedLoadSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-9,
            roller_tolerance: 1e-10,
            max_iterations: 60,
            max_roller_iterations: 100,
            jacobian_step: 1e-5,
            row1_offset_pitch: 0.0,
        }
    }
}
