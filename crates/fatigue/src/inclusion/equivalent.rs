//! Eshelby's equivalent inclusion (theory §10.6.2; Eshelby 1957; Mura 1987 §22): an ellipsoidal
//! inhomogeneity of stiffness C₁ in a matrix of stiffness C under the uniform remote stress σ⁰
//! (remote strain ε⁰ = C⁻¹σ⁰) carries the same field as a homogeneous inclusion with the uniform
//! eigenstrain ε* that solves the consistency condition
//!
//! C₁ (ε⁰ + S ε*) = C (ε⁰ + S ε* − ε*),  i.e.  [(C₁ − C) S + C] ε* = (C − C₁) ε⁰.
//!
//! Inside, the strain is ε⁰ + S ε* and the stress σ⁰ + C (S − I) ε*. A cavity is C₁ = 0: then
//! C (I − S) ε* = C ε⁰ and the interior stress vanishes.

use super::mandel::{self, Mat6};
use rolldyn_numerics::dense_lu::Singular;

/// The linear maps of the equivalent inclusion, Mandel components.
#[derive(Debug, Clone, PartialEq)]
pub struct EquivalentInclusion {
    /// ε* = A σ⁰
    pub eigenstrain_per_stress: Mat6,
    /// σ_inside = B σ⁰ = [I + C (S − I) A] σ⁰
    pub interior_stress: Mat6,
}

impl EquivalentInclusion {
    /// The maps for matrix stiffness `c`, inclusion stiffness `c_inclusion` (zero: a cavity)
    /// and Eshelby tensor `s` (all Mandel).
    pub fn new(c: &Mat6, c_inclusion: &Mat6, s: &Mat6) -> Result<Self, Singular> {
        let stiffness_jump = mandel::sub(c_inclusion, c);
        let consistency = mandel::add(&mandel::mul(&stiffness_jump, s), c);
        let remote_strain_per_stress = mandel::solve(c, &mandel::identity())?;
        let right = mandel::mul(&mandel::sub(c, c_inclusion), &remote_strain_per_stress);
        let eigenstrain_per_stress = mandel::solve(&consistency, &right)?;
        let s_minus_i = mandel::sub(s, &mandel::identity());
        let interior_stress = mandel::add(
            &mandel::identity(),
            &mandel::mul(&mandel::mul(c, &s_minus_i), &eigenstrain_per_stress),
        );
        Ok(Self {
            eigenstrain_per_stress,
            interior_stress,
        })
    }
}
