//! `rolldyn life MODEL.toml`: rating life of a cylindrical or double-row tapered bearing —
//! ISO 281 C_r, L10, L_nm, ISO 76 C0r and s0, ISO/TS 16281 L10r from the slice loads
//! (`rolldyn::life`); `--duty` rows are combined by Palmgren–Miner.

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::life::{DutyRow, Life, LifeRequest};
use rolldyn_rating::iso281::ContaminationLevel;
use rolldyn_units::{KinematicViscosity, Length, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) of a cylindrical or double-row tapered bearing.
    pub model: PathBuf,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Diametral operating clearance of a cylindrical bearing, e.g. 20um (replaces the one
    /// derived from the model's clearance, fits and temperatures; negative: preload).
    #[arg(long, allow_hyphen_values = true)]
    pub clearance: Option<Quantity<Length>>,
    /// Contamination level of ISO 281 Table 13 (extreme-cleanliness, high-cleanliness,
    /// normal-cleanliness, slight-contamination, typical-contamination, severe-contamination,
    /// very-severe-contamination); default normal-cleanliness, named in the output.
    #[arg(long)]
    pub contamination: Option<ContaminationLevel>,
    /// Contamination factor e_C (0…1) given directly instead of a level.
    #[arg(long)]
    pub contamination_factor: Option<f64>,
    /// Reliability in % (ISO 281 Table 12: 90, 95, 96, 97, 98, 99, 99.2 … 99.95); default 90.
    #[arg(long)]
    pub reliability: Option<f64>,
    /// Kinematic viscosity at the operating temperature, e.g. 12cSt (replaces the model oil's).
    #[arg(long)]
    pub viscosity: Option<Quantity<KinematicViscosity>>,
    /// A duty-cycle row, repeatable: time=0.3,speed=5000rpm,radial-load=15kN (keys time,
    /// speed, radial-load, axial-load, oil-temperature; time a share or hours).
    #[arg(long)]
    pub duty: Vec<DutyRow>,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = LifeRequest {
        operating: args.operating.operating(),
        clearance: args.clearance,
        contamination: args.contamination,
        contamination_factor: args.contamination_factor,
        reliability: args.reliability,
        viscosity: args.viscosity,
        duty: args.duty,
    };
    run_and_print::<Life>(&request, Some(&args.model), args.json)
}
