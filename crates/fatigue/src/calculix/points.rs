//! Where the solid model reads the fillet stresses (theory §10.4) and their conversion to
//! cylindrical components.

use super::mesh::Mesh;
use crate::cage::{CageGeometry, FilletPoint, PocketSide};
use crate::unit_stresses::Stress;
use std::f64::consts::FRAC_1_SQRT_2;

/// The point of the fillet arc nearest to the sharp corner the fillet rounds, on the outside
/// or bore surface of `point`: the corner moved by `f (1 − 1/√2)` along the flank and along
/// the rim face towards the window centre (the arc's mid-point), m.
pub fn fillet_arc_midpoint(point: FilletPoint, cage: &CageGeometry) -> [f64; 3] {
    let [x, y, z] = point.corner(cage);
    let inset = cage.fillet_radius() * (1.0 - FRAC_1_SQRT_2);
    let pocket = cage.pocket_angle(match point.side {
        PocketSide::Minus => point.bar,
        PocketSide::Plus => (point.bar + 1) % cage.pockets,
    });
    let (s, c) = pocket.sin_cos();
    let across = -x * s + y * c;
    let across = across - across.signum() * inset;
    let r = x.hypot(y);
    let along = (r * r - across * across).sqrt();
    [
        along * c - across * s,
        along * s + across * c,
        z - z.signum() * inset,
    ]
}

/// The mesh node that represents each fillet point ([`FilletPoint::all`] order): the node
/// nearest to [`fillet_arc_midpoint`], with its distance from it, m.
pub fn evaluation_nodes(mesh: &Mesh, used: &[bool], cage: &CageGeometry) -> Vec<(usize, f64)> {
    FilletPoint::all(cage.pockets)
        .into_iter()
        .map(|p| {
            let target = fillet_arc_midpoint(p, cage);
            let n = mesh
                .nearest(target, (0..mesh.coords.len()).filter(|&n| used[n]))
                .expect("a mesh with elements has used nodes");
            (n, super::mesh::distance(mesh.coords[n], target))
        })
        .collect()
}

/// Cartesian stress `[xx, yy, zz, xy, yz, zx]` at `position` in cylindrical components
/// `[rr, θθ, zz, rθ, θz, zr]` (rotation by the node's polar angle).
pub fn to_cylindrical(s: [f64; 6], position: [f64; 3]) -> Stress {
    let [xx, yy, zz, xy, yz, zx] = s;
    let theta = position[1].atan2(position[0]);
    let (sn, cs) = theta.sin_cos();
    [
        cs * cs * xx + sn * sn * yy + 2.0 * cs * sn * xy,
        sn * sn * xx + cs * cs * yy - 2.0 * cs * sn * xy,
        zz,
        cs * sn * (yy - xx) + (cs * cs - sn * sn) * xy,
        cs * yz - sn * zx,
        cs * zx + sn * yz,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hoop_stress_on_the_y_axis_is_the_cartesian_xx() {
        let s = to_cylindrical([5.0, 2.0, 1.0, 0.0, 3.0, 0.0], [0.0, 1.0, 0.0]);
        let expected = [2.0, 5.0, 1.0, 0.0, 0.0, 3.0];
        s.iter()
            .zip(expected)
            .for_each(|(a, b)| assert!((a - b).abs() < 1e-12));
    }

    #[test]
    fn the_arc_midpoint_lies_on_the_fillet_and_the_surface() {
        let cage = crate::calculix::tests::small_cage();
        let f = cage.fillet_radius();
        for p in FilletPoint::all(cage.pockets) {
            let m = fillet_arc_midpoint(p, &cage);
            let r = match p.face {
                crate::cage::Face::Outer => cage.outer_radius,
                crate::cage::Face::Inner => cage.inner_radius,
            };
            assert!((m[0].hypot(m[1]) - r).abs() < 1e-12);
            let pocket = match p.side {
                PocketSide::Minus => p.bar,
                PocketSide::Plus => (p.bar + 1) % cage.pockets,
            };
            let (s, c) = cage.pocket_angle(pocket).sin_cos();
            let across = -m[0] * s + m[1] * c;
            let half = cage.window_edge_on(r)[1];
            let from_axis =
                (across.abs() - (half - f)).hypot(m[2].abs() - (0.5 * cage.pocket.axial - f));
            assert!((from_axis - f).abs() < 1e-12);
        }
    }
}
