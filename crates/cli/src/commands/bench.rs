//! `rolldyn bench [MODEL.toml]`: the dynamics speed benchmark, simulated time over wall time
//! on one thread, repeated (`rolldyn_setup::speed`; BENCHMARKS.md, "Dynamics").

use super::operating_args::OperatingArgs;
use super::simulate::Duration;
use crate::failure::Failure;
use crate::output::{load_model, print_json};
use rolldyn_setup::speed::{SpeedError, SpeedRun, cpu_name, measure_speed, vector_loops};
use serde::Serialize;
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

#[derive(Serialize)]
struct RunAnswer {
    setup_s: f64,
    integration_s: f64,
    simulated_time_s: f64,
    cage_revolutions: f64,
    simulated_over_wall: f64,
    simulated_over_wall_with_setup: f64,
    steps: u64,
    rejected_steps: u64,
    rhs_evaluations: u64,
    us_per_rhs: f64,
    roller_slices: usize,
    ns_per_roller_slice: f64,
}

impl From<&SpeedRun> for RunAnswer {
    fn from(r: &SpeedRun) -> Self {
        Self {
            setup_s: r.setup_s,
            integration_s: r.integration_s,
            simulated_time_s: r.simulated_s,
            cage_revolutions: r.cage_revolutions,
            simulated_over_wall: r.ratio(),
            simulated_over_wall_with_setup: r.ratio_with_setup(),
            steps: r.steps,
            rejected_steps: r.rejected_steps,
            rhs_evaluations: r.rhs_evaluations,
            us_per_rhs: r.us_per_rhs(),
            roller_slices: r.roller_slices,
            ns_per_roller_slice: r.ns_per_roller_slice(),
        }
    }
}

#[derive(Serialize)]
struct Answer<'a> {
    model: &'a str,
    cpu: Option<String>,
    vector_loops: &'static str,
    threads: usize,
    optimised_build: bool,
    runs: Vec<RunAnswer>,
    best_simulated_over_wall: f64,
    median_simulated_over_wall: f64,
    median_simulated_over_wall_with_setup: f64,
    deterministic: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?;
    let name = model.bearing.name();
    let overrides = args.operating.overrides();
    let optimised_build = !cfg!(debug_assertions);
    let talk = !(args.quiet || args.json);
    if talk {
        eprintln!(
            "rolldyn bench: {name}, {} run(s) on one thread; CPU {} ({} loops){}",
            args.repeat,
            cpu_name().as_deref().unwrap_or("unknown"),
            vector_loops(),
            if optimised_build {
                ""
            } else {
                "; DEBUG BUILD: the figures mean nothing, build with --release"
            },
        );
    }
    let duration = args.duration;
    let report = measure_speed(
        &model,
        &overrides,
        args.tolerance,
        &|revolution| duration.end_time(revolution),
        args.repeat as usize,
        &mut |k, r| {
            if talk {
                eprintln!(
                    "run {}: set-up {:.3} s, {:.4} s simulated ({:.1} cage revolutions) in {:.3} s → {:.4} ({} steps, {} rejected, {} RHS, {:.2} µs per RHS, {:.1} ns per roller slice)",
                    k + 1,
                    r.setup_s,
                    r.simulated_s,
                    r.cage_revolutions,
                    r.integration_s,
                    r.ratio(),
                    r.steps,
                    r.rejected_steps,
                    r.rhs_evaluations,
                    r.us_per_rhs(),
                    r.ns_per_roller_slice(),
                );
            }
        },
    )
    .map_err(|e| match e {
        SpeedError::Setup(e) => Failure::from(e),
        SpeedError::Run { .. } => Failure::Run(e.to_string()),
    })?;
    if args.json {
        return print_json(&Answer {
            model: name,
            cpu: cpu_name(),
            vector_loops: vector_loops(),
            threads: 1,
            optimised_build,
            runs: report.runs.iter().map(RunAnswer::from).collect(),
            best_simulated_over_wall: report.best_ratio(),
            median_simulated_over_wall: report.median_ratio(),
            median_simulated_over_wall_with_setup: report.median_ratio_with_setup(),
            deterministic: report.deterministic,
        });
    }
    println!(
        "{name}: simulated/wall time best {:.4}, median {:.4} over {} run(s) ({:.4} with the set-up); results {}",
        report.best_ratio(),
        report.median_ratio(),
        report.runs.len(),
        report.median_ratio_with_setup(),
        match (report.runs.len(), report.deterministic) {
            (1, _) => "of one run (give --repeat 2 or more to compare runs)",
            (_, true) => "identical in every run",
            (_, false) => "DIFFER between runs",
        },
    );
    println!(
        "goal of the project: ≥ 0.1 for the embedded 2002834 model over 20 cage revolutions (BENCHMARKS.md)"
    );
    Ok(())
}
