//! Records the cage loads of a dynamics run ([`CageLoadRecorder`], an output sink) and picks
//! the load sets of its last cage revolution: 180 sets 2° of cage rotation apart (SPEC §7.2),
//! each the output sample nearest to its angle — every set is a state the dynamics computed,
//! not an interpolation between two.

use crate::loads::{ContactKind, ContactLoad, LoadSet, RevolutionMaxima};
use rolldyn_dynamics::output::{OutputSink, PointForce, RevolutionSummary, Snapshot};
use std::collections::VecDeque;
use std::f64::consts::TAU;

/// Load sets per cage revolution (2° steps, seed 000 §2.5).
pub const SETS_PER_REVOLUTION: usize = 180;

/// The output step that gives at least `samples_per_set` samples per 2° of cage rotation at
/// the cage speed `cage_speed_rad_s`, s.
pub fn export_output_step(cage_speed_rad_s: f64, samples_per_set: f64) -> f64 {
    TAU / SETS_PER_REVOLUTION as f64 / cage_speed_rad_s.abs() / samples_per_set
}

/// One recorded sample: its cage angle (unwrapped, rad) and its loads in cage coordinates.
#[derive(Debug, Clone)]
struct Sample {
    angle: f64,
    set: LoadSet,
}

/// An output sink keeping the samples of the last cage revolution (and a little more) and the
/// largest contact forces of the revolutions it saw end.
#[derive(Debug, Default)]
pub struct CageLoadRecorder {
    samples: VecDeque<Sample>,
    maxima: Option<RevolutionMaxima>,
}

/// The frame of the cage: unit vectors `e_x` (through pocket 0), `e_y`, `e_z` (the cage axis)
/// and the centre.
struct CageFrame {
    axes: [[f64; 3]; 3],
    centre: [f64; 3],
}

impl CageFrame {
    fn new(axis: [f64; 3], angle: f64, centre: [f64; 3]) -> Self {
        let (s, c) = angle.sin_cos();
        let d = [c, s, 0.0];
        let along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
        let ex = [0, 1, 2].map(|i| d[i] - along * axis[i]);
        let n = (ex[0] * ex[0] + ex[1] * ex[1] + ex[2] * ex[2]).sqrt();
        let ex = ex.map(|v| v / n);
        let ey = [
            axis[1] * ex[2] - axis[2] * ex[1],
            axis[2] * ex[0] - axis[0] * ex[2],
            axis[0] * ex[1] - axis[1] * ex[0],
        ];
        Self {
            axes: [ex, ey, axis],
            centre,
        }
    }

    /// Components of a vector in the cage frame.
    fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        self.axes.map(|e| e[0] * v[0] + e[1] * v[1] + e[2] * v[2])
    }

    /// Cage coordinates of a point.
    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        self.vector([0, 1, 2].map(|i| p[i] - self.centre[i]))
    }

    fn load(
        &self,
        kind: ContactKind,
        pocket: usize,
        location: usize,
        f: &PointForce,
    ) -> ContactLoad {
        ContactLoad {
            kind,
            pocket,
            location,
            force_n: self.vector(f.force_n),
            point_m: self.point(f.point_m),
        }
    }
}

fn loaded(f: &PointForce) -> bool {
    f.force_n.iter().any(|&x| x != 0.0)
}

/// The loads of a snapshot in cage coordinates.
fn load_set(s: &Snapshot) -> LoadSet {
    let cl = &s.cage_loads;
    let frame = CageFrame::new(cl.axis, s.cage_angle_rad, s.cage_center_m);
    let mut contacts = Vec::new();
    for (j, pocket) in cl.pockets.iter().enumerate() {
        for (k, f) in pocket.bar.iter().enumerate().filter(|(_, f)| loaded(f)) {
            contacts.push(frame.load(ContactKind::Bar, j, k, f));
        }
        for (k, f) in pocket.end.iter().enumerate().filter(|(_, f)| loaded(f)) {
            contacts.push(frame.load(ContactKind::PocketEnd, j, k, f));
        }
    }
    let z = cl.pockets.len().max(1);
    for (k, f) in cl.land.iter().enumerate().filter(|(_, f)| loaded(f)) {
        let mut load = frame.load(ContactKind::Land, 0, k, f);
        let angle = load.point_m[1].atan2(load.point_m[0]).rem_euclid(TAU);
        load.pocket = (angle / TAU * z as f64).round() as usize % z;
        contacts.push(load);
    }
    LoadSet {
        cage_angle_deg: 0.0,
        time_s: s.time_s,
        acceleration_m_s2: frame.vector(cl.acceleration_m_s2),
        angular_velocity_rad_s: frame.vector(cl.angular_velocity_rad_s),
        angular_acceleration_rad_s2: frame.vector(cl.angular_acceleration_rad_s2),
        contacts,
    }
}

impl OutputSink for CageLoadRecorder {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        let angle = s.cage_angle_rad;
        // keep a little more than one revolution
        while let Some(first) = self.samples.front() {
            if (angle - first.angle).abs() > 1.05 * TAU {
                self.samples.pop_front();
            } else {
                break;
            }
        }
        self.samples.push_back(Sample {
            angle,
            set: load_set(s),
        });
    }

    fn revolution(&mut self, v: &RevolutionSummary) {
        let seen = RevolutionMaxima {
            max_cage_land_force_n: v.max_cage_land_force_n,
            max_roller_cage_force_n: v.max_roller_cage_force_n,
            max_roller_raceway_force_n: v
                .max_inner_contact_force_n
                .max(v.max_outer_contact_force_n),
        };
        self.maxima = Some(match self.maxima {
            None => seen,
            Some(m) => RevolutionMaxima {
                max_cage_land_force_n: m.max_cage_land_force_n.max(seen.max_cage_land_force_n),
                max_roller_cage_force_n: m
                    .max_roller_cage_force_n
                    .max(seen.max_roller_cage_force_n),
                max_roller_raceway_force_n: m
                    .max_roller_raceway_force_n
                    .max(seen.max_roller_raceway_force_n),
            },
        });
    }
}

impl CageLoadRecorder {
    /// The largest contact forces of the revolutions that ended while recording (zeros when
    /// none did: then the recorded samples' own figures are the export's).
    pub fn maxima(&self) -> RevolutionMaxima {
        self.maxima.unwrap_or(RevolutionMaxima {
            max_cage_land_force_n: 0.0,
            max_roller_cage_force_n: 0.0,
            max_roller_raceway_force_n: 0.0,
        })
    }

    /// The 180 load sets of the last cage revolution, or why there are none: the run covered
    /// less than a revolution, or its samples are further apart than 2°.
    pub fn last_revolution(&self) -> Result<Vec<LoadSet>, String> {
        let (Some(first), Some(last)) = (self.samples.front(), self.samples.back()) else {
            return Err("no output samples were recorded".into());
        };
        let sweep = last.angle - first.angle;
        if sweep.abs() < TAU {
            return Err(format!(
                "the recorded samples cover {:.1}° of cage rotation, less than a revolution",
                sweep.abs().to_degrees()
            ));
        }
        let direction = sweep.signum();
        let step = TAU / SETS_PER_REVOLUTION as f64;
        let widest = self
            .samples
            .iter()
            .zip(self.samples.iter().skip(1))
            .map(|(a, b)| (b.angle - a.angle).abs())
            .fold(0.0, f64::max);
        if widest > step {
            return Err(format!(
                "output samples up to {:.2}° of cage rotation apart, more than the 2° of a load set",
                widest.to_degrees()
            ));
        }
        let start = last.angle - direction * TAU;
        let mut sets = Vec::with_capacity(SETS_PER_REVOLUTION);
        let mut i = 0;
        for k in 0..SETS_PER_REVOLUTION {
            let target = direction * (start + direction * k as f64 * step);
            let along = |s: &Sample| direction * s.angle;
            while i + 1 < self.samples.len()
                && (along(&self.samples[i + 1]) - target).abs()
                    <= (along(&self.samples[i]) - target).abs()
            {
                i += 1;
            }
            let sample = &self.samples[i];
            let mut set = sample.set.clone();
            set.cage_angle_deg = (direction * (sample.angle - start)).to_degrees();
            sets.push(set);
        }
        Ok(sets)
    }
}
