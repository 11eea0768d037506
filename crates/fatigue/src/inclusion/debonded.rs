//! The interface condition (theory §10.6.4). Seed 000 §3.1.1.8 models the inclusion–matrix
//! interface as a contact that may open. rolldyn approximates it per load state and per surface
//! point: where the bonded solution pulls the interface apart (normal traction n·σ·n > 0) the
//! matrix stress of that state is taken from the ellipsoidal *cavity* (the equivalent inclusion
//! with C₁ = 0); elsewhere the bonded stress stands. This is a switch between two exact
//! solutions, not a contact solution: a partly open interface changes the field everywhere,
//! which the switch ignores.

use super::interface::{SamplePoint, normal_traction};
use super::mandel::{self, Mat6};
use serde::{Deserialize, Serialize};

/// How the inclusion is attached to the matrix.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Interface {
    /// perfectly bonded everywhere, in tension too
    Bonded,
    /// opens where the bonded normal traction is tensile (per state and point)
    Debonded,
}

/// The precomputed linear maps of one surface point: remote stress → matrix stress just
/// outside, stress components `[xx, yy, zz, xy, yz, zx]` in the ellipsoid axes.
#[derive(Debug, Clone, PartialEq)]
pub struct PointMaps {
    pub point: SamplePoint,
    /// bonded inhomogeneity
    pub bonded: Mat6,
    /// cavity (inhomogeneity of zero stiffness)
    pub cavity: Mat6,
}

impl PointMaps {
    /// Matrix stress at the point for the remote stress `remote`, Pa.
    pub fn matrix_stress(&self, remote: &[f64; 6], interface: Interface) -> [f64; 6] {
        let bonded = mandel::apply(&self.bonded, remote);
        let open =
            interface == Interface::Debonded && normal_traction(&bonded, self.point.normal) > 0.0;
        if open {
            mandel::apply(&self.cavity, remote)
        } else {
            bonded
        }
    }

    /// Interface contact pressure −n·σ·n of the bonded solution where it is compressive, 0
    /// where the interface is open (the quantity of seed 000 Fig. 3.69), Pa.
    pub fn contact_pressure(&self, remote: &[f64; 6]) -> f64 {
        let bonded = mandel::apply(&self.bonded, remote);
        (-normal_traction(&bonded, self.point.normal)).max(0.0)
    }
}
