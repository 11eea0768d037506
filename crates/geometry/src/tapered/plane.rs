//! Points and directions in the (r, z) half-plane of a bearing: r = distance from the bearing
//! axis, z = position along it.

use std::ops::{Add, Mul, Neg, Sub};

/// A point or vector in the (r, z) half-plane [m or dimensionless for directions].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Rz {
    pub r: f64,
    pub z: f64,
}

impl Rz {
    pub const fn new(r: f64, z: f64) -> Self {
        Self { r, z }
    }

    pub fn dot(self, other: Self) -> f64 {
        self.r * other.r + self.z * other.z
    }

    pub fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// Unit vector at `angle` [rad] from the bearing axis (+z) toward +r.
    pub fn at_angle_from_axis(angle: f64) -> Self {
        Self::new(angle.sin(), angle.cos())
    }

    /// This direction turned by +90° from +z toward +r: for a direction along +z it gives +r.
    pub fn perpendicular(self) -> Self {
        Self::new(self.z, -self.r)
    }

    /// Distance of this point from the line through `point` with unit `direction`.
    pub fn distance_to_line(self, point: Self, direction: Self) -> f64 {
        (self - point).dot(direction.perpendicular()).abs()
    }
}

impl Add for Rz {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::new(self.r + o.r, self.z + o.z)
    }
}

impl Sub for Rz {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::new(self.r - o.r, self.z - o.z)
    }
}

impl Mul<Rz> for f64 {
    type Output = Rz;
    fn mul(self, v: Rz) -> Rz {
        Rz::new(self * v.r, self * v.z)
    }
}

impl Neg for Rz {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.r, -self.z)
    }
}

/// Where the line through `point` with direction `direction` crosses the bearing axis (r = 0):
/// its z coordinate, or `None` for a line parallel to the axis.
pub fn axis_crossing(point: Rz, direction: Rz) -> Option<f64> {
    (direction.r != 0.0).then(|| point.z - point.r * direction.z / direction.r)
}
