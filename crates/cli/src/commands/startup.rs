//! `rolldyn startup MODEL.toml`: quasi-steady start-up at frozen time points (seed 000 §3.1.2,
//! SPEC §3.1, V-08). At every time of `[startup] frozen_points` the schedules of `[operating]`
//! (speed, loads with their steps, unbalance, clearance, oil temperature) are frozen, a
//! constant-condition dynamics run is taken from the quasi-static start over N cage
//! revolutions, and the mean cage slip of the last revolutions is reported next to the
//! quasi-static slip. Points run in parallel.

use super::jobs_args::JobsArgs;
use crate::failure::Failure;
use crate::output::{load_model, print_json};
use rolldyn_dynamics::output::{OutputSink, RevolutionSummary, Snapshot};
use rolldyn_model::FrozenPoint;
use rolldyn_setup::{Overrides, frozen_conditions, prepare_frozen};
use rolldyn_sweep::frozen::{
    FrozenPointRow, drift_of_last, mean_of_last, run_points, write_outputs,
};
use serde::Serialize;
use std::path::PathBuf;

/// Below this inner-ring speed a frozen point has no cage motion to simulate (the start at
/// t = 0 of a start-up), rad/s.
const MIN_SPEED_RAD_S: f64 = 1.0;

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
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
    /// No per-point progress lines.
    #[arg(long)]
    pub quiet: bool,
}

/// Collects the per-revolution summaries of a run.
#[derive(Default)]
struct Revolutions(Vec<RevolutionSummary>);

impl OutputSink for Revolutions {
    fn sample(&mut self, _t: f64, _snapshot: &Snapshot) {}
    fn revolution(&mut self, summary: &RevolutionSummary) {
        self.0.push(*summary);
    }
}

/// How the points are run.
#[derive(Clone, Copy)]
struct Settings {
    revolutions: f64,
    average: Option<f64>,
}

/// The frozen point `p` of `model`: conditions, quasi-static solution and dynamics.
fn analyse(model: &rolldyn_model::Model, p: &FrozenPoint, s: Settings) -> FrozenPointRow {
    let start = std::time::Instant::now();
    let overrides = Overrides::default();
    let failed = |e: String| FrozenPointRow::conditions_only(&p.label, p.time, e);
    let c = match frozen_conditions(&overrides, model, p.time) {
        Ok(c) => c,
        Err(e) => return failed(format!("failed: {e}")),
    };
    let fixed = c.fixed_force(0.0);
    let speed = c.inner_speed.speed(0.0);
    let mut row = FrozenPointRow {
        inner_speed_rad_s: speed,
        fixed_load_n: fixed[0].hypot(fixed[1]),
        rotating_load_n: c.rotating_force_magnitude(0.0),
        clearance_m: c.clearance_at(0.0).unwrap_or(match &model.bearing {
            rolldyn_geometry::BearingModel::Cylindrical(b) => b.clearance.radial,
            _ => f64::NAN,
        }),
        oil_temperature_k: c.temperatures.inner_raceway_k,
        ..FrozenPointRow::conditions_only(&p.label, p.time, "")
    };
    if speed.abs() < MIN_SPEED_RAD_S {
        row.note = "zero inner-ring speed: nothing to simulate (skipped)".into();
        return row;
    }
    let prepared = match prepare_frozen(model, &overrides, p.time, 0.0, None) {
        Ok(prepared) => prepared,
        Err(e) => {
            row.note = format!("failed: {e}");
            return row;
        }
    };
    match &prepared.quasi_static {
        Ok(qs) => {
            row.cage_slip_quasi_static = qs.cage_slip;
            row.max_roller_load_quasi_static_n = qs.max_roller_load_n;
        }
        Err(e) => row.note = format!("quasi-static: {e}; "),
    }
    let Some(period) = prepared.revolution_s else {
        row.note
            .push_str("the rings are at rest: nothing to simulate (skipped)");
        return row;
    };
    let mut sim = prepared.simulation;
    let wanted = s.revolutions.ceil() as usize;
    let mut revs = Revolutions::default();
    // run revolution by revolution until N cage revolutions are complete (the cage slips, so
    // N epicyclic periods are not quite enough), with a cap at 1.5 N periods
    let t_cap = 1.5 * s.revolutions * period;
    let mut result = Ok(());
    while revs.0.len() < wanted && sim.time() < t_cap {
        let target = (sim.time() + period).min(t_cap);
        if let Err(e) = sim.run_until(target, &mut revs, &mut |_| {}) {
            result = Err(e);
            break;
        }
    }
    if let Err(e) = result {
        row.note.push_str(&format!("the simulation stopped: {e}"));
    }
    let n = revs.0.len();
    let average = s
        .average
        .map_or(n.div_ceil(2), |a| a.round() as usize)
        .clamp(1, n.max(1));
    let tail = &revs.0[n.saturating_sub(average)..];
    let slips: Vec<f64> = revs.0.iter().map(|r| r.cage_slip_mean).collect();
    row.cage_slip_dynamic = mean_of_last(&slips, average);
    row.slip_drift = drift_of_last(&slips, average);
    row.max_roller_load_n = tail
        .iter()
        .map(|r| r.max_inner_contact_force_n.max(r.max_outer_contact_force_n))
        .fold(f64::NAN, f64::max);
    row.revolutions = n as f64;
    row.averaged_revolutions = tail.len() as f64;
    row.steady = revs.0.last().is_some_and(|r| r.steady);
    row.slip_history = slips;
    if n == 0 {
        row.note.push_str("no complete cage revolution");
    }
    row.wall_time_s = start.elapsed().as_secs_f64();
    row
}

#[derive(Serialize)]
struct Answer<'a> {
    model: &'a str,
    revolutions: f64,
    average_revolutions: Option<f64>,
    output_folder: String,
    points: &'a [FrozenPointRow],
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(Some(&args.model))?;
    let startup = model.startup.clone().ok_or_else(|| {
        Failure::Input(format!(
            "{}: startup needs a [startup] section with frozen_points",
            args.model.display()
        ))
    })?;
    let revolutions = args.revolutions.unwrap_or(startup.revolutions);
    if !(revolutions >= 1.0 && revolutions.is_finite()) {
        return Err(Failure::Input("--revolutions must be at least 1".into()));
    }
    // the file's average is capped by a smaller --revolutions; an explicit --average is not
    let average = args.average.or(startup
        .average_revolutions
        .map(|a| a.min(revolutions.floor())));
    if let Some(a) = average
        && !(a >= 1.0 && a <= revolutions)
    {
        return Err(Failure::Input(
            "--average must lie between 1 and the number of revolutions".into(),
        ));
    }
    let points: Vec<FrozenPoint> = match &args.points {
        None => startup.points.clone(),
        Some(labels) => {
            if let Some(missing) = labels
                .iter()
                .find(|l| !startup.points.iter().any(|p| &p.label == *l))
            {
                return Err(Failure::Input(format!(
                    "--points: no frozen point labelled '{missing}' (labels: {})",
                    startup
                        .points
                        .iter()
                        .map(|p| p.label.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                )));
            }
            startup
                .points
                .iter()
                .filter(|p| labels.contains(&p.label))
                .cloned()
                .collect()
        }
    };
    // fail early on conditions that cannot be built (no speed, no oil, no [lubricant]…)
    if let Some(p) = points.first() {
        frozen_conditions(&Overrides::default(), &model, p.time)?;
        if model.lubrication.is_none() {
            return Err(Failure::Input(format!(
                "{}: startup needs a [lubricant] section",
                args.model.display()
            )));
        }
    }
    let stem = args
        .model
        .file_stem()
        .map_or("model".into(), |s| s.to_string_lossy().to_string());
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out").join(format!("{stem}-startup")));
    let jobs = args.jobs.count();
    let settings = Settings {
        revolutions,
        average,
    };
    let quiet = args.quiet;
    let progress = |r: &FrozenPointRow| {
        if !quiet {
            eprintln!(
                "point {} (t = {} s) done in {:.1} s{}",
                r.label,
                r.time_s,
                r.wall_time_s,
                if r.note.is_empty() {
                    String::new()
                } else {
                    format!(": {}", r.note)
                }
            );
        }
    };
    let rows = run_points(
        &points,
        jobs,
        &|p: &FrozenPoint| analyse(&model, p, settings),
        &progress,
    )
    .map_err(|e| Failure::Run(e.to_string()))?;
    write_outputs(&out, model.bearing.name(), &rows).map_err(|e| Failure::Run(e.to_string()))?;
    if args.json {
        return print_json(&Answer {
            model: model.bearing.name(),
            revolutions,
            average_revolutions: average,
            output_folder: out.display().to_string(),
            points: &rows,
        });
    }
    print_table(model.bearing.name(), revolutions, &rows);
    println!("  tables and plots in {}", out.display());
    if !rows.is_empty() && rows.iter().all(|r| r.note.starts_with("failed")) {
        return Err(Failure::Run("every frozen point failed".into()));
    }
    Ok(())
}

fn print_table(model: &str, revolutions: f64, rows: &[FrozenPointRow]) {
    println!(
        "{model}: start-up at {} frozen points, {revolutions} cage revolutions each",
        rows.len()
    );
    println!(
        "  {:>5} {:>9} {:>8} {:>8} {:>8} {:>8} {:>6} {:>9} {:>8} {:>9} {:>9} {:>5}  note",
        "point",
        "time, s",
        "rpm",
        "fixed N",
        "Uω² N",
        "Gr µm",
        "oil °C",
        "slip dyn%",
        "drift%",
        "slip qs%",
        "Qmax N",
        "revs"
    );
    for r in rows {
        println!(
            "  {:>5} {:>9.4} {:>8.0} {:>8.1} {:>8.1} {:>8.2} {:>6.1} {:>9.3} {:>8.3} {:>9.3} {:>9.1} {:>5}  {}",
            r.label,
            r.time_s,
            r.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
            r.fixed_load_n,
            r.rotating_load_n,
            r.clearance_m * 1e6,
            r.oil_temperature_k - rolldyn_units::CELSIUS_ZERO,
            100.0 * r.cage_slip_dynamic,
            100.0 * r.slip_drift,
            100.0 * r.cage_slip_quasi_static,
            r.max_roller_load_n,
            r.revolutions,
            r.note
        );
    }
}
