//! `rolldyn check MODEL.toml`: validate a model and print derived quantities.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::check::{Check, CheckRequest};
use rolldyn_units::{AngularSpeed, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML); the embedded default model (2002834) when omitted.
    pub model: Option<PathBuf>,
    /// Inner-ring speed for the epicyclic speeds, e.g. `6371rpm` (default: the model's
    /// `operating.inner_speed`, else 1000 rpm).
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings), e.g. `13067rpm` (default: the model's
    /// `operating.outer_speed`, else 0).
    #[arg(long, allow_hyphen_values = true)]
    pub outer_speed: Option<Quantity<AngularSpeed>>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = CheckRequest {
        speed: args.speed,
        outer_speed: args.outer_speed,
    };
    run_and_print::<Check>(&request, args.model.as_deref(), args.json)
}
