//! User oil files (`--oil-file`, `lubricant.file`): TOML with units like model files, read into a
//! [`Lubricant`]. A value is a number (SI) or a string with its unit (`"870 kg/m3"`,
//! `"20 1/GPa"`, `"40 C"`); every property is either such a constant or a temperature law
//! table; the viscosity may be given as two points (`kinematic_viscosity`, joined by ASTM D341
//! like a model's `[lubricant]` table). docs/lubricants.md lists every key.

use crate::error::ModelError;
use crate::schema::ViscosityPoints;
use crate::{Document, read};
use rolldyn_lubrication::lubricant::MixedLimitsData;
use rolldyn_lubrication::viscosity::walther_from_two_points;
use rolldyn_lubrication::{
    LubError, Lubricant, OilProperty, PropertySource, TempLaw, ViscosityLaw,
};
use rolldyn_units::{
    Density, Dim, DynamicViscosity, KinematicViscosity, PerPressure, PerTemperature, Pressure,
    Quantity, Temperature, ThermalConductivity,
};
use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, Visitor};
use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;
use std::path::Path;

/// The schema of an oil file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct OilFile {
    name: String,
    #[serde(default)]
    source: String,
    #[serde(default)]
    class: String,
    temperature_range: [Quantity<Temperature>; 2],
    density: Option<Law<Density>>,
    kinematic_viscosity: Option<LawOrPoints>,
    dynamic_viscosity: Option<Law<DynamicViscosity>>,
    pressure_viscosity: Option<Law<PerPressure>>,
    roelands_z: Option<f64>,
    shear_modulus: Option<Law<Pressure>>,
    eyring_stress: Option<Law<Pressure>>,
    beta0: Option<Quantity<PerTemperature>>,
    kappa_per_k_pa: Option<f64>,
    thermal_conductivity: Option<Law<ThermalConductivity>>,
    mixed_friction: Option<MixedFriction>,
    #[serde(default)]
    missing: Vec<String>,
    /// property key → source, for the measured properties
    #[serde(default)]
    measured: BTreeMap<String, String>,
    /// property key → rule or class value, for the estimated properties
    #[serde(default)]
    estimated: BTreeMap<String, String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MixedFriction {
    lambda_bd: f64,
    lambda_hd: f64,
}

/// A kinematic viscosity: two points (ASTM D341 through them) or a law.
#[derive(Debug)]
enum LawOrPoints {
    Points(ViscosityPoints),
    Law(Law<KinematicViscosity>),
}

impl<'de> Deserialize<'de> for LawOrPoints {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        if value.as_table().is_some_and(|t| !t.contains_key("kind")) {
            ViscosityPoints::deserialize(value)
                .map(LawOrPoints::Points)
                .map_err(de::Error::custom)
        } else {
            Law::deserialize(value)
                .map(LawOrPoints::Law)
                .map_err(de::Error::custom)
        }
    }
}

/// A property of dimension `D` as a function of temperature: a constant (number in SI or string
/// with unit) or a law table with `kind`.
#[derive(Debug)]
struct Law<D: Dim>(LawTable<D>);

/// The law tables; polynomial and power coefficients are in `unit` (SI when absent) per °Cᵏ
/// or per unit of the temperature power.
#[derive(Debug, Deserialize)]
#[serde(
    tag = "kind",
    rename_all = "snake_case",
    deny_unknown_fields,
    bound(deserialize = "")
)]
enum LawTable<D: Dim> {
    Constant {
        value: Quantity<D>,
    },
    PolynomialCelsius {
        coeffs: Vec<f64>,
        unit: Option<String>,
    },
    PowerCelsius {
        a: f64,
        b: f64,
        unit: Option<String>,
    },
    PowerKelvin {
        a: f64,
        b: f64,
        unit: Option<String>,
    },
    Exponential {
        value_ref: Quantity<D>,
        t_ref: Quantity<Temperature>,
        beta: Quantity<PerTemperature>,
    },
    Walther {
        a: f64,
        b: f64,
    },
}

impl<'de, D: Dim> Deserialize<'de> for Law<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        struct LawVisitor<D>(PhantomData<D>);
        impl<'de, D: Dim> Visitor<'de> for LawVisitor<D> {
            type Value = Law<D>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(
                    f,
                    "{} (a number in {} or a string with unit) or a law table with `kind`",
                    D::DIMENSION.name(),
                    D::DIMENSION.si_symbol()
                )
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                let value = Quantity::parse(v).map_err(E::custom)?;
                Ok(Law(LawTable::Constant { value }))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                Ok(Law(LawTable::Constant {
                    value: Quantity::from_si(v),
                }))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                self.visit_f64(v as f64)
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                self.visit_f64(v as f64)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
                LawTable::deserialize(de::value::MapAccessDeserializer::new(map)).map(Law)
            }
        }
        deserializer.deserialize_any(LawVisitor(PhantomData))
    }
}

impl<D: Dim> Law<D> {
    /// The SI [`TempLaw`]; `Err` names the bad `unit`.
    fn to_temp_law(&self) -> Result<TempLaw, String> {
        let scale = |unit: &Option<String>| match unit {
            None => Ok(1.0),
            Some(unit) => Quantity::<D>::parse(&format!("1 {unit}"))
                .map(|q| q.si())
                .map_err(|e| format!("unit: {e}")),
        };
        Ok(match &self.0 {
            LawTable::Constant { value } => TempLaw::Constant { value: value.si() },
            LawTable::PolynomialCelsius { coeffs, unit } => {
                let s = scale(unit)?;
                TempLaw::PolynomialCelsius {
                    coeffs: coeffs.iter().map(|c| c * s).collect(),
                }
            }
            LawTable::PowerCelsius { a, b, unit } => TempLaw::PowerCelsius {
                a: a * scale(unit)?,
                b: *b,
            },
            LawTable::PowerKelvin { a, b, unit } => TempLaw::PowerKelvin {
                a: a * scale(unit)?,
                b: *b,
            },
            LawTable::Exponential {
                value_ref,
                t_ref,
                beta,
            } => TempLaw::Exponential {
                value_ref: value_ref.si(),
                t_ref_k: t_ref.si(),
                beta_per_k: beta.si(),
            },
            LawTable::Walther { a, b } => {
                if D::DIMENSION != KinematicViscosity::DIMENSION {
                    return Err("kind = \"walther\" is a kinematic-viscosity law".into());
                }
                TempLaw::Walther { a: *a, b: *b }
            }
        })
    }
}

/// Reads the oil file at `path`.
pub fn load_oil_file(path: &Path) -> Result<Lubricant, ModelError> {
    let (text, file) = read(path)?;
    parse_oil_file(&text, &file)
}

/// Parses oil-file `text` (named `file` in errors) and checks that the oil is physical.
pub fn parse_oil_file(text: &str, file: &str) -> Result<Lubricant, ModelError> {
    let document = Document::<OilFile>::parse(text, file)?;
    let f = &document.schema;
    let law = |key: &str, law: Option<Result<TempLaw, String>>| {
        law.transpose().map_err(|e| document.error(key, e))
    };
    let viscosity = match (&f.kinematic_viscosity, &f.dynamic_viscosity) {
        (Some(_), Some(_)) => {
            return Err(document.error(
                "dynamic_viscosity",
                "give kinematic_viscosity or dynamic_viscosity, not both".into(),
            ));
        }
        (Some(LawOrPoints::Points(points)), None) => Some(ViscosityLaw::Kinematic {
            law: two_point_law(points).map_err(|e| document.error("kinematic_viscosity", e))?,
        }),
        (Some(LawOrPoints::Law(l)), None) => Some(ViscosityLaw::Kinematic {
            law: law("kinematic_viscosity", Some(l.to_temp_law()))?.expect("given"),
        }),
        (None, Some(l)) => Some(ViscosityLaw::Dynamic {
            law: law("dynamic_viscosity", Some(l.to_temp_law()))?.expect("given"),
        }),
        (None, None) => None,
    };
    let oil = Lubricant {
        name: f.name.clone(),
        source: f.source.clone(),
        class: f.class.clone(),
        temperature_range_k: f.temperature_range.map(|t| t.si()),
        density: law("density", f.density.as_ref().map(Law::to_temp_law))?,
        viscosity,
        pressure_viscosity: law(
            "pressure_viscosity",
            f.pressure_viscosity.as_ref().map(Law::to_temp_law),
        )?,
        roelands_z: f.roelands_z,
        shear_modulus: law(
            "shear_modulus",
            f.shear_modulus.as_ref().map(Law::to_temp_law),
        )?,
        eyring_stress: law(
            "eyring_stress",
            f.eyring_stress.as_ref().map(Law::to_temp_law),
        )?,
        beta0_per_k: f.beta0.map(|q| q.si()),
        kappa_per_k_pa: f.kappa_per_k_pa,
        thermal_conductivity: law(
            "thermal_conductivity",
            f.thermal_conductivity.as_ref().map(Law::to_temp_law),
        )?,
        mixed_friction: f.mixed_friction.as_ref().map(|m| MixedLimitsData {
            lambda_bd: m.lambda_bd,
            lambda_hd: m.lambda_hd,
        }),
        missing: f.missing.clone(),
        provenance: provenance(f).map_err(|(key, reason)| document.error(&key, reason))?,
    };
    for t in &oil.temperature_range_k {
        crate::bounds::check_temperature("temperature_range", *t)
            .map_err(|e| document.error(&e.key, e.reason))?;
    }
    oil.validate().map_err(|e| match e {
        LubError::Property { key, reason, .. } => {
            document.error(file_key(f, key), format!("{key} {reason}"))
        }
        other => document.error("", other.to_string()),
    })?;
    Ok(oil)
}

/// The oil-file key that gives property `key` of [`Lubricant::validate`]'s errors.
fn file_key(f: &OilFile, key: &'static str) -> &'static str {
    match key {
        "viscosity" if f.dynamic_viscosity.is_some() => "dynamic_viscosity",
        "viscosity" => "kinematic_viscosity",
        // β0 is derived from the viscosity law when not given
        "beta0" if f.beta0.is_none() => file_key(f, "viscosity"),
        "kappa" => "kappa_per_k_pa",
        key => key,
    }
}

/// ASTM D341 through the two points of `kinematic_viscosity`.
fn two_point_law(points: &ViscosityPoints) -> Result<TempLaw, String> {
    let [t1, t2] = points.temperatures.map(|t| t.si());
    let [n1, n2] = points.values.map(|v| v.si());
    if !(t1 > 0.0 && t2 > t1 && n1 > n2 && n2 > 0.0) {
        return Err(
            "needs two increasing temperatures with decreasing positive viscosities".into(),
        );
    }
    Ok(walther_from_two_points(t1, n1, t2, n2))
}

/// The `[measured]` and `[estimated]` tables as provenance entries; `Err((key, reason))` for a
/// key that names no property.
fn provenance(f: &OilFile) -> Result<Vec<PropertySource>, (String, String)> {
    let entries = |table: &'static str, map: &BTreeMap<String, String>, measured: bool| {
        map.iter()
            .map(move |(key, source)| {
                let property = OilProperty::from_key(key).ok_or_else(|| {
                    (
                        format!("{table}.{key}"),
                        format!(
                            "not a property; one of {}",
                            OilProperty::ALL.map(OilProperty::key).join(", ")
                        ),
                    )
                })?;
                Ok(if measured {
                    PropertySource::measured(property, source.clone())
                } else {
                    PropertySource::estimated(property, source.clone())
                })
            })
            .collect::<Vec<_>>()
    };
    entries("measured", &f.measured, true)
        .into_iter()
        .chain(entries("estimated", &f.estimated, false))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const OIL: &str = r#"
        name = "my-oil"
        source = "data sheet"
        temperature_range = ["20 C", "120 C"]
        density = { kind = "polynomial_celsius", coeffs = [870.0, -0.6], unit = "kg/m3" }
        kinematic_viscosity = { temperatures = ["40 C", "100 C"], values = ["220 mm2/s", "19 mm2/s"] }
        pressure_viscosity = "20 1/GPa"
        shear_modulus = "1 GPa"
        eyring_stress = { kind = "exponential", value_ref = "5 MPa", t_ref = "40 C", beta = "0.01 1/K" }
        beta0 = "0.03 1/K"
        kappa_per_k_pa = 1.0e-10
        thermal_conductivity = 0.13
        mixed_friction = { lambda_bd = 0.01, lambda_hd = 1.5 }
        [measured]
        viscosity = "data sheet"
        [estimated]
        pressure_viscosity = "class value"
    "#;

    #[test]
    fn units_are_read_and_si_numbers_stay_si() {
        let oil = parse_oil_file(OIL, "my-oil.toml").unwrap();
        let t40 = 313.15;
        assert!((oil.temperature_range_k[0] - 293.15).abs() < 1e-9);
        assert!((oil.density(t40).unwrap() - (870.0 - 24.0)).abs() < 1e-9);
        assert!((oil.kinematic_viscosity(t40).unwrap() / 220e-6 - 1.0).abs() < 1e-9);
        assert!((oil.kinematic_viscosity(373.15).unwrap() / 19e-6 - 1.0).abs() < 1e-9);
        assert!((oil.pressure_viscosity(t40).unwrap() - 2e-8).abs() < 1e-20);
        assert!((oil.shear_modulus(t40).unwrap() - 1e9).abs() < 1e-3);
        let tau = oil.eyring_stress(323.15).unwrap();
        assert!((tau - 5e6 * (-0.1f64).exp()).abs() < 1e-6);
        assert_eq!(oil.beta0_per_k, Some(0.03));
        assert!((oil.thermal_conductivity(t40).unwrap() - 0.13).abs() < 1e-12);
        assert_eq!(oil.provenance.len(), 2);
    }

    #[test]
    fn a_bad_unit_names_the_file_and_key() {
        let text = OIL.replace("\"20 1/GPa\"", "\"20 GPa\"");
        let e = parse_oil_file(&text, "my-oil.toml")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("my-oil.toml:") && e.contains("pressure_viscosity") && e.contains("GPa"),
            "{e}"
        );
        let text = OIL.replace("unit = \"kg/m3\"", "unit = \"kg/m\"");
        let e = parse_oil_file(&text, "my-oil.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("density") && e.contains("kg/m"), "{e}");
        let text = OIL.replace("[estimated]", "[estimated]\nviscosity_index = \"95\"");
        let e = parse_oil_file(&text, "my-oil.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("estimated.viscosity_index"), "{e}");
        let text = format!("{OIL}\nviscosity_index = 95");
        assert!(parse_oil_file(&text, "my-oil.toml").is_err());
    }

    #[test]
    fn n12_implausible_values_name_their_line_and_key() {
        let cases = [
            (
                "shear_modulus = \"1 GPa\"",
                "shear_modulus = \"1e12 GPa\"",
                "shear_modulus",
            ),
            (
                "thermal_conductivity = 0.13",
                "thermal_conductivity = 1e9",
                "thermal_conductivity",
            ),
            ("coeffs = [870.0, -0.6]", "coeffs = [9e11, -0.6]", "density"),
            (
                "kappa_per_k_pa = 1.0e-10",
                "kappa_per_k_pa = 1.0",
                "kappa_per_k_pa",
            ),
            ("\"20 1/GPa\"", "\"2e6 1/GPa\"", "pressure_viscosity"),
            (
                "[\"20 C\", \"120 C\"]",
                "[\"20 C\", \"1e6 C\"]",
                "temperature_range",
            ),
        ];
        for (from, to, key) in cases {
            let text = OIL.replace(from, to);
            assert_ne!(text, OIL, "{from}");
            let line = 1 + text.lines().position(|l| l.contains(to)).unwrap();
            let e = parse_oil_file(&text, "my-oil.toml")
                .unwrap_err()
                .to_string();
            assert!(
                e.starts_with(&format!("my-oil.toml:{line}:")) && e.contains(key),
                "{to}: {e}"
            );
        }
    }

    #[test]
    fn unphysical_oils_are_refused() {
        let text = OIL.replace("shear_modulus = \"1 GPa\"", "shear_modulus = \"-1 GPa\"");
        let e = parse_oil_file(&text, "my-oil.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("shear_modulus"), "{e}");
        let text = OIL.replace("lambda_bd = 0.01", "lambda_bd = 3.0");
        assert!(parse_oil_file(&text, "my-oil.toml").is_err());
    }
}
