//! SPEC V-06 with the 6-DOF dynamics (seed 000 §2.3, Figs 2.14–2.16): cage slip of the
//! O'Brien–Taylor bearing against radial load, speed and misalignment.
//!
//! Each point is the simulation `rolldyn simulate` builds from `examples/obrien-taylor.toml`
//! (`rolldyn_setup::prepare`: quasi-static start, hydrodynamic cage land, the model's cage drag,
//! its NVI 65 linear-elastic traction with the seed's Λ limits), at the seed's oil temperature for
//! the speed (Table 2.4). The slip is measured over whole cage-revolution periods after steady
//! state by the cage angle ([`rolldyn_dynamics::study::measure_cage_slip`]).

use rolldyn_dynamics::study::{SlipMeasurement, SlipWindow, measure_cage_slip};
use rolldyn_geometry::BearingModel;
use rolldyn_model::Model;
use rolldyn_setup::Overrides;

/// Seed 000 Table 2.4: (speed rpm, oil temperature °C).
pub const TABLE_2_4: [(f64, f64); 4] = [
    (1500.0, 44.0),
    (2500.0, 49.5),
    (4000.0, 54.5),
    (4500.0, 59.0),
];

/// Oil temperature of the O'Brien–Taylor tests at `rpm` (Table 2.4, linear interpolation,
/// constant outside), K.
pub fn oil_temperature_k(rpm: f64) -> f64 {
    let pts: Vec<(f64, f64)> = TABLE_2_4.iter().map(|&(n, t)| (n, t + 273.15)).collect();
    rolldyn_dynamics::conditions::piecewise_linear(&pts, rpm)
}

/// Settings of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudySettings {
    /// slices per roller (overrides the model)
    pub slices: Option<usize>,
    /// run length, averaging window and steady-state test of each point
    pub window: SlipWindow,
}

impl Default for StudySettings {
    /// The model's slices, [`SlipWindow::default`].
    fn default() -> Self {
        Self {
            slices: None,
            window: SlipWindow::default(),
        }
    }
}

/// One point of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicPoint {
    /// inner-ring speed, rpm
    pub speed_rpm: f64,
    /// radial load, N
    pub radial_load_n: f64,
    /// misalignment of the inner ring, rad
    pub misalignment_rad: f64,
    /// oil temperature (seed Table 2.4), K
    pub temperature_k: f64,
    /// cage slip and its averaging window
    pub slip: SlipMeasurement,
    /// wall time of the point, s
    pub wall_s: f64,
}

/// Runs one point on `model` (the O'Brien–Taylor example) at `speed_rpm`, `radial_load_n` and
/// `misalignment_rad`.
pub fn dynamic_point(
    model: &Model,
    speed_rpm: f64,
    radial_load_n: f64,
    misalignment_rad: f64,
    settings: &StudySettings,
) -> Result<DynamicPoint, String> {
    let mut model = model.clone();
    let BearingModel::Cylindrical(bearing) = &mut model.bearing else {
        return Err("the O'Brien–Taylor study needs a cylindrical bearing".into());
    };
    if let Some(n) = settings.slices {
        bearing.roller.slice_count = n;
    }
    bearing.misalignment.inner_ring_tilt = misalignment_rad;
    let temperature_k = oil_temperature_k(speed_rpm);
    let overrides = Overrides {
        speed: Some(speed_rpm * std::f64::consts::PI / 30.0),
        radial_load: Some(radial_load_n),
        axial_load: None,
        oil_temperature: Some(temperature_k),
        ..Overrides::default()
    };
    let (mut sim, _) =
        rolldyn_setup::prepare(&model, &overrides, 0.0, None).map_err(|e| e.to_string())?;
    let epicyclic = sim.epicyclic_cage_speed();
    let slip =
        measure_cage_slip(&mut sim, epicyclic, &settings.window).map_err(|e| e.to_string())?;
    Ok(DynamicPoint {
        speed_rpm,
        radial_load_n,
        misalignment_rad,
        temperature_k,
        slip,
        wall_s: sim.summary().wall_time_s,
    })
}
