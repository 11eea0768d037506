//! `run.json`: what a run of `simulate`, `sweep`, `wear` or `fatigue` was given and answered.

use crate::ReportError;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// File name of the manifest in an output folder.
pub const MANIFEST_FILE: &str = "run.json";

/// The command whose output folder it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RunKind {
    Simulate,
    Sweep,
    Wear,
    Fatigue,
}

impl RunKind {
    pub fn name(self) -> &'static str {
        match self {
            Self::Simulate => "simulate",
            Self::Sweep => "sweep",
            Self::Wear => "wear",
            Self::Fatigue => "fatigue",
        }
    }
}

/// The inputs and the answer of one run, written to `DIR/run.json` at its end.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunManifest {
    pub kind: RunKind,
    pub rolldyn_version: String,
    /// The command line, program name first.
    pub command: Vec<String>,
    /// The model (or sweep) file; `None` for the embedded model or a model given in memory.
    pub model_file: Option<String>,
    /// The text of that file, or of the embedded model.
    pub model_text: Option<String>,
    /// The flags given on the command line (`"--speed": "4000rpm"`), as typed.
    pub overrides: BTreeMap<String, String>,
    /// The JSON answer of the run (what `--json` prints).
    pub summary: serde_json::Value,
    /// The files of the folder the run wrote that a report inlines (its SVG plots), by path
    /// relative to the folder, with their checksum ([`rolldyn_output::checksum_hex`]); `None`
    /// in manifests of older versions.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub files: Option<BTreeMap<String, String>>,
}

impl RunManifest {
    /// Writes `dir/run.json` (replacing a previous one whole) and returns its path.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, ReportError> {
        let path = dir.join(MANIFEST_FILE);
        let text = serde_json::to_string_pretty(self).map_err(|e| ReportError::Manifest {
            path: path.clone(),
            reason: e.to_string(),
        })?;
        rolldyn_output::replace_file_atomically(&path, (text + "\n").as_bytes())?;
        Ok(path)
    }

    /// Reads `dir/run.json`; `None` when the folder has none.
    pub fn read(dir: &Path) -> Result<Option<Self>, ReportError> {
        let path = dir.join(MANIFEST_FILE);
        let text = match std::fs::read_to_string(&path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(ReportError::io(&path, e)),
        };
        serde_json::from_str(&text)
            .map(Some)
            .map_err(|e| ReportError::Manifest {
                path,
                reason: e.to_string(),
            })
    }
}
