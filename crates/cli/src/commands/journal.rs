//! `rolldyn journal`: finite journal bearing by the Reynolds equation (SPEC §8.6, seed 002 ch. 4)
//! for a given eccentricity ratio or load, from the flags or a journal file (`rolldyn::journal`).

use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::journal::{CavitationName, FilmStartName, Journal, JournalRequest};
use rolldyn_units::{AngularSpeed, DynamicViscosity, Force, Length, Quantity, Temperature};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with geometry, operating point, viscosity law, liner and thermal model
    /// (see examples/journal/seed002-ch4.toml); replaces the geometry/operating flags.
    #[arg(long, conflicts_with_all = ["radius", "length", "clearance", "viscosity", "speed", "eccentricity", "load"])]
    pub file: Option<PathBuf>,
    /// Journal radius R.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<Quantity<Length>>,
    /// Bearing length L.
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<Quantity<Length>>,
    /// Radial clearance c.
    #[arg(long, allow_hyphen_values = true)]
    pub clearance: Option<Quantity<Length>>,
    /// Dynamic viscosity μ (isoviscous).
    #[arg(long, allow_hyphen_values = true)]
    pub viscosity: Option<Quantity<DynamicViscosity>>,
    /// Journal speed (bush fixed).
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Eccentricity ratio ε = e/c, 0 < ε < 1.
    #[arg(long, conflicts_with = "load", allow_hyphen_values = true)]
    pub eccentricity: Option<f64>,
    /// Static load W: solve for the equilibrium eccentricity and attitude.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Option<Quantity<Force>>,
    /// Lubricant temperature (isothermal model).
    #[arg(long, allow_hyphen_values = true, default_value = "40C")]
    pub temperature: Quantity<Temperature>,
    /// Cavitation model [default: reynolds].
    #[arg(long, value_enum)]
    pub cavitation: Option<CavitationName>,
    /// Grid: circumferential × axial nodes (full length) [default: 120x40].
    #[arg(long)]
    pub grid: Option<String>,
    /// Where the film starts without a feed groove [default: max-gap].
    #[arg(long, value_enum)]
    pub film_start: Option<FilmStartName>,
    /// Skip the 2×2 stiffness and damping coefficients (8 extra solves).
    #[arg(long)]
    pub no_coefficients: bool,
    #[arg(long)]
    pub json: bool,
    /// Write the pressure field (CSV), a heat map and the mid-plane profile (SVG) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Solves, prints the result, then fails (exit 1) when the solution did not converge.
pub fn run(args: Args) -> Result<(), Failure> {
    let request = JournalRequest {
        file: args.file,
        radius: args.radius,
        length: args.length,
        clearance: args.clearance,
        viscosity: args.viscosity,
        speed: args.speed,
        eccentricity: args.eccentricity,
        load: args.load,
        temperature: args.temperature,
        cavitation: args.cavitation,
        grid: args.grid,
        film_start: args.film_start,
        no_coefficients: args.no_coefficients,
        out: args.out,
    };
    let result = Journal::run(&request, &context(None, &Bar::hidden()))?;
    if args.json {
        print_json(&result)?;
    } else {
        print_text(&result.to_string())?;
    }
    result.convergence_failure().map_or(Ok(()), Err)
}
