//! Plausibility bounds of operating values (issue 22 item 5), shared by the model file and the
//! command-line overrides: a speed or temperature no bearing runs at is bad input, named by
//! its key (or flag), not a numerical failure later. The bounds of the geometry are in
//! [`rolldyn_geometry::plausible`]; docs/model-format.md lists them all.

use rolldyn_contact::hertz::{
    Conformity, LineContact, MAX_CREDIBLE_PRESSURE_PA, reduced_modulus, reduced_radius,
};
use rolldyn_geometry::{BearingModel, GeometryError};
use rolldyn_units::format_number;

/// Largest surface speed at the pitch diameter, m/s (record bearings run at ≈ 200 m/s,
/// a speed factor n·d_m of 4·10⁶ mm/min); also the largest rolling (entrainment) speed of a
/// lubricated contact, which cannot exceed the surface speeds of its bodies.
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

/// Checks a rolling (entrainment) speed [m/s] given at `key` against
/// [`MAX_PITCH_SURFACE_SPEED_M_S`].
pub fn check_rolling_speed(key: &str, speed: f64) -> Result<(), GeometryError> {
    if speed.abs() <= MAX_PITCH_SURFACE_SPEED_M_S {
        return Ok(());
    }
    Err(GeometryError::new(
        key,
        format!(
            "{} m/s is implausible: more than {MAX_PITCH_SURFACE_SPEED_M_S} m/s, the surface \
             speed of the fastest bearings",
            format_number(speed)
        ),
    ))
}

/// The reason a contact pressure `pressure_pa` is beyond [`MAX_CREDIBLE_PRESSURE_PA`], for a
/// message naming the load that gives it; `None` within the bound.
pub fn pressure_beyond_materials(pressure_pa: f64) -> Option<String> {
    (pressure_pa.is_nan() || pressure_pa > MAX_CREDIBLE_PRESSURE_PA).then(|| {
        format!(
            "a Hertz pressure of {} GPa, beyond any bearing material ({} GPa): the elastic \
             contact model does not apply",
            format_number(pressure_pa * 1e-9),
            MAX_CREDIBLE_PRESSURE_PA * 1e-9
        )
    })
}

/// A lower bound of the largest Hertz pressure a radial load `load` [N] gives in `bearing`:
/// the most loaded roller carries at least F/(Z/π + 1) (the loaded rollers' radial components
/// carry F and Σ max(0, cos ψ_j) ≤ Z/π + 1 over Z rollers; a roller–raceway pair carries F),
/// pressed along its whole length on the inner raceway (on its own radius for a tapered
/// roller, a smaller curvature than the cone's).
pub fn radial_load_pressure_floor(bearing: &BearingModel, load: f64) -> f64 {
    let (rollers, roller, raceway, conformity, modulus) = match bearing {
        BearingModel::Cylindrical(b) => (
            b.roller_count as f64,
            &b.roller,
            0.5 * b.inner_ring.raceway_diameter,
            Conformity::ConvexConvex,
            moduli(&b.roller.material, &b.inner_ring.material),
        ),
        BearingModel::RollerRaceway(p) => (
            0.0,
            &p.roller,
            0.5 * p.raceway.raceway_diameter,
            if p.raceway_is_inner {
                Conformity::ConvexConvex
            } else {
                Conformity::ConvexConcave
            },
            moduli(&p.roller.material, &p.raceway.material),
        ),
        BearingModel::Tapered(b) => {
            let line = LineContact {
                reduced_radius: 0.5 * b.roller.mean_diameter,
                reduced_modulus: moduli(&b.roller.material, &b.inner_material),
                length: b.roller.length,
            };
            let rollers = 2.0 * b.rollers_per_row as f64;
            return line.max_pressure(load / (rollers / std::f64::consts::PI + 1.0));
        }
    };
    let roller_load = if rollers > 0.0 {
        load / (rollers / std::f64::consts::PI + 1.0)
    } else {
        load
    };
    let reduced_radius =
        reduced_radius(0.5 * roller.diameter, raceway, conformity).unwrap_or(0.5 * roller.diameter);
    LineContact {
        reduced_radius,
        reduced_modulus: modulus,
        length: roller.length,
    }
    .max_pressure(roller_load)
}

fn moduli(a: &rolldyn_geometry::Material, b: &rolldyn_geometry::Material) -> f64 {
    reduced_modulus(
        a.youngs_modulus,
        a.poisson_ratio,
        b.youngs_modulus,
        b.poisson_ratio,
    )
}

/// Checks a radial load [N] given at `key` (a model key or a flag): not negative, and its
/// Hertz pressure ([`radial_load_pressure_floor`]) within [`MAX_CREDIBLE_PRESSURE_PA`].
pub fn check_radial_load(
    bearing: &BearingModel,
    key: &str,
    load: f64,
) -> Result<(), GeometryError> {
    if load.is_nan() || load < 0.0 {
        return Err(GeometryError::new(key, "must be ≥ 0"));
    }
    match pressure_beyond_materials(radial_load_pressure_floor(bearing, load)) {
        None => Ok(()),
        Some(reason) => Err(GeometryError::new(
            key,
            format!("{} N gives at least {reason}", format_number(load)),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn n14_a_radial_load_beyond_any_material_is_refused() {
        let bearing = BearingModel::Cylindrical(crate::default_cylindrical_bearing());
        assert!(check_radial_load(&bearing, "--radial-load", 1600.0).is_ok());
        assert!(check_radial_load(&bearing, "--radial-load", 1e5).is_ok());
        for load in [1e8, 1e300, f64::INFINITY, f64::NAN, -1.0] {
            let e = check_radial_load(&bearing, "--radial-load", load).unwrap_err();
            assert_eq!(e.key, "--radial-load");
            assert!(e.reason.len() < 200, "{}", e.reason);
        }
        // the floor stays below the quasi-static Hertz pressure of 2002834 at 1600 N (≈ 1 GPa)
        let floor = radial_load_pressure_floor(&bearing, 1600.0);
        assert!(floor > 0.2e9 && floor < 1.0e9, "{floor}");
    }

    #[test]
    fn n14_rolling_speeds_are_bounded() {
        assert!(check_rolling_speed("--rolling-speed", 40.0).is_ok());
        let e = check_rolling_speed("--rolling-speed", 1e300).unwrap_err();
        assert!(e.reason.starts_with("1.0000e300 m/s"), "{}", e.reason);
    }
}
