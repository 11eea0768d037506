//! The dynamics run of a cylindrical roller bearing (SPEC §3): checkpoints and resume, the
//! `out` tables and plots, the cage-load export, the run manifest.

use super::cage_loads::{export_period, sampling, write_cage_loads};
use super::checkpoint::{checkpoint_interval, resume, write_checkpoint};
use super::request::SimulateRequest;
use super::result::{Run, SimulateResult, step_limits};
use super::sinks::{FileSink, OrbitCircles, Sinks, encode_note};
use crate::analysis::Context;
use crate::failure::Failure;
use crate::observer::Progress;
use crate::output::out_dir;
use crate::run_record::{ModelOrigin, finish_out_folder};
use crate::table::Table;
use rolldyn_dynamics::output_columns::{
    BEARING_COLUMNS, MemoryTables, REVOLUTION_COLUMNS, ROLLER_COLUMNS, column_names, table_values,
};
use rolldyn_fatigue::CageLoadRecorder;
use rolldyn_report::RunKind;
use std::ops::ControlFlow;
use std::path::Path;

/// Runs the cylindrical bearing `model` as `request` asks.
pub fn run(
    request: &SimulateRequest,
    model: &rolldyn_model::Model,
    context: &Context<'_>,
) -> Result<SimulateResult, Failure> {
    if request.row_offset.is_some() {
        return Err(Failure::Input(
            "--row-offset: only a double-row tapered bearing has a second row".into(),
        ));
    }
    let output_step = request.output_step_s()?;
    // the cage-load export samples on the epicyclic cage period at t = 0
    let period = export_period(request, model)?;
    let tables = request.out.is_some() || request.keep_tables;
    let (grid_step, thin) = sampling(request, output_step, period, tables)?;
    let overrides = request.operating.overrides();
    let (mut sim, revolution) =
        rolldyn_setup::prepare(model, &overrides, grid_step, request.tolerance)?;
    if let Some(integrator) = request.integrator {
        sim.set_integrator_method(integrator.method());
    }
    let t_end = request
        .duration
        .end_time(revolution)
        .map_err(Failure::Input)?;
    let kept = match &request.resume {
        Some(path) => resume(&mut sim, path, t_end)?,
        None => None,
    };
    let chunk = checkpoint_interval(request, revolution)?.unwrap_or(t_end);
    let dir = match &request.out {
        Some(dir) => {
            let samples = (t_end / output_step).floor() + 1.0;
            let revolutions = revolution.map_or(0.0, |period| t_end / period);
            let values = table_values(samples, revolutions, sim.roller_count());
            request.check_output_size(values, samples, t_end, output_step)?;
            Some(out_dir(dir)?)
        }
        None => None,
    };
    let mut sinks = Sinks {
        files: dir
            .as_deref()
            .map(|dir| FileSink::open(dir, kept, request.resume.is_some()))
            .transpose()?,
        loads: request
            .cage_loads
            .as_ref()
            .map(|_| CageLoadRecorder::default()),
        memory: request.keep_tables.then(MemoryTables::default),
        step: grid_step,
        thin,
    };
    let observer = context.observer;
    let mut report = |t: f64| {
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
    let mut result = Ok(sim.summary());
    while sim.time() < t_end && result.is_ok() {
        let target = (sim.time() + chunk).min(t_end);
        result = sim.run_until_interruptible(target, &mut sinks, &mut report);
        if let (Some(path), Ok(_)) = (&request.checkpoint, &result) {
            let mut note = Vec::new();
            if let Some(files) = &mut sinks.files {
                files.flush().map_err(|e| Failure::Run(e.to_string()))?;
                note = encode_note(&files.kept());
            }
            write_checkpoint(path, &sim.checkpoint_with(&note))?;
        }
    }
    let written = match (sinks.files, &dir) {
        (Some(files), Some(dir)) => files.finish(dir, &orbit_circles(model)),
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
    if let (Some(path), Some(recorder)) = (&request.cage_loads, &sinks.loads) {
        write_cage_loads(path, model, recorder)?;
    }
    let result = SimulateResult {
        model: model.bearing.name().to_string(),
        run: Run::Cylindrical {
            summary,
            step_limited_by: step_limits(&sim.step_limits()),
            drag_and_land: rolldyn_setup::drag_and_land_inputs(model),
        },
        output_folder: dir.as_deref().map(Path::to_path_buf),
        tables: sinks.memory.map(memory_tables).unwrap_or_default(),
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

/// The tables recorded in memory as named columns.
fn memory_tables(memory: MemoryTables) -> Vec<Table> {
    vec![
        Table::from_rows("bearing", &column_names(&BEARING_COLUMNS), &memory.bearing),
        Table::from_rows("rollers", &column_names(&ROLLER_COLUMNS), &memory.rollers),
        Table::from_rows(
            "revolutions",
            &column_names(&REVOLUTION_COLUMNS),
            &memory.revolutions,
        ),
    ]
}

/// The circles of the orbit plots of a cylindrical bearing's run.
fn orbit_circles(model: &rolldyn_model::Model) -> OrbitCircles {
    match &model.bearing {
        rolldyn_geometry::BearingModel::Cylindrical(bearing) => OrbitCircles::of(bearing),
        _ => OrbitCircles {
            cage_land_gap_m: None,
            ring_play_m: 0.0,
        },
    }
}
