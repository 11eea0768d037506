//! The speed benchmark of the dynamics (`rolldyn bench`): simulated time over wall time of a
//! model's run on one thread, repeated, because a shared machine's speed drifts from run to run
//! (BENCHMARKS.md, "Dynamics"). The goal of the project is ≥ 0.1 for the embedded 2002834 model
//! over 20 cage revolutions.

use crate::{Overrides, SetupError, prepare, prepare_tapered};
use rolldyn_dynamics::output::NullSink;
use rolldyn_dynamics::tapered::{TaperedRunSettings, run as run_tapered};
use rolldyn_geometry::BearingModel;
use std::time::Instant;

/// One timed run: building the simulation, then integrating it without file output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedRun {
    /// building the simulation from the model (initial state, quasi-static start, the
    /// hydrodynamic cage land's table), s
    pub setup_s: f64,
    /// the integration: [`RunSummary::wall_time_s`], s
    pub integration_s: f64,
    /// simulated time, s
    pub simulated_s: f64,
    /// cage revolutions simulated (at the epicyclic cage speed of the start)
    pub cage_revolutions: f64,
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evaluations: u64,
    /// roller slices in contact evaluations per right-hand side: rollers × slices per roller
    /// (each against both raceways)
    pub roller_slices: usize,
}

impl SpeedRun {
    /// Simulated time / integration wall time (the figure of BENCHMARKS.md).
    pub fn ratio(&self) -> f64 {
        self.simulated_s / self.integration_s
    }

    /// Simulated time / (set-up + integration) wall time: what timing the whole command sees,
    /// less the process start and the file output.
    pub fn ratio_with_setup(&self) -> f64 {
        self.simulated_s / (self.setup_s + self.integration_s)
    }

    /// Integration wall time per right-hand-side evaluation, µs.
    pub fn us_per_rhs(&self) -> f64 {
        1e6 * self.integration_s / self.rhs_evaluations as f64
    }

    /// Integration wall time per right-hand-side evaluation and roller slice, ns: the cost
    /// that makes bearings of different sizes comparable.
    pub fn ns_per_roller_slice(&self) -> f64 {
        1e3 * self.us_per_rhs() / self.roller_slices as f64
    }
}

/// Why [`measure_speed`] stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpeedError {
    /// the model cannot be set up, or no run was asked for
    #[error(transparent)]
    Setup(#[from] SetupError),
    /// a run stopped (divergence, step-size collapse)
    #[error("run {run}: the simulation stopped: {message}")]
    Run { run: usize, message: String },
}

impl SpeedError {
    /// A run's failure; its index is set by [`SpeedError::in_run`].
    fn run(message: String) -> Self {
        Self::Run { run: 0, message }
    }

    /// This error as that of run `index` (1-based).
    fn in_run(self, index: usize) -> Self {
        match self {
            Self::Run { message, .. } => Self::Run {
                run: index,
                message,
            },
            other => other,
        }
    }
}

/// Result of [`measure_speed`].
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedReport {
    pub runs: Vec<SpeedRun>,
    /// every run gave the same summary (all figures but the wall time, bit for bit)
    pub deterministic: bool,
}

impl SpeedReport {
    /// Largest [`SpeedRun::ratio`] (the run least disturbed by the machine).
    pub fn best_ratio(&self) -> f64 {
        self.runs.iter().map(SpeedRun::ratio).fold(0.0, f64::max)
    }

    /// Median [`SpeedRun::ratio`].
    pub fn median_ratio(&self) -> f64 {
        median(self.runs.iter().map(SpeedRun::ratio))
    }

    /// Median [`SpeedRun::ratio_with_setup`].
    pub fn median_ratio_with_setup(&self) -> f64 {
        median(self.runs.iter().map(SpeedRun::ratio_with_setup))
    }
}

fn median(values: impl Iterator<Item = f64>) -> f64 {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    match v.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => v[n / 2],
        n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

/// Runs `model` `repeat` times, one after the other on this thread, each from a fresh
/// simulation up to `end_time(cage revolution period)` (`None`: rings at rest), and times
/// set-up and integration
/// separately. `on_run` is called after each run with its index.
pub fn measure_speed(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
    tolerance: Option<f64>,
    end_time: &dyn Fn(Option<f64>) -> Result<f64, String>,
    repeat: usize,
    on_run: &mut dyn FnMut(usize, &SpeedRun),
) -> Result<SpeedReport, SpeedError> {
    if repeat == 0 {
        return Err(SetupError("the benchmark needs at least one run".into()).into());
    }
    let mut runs = Vec::with_capacity(repeat);
    let mut first: Option<String> = None;
    let mut deterministic = true;
    for k in 0..repeat {
        let (run, fingerprint) =
            timed_run(model, overrides, tolerance, end_time).map_err(|e| e.in_run(k + 1))?;
        on_run(k, &run);
        runs.push(run);
        match &first {
            None => first = Some(fingerprint),
            Some(f) => deterministic &= *f == fingerprint,
        }
    }
    Ok(SpeedReport {
        runs,
        deterministic,
    })
}

/// One timed run of `model` from a fresh set-up, and the run's figures but its wall time as
/// text (Debug formatting prints every f64 with its shortest exact representation, and NaN as
/// NaN, so equal strings mean equal figures).
fn timed_run(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
    tolerance: Option<f64>,
    end_time: &dyn Fn(Option<f64>) -> Result<f64, String>,
) -> Result<(SpeedRun, String), SpeedError> {
    if let BearingModel::Tapered(bearing) = &model.bearing {
        let roller_slices = 2 * bearing.rollers_per_row * bearing.roller.slice_count;
        return timed_tapered_run(model, overrides, tolerance, end_time, roller_slices);
    }
    let start = Instant::now();
    let (mut sim, revolution) = prepare(model, overrides, 0.0, tolerance)?;
    let setup_s = start.elapsed().as_secs_f64();
    let t_end = end_time(revolution).map_err(SetupError)?;
    let summary = sim
        .run_until(t_end, &mut NullSink, &mut |_| {})
        .map_err(|e| SpeedError::run(e.to_string()))?;
    let slices_per_roller = model.bearing.roller().map_or(1, |r| r.slice_count);
    let roller_slices = sim.layout().rollers * slices_per_roller;
    let run = SpeedRun {
        setup_s,
        integration_s: summary.wall_time_s,
        simulated_s: summary.simulated_time_s,
        cage_revolutions: revolution.map_or(0.0, |p| summary.simulated_time_s / p),
        steps: summary.steps,
        rejected_steps: summary.rejected_steps,
        rhs_evaluations: summary.rhs_evaluations,
        roller_slices,
    };
    let mut figures = summary;
    figures.wall_time_s = 0.0;
    Ok((run, format!("{figures:?}")))
}

/// [`timed_run`] of a double-row tapered bearing: its own dynamics with the default
/// [`TaperedRunSettings`] (one sample at the end, so no sample recording is timed).
fn timed_tapered_run(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
    tolerance: Option<f64>,
    end_time: &dyn Fn(Option<f64>) -> Result<f64, String>,
    roller_slices: usize,
) -> Result<(SpeedRun, String), SpeedError> {
    let start = Instant::now();
    let tm = prepare_tapered(model, overrides)?;
    let setup_s = start.elapsed().as_secs_f64();
    let revolution = std::f64::consts::TAU / tm.epicyclic_cage_speed.abs();
    let t_end = end_time(Some(revolution)).map_err(SetupError)?;
    let mut settings = TaperedRunSettings {
        duration_s: t_end,
        sample_interval_s: t_end,
        ..TaperedRunSettings::default()
    };
    if let Some(tol) = tolerance {
        settings.integrator.tolerance = tol;
    }
    let wall = Instant::now();
    let outcome =
        run_tapered(&tm, &settings, |_| {}).map_err(|e| SpeedError::run(e.to_string()))?;
    let integration_s = wall.elapsed().as_secs_f64();
    let run = SpeedRun {
        setup_s,
        integration_s,
        simulated_s: t_end,
        cage_revolutions: t_end / revolution,
        steps: outcome.steps,
        rejected_steps: outcome.rejected_steps,
        rhs_evaluations: outcome.rhs_evaluations,
        roller_slices,
    };
    Ok((run, format!("{:?}", outcome.samples)))
}

/// The processor's name (Linux `/proc/cpuinfo`), if it can be read.
pub fn cpu_name() -> Option<String> {
    let info = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    info.lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split_once(':'))
        .map(|(_, name)| name.trim().to_string())
}

/// The compiled copy of the vectorised hot loops this CPU runs: `avx512f`, `avx2` or
/// `portable`.
pub fn vector_loops() -> &'static str {
    use rolldyn_numerics::vector_copies::LoopCopy;
    match LoopCopy::detect() {
        LoopCopy::Avx512 => "avx512f",
        LoopCopy::Portable if cfg!(target_feature = "avx2") => "avx2",
        LoopCopy::Portable => "portable",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median([3.0, 1.0, 2.0].into_iter()), 2.0);
        assert_eq!(median([4.0, 1.0, 2.0, 3.0].into_iter()), 2.5);
        assert!(median(std::iter::empty()).is_nan());
    }

    #[test]
    fn two_short_runs_agree_bit_for_bit() {
        let model =
            rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").expect("model");
        let mut seen = 0;
        let report = measure_speed(
            &model,
            &Overrides::default(),
            None,
            &|_| Ok(2e-4),
            2,
            &mut |_, _| seen += 1,
        )
        .expect("runs");
        assert_eq!(seen, 2);
        assert!(report.deterministic);
        let (a, b) = (report.runs[0], report.runs[1]);
        assert_eq!(
            (a.steps, a.rejected_steps, a.rhs_evaluations),
            (b.steps, b.rejected_steps, b.rhs_evaluations)
        );
        assert!(a.ratio() > 0.0 && a.ratio_with_setup() < a.ratio());
        assert!(
            measure_speed(
                &model,
                &Overrides::default(),
                None,
                &|_| Ok(1e-4),
                0,
                &mut |_, _| {}
            )
            .is_err()
        );
    }
}
