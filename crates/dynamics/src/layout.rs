//! Layout of the flat state vector (see the crate docs, "Coordinates").
//!
//! * roller `j` (12 values from `12 j`): `θ, r, z, a_x, a_y, a_z, θ̇, ṙ, ż, L_x, L_y, L_z`
//! * cage (13 values): `x, y, z, φ, a_x, a_y, a_z, v_x, v_y, v_z, L_x, L_y, L_z`
//! * inner ring (6 values): `x, y, z, v_x, v_y, v_z`

/// Values per roller.
pub const ROLLER_DOF: usize = 12;
/// Values of the cage.
pub const CAGE_DOF: usize = 13;
/// Values of the inner ring.
pub const INNER_DOF: usize = 6;

/// Offsets of a roller's components from its first index ([`Layout::roller`]).
pub mod roller {
    /// azimuth θ of the centre, rad
    pub const AZIMUTH: usize = 0;
    /// radius r of the centre, m
    pub const RADIUS: usize = 1;
    /// axial position z of the centre, m
    pub const AXIAL: usize = 2;
    /// axis a (3 values, unit up to integration error)
    pub const AXIS: usize = 3;
    /// orbital speed θ̇, rad/s
    pub const ORBITAL_SPEED: usize = 6;
    /// radial velocity ṙ, m/s
    pub const RADIAL_VELOCITY: usize = 7;
    /// axial velocity ż, m/s
    pub const AXIAL_VELOCITY: usize = 8;
    /// angular momentum L (3 values), inertial frame, N·m·s
    pub const MOMENTUM: usize = 9;
}

/// Offsets of the cage's components from its first index ([`Layout::cage`]).
pub mod cage {
    /// centre (3 values), m
    pub const CENTRE: usize = 0;
    /// angle φ about its axis, rad
    pub const ANGLE: usize = 3;
    /// axis (3 values, unit up to integration error)
    pub const AXIS: usize = 4;
    /// velocity of the centre (3 values), m/s
    pub const VELOCITY: usize = 7;
    /// angular momentum L (3 values), inertial frame, N·m·s
    pub const MOMENTUM: usize = 10;
}

/// Offsets of the inner ring's components from its first index ([`Layout::inner`]).
pub mod inner_ring {
    /// centre (3 values), m
    pub const CENTRE: usize = 0;
    /// velocity of the centre (3 values), m/s
    pub const VELOCITY: usize = 3;
}

/// The 3-vector of `y` from index `i`.
#[inline]
pub(crate) fn read3(y: &[f64], i: usize) -> [f64; 3] {
    [y[i], y[i + 1], y[i + 2]]
}

/// Writes the 3-vector `v` into `y` from index `i`.
#[inline]
pub(crate) fn write3(y: &mut [f64], i: usize, v: [f64; 3]) {
    y[i..i + 3].copy_from_slice(&v);
}

/// Index arithmetic of the state vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// number of rollers
    pub rollers: usize,
}

/// Names of a roller's state components, in layout order.
const ROLLER_NAMES: [&str; ROLLER_DOF] = [
    "azimuth θ",
    "radius r",
    "axial position z",
    "axis a_x",
    "axis a_y",
    "axis a_z",
    "orbital speed θ̇",
    "radial velocity ṙ",
    "axial velocity ż",
    "angular momentum L_x",
    "angular momentum L_y",
    "angular momentum L_z (spin)",
];
/// Names of the cage's state components.
const CAGE_NAMES: [&str; CAGE_DOF] = [
    "centre x",
    "centre y",
    "centre z",
    "angle φ",
    "axis a_x",
    "axis a_y",
    "axis a_z",
    "velocity v_x",
    "velocity v_y",
    "velocity v_z",
    "angular momentum L_x",
    "angular momentum L_y",
    "angular momentum L_z (spin)",
];
/// Names of the inner ring's state components.
const INNER_NAMES: [&str; INNER_DOF] = [
    "centre x",
    "centre y",
    "centre z",
    "velocity v_x",
    "velocity v_y",
    "velocity v_z",
];

impl Layout {
    /// Length of the state vector.
    pub fn len(&self) -> usize {
        ROLLER_DOF * self.rollers + CAGE_DOF + INNER_DOF
    }
    /// Never empty.
    pub fn is_empty(&self) -> bool {
        false
    }
    /// First index of roller `j`.
    #[inline]
    pub fn roller(&self, j: usize) -> usize {
        ROLLER_DOF * j
    }
    /// First index of the cage.
    #[inline]
    pub fn cage(&self) -> usize {
        ROLLER_DOF * self.rollers
    }
    /// First index of the inner ring.
    #[inline]
    pub fn inner(&self) -> usize {
        ROLLER_DOF * self.rollers + CAGE_DOF
    }

    /// Human-readable name of state component `i` (diagnoses).
    pub fn describe(&self, i: usize) -> String {
        match self.kind(i) {
            (_, Some(roller)) => format!("roller {roller} {}", ROLLER_NAMES[i % ROLLER_DOF]),
            (kind, None) => kind,
        }
    }

    /// Component `i` without the roller number ("roller radius r" for every roller's r), and
    /// the roller number if it belongs to a roller.
    pub fn kind(&self, i: usize) -> (String, Option<usize>) {
        if i < self.cage() {
            (
                format!("roller {}", ROLLER_NAMES[i % ROLLER_DOF]),
                Some(i / ROLLER_DOF),
            )
        } else if i < self.inner() {
            (format!("cage {}", CAGE_NAMES[i - self.cage()]), None)
        } else if i < self.len() {
            (
                format!("inner ring {}", INNER_NAMES[i - self.inner()]),
                None,
            )
        } else {
            (format!("state component {i}"), None)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_with_and_without_the_roller_number() {
        let l = Layout { rollers: 2 };
        assert_eq!(l.describe(13), "roller 1 radius r");
        assert_eq!(l.kind(13), ("roller radius r".to_string(), Some(1)));
        assert_eq!(l.describe(l.cage() + 3), "cage angle φ");
        assert_eq!(l.kind(l.inner()), ("inner ring centre x".to_string(), None));
        assert_eq!(l.describe(l.len()), format!("state component {}", l.len()));
    }
}
