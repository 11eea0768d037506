//! Elastic half-space under a line load (plane strain), seed 002 eq. (3.3) (SPEC §8.3):
//! K(u) = (2/π)·Σ(1 − ν²)/E · ln(L/|u|), with L a reference length (the half-space deflection is
//! defined only up to a constant; the seed writes ln(2L/|x − x′|)).

use super::LineKernel;

/// Half-space (or two half-spaces in contact) log kernel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfSpace {
    /// Σ (1 − νᵢ²)/Eᵢ over the bodies, 1/Pa (= 2/E′).
    pub compliance: f64,
    /// Reference length L of ln(L/|u|), m (distance at which the deflection is zero).
    pub reference_length: f64,
}

impl HalfSpace {
    /// One body with modulus `e` (Pa), Poisson ratio `nu` and reference length (m).
    pub fn new(e: f64, nu: f64, reference_length: f64) -> Self {
        Self {
            compliance: (1.0 - nu * nu) / e,
            reference_length,
        }
    }

    /// Two bodies (roller and raceway) with effective modulus E′ = 2/Σ(1−ν²)/E.
    pub fn pair(e1: f64, nu1: f64, e2: f64, nu2: f64, reference_length: f64) -> Self {
        Self {
            compliance: (1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2,
            reference_length,
        }
    }

    /// Roller of radius R loaded on its surface and held at its axis: deflection of the surface
    /// relative to the axis. Matches the classical compression of a cylinder by a Hertzian
    /// line load, δ = 2(1−ν²)P/(πE)·[ln(4R/a) − ½] (Johnson, Contact Mechanics §5.6, standard
    /// form, not in the seeds), which gives L = 2R/e.
    pub fn roller_on_axis(radius: f64, e: f64, nu: f64) -> Self {
        Self::new(e, nu, 2.0 * radius / std::f64::consts::E)
    }

    /// Effective modulus E′ = 2/compliance.
    pub fn e_prime(&self) -> f64 {
        2.0 / self.compliance
    }
}

impl LineKernel for HalfSpace {
    fn value(&self, u: f64) -> f64 {
        2.0 / std::f64::consts::PI * self.compliance * (self.reference_length / u.abs()).ln()
    }

    fn integral(&self, u0: f64, u1: f64) -> f64 {
        // ∫ ln(L/|u|) du = u (ln L − ln|u| + 1)
        let l = self.reference_length.ln();
        let f = |u: f64| {
            if u == 0.0 {
                0.0
            } else {
                u * (l - u.abs().ln() + 1.0)
            }
        };
        2.0 / std::f64::consts::PI * self.compliance * (f(u1) - f(u0))
    }
}
