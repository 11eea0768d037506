//! The linear stress response of the cage (theory §10.2): the stress at every fillet point for a
//! unit force at every station of pocket 0 and for a unit spin² — what a stress model ("frame"
//! or "calculix") computes once per cage geometry. Loads at other pockets follow by cyclic
//! symmetry ([`crate::cage`]); every unit case is balanced by the cage's rigid-body inertia
//! (inertia relief), so the sum over a load set is the stress of the free, accelerating cage.

use crate::cage::{CageGeometry, FilletPoint, STATIONS};
use serde::{Deserialize, Serialize};

/// Cylindrical stress components `[σ_rr, σ_θθ, σ_zz, τ_rθ, τ_θz, τ_zr]`, Pa.
pub type Stress = [f64; 6];

/// Unit stress cases of one cage geometry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UnitStresses {
    /// which model computed them ("frame", "calculix")
    pub model: String,
    pub cage: CageGeometry,
    /// axial position of the bar stations (±), m
    pub bar_station_z: f64,
    /// stress at fillet point `p` (index of [`FilletPoint::all`]) for a unit force (1 N) along
    /// component `c` (0 radial, 1 tangential, 2 axial, in the pocket frame) at station `s` of
    /// pocket 0 ([`STATIONS`] order): `per_unit_force[(3 s + c) P + p]`, Pa/N
    pub per_unit_force: Vec<Stress>,
    /// stress at fillet point `p` for a cage spin of 1 rad/s (centrifugal load ρω²r), Pa/(rad/s)²
    pub per_unit_spin_squared: Vec<Stress>,
}

impl UnitStresses {
    /// Number of fillet points.
    pub fn points(&self) -> usize {
        8 * self.cage.pockets
    }

    /// Stress at `point` for a unit force along `component` at station `station` of pocket
    /// `pocket`: the pocket-0 case at the point `pocket` pitches lower.
    pub fn unit(
        &self,
        point: FilletPoint,
        station: usize,
        component: usize,
        pocket: usize,
    ) -> &Stress {
        let p = point.shifted_down(pocket, self.cage.pockets).index();
        &self.per_unit_force[(3 * station + component) * self.points() + p]
    }

    /// Checks the table sizes against the cage.
    pub fn consistent(&self) -> bool {
        let p = self.points();
        self.per_unit_force.len() == 3 * STATIONS.len() * p
            && self.per_unit_spin_squared.len() == p
    }
}

/// Signed equivalent stress: von Mises with the sign of the principal stress of largest
/// magnitude (SPEC-proposed scalar for counting, theory §10.3), Pa.
pub fn signed_von_mises(s: &Stress) -> f64 {
    let [xx, yy, zz, xy, yz, zx] = *s;
    let vm = (0.5 * ((xx - yy).powi(2) + (yy - zz).powi(2) + (zz - xx).powi(2))
        + 3.0 * (xy * xy + yz * yz + zx * zx))
        .sqrt();
    let (lo, hi) = principal_extremes(s);
    if hi.abs() >= lo.abs() { vm } else { -vm }
}

/// Smallest and largest principal stresses of `s` (eigenvalues of the symmetric tensor, by the
/// trigonometric solution of the characteristic cubic), Pa.
pub fn principal_extremes(s: &Stress) -> (f64, f64) {
    let [xx, yy, zz, xy, yz, zx] = *s;
    let mean = (xx + yy + zz) / 3.0;
    let (dx, dy, dz) = (xx - mean, yy - mean, zz - mean);
    let j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + xy * xy + yz * yz + zx * zx;
    if j2 <= 1e-30 * (mean * mean).max(1e-300) {
        return (mean, mean);
    }
    let j3 = dx * (dy * dz - yz * yz) - xy * (xy * dz - yz * zx) + zx * (xy * yz - dy * zx);
    let r = (j2 / 3.0).sqrt();
    let cos3 = (j3 / (2.0 * r * r * r)).clamp(-1.0, 1.0);
    let phi = cos3.acos() / 3.0;
    let hi = mean + 2.0 * r * phi.cos();
    let lo = mean + 2.0 * r * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniaxial_stress_keeps_its_sign() {
        assert!((signed_von_mises(&[0.0, 0.0, 100.0, 0.0, 0.0, 0.0]) - 100.0).abs() < 1e-9);
        assert!((signed_von_mises(&[0.0, -80.0, 0.0, 0.0, 0.0, 0.0]) + 80.0).abs() < 1e-9);
    }

    #[test]
    fn principal_stresses_of_pure_shear() {
        let (lo, hi) = principal_extremes(&[0.0, 0.0, 0.0, 50.0, 0.0, 0.0]);
        assert!((lo + 50.0).abs() < 1e-9 && (hi - 50.0).abs() < 1e-9);
        let vm = signed_von_mises(&[0.0, 0.0, 0.0, 50.0, 0.0, 0.0]);
        assert!((vm.abs() - 50.0 * 3f64.sqrt()).abs() < 1e-9);
    }
}
