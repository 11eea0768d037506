//! The non-metallic inclusion micro-model (theory §10.6; seed 000 §2.5, §3.1.1.8): a hard
//! ellipsoidal oxide particle in the cage steel under the uniform remote stress of the macro
//! model at the critical fillet. Eshelby's solution ([`eshelby`], [`equivalent`]) gives the
//! matrix stress just outside the interface ([`interface`]) as a linear map of the remote stress
//! at every sample point of the surface, bonded or with an opening interface ([`debonded`]);
//! a history of remote stresses then costs one 6 × 6 product per state and point.
//!
//! Assumptions: the particle is small against the stress gradient of the cage (uniform remote
//! stress) and far from the free surface (infinite matrix; the seed's 50 µm depth is ten times
//! the largest semi-axis); both materials linear elastic and isotropic; the largest matrix
//! stress lies on the interface, where the samples are.

pub mod debonded;
pub mod equivalent;
pub mod eshelby;
pub mod interface;
pub mod mandel;

pub use debonded::{Interface, PointMaps};
pub use equivalent::EquivalentInclusion;
pub use eshelby::{EshelbyTensor, IIntegrals, QuadratureSettings};
pub use interface::{SamplePoint, sample_points};

use crate::unit_stresses::Stress;
use serde::{Deserialize, Serialize};

/// The inclusion and its evaluation, SI.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InclusionSettings {
    /// semi-axes a₁, a₂, a₃ along the ellipsoid axes 1, 2, 3, m. Default 2, 3.5, 5 µm (seed 000
    /// §3.1.1.8: "along X, Y, Z" of its FE model). The seed does not say how X, Y, Z lie in
    /// the cage; rolldyn takes X radial, Y circumferential, Z axial ([`Self::axes_in_cylindrical`]).
    pub semi_axes_m: [f64; 3],
    /// Young's modulus of the inclusion, Pa (0: a void). Default 375 GPa, Al₂O₃ (seed 000
    /// §3.1.1.8).
    pub youngs_modulus: f64,
    /// Poisson's ratio of the inclusion. Default 0.25 (Al₂O₃, seed 000 §3.1.1.8).
    pub poisson_ratio: f64,
    /// Default [`Interface::Debonded`]: the seed's contact interface may open.
    pub interface: Interface,
    /// rows: the unit vectors of ellipsoid axes 1, 2, 3 in the cage's local cylindrical
    /// components (r, θ, z). Default the identity (axis 1 radial, 2 circumferential, 3 axial).
    pub axes_in_cylindrical: [[f64; 3]; 3],
    /// latitude circles of the surface grid besides the poles of axis 3. Default 17 (every 10°).
    pub latitudes: usize,
    /// meridians of the surface grid. Default 36 (every 10°): with 17 latitudes, 614 points.
    pub longitudes: usize,
    pub quadrature: QuadratureSettings,
}

impl Default for InclusionSettings {
    fn default() -> Self {
        Self {
            semi_axes_m: [2e-6, 3.5e-6, 5e-6],
            youngs_modulus: 375e9,
            poisson_ratio: 0.25,
            interface: Interface::Debonded,
            axes_in_cylindrical: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            latitudes: 17,
            longitudes: 36,
            quadrature: QuadratureSettings::default(),
        }
    }
}

impl InclusionSettings {
    /// The reasons these settings cannot be evaluated (empty when they can).
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        if !self.semi_axes_m.iter().all(|a| a.is_finite() && *a > 0.0) {
            out.push("the semi-axes must be positive".into());
        }
        if !(self.youngs_modulus.is_finite() && self.youngs_modulus >= 0.0) {
            out.push("the inclusion's Young's modulus must be ≥ 0".into());
        }
        if !(self.poisson_ratio > -1.0 && self.poisson_ratio < 0.5) {
            out.push("the inclusion's Poisson's ratio must lie in (−1, 0.5)".into());
        }
        let q = &self.axes_in_cylindrical;
        let orthonormal = (0..3).all(|i| {
            (0..3).all(|j| {
                let dot: f64 = (0..3).map(|k| q[i][k] * q[j][k]).sum();
                (dot - if i == j { 1.0 } else { 0.0 }).abs() < 1e-9
            })
        });
        if !orthonormal {
            out.push("the ellipsoid axes must be orthonormal".into());
        }
        out
    }
}

/// The inclusion in a given matrix, with the per-point maps precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct InclusionModel {
    pub settings: InclusionSettings,
    pub points: Vec<PointMaps>,
    /// remote → stress inside the bonded inclusion (uniform), stress components
    pub interior: mandel::Mat6,
}

impl InclusionModel {
    /// The model for a matrix of Young's modulus `matrix_youngs_modulus` (Pa) and Poisson's
    /// ratio `matrix_poisson_ratio`.
    pub fn new(
        settings: &InclusionSettings,
        matrix_youngs_modulus: f64,
        matrix_poisson_ratio: f64,
    ) -> Result<Self, String> {
        let mut problems = settings.problems();
        if !(matrix_youngs_modulus > 0.0
            && matrix_poisson_ratio > -1.0
            && matrix_poisson_ratio < 0.5)
        {
            problems.push("the matrix needs E > 0 and ν in (−1, 0.5)".into());
        }
        if !problems.is_empty() {
            return Err(problems.join("; "));
        }
        let (e, nu) = (matrix_youngs_modulus, matrix_poisson_ratio);
        let (_, mu) = mandel::lame(e, nu);
        let c = mandel::isotropic_stiffness(e, nu);
        let c_inclusion =
            mandel::isotropic_stiffness(settings.youngs_modulus, settings.poisson_ratio);
        let s = EshelbyTensor::new(settings.semi_axes_m, nu, &settings.quadrature).mandel();
        let singular = |_| "singular equivalent-inclusion system".to_string();
        let bonded = EquivalentInclusion::new(&c, &c_inclusion, &s).map_err(singular)?;
        let cavity = EquivalentInclusion::new(&c, &[[0.0; 6]; 6], &s).map_err(singular)?;
        let points = sample_points(
            settings.semi_axes_m,
            settings.latitudes,
            settings.longitudes,
        )
        .into_iter()
        .map(|point| {
            let jump = interface::strain_jump(point.normal, &c, mu, nu);
            let map = |eq: &EquivalentInclusion| {
                mandel::to_stress_map(&interface::matrix_stress_map(
                    &c,
                    &s,
                    &jump,
                    &eq.eigenstrain_per_stress,
                ))
            };
            PointMaps {
                point,
                bonded: map(&bonded),
                cavity: map(&cavity),
            }
        })
        .collect();
        Ok(Self {
            settings: settings.clone(),
            points,
            interior: mandel::to_stress_map(&bonded.interior_stress),
        })
    }

    /// The matrix stress history at every sample point for the remote stress history `remote`
    /// (components `[xx, yy, zz, xy, yz, zx]` in the ellipsoid axes, Pa), under the
    /// settings' interface condition.
    pub fn matrix_stress_histories(
        &self,
        remote: &[[f64; 6]],
    ) -> Vec<(SamplePoint, Vec<[f64; 6]>)> {
        let interface = self.settings.interface;
        self.points
            .iter()
            .map(|maps| {
                let history = remote
                    .iter()
                    .map(|r| maps.matrix_stress(r, interface))
                    .collect();
                (maps.point, history)
            })
            .collect()
    }

    /// The stress inside the bonded inclusion for the remote stress `remote`, Pa.
    pub fn interior_stress(&self, remote: &[f64; 6]) -> [f64; 6] {
        mandel::apply(&self.interior, remote)
    }

    /// A stress in the cage's cylindrical components `[σ_rr, σ_θθ, σ_zz, τ_rθ, τ_θz, τ_zr]`
    /// expressed in the ellipsoid axes.
    pub fn remote_from_cylindrical(&self, stress: &Stress) -> [f64; 6] {
        mandel::rotate_stress(stress, &self.settings.axes_in_cylindrical)
    }
}
