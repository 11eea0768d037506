//! `rolldyn ehl-line`: lubricated roller–plate line contact by the Reynolds equation (SPEC
//! §8.4–8.5, seed 002 ch. 3 and 5) for a given minimum film or load per length, and a load step
//! (`--step-to`) (`rolldyn::ehl_line`).

use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::ehl_line::{DensityName, EhlLine, EhlLineRequest, LawName};
use rolldyn_units::{
    DynamicViscosity, Length, LoadPerLength, Mass, PerPressure, Pressure, Quantity, Speed, Time,
};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// (Reduced) roller radius R.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Quantity<Length>,
    /// Dynamic viscosity μ₀ at ambient pressure.
    #[arg(long, allow_hyphen_values = true)]
    pub viscosity: Quantity<DynamicViscosity>,
    /// Rolling (entrainment) speed u_m = (u₁ + u₂)/2; the seed's V = u₁ + u₂ = 2u_m.
    #[arg(long, allow_hyphen_values = true)]
    pub rolling_speed: Quantity<Speed>,
    /// Minimum film thickness h_m (given-film mode).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "load_per_length")]
    pub min_film: Option<Quantity<Length>>,
    /// Load per unit length (inverse mode): N/m, kN/m, MN/m, N/mm, kN/mm (e.g. 300kN/m).
    #[arg(long, allow_hyphen_values = true)]
    pub load_per_length: Option<Quantity<LoadPerLength>>,
    /// Pressure–viscosity coefficient α: 1/Pa, /Pa, 1/GPa, /GPa (e.g. 7.5e-9/Pa); 0 = isoviscous.
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub piezo: Quantity<PerPressure>,
    /// Pressure–viscosity law used with --piezo.
    #[arg(long, value_enum, default_value = "barus")]
    pub law: LawName,
    /// Density law.
    #[arg(long, value_enum, default_value = "incompressible")]
    pub density: DensityName,
    /// Elastic bodies: none | half-space (roller and plate half-spaces) | plate:THICKNESS
    /// (bonded plate of that thickness + roller compressed about its axis).
    #[arg(long, default_value = "none")]
    pub elastic: String,
    /// Young's modulus of both bodies.
    #[arg(long, allow_hyphen_values = true, default_value = "210GPa")]
    pub modulus: Quantity<Pressure>,
    /// Poisson ratio of both bodies.
    #[arg(long, default_value = "0.3")]
    pub poisson: f64,
    /// Normal approach speed dh/dt (positive = separating).
    #[arg(long, default_value = "0m/s", allow_hyphen_values = true)]
    pub squeeze_velocity: Quantity<Speed>,
    /// Grid nodes.
    #[arg(long, default_value = "1000")]
    pub nodes: usize,
    /// Transient: step the load per length to this value at t = 0 (e.g. 600kN/m).
    #[arg(long, allow_hyphen_values = true)]
    pub step_to: Option<Quantity<LoadPerLength>>,
    /// Transient: simulated time after the step.
    #[arg(long, allow_hyphen_values = true, default_value = "1ms")]
    pub duration: Quantity<Time>,
    /// Transient: roller length carrying the load.
    #[arg(long, allow_hyphen_values = true, default_value = "10mm")]
    pub contact_length: Quantity<Length>,
    /// Transient: roller mass [default: steel cylinder π R² × contact length × 7850 kg/m³].
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<Quantity<Mass>>,
    #[arg(long)]
    pub json: bool,
    /// Write pressure/film profiles (CSV + SVG), and the transient history, here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Solves, prints the result, then fails (exit 1) when the contact did not converge.
pub fn run(args: Args) -> Result<(), Failure> {
    let request = EhlLineRequest {
        radius: args.radius,
        viscosity: args.viscosity,
        rolling_speed: args.rolling_speed,
        min_film: args.min_film,
        load_per_length: args.load_per_length,
        piezo: args.piezo,
        law: args.law,
        density: args.density,
        elastic: args.elastic,
        modulus: args.modulus,
        poisson: args.poisson,
        squeeze_velocity: args.squeeze_velocity,
        nodes: args.nodes,
        step_to: args.step_to,
        duration: args.duration,
        contact_length: args.contact_length,
        mass: args.mass,
        out: args.out,
    };
    let result = EhlLine::run(&request, &context(None, &Bar::hidden()))?;
    if args.json {
        print_json(&result)?;
    } else {
        print_text(&result.to_string())?;
    }
    result.convergence_failure().map_or(Ok(()), Err)
}
