//! Journal-bearing liner compliances, SPEC §8.3 (seed 002 ch. 2 and §4.4).
//!
//! Radii: R₁ liner bore, R₂ liner outer / housing bore, R₃ housing outer (fixed). Deflection
//! positive = bore grows (film opens).

use super::LineKernel as _;
use crate::error::{Result, ReynoldsError, positive};

/// Winkler compliance of a thin layer of thickness ψ bonded to a rigid housing (first order in
/// ψ/R₁), seed 002 eqs. (2.1), (2.2): δ = D·P, D = ψ(1+m)(1−2m)/(E(1−m)), m/Pa.
pub fn winkler(thickness: f64, e: f64, nu: f64) -> f64 {
    thickness * (1.0 + nu) * (1.0 - 2.0 * nu) / (e * (1.0 - nu))
}

/// Exact plane-strain compliance of a cylindrical layer R₁ ≤ r ≤ R₂ with a clamped outer surface
/// under uniform bore pressure, seed 002 eq. (2.25) = (4.9) (with the square restored, F-59):
/// δ/P = (1+m)(1−2m)R₁/(E(2m/R₁² − 1/R₂² − 1/R₁²))·(1/R₂² − 1/R₁²), m/Pa.
pub fn clamped_layer(r1: f64, r2: f64, e: f64, nu: f64) -> f64 {
    let (a1, a2) = (1.0 / (r1 * r1), 1.0 / (r2 * r2));
    (1.0 + nu) * (1.0 - 2.0 * nu) * r1 / (e * (2.0 * nu * a1 - a2 - a1)) * (a2 - a1)
}

/// Lamé plane-strain compliance of a free cylindrical layer (outer surface traction-free) under
/// bore pressure: u(R₁) = aR₁ + b/R₁ with a = PR₁²(1+m)(1−2m)/(E(R₂²−R₁²)),
/// b = PR₁²R₂²(1+m)/(E(R₂²−R₁²)) (SPEC §8.3, F-59: without the seed's extra (1 − 2m) in b), m/Pa.
pub fn free_layer(r1: f64, r2: f64, e: f64, nu: f64) -> f64 {
    let d = r2 * r2 - r1 * r1;
    let a = r1 * r1 * (1.0 + nu) * (1.0 - 2.0 * nu) / (e * d);
    let b = r1 * r1 * r2 * r2 * (1.0 + nu) / (e * d);
    a * r1 + b / r1
}

/// Material of one layer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus, Pa.
    pub e: f64,
    /// Poisson ratio.
    pub nu: f64,
}

/// Two-layer (liner + housing) Winkler compliance K₀, seed 002 eq. (4.15) with the material
/// indices corrected (flag F-73): K₀ = (R₂−R₁)(1+m_l)(1−2m_l)/(E_l(1−m_l)) +
/// (R₃−R₂)(1+m_h)(1−2m_h)/(E_h(1−m_h)), m/Pa.
pub fn two_layer(r1: f64, r2: f64, r3: f64, liner: Material, housing: Material) -> f64 {
    winkler(r2 - r1, liner.e, liner.nu) + winkler(r3 - r2, housing.e, housing.nu)
}

/// Analytic approximation of the journal-bearing compliance function, seed 002 eqs. (4.14),
/// (4.36): K(φ) = 1.2 K₀ [1/(1 + a|φ|^α)]^β on φ ∈ [−π, π], periodic, per radian
/// (δ(φ) = ∫ p(φ′) K(φ − φ′) dφ′). Defaults a = 5, α = 1.7, β = 1.4 (the seed's "three
/// parameters of the compliance function").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalyticLinerKernel {
    /// K₀, m/Pa.
    pub k0: f64,
    /// a (the seed's γ).
    pub a: f64,
    /// α′ (the seed's α).
    pub alpha: f64,
    /// β.
    pub beta: f64,
}

impl AnalyticLinerKernel {
    /// Kernel with the seed's parameters a = 5, α′ = 1.7, β = 1.4.
    pub fn seed(k0: f64) -> Self {
        Self {
            k0,
            a: 5.0,
            alpha: 1.7,
            beta: 1.4,
        }
    }

    /// K(φ), 1/Pa·m per rad.
    pub fn value(&self, phi: f64) -> f64 {
        let p = wrap_pi(phi).abs();
        1.2 * self.k0 * (1.0 + self.a * p.powf(self.alpha)).powf(-self.beta)
    }
}

/// Wraps an angle to (−π, π].
pub fn wrap_pi(phi: f64) -> f64 {
    let t = std::f64::consts::TAU;
    let mut p = phi.rem_euclid(t);
    if p > std::f64::consts::PI {
        p -= t;
    }
    p
}

/// Periodic compliance kernel of a journal liner, per radian.
#[derive(Debug, Clone, PartialEq)]
pub enum LinerKernel {
    /// Local (Winkler) response δ = K₀ p.
    Winkler {
        /// K₀, m/Pa.
        k0: f64,
    },
    /// The seed's analytic kernel (4.36).
    Analytic(AnalyticLinerKernel),
    /// A kernel identified from FE data by [`super::fourier::FourierKernel::identify_periodic`].
    Fourier(super::fourier::FourierKernel),
}

impl LinerKernel {
    /// Circulant weights cₘ on a periodic grid of n nodes (spacing 2π/n): δᵢ = Σₖ c_{(i−k) mod n} pₖ,
    /// cₘ = ∫ over the cell of node k of K(φᵢ − φ′) dφ′ (Gauss quadrature, 4 panels).
    pub fn circulant(&self, n: usize) -> Result<Vec<f64>> {
        if n < 3 {
            return Err(ReynoldsError::InvalidInput {
                what: "liner kernel grid",
                reason: format!("{n} nodes"),
            });
        }
        let h = std::f64::consts::TAU / n as f64;
        Ok(match self {
            LinerKernel::Winkler { k0 } => {
                positive("K0", *k0)?;
                let mut c = vec![0.0; n];
                c[0] = *k0;
                c
            }
            LinerKernel::Analytic(k) => {
                positive("K0", k.k0)?;
                (0..n)
                    .map(|m| {
                        let d = m as f64 * h;
                        // K has a cusp at 0: integrate the two half cells separately
                        super::gauss_panels(|u| k.value(u), d - 0.5 * h, d, 4)
                            + super::gauss_panels(|u| k.value(u), d, d + 0.5 * h, 4)
                    })
                    .collect()
            }
            LinerKernel::Fourier(fk) => (0..n)
                .map(|m| {
                    let d = m as f64 * h;
                    fk.integral(d - 0.5 * h, d + 0.5 * h)
                })
                .collect(),
        })
    }

    /// K₀-like scale (deflection per Pa of a uniform pressure), m/Pa.
    pub fn uniform_compliance(&self, n: usize) -> Result<f64> {
        Ok(self.circulant(n)?.iter().sum())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// V-29 (seed 002 §2.3, F-60): R₁ = 0.05 m, R₂ = 0.055 m, E = 2.1×10¹¹ Pa, m = 0.3; the
    /// seed's tabulated deflections correspond to P = 4000 Pa: Winkler 7.075×10⁻¹¹ m, exact
    /// 7.008×10⁻¹¹ m (difference 0.95 %, not the printed 1.5 %). Tolerance 10⁻⁴ relative (SPEC).
    #[test]
    fn v29_cylindrical_layer() {
        let (r1, r2, e, nu, p) = (0.05, 0.055, 2.1e11, 0.3, 4000.0);
        let w = winkler(r2 - r1, e, nu) * p;
        let x = clamped_layer(r1, r2, e, nu) * p;
        assert!((w - 7.0748e-11).abs() < 1e-4 * 7.075e-11, "{w}");
        assert!((x - 7.0078e-11).abs() < 1e-4 * 7.008e-11, "{x}");
        assert!(((w - x) / x - 0.0095).abs() < 5e-4);
        // at the stated 3000 Pa: 5.306e-11 and 5.256e-11 (F-60)
        assert!((winkler(r2 - r1, e, nu) * 3000.0 - 5.306e-11).abs() < 1e-4 * 5.306e-11);
        assert!((clamped_layer(r1, r2, e, nu) * 3000.0 - 5.256e-11).abs() < 2e-4 * 5.256e-11);
        // the free layer is softer than the clamped one
        assert!(free_layer(r1, r2, e, nu) > clamped_layer(r1, r2, e, nu));
    }
}
