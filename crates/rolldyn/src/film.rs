//! Film: central and minimum film thickness, Λ and regime of a lubricated contact
//! (SPEC §4.3, §4.7).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::oil::{ContactKind, OilChoice, Rig};
use crate::table::Tables;
use rolldyn_lubrication::film::{GREASE_STARVATION_FACTOR, film_thickness};
use rolldyn_lubrication::{ContactState, FilmFormula, FilmSettings, LambdaDefinition};
use rolldyn_units::{Force, Length, Quantity, Speed, Temperature};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Which film formula.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum FormulaName {
    /// Seed 000 choice: (2.17) for line contacts, (2.19) for point contacts.
    #[default]
    Auto,
    /// Rigid–piezoviscous line contact, seed 000 eq. (2.17).
    RigidPiezoviscous,
    /// Piezoviscous–elastic point contact, seed 000 eq. (2.19).
    PiezoviscousElastic,
    /// Seed 001 formula with its thermal factor K_p.
    Seed001,
    /// Pan–Hamrock line contact.
    PanHamrock,
    /// Hamrock–Dowson point contact.
    HamrockDowson,
}

/// Which definition of the film parameter Λ.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum LambdaName {
    /// Λ = h/(1.25 √(Ra₁² + Ra₂²)), seed 000 eq. (1.2).
    #[default]
    Seed000,
    /// Λ = h/√(Ra₁² + Ra₂²), Tallian, seed 001.
    Tallian,
}

/// A film analysis: the oil, the contact and its operating point.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FilmRequest {
    #[serde(default)]
    pub oil: OilChoice,
    #[serde(default)]
    pub rig: Rig,
    #[serde(default = "forty_celsius")]
    pub temperature: Quantity<Temperature>,
    /// Normal load of the contact.
    pub load: Quantity<Force>,
    /// Rolling (entrainment) speed u.
    pub rolling_speed: Quantity<Speed>,
    /// Roughness Ra of the two surfaces.
    #[serde(default)]
    pub roughness: Vec<Quantity<Length>>,
    #[serde(default)]
    pub formula: FormulaName,
    #[serde(default)]
    pub lambda: LambdaName,
    /// Inlet starvation: both films multiplied by this factor (1 = flooded).
    #[serde(default = "flooded")]
    pub starvation: f64,
    /// Grease lubrication: starvation factor 0.7 (seed 000, −30 %).
    #[serde(default)]
    pub grease: bool,
}

fn forty_celsius() -> Quantity<Temperature> {
    Quantity::from_si(313.15)
}

fn flooded() -> f64 {
    1.0
}

/// The film of the contact.
#[derive(Clone, Debug, Serialize)]
pub struct FilmResult {
    pub oil: String,
    pub central_film_m: f64,
    pub min_film_m: f64,
    pub lambda: f64,
    pub regime: String,
    pub formula: &'static str,
    pub g1: Option<f64>,
    pub g2: Option<f64>,
    pub thermal_factor_kp: Option<f64>,
    pub piezoviscous_elastic_condition: Option<bool>,
    /// The operating point, for the text heading.
    #[serde(skip)]
    heading: String,
}

impl Tables for FilmResult {}

impl fmt::Display for FilmResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}", self.heading)?;
        writeln!(f, "  formula        {}", self.formula)?;
        writeln!(f, "  central film   {:.4} µm", self.central_film_m * 1e6)?;
        writeln!(f, "  minimum film   {:.4} µm", self.min_film_m * 1e6)?;
        writeln!(f, "  Λ              {:.3}", self.lambda)?;
        write!(f, "  regime         {}", self.regime)
    }
}

/// The film analysis.
pub struct Film;

impl Analysis for Film {
    const NAME: &'static str = "film";
    type Request = FilmRequest;
    type Result = FilmResult;

    fn run(request: &FilmRequest, context: &Context<'_>) -> Result<FilmResult, Failure> {
        let oil = request.oil.load()?;
        let t = request.temperature.si();
        request.oil.check_temperature(&oil, t, context)?;
        let (geometry, r, e) = request.rig.geometry()?;
        rolldyn_model::bounds::check_rolling_speed("--rolling-speed", request.rolling_speed.si())
            .map_err(|e| Failure::Input(e.to_string()))?;
        request.rig.check_load("--load", request.load.si())?;
        let roughness = match request.roughness.as_slice() {
            [] => [0.0, 0.0],
            [a] => [a.si(), 0.0],
            [a, b] => [a.si(), b.si()],
            _ => return Err(Failure::Input("--roughness takes one or two values".into())),
        };
        if roughness.iter().any(|r| *r < 0.0) {
            return Err(Failure::Input("--roughness must not be negative".into()));
        }
        let starvation = if request.grease {
            GREASE_STARVATION_FACTOR
        } else {
            request.starvation
        };
        if !(starvation > 0.0 && starvation <= 1.0) {
            return Err(Failure::Input("--starvation must lie in (0, 1]".into()));
        }
        let formula = match request.formula {
            FormulaName::Auto => FilmFormula::Auto,
            FormulaName::RigidPiezoviscous => FilmFormula::RigidPiezoviscousLine,
            FormulaName::PiezoviscousElastic => FilmFormula::PiezoviscousElasticPoint,
            FormulaName::Seed001 => FilmFormula::Seed001,
            FormulaName::PanHamrock => FilmFormula::PanHamrockLine,
            FormulaName::HamrockDowson => FilmFormula::HamrockDowsonPoint,
        };
        let state = ContactState {
            normal_force_n: request.load.si(),
            geometry,
            reduced_radius_m: r,
            reduced_modulus_pa: e,
            rolling_speed_m_s: request.rolling_speed.si(),
            sliding_speed_m_s: 0.0,
            temperature_k: t,
            roughness_ra_m: roughness,
            film_thickness_m: None,
        };
        let settings = FilmSettings {
            formula,
            starvation_factor: starvation,
            ..FilmSettings::default()
        };
        let lambda = match request.lambda {
            LambdaName::Seed000 => LambdaDefinition::Seed000,
            LambdaName::Tallian => LambdaDefinition::Tallian,
        };
        let film = film_thickness(&state, &oil, &settings, lambda)
            .map_err(|e| Failure::Input(e.to_string()))?;
        let kind = match request.rig.contact {
            ContactKind::Line => "line",
            ContactKind::BallOnDisc => "point",
        };
        Ok(FilmResult {
            heading: format!(
                "{}: {kind} contact, {:.1} N, u = {:.3} m/s, {:.1} °C",
                oil.name,
                request.load.si(),
                request.rolling_speed.si(),
                t - 273.15
            ),
            oil: oil.name.clone(),
            central_film_m: film.central_m,
            min_film_m: film.minimum_m,
            lambda: film.lambda,
            regime: format!("{:?}", film.regime),
            formula: film.formula_name(),
            g1: film.g1,
            g2: film.g2,
            thermal_factor_kp: film.thermal_factor_kp,
            piezoviscous_elastic_condition: film.pve_condition,
        })
    }
}
