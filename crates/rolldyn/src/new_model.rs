//! New model: a cylindrical roller bearing model file from an ISO designation (`NU2215`) or from
//! its boundary dimensions, by the design rules of `rolldyn_design` (docs/theory.md, "A model
//! from a designation"). The model written is loaded and checked before it is returned.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::table::Tables;
use rolldyn_design::{
    Boundary, CageMaterial, ClearanceGroup, DesignInput, OperatingPoint, RibArrangement,
    designation, model_file,
};
use rolldyn_units::{AngularSpeed, Force, Length, Quantity, Temperature};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::PathBuf;

/// The cage material.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum CageName {
    /// Machined brass CuZn40Pb2.
    #[default]
    Brass,
    /// Machined steel AISI 4340.
    Steel,
    /// PEEK.
    Peek,
    /// Polyamide PA66-GF25.
    Pa66,
}

/// The ISO 5753-1 clearance group.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "UPPERCASE")]
pub enum ClearanceGroupName {
    #[cfg_attr(feature = "clap", value(name = "C2"))]
    C2,
    #[default]
    #[cfg_attr(feature = "clap", value(name = "CN"))]
    CN,
    #[cfg_attr(feature = "clap", value(name = "C3"))]
    C3,
    #[cfg_attr(feature = "clap", value(name = "C4"))]
    C4,
}

/// Which ring has the ribs, for the boundary form (a designation says it).
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "UPPERCASE")]
pub enum RibsName {
    #[default]
    #[cfg_attr(feature = "clap", value(name = "NU"))]
    NU,
    #[cfg_attr(feature = "clap", value(name = "NJ"))]
    NJ,
    #[cfg_attr(feature = "clap", value(name = "NUP"))]
    NUP,
    #[cfg_attr(feature = "clap", value(name = "N"))]
    N,
}

/// A new model: a designation, or the boundary dimensions; catalogue values where known; the
/// operating point to write, if any.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NewModelRequest {
    /// ISO designation, e.g. `NU2215`, `NJ 310`.
    #[serde(default)]
    pub designation: Option<String>,
    /// Boundary form: bore d, outside diameter D, width B (all three, without a designation).
    #[serde(default)]
    pub bore: Option<Quantity<Length>>,
    #[serde(default)]
    pub outside: Option<Quantity<Length>>,
    #[serde(default)]
    pub width: Option<Quantity<Length>>,
    /// Boundary form: type (which ring has the ribs), NU unless given.
    #[serde(default, rename = "type")]
    pub ribs: Option<RibsName>,
    #[serde(default)]
    pub roller_diameter: Option<Quantity<Length>>,
    #[serde(default)]
    pub roller_length: Option<Quantity<Length>>,
    #[serde(default)]
    pub rollers: Option<usize>,
    #[serde(default)]
    pub cage: CageName,
    #[serde(default)]
    pub clearance_group: ClearanceGroupName,
    /// Built-in oil name (default: `rolldyn_design::ASSUMED_OIL`, named as assumed).
    #[serde(default)]
    pub oil: Option<String>,
    /// Name of the bearing in the model (the designation, or d×D×B).
    #[serde(default)]
    pub name: Option<String>,
    /// Inner-ring speed, radial load and oil temperature to write as `[operating]`.
    #[serde(default)]
    pub speed: Option<Quantity<AngularSpeed>>,
    #[serde(default)]
    pub radial_load: Option<Quantity<Force>>,
    #[serde(default)]
    pub oil_temperature: Option<Quantity<Temperature>>,
    /// Write the model to this file (else it is only returned).
    #[serde(default)]
    pub out: Option<PathBuf>,
}

/// The model written, with its main dimensions (SI).
#[derive(Clone, Debug, Serialize)]
pub struct NewModelResult {
    pub name: String,
    /// The model file's text.
    pub toml: String,
    /// The file written, if any.
    pub file: Option<String>,
    pub bore_m: f64,
    pub outside_diameter_m: f64,
    pub width_m: f64,
    pub roller_diameter_m: f64,
    pub roller_length_m: f64,
    pub rollers: usize,
    pub pitch_diameter_m: f64,
    pub radial_clearance_m: f64,
    pub cage_material: String,
    pub oil: String,
    /// Stand-ins for missing input (also given as warnings).
    pub warnings: Vec<String>,
}

impl Tables for NewModelResult {}

impl fmt::Display for NewModelResult {
    /// The model text, or, when a file was written, what it holds.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Some(file) = &self.file else {
            return write!(f, "{}", self.toml.trim_end());
        };
        writeln!(
            f,
            "{}: wrote {file} ({} × {} × {} mm, {} rollers Ø{} × {} mm, D_pw {:.3} mm, G_r {:.1} µm, \
             cage {}, oil {})",
            self.name,
            self.bore_m * 1e3,
            self.outside_diameter_m * 1e3,
            self.width_m * 1e3,
            self.rollers,
            self.roller_diameter_m * 1e3,
            self.roller_length_m * 1e3,
            self.pitch_diameter_m * 1e3,
            self.radial_clearance_m * 1e6,
            self.cage_material,
            self.oil
        )?;
        write!(
            f,
            "  values marked ESTIMATED in the file are design-rule estimates; next: rolldyn check {file}"
        )
    }
}

/// The new-model analysis.
pub struct NewModel;

impl Analysis for NewModel {
    const NAME: &'static str = "new";
    type Request = NewModelRequest;
    type Result = NewModelResult;

    fn run(request: &NewModelRequest, context: &Context<'_>) -> Result<NewModelResult, Failure> {
        let input = design_input(request)?;
        let design =
            rolldyn_design::design(&input).map_err(|e| Failure::Input(format!("new: {e}")))?;
        let text = model_file::write(&design);
        rolldyn_model::parse(&text, &format!("<rolldyn new {}>", input.name)).map_err(|e| {
            Failure::Input(format!(
                "new: the model designed for {} does not load: {e}",
                input.name
            ))
        })?;
        for warning in &design.warnings {
            context.observer.warning(warning);
        }
        let file = match &request.out {
            Some(path) => {
                std::fs::write(path, &text).map_err(|e| {
                    Failure::Run(format!("new: cannot write {}: {e}", path.display()))
                })?;
                Some(path.display().to_string())
            }
            None => None,
        };
        let b = &input.boundary;
        Ok(NewModelResult {
            name: input.name.clone(),
            toml: text,
            file,
            bore_m: b.bore,
            outside_diameter_m: b.outside,
            width_m: b.width,
            roller_diameter_m: design.roller_diameter.value,
            roller_length_m: design.roller_length.value,
            rollers: design.roller_count,
            pitch_diameter_m: design.pitch_diameter.value,
            radial_clearance_m: design.clearance.value,
            cage_material: input.cage.material().to_string(),
            oil: input.oil_name().to_string(),
            warnings: design.warnings.clone(),
        })
    }
}

/// The generator's input from the request: the designation's ISO 15 row or the three boundary
/// dimensions (not both).
fn design_input(r: &NewModelRequest) -> Result<DesignInput, Failure> {
    let given = [&r.bore, &r.outside, &r.width]
        .iter()
        .filter(|q| q.is_some())
        .count();
    let (name, ribs, boundary) = match (&r.designation, given) {
        (Some(text), 0) => {
            if r.ribs.is_some() {
                return Err(Failure::Input(
                    "new: --type applies to the boundary form; a designation gives its type".into(),
                ));
            }
            let d = designation::parse(text).map_err(|e| Failure::Input(format!("new: {e}")))?;
            let boundary = Boundary {
                bore: d.row.bore_mm * 1e-3,
                outside: d.row.outside_mm * 1e-3,
                width: d.row.width_mm * 1e-3,
                chamfer_min: Some(d.row.chamfer_min_mm * 1e-3),
                source: d.series.table().to_string(),
            };
            (d.text.clone(), d.ribs, boundary)
        }
        (Some(_), _) => {
            return Err(Failure::Input(
                "new: give a designation or --bore/--outside/--width, not both".into(),
            ));
        }
        (None, 3) => {
            let (d, o, w) = (si(&r.bore), si(&r.outside), si(&r.width));
            let ribs = match r.ribs.unwrap_or_default() {
                RibsName::NU => RibArrangement::Nu,
                RibsName::NJ => RibArrangement::Nj,
                RibsName::NUP => RibArrangement::Nup,
                RibsName::N => RibArrangement::N,
            };
            let boundary = Boundary {
                bore: d,
                outside: o,
                width: w,
                chamfer_min: None,
                source: "given (--bore, --outside, --width)".into(),
            };
            let name = format!("{}{}x{}x{}", ribs.letters(), d * 1e3, o * 1e3, w * 1e3);
            (name, ribs, boundary)
        }
        (None, _) => {
            return Err(Failure::Input(
                "new: give a designation (e.g. NU2215) or all of --bore, --outside, --width \
                 (e.g. --bore 75mm --outside 130mm --width 31mm)"
                    .into(),
            ));
        }
    };
    let operating = match (&r.speed, &r.radial_load) {
        (Some(speed), Some(load)) => Some(OperatingPoint {
            speed: speed.si(),
            radial_load: load.si(),
            oil_temperature: r.oil_temperature.as_ref().map(|t| t.si()),
        }),
        (None, None) if r.oil_temperature.is_none() => None,
        _ => {
            return Err(Failure::Input(
                "new: [operating] needs both --speed and --radial-load (--oil-temperature \
                 optional with them)"
                    .into(),
            ));
        }
    };
    Ok(DesignInput {
        name: r.name.clone().unwrap_or(name),
        ribs,
        boundary,
        roller_diameter: r.roller_diameter.as_ref().map(|q| q.si()),
        roller_length: r.roller_length.as_ref().map(|q| q.si()),
        rollers: r.rollers,
        cage: match r.cage {
            CageName::Brass => CageMaterial::Brass,
            CageName::Steel => CageMaterial::Steel,
            CageName::Peek => CageMaterial::Peek,
            CageName::Pa66 => CageMaterial::Pa66,
        },
        clearance_group: match r.clearance_group {
            ClearanceGroupName::C2 => ClearanceGroup::C2,
            ClearanceGroupName::CN => ClearanceGroup::CN,
            ClearanceGroupName::C3 => ClearanceGroup::C3,
            ClearanceGroupName::C4 => ClearanceGroup::C4,
        },
        oil: r.oil.clone(),
        operating,
    })
}

fn si(q: &Option<Quantity<Length>>) -> f64 {
    q.as_ref().map_or(f64::NAN, |q| q.si())
}
