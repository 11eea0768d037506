//! Kinematics of a roller as its contacts see it.

use crate::vec3::V3;

/// Centre `c` (m), unit axis `a`, centre velocity `v` (m/s), angular velocity `w` (rad/s) and
/// orbital speed θ̇ (rad/s) of a roller, in the inertial frame: the input of its raceway
/// slices ([`crate::slice_kernel`]), roller ends ([`crate::ends`]) and cage bars.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RollerKinematics {
    pub c: V3,
    pub a: V3,
    pub v: V3,
    pub w: V3,
    pub orbit: f64,
}
