//! `rolldyn skid MODEL.toml`: quasi-static roller and cage skidding (SPEC §5, seed 001) at one
//! operating point, or a sweep over speed, outer-ring speed or radial load.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::skid::{FrictionName, LandName, PartTemperatures, Skid, SkidRequest, Values};
use rolldyn_units::{AngularSpeed, Force};
use std::path::PathBuf;
use std::str::FromStr;

#[derive(clap::Args)]
pub struct Args {
    /// Model file with [lubricant] (and optionally [operating]); the embedded 2002834 model when
    /// omitted.
    pub model: Option<PathBuf>,
    /// Inner-ring speed, or a sweep `1500rpm..4500rpm:500rpm`.
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<Values<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings), or a sweep.
    #[arg(long, allow_hyphen_values = true)]
    pub outer_speed: Option<Values<AngularSpeed>>,
    /// Radial load, or a sweep `100N..700N:50N`.
    #[arg(long, allow_hyphen_values = true)]
    pub radial_load: Option<Values<Force>>,
    /// Part temperatures, e.g. `inner=47.3C,outer=43C,cage=45C,oil=45C` (parts not given take
    /// the oil temperature).
    #[arg(long, value_parser = PartTemperatures::from_str)]
    pub temperatures: Option<PartTemperatures>,
    #[arg(long, value_enum, default_value = "muraki")]
    pub friction: FrictionName,
    /// Cage–guiding-land model.
    #[arg(long, value_enum, default_value = "finite")]
    pub cage_land: LandName,
    #[arg(long)]
    pub json: bool,
    /// Folder for the table: a point's rollers (`rollers.csv`), a sweep's `skid_sweep.csv` and
    /// its plot (SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Solves the operating point, or the sweep, and prints it (text or JSON).
pub fn run(args: Args) -> Result<(), Failure> {
    let request = SkidRequest {
        speed: args.speed,
        outer_speed: args.outer_speed,
        radial_load: args.radial_load,
        temperatures: args.temperatures,
        friction: args.friction,
        cage_land: args.cage_land,
        out: args.out,
    };
    run_and_print::<Skid>(&request, args.model.as_deref(), args.json)
}
