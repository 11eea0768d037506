//! Startup: quasi-steady start-up at frozen time points (seed 000 §3.1.2, SPEC §3.1, V-08). At
//! every time of `[startup] frozen_points` the schedules of `[operating]` (speed, loads with
//! their steps, unbalance, clearance, oil temperature) are frozen, a constant-condition dynamics
//! run is taken from the quasi-static start over N cage revolutions, and the mean cage slip of
//! the last revolutions is reported next to the quasi-static slip. Points run in parallel.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::model_source::ModelSource;
use crate::observer::{Observer, Progress};
use crate::output::out_dir;
use crate::table::{Table, Tables};
use rolldyn_dynamics::output::{OutputSink, RevolutionSummary, Snapshot};
use rolldyn_model::FrozenPoint;
use rolldyn_output::run_state::{StateFile, fingerprint};
use rolldyn_setup::{Overrides, frozen_conditions, prepare_frozen};
use rolldyn_sweep::frozen::{
    FrozenPointRow, NUMERIC_COLUMNS, drift_of_last, mean_of_last, run_points, write_outputs,
};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::ops::ControlFlow;
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Below this inner-ring speed a frozen point has no cage motion to simulate (the start at
/// t = 0 of a start-up), rad/s.
const MIN_SPEED_RAD_S: f64 = 1.0;

/// The note of a point not run because the caller asked to stop.
const INTERRUPTED: &str = "interrupted";

/// A start-up at the frozen points of the model's `[startup]` section.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StartupRequest {
    /// Parallel jobs, at least 1 (default: the number of cores).
    pub jobs: Option<usize>,
    /// Cage revolutions per point (overrides startup.revolutions; default 10).
    pub revolutions: Option<f64>,
    /// Last revolutions averaged for the slip (overrides startup.average_revolutions; default
    /// the last half).
    pub average: Option<f64>,
    /// Run only these points, by label.
    pub points: Option<Vec<String>>,
    /// Output folder for startup.csv, startup.parquet and the SVG plots (default
    /// `out/<model file name>-startup`).
    pub out: Option<PathBuf>,
    /// Continue the run killed or interrupted in `out`: the points it finished (stored in
    /// `startup.state` as each one ends) are kept, the others run.
    pub resume: bool,
}

/// The file of the output folder that holds the finished points of its run
/// ([`rolldyn_output::run_state`]).
pub const STATE_FILE: &str = "startup.state";

/// The frozen points' figures.
#[derive(Clone, Debug, Serialize)]
pub struct StartupResult {
    pub model: String,
    pub revolutions: f64,
    pub average_revolutions: Option<f64>,
    pub output_folder: String,
    pub points: Vec<FrozenPointRow>,
}

impl StartupResult {
    /// Whether every frozen point failed (the command line then exits with 1 after the table).
    pub fn every_point_failed(&self) -> bool {
        !self.points.is_empty() && self.points.iter().all(|r| r.note.starts_with("failed"))
    }
}

impl fmt::Display for StartupResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_table(f, &self.model, self.revolutions, &self.points)?;
        write!(f, "  tables and plots in {}", self.output_folder)
    }
}

impl Tables for StartupResult {
    /// `startup` (the columns of startup.csv) and `startup_revolutions` (the slip history).
    fn tables(&self) -> Vec<Table> {
        let rows = &self.points;
        let mut startup =
            Table::new("startup").text("point", rows.iter().map(|r| r.label.clone()).collect());
        for c in &NUMERIC_COLUMNS {
            startup = startup.real(c.name, rows.iter().map(|r| (c.value)(r)).collect());
        }
        startup = startup.text("note", rows.iter().map(|r| r.note.clone()).collect());
        let history: Vec<(&FrozenPointRow, usize, f64)> = rows
            .iter()
            .flat_map(|r| {
                r.slip_history
                    .iter()
                    .enumerate()
                    .map(move |(i, s)| (r, i + 1, *s))
            })
            .collect();
        let revolutions = Table::new("startup_revolutions")
            .text("point", history.iter().map(|h| h.0.label.clone()).collect())
            .real("time_s", history.iter().map(|h| h.0.time_s).collect())
            .integer("revolution", history.iter().map(|h| h.1 as i64).collect())
            .real("cage_slip", history.iter().map(|h| h.2).collect());
        vec![startup, revolutions]
    }
}

/// The start-up analysis. Progress: one step per finished point (unit "points", the message
/// describing it); an observer that asks to stop ends the running points' dynamics and starts no
/// more, and the analysis ends interrupted without writing its tables.
pub struct Startup;

impl Analysis for Startup {
    const NAME: &'static str = "startup";
    type Request = StartupRequest;
    type Result = StartupResult;

    fn run(request: &StartupRequest, context: &Context<'_>) -> Result<StartupResult, Failure> {
        let model = context.model.load()?;
        let name = model_name(&context.model);
        let startup = model.startup.clone().ok_or_else(|| {
            Failure::Input(format!(
                "{name}: startup needs a [startup] section with frozen_points"
            ))
        })?;
        let revolutions = request.revolutions.unwrap_or(startup.revolutions);
        if !(revolutions >= 1.0 && revolutions.is_finite()) {
            return Err(Failure::Input("--revolutions must be at least 1".into()));
        }
        // the file's average is capped by a smaller --revolutions; an explicit --average is not
        let average = request.average.or(startup
            .average_revolutions
            .map(|a| a.min(revolutions.floor())));
        if let Some(a) = average
            && !(a >= 1.0 && a <= revolutions)
        {
            return Err(Failure::Input(
                "--average must lie between 1 and the number of revolutions".into(),
            ));
        }
        if request.jobs == Some(0) {
            return Err(Failure::Input("--jobs must be at least 1".into()));
        }
        let points: Vec<FrozenPoint> = match &request.points {
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
                    "{name}: startup needs a [lubricant] section"
                )));
            }
        }
        let stem = context
            .model
            .file()
            .and_then(|p| p.file_stem())
            .map_or("model".into(), |s| s.to_string_lossy().to_string());
        let out = out_dir(
            &request
                .out
                .clone()
                .unwrap_or_else(|| PathBuf::from("out").join(format!("{stem}-startup"))),
        )?;
        let jobs = crate::operating::jobs_or_cores(request.jobs);
        let settings = Settings {
            revolutions,
            average,
        };
        let store = StateFile::new(
            out.join(STATE_FILE),
            fingerprint(&format!("startup\n{model:?}\n{revolutions:?}\n{average:?}")),
        );
        let finished: Vec<FrozenPointRow> = match request.resume {
            true => store
                .load()
                .map_err(|e| Failure::Input(e.to_string()))?
                .unwrap_or_default(),
            false => Vec::new(),
        };
        let finished = Mutex::new(finished);
        let store_error = Mutex::new(None);
        let observer = context.observer;
        let done = AtomicUsize::new(0);
        let progress = |r: &FrozenPointRow| {
            let done = done.fetch_add(1, Ordering::Relaxed) + 1;
            observer.progress(&Progress {
                done: done as f64,
                total: points.len() as f64,
                unit: "points",
                message: Some(format!(
                    "point {} (t = {} s) done in {:.1} s{}",
                    r.label,
                    r.time_s,
                    r.wall_time_s,
                    if r.note.is_empty() {
                        String::new()
                    } else {
                        format!(": {}", r.note)
                    }
                )),
            });
        };
        let stored_or_analysed = |p: &FrozenPoint| {
            let held = "no panic while the lock is held";
            let stored = finished
                .lock()
                .expect(held)
                .iter()
                .find(|r| r.label == p.label && r.time_s == p.time)
                .cloned();
            if let Some(row) = stored {
                return row;
            }
            let row = analyse(&model, p, settings, observer);
            // a point cut short by the stop request is not finished
            if !observer.stop_requested() {
                let mut done = finished.lock().expect(held);
                done.push(row.clone());
                if let Err(e) = store.store(&*done) {
                    store_error.lock().expect(held).get_or_insert(e);
                }
            }
            row
        };
        let rows = run_points(&points, jobs, &stored_or_analysed, &progress)
            .map_err(|e| Failure::Run(e.to_string()))?;
        if let Some(e) = store_error
            .into_inner()
            .expect("no panic while the lock is held")
        {
            return Err(Failure::Run(e.to_string()));
        }
        if observer.stop_requested() {
            return Err(Failure::Run(format!(
                "startup: interrupted; no tables written (--resume continues from the points finished, stored in {})",
                store.path().display()
            )));
        }
        write_outputs(&out, model.bearing.name(), &rows)
            .map_err(|e| Failure::Run(e.to_string()))?;
        Ok(StartupResult {
            model: model.bearing.name().to_string(),
            revolutions,
            average_revolutions: average,
            output_folder: out.display().to_string(),
            points: rows,
        })
    }
}

/// The model's file as given, or the embedded model's name, for messages.
fn model_name(source: &ModelSource) -> String {
    source.file().map_or_else(
        || crate::model_source::EMBEDDED_MODEL_NAME.to_string(),
        |p| p.display().to_string(),
    )
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
fn analyse(
    model: &rolldyn_model::Model,
    p: &FrozenPoint,
    s: Settings,
    observer: &dyn Observer,
) -> FrozenPointRow {
    let start = std::time::Instant::now();
    if observer.stop_requested() {
        return FrozenPointRow::conditions_only(&p.label, p.time, INTERRUPTED);
    }
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
        let mut stop = |_| match observer.stop_requested() {
            true => ControlFlow::Break(()),
            false => ControlFlow::Continue(()),
        };
        if let Err(e) = sim.run_until_interruptible(target, &mut revs, &mut stop) {
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

/// The table of the frozen points, with its heading.
fn write_table(
    f: &mut fmt::Formatter<'_>,
    model: &str,
    revolutions: f64,
    rows: &[FrozenPointRow],
) -> fmt::Result {
    writeln!(
        f,
        "{model}: start-up at {} frozen points, {revolutions} cage revolutions each",
        rows.len()
    )?;
    writeln!(
        f,
        "  {:>5} {:>9} {:>8} {:>8} {:>8} {:>8} {:>6} {:>9} {:>8} {:>9} {:>9} {:>5}  note",
        "point",
        "time, s",
        "rpm",
        "fixed N",
        "Uω² N",
        "Gr µm",
        "oil °C",
        "slip dyn",
        "drift",
        "slip qs",
        "Qmax N",
        "revs"
    )?;
    for r in rows {
        writeln!(
            f,
            "  {:>5} {:>9.4} {:>8.0} {:>8.1} {:>8.1} {:>8.2} {:>6.1} {:>9.5} {:>8.5} {:>9.5} {:>9.1} {:>5}  {}",
            r.label,
            r.time_s,
            r.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
            r.fixed_load_n,
            r.rotating_load_n,
            r.clearance_m * 1e6,
            r.oil_temperature_k - rolldyn_units::CELSIUS_ZERO,
            r.cage_slip_dynamic,
            r.slip_drift,
            r.cage_slip_quasi_static,
            r.max_roller_load_n,
            r.revolutions,
            r.note
        )?;
    }
    Ok(())
}
