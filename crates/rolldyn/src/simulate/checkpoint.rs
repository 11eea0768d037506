//! Checkpoints of a cylindrical run: written every interval through a temporary file, and a
//! run resumed from one (bit for bit, with its note on the output tables).

use super::request::SimulateRequest;
use super::sinks::{TablesNote, decode_note};
use crate::failure::Failure;
use crate::operating::Duration;
use crate::output::replace_failure;
use rolldyn_dynamics::Simulation;
use rolldyn_output::replace_file_atomically;
use std::path::Path;

/// Restores the checkpoint at `path` into `sim` and returns its note on the output tables;
/// refuses one that is damaged, foreign, or already at or past the end time `t_end` [s].
pub fn resume(
    sim: &mut Simulation,
    path: &Path,
    t_end: f64,
) -> Result<Option<TablesNote>, Failure> {
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

/// The simulated time between checkpoints [s]: `checkpoint_interval`, else one cage
/// revolution; `None` (only at the end) without `checkpoint` or for rings starting at rest.
pub fn checkpoint_interval(
    request: &SimulateRequest,
    revolution: Option<f64>,
) -> Result<Option<f64>, Failure> {
    if request.checkpoint.is_none() {
        return Ok(None);
    }
    match (request.checkpoint_interval, revolution) {
        (Some(Duration::CageRevolutions(_)), None) => Err(Failure::Input(
            "--checkpoint-interval: the inner ring starts at rest (operating.speed_schedule): give the interval as a time, e.g. 10ms".into(),
        )),
        (Some(interval), _) => interval.end_time(revolution).map(Some).map_err(Failure::Input),
        (None, period) => Ok(period),
    }
}

/// Writes a checkpoint through a temporary file renamed over `path`, so that a run killed
/// while writing leaves the previous checkpoint intact; `path` must be a regular file or new.
pub fn write_checkpoint(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    replace_file_atomically(path, bytes).map_err(|e| replace_failure("--checkpoint", e))
}
