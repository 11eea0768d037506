//! `rolldyn bench [MODEL.toml]`: the dynamics speed benchmark, simulated time over wall time
//! on one thread, repeated (`rolldyn::bench`; BENCHMARKS.md, "Dynamics").

use super::operating_args::OperatingArgs;
use super::progress_lines::ProgressLines;
use crate::failure::Failure;
use crate::output::{context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::bench::{Bench, BenchRequest};
use rolldyn::operating::Duration;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with [lubricant] and [operating], cylindrical or double-row tapered; the
    /// embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Simulated duration of each run: cage revolutions (`20rev`) or time (`0.2s`).
    #[arg(long, default_value = "20rev", allow_hyphen_values = true)]
    pub duration: Duration,
    /// Number of runs (one after the other, each from a fresh simulation).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    pub repeat: u32,
    /// Relative tolerance of the integrator (default: the settings default).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// No line per run on stderr.
    #[arg(long)]
    pub quiet: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = BenchRequest {
        operating: args.operating.operating(),
        duration: args.duration,
        repeat: args.repeat,
        tolerance: args.tolerance,
    };
    let lines = ProgressLines {
        quiet: args.quiet || args.json,
    };
    let result = Bench::run(&request, &context(args.model.as_deref(), &lines))?;
    match args.json {
        true => print_json(&result),
        false => print_text(&result.to_string()),
    }
}
