//! `[lubricant]` and `[operating]`: the oil of a model and its operating point, in SI units.

use crate::schema::{LoadDirection, LubricantSection, OperatingSection, RheologyName};
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
}

pub(crate) fn operating(section: Option<&OperatingSection>) -> Result<Operating, GeometryError> {
    let Some(s) = section else {
        return Ok(Operating::default());
    };
    let t = &s.temperatures;
    let kelvin = |q: Option<rolldyn_units::Quantity<rolldyn_units::Temperature>>, key: &str| {
        q.map(|q| q.si())
            .map(|k| {
                if k > 0.0 {
                    Ok(k)
                } else {
                    Err(GeometryError::new(
                        format!("operating.temperatures.{key}"),
                        "is below absolute zero",
                    ))
                }
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
    };
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
            let text = std::fs::read_to_string(&path).map_err(|e| {
                GeometryError::new(
                    "lubricant.file",
                    format!("cannot read {}: {e}", path.display()),
                )
            })?;
            toml::from_str(&text).map_err(|e| {
                GeometryError::new(
                    "lubricant.file",
                    format!("{}: {}", path.display(), e.message().trim()),
                )
            })?
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
    oil.validate()
        .map_err(|e| GeometryError::new("lubricant", e.to_string()))?;
    let rheology = match s.rheology.unwrap_or(RheologyName::ViscoElastic) {
        RheologyName::ViscoElastic => Rheology::ViscoElastic,
        RheologyName::Isothermal => Rheology::Isothermal,
        RheologyName::LinearElastic => Rheology::LinearElastic { cap: 0.1 },
    };
    Ok(Some(Lubrication { oil, rheology }))
}
