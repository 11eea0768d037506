//! `rolldyn film`: central and minimum film thickness, Λ and regime of a lubricated contact
//! (SPEC §4.3, §4.7).

use super::oil_args::OilArgs;
use super::rig_args::{ContactKind, RigArgs};
use crate::failure::Failure;
use crate::output::print_json;
use rolldyn_lubrication::film::{GREASE_STARVATION_FACTOR, film_thickness};
use rolldyn_lubrication::{ContactState, FilmFormula, FilmSettings, LambdaDefinition};
use rolldyn_units::{Force, Length, Quantity, Speed, Temperature};
use serde::Serialize;

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum FormulaName {
    /// Seed 000 choice: (2.17) for line contacts, (2.19) for point contacts.
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

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum LambdaName {
    /// Λ = h/(1.25 √(Ra₁² + Ra₂²)), seed 000 eq. (1.2).
    Seed000,
    /// Λ = h/√(Ra₁² + Ra₂²), Tallian, seed 001.
    Tallian,
}

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub oil: OilArgs,
    #[command(flatten)]
    pub rig: RigArgs,
    #[arg(long, allow_hyphen_values = true, default_value = "40C")]
    pub temperature: Quantity<Temperature>,
    /// Normal load of the contact.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Quantity<Force>,
    /// Rolling (entrainment) speed u.
    #[arg(long, allow_hyphen_values = true)]
    pub rolling_speed: Quantity<Speed>,
    /// Roughness Ra of the two surfaces, e.g. `0.32um,0.16um`.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_delimiter = ',',
        default_value = "0,0"
    )]
    pub roughness: Vec<Quantity<Length>>,
    #[arg(long, value_enum, default_value = "auto")]
    pub formula: FormulaName,
    #[arg(long, value_enum, default_value = "seed000")]
    pub lambda: LambdaName,
    /// Inlet starvation: multiply both films by this factor (1 = flooded).
    #[arg(long, default_value = "1", conflicts_with = "grease")]
    pub starvation: f64,
    /// Grease lubrication: starvation factor 0.7 (seed 000, −30 %).
    #[arg(long)]
    pub grease: bool,
    #[arg(long)]
    pub json: bool,
}

#[derive(Serialize)]
struct Answer {
    oil: String,
    central_film_m: f64,
    min_film_m: f64,
    lambda: f64,
    regime: String,
    formula: &'static str,
    g1: Option<f64>,
    g2: Option<f64>,
    thermal_factor_kp: Option<f64>,
    piezoviscous_elastic_condition: Option<bool>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let oil = args.oil.load()?;
    let t = args.temperature.si();
    args.oil.check_temperature(&oil, t)?;
    let (geometry, r, e) = args.rig.geometry()?;
    let roughness = match args.roughness.as_slice() {
        [a] => [a.si(), 0.0],
        [a, b] => [a.si(), b.si()],
        _ => return Err(Failure::Input("--roughness takes one or two values".into())),
    };
    if roughness.iter().any(|r| *r < 0.0) {
        return Err(Failure::Input("--roughness must not be negative".into()));
    }
    let starvation = if args.grease {
        GREASE_STARVATION_FACTOR
    } else {
        args.starvation
    };
    if !(starvation > 0.0 && starvation <= 1.0) {
        return Err(Failure::Input("--starvation must lie in (0, 1]".into()));
    }
    let formula = match args.formula {
        FormulaName::Auto => FilmFormula::Auto,
        FormulaName::RigidPiezoviscous => FilmFormula::RigidPiezoviscousLine,
        FormulaName::PiezoviscousElastic => FilmFormula::PiezoviscousElasticPoint,
        FormulaName::Seed001 => FilmFormula::Seed001,
        FormulaName::PanHamrock => FilmFormula::PanHamrockLine,
        FormulaName::HamrockDowson => FilmFormula::HamrockDowsonPoint,
    };
    let state = ContactState {
        normal_force_n: args.load.si(),
        geometry,
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: args.rolling_speed.si(),
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
    let lambda = match args.lambda {
        LambdaName::Seed000 => LambdaDefinition::Seed000,
        LambdaName::Tallian => LambdaDefinition::Tallian,
    };
    let f = film_thickness(&state, &oil, &settings, lambda)
        .map_err(|e| Failure::Input(e.to_string()))?;
    let answer = Answer {
        oil: oil.name.clone(),
        central_film_m: f.central_m,
        min_film_m: f.minimum_m,
        lambda: f.lambda,
        regime: format!("{:?}", f.regime),
        formula: f.formula_name(),
        g1: f.g1,
        g2: f.g2,
        thermal_factor_kp: f.thermal_factor_kp,
        piezoviscous_elastic_condition: f.pve_condition,
    };
    if args.json {
        return print_json(&answer);
    }
    let kind = if args.rig.contact == ContactKind::Line {
        "line"
    } else {
        "point"
    };
    println!(
        "{}: {kind} contact, {:.1} N, u = {:.3} m/s, {:.1} °C",
        answer.oil,
        args.load.si(),
        args.rolling_speed.si(),
        t - 273.15
    );
    println!("  formula        {}", answer.formula);
    println!("  central film   {:.4} µm", answer.central_film_m * 1e6);
    println!("  minimum film   {:.4} µm", answer.min_film_m * 1e6);
    println!("  Λ              {:.3}", answer.lambda);
    println!("  regime         {}", answer.regime);
    Ok(())
}
