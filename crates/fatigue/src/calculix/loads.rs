//! The unit load cases of the solid model (theory §10.4): the surface patch that carries a
//! station's unit force, the rigid-body inertia that balances it (inertia relief) and the
//! statically determinate 3-2-1 support.

use super::mesh::{Mesh, distance};
use super::{CalculixError, CalculixSettings};
use crate::cage::{CageGeometry, Station};
use std::f64::consts::PI;

/// Mass, centre of mass and inverse inertia tensor (about the centre) of the meshed cage.
#[derive(Debug, Clone)]
pub struct RigidBody {
    pub mass: f64,
    pub centre: [f64; 3],
    inertia_inverse: [[f64; 3]; 3],
}

impl RigidBody {
    /// From the nodal masses `masses` of `mesh`.
    pub fn of(mesh: &Mesh, masses: &[f64]) -> RigidBody {
        let mass: f64 = masses.iter().sum();
        let mut centre = [0.0; 3];
        for (m, x) in masses.iter().zip(&mesh.coords) {
            (0..3).for_each(|i| centre[i] += m * x[i] / mass);
        }
        let mut inertia = [[0.0; 3]; 3];
        for (m, x) in masses.iter().zip(&mesh.coords) {
            let d = sub(*x, centre);
            let d2 = dot(d, d);
            for i in 0..3 {
                for j in 0..3 {
                    let delta = if i == j { d2 } else { 0.0 };
                    inertia[i][j] += m * (delta - d[i] * d[j]);
                }
            }
        }
        RigidBody {
            mass,
            centre,
            inertia_inverse: inverse(inertia),
        }
    }

    /// Angular acceleration of the free cage under force `force` at `point`:
    /// `α = I⁻¹ ((p − c) × F)`, rad/s².
    pub fn angular_acceleration(&self, force: [f64; 3], point: [f64; 3]) -> [f64; 3] {
        let moment = cross(sub(point, self.centre), force);
        self.inertia_inverse.map(|row| dot(row, moment))
    }

    /// Inertial nodal load of a unit angular acceleration about axis `k` at a node of mass
    /// `m` at `x`: `−m e_k × (x − c)`, N per rad/s².
    pub fn angular_inertia_load(&self, k: usize, m: f64, x: [f64; 3]) -> [f64; 3] {
        let mut axis = [0.0; 3];
        axis[k] = 1.0;
        cross(axis, sub(x, self.centre)).map(|v| -m * v)
    }
}

/// Unit vectors `[radial, tangential, axial]` of the pocket-0 frame at `station`.
pub fn station_frame(station: Station, cage: &CageGeometry) -> [[f64; 3]; 3] {
    let angle = match station {
        Station::Land { at_bar: true, .. } => PI / cage.pockets as f64,
        _ => 0.0,
    };
    let (s, c) = angle.sin_cos();
    [[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]]
}

/// Distance of `x` from the surface a station lies on: the window flank (bar), the rim face
/// closing the window (pocket end) or the bore (land), m.
fn gap_to_station_surface(station: Station, cage: &CageGeometry, x: [f64; 3]) -> f64 {
    let point = station.point(cage, 0.0);
    match station {
        Station::Bar { .. } => (x[1] - point[1]).abs(),
        Station::PocketEnd { .. } => (x[2] - point[2]).abs(),
        Station::Land { .. } => (x[0].hypot(x[1]) - cage.inner_radius).abs(),
    }
}

/// Largest distance of a node from the surface it discretizes, m: on the bore, 1.5 × the
/// sagitta `h²/(8 r)` of an edge of the coarse size (mid-side nodes sit on the straight
/// chords); on the planes, round-off.
fn surface_tolerance(station: Station, cage: &CageGeometry, settings: &CalculixSettings) -> f64 {
    match station {
        Station::Land { .. } => 1.5 * settings.mesh_size.powi(2) / (8.0 * cage.inner_radius),
        _ => 1e-8 * cage.outer_radius,
    }
}

/// The boundary nodes on the station's surface that share its unit force: those within
/// `patch_radius` of the station point, or the `patch_min_nodes` nearest when fewer.
pub fn patch(
    mesh: &Mesh,
    boundary: &[bool],
    station: Station,
    cage: &CageGeometry,
    bar_station_z: f64,
    settings: &CalculixSettings,
) -> Result<Vec<usize>, CalculixError> {
    let point = station.point(cage, bar_station_z);
    let tolerance = surface_tolerance(station, cage, settings);
    let mut on_surface: Vec<(f64, usize)> = (0..mesh.coords.len())
        .filter(|&n| boundary[n])
        .filter(|&n| gap_to_station_surface(station, cage, mesh.coords[n]) < tolerance)
        .map(|n| (distance(mesh.coords[n], point), n))
        .collect();
    on_surface.sort_by(|a, b| a.0.total_cmp(&b.0));
    let within = on_surface
        .iter()
        .take_while(|(d, _)| *d <= settings.patch_radius)
        .count();
    let count = within.max(settings.patch_min_nodes);
    if on_surface.len() < count || on_surface[count - 1].0 > 0.25 * cage.width {
        return Err(CalculixError::Results(format!(
            "no surface nodes around station {station:?}"
        )));
    }
    Ok(on_surface[..count].iter().map(|(_, n)| *n).collect())
}

/// The 3-2-1 support: nodes nearest to the outside surface at mid-width under bars 0, Z/3
/// and 2Z/3, and the degree of freedom (1 = x, 2 = y) the second one holds in the plane.
pub fn supports(mesh: &Mesh, used: &[bool], cage: &CageGeometry) -> ([usize; 3], usize) {
    let node = |bar: usize| {
        let (s, c) = cage.bar_angle(bar).sin_cos();
        let target = [cage.outer_radius * c, cage.outer_radius * s, 0.0];
        mesh.nearest(target, (0..mesh.coords.len()).filter(|&n| used[n]))
            .expect("a mesh with elements has used nodes")
    };
    let nodes = [0, cage.pockets / 3, 2 * cage.pockets / 3].map(node);
    let d = sub(mesh.coords[nodes[1]], mesh.coords[nodes[0]]);
    let in_plane_dof = if d[0].abs() >= d[1].abs() { 2 } else { 1 };
    (nodes, in_plane_dof)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Inverse of a 3×3 matrix by cofactors.
fn inverse(m: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let cof = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    };
    let det = m[0][0] * cof(0, 0) + m[0][1] * cof(0, 1) + m[0][2] * cof(0, 2);
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = cof(j, i) / det;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_of_a_symmetric_matrix() {
        let m = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.2], [0.5, 0.2, 2.0]];
        let inv = inverse(m);
        for (i, row) in m.iter().enumerate() {
            for j in 0..3 {
                let p: f64 = row
                    .iter()
                    .zip(&inv)
                    .map(|(a, inv_row)| a * inv_row[j])
                    .sum();
                assert!((p - f64::from(u8::from(i == j))).abs() < 1e-12);
            }
        }
    }
}
