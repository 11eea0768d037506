//! `rolldyn simulate MODEL.toml`: time-domain 6-DOF dynamics of a cylindrical or double-row
//! tapered roller bearing (`rolldyn::simulate`).

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
pub use rolldyn::operating::Duration;
use rolldyn::simulate::{IntegratorName, Simulate, SimulateRequest, check_row_offset};
use rolldyn_output::ByteSize;
use rolldyn_units::{Quantity, Time};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with [lubricant] and [operating]; the embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Simulated duration: cage revolutions (`20rev`) or time (`0.2s`).
    #[arg(long, default_value = "5rev", allow_hyphen_values = true)]
    pub duration: Duration,
    /// Interval of the time-series samples (at least the integrator's minimum step).
    #[arg(long, default_value = "0.05ms", allow_hyphen_values = true)]
    pub output_step: Quantity<Time>,
    /// Largest estimated size of the `--out` tables: a run whose tables would be larger is
    /// refused before it starts (e.g. `20GB`).
    #[arg(long, default_value = "2GB")]
    pub max_output: ByteSize,
    /// Relative tolerance of the integrator.
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Integration method (default: dopri5 for a cylindrical bearing, rosenbrock-w for a tapered one).
    #[arg(long, value_enum)]
    pub integrator: Option<IntegratorName>,
    /// Write the state to this file every `--checkpoint-interval` and at the end (the `--out`
    /// CSV rows are flushed first; README "Long runs").
    #[arg(long)]
    pub checkpoint: Option<PathBuf>,
    /// Interval of the checkpoints: cage revolutions (`2rev`) or time (`10ms`); default 1rev.
    #[arg(long, requires = "checkpoint", allow_hyphen_values = true)]
    pub checkpoint_interval: Option<Duration>,
    /// Continue a run from a checkpoint file (bit-for-bit) up to the new duration; with
    /// `--out`, the tables of that folder are continued.
    #[arg(long)]
    pub resume: Option<PathBuf>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
    /// Folder for time series (CSV + Parquet) and plots (SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the HTML report of the `--out` folder (`report.html`) at the end of the run.
    #[arg(long, requires = "out")]
    pub report: bool,
    /// Write the cage loads of the last cage revolution (180 load sets, 2° apart) to this
    /// Parquet file and its JSON header beside it (docs/outputs.md "Cage loads"); the run
    /// samples the dynamics at least 4 times per set.
    #[arg(long)]
    pub cage_loads: Option<PathBuf>,
    /// Double-row tapered bearing: the initial turn of row 2's rollers and cage against row
    /// 1's, in pocket pitches (0…1; default 0, the cage windows opposite each other).
    #[arg(long, value_parser = parse_row_offset)]
    pub row_offset: Option<f64>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// `--row-offset`: a fraction of the pocket pitch in [0, 1).
fn parse_row_offset(text: &str) -> Result<f64, String> {
    match text.parse::<f64>().map(check_row_offset) {
        Ok(Ok(v)) => Ok(v),
        _ => Err(format!(
            "'{text}': give a fraction of the pocket pitch in [0, 1), e.g. 0.45"
        )),
    }
}

impl Args {
    /// The request of these flags.
    fn request(&self) -> SimulateRequest {
        SimulateRequest {
            operating: self.operating.operating(),
            duration: self.duration,
            output_step: self.output_step,
            max_output: self.max_output,
            tolerance: self.tolerance,
            integrator: self.integrator,
            checkpoint: self.checkpoint.clone(),
            checkpoint_interval: self.checkpoint_interval,
            resume: self.resume.clone(),
            out: self.out.clone(),
            report: self.report,
            cage_loads: self.cage_loads.clone(),
            row_offset: self.row_offset,
            keep_tables: false,
        }
    }
}

pub fn run(args: Args) -> Result<(), Failure> {
    let bar = Bar::new(args.quiet, "simulating");
    let result = Simulate::run(&args.request(), &context(args.model.as_deref(), &bar));
    bar.finish();
    let result = result?;
    match args.json {
        true => print_json(&result),
        false => print_text(&result.to_string()),
    }
}
