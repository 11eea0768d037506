//! `rolldyn startup MODEL.toml`: quasi-steady start-up at frozen time points (seed 000 §3.1.2,
//! SPEC §3.1, V-08; `rolldyn::startup`).

use super::jobs_args::JobsArgs;
use super::progress_lines::ProgressLines;
use crate::failure::Failure;
use crate::output::{context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::startup::{Startup, StartupRequest};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with [lubricant], [operating] (schedules) and [startup] (frozen points).
    pub model: PathBuf,
    #[command(flatten)]
    pub jobs: JobsArgs,
    /// Cage revolutions per point (overrides startup.revolutions; default 10).
    #[arg(long)]
    pub revolutions: Option<f64>,
    /// Last revolutions averaged for the slip (overrides startup.average_revolutions; default:
    /// the last half).
    #[arg(long)]
    pub average: Option<f64>,
    /// Run only these points, by label (comma-separated, e.g. `2,3`).
    #[arg(long, value_delimiter = ',')]
    pub points: Option<Vec<String>>,
    /// Output folder for startup.csv, startup.parquet and the SVG plots (default
    /// `out/<model file name>-startup`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Continue the run killed or interrupted in the output folder: the points it finished
    /// (stored in `startup.state` as each one ends) are kept, the others run.
    #[arg(long)]
    pub resume: bool,
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
    /// No per-point progress lines.
    #[arg(long)]
    pub quiet: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = StartupRequest {
        jobs: args.jobs.jobs,
        revolutions: args.revolutions,
        average: args.average,
        points: args.points,
        out: args.out,
        resume: args.resume,
    };
    let lines = ProgressLines { quiet: args.quiet };
    let result = Startup::run(&request, &context(Some(&args.model), &lines))?;
    if args.json {
        return print_json(&result);
    }
    print_text(&result.to_string())?;
    match result.every_point_failed() {
        true => Err(Failure::Run("every frozen point failed".into())),
        false => Ok(()),
    }
}
