//! The stress history of every fillet point over a revolution (theory §10.2): each contact
//! force of a load set goes to the stations of its pocket — bar forces split linearly between
//! the two bar stations by their axial position, land forces between the neighbouring land
//! stations by angle and between the rims by axial position — in the station's local frame,
//! and the unit cases are summed with the centrifugal case (ω²).

use crate::cage::{CageGeometry, STATIONS};
use crate::loads::{CageLoadExport, ContactKind, ContactLoad};
use crate::unit_stresses::{Stress, UnitStresses};
use std::f64::consts::PI;

/// A share of a contact force at one station of one pocket, in the station's local frame
/// `[radial, tangential, axial]`, N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StationLoad {
    /// index into [`STATIONS`]
    pub station: usize,
    pub pocket: usize,
    pub force: [f64; 3],
}

/// The force in the local frame at the angle `angle`.
fn local(force: [f64; 3], angle: f64) -> [f64; 3] {
    let (s, c) = angle.sin_cos();
    [
        c * force[0] + s * force[1],
        -s * force[0] + c * force[1],
        force[2],
    ]
}

/// Linear share `∈ [0, 1]` of the upper of two stations at `±half` for a load at `z`.
fn upper_share(z: f64, half: f64) -> f64 {
    ((z + half) / (2.0 * half)).clamp(0.0, 1.0)
}

/// The station loads of one contact force.
pub fn station_loads(cage: &CageGeometry, bar_z: f64, c: &ContactLoad) -> Vec<StationLoad> {
    let z = cage.pockets;
    let pocket = c.pocket % z;
    let scaled = |f: [f64; 3], w: f64| f.map(|v| v * w);
    match c.kind {
        ContactKind::Bar => {
            let f = local(c.force_n, cage.pocket_angle(pocket));
            let first = if c.location < 2 { 0 } else { 2 };
            let up = upper_share(c.point_m[2], bar_z);
            vec![
                StationLoad {
                    station: first,
                    pocket,
                    force: scaled(f, 1.0 - up),
                },
                StationLoad {
                    station: first + 1,
                    pocket,
                    force: scaled(f, up),
                },
            ]
        }
        ContactKind::PocketEnd => vec![StationLoad {
            station: 4 + c.location.min(1),
            pocket,
            force: local(c.force_n, cage.pocket_angle(pocket)),
        }],
        ContactKind::Land => {
            let half_pitch = PI / z as f64;
            let angle = c.point_m[1].atan2(c.point_m[0]).rem_euclid(2.0 * PI);
            let u = angle / half_pitch;
            let (h0, frac) = (u.floor() as usize, u - u.floor());
            let rim_z = 0.5 * (cage.pocket.axial + cage.rim_axial());
            let up = upper_share(c.point_m[2], rim_z);
            let mut out = Vec::with_capacity(4);
            for (h, w_angle) in [(h0, 1.0 - frac), (h0 + 1, frac)] {
                let h = h % (2 * z);
                let at_bar = h % 2 == 1;
                let f = local(c.force_n, h as f64 * half_pitch);
                for (rim, w_rim) in [(0, 1.0 - up), (1, up)] {
                    out.push(StationLoad {
                        station: 6 + 2 * rim + usize::from(at_bar),
                        pocket: h / 2,
                        force: scaled(f, w_angle * w_rim),
                    });
                }
            }
            out
        }
    }
}

/// The stress history at every fillet point: `histories[point][set]`, cylindrical components,
/// Pa.
pub fn stress_histories(unit: &UnitStresses, export: &CageLoadExport) -> Vec<Vec<Stress>> {
    let cage = &unit.cage;
    let points = crate::cage::FilletPoint::all(cage.pockets);
    let mut out = vec![Vec::with_capacity(export.sets.len()); points.len()];
    for set in &export.sets {
        let spin_sq = set.angular_velocity_rad_s[2].powi(2);
        let mut stress: Vec<Stress> = unit
            .per_unit_spin_squared
            .iter()
            .map(|s| s.map(|v| v * spin_sq))
            .collect();
        for contact in &set.contacts {
            for load in station_loads(cage, unit.bar_station_z, contact) {
                debug_assert!(load.station < STATIONS.len());
                for (p, point) in points.iter().enumerate() {
                    for (component, &f) in load.force.iter().enumerate() {
                        if f == 0.0 {
                            continue;
                        }
                        let u = unit.unit(*point, load.station, component, load.pocket);
                        for (s, v) in stress[p].iter_mut().zip(u) {
                            *s += f * v;
                        }
                    }
                }
            }
        }
        for (history, s) in out.iter_mut().zip(stress) {
            history.push(s);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cage() -> CageGeometry {
        crate::cage::tests::cage_2002834()
    }

    fn total(loads: &[StationLoad], cage: &CageGeometry) -> [f64; 3] {
        let mut sum = [0.0; 3];
        for l in loads {
            let angle = match STATIONS[l.station] {
                crate::cage::Station::Land { at_bar: true, .. } => {
                    cage.pocket_angle(l.pocket) + PI / cage.pockets as f64
                }
                _ => cage.pocket_angle(l.pocket),
            };
            let g = local(l.force, -angle);
            for i in 0..3 {
                sum[i] += g[i];
            }
        }
        sum
    }

    #[test]
    fn shares_keep_the_force() {
        let c = cage();
        let bar = ContactLoad {
            kind: ContactKind::Bar,
            pocket: 3,
            location: 2,
            force_n: [1.0, -40.0, 2.0],
            point_m: [0.0, 0.0, 1e-3],
        };
        let land = ContactLoad {
            kind: ContactKind::Land,
            pocket: 0,
            location: 1,
            force_n: [-300.0, 5.0, 0.0],
            point_m: [-0.08, -0.03, 5e-3],
        };
        for contact in [bar, land] {
            let loads = station_loads(&c, 4.4e-3, &contact);
            let sum = total(&loads, &c);
            for i in 0..3 {
                assert!((sum[i] - contact.force_n[i]).abs() < 1e-9, "{sum:?}");
            }
        }
    }
}
