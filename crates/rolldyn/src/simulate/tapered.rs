//! `simulate` on a double-row tapered bearing (seed 000 §3.2.1): the run, its table and plots
//! with `out`, the summary.

use super::checkpoint::{checkpoint_interval, write_checkpoint};
use super::request::SimulateRequest;
use super::result::{Run, SimulateResult};
use crate::analysis::Context;
use crate::failure::Failure;
use crate::observer::Progress;
use crate::output::out_dir;
use crate::run_record::{ModelOrigin, finish_out_folder};
use crate::table::Table;
use rolldyn_dynamics::tapered::{
    SAMPLE_COLUMNS, TaperedRun, TaperedRunSettings, TaperedSample, TaperedSimulation,
    axial_spectrum, sample_row, steady_window, summary_entries,
};
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot, orbit_plot};
use rolldyn_report::RunKind;
use std::ops::ControlFlow;
use std::path::Path;

/// Runs the tapered bearing `model` as `request` asks; the observer hears of every sample.
pub fn run(
    request: &SimulateRequest,
    model: &rolldyn_model::Model,
    context: &Context<'_>,
) -> Result<SimulateResult, Failure> {
    refuse_cylindrical_only_options(request)?;
    let output_step = request.output_step_s()?;
    let tm = rolldyn_setup::prepare_tapered(model, &request.operating.overrides())?;
    let revolution = std::f64::consts::TAU / tm.epicyclic_cage_speed.abs();
    let t_end = request
        .duration
        .end_time(Some(revolution))
        .map_err(Failure::Input)?;
    if request.out.is_some() {
        let samples = (t_end / output_step).floor() + 1.0;
        let values = samples * SAMPLE_COLUMNS.len() as f64;
        request.check_output_size(values, samples, t_end, output_step)?;
    }
    let mut settings = TaperedRunSettings {
        duration_s: t_end,
        sample_interval_s: output_step,
        row1_offset_pitch: request.row_offset.unwrap_or(0.0),
        ..TaperedRunSettings::default()
    };
    if let Some(tol) = request.tolerance {
        settings.integrator.tolerance = tol;
    }
    if let Some(method) = request.integrator {
        settings.integrator.method = method.method();
    }
    let dir = request.out.as_deref().map(out_dir).transpose()?;
    let observer = context.observer;
    let wall = std::time::Instant::now();
    let mut sim = TaperedSimulation::new(&tm, &settings, false);
    if let Some(path) = &request.resume {
        resume(&mut sim, path, t_end)?;
    }
    let chunk = checkpoint_interval(request, Some(revolution))?.unwrap_or(t_end);
    let mut progress = |t: f64| {
        observer.progress(&Progress {
            done: t.min(t_end),
            total: t_end,
            unit: "s",
            message: None,
        });
        match observer.stop_requested() {
            true => ControlFlow::Break(()),
            false => ControlFlow::Continue(()),
        }
    };
    let mut target = sim.time().unwrap_or(0.0);
    let mut result = Ok(());
    while target < t_end && result.is_ok() {
        target = (target + chunk).min(t_end);
        result = sim.run_until(target, None, &mut progress);
        if let (Some(path), Ok(())) = (&request.checkpoint, &result) {
            write_checkpoint(path, &sim.checkpoint_with(&[]))?;
        }
    }
    result.map_err(|e| Failure::Run(format!("the simulation stopped: {e}")))?;
    let outcome = sim.finish();
    let wall_s = wall.elapsed().as_secs_f64();
    if let Some(dir) = &dir {
        write_outputs(dir, &outcome)?;
    }
    let mut entries = summary_entries(&outcome.summary);
    entries.push(("simulated_s".into(), t_end));
    entries.push(("wall_time_s".into(), wall_s));
    entries.push(("steps".into(), outcome.steps as f64));
    let tables = match request.keep_tables {
        true => vec![sample_table(&outcome)],
        false => Vec::new(),
    };
    let result = SimulateResult {
        model: model.bearing.name().to_string(),
        run: Run::Tapered {
            duration_s: t_end,
            entries,
            most_limiting: outcome.most_limiting.clone(),
        },
        output_folder: dir.as_deref().map(Path::to_path_buf),
        tables,
    };
    if let Some(dir) = &dir {
        finish_out_folder(
            dir,
            RunKind::Simulate,
            ModelOrigin::Source(&context.model),
            &context.invocation,
            &result,
            request.report,
        )?;
    }
    Ok(result)
}

/// Refuses (bad input) the option the tapered dynamics does not have: the cage-load export of
/// the machined cage's fatigue analysis.
fn refuse_cylindrical_only_options(request: &SimulateRequest) -> Result<(), Failure> {
    match request.cage_loads.is_some() {
        true => Err(Failure::Input(
            "--cage-loads: not available for a double-row tapered bearing (cylindrical bearings only)".into(),
        )),
        false => Ok(()),
    }
}

/// Restores the checkpoint at `path` into `sim`; refuses one that is damaged, foreign, or
/// already at or past the end time `t_end` [s]. The tables are written at the end of the run
/// from every sample, those of the checkpoint included.
fn resume(sim: &mut TaperedSimulation, path: &Path, t_end: f64) -> Result<(), Failure> {
    let input = |e: String| Failure::Input(format!("{}: {e}", path.display()));
    let bytes = std::fs::read(path).map_err(|e| input(e.to_string()))?;
    sim.restore(&bytes).map_err(|e| input(e.to_string()))?;
    match sim.time() {
        Some(t) if t >= t_end => Err(input(format!(
            "the checkpoint is at t = {t:.6e} s, at or past the end of --duration ({t_end:.6e} s): nothing to simulate; give a longer --duration"
        ))),
        _ => Ok(()),
    }
}

/// The samples as the table `tapered` (the columns of `tapered.csv`).
fn sample_table(run: &TaperedRun) -> Table {
    let names: Vec<String> = SAMPLE_COLUMNS.iter().map(|s| s.to_string()).collect();
    let values: Vec<f64> = run.samples.iter().flat_map(sample_row).collect();
    Table::from_rows("tapered", &names, &values)
}

/// `tapered.csv`/`.parquet` and the plots of seed 000 Figs. 3.75–3.81.
fn write_outputs(dir: &Path, run: &TaperedRun) -> Result<(), Failure> {
    let names: Vec<String> = SAMPLE_COLUMNS.iter().map(|s| s.to_string()).collect();
    let fail = |e: rolldyn_output::OutputError| Failure::Run(e.to_string());
    let mut table =
        TableWriter::create(dir, "tapered", &names, Formats::default()).map_err(fail)?;
    for s in &run.samples {
        table.write_row(&sample_row(s)).map_err(fail)?;
    }
    table.finish().map_err(fail)?;
    let curve = |f: &dyn Fn(&TaperedSample) -> (f64, f64)| -> Vec<(f64, f64)> {
        run.samples.iter().map(f).collect()
    };
    let ms = 1e3;
    let um = 1e6;
    let plots: [Plot; 4] = [
        (
            "inner_ring_axial.svg",
            "Inner-ring axial displacement",
            "axial displacement, µm",
            vec![(
                "z".into(),
                curve(&|s| (s.time_s * ms, s.inner_ring[2] * um)),
            )],
        ),
        (
            "cage_speeds.svg",
            "Cage speeds",
            "cage speed, rad/s",
            (0..2)
                .map(|k| {
                    (
                        format!("cage {k}"),
                        curve(&|s| (s.time_s * ms, s.cage_speed[k])),
                    )
                })
                .collect(),
        ),
        (
            "rib_forces.svg",
            "Roller 0: large-end and small-end rib forces",
            "force, N",
            (0..2)
                .flat_map(|k| {
                    [
                        (
                            format!("row {k} large end"),
                            curve(&|s| (s.time_s * ms, s.tracked_large_rib[k])),
                        ),
                        (
                            format!("row {k} small end"),
                            curve(&|s| (s.time_s * ms, s.tracked_small_rib[k])),
                        ),
                    ]
                })
                .collect(),
        ),
        (
            "max_roller_loads.svg",
            "Largest roller load on the cone per row",
            "load, N",
            (0..2)
                .map(|k| {
                    (
                        format!("row {k}"),
                        curve(&|s| (s.time_s * ms, s.max_cone_load[k])),
                    )
                })
                .collect(),
        ),
    ];
    for (file, title, y, curves) in plots.into_iter().chain(analysis_plots(run)) {
        let x = match file {
            "inner_ring_trajectory.svg" => "x, µm",
            "inner_ring_axial_spectrum.svg" => "frequency, Hz",
            _ => "time, ms",
        };
        let labels = Labels { title, x, y };
        let series = Series::from_pairs(&curves);
        match file {
            "inner_ring_trajectory.svg" => orbit_plot(&dir.join(file), &labels, &series, &[]),
            _ => line_plot(&dir.join(file), &labels, &series),
        }
        .map_err(|e| Failure::Run(e.to_string()))?;
    }
    Ok(())
}

/// A plot: file name, title, y label, curves.
type Plot = (
    &'static str,
    &'static str,
    &'static str,
    Vec<(String, Vec<(f64, f64)>)>,
);

/// The plots of seed 000 §3.2.1's findings: the inner ring's centre trajectory (polygonal at the
/// roller-pass frequency) and the axial spectrum of the steady window with the
/// roller-pass frequencies marked, the lag of cage 1 behind cage 0 in pocket pitches, and the
/// load-weighted sliding on cone and cup.
fn analysis_plots(run: &TaperedRun) -> [Plot; 4] {
    let steady = steady_window(&run.samples);
    let spectrum = axial_spectrum(steady);
    let top = spectrum.iter().map(|p| p.1 * 1e9).fold(0.0, f64::max);
    let marker = |f: f64| vec![(f, 0.0), (f, top)];
    let pass = [
        run.summary.pass_frequency_outer_hz,
        run.summary.pass_frequency_inner_hz,
    ];
    let pitch = std::f64::consts::TAU / run.summary.rollers_per_row as f64;
    let curve = |f: &dyn Fn(&TaperedSample) -> (f64, f64)| -> Vec<(f64, f64)> {
        run.samples.iter().map(f).collect()
    };
    [
        (
            "inner_ring_trajectory.svg",
            "Inner-ring centre trajectory over the steady window",
            "y, µm",
            vec![(
                "centre".into(),
                steady
                    .iter()
                    .map(|s| (s.inner_ring[0] * 1e6, s.inner_ring[1] * 1e6))
                    .collect(),
            )],
        ),
        (
            "inner_ring_axial_spectrum.svg",
            "Inner-ring axial displacement: amplitude spectrum of the steady window",
            "amplitude, nm",
            vec![
                (
                    "spectrum".into(),
                    spectrum.iter().map(|&(f, a)| (f, a * 1e9)).collect(),
                ),
                (format!("pass, cup {:.1} Hz", pass[0]), marker(pass[0])),
                (format!("pass, cone {:.1} Hz", pass[1]), marker(pass[1])),
            ],
        ),
        (
            "cage_lag.svg",
            "Lag of cage 1 behind cage 0",
            "lag, pocket pitches",
            vec![(
                "cage 1 behind cage 0".into(),
                curve(&|s| (s.time_s * 1e3, (s.cage_angle[0] - s.cage_angle[1]) / pitch)),
            )],
        ),
        (
            "sliding.svg",
            "Load-weighted sliding speed on cone and cup",
            "sliding speed, m/s",
            (0..2)
                .flat_map(|k| {
                    [
                        (
                            format!("row {k} cone"),
                            curve(&|s| (s.time_s * 1e3, s.cone_sliding[k])),
                        ),
                        (
                            format!("row {k} cup"),
                            curve(&|s| (s.time_s * 1e3, s.cup_sliding[k])),
                        ),
                    ]
                })
                .collect(),
        ),
    ]
}
