//! Boundary friction, Kragelsky, seed 000 (2.10), SPEC §4.4.

use rolldyn_numerics::fastmath;

/// Boundary (asperity) friction law.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum BoundaryFriction {
    /// μ_bd(s) of (2.10). Default.
    #[default]
    Kragelsky,
    /// constant coefficient (e.g. 0.065 of seed 000 §2.1 for roller ends)
    Constant(f64),
}

/// Kragelsky boundary friction (2.10): μ_bd = (−0.1 + 22.28 s) e^{−181.46 s} + 0.1, evaluated at
/// |s| (magnitude; the caller applies the sign of sliding). μ_bd(0) = 0, max 0.1200 at s = 0.0100,
/// → 0.1 for large s (V-16).
#[inline]
pub fn kragelsky(s: f64) -> f64 {
    let s = s.abs();
    (-0.1 + 22.28 * s) * fastmath::exp(-181.46 * s) + 0.1
}

impl BoundaryFriction {
    /// μ_bd at relative slip `s` (magnitude).
    #[inline]
    pub fn eval(self, s: f64) -> f64 {
        match self {
            BoundaryFriction::Kragelsky => kragelsky(s),
            BoundaryFriction::Constant(m) => m,
        }
    }
}
