//! The Eshelby tensor of an ellipsoid in an isotropic matrix (theory §10.6.1): Mura (1987),
//! *Micromechanics of Defects in Solids*, §11, eqs. (11.16)–(11.19). The I-integrals are
//! evaluated in one form for every shape — distinct, two equal (spheroids) or three equal axes
//! (sphere) — by the substitution s = eᵗ and composite Gauss–Legendre quadrature, so no limit
//! needs a special case or divides by a difference of axes.

use super::mandel::Mat6;
use rolldyn_numerics::gauss_legendre;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Quadrature of the I-integrals in t = ln(s/a_max²). The integrands are analytic in the strip
/// |Im t| < π (their poles sit at s = −a_k²), so 8-point panels of width 1 converge to ≈1e-17
/// per panel; the tails beyond the window are below e^(−36) of the integral.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct QuadratureSettings {
    /// panel width in t. Default 1: Bernstein ellipse ρ ≈ 12.6, error ~ρ⁻¹⁶ per panel.
    pub panel_width: f64,
    /// window start below ln(a_min²/a_max²). Default 40: the integrand grows like eᵗ there,
    /// so the cut-off part is e⁻⁴⁰ ≈ 4e-18 relative.
    pub below_smallest: f64,
    /// window end beyond t = 0 (the largest axis). Default 30: the integrands decay at least
    /// like e^(−3t/2), so the cut-off part is e⁻⁴⁵ relative.
    pub beyond_largest: f64,
}

impl Default for QuadratureSettings {
    fn default() -> Self {
        Self {
            panel_width: 1.0,
            below_smallest: 40.0,
            beyond_largest: 30.0,
        }
    }
}

/// The I-integrals of an ellipsoid with semi-axes a₁, a₂, a₃ (Mura 1987 §11, (11.17)–(11.18)):
/// I_i = 2π a₁a₂a₃ ∫₀^∞ ds / ((a_i² + s) Δ(s)), I_ij = 2π a₁a₂a₃ ∫₀^∞ ds / ((a_i² + s)(a_j² + s) Δ(s)),
/// Δ(s) = √((a₁² + s)(a₂² + s)(a₃² + s)).
#[derive(Debug, Clone, PartialEq)]
pub struct IIntegrals {
    /// I_i, dimensionless
    pub single: [f64; 3],
    /// I_ij (symmetric), 1/m²
    pub pair: [[f64; 3]; 3],
}

impl IIntegrals {
    /// The integrals of the ellipsoid with `semi_axes` (m, any order, > 0).
    pub fn new(semi_axes: [f64; 3], quadrature: &QuadratureSettings) -> Self {
        let largest = semi_axes.iter().cloned().fold(0.0, f64::max);
        let squares = semi_axes.map(|a| (a / largest).powi(2));
        let integral = |extra: [i32; 3]| scaled_integral(squares, extra, quadrature);
        let single = std::array::from_fn(|i| {
            let mut extra = [0; 3];
            extra[i] = 1;
            integral(extra)
        });
        let pair = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut extra = [0; 3];
                extra[i] += 1;
                extra[j] += 1;
                integral(extra) / (largest * largest)
            })
        });
        Self { single, pair }
    }
}

/// 2π b₁b₂b₃ ∫₀^∞ ds / (Δ(s) Π_k (b_k² + s)^extra_k) for the squared semi-axes `squares`
/// (b_k², scaled so the largest is 1), with s = eᵗ, ds = eᵗ dt.
fn scaled_integral(squares: [f64; 3], extra: [i32; 3], q: &QuadratureSettings) -> f64 {
    let smallest = squares.iter().cloned().fold(f64::INFINITY, f64::min);
    let (t0, t1) = (smallest.ln() - q.below_smallest, q.beyond_largest);
    let panels = ((t1 - t0) / q.panel_width).ceil() as usize;
    let integrand = |t: f64| {
        let s = t.exp();
        let factors = (0..3).map(|k| (squares[k] + s).powf(-0.5 - extra[k] as f64));
        s * factors.product::<f64>()
    };
    let volume_factor = squares.iter().product::<f64>().sqrt();
    2.0 * PI * volume_factor * gauss_legendre::integrate(integrand, t0, t1, panels)
}

/// The non-zero components of the Eshelby tensor of an ellipsoid in an isotropic matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct EshelbyTensor {
    /// S_iijj (no sum), row i, column j
    pub normal: [[f64; 3]; 3],
    /// S_ijij for the pairs (1,2), (2,3), (3,1)
    pub shear: [f64; 3],
}

impl EshelbyTensor {
    /// Mura (1987) eq. (11.16) and its cyclic permutations, matrix Poisson's ratio `nu`:
    /// S_iiii = 3/(8π(1−ν)) a_i² I_ii + (1−2ν)/(8π(1−ν)) I_i,
    /// S_iijj = 1/(8π(1−ν)) a_j² I_ij − (1−2ν)/(8π(1−ν)) I_i (i ≠ j),
    /// S_ijij = (a_i² + a_j²)/(16π(1−ν)) I_ij + (1−2ν)/(16π(1−ν)) (I_i + I_j).
    pub fn new(semi_axes: [f64; 3], nu: f64, quadrature: &QuadratureSettings) -> Self {
        let integrals = IIntegrals::new(semi_axes, quadrature);
        let (i1, i2) = (&integrals.single, &integrals.pair);
        let a2 = semi_axes.map(|a| a * a);
        let q = 1.0 / (8.0 * PI * (1.0 - nu));
        let r = (1.0 - 2.0 * nu) * q;
        let normal = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                if i == j {
                    3.0 * q * a2[i] * i2[i][i] + r * i1[i]
                } else {
                    q * a2[j] * i2[i][j] - r * i1[i]
                }
            })
        });
        let shear = std::array::from_fn(|p| {
            let (i, j) = (p, (p + 1) % 3);
            0.5 * q * (a2[i] + a2[j]) * i2[i][j] + 0.5 * r * (i1[i] + i1[j])
        });
        Self { normal, shear }
    }

    /// The tensor as a Mandel 6 × 6 map of strains (shear entries 2 S_ijij).
    pub fn mandel(&self) -> Mat6 {
        let mut m = [[0.0; 6]; 6];
        for i in 0..3 {
            m[i][..3].copy_from_slice(&self.normal[i]);
            m[3 + i][3 + i] = 2.0 * self.shear[i];
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrals(a: [f64; 3]) -> IIntegrals {
        IIntegrals::new(a, &QuadratureSettings::default())
    }

    /// Mura (1987) eq. (11.19): Σ I_i = 4π, 3 I_11 + I_12 + I_13 = 4π/a₁²,
    /// 3 a₁² I_11 + a₂² I_12 + a₃² I_13 = 3 I_1, and I_12 = (I_2 − I_1)/(a₁² − a₂²).
    #[test]
    fn identities_of_a_general_ellipsoid() {
        let a = [2e-6, 3.5e-6, 5e-6];
        let g = integrals(a);
        let sum: f64 = g.single.iter().sum();
        assert!((sum / (4.0 * PI) - 1.0).abs() < 1e-13, "{sum}");
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let a2 = a.map(|x| x * x);
            let lhs = 3.0 * g.pair[i][i] + g.pair[i][j] + g.pair[i][k];
            assert!((lhs * a2[i] / (4.0 * PI) - 1.0).abs() < 1e-13);
            let lhs = 3.0 * a2[i] * g.pair[i][i] + a2[j] * g.pair[i][j] + a2[k] * g.pair[i][k];
            assert!((lhs / (3.0 * g.single[i]) - 1.0).abs() < 1e-13);
            let divided = (g.single[j] - g.single[i]) / (a2[i] - a2[j]);
            assert!((g.pair[i][j] / divided - 1.0).abs() < 1e-11);
        }
    }

    /// Sphere: I_i = 4π/3, I_ij = 4π/(5a²) (Mura 1987 §11, the sphere).
    #[test]
    fn sphere_integrals() {
        let a = 3e-6;
        let g = integrals([a; 3]);
        for i in 0..3 {
            assert!((g.single[i] / (4.0 * PI / 3.0) - 1.0).abs() < 1e-13);
            for j in 0..3 {
                assert!((g.pair[i][j] * 5.0 * a * a / (4.0 * PI) - 1.0).abs() < 1e-13);
            }
        }
    }

    /// Prolate spheroid a₁ = a₂ = a < a₃ = c: I₁ = I₂ = 2πa²c/(c² − a²)^{3/2} [c/a (c²/a² − 1)^{1/2}
    /// − arccosh(c/a)] (Mura 1987 §11, the prolate spheroid).
    #[test]
    fn prolate_spheroid_closed_form() {
        let (a, c) = (1.0, 4.0f64);
        let g = integrals([a, a, c]);
        let ratio = c / a;
        let i1 = 2.0 * PI * a * a * c / (c * c - a * a).powf(1.5)
            * (ratio * (ratio * ratio - 1.0).sqrt() - ratio.acosh());
        assert!(
            (g.single[0] / i1 - 1.0).abs() < 1e-13,
            "{} {i1}",
            g.single[0]
        );
        assert_eq!(g.single[0], g.single[1]);
    }

    /// Oblate spheroid a₁ = a₂ = a > a₃ = c: I₁ = I₂ = 2πa²c/(a² − c²)^{3/2} [arccos(c/a)
    /// − (c/a)(1 − c²/a²)^{1/2}] (Mura 1987 §11, the oblate spheroid).
    #[test]
    fn oblate_spheroid_closed_form() {
        let (a, c) = (5.0, 1.0f64);
        let g = integrals([a, a, c]);
        let ratio = c / a;
        let i1 = 2.0 * PI * a * a * c / (a * a - c * c).powf(1.5)
            * (ratio.acos() - ratio * (1.0 - ratio * ratio).sqrt());
        assert!(
            (g.single[0] / i1 - 1.0).abs() < 1e-13,
            "{} {i1}",
            g.single[0]
        );
    }

    /// Elliptic cylinder a₃ → ∞ (Mura 1987 §11): with t = a₂/(a₁ + a₂),
    /// S₁₁₁₁ = [(a₂² + 2a₁a₂)/(a₁ + a₂)² + (1 − 2ν) t] / (2(1 − ν)),
    /// S₁₁₂₂ = [a₂²/(a₁ + a₂)² − (1 − 2ν) t] / (2(1 − ν)), S₁₁₃₃ = ν t/(1 − ν),
    /// S₁₂₁₂ = [(a₁² + a₂²)/(2(a₁ + a₂)²) + (1 − 2ν)/2] / (2(1 − ν)), S₃₁₃₁ = a₂/(2(a₁ + a₂)).
    #[test]
    fn elliptic_cylinder_limit() {
        let (a1, a2, nu) = (1.0, 2.5, 0.3);
        let s = EshelbyTensor::new([a1, a2, 1e9], nu, &QuadratureSettings::default());
        let sum = a1 + a2;
        let t = a2 / sum;
        let k = 1.0 / (2.0 * (1.0 - nu));
        let expected = [
            k * ((a2 * a2 + 2.0 * a1 * a2) / (sum * sum) + (1.0 - 2.0 * nu) * t),
            k * (a2 * a2 / (sum * sum) - (1.0 - 2.0 * nu) * t),
            nu * t / (1.0 - nu),
            k * ((a1 * a1 + a2 * a2) / (2.0 * sum * sum) + 0.5 * (1.0 - 2.0 * nu)),
            a2 / (2.0 * sum),
        ];
        let got = [
            s.normal[0][0],
            s.normal[0][1],
            s.normal[0][2],
            s.shear[0],
            s.shear[2],
        ];
        for i in 0..5 {
            assert!((got[i] - expected[i]).abs() < 1e-8, "{got:?} {expected:?}");
        }
    }

    /// Nearly equal axes give the sphere's values: no division by a difference of axes.
    #[test]
    fn nearly_spherical_is_continuous() {
        let g = integrals([1.0, 1.0 + 1e-9, 1.0 - 1e-9]);
        for i in 0..3 {
            assert!((g.single[i] / (4.0 * PI / 3.0) - 1.0).abs() < 1e-8);
            for j in 0..3 {
                assert!((g.pair[i][j] * 5.0 / (4.0 * PI) - 1.0).abs() < 1e-8);
            }
        }
    }

    /// Extreme aspect ratio (10⁶): the identities (11.19) still hold to 1e-12.
    #[test]
    fn needle_identities() {
        let a = [1e-6, 2e-6, 1.0];
        let g = integrals(a);
        let sum: f64 = g.single.iter().sum();
        assert!((sum / (4.0 * PI) - 1.0).abs() < 1e-12, "{sum}");
        let a2 = a.map(|x| x * x);
        let lhs = 3.0 * a2[2] * g.pair[2][2] + a2[0] * g.pair[2][0] + a2[1] * g.pair[2][1];
        assert!((lhs / (3.0 * g.single[2]) - 1.0).abs() < 1e-12);
    }
}
