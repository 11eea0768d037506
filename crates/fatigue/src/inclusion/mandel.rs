//! Symmetric second-order tensors as 6-vectors and fourth-order tensors with minor symmetries
//! as 6 × 6 matrices in Mandel's orthonormal basis (theory §10.6): components
//! `[11, 22, 33, √2·12, √2·23, √2·31]`, so that double contraction is the matrix product and
//! the inverse of a map is the matrix inverse. The stress vectors of the API use tensor
//! components in the same order (`[xx, yy, zz, xy, yz, zx]`); [`from_stress`] and
//! [`to_stress`] convert.

use rolldyn_numerics::dense_lu::{DenseLu, Singular};
use std::f64::consts::SQRT_2;

/// A symmetric tensor in Mandel components.
pub type Vec6 = [f64; 6];
/// A linear map of symmetric tensors in Mandel components (row-major).
pub type Mat6 = [[f64; 6]; 6];

/// The (i, j) index pair of each Mandel component.
pub const PAIRS: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (2, 0)];

/// Mandel weight of component `k`: 1 for normal, √2 for shear components.
fn weight(k: usize) -> f64 {
    if k < 3 { 1.0 } else { SQRT_2 }
}

/// Mandel vector of the stress `[xx, yy, zz, xy, yz, zx]`.
pub fn from_stress(s: &[f64; 6]) -> Vec6 {
    std::array::from_fn(|k| weight(k) * s[k])
}

/// Stress `[xx, yy, zz, xy, yz, zx]` of a Mandel vector.
pub fn to_stress(v: &Vec6) -> [f64; 6] {
    std::array::from_fn(|k| v[k] / weight(k))
}

/// The 3 × 3 tensor of a Mandel vector.
pub fn to_tensor(v: &Vec6) -> [[f64; 3]; 3] {
    let mut t = [[0.0; 3]; 3];
    for (k, &(i, j)) in PAIRS.iter().enumerate() {
        t[i][j] = v[k] / weight(k);
        t[j][i] = t[i][j];
    }
    t
}

/// The Mandel vector of the symmetric part of a 3 × 3 tensor.
pub fn from_tensor(t: &[[f64; 3]; 3]) -> Vec6 {
    std::array::from_fn(|k| {
        let (i, j) = PAIRS[k];
        weight(k) * 0.5 * (t[i][j] + t[j][i])
    })
}

/// Isotropic stiffness C = λ 1⊗1 + 2μ I (Young's modulus `e`, Poisson's ratio `nu`); the zero
/// map for `e = 0`.
pub fn isotropic_stiffness(e: f64, nu: f64) -> Mat6 {
    let (lambda, mu) = lame(e, nu);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let volumetric = if i < 3 && j < 3 { lambda } else { 0.0 };
            volumetric + if i == j { 2.0 * mu } else { 0.0 }
        })
    })
}

/// Lamé constants (λ, μ) of Young's modulus `e` and Poisson's ratio `nu`.
pub fn lame(e: f64, nu: f64) -> (f64, f64) {
    (
        e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
        e / (2.0 * (1.0 + nu)),
    )
}

/// The identity map.
pub fn identity() -> Mat6 {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { 1.0 } else { 0.0 }))
}

/// a + b.
pub fn add(a: &Mat6, b: &Mat6) -> Mat6 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
}

/// a − b.
pub fn sub(a: &Mat6, b: &Mat6) -> Mat6 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] - b[i][j]))
}

/// The product a b.
pub fn mul(a: &Mat6, b: &Mat6) -> Mat6 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..6).map(|k| a[i][k] * b[k][j]).sum()))
}

/// a v.
pub fn apply(a: &Mat6, v: &Vec6) -> Vec6 {
    std::array::from_fn(|i| (0..6).map(|k| a[i][k] * v[k]).sum())
}

/// a⁻¹ b (dense LU with partial pivoting).
pub fn solve(a: &Mat6, b: &Mat6) -> Result<Mat6, Singular> {
    let lu = DenseLu::new(6, a.iter().flatten().copied().collect())?;
    let mut x = [[0.0; 6]; 6];
    for j in 0..6 {
        let mut column: Vec<f64> = (0..6).map(|i| b[i][j]).collect();
        lu.solve(&mut column);
        for i in 0..6 {
            x[i][j] = column[i];
        }
    }
    Ok(x)
}

/// The map from tensor-component stress vectors to tensor-component stress vectors that the
/// Mandel map `m` is: D⁻¹ m D with D = diag(1, 1, 1, √2, √2, √2).
pub fn to_stress_map(m: &Mat6) -> Mat6 {
    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j] * weight(j) / weight(i)))
}

/// The stress `[xx, yy, zz, xy, yz, zx]` in the rotated axes whose unit vectors are the rows
/// of `q` (in the old axes): σ′ = Q σ Qᵀ.
pub fn rotate_stress(stress: &[f64; 6], q: &[[f64; 3]; 3]) -> [f64; 6] {
    let t = to_tensor(&from_stress(stress));
    let rotated: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut sum = 0.0;
            for k in 0..3 {
                for l in 0..3 {
                    sum += q[i][k] * q[j][l] * t[k][l];
                }
            }
            sum
        })
    });
    to_stress(&from_tensor(&rotated))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tensor_round_trip_and_stress_weights() {
        let s = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let v = from_stress(&s);
        assert_eq!(to_tensor(&v)[0][1], 4.0);
        assert_eq!(to_tensor(&v)[0][2], 6.0);
        let back = to_stress(&from_tensor(&to_tensor(&v)));
        for k in 0..6 {
            assert!((back[k] - s[k]).abs() < 1e-14);
        }
    }

    #[test]
    fn hookes_law_in_mandel_form() {
        let c = isotropic_stiffness(200.0, 0.25);
        let shear_strain_tensor = [[0.0, 0.01, 0.0], [0.01, 0.0, 0.0], [0.0, 0.0, 0.0]];
        let stress = to_tensor(&apply(&c, &from_tensor(&shear_strain_tensor)));
        assert!((stress[0][1] - 2.0 * 80.0 * 0.01).abs() < 1e-12);
        let inverse = solve(&c, &identity()).unwrap();
        let uniaxial = to_tensor(&apply(
            &inverse,
            &from_stress(&[0.0, 0.0, 100.0, 0.0, 0.0, 0.0]),
        ));
        assert!((uniaxial[2][2] - 0.5).abs() < 1e-12 && (uniaxial[0][0] + 0.125).abs() < 1e-12);
    }

    #[test]
    fn rotating_uniaxial_stress_by_45_degrees_gives_shear() {
        let h = 0.5f64.sqrt();
        let q = [[h, h, 0.0], [-h, h, 0.0], [0.0, 0.0, 1.0]];
        let s = rotate_stress(&[100.0, 0.0, 0.0, 0.0, 0.0, 0.0], &q);
        let expected = [50.0, 50.0, 0.0, -50.0, 0.0, 0.0];
        for k in 0..6 {
            assert!((s[k] - expected[k]).abs() < 1e-12, "{s:?}");
        }
    }
}
