//! `rolldyn oils [--temperature 40C] [--json]`: the lubricant library with properties at a
//! temperature.

use crate::failure::Failure;
use crate::output::print_json;
use rolldyn_lubrication::{KNOWN_OILS, Lubricant, lubricant_by_name};
use rolldyn_units::{Quantity, Temperature};
use serde::Serialize;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Temperature at which the properties are evaluated (where every oil's laws give finite,
    /// positive values).
    #[arg(long, default_value = "40C", allow_hyphen_values = true)]
    pub temperature: Quantity<Temperature>,
    /// Also list a user oil file (TOML).
    #[arg(long)]
    pub oil_file: Option<PathBuf>,
    #[arg(long)]
    pub json: bool,
}

#[derive(Serialize)]
struct OilRow {
    name: String,
    source: String,
    temperature_k: f64,
    in_range: bool,
    valid_range_k: [f64; 2],
    density_kg_m3: Option<f64>,
    dynamic_viscosity_pa_s: Option<f64>,
    kinematic_viscosity_m2_s: Option<f64>,
    pressure_viscosity_per_pa: Option<f64>,
    shear_modulus_pa: Option<f64>,
    eyring_stress_pa: Option<f64>,
    beta0_per_k: Option<f64>,
    kappa_per_k_pa: Option<f64>,
    thermal_conductivity_w_mk: Option<f64>,
    missing: Vec<String>,
}

fn row(oil: &Lubricant, t: f64) -> OilRow {
    let p = oil.properties(t);
    OilRow {
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
    }
}

/// The first property of `r` whose law gives no finite positive value at its temperature.
fn outside_law(r: &OilRow) -> Option<(&'static str, f64)> {
    [
        ("density", r.density_kg_m3),
        ("dynamic viscosity", r.dynamic_viscosity_pa_s),
        ("kinematic viscosity", r.kinematic_viscosity_m2_s),
        (
            "pressure-viscosity coefficient",
            r.pressure_viscosity_per_pa,
        ),
        ("shear modulus", r.shear_modulus_pa),
        ("Eyring stress", r.eyring_stress_pa),
        ("thermal conductivity", r.thermal_conductivity_w_mk),
    ]
    .into_iter()
    .find_map(|(name, value)| {
        value
            .filter(|v| !(v.is_finite() && *v > 0.0))
            .map(|v| (name, v))
    })
}

pub fn run(args: Args) -> Result<(), Failure> {
    let t = args.temperature.si();
    let mut oils: Vec<Lubricant> = KNOWN_OILS
        .iter()
        .map(|name| lubricant_by_name(name).map_err(|e| Failure::Run(e.to_string())))
        .collect::<Result<_, _>>()?;
    if let Some(path) = args.oil_file {
        let user = super::oil_args::OilArgs {
            oil: String::new(),
            oil_file: Some(path),
            strict: false,
        };
        oils.push(user.choice().load()?);
    }
    let rows: Vec<OilRow> = oils.iter().map(|o| row(o, t)).collect();
    if let Some((r, (property, value))) = rows.iter().find_map(|r| outside_law(r).map(|p| (r, p))) {
        return Err(Failure::Input(format!(
            "--temperature {:.1} °C is outside the laws of {}: its {property} would be {value:e} \
             (documented range {:.0}…{:.0} °C)",
            t - 273.15,
            r.name,
            r.valid_range_k[0] - 273.15,
            r.valid_range_k[1] - 273.15
        )));
    }
    if args.json {
        return print_json(&rows);
    }
    let fmt = |v: Option<f64>, scale: f64, digits: usize| {
        v.map_or("—".to_string(), |v| format!("{:.*}", digits, v * scale))
    };
    println!(
        "Lubricants at {:.1} °C (— = not given by the source)\n",
        t - 273.15
    );
    println!(
        "{:<18} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>8} {:>8}  range °C",
        "name", "ρ kg/m³", "η mPa·s", "ν mm²/s", "α 1/GPa", "Γ GPa", "τ0 MPa", "β0 1/K", "K W/mK"
    );
    for r in &rows {
        println!(
            "{:<18} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9} {:>8} {:>8}  {:.0}…{:.0}{}",
            r.name,
            fmt(r.density_kg_m3, 1.0, 0),
            fmt(r.dynamic_viscosity_pa_s, 1e3, 2),
            fmt(r.kinematic_viscosity_m2_s, 1e6, 1),
            fmt(r.pressure_viscosity_per_pa, 1e9, 1),
            fmt(r.shear_modulus_pa, 1e-9, 3),
            fmt(r.eyring_stress_pa, 1e-6, 2),
            fmt(r.beta0_per_k, 1.0, 4),
            fmt(r.thermal_conductivity_w_mk, 1.0, 3),
            r.valid_range_k[0] - 273.15,
            r.valid_range_k[1] - 273.15,
            if r.in_range { "" } else { "  (outside range)" }
        );
    }
    println!();
    for r in &rows {
        println!("{}: {}", r.name, r.source);
        if !r.missing.is_empty() {
            println!("    missing: {}", r.missing.join("; "));
        }
    }
    Ok(())
}
