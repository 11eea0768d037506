//! Rigid motions of the (r, z) half-plane of one roller: the in-plane part of the inner-ring
//! displacement (Harris & Kotzalas, Advanced Concepts, ch. 1: the ring displacements projected
//! on the azimuth of the roller).

use rolldyn_geometry::Rz;

/// `v` turned by `angle` in the half-plane: `(r cos a + z sin a, −r sin a + z cos a)`, whose
/// derivative at 0 is the small rotation `(r, z) ↦ (z, −r)` of a tilt (see [`PlaneMotion`]).
pub(crate) fn rotated(v: Rz, angle: f64) -> Rz {
    let (s, c) = angle.sin_cos();
    Rz::new(v.r * c + v.z * s, -v.r * s + v.z * c)
}

/// 2-D cross product `a_r b_z − a_z b_r`.
pub(crate) fn cross(a: Rz, b: Rz) -> f64 {
    a.r * b.z - a.z * b.r
}

/// A straight line of the half-plane: a point and the unit normal toward the roller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Line {
    pub point: Rz,
    pub normal: Rz,
}

impl Line {
    /// Signed distance of `p` from the line, positive on the roller's side [m].
    pub fn distance(&self, p: Rz) -> f64 {
        self.normal.dot(p - self.point)
    }
}

/// The inner ring's motion in the axial plane at azimuth ψ: a point `P` of the ring moves to
/// `rotated(P, γ) + a`. With the ring translation (δx, δy, δz) and tilt (θx, θy), the 3-D
/// small rotation θ × P has the in-plane part `γ (z, −r)` with `γ = −θx sin ψ + θy cos ψ`
/// (the out-of-plane part is neglected, as in Jones' and Harris' analyses).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlaneMotion {
    pub shift: Rz,
    pub angle: f64,
}

impl PlaneMotion {
    /// The motion at azimuth `psi` of the ring displacement `x = (δx, δy, δz, θx, θy)`.
    pub fn at(x: &[f64; 5], psi: f64) -> Self {
        let (s, c) = psi.sin_cos();
        Self {
            shift: Rz::new(x[0] * c + x[1] * s, x[2]),
            angle: -x[3] * s + x[4] * c,
        }
    }

    /// A bearing-frame point seen from the ring: the inverse motion.
    pub fn to_ring(self, p: Rz) -> Rz {
        rotated(p - self.shift, -self.angle)
    }

    /// A bearing-frame line seen from the ring.
    pub fn line_to_ring(self, l: &Line) -> Line {
        Line {
            point: self.to_ring(l.point),
            normal: rotated(l.normal, -self.angle),
        }
    }

    /// A ring-frame force `f` with moment `m` about the ring-frame origin (`z F_r − r F_z`,
    /// its vector along the circumferential direction e_t) as bearing-frame force and moment
    /// about the bearing origin.
    pub fn wrench_to_bearing(self, f: Rz, m: f64) -> (Rz, f64) {
        let force = rotated(f, self.angle);
        (force, m - cross(self.shift, force))
    }
}
