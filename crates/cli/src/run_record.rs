//! The end of a run with `--out`: its manifest (`run.json`) and, with `--report`, the HTML
//! report of the folder.

use crate::failure::Failure;
use clap::CommandFactory;
use clap::parser::ValueSource;
use rolldyn_report::{RunKind, RunManifest};
use std::collections::BTreeMap;
use std::path::Path;

/// Flags that change where, how or how fast the answer is given, not what is computed.
const PRESENTATION_FLAGS: [&str; 5] = ["out", "json", "quiet", "report", "jobs"];

/// Where the run's model came from.
pub enum ModelOrigin<'a> {
    /// A model (or sweep) file.
    File(&'a Path),
    /// The embedded model, unless one is given in memory through [`crate::api`].
    Default,
    /// No model read (e.g. `fatigue --loads`).
    None,
}

impl<'a> ModelOrigin<'a> {
    /// The origin of a command's optional model argument.
    pub fn of(model: Option<&'a Path>) -> Self {
        model.map_or(Self::Default, Self::File)
    }
}

/// Writes `dir/run.json` with the run's `answer` and, when `report` is asked, `dir/report.html`.
pub fn finish_out_folder(
    dir: &Path,
    kind: RunKind,
    model: ModelOrigin<'_>,
    answer: &impl serde::Serialize,
    report: bool,
) -> Result<(), Failure> {
    let summary = serde_json::to_value(answer).map_err(|e| Failure::Run(e.to_string()))?;
    let command = crate::api::command_line();
    let given_in_memory = crate::api::given_model().is_some();
    let (model_file, model_text) = match model {
        // a model given through the api replaces the file's text
        ModelOrigin::File(path) if given_in_memory => (Some(path.display().to_string()), None),
        ModelOrigin::File(path) => (
            Some(path.display().to_string()),
            std::fs::read_to_string(path).ok(),
        ),
        ModelOrigin::Default if !given_in_memory => {
            (None, Some(rolldyn_model::DEFAULT_MODEL.to_string()))
        }
        ModelOrigin::Default | ModelOrigin::None => (None, None),
    };
    let manifest = RunManifest {
        kind,
        rolldyn_version: env!("CARGO_PKG_VERSION").to_string(),
        overrides: given_flags(&command),
        command,
        model_file,
        model_text,
        summary,
    };
    manifest.write(dir)?;
    if report {
        rolldyn_report::write_report(dir)?;
    }
    Ok(())
}

/// The flags of `command_line` given on it, as typed (`"--speed": "4000rpm"`), without the
/// presentation flags.
fn given_flags(command_line: &[String]) -> BTreeMap<String, String> {
    let cli = crate::Cli::command();
    let Ok(matches) = cli.clone().try_get_matches_from(command_line) else {
        return BTreeMap::new();
    };
    let Some((name, given)) = matches.subcommand() else {
        return BTreeMap::new();
    };
    let Some(command) = cli.find_subcommand(name) else {
        return BTreeMap::new();
    };
    command
        .get_arguments()
        .filter_map(|arg| {
            let long = arg.get_long()?;
            let id = arg.get_id().as_str();
            if PRESENTATION_FLAGS.contains(&long)
                || given.value_source(id) != Some(ValueSource::CommandLine)
            {
                return None;
            }
            let values: Vec<String> = given
                .try_get_raw(id)
                .ok()
                .flatten()
                .map(|raw| raw.map(|v| v.to_string_lossy().into_owned()).collect())
                .unwrap_or_default();
            Some((format!("--{long}"), values.join(",")))
        })
        .collect()
}
