//! Oils: the lubricant library (and a user oil file) with its properties at a temperature, its
//! sources and its missing data (docs/lubricants.md).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::oil::OilChoice;
use crate::table::{Table, Tables};
use rolldyn_lubrication::viscosity_index::viscosity_index;
use rolldyn_lubrication::{Basis, KNOWN_OILS, Lubricant, OilProperty, lubricant_by_name};
use rolldyn_units::{Quantity, Temperature};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::PathBuf;

/// The oils at a temperature.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OilsRequest {
    /// Temperature at which the properties are evaluated (where every oil's laws give finite,
    /// positive values).
    #[serde(default = "forty_celsius")]
    pub temperature: Quantity<Temperature>,
    /// Also list a user oil file (TOML).
    #[serde(default)]
    pub oil_file: Option<PathBuf>,
}

fn forty_celsius() -> Quantity<Temperature> {
    Quantity::from_si(313.15)
}

/// One oil's properties at the temperature (SI; `None` where the source gives none).
#[derive(Clone, Debug, Serialize)]
pub struct OilRow {
    pub name: String,
    pub source: String,
    pub temperature_k: f64,
    pub in_range: bool,
    pub valid_range_k: [f64; 2],
    pub density_kg_m3: Option<f64>,
    pub dynamic_viscosity_pa_s: Option<f64>,
    pub kinematic_viscosity_m2_s: Option<f64>,
    pub pressure_viscosity_per_pa: Option<f64>,
    pub shear_modulus_pa: Option<f64>,
    pub eyring_stress_pa: Option<f64>,
    pub beta0_per_k: Option<f64>,
    pub kappa_per_k_pa: Option<f64>,
    pub thermal_conductivity_w_mk: Option<f64>,
    pub missing: Vec<String>,
    /// Oil class and grade (empty when the source gives none).
    pub class: String,
    /// ν at 40 and 100 °C (the points of the viscosity grade and index), m²/s.
    pub nu40_m2_s: Option<f64>,
    pub nu100_m2_s: Option<f64>,
    /// ASTM D2270 viscosity index from `nu40_m2_s` and `nu100_m2_s`.
    pub viscosity_index: Option<f64>,
    /// Keys of the properties from a measurement (standard, data sheet, test).
    pub measured: Vec<String>,
    /// Keys of the properties from a correlation, class value or another oil.
    pub estimated: Vec<String>,
    /// Each property's basis and source.
    pub provenance: Vec<ProvenanceRow>,
}

/// Where one property of an oil comes from.
#[derive(Clone, Debug, Serialize)]
pub struct ProvenanceRow {
    pub property: String,
    pub basis: String,
    pub source: String,
}

/// 40 °C and 100 °C, K: the temperatures of ISO 3448 grades and ASTM D2270.
const VISCOSITY_GRADE_TEMPERATURES_K: [f64; 2] = [313.15, 373.15];

impl OilRow {
    /// The properties of `oil` at `t` (K).
    pub fn of(oil: &Lubricant, t: f64) -> Self {
        let p = oil.properties(t);
        let [nu40, nu100] = VISCOSITY_GRADE_TEMPERATURES_K.map(|t| oil.kinematic_viscosity(t).ok());
        Self {
            name: oil.name.clone(),
            source: oil.source.clone(),
            temperature_k: t,
            in_range: oil.in_range(t),
            valid_range_k: oil.temperature_range_k,
            density_kg_m3: p.density,
            dynamic_viscosity_pa_s: p.dynamic_viscosity,
            kinematic_viscosity_m2_s: oil.kinematic_viscosity(t).ok(),
            pressure_viscosity_per_pa: p.pressure_viscosity,
            shear_modulus_pa: p.shear_modulus,
            eyring_stress_pa: p.eyring_stress,
            beta0_per_k: p.beta0,
            kappa_per_k_pa: p.kappa,
            thermal_conductivity_w_mk: p.thermal_conductivity,
            missing: oil.missing.clone(),
            class: oil.class.clone(),
            nu40_m2_s: nu40,
            nu100_m2_s: nu100,
            viscosity_index: nu40
                .zip(nu100)
                .and_then(|(a, b)| viscosity_index(a, b).ok()),
            measured: keys(oil.properties_with(Basis::Measured)),
            estimated: keys(oil.properties_with(Basis::Estimated)),
            provenance: oil
                .provenance
                .iter()
                .map(|s| ProvenanceRow {
                    property: s.property.key().into(),
                    basis: s.basis.name().into(),
                    source: s.source.clone(),
                })
                .collect(),
        }
    }

    /// The first property whose law gives no finite positive value at the row's temperature.
    fn outside_law(&self) -> Option<(&'static str, f64)> {
        [
            ("density", self.density_kg_m3),
            ("dynamic viscosity", self.dynamic_viscosity_pa_s),
            ("kinematic viscosity", self.kinematic_viscosity_m2_s),
            (
                "pressure-viscosity coefficient",
                self.pressure_viscosity_per_pa,
            ),
            ("shear modulus", self.shear_modulus_pa),
            ("Eyring stress", self.eyring_stress_pa),
            ("thermal conductivity", self.thermal_conductivity_w_mk),
        ]
        .into_iter()
        .find_map(|(name, value)| {
            value
                .filter(|v| !(v.is_finite() && *v > 0.0))
                .map(|v| (name, v))
        })
    }
}

fn keys(properties: Vec<OilProperty>) -> Vec<String> {
    properties.iter().map(|p| p.key().to_string()).collect()
}

/// Short symbol of a property in the text listing.
fn symbol(key: &str) -> &str {
    match OilProperty::from_key(key) {
        Some(OilProperty::Viscosity) => "ν",
        Some(OilProperty::Density) => "ρ",
        Some(OilProperty::PressureViscosity) => "α",
        Some(OilProperty::ShearModulus) => "Γ",
        Some(OilProperty::EyringStress) => "τ0",
        Some(OilProperty::Beta0) => "β0",
        Some(OilProperty::Kappa) => "κ",
        Some(OilProperty::ThermalConductivity) => "K",
        Some(OilProperty::MixedFriction) => "Λ",
        None => key,
    }
}

/// The oils at the temperature; serialised as the list of rows.
#[derive(Clone, Debug, Serialize)]
#[serde(transparent)]
pub struct OilsResult {
    pub oils: Vec<OilRow>,
    /// The temperature, K, for the text heading.
    #[serde(skip)]
    pub temperature_k: f64,
}

impl Tables for OilsResult {
    /// `oils`: one row per oil, a missing property as NaN, `in_range` 1 or 0.
    fn tables(&self) -> Vec<Table> {
        let real = |f: fn(&OilRow) -> Option<f64>| {
            self.oils.iter().map(|r| f(r).unwrap_or(f64::NAN)).collect()
        };
        let text = |f: fn(&OilRow) -> String| self.oils.iter().map(f).collect();
        vec![
            Table::new("oils")
                .text("name", text(|r| r.name.clone()))
                .text("source", text(|r| r.source.clone()))
                .real("temperature_k", real(|r| Some(r.temperature_k)))
                .integer(
                    "in_range",
                    self.oils.iter().map(|r| i64::from(r.in_range)).collect(),
                )
                .real("valid_range_min_k", real(|r| Some(r.valid_range_k[0])))
                .real("valid_range_max_k", real(|r| Some(r.valid_range_k[1])))
                .real("density_kg_m3", real(|r| r.density_kg_m3))
                .real("dynamic_viscosity_pa_s", real(|r| r.dynamic_viscosity_pa_s))
                .real(
                    "kinematic_viscosity_m2_s",
                    real(|r| r.kinematic_viscosity_m2_s),
                )
                .real(
                    "pressure_viscosity_per_pa",
                    real(|r| r.pressure_viscosity_per_pa),
                )
                .real("shear_modulus_pa", real(|r| r.shear_modulus_pa))
                .real("eyring_stress_pa", real(|r| r.eyring_stress_pa))
                .real("beta0_per_k", real(|r| r.beta0_per_k))
                .real("kappa_per_k_pa", real(|r| r.kappa_per_k_pa))
                .real(
                    "thermal_conductivity_w_mk",
                    real(|r| r.thermal_conductivity_w_mk),
                )
                .text("missing", text(|r| r.missing.join("; ")))
                .text("class", text(|r| r.class.clone()))
                .real("nu40_m2_s", real(|r| r.nu40_m2_s))
                .real("nu100_m2_s", real(|r| r.nu100_m2_s))
                .real("viscosity_index", real(|r| r.viscosity_index))
                .text("measured", text(|r| r.measured.join(" ")))
                .text("estimated", text(|r| r.estimated.join(" "))),
        ]
    }
}

impl fmt::Display for OilsResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let cell = |v: Option<f64>, scale: f64, digits: usize| {
            v.map_or("—".to_string(), |v| format!("{:.*}", digits, v * scale))
        };
        writeln!(
            f,
            "Lubricants at {:.1} °C (— = not given by the source)\n",
            self.temperature_k - 273.15
        )?;
        writeln!(
            f,
            "{:<18} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>8} {:>8}  range °C",
            "name",
            "ρ kg/m³",
            "η mPa·s",
            "ν mm²/s",
            "α 1/GPa",
            "Γ GPa",
            "τ0 MPa",
            "β0 1/K",
            "K W/mK"
        )?;
        for r in &self.oils {
            writeln!(
                f,
                "{:<18} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>8} {:>8}  {:.0}…{:.0}{}",
                r.name,
                cell(r.density_kg_m3, 1.0, 0),
                cell(r.dynamic_viscosity_pa_s, 1e3, 2),
                cell(r.kinematic_viscosity_m2_s, 1e6, 1),
                cell(r.pressure_viscosity_per_pa, 1e9, 1),
                cell(r.shear_modulus_pa, 1e-9, 3),
                cell(r.eyring_stress_pa, 1e-6, 2),
                cell(r.beta0_per_k, 1.0, 4),
                cell(r.thermal_conductivity_w_mk, 1.0, 3),
                r.valid_range_k[0] - 273.15,
                r.valid_range_k[1] - 273.15,
                if r.in_range { "" } else { "  (outside range)" }
            )?;
        }
        writeln!(
            f,
            "\n{:<18} {:<40} {:>8} {:>8} {:>5}  {:<18} estimated",
            "name", "class", "ν40", "ν100", "VI", "measured"
        )?;
        let symbols =
            |keys: &[String]| keys.iter().map(|k| symbol(k)).collect::<Vec<_>>().join(" ");
        for r in &self.oils {
            writeln!(
                f,
                "{:<18} {:<40} {:>8} {:>8} {:>5}  {:<18} {}",
                r.name,
                if r.class.is_empty() { "—" } else { &r.class },
                cell(r.nu40_m2_s, 1e6, 2),
                cell(r.nu100_m2_s, 1e6, 2),
                cell(r.viscosity_index, 1.0, 0),
                symbols(&r.measured),
                symbols(&r.estimated)
            )?;
        }
        let mut sources = Vec::new();
        for r in &self.oils {
            sources.push(format!("{}: {}", r.name, r.source));
            for p in &r.provenance {
                sources.push(format!("    {} ({}): {}", p.property, p.basis, p.source));
            }
            if !r.missing.is_empty() {
                sources.push(format!("    missing: {}", r.missing.join("; ")));
            }
        }
        write!(f, "\n{}", sources.join("\n"))
    }
}

/// The oils analysis.
pub struct Oils;

impl Analysis for Oils {
    const NAME: &'static str = "oils";
    type Request = OilsRequest;
    type Result = OilsResult;

    fn run(request: &OilsRequest, _context: &Context<'_>) -> Result<OilsResult, Failure> {
        let t = request.temperature.si();
        let mut oils: Vec<Lubricant> = KNOWN_OILS
            .iter()
            .map(|name| lubricant_by_name(name).map_err(|e| Failure::Run(e.to_string())))
            .collect::<Result<_, _>>()?;
        if let Some(path) = &request.oil_file {
            let user = OilChoice {
                oil_file: Some(path.clone()),
                ..OilChoice::default()
            };
            oils.push(user.load()?);
        }
        let rows: Vec<OilRow> = oils.iter().map(|o| OilRow::of(o, t)).collect();
        if let Some((r, (property, value))) =
            rows.iter().find_map(|r| r.outside_law().map(|p| (r, p)))
        {
            return Err(Failure::Input(format!(
                "--temperature {:.1} °C is outside the laws of {}: its {property} would be \
                 {value:e} (documented range {:.0}…{:.0} °C)",
                t - 273.15,
                r.name,
                r.valid_range_k[0] - 273.15,
                r.valid_range_k[1] - 273.15
            )));
        }
        Ok(OilsResult {
            oils: rows,
            temperature_k: t,
        })
    }
}
