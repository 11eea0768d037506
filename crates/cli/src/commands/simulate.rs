//! `rolldyn simulate MODEL.toml`: time-domain 6-DOF dynamics of a cylindrical roller bearing
//! (SPEC §3), streaming its time series to CSV/Parquet and plotting the main histories.

use crate::failure::Failure;
use crate::output::{load_model, print_json};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rolldyn::output::out_dir;
use rolldyn_dynamics::output::{OutputSink, RevolutionSummary, RunSummary, Snapshot};
use rolldyn_dynamics::output_columns::{
    BEARING_COLUMNS, Column, REVOLUTION_COLUMNS, ROLLER_COLUMNS, bearing_row, column_names,
    revolution_row, roller_row, table_values,
};
use rolldyn_dynamics::settings::DynamicsSettings;
use rolldyn_dynamics::{IntegratorMethod, Simulation, SummaryValue};
use rolldyn_output::{
    ByteSize, Formats, KeptRows, OutputError, TableWriter, estimated_table_bytes,
};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_units::{Quantity, Time};
use serde::Serialize;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use super::operating_args::OperatingArgs;
use rolldyn::run_record::{ModelOrigin, finish_out_folder};
use rolldyn_fatigue::{CageLoadExport, CageLoadRecorder, export_output_step};
use rolldyn_report::RunKind;
use rolldyn_setup::prepare;

/// How long to simulate: cage revolutions (`20rev`) or a time (`0.2s`, `50ms`).
#[derive(Clone, Copy, Debug)]
pub enum Duration {
    CageRevolutions(f64),
    Time(f64),
}

impl FromStr for Duration {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let text = text.trim();
        let duration = match text.strip_suffix("rev") {
            Some(n) => Duration::CageRevolutions(
                n.trim()
                    .parse()
                    .map_err(|_| format!("'{text}': expected e.g. 20rev or 0.2s"))?,
            ),
            None => Duration::Time(
                Quantity::<Time>::parse(text)
                    .map_err(|e| e.to_string())?
                    .si(),
            ),
        };
        match duration {
            Duration::CageRevolutions(v) | Duration::Time(v) if v > 0.0 && v.is_finite() => {
                Ok(duration)
            }
            _ => Err(format!("'{text}': the duration must be positive")),
        }
    }
}

/// Integration method (`docs/dynamics-integrator.md`).
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum IntegratorArg {
    /// explicit Dormand–Prince 5(4)
    Dopri5,
    /// linearly implicit Rosenbrock-W ROS34PW2, order 3(2)
    RosenbrockW,
}

impl IntegratorArg {
    pub(crate) fn method(self) -> IntegratorMethod {
        match self {
            Self::Dopri5 => IntegratorMethod::Dopri5,
            Self::RosenbrockW => IntegratorMethod::RosenbrockW,
        }
    }
}

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
    pub integrator: Option<IntegratorArg>,
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
    match text.parse::<f64>() {
        Ok(v) if (0.0..1.0).contains(&v) => Ok(v),
        _ => Err(format!(
            "'{text}': give a fraction of the pocket pitch in [0, 1), e.g. 0.45"
        )),
    }
}

/// Keeps at most `capacity` points of a history for plotting (halving the density when full),
/// so that memory stays bounded however long the run.
struct Decimated {
    points: Vec<(f64, f64)>,
    stride: usize,
    seen: usize,
    capacity: usize,
}

impl Decimated {
    fn new(capacity: usize) -> Self {
        Self {
            points: Vec::new(),
            stride: 1,
            seen: 0,
            capacity,
        }
    }

    fn push(&mut self, x: f64, y: f64) {
        if self.seen.is_multiple_of(self.stride) {
            if self.points.len() == self.capacity {
                self.points = self.points.iter().step_by(2).copied().collect();
                self.stride *= 2;
            }
            if self.seen.is_multiple_of(self.stride) {
                self.points.push((x, y));
            }
        }
        self.seen += 1;
    }
}

/// The decimated histories of the plots, fed with the table rows (so that a resumed run
/// rebuilds them from the rows it keeps).
struct Plots {
    cage_speed: Decimated,
    epicyclic: Decimated,
    cage_slip: Decimated,
    cage_orbit: Decimated,
    inner_orbit: Decimated,
    roller_inner: Decimated,
    roller_outer: Decimated,
    roller_bar: Decimated,
}

/// Position of the column `name` in a table schema.
fn position<A>(columns: &[Column<A>], name: &str) -> usize {
    columns
        .iter()
        .position(|c| c.name == name)
        .expect("a column of the schema")
}

impl Plots {
    fn new() -> Self {
        let plot = || Decimated::new(4000);
        Self {
            cage_speed: plot(),
            epicyclic: plot(),
            cage_slip: plot(),
            cage_orbit: plot(),
            inner_orbit: plot(),
            roller_inner: plot(),
            roller_outer: plot(),
            roller_bar: plot(),
        }
    }

    /// A row of the `bearing` table.
    fn bearing(&mut self, row: &[f64]) {
        let v = |name| row[position(&BEARING_COLUMNS, name)];
        let t = v("time_s");
        self.cage_speed.push(t, v("cage_speed_rad_s"));
        self.epicyclic.push(t, v("epicyclic_cage_speed_rad_s"));
        self.cage_slip.push(t, v("cage_slip"));
        self.cage_orbit
            .push(v("cage_x_m") * 1e6, v("cage_y_m") * 1e6);
        self.inner_orbit
            .push(v("inner_ring_x_m") * 1e6, v("inner_ring_y_m") * 1e6);
    }

    /// A row of the `rollers` table: the forces of roller 1 are plotted.
    fn roller(&mut self, row: &[f64]) {
        let v = |name| row[position(&ROLLER_COLUMNS, name)];
        if v("roller") == 1.0 {
            let t = v("time_s");
            self.roller_inner.push(t, v("inner_force_n"));
            self.roller_outer.push(t, v("outer_force_n"));
            self.roller_bar.push(t, v("cage_bar_force_n"));
        }
    }
}

/// What a checkpoint notes of the `--out` tables `bearing`, `rollers` and `revolutions`: their
/// rows and digests at that point.
type TablesNote = [KeptRows; 3];

fn encode_note(note: &TablesNote) -> Vec<u8> {
    note.iter()
        .flat_map(|k| [k.rows as u64, k.digest])
        .flat_map(u64::to_le_bytes)
        .collect()
}

/// The tables note of a checkpoint; `None` when its run had no `--out` (an empty note).
fn decode_note(note: &[u8]) -> Result<Option<TablesNote>, String> {
    if note.is_empty() {
        return Ok(None);
    }
    let words: Vec<u64> = note
        .chunks_exact(8)
        .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
        .collect();
    match words.as_slice() {
        &[r0, d0, r1, d1, r2, d2] if note.len() == 48 => Ok(Some(
            [(r0, d0), (r1, d1), (r2, d2)].map(|(rows, digest)| KeptRows {
                rows: rows as usize,
                digest,
            }),
        )),
        _ => Err("the note on the output tables is not one of rolldyn simulate".into()),
    }
}

/// Streams samples to tables and keeps decimated histories for the plots.
struct FileSink {
    bearing: TableWriter,
    rollers: TableWriter,
    revolutions: TableWriter,
    row: Vec<f64>,
    error: Option<OutputError>,
    plots: Plots,
}

impl FileSink {
    /// The tables in `dir`: new ones, or those of an interrupted run continued after the rows
    /// `kept` by its checkpoint (a `resumed` run; new tables when that run had no `--out`); the
    /// plots start from the kept rows.
    fn open(dir: &Path, kept: Option<TablesNote>, resumed: bool) -> Result<Self, Failure> {
        let fresh = KeptRows { rows: 0, digest: 0 };
        let [bearing, rollers, revolutions] = kept.unwrap_or([fresh; 3]);
        let table = |stem: &str, names: Vec<String>, kept, on_row: &mut dyn FnMut(&[f64])| {
            TableWriter::resume(dir, stem, &names, Formats::default(), kept, on_row).map_err(
                |e| match resumed {
                    true => Failure::Input(format!(
                        "{e} (--resume continues the --out folder of the run that wrote the checkpoint)"
                    )),
                    false => Failure::Run(e.to_string()),
                },
            )
        };
        let mut plots = Plots::new();
        Ok(Self {
            bearing: table(
                "bearing",
                column_names(&BEARING_COLUMNS),
                bearing,
                &mut |row| plots.bearing(row),
            )?,
            rollers: table(
                "rollers",
                column_names(&ROLLER_COLUMNS),
                rollers,
                &mut |row| plots.roller(row),
            )?,
            revolutions: table(
                "revolutions",
                column_names(&REVOLUTION_COLUMNS),
                revolutions,
                &mut |_| {},
            )?,
            row: Vec::with_capacity(ROLLER_COLUMNS.len()),
            error: None,
            plots,
        })
    }

    /// The rows written so far, for the checkpoint's note.
    fn kept(&self) -> TablesNote {
        [&self.bearing, &self.rollers, &self.revolutions].map(TableWriter::kept)
    }

    fn keep(&mut self, result: Result<(), OutputError>) {
        if let (Err(e), None) = (result, &self.error) {
            self.error = Some(e);
        }
    }

    /// Hands the rows written so far to the system (before a checkpoint, so that the CSV files
    /// are never behind it).
    fn flush(&mut self) -> Result<(), OutputError> {
        if let Some(e) = &self.error {
            return Err(e.clone());
        }
        for table in [&mut self.bearing, &mut self.rollers, &mut self.revolutions] {
            table.flush()?;
        }
        Ok(())
    }

    fn finish(self, dir: &Path) -> Result<(), Failure> {
        if let Some(e) = self.error {
            return Err(Failure::Run(e.to_string()));
        }
        for table in [self.bearing, self.rollers, self.revolutions] {
            table.finish().map_err(|e| Failure::Run(e.to_string()))?;
        }
        let plot = |file: &str, title: &str, x: &str, y: &str, series: &[Series]| {
            line_plot(&dir.join(file), &Labels { title, x, y }, series)
        };
        plot(
            "cage_speed.svg",
            "Cage speed",
            "time, s",
            "rad/s",
            &[
                Series {
                    label: "cage",
                    points: &self.plots.cage_speed.points,
                },
                Series {
                    label: "epicyclic",
                    points: &self.plots.epicyclic.points,
                },
            ],
        )?;
        plot(
            "cage_slip.svg",
            "Cage slip (1 − ω_c/ω_epicyclic)",
            "time, s",
            "slip",
            &[Series {
                label: "",
                points: &self.plots.cage_slip.points,
            }],
        )?;
        plot(
            "cage_orbit.svg",
            "Cage centre orbit",
            "x, µm",
            "y, µm",
            &[Series {
                label: "",
                points: &self.plots.cage_orbit.points,
            }],
        )?;
        plot(
            "inner_ring_orbit.svg",
            "Inner-ring centre orbit",
            "x, µm",
            "y, µm",
            &[Series {
                label: "",
                points: &self.plots.inner_orbit.points,
            }],
        )?;
        plot(
            "roller_1_forces.svg",
            "Contact forces of roller 1",
            "time, s",
            "force, N",
            &[
                Series {
                    label: "inner raceway",
                    points: &self.plots.roller_inner.points,
                },
                Series {
                    label: "outer raceway",
                    points: &self.plots.roller_outer.points,
                },
                Series {
                    label: "cage bars",
                    points: &self.plots.roller_bar.points,
                },
            ],
        )?;
        Ok(())
    }
}

impl OutputSink for FileSink {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        bearing_row(s, &mut self.row);
        let result = self.bearing.write_row(&self.row);
        self.keep(result);
        self.plots.bearing(&self.row);
        for j in 0..s.rollers.azimuth_rad.len() {
            roller_row(s, j, &mut self.row);
            let result = self.rollers.write_row(&self.row);
            self.keep(result);
            self.plots.roller(&self.row);
        }
    }

    fn revolution(&mut self, v: &RevolutionSummary) {
        revolution_row(v, &mut self.row);
        let result = self.revolutions.write_row(&self.row);
        self.keep(result);
    }
}

/// Forwards to an optional file sink (so the run is the same with or without `--out`) and an
/// observer's tables — every `thin`-th sample of the grid `step`, when the cage-load recorder
/// needs a finer grid — and to an optional cage-load recorder.
struct Sinks<'a> {
    files: Option<FileSink>,
    loads: Option<CageLoadRecorder>,
    observer: Option<&'a mut dyn OutputSink>,
    step: f64,
    thin: u64,
}

impl OutputSink for Sinks<'_> {
    fn sample(&mut self, t: f64, s: &Snapshot) {
        if ((t / self.step).round() as u64).is_multiple_of(self.thin) {
            if let Some(f) = &mut self.files {
                f.sample(t, s);
            }
            if let Some(o) = &mut self.observer {
                o.sample(t, s);
            }
        }
        if let Some(r) = &mut self.loads {
            r.sample(t, s);
        }
    }
    fn revolution(&mut self, v: &RevolutionSummary) {
        if let Some(f) = &mut self.files {
            f.revolution(v);
        }
        if let Some(o) = &mut self.observer {
            o.revolution(v);
        }
        if let Some(r) = &mut self.loads {
            r.revolution(v);
        }
    }
}

/// The sampling of a run: the step of the dynamics' output grid and every how many samples the
/// `--out` tables take one (1 without `--cage-loads`; else the grid is refined to at least four
/// samples per 2° load set).
fn sampling(
    args: &Args,
    output_step: f64,
    revolution: Option<f64>,
    observed: bool,
) -> Result<(f64, u64), Failure> {
    let tables = args.out.is_some() || observed;
    let Some(path) = &args.cage_loads else {
        return Ok((if tables { output_step } else { 0.0 }, 1));
    };
    let period = revolution.ok_or_else(|| {
        Failure::Input(format!(
            "--cage-loads {}: the rings do not turn at t = 0, there is no cage revolution to record",
            path.display()
        ))
    })?;
    let fine = export_output_step(std::f64::consts::TAU / period, 4.0);
    if !tables {
        return Ok((fine, 1));
    }
    let thin = (output_step / fine).ceil().max(1.0);
    Ok((output_step / thin, thin as u64))
}

/// Writes the load export of the recorded revolution to `path`.
fn write_cage_loads(
    path: &Path,
    model: &rolldyn_model::Model,
    recorder: &CageLoadRecorder,
) -> Result<(), Failure> {
    let bearing = model
        .bearing
        .require_cylindrical("--cage-loads")
        .map_err(Failure::Input)?;
    let cage = rolldyn_fatigue::study::cage_geometry(bearing, None).map_err(Failure::Input)?;
    let sets = recorder.last_revolution().map_err(|e| {
        Failure::Run(format!(
            "--cage-loads: {e}; run at least one cage revolution (--duration)"
        ))
    })?;
    let turned = sets.last().map_or(0.0, |s| s.time_s) - sets.first().map_or(0.0, |s| s.time_s);
    let speed = std::f64::consts::TAU * (1.0 - 1.0 / sets.len() as f64) / turned.max(1e-12);
    let export = CageLoadExport {
        header: rolldyn_fatigue::study::export_header(
            &model.source.file,
            &cage,
            bearing.roller.bar_contact_half_span(),
            speed,
        ),
        sets,
    };
    export
        .write(path)
        .map_err(|e| Failure::Run(format!("--cage-loads: {e}")))
}

/// A kind of state component and its share of the steps it limited.
#[derive(Serialize)]
pub struct StepLimit {
    component: String,
    share: f64,
}

/// The three kinds of state component that limited the step most often (of
/// `Simulation::step_limits`), with their shares of all counted steps.
pub(crate) fn step_limits(counts: &[(String, u64)]) -> Vec<StepLimit> {
    let total: u64 = counts.iter().map(|(_, c)| c).sum();
    counts
        .iter()
        .take(3)
        .map(|(kind, c)| StepLimit {
            component: kind.clone(),
            share: *c as f64 / total.max(1) as f64,
        })
        .collect()
}

/// The JSON answer of `rolldyn simulate --json`: the model, every figure of the run summary
/// (`RunSummary::fields`, SI units), the step limits (when counted) and the output folder, under
/// the non-finite policy of docs/outputs.md.
fn answer_json(
    model: &str,
    s: &RunSummary,
    step_limited_by: &[StepLimit],
    output_folder: Option<String>,
) -> serde_json::Value {
    let mut object = serde_json::Map::new();
    object.insert("model".into(), model.into());
    for (name, value) in s.fields() {
        let value = match value {
            SummaryValue::Real(v) => v.into(),
            SummaryValue::Count(n) => n.into(),
            SummaryValue::Flag(b) => b.into(),
        };
        object.insert(name.into(), value);
    }
    if !step_limited_by.is_empty() {
        let limits = serde_json::to_value(step_limited_by).unwrap_or_default();
        object.insert("step_limited_by".into(), limits);
    }
    object.insert("output_folder".into(), output_folder.into());
    rolldyn_output::mark_non_finite(&mut object, &s.columns(), |key, v| {
        non_finite_reason(key, v).to_string()
    });
    serde_json::Value::Object(object)
}

impl Duration {
    /// The end time for a cage revolution period `revolution` [s] (`None`: the rings start at
    /// rest, and a number of revolutions is no duration).
    pub fn end_time(self, revolution: Option<f64>) -> Result<f64, String> {
        match (self, revolution) {
            (Duration::CageRevolutions(n), Some(period)) => Ok(n * period),
            (Duration::CageRevolutions(_), None) => Err(
                "the inner ring starts at rest (operating.speed_schedule): give --duration as a time, e.g. 0.5s, or a constant --speed".into(),
            ),
            (Duration::Time(t), _) => Ok(t),
        }
    }
}

/// What a caller of [`run_observed`] sees of a run besides its answer.
pub struct Observer<'a> {
    /// Receives the samples and revolutions of the `--out` tables (the run then samples at
    /// `--output-step` even without `--out`).
    pub tables: Option<&'a mut dyn OutputSink>,
    /// Called with the simulated time and the end time (s) after every accepted step; `Break`
    /// stops the run ([`rolldyn_dynamics::DynError::Interrupted`]).
    pub progress: &'a mut dyn FnMut(f64, f64) -> ControlFlow<()>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    run_observed(
        args,
        Observer {
            tables: None,
            progress: &mut |_, _| ControlFlow::Continue(()),
        },
    )
}

/// [`run`], with the tables and the progress also handed to `observer`.
pub fn run_observed(args: Args, observer: Observer<'_>) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?;
    if let rolldyn_geometry::BearingModel::Tapered(_) = &model.bearing {
        return super::simulate_tapered::run_tapered(&args, &model, observer.progress);
    }
    if args.row_offset.is_some() {
        return Err(Failure::Input(
            "--row-offset: only a double-row tapered bearing has a second row".into(),
        ));
    }
    let output_step = checked_output_step(args.output_step)?;
    // the cage-load export samples on the epicyclic cage period at t = 0
    let period = match (&args.cage_loads, &model.bearing) {
        (Some(_), rolldyn_geometry::BearingModel::Cylindrical(bearing)) => {
            let c = rolldyn_setup::conditions(&args.operating.overrides(), &model)?;
            let w =
                bearing.epicyclic_cage_speed(c.inner_speed.speed(0.0), c.outer_speed.speed(0.0));
            (w != 0.0).then(|| std::f64::consts::TAU / w.abs())
        }
        (Some(_), _) => {
            return Err(Failure::Input(
                "--cage-loads needs a complete bearing (bearing.kind = \"cylindrical\")".into(),
            ));
        }
        (None, _) => None,
    };
    let (grid_step, thin) = sampling(&args, output_step, period, observer.tables.is_some())?;
    let (mut sim, revolution) = prepare(
        &model,
        &args.operating.overrides(),
        grid_step,
        args.tolerance,
    )?;
    if let Some(integrator) = args.integrator {
        sim.set_integrator_method(integrator.method());
    }
    let t_end = args.duration.end_time(revolution).map_err(Failure::Input)?;
    let kept = match &args.resume {
        Some(path) => resume(&mut sim, path, t_end)?,
        None => None,
    };
    let chunk = checkpoint_interval(&args, revolution)?.unwrap_or(t_end);
    let dir = match &args.out {
        Some(dir) => {
            let samples = (t_end / output_step).floor() + 1.0;
            let revolutions = revolution.map_or(0.0, |period| t_end / period);
            let values = table_values(samples, revolutions, sim.roller_count());
            check_output_size(values, samples, t_end, output_step, args.max_output)?;
            Some(out_dir(dir)?)
        }
        None => None,
    };
    let mut sinks = Sinks {
        files: dir
            .as_deref()
            .map(|dir| FileSink::open(dir, kept, args.resume.is_some()))
            .transpose()?,
        loads: args
            .cage_loads
            .as_ref()
            .map(|_| CageLoadRecorder::default()),
        observer: observer.tables,
        step: grid_step,
        thin,
    };
    let bar = progress_bar(args.quiet, t_end);
    let mut report = |t: f64| {
        bar.set_position((1000.0 * t / t_end).min(1000.0) as u64);
        (observer.progress)(t, t_end)
    };
    let mut result = Ok(sim.summary());
    while sim.time() < t_end && result.is_ok() {
        let target = (sim.time() + chunk).min(t_end);
        result = sim.run_until_interruptible(target, &mut sinks, &mut report);
        if let (Some(path), Ok(_)) = (&args.checkpoint, &result) {
            let mut note = Vec::new();
            if let Some(files) = &mut sinks.files {
                files.flush().map_err(|e| Failure::Run(e.to_string()))?;
                note = encode_note(&files.kept());
            }
            write_checkpoint(path, &sim.checkpoint_with(&note))?;
        }
    }
    bar.finish_and_clear();
    let written = match (sinks.files, &dir) {
        (Some(files), Some(dir)) => files.finish(dir),
        _ => Ok(()),
    };
    let summary = result.map_err(|e| {
        Failure::Run(format!(
            "the simulation stopped: {e}{}",
            dir.as_ref().map_or(String::new(), |d| format!(
                "; outputs up to that time are in {}",
                d.display()
            ))
        ))
    })?;
    written?;
    if let (Some(path), Some(recorder)) = (&args.cage_loads, &sinks.loads) {
        write_cage_loads(path, &model, recorder)?;
    }
    let limits = step_limits(&sim.step_limits());
    let answer = answer_json(
        model.bearing.name(),
        &summary,
        &limits,
        dir.as_ref().map(|d| d.display().to_string()),
    );
    if let Some(dir) = &dir {
        let model_source = rolldyn::ModelSource::file_or_embedded(args.model.as_deref());
        let model_file = ModelOrigin::Source(&model_source);
        finish_out_folder(
            dir,
            RunKind::Simulate,
            model_file,
            &crate::output::invocation(),
            &answer,
            args.report,
        )?;
    }
    if args.json {
        return print_json(&answer);
    }
    print_summary(model.bearing.name(), &summary, &limits);
    for (name, value) in rolldyn_setup::drag_and_land_inputs(&model) {
        println!("  {name:<34} {value}");
    }
    Ok(())
}

/// The `--output-step` in seconds: at least the integrator's minimum step (no sample can
/// resolve less), so never zero.
pub(super) fn checked_output_step(step: Quantity<Time>) -> Result<f64, Failure> {
    let floor = DynamicsSettings::default().integrator.min_step_s;
    match step.si() {
        s if s >= floor => Ok(s),
        s => Err(Failure::Input(format!(
            "--output-step {s:e} s: must be at least the integrator's minimum step, {floor:e} s"
        ))),
    }
}

/// Restores the checkpoint at `path` into `sim` and returns its note on the output tables;
/// refuses one that is damaged, foreign, or already at or past the end time `t_end` [s].
fn resume(sim: &mut Simulation, path: &Path, t_end: f64) -> Result<Option<TablesNote>, Failure> {
    let bytes =
        std::fs::read(path).map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
    let note = sim.restore(&bytes).map_err(|e| {
        let text = e.to_string();
        let hint = if text.contains("integrator method") {
            " (resume with the --integrator of the run that wrote it)"
        } else if text.contains("output step") {
            " (resume with the --output-step of the run that wrote it)"
        } else {
            ""
        };
        Failure::Input(format!("{}: {text}{hint}", path.display()))
    })?;
    if sim.time() >= t_end {
        return Err(Failure::Input(format!(
            "{}: the checkpoint is at t = {:.6e} s, at or past the end of --duration ({t_end:.6e} s): nothing to simulate; give a longer --duration",
            path.display(),
            sim.time()
        )));
    }
    decode_note(&note).map_err(|e| Failure::Input(format!("{}: {e}", path.display())))
}

/// The simulated time between checkpoints [s]: `--checkpoint-interval`, else one cage
/// revolution; `None` (only at the end) without `--checkpoint` or for rings starting at rest.
fn checkpoint_interval(args: &Args, revolution: Option<f64>) -> Result<Option<f64>, Failure> {
    if args.checkpoint.is_none() {
        return Ok(None);
    }
    match (args.checkpoint_interval, revolution) {
        (Some(Duration::CageRevolutions(_)), None) => Err(Failure::Input(
            "--checkpoint-interval: the inner ring starts at rest (operating.speed_schedule): give the interval as a time, e.g. 10ms".into(),
        )),
        (Some(interval), _) => interval.end_time(revolution).map(Some).map_err(Failure::Input),
        (None, period) => Ok(period),
    }
}

/// Refuses (bad input) a run whose tables of `values` numbers in `samples` samples are
/// estimated ([`estimated_table_bytes`]) to exceed `--max-output`, before anything is written.
pub(super) fn check_output_size(
    values: f64,
    samples: f64,
    t_end: f64,
    output_step: f64,
    max_output: ByteSize,
) -> Result<(), Failure> {
    let size = estimated_table_bytes(values);
    if size <= max_output {
        return Ok(());
    }
    Err(Failure::Input(format!(
        "--out: {samples:.3e} samples (--output-step {output_step:e} s over {t_end:.6e} s) would take an estimated {size}, more than --max-output {max_output}: choose a larger --output-step or a shorter --duration, or raise --max-output"
    )))
}

/// Writes a checkpoint through a temporary file renamed over `path`, so that a run killed
/// while writing leaves the previous checkpoint intact.
fn write_checkpoint(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    let mut partial = path.as_os_str().to_owned();
    partial.push(".partial");
    let partial = PathBuf::from(partial);
    std::fs::write(&partial, bytes)
        .and_then(|_| std::fs::rename(&partial, path))
        .map_err(|e| Failure::Run(format!("{}: {e}", path.display())))
}

pub(crate) fn progress_bar(quiet: bool, t_end: f64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::stderr());
    if quiet {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} simulating {msg} [{bar:40}] {percent}% ({elapsed}, eta {eta})",
        )
        .expect("valid template")
        .progress_chars("=> "),
    );
    bar.set_message(format!("{:.4} s", t_end));
    bar
}

pub fn print_summary(model: &str, s: &RunSummary, limits: &[StepLimit]) {
    println!(
        "{model}: dynamics, {:.4} s simulated in {:.2} s",
        s.simulated_time_s, s.wall_time_s
    );
    let line = |label: &str, value: String| println!("  {label:<34} {value}");
    line(
        "cage speed (mean)",
        format!("{:.2} rad/s", s.cage_speed_mean_rad_s),
    );
    line(
        "epicyclic cage speed",
        format!("{:.2} rad/s", s.epicyclic_cage_speed_rad_s),
    );
    line(
        "cage slip (mean)",
        format!("{:.4} %", s.cage_slip_mean * 100.0),
    );
    line(
        "max inner / outer contact force",
        format!(
            "{:.1} / {:.1} N",
            s.max_inner_contact_force_n, s.max_outer_contact_force_n
        ),
    );
    line(
        "max roller–cage force",
        format!("{:.2} N", s.max_roller_cage_force_n),
    );
    line(
        "max cage–land force",
        format!("{:.2} N", s.max_cage_land_force_n),
    );
    line(
        "max inner sliding speed",
        format!(
            "{:.3} m/s (rolling direction {:.3}, axial {:.3}; most loaded roller {:.3}, {:.3})",
            s.max_inner_sliding_speed_m_s,
            s.max_inner_sliding_rolling_direction_m_s,
            s.max_inner_sliding_axial_m_s,
            s.max_inner_sliding_rolling_direction_most_loaded_m_s,
            s.max_inner_sliding_axial_most_loaded_m_s
        ),
    );
    line("max relative slip", format!("{:.4}", s.max_relative_slip));
    line(
        "min scuffing margin s_cr/s",
        format!("{:.2}", s.min_scuffing_margin),
    );
    line(
        "whirl ratio",
        if s.whirl_ratio.is_finite() {
            format!(
                "{:.3}{}",
                s.whirl_ratio,
                if s.precession { " (precession)" } else { "" }
            )
        } else {
            format!(
                "— (the cage centre does not orbit; RMS offset {:.1} µm)",
                s.cage_orbit_radius_m * 1e6
            )
        },
    );
    line(
        "steps (rejected) / RHS evaluations",
        format!("{} ({}) / {}", s.steps, s.rejected_steps, s.rhs_evaluations),
    );
    if !limits.is_empty() {
        let shares: Vec<String> = limits
            .iter()
            .map(|l| format!("{} {:.0} %", l.component, 100.0 * l.share))
            .collect();
        line("step limited by", shares.join(", "));
    }
}

/// Why a run-summary value is not a finite number (docs/outputs.md).
fn non_finite_reason(key: &str, value: f64) -> &'static str {
    match key {
        "min_scuffing_margin" => "no scuffing-margin maximum in the run",
        "whirl_ratio" if value.is_nan() => "the cage centre does not orbit (no whirl)",
        _ => rolldyn_output::default_reason(value),
    }
}

/// The JSON form of a run summary (used by `demo`).
pub fn summary_json(model: &str, s: &RunSummary) -> serde_json::Value {
    answer_json(model, s, &[], None)
}
