//! `[lubricant]` and `[operating]`: the oil of a model and its operating point, in SI units.

use crate::schema::{
    LoadDirection, LubricantSection, OperatingSection, RheologyName, StartupSection,
};
use rolldyn_geometry::GeometryError;
use rolldyn_lubrication::viscosity::walther_from_two_points;
use rolldyn_lubrication::{
    LubError, Lubricant, MurakiSettings, Rheology, TempLaw, TractionModel, ViscosityLaw,
    lubricant_by_name,
};
use std::path::Path;

/// The oil of a model and how its traction is modelled.
#[derive(Debug, Clone, PartialEq)]
pub struct Lubrication {
    pub oil: Lubricant,
    pub rheology: Rheology,
}

impl Lubrication {
    /// The traction model of the raceway contacts (Muraki with the mixed-friction blend).
    pub fn traction_model(&self) -> Result<TractionModel, LubError> {
        TractionModel::lubricated(
            self.oil.clone(),
            MurakiSettings {
                rheology: self.rheology,
                ..MurakiSettings::default()
            },
        )
    }
}

/// Temperatures of the parts [K]; `None` where the model file is silent.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Temperatures {
    pub oil: Option<f64>,
    pub inner_ring: Option<f64>,
    pub outer_ring: Option<f64>,
    pub rollers: Option<f64>,
    pub cage: Option<f64>,
    pub shaft: Option<f64>,
    pub housing: Option<f64>,
}

/// The operating point a model file gives; every value may be overridden on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Operating {
    /// Inner-ring speed [rad/s].
    pub inner_speed: Option<f64>,
    /// Outer-ring speed [rad/s] (intershaft bearings).
    pub outer_speed: Option<f64>,
    /// Radial load on the inner ring [N].
    pub radial_load: Option<f64>,
    /// Axial load [N].
    pub axial_load: Option<f64>,
    /// The radial load rotates with the inner ring (unbalance; 2002834) instead of being fixed.
    pub load_rotates: bool,
    pub temperatures: Temperatures,
    /// Rotating unbalance U [kg·m], F = U ω² (SPEC §3.7).
    pub unbalance: Option<f64>,
    /// Direction of the unbalance force at t = 0 [rad from +x].
    pub unbalance_phase: f64,
}

/// A radial force on the inner ring fixed in space, optionally with one step (SPEC §3.7:
/// rotor weight share, gearbox load with its step at starter cut-off).
#[derive(Debug, Clone, PartialEq)]
pub struct FixedLoad {
    pub name: Option<String>,
    /// Magnitude [N] (up to and including the step time).
    pub magnitude: f64,
    /// Direction in the x–y plane [rad from +x] (default 3π/2 = −y).
    pub direction: f64,
    /// `(magnitude after the step [N], step time [s])`.
    pub step: Option<(f64, f64)>,
}

/// Time-dependent operating data: extra loads and piecewise-linear schedules `(t [s], value
/// [SI])`, strictly increasing in time, constant beyond their ends (SPEC §3.7).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Schedules {
    /// `[[operating.loads]]`.
    pub loads: Vec<FixedLoad>,
    /// Inner-ring speed [rad/s].
    pub speed: Option<Vec<(f64, f64)>>,
    /// Operating radial (diametral) clearance [m].
    pub clearance: Option<Vec<(f64, f64)>>,
    /// Oil temperature [K].
    pub oil_temperature: Option<Vec<(f64, f64)>>,
}

/// One frozen time point of a start-up.
#[derive(Debug, Clone, PartialEq)]
pub struct FrozenPoint {
    pub label: String,
    /// [s]
    pub time: f64,
}

/// `[startup]`: frozen points of a start-up (seed 000 §3.1.2, Table 3.4).
#[derive(Debug, Clone, PartialEq)]
pub struct Startup {
    pub points: Vec<FrozenPoint>,
    /// Cage revolutions simulated per point.
    pub revolutions: f64,
    /// Last revolutions averaged for the reported slip (`None`: the last half).
    pub average_revolutions: Option<f64>,
}

/// Default cage revolutions per frozen point.
pub const DEFAULT_STARTUP_REVOLUTIONS: f64 = 10.0;

pub(crate) fn operating(section: Option<&OperatingSection>) -> Result<Operating, GeometryError> {
    let Some(s) = section else {
        return Ok(Operating::default());
    };
    let t = &s.temperatures;
    let kelvin = |q: Option<rolldyn_units::Quantity<rolldyn_units::Temperature>>, key: &str| {
        q.map(|q| q.si())
            .map(|k| {
                crate::bounds::check_temperature(&format!("operating.temperatures.{key}"), k)
                    .map(|()| k)
            })
            .transpose()
    };
    let operating = Operating {
        inner_speed: s.inner_speed.map(|q| q.si()),
        outer_speed: s.outer_speed.map(|q| q.si()),
        radial_load: s.radial_load.map(|q| q.si()),
        axial_load: s.axial_load.map(|q| q.si()),
        load_rotates: s.load_direction == Some(LoadDirection::Rotating),
        temperatures: Temperatures {
            oil: kelvin(t.oil, "oil")?,
            inner_ring: kelvin(t.inner_ring, "inner_ring")?,
            outer_ring: kelvin(t.outer_ring, "outer_ring")?,
            rollers: kelvin(t.rollers, "rollers")?,
            cage: kelvin(t.cage, "cage")?,
            shaft: kelvin(t.shaft, "shaft")?,
            housing: kelvin(t.housing, "housing")?,
        },
        unbalance: s.unbalance.map(|q| q.si()),
        unbalance_phase: s.unbalance_phase.map_or(0.0, |q| q.si()),
    };
    if let Some(u) = operating.unbalance
        && u < 0.0
    {
        return Err(GeometryError::new(
            "operating.unbalance",
            "must not be negative",
        ));
    }
    if s.inner_speed.is_some() && s.speed_schedule.is_some() {
        return Err(GeometryError::new(
            "operating.speed_schedule",
            "give operating.inner_speed or operating.speed_schedule, not both",
        ));
    }
    if t.oil.is_some() && s.oil_temperature_schedule.is_some() {
        return Err(GeometryError::new(
            "operating.oil_temperature_schedule",
            "give operating.temperatures.oil or operating.oil_temperature_schedule, not both",
        ));
    }
    if let Some(load) = operating.radial_load
        && load < 0.0
    {
        return Err(GeometryError::new(
            "operating.radial_load",
            "must not be negative",
        ));
    }
    Ok(operating)
}

/// Pairs `time` with `values` after checking lengths and strictly increasing finite times.
fn schedule(
    key: &str,
    value_key: &str,
    times: &[rolldyn_units::Quantity<rolldyn_units::Time>],
    values: Vec<f64>,
) -> Result<Vec<(f64, f64)>, GeometryError> {
    if times.is_empty() {
        return Err(GeometryError::new(
            format!("{key}.time"),
            "needs at least one point",
        ));
    }
    if times.len() != values.len() {
        return Err(GeometryError::new(
            format!("{key}.{value_key}"),
            format!(
                "has {} values for {} times: give one value per time",
                values.len(),
                times.len()
            ),
        ));
    }
    let times: Vec<f64> = times.iter().map(|q| q.si()).collect();
    if let Some(i) = times.windows(2).position(|w| w[1] <= w[0]) {
        return Err(GeometryError::new(
            format!("{key}.time"),
            format!(
                "times must increase strictly: {} s follows {} s",
                times[i + 1],
                times[i]
            ),
        ));
    }
    Ok(times.into_iter().zip(values).collect())
}

/// `[[operating.loads]]` and the schedules of `[operating]`, in SI.
pub(crate) fn schedules(section: Option<&OperatingSection>) -> Result<Schedules, GeometryError> {
    let Some(s) = section else {
        return Ok(Schedules::default());
    };
    let mut loads = Vec::with_capacity(s.loads.len());
    for (i, l) in s.loads.iter().enumerate() {
        let key = format!("operating.loads[{i}]");
        let magnitude = l.magnitude.si();
        if magnitude < 0.0 {
            return Err(GeometryError::new(
                format!("{key}.magnitude"),
                "must not be negative (turn the direction instead)",
            ));
        }
        let step = match (l.after, l.at) {
            (Some(after), Some(at)) => {
                if after.si() < 0.0 {
                    return Err(GeometryError::new(
                        format!("{key}.after"),
                        "must not be negative",
                    ));
                }
                Some((after.si(), at.si()))
            }
            (None, None) => None,
            (Some(_), None) => {
                return Err(GeometryError::new(
                    format!("{key}.after"),
                    "a load step needs its time: give `at` as well",
                ));
            }
            (None, Some(_)) => {
                return Err(GeometryError::new(
                    format!("{key}.at"),
                    "a load step needs the magnitude after it: give `after` as well",
                ));
            }
        };
        loads.push(FixedLoad {
            name: l.name.clone(),
            magnitude,
            direction: l.direction.map_or(1.5 * std::f64::consts::PI, |q| q.si()),
            step,
        });
    }
    let speed = s
        .speed_schedule
        .as_ref()
        .map(|p| {
            schedule(
                "operating.speed_schedule",
                "speed",
                &p.time,
                p.speed.iter().map(|q| q.si()).collect(),
            )
        })
        .transpose()?;
    let clearance = s
        .clearance_schedule
        .as_ref()
        .map(|p| {
            schedule(
                "operating.clearance_schedule",
                "radial",
                &p.time,
                p.radial.iter().map(|q| q.si()).collect(),
            )
        })
        .transpose()?;
    let oil_temperature = s
        .oil_temperature_schedule
        .as_ref()
        .map(|p| {
            let values: Vec<f64> = p.oil.iter().map(|q| q.si()).collect();
            for &k in &values {
                crate::bounds::check_temperature("operating.oil_temperature_schedule.oil", k)?;
            }
            schedule("operating.oil_temperature_schedule", "oil", &p.time, values)
        })
        .transpose()?;
    Ok(Schedules {
        loads,
        speed,
        clearance,
        oil_temperature,
    })
}

/// `[startup]` in SI.
pub(crate) fn startup(section: Option<&StartupSection>) -> Result<Option<Startup>, GeometryError> {
    let Some(s) = section else {
        return Ok(None);
    };
    if s.frozen_points.is_empty() {
        return Err(GeometryError::new(
            "startup.frozen_points",
            "needs at least one time",
        ));
    }
    let times: Vec<f64> = s.frozen_points.iter().map(|q| q.si()).collect();
    if let Some(i) = times.windows(2).position(|w| w[1] <= w[0]) {
        return Err(GeometryError::new(
            "startup.frozen_points",
            format!(
                "times must increase strictly: {} s follows {} s",
                times[i + 1],
                times[i]
            ),
        ));
    }
    let labels = match &s.labels {
        Some(l) if l.len() != times.len() => {
            return Err(GeometryError::new(
                "startup.labels",
                format!(
                    "has {} labels for {} frozen points: give one per point",
                    l.len(),
                    times.len()
                ),
            ));
        }
        Some(l) => l.clone(),
        None => (1..=times.len()).map(|i| i.to_string()).collect(),
    };
    if let Some((i, label)) = labels
        .iter()
        .enumerate()
        .find(|(i, l)| labels[..*i].contains(l))
    {
        return Err(GeometryError::new(
            format!("startup.labels[{i}]"),
            format!("label '{label}' is used twice"),
        ));
    }
    let revolutions = s.revolutions.unwrap_or(DEFAULT_STARTUP_REVOLUTIONS);
    if !(revolutions >= 1.0 && revolutions.is_finite()) {
        return Err(GeometryError::new(
            "startup.revolutions",
            "must be at least 1 cage revolution",
        ));
    }
    if let Some(n) = s.average_revolutions
        && !(n >= 1.0 && n <= revolutions)
    {
        return Err(GeometryError::new(
            "startup.average_revolutions",
            "must lie between 1 and startup.revolutions",
        ));
    }
    Ok(Some(Startup {
        points: labels
            .into_iter()
            .zip(times)
            .map(|(label, time)| FrozenPoint { label, time })
            .collect(),
        revolutions,
        average_revolutions: s.average_revolutions,
    }))
}

/// The `[lubricant]` key that overrides property `key` of [`Lubricant::validate`]'s errors, or
/// the key naming the oil when the table does not override it.
fn section_key(s: &LubricantSection, key: &str) -> &'static str {
    let (given, section_key) = match key {
        "density" => (s.density.is_some(), "lubricant.density"),
        "viscosity" | "beta0" => (
            s.kinematic_viscosity.is_some(),
            "lubricant.kinematic_viscosity",
        ),
        "pressure_viscosity" => (
            s.pressure_viscosity.is_some(),
            "lubricant.pressure_viscosity",
        ),
        "shear_modulus" => (s.shear_modulus.is_some(), "lubricant.shear_modulus"),
        "eyring_stress" => (s.eyring_stress.is_some(), "lubricant.eyring_stress"),
        "thermal_conductivity" => (
            s.thermal_conductivity.is_some(),
            "lubricant.thermal_conductivity",
        ),
        "mixed_friction" => (s.lambda_boundary.is_some(), "lubricant.lambda_boundary"),
        _ => (false, ""),
    };
    match (given, s.file.is_some()) {
        (true, _) => section_key,
        (false, true) => "lubricant.file",
        (false, false) => "lubricant.oil",
    }
}

pub(crate) fn lubrication(
    section: Option<&LubricantSection>,
    model_file: &str,
) -> Result<Option<Lubrication>, GeometryError> {
    let Some(s) = section else {
        return Ok(None);
    };
    let mut oil = match (&s.oil, &s.file) {
        (Some(name), None) => lubricant_by_name(name)
            .map_err(|e| GeometryError::new("lubricant.oil", e.to_string()))?,
        (None, Some(file)) => {
            let path = Path::new(model_file)
                .parent()
                .unwrap_or(Path::new("."))
                .join(file);
            crate::load_oil_file(&path)
                .map_err(|e| GeometryError::new("lubricant.file", e.to_string()))?
        }
        _ => {
            return Err(GeometryError::new(
                "lubricant.oil",
                "give exactly one of lubricant.oil and lubricant.file",
            ));
        }
    };
    if let Some(points) = &s.kinematic_viscosity {
        let [t1, t2] = points.temperatures.map(|t| t.si());
        let [n1, n2] = points.values.map(|v| v.si());
        if !(t1 > 0.0 && t2 > t1 && n1 > n2 && n2 > 0.0) {
            return Err(GeometryError::new(
                "lubricant.kinematic_viscosity",
                "needs two increasing temperatures with decreasing positive viscosities",
            ));
        }
        oil.viscosity = Some(ViscosityLaw::Kinematic {
            law: walther_from_two_points(t1, n1, t2, n2),
        });
    }
    let constant = |q: Option<f64>| q.map(|value| TempLaw::Constant { value });
    if let Some(law) = constant(s.density.map(|q| q.si())) {
        oil.density = Some(law);
    }
    if let Some(law) = constant(s.pressure_viscosity.map(|q| q.si())) {
        oil.pressure_viscosity = Some(law);
    }
    if let Some(law) = constant(s.shear_modulus.map(|q| q.si())) {
        oil.shear_modulus = Some(law);
    }
    if let Some(law) = constant(s.eyring_stress.map(|q| q.si())) {
        oil.eyring_stress = Some(law);
    }
    if let Some(law) = constant(s.thermal_conductivity.map(|q| q.si())) {
        oil.thermal_conductivity = Some(law);
    }
    match (s.lambda_boundary, s.lambda_hydrodynamic) {
        (Some(lambda_bd), Some(lambda_hd)) => {
            oil.mixed_friction = Some(rolldyn_lubrication::lubricant::MixedLimitsData {
                lambda_bd,
                lambda_hd,
            })
        }
        (None, None) => {}
        _ => {
            return Err(GeometryError::new(
                "lubricant.lambda_boundary",
                "give lambda_boundary and lambda_hydrodynamic together",
            ));
        }
    }
    oil.validate().map_err(|e| match e {
        LubError::Property { key, reason, .. } => {
            GeometryError::new(section_key(s, key), format!("{key} {reason}"))
        }
        other => GeometryError::new("lubricant", other.to_string()),
    })?;
    let rheology = match s.rheology.unwrap_or(RheologyName::ViscoElastic) {
        RheologyName::ViscoElastic => Rheology::ViscoElastic,
        RheologyName::Isothermal => Rheology::Isothermal,
        RheologyName::LinearElastic => Rheology::LinearElastic { cap: 0.1 },
    };
    Ok(Some(Lubrication { oil, rheology }))
}
