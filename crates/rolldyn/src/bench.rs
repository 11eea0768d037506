//! Bench: the dynamics speed benchmark, simulated time over wall time on one thread, repeated,
//! each run from a fresh simulation with its set-up timed apart (`rolldyn_setup::speed`;
//! BENCHMARKS.md, "Dynamics").

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::observer::Progress;
use crate::operating::{Duration, Operating};
use crate::table::{Table, Tables};
use rolldyn_setup::speed::{SpeedError, SpeedRun, cpu_name, measure_speed, vector_loops};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A speed benchmark of the model's dynamics.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct BenchRequest {
    /// Overrides of the model's operating point.
    pub operating: Operating,
    /// Simulated duration of each run: cage revolutions (`"20rev"`) or a time (`"0.2s"`).
    pub duration: Duration,
    /// Number of runs (one after the other, each from a fresh simulation), at least 1.
    pub repeat: u32,
    /// Relative tolerance of the integrator (default: the settings default).
    pub tolerance: Option<f64>,
}

impl Default for BenchRequest {
    fn default() -> Self {
        Self {
            operating: Operating::default(),
            duration: Duration::CageRevolutions(20.0),
            repeat: 3,
            tolerance: None,
        }
    }
}

/// One timed run.
#[derive(Clone, Debug, Serialize)]
pub struct BenchRun {
    pub setup_s: f64,
    pub integration_s: f64,
    pub simulated_time_s: f64,
    pub cage_revolutions: f64,
    pub simulated_over_wall: f64,
    pub simulated_over_wall_with_setup: f64,
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evaluations: u64,
    pub us_per_rhs: f64,
    pub roller_slices: usize,
    pub ns_per_roller_slice: f64,
}

impl From<&SpeedRun> for BenchRun {
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

/// The benchmark's figures.
#[derive(Clone, Debug, Serialize)]
pub struct BenchResult {
    pub model: String,
    pub cpu: Option<String>,
    pub vector_loops: &'static str,
    pub threads: usize,
    pub optimised_build: bool,
    pub runs: Vec<BenchRun>,
    pub best_simulated_over_wall: f64,
    pub median_simulated_over_wall: f64,
    pub median_simulated_over_wall_with_setup: f64,
    pub deterministic: bool,
}

impl fmt::Display for BenchResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}: simulated/wall time best {:.4}, median {:.4} over {} run(s) ({:.4} with the set-up); results {}",
            self.model,
            self.best_simulated_over_wall,
            self.median_simulated_over_wall,
            self.runs.len(),
            self.median_simulated_over_wall_with_setup,
            match (self.runs.len(), self.deterministic) {
                (1, _) => "of one run (give --repeat 2 or more to compare runs)",
                (_, true) => "identical in every run",
                (_, false) => "DIFFER between runs",
            },
        )?;
        write!(
            f,
            "goal of the project: ≥ 0.1 for the embedded 2002834 model over 20 cage revolutions (BENCHMARKS.md)"
        )
    }
}

impl Tables for BenchResult {
    /// The runs, one row each.
    fn tables(&self) -> Vec<Table> {
        let real = |f: fn(&BenchRun) -> f64| self.runs.iter().map(f).collect();
        let integer = |f: fn(&BenchRun) -> i64| self.runs.iter().map(f).collect();
        vec![
            Table::new("runs")
                .integer("run", (1..=self.runs.len() as i64).collect())
                .real("setup_s", real(|r| r.setup_s))
                .real("integration_s", real(|r| r.integration_s))
                .real("simulated_time_s", real(|r| r.simulated_time_s))
                .real("cage_revolutions", real(|r| r.cage_revolutions))
                .real("simulated_over_wall", real(|r| r.simulated_over_wall))
                .real(
                    "simulated_over_wall_with_setup",
                    real(|r| r.simulated_over_wall_with_setup),
                )
                .integer("steps", integer(|r| r.steps as i64))
                .integer("rejected_steps", integer(|r| r.rejected_steps as i64))
                .integer("rhs_evaluations", integer(|r| r.rhs_evaluations as i64))
                .real("us_per_rhs", real(|r| r.us_per_rhs))
                .integer("roller_slices", integer(|r| r.roller_slices as i64))
                .real("ns_per_roller_slice", real(|r| r.ns_per_roller_slice)),
        ]
    }
}

/// The speed benchmark. Progress: one step per run (unit "runs"), the message describing the
/// set-up first, then each run; an observer that asks to stop ends it before the next run.
pub struct Bench;

impl Analysis for Bench {
    const NAME: &'static str = "bench";
    type Request = BenchRequest;
    type Result = BenchResult;

    fn run(request: &BenchRequest, context: &Context<'_>) -> Result<BenchResult, Failure> {
        if request.repeat < 1 {
            return Err(Failure::Input("--repeat must be at least 1".into()));
        }
        let model = context.model.load()?;
        let name = model.bearing.name();
        let overrides = request.operating.overrides();
        let optimised_build = !cfg!(debug_assertions);
        let observer = context.observer;
        let total = f64::from(request.repeat);
        let say = |done: f64, message: String| {
            observer.progress(&Progress {
                done,
                total,
                unit: "runs",
                message: Some(message),
            })
        };
        say(
            0.0,
            format!(
                "rolldyn bench: {name}, {} run(s) on one thread; CPU {} ({} loops){}",
                request.repeat,
                cpu_name().as_deref().unwrap_or("unknown"),
                vector_loops(),
                if optimised_build {
                    ""
                } else {
                    "; DEBUG BUILD: the figures mean nothing, build with --release"
                },
            ),
        );
        let duration = request.duration;
        const INTERRUPTED: &str = "interrupted";
        let report = measure_speed(
            &model,
            &overrides,
            request.tolerance,
            &|revolution| match observer.stop_requested() {
                true => Err(INTERRUPTED.into()),
                false => duration.end_time(revolution),
            },
            request.repeat as usize,
            &mut |k, r| {
                say(
                    (k + 1) as f64,
                    format!(
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
                    ),
                )
            },
        )
        .map_err(|e| match e {
            SpeedError::Setup(e) if e.0 == INTERRUPTED => {
                Failure::Run("bench: interrupted before the next run".into())
            }
            SpeedError::Setup(e) => Failure::from(e),
            SpeedError::Run { .. } => Failure::Run(e.to_string()),
        })?;
        Ok(BenchResult {
            model: name.to_string(),
            cpu: cpu_name(),
            vector_loops: vector_loops(),
            threads: 1,
            optimised_build,
            runs: report.runs.iter().map(BenchRun::from).collect(),
            best_simulated_over_wall: report.best_ratio(),
            median_simulated_over_wall: report.median_ratio(),
            median_simulated_over_wall_with_setup: report.median_ratio_with_setup(),
            deterministic: report.deterministic,
        })
    }
}
