//! The cage-load export of a cylindrical run (`cage_loads`): the epicyclic period it samples
//! on, the refined output grid, and the file of the last cage revolution's load sets.

use super::request::SimulateRequest;
use crate::failure::Failure;
use rolldyn_fatigue::{CageLoadExport, CageLoadRecorder, export_output_step};
use rolldyn_geometry::BearingModel;
use std::path::Path;

/// The epicyclic cage period at t = 0 [s] that the export samples on; `None` without
/// `cage_loads` or when the rings are at rest.
pub fn export_period(
    request: &SimulateRequest,
    model: &rolldyn_model::Model,
) -> Result<Option<f64>, Failure> {
    match (&request.cage_loads, &model.bearing) {
        (Some(_), BearingModel::Cylindrical(bearing)) => {
            let c = rolldyn_setup::conditions(&request.operating.overrides(), model)?;
            let w =
                bearing.epicyclic_cage_speed(c.inner_speed.speed(0.0), c.outer_speed.speed(0.0));
            Ok((w != 0.0).then(|| std::f64::consts::TAU / w.abs()))
        }
        (Some(_), _) => Err(Failure::Input(
            "--cage-loads needs a complete bearing (bearing.kind = \"cylindrical\")".into(),
        )),
        (None, _) => Ok(None),
    }
}

/// The sampling of a run: the step of the dynamics' output grid and every how many samples the
/// tables take one (1 without `cage_loads`; else the grid is refined to at least four samples
/// per 2° load set). `tables`: the run writes or keeps tables.
pub fn sampling(
    request: &SimulateRequest,
    output_step: f64,
    revolution: Option<f64>,
    tables: bool,
) -> Result<(f64, u64), Failure> {
    let Some(path) = &request.cage_loads else {
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
pub fn write_cage_loads(
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
            rolldyn_fatigue::cage_material::CageMaterial::of(bearing),
            bearing.roller.bar_contact_half_span(),
            speed,
        ),
        sets,
    };
    export
        .write(path)
        .map_err(|e| Failure::Run(format!("--cage-loads: {e}")))
}
