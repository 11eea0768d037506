//! The run manifest (`run.json`) of an output folder of `rolldyn simulate`, `sweep`, `wear` or
//! `fatigue`, and the self-contained HTML report of such a folder (`report.html`: plots inline,
//! no network).

mod folder;
mod html;
pub mod manifest;
mod plain_svg;
mod quantities;
mod warnings;

pub use folder::plot_checksums;
pub use manifest::{MANIFEST_FILE, RunKind, RunManifest};
pub use warnings::{
    CAGE_LAND_FORCE_THRESHOLD_N, CAGE_LAND_TO_ROLLER_FORCE_RATIO, Level, SCUFFING_CAUTION_MARGIN,
    SCUFFING_PREDICTED_MARGIN,
};

use std::path::{Path, PathBuf};

/// File name of the report in an output folder.
pub const REPORT_FILE: &str = "report.html";

/// Why no report could be written.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// The folder does not exist or is not one of the four kinds of output folder.
    #[error("{path}: {reason}")]
    Folder { path: PathBuf, reason: String },
    /// `run.json` is damaged or cannot be written.
    #[error("{path}: {reason}")]
    Manifest { path: PathBuf, reason: String },
    #[error("{path}: {reason}")]
    Io { path: PathBuf, reason: String },
    /// `run.json` or `report.html` cannot be written (or is there and not a regular file).
    #[error(transparent)]
    Replace(#[from] rolldyn_output::ReplaceError),
}

impl ReportError {
    fn io(path: &Path, e: std::io::Error) -> Self {
        Self::Io {
            path: path.to_path_buf(),
            reason: e.to_string(),
        }
    }
}

/// A written report: where, of what kind of run, and its findings.
#[derive(Debug, Clone, serde::Serialize)]
pub struct WrittenReport {
    pub report: PathBuf,
    pub kind: RunKind,
    /// The errors and warnings (not the notes), most severe first.
    pub warnings: Vec<String>,
    /// Every finding with its level (error, warning, note).
    pub findings: Vec<Finding>,
}

/// One finding of a report.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Finding {
    pub level: Level,
    /// `""` for the run itself, else `variant <name>`.
    pub place: String,
    pub text: String,
}

/// Writes `dir/report.html` and returns its path.
pub fn write_report(dir: &Path) -> Result<PathBuf, ReportError> {
    report_folder(dir).map(|written| written.report)
}

/// [`write_report`], with the kind of run and the warnings.
pub fn report_folder(dir: &Path) -> Result<WrittenReport, ReportError> {
    let folder = folder::OutputFolder::read(dir)?;
    let warnings = warnings::assess(&folder);
    let page = html::page(&folder, &warnings);
    let path = dir.join(REPORT_FILE);
    rolldyn_output::replace_file_atomically(&path, page.as_bytes())?;
    Ok(WrittenReport {
        report: path,
        kind: folder.kind,
        warnings: warnings.serious().map(|w| w.to_string()).collect(),
        findings: warnings
            .alerts
            .iter()
            .map(|a| Finding {
                level: a.level,
                place: a.place.clone(),
                text: a.text.clone(),
            })
            .collect(),
    })
}
