//! The matrix stress just outside the interface (theory §10.6.3). With the equivalent
//! eigenstrain ε* known, displacement continuity leaves a jump of the displacement gradient of
//! the form a ⊗ n across the interface (unit outward normal n), and traction continuity fixes a
//! (Hill 1961; Mura 1987 §11, the jump conditions at the boundary of an inclusion):
//!
//! ⟦u_i,j⟧ = a_i n_j,  a = −N(n) (C : ε*) n,  N = K⁻¹, K_ik = C_ijkl n_j n_l.
//!
//! For the isotropic matrix N_ik = [δ_ik − n_i n_k / (2(1 − ν))] / μ. The matrix stress outside
//! is σ_out = σ⁰ + C (S ε* + sym(a ⊗ n)): a linear map of σ⁰ at every point of the surface.

use super::mandel::{self, Mat6};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A point of the ellipsoid surface where the matrix stress is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SamplePoint {
    /// position in the ellipsoid axes, m
    pub position: [f64; 3],
    /// unit outward normal
    pub normal: [f64; 3],
}

/// The surface points of the ellipsoid with `semi_axes`: the six poles (±a_i on each axis)
/// first, then a grid x = (a₁ sin ϑ cos φ, a₂ sin ϑ sin φ, a₃ cos ϑ) with ϑ_k = kπ/(L + 1),
/// k = 1…L (`latitudes`), and φ_m = 2πm/M, m = 0…M − 1 (`longitudes`), leaving out the grid
/// points that are poles.
pub fn sample_points(semi_axes: [f64; 3], latitudes: usize, longitudes: usize) -> Vec<SamplePoint> {
    let mut points: Vec<SamplePoint> = (0..6)
        .map(|p| {
            let mut direction = [0.0; 3];
            direction[p / 2] = if p % 2 == 0 { 1.0 } else { -1.0 };
            surface_point(semi_axes, direction)
        })
        .collect();
    for k in 1..=latitudes {
        let polar = PI * k as f64 / (latitudes + 1) as f64;
        for m in 0..longitudes {
            let azimuth = 2.0 * PI * m as f64 / longitudes as f64;
            let direction = [
                polar.sin() * azimuth.cos(),
                polar.sin() * azimuth.sin(),
                polar.cos(),
            ];
            let point = surface_point(semi_axes, direction);
            let is_pole = points[..6]
                .iter()
                .any(|pole| distance(pole.normal, point.normal) < 1e-9);
            if !is_pole {
                points.push(point);
            }
        }
    }
    points
}

/// The surface point a_i d_i of the unit direction `d` and its normal ∝ (x_i / a_i²).
fn surface_point(semi_axes: [f64; 3], direction: [f64; 3]) -> SamplePoint {
    let position: [f64; 3] = std::array::from_fn(|i| semi_axes[i] * direction[i]);
    let gradient: [f64; 3] = std::array::from_fn(|i| position[i] / semi_axes[i].powi(2));
    let length = gradient.iter().map(|g| g * g).sum::<f64>().sqrt();
    SamplePoint {
        position,
        normal: gradient.map(|g| g / length),
    }
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

/// The strain jump ε* ↦ sym(a ⊗ n) across the interface at normal `n` of an isotropic matrix
/// (Lamé μ `mu`, Poisson's ratio `nu`, stiffness `c`), Mandel components.
pub fn strain_jump(n: [f64; 3], c: &Mat6, mu: f64, nu: f64) -> Mat6 {
    let mut jump = [[0.0; 6]; 6];
    for column in 0..6 {
        let mut unit = [0.0; 6];
        unit[column] = 1.0;
        let stress = mandel::to_tensor(&mandel::apply(c, &unit));
        let traction: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| stress[i][j] * n[j]).sum());
        let n_dot_t: f64 = (0..3).map(|i| n[i] * traction[i]).sum();
        let a: [f64; 3] =
            std::array::from_fn(|i| -(traction[i] - n[i] * n_dot_t / (2.0 * (1.0 - nu))) / mu);
        let gradient: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| a[i] * n[j]));
        let jumped = mandel::from_tensor(&gradient);
        for row in 0..6 {
            jump[row][column] = jumped[row];
        }
    }
    jump
}

/// The map σ⁰ ↦ σ_out = [I + C (S + J) A] σ⁰ of the matrix stress just outside the interface,
/// Mandel components: `c` matrix stiffness, `s` Eshelby tensor, `jump` the [`strain_jump`] of
/// the point, `eigenstrain_per_stress` A of the equivalent inclusion.
pub fn matrix_stress_map(c: &Mat6, s: &Mat6, jump: &Mat6, eigenstrain_per_stress: &Mat6) -> Mat6 {
    let strain_outside_per_eigenstrain = mandel::add(s, jump);
    let perturbation = mandel::mul(
        &mandel::mul(c, &strain_outside_per_eigenstrain),
        eigenstrain_per_stress,
    );
    mandel::add(&mandel::identity(), &perturbation)
}

/// The normal traction n · σ · n of the stress `[xx, yy, zz, xy, yz, zx]`.
pub fn normal_traction(stress: &[f64; 6], n: [f64; 3]) -> f64 {
    let t = mandel::to_tensor(&mandel::from_stress(stress));
    (0..3)
        .map(|i| (0..3).map(|j| n[i] * t[i][j] * n[j]).sum::<f64>())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_keeps_the_poles_once() {
        let points = sample_points([1.0, 2.0, 3.0], 17, 36);
        assert_eq!(points.len(), 6 + 17 * 36 - 4);
        for p in &points {
            let on_surface: f64 = (0..3)
                .map(|i| (p.position[i] / [1.0, 2.0, 3.0][i]).powi(2))
                .sum();
            assert!((on_surface - 1.0).abs() < 1e-12);
        }
    }
}
