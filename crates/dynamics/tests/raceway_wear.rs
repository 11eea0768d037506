//! A raceway wear map read at each roller's angle on the ring (issue 24 item 5), and the
//! snapshot fields the wear recorder reads.

mod common;
use common::*;
use rolldyn_dynamics::*;
use rolldyn_geometry::{CylindricalRollerBearing, RacewayWearMap};
use std::f64::consts::TAU;

/// The last sample's inner-raceway forces (per roller and per slice), roller azimuths and ring
/// angle.
#[derive(Default)]
struct Last {
    force: Vec<f64>,
    slice_force: Vec<f64>,
    azimuth: Vec<f64>,
    inner_angle: f64,
}

impl OutputSink for Last {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        self.force = s.rollers.inner.force_n.to_vec();
        self.slice_force = s.rollers.inner.slice_force_n.to_vec();
        self.azimuth = s.rollers.azimuth_rad.to_vec();
        self.inner_angle = s.inner_ring_angle_rad;
    }
}

/// 36 angle bins over the ring, `depth` deep within 30° of `centre_rad`, 0 elsewhere, uniform
/// along the raceway.
fn sector_map(centre_rad: f64, depth: f64) -> RacewayWearMap {
    let bins = 36;
    let depths: Vec<f64> = (0..bins)
        .map(|k| {
            let psi = (k as f64 + 0.5) * TAU / bins as f64;
            let off = (psi - centre_rad + 0.5 * TAU).rem_euclid(TAU) - 0.5 * TAU;
            if off.abs() < 30f64.to_radians() {
                depth
            } else {
                0.0
            }
        })
        .collect();
    RacewayWearMap::new(vec![0.0], bins, depths).unwrap()
}

/// The sample at the start of a run of `b` at 6371 rpm under 2 kN (load toward −y).
fn sample_at_start(b: &CylindricalRollerBearing) -> Last {
    let cond = OperatingConditions::new(rpm(6371.0), 2000.0);
    let params = ContactParameters::for_bearing(b);
    let traction = RacewayTraction::same(pao());
    let mut sim = Simulation::new(b, cond, params, DynamicsSettings::default(), traction).unwrap();
    let mut last = Last::default();
    sim.sample_now(&mut last);
    last
}

#[test]
fn a_worn_sector_of_the_inner_ring_unloads_the_roller_over_it() {
    let unworn = b2002834(10);
    let mut worn = unworn.clone();
    // at t = 0 the ring frame is the bearing frame: the sector under the load (−y, 270°)
    worn.inner_ring.raceway_wear = Some(sector_map(0.75 * TAU, 2e-6));
    let (a, b) = (sample_at_start(&unworn), sample_at_start(&worn));
    let bottom = (0..a.force.len())
        .max_by(|&i, &j| a.force[i].total_cmp(&a.force[j]))
        .unwrap();
    assert!(
        b.force[bottom] < 0.9 * a.force[bottom],
        "{} N worn vs {} N unworn",
        b.force[bottom],
        a.force[bottom]
    );
    // a loaded roller outside the sector keeps its force within a small share
    let outside = (0..a.force.len()).find(|&j| {
        let off = (a.azimuth[j] - 0.75 * TAU + 0.5 * TAU).rem_euclid(TAU) - 0.5 * TAU;
        off.abs() > 45f64.to_radians() && a.force[j] > 0.0
    });
    if let Some(j) = outside {
        assert!(
            b.force[j] >= a.force[j],
            "{j}: {} vs {}",
            b.force[j],
            a.force[j]
        );
    }
    assert_eq!(a.inner_angle, 0.0);
}

#[test]
fn slice_forces_add_up_to_the_roller_force() {
    let last = sample_at_start(&b2002834(10));
    let slices = last.slice_force.len() / last.force.len();
    assert_eq!(slices, 10);
    for (j, &q) in last.force.iter().enumerate() {
        let sum: f64 = last.slice_force[j * slices..(j + 1) * slices].iter().sum();
        assert!((sum - q).abs() <= 1e-9 * q.max(1.0), "{j}: {sum} vs {q}");
    }
    assert!(last.force.iter().any(|&q| q > 0.0));
}

/// Every sample of a short run: the ring angles are ∫ω dt, the bar sliding speed is 0 exactly
/// without bar force, and the rib fields are NaN exactly without rib force (otherwise the
/// contact lies on the roller end and on the rib face).
#[test]
fn the_wear_fields_of_the_snapshot_are_consistent() {
    struct Check {
        w: f64,
        rw: f64,
        samples: usize,
        rib_contacts: usize,
    }
    impl OutputSink for Check {
        fn sample(&mut self, t: f64, s: &Snapshot) {
            self.samples += 1;
            assert!((s.inner_ring_angle_rad - self.w * t).abs() < 1e-12);
            assert_eq!(s.outer_ring_angle_rad, 0.0);
            let r = &s.rollers;
            for j in 0..r.cage_bar_force_n.len() {
                let v = r.cage_bar_sliding_speed_m_s[j];
                assert!(
                    v >= 0.0 && (r.cage_bar_force_n[j] > 0.0 || v == 0.0),
                    "{j}: {v}"
                );
                let radii = [r.rib_contact_radius_m[j], r.rib_contact_ring_radius_m[j]];
                if r.rib_force_n[j] > 0.0 {
                    self.rib_contacts += 1;
                    assert!(r.rib_reduced_radius_m[j] > 0.0);
                    assert!(radii[0] >= 0.0 && radii[0] <= self.rw, "{radii:?}");
                    assert!(radii[1] > 0.0, "{radii:?}");
                } else {
                    assert!(r.rib_reduced_radius_m[j].is_nan());
                    assert!(radii.iter().all(|x| x.is_nan()), "{radii:?}");
                }
            }
        }
    }
    let b = b2002834(6);
    let w = rpm(6371.0);
    let cond = OperatingConditions::new(w, 2000.0);
    let settings = DynamicsSettings {
        output_step_s: 5e-6,
        ..DynamicsSettings::default()
    };
    let traction = RacewayTraction::same(pao());
    let params = ContactParameters::for_bearing(&b);
    let mut check = Check {
        w,
        rw: 0.5 * b.roller.diameter,
        samples: 0,
        rib_contacts: 0,
    };
    let mut sim = Simulation::new(&b, cond.clone(), params, settings, traction.clone()).unwrap();
    sim.run_until(3e-5, &mut check, &mut |_| {}).unwrap();
    assert!(check.samples >= 5, "{}", check.samples);
    // every roller pushed 5 µm into the rib on its +z side
    let mut init =
        Simulation::default_initial_state(&b, cond.clone(), params, traction.clone()).unwrap();
    let reach = 0.5 * b.roller_rib_axial_clearance().unwrap() + 5e-6;
    for r in &mut init.rollers {
        r.axial_m = reach;
    }
    let mut sim =
        Simulation::with_initial_state(&b, cond, params, settings, traction, &init).unwrap();
    sim.sample_now(&mut check);
    assert!(check.rib_contacts > 0);
}
