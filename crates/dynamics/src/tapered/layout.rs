//! State layout of the double-row tapered bearing: the rollers of row 0 then row 1 (the
//! cylindrical roller layout, [`crate::layout::roller`]), the two cages
//! ([`crate::layout::cage`]), the inner-ring assembly ([`crate::layout::inner_ring`]).

use crate::layout::{CAGE_DOF, INNER_DOF, ROLLER_DOF};

/// Index arithmetic of the tapered state vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TaperedLayout {
    /// rollers per row
    pub z: usize,
}

impl TaperedLayout {
    /// First index of roller `j` (0 ≤ j < 2z; row `j / z`).
    pub fn roller(&self, j: usize) -> usize {
        j * ROLLER_DOF
    }

    /// First index of the cage of row `k`.
    pub fn cage(&self, k: usize) -> usize {
        2 * self.z * ROLLER_DOF + k * CAGE_DOF
    }

    /// First index of the inner ring.
    pub fn inner(&self) -> usize {
        self.cage(2)
    }

    /// Length of the state vector.
    pub fn len(&self) -> usize {
        self.inner() + INNER_DOF
    }

    /// Whether the layout has no rollers.
    pub fn is_empty(&self) -> bool {
        self.z == 0
    }
}
