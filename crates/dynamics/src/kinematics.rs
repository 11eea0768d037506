//! Kinematics of a roller as its contacts see it.

use crate::vec3::{V3, axpy, cross, dot, norm, scale};

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

/// The sliding velocity of a roller line contact split along the roller (SPEC §3.5: "the
/// difference of surface speeds along the rolling direction, plus the axial component from
/// skew"), m/s. Signed along the contact's own tangent axes, so that the components of the
/// slices of one contact can be averaged; `rolling² + axial² = |v_t|²`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct SlidingSplit {
    /// along the rolling direction e_ax × n (circumferential)
    pub rolling: f64,
    /// along e_ax, the roller axis projected on the tangent plane (from skew)
    pub axial: f64,
}

/// Splits the tangential sliding velocity `v_t` (⟂ `n`) of a contact with unit normal `n` on a
/// roller of unit axis `a` into [`SlidingSplit`]. A roller axis along the normal (no line
/// contact) leaves all of it in `rolling`.
#[inline]
pub(crate) fn split_sliding(n: V3, a: V3, v_t: V3) -> SlidingSplit {
    let a_t = axpy(a, -dot(a, n), n);
    let len = norm(a_t);
    if len == 0.0 {
        return SlidingSplit {
            rolling: norm(v_t),
            axial: 0.0,
        };
    }
    let e_ax = scale(a_t, 1.0 / len);
    SlidingSplit {
        rolling: dot(v_t, cross(e_ax, n)),
        axial: dot(v_t, e_ax),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A skewed roller on a raceway: the sliding velocity's components along the rolling
    /// direction and along the (tilted) axis add up in squares to its magnitude.
    #[test]
    fn components_add_up_in_squares() {
        let n = [0.0, -1.0, 0.0];
        let skew = 2e-3_f64;
        let a = [skew.sin(), 0.05, skew.cos()];
        let a = scale(a, 1.0 / norm(a));
        let v_t = [0.3, 0.0, -0.04];
        let s = split_sliding(n, a, v_t);
        let v2 = dot(v_t, v_t);
        assert!((s.rolling * s.rolling + s.axial * s.axial - v2).abs() < 1e-15 * v2);
        assert!((s.axial - (0.3 * skew.sin() - 0.04 * skew.cos())).abs() < 1e-12);
        assert!(s.rolling.abs() > 0.29);
    }
}
