//! Plausibility bounds of operating values (issue 22 item 5), shared by the model file and the
//! command-line overrides: a speed or temperature no bearing runs at is bad input, named by
//! its key (or flag), not a numerical failure later. The bounds of the geometry are in
//! [`rolldyn_geometry::plausible`]; docs/model-format.md lists them all.

use rolldyn_geometry::{BearingModel, GeometryError};

/// Largest surface speed at the pitch diameter, m/s (record bearings run at ≈ 200 m/s,
/// a speed factor n·d_m of 4·10⁶ mm/min).
pub const MAX_PITCH_SURFACE_SPEED_M_S: f64 = 300.0;
/// Plausible part and oil temperatures, K (−200 °C … 500 °C).
pub const TEMPERATURE_RANGE_K: (f64, f64) = (73.15, 773.15);

/// Checks a temperature [K] given at `key` (a model key or a flag).
pub fn check_temperature(key: &str, kelvin: f64) -> Result<(), GeometryError> {
    let (lo, hi) = TEMPERATURE_RANGE_K;
    if (lo..=hi).contains(&kelvin) {
        return Ok(());
    }
    let reason = if kelvin <= 0.0 {
        format!("{:.2} °C is below absolute zero", kelvin - 273.15)
    } else {
        format!(
            "{:.4e} °C is implausible (expected {:.2}…{:.2} °C)",
            kelvin - 273.15,
            lo - 273.15,
            hi - 273.15
        )
    };
    Err(GeometryError::new(key, reason))
}

/// Checks a ring speed [rad/s] given at `key` against the surface-speed bound at the pitch
/// diameter of `bearing` (no bound for a roller–raceway pair).
pub fn check_speed(bearing: &BearingModel, key: &str, speed: f64) -> Result<(), GeometryError> {
    let pitch_diameter = match bearing {
        BearingModel::Cylindrical(b) => b.pitch_diameter(),
        BearingModel::Tapered(b) => b.pitch_diameter,
        BearingModel::RollerRaceway(_) => {
            return speed
                .is_finite()
                .then_some(())
                .ok_or_else(|| GeometryError::new(key, "must be finite"));
        }
    };
    let limit = MAX_PITCH_SURFACE_SPEED_M_S / (0.5 * pitch_diameter);
    if speed.abs() <= limit {
        return Ok(());
    }
    let rpm = 30.0 / std::f64::consts::PI;
    Err(GeometryError::new(
        key,
        format!(
            "{:.4e} rpm is implausible: more than {:.0} rpm, a surface speed of {} m/s at the \
             pitch diameter Ø{:.3} mm",
            speed * rpm,
            limit * rpm,
            MAX_PITCH_SURFACE_SPEED_M_S,
            pitch_diameter * 1e3
        ),
    ))
}
