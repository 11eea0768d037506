//! The end of a run with an output folder: its manifest (`run.json`) and, when asked, the HTML
//! report of the folder.

use crate::failure::Failure;
use crate::model_source::ModelSource;
use rolldyn_report::{RunKind, RunManifest};
use std::collections::BTreeMap;
use std::path::Path;

/// How a run was asked for, as the skin that asked saw it: recorded in `run.json`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Invocation {
    /// The command line, program name first (`["rolldyn", "simulate", …]`), or the Python call
    /// (`["rolldyn.simulate", "duration=2rev", …]`).
    pub command: Vec<String>,
    /// The options given, as typed (`"--speed": "4000rpm"`), without those that only change
    /// where or how the answer is given (output folder, JSON, quiet, report, jobs).
    pub given: BTreeMap<String, String>,
}

/// Where the run's model came from, for its manifest.
#[derive(Clone, Copy)]
pub enum ModelOrigin<'a> {
    /// A model (or sweep) file.
    File(&'a Path),
    /// The model of a [`ModelSource`].
    Source(&'a ModelSource),
    /// No model read (e.g. `fatigue --loads`).
    None,
}

/// Writes `dir/run.json` with the run's `answer` and, when `report` is asked, `dir/report.html`.
pub fn finish_out_folder(
    dir: &Path,
    kind: RunKind,
    model: ModelOrigin<'_>,
    invocation: &Invocation,
    answer: &impl serde::Serialize,
    report: bool,
) -> Result<(), Failure> {
    let summary = serde_json::to_value(answer)?;
    let (model_file, model_text) = match model {
        ModelOrigin::File(path) => (
            Some(path.display().to_string()),
            std::fs::read_to_string(path).ok(),
        ),
        ModelOrigin::Source(source) => (
            source.file().map(|p| p.display().to_string()),
            source.text(),
        ),
        ModelOrigin::None => (None, None),
    };
    let manifest = RunManifest {
        kind,
        rolldyn_version: env!("CARGO_PKG_VERSION").to_string(),
        overrides: invocation.given.clone(),
        command: invocation.command.clone(),
        model_file,
        model_text,
        summary,
        files: Some(rolldyn_report::plot_checksums(dir)?),
    };
    manifest.write(dir)?;
    if report {
        rolldyn_report::write_report(dir)?;
    }
    Ok(())
}
