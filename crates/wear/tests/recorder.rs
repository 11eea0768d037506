//! The direct and averaged methods on hand-made output steps: one roller on the inner raceway,
//! its bar and a rib, with every input known, against eq. (45) of docs/theory.md §8.6.

use rolldyn_dynamics::EndContactRegime;
use rolldyn_dynamics::V3;
use rolldyn_dynamics::output::{CageLoads, ContactSnapshot, OutputSink, RollerSnapshot, Snapshot};
use rolldyn_geometry::BearingModel;
use rolldyn_wear::bearing_data::WearData;
use rolldyn_wear::recorder::WearRecorder;
use rolldyn_wear::wear_line::slice_patch;
use rolldyn_wear::{Surface, WearMethod, WearSettings};
use std::f64::consts::PI;

fn bearing() -> (
    rolldyn_geometry::CylindricalRollerBearing,
    rolldyn_lubrication::Lubricant,
) {
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
    let BearingModel::Cylindrical(b) = model.bearing else {
        panic!()
    };
    (b, model.lubrication.unwrap().oil)
}

/// Output-step inputs of all rollers: roller 0 loaded on the inner raceway over its middle
/// slices, every other contact idle.
struct Step {
    z: usize,
    slices: usize,
    zeros: Vec<f64>,
    slice_forces: Vec<f64>,
    inner_force: Vec<f64>,
    sliding: Vec<f64>,
    lambda: Vec<f64>,
    nan: Vec<f64>,
    regime: Vec<EndContactRegime>,
}

impl Step {
    fn new(z: usize, slices: usize, slice_force: f64) -> Self {
        let mut slice_forces = vec![0.0; z * slices];
        slice_forces[3..slices - 3].fill(slice_force);
        let mut inner_force = vec![0.0; z];
        inner_force[0] = slice_forces.iter().sum();
        let mut sliding = vec![0.0; z];
        sliding[0] = 0.5;
        let mut lambda = vec![f64::NAN; z];
        lambda[0] = 0.75;
        Self {
            z,
            slices,
            zeros: vec![0.0; z * slices],
            slice_forces,
            inner_force,
            sliding,
            lambda,
            nan: vec![f64::NAN; z],
            regime: vec![EndContactRegime::None; z],
        }
    }

    fn snapshot(&self, t: f64) -> Snapshot<'_> {
        let zero = &self.zeros[..self.z];
        let idle = ContactSnapshot {
            force_n: zero,
            sliding_speed_m_s: zero,
            rolling_speed_m_s: zero,
            slide_to_roll: zero,
            film_thickness_m: &self.nan,
            lambda: &self.nan,
            traction_coefficient: zero,
            friction_power_w: zero,
            slice_force_n: &self.zeros,
        };
        let inner = ContactSnapshot {
            force_n: &self.inner_force,
            sliding_speed_m_s: &self.sliding,
            lambda: &self.lambda,
            slice_force_n: &self.slice_forces,
            ..idle
        };
        assert_eq!(self.slice_forces.len(), self.z * self.slices);
        Snapshot {
            time_s: t,
            inner_ring_speed_rad_s: 0.0,
            outer_ring_speed_rad_s: 0.0,
            inner_ring_angle_rad: 0.0,
            outer_ring_angle_rad: 0.0,
            inner_ring_center_m: V3::default(),
            cage_center_m: V3::default(),
            cage_angle_rad: 0.0,
            cage_speed_rad_s: 0.0,
            epicyclic_cage_speed_rad_s: 0.0,
            cage_slip: 0.0,
            cage_land_force_n: 0.0,
            cage_land_power_w: 0.0,
            rollers: RollerSnapshot {
                azimuth_rad: zero,
                radius_m: zero,
                axial_m: zero,
                orbital_speed_rad_s: zero,
                spin_speed_rad_s: zero,
                yaw_rad: zero,
                pitch_rad: zero,
                inner,
                outer: idle,
                cage_bar_force_n: zero,
                cage_bar_power_w: zero,
                cage_bar_sliding_speed_m_s: zero,
                rib_force_n: zero,
                rib_sliding_speed_m_s: zero,
                rib_edge_distance_m: &self.nan,
                rib_reduced_radius_m: &self.nan,
                rib_contact_radius_m: &self.nan,
                rib_contact_ring_radius_m: &self.nan,
                rib_friction_coefficient: zero,
                rib_power_w: zero,
                rib_regime: &self.regime,
                pocket_face_force_n: zero,
                pocket_face_power_w: zero,
            },
            cage_loads: CageLoads {
                axis: [0.0, 0.0, 1.0],
                acceleration_m_s2: V3::default(),
                angular_velocity_rad_s: V3::default(),
                angular_acceleration_rad_s2: V3::default(),
                pockets: &[],
                land: Default::default(),
            },
        }
    }
}

#[test]
fn direct_rates_follow_archard_with_the_exposure_of_each_surface() {
    let (b, oil) = bearing();
    let settings = WearSettings::default();
    let data = WearData::new(&b, &oil, 373.15, &settings).unwrap();
    let step = Step::new(b.roller_count, data.lines(), 100.0);
    let mut recorder = WearRecorder::new(&data, &settings);
    for i in 0..50 {
        recorder.sample(i as f64 * settings.output_step_s, &step.snapshot(0.0));
    }
    let rates = recorder.rates().unwrap();
    // eq. (45) on a middle line: k p̄ v / H × 2b / ρ, the roller in every step (mean over z)
    let s = 4;
    let patch = slice_patch(
        100.0,
        data.slice_lengths_m[s],
        data.inner.reduced_radius_m,
        data.inner.reduced_modulus_pa,
    );
    let k = settings.coefficient.for_contact(0.75, false);
    let kpv = k * patch.mean_pressure_pa * 0.5;
    let roller = kpv / data.roller_hardness_pa * 2.0 * patch.half_width_m
        / (PI * data.roller_diameter_m)
        / b.roller_count as f64;
    assert!(
        (rates.roller[s] / roller - 1.0).abs() < 1e-12,
        "{} vs {roller}",
        rates.roller[s]
    );
    // the raceway: the contact sits in bin 0 (azimuth 0, ring at 0) all the time
    let arc = data.inner.raceway_radius_m * 2.0 * PI / settings.angle_bins as f64;
    let ring = kpv / data.inner.ring_hardness_pa * 2.0 * patch.half_width_m / arc;
    assert!((rates.inner_map[s * settings.angle_bins] / ring - 1.0).abs() < 1e-12);
    assert_eq!(rates.inner_map[s * settings.angle_bins + 1], 0.0);
    assert_eq!(rates.max(Surface::CageBar), 0.0);
    assert_eq!(rates.max(Surface::Rib), 0.0);
    // a constant force: the averaged method gives the direct rates
    let averaged = WearSettings {
        method: WearMethod::Averaged,
        ..settings.clone()
    };
    let mut recorder = WearRecorder::new(&data, &averaged);
    for i in 0..50 {
        recorder.sample(i as f64 * settings.output_step_s, &step.snapshot(0.0));
    }
    let a = recorder.rates().unwrap();
    assert!((a.roller[s] / rates.roller[s] - 1.0).abs() < 1e-9);
    assert!((a.inner_map[s * settings.angle_bins] / ring - 1.0).abs() < 1e-9);
    assert!((a.diagnostics[0].equivalent_force_n - step.inner_force[0]).abs() < 1e-9);
    assert!((a.diagnostics[0].contact_fraction - 1.0 / b.roller_count as f64).abs() < 1e-12);
}
