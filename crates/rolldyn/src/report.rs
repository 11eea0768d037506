//! Report: the self-contained HTML report (`DIR/report.html`) of an output folder of
//! `simulate`, `sweep`, `wear` or `fatigue` (`rolldyn_report`).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::table::Tables;
use rolldyn_report::WrittenReport;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::PathBuf;

/// The output folder to report on.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReportRequest {
    /// Output folder of `simulate`, `sweep`, `wear` or `fatigue` (their `out`).
    pub dir: PathBuf,
}

/// The report written: its path, the kind of run and the warnings at its top.
#[derive(Clone, Debug, Serialize)]
pub struct ReportResult {
    #[serde(flatten)]
    pub written: WrittenReport,
}

impl Tables for ReportResult {}

impl fmt::Display for ReportResult {
    /// The report's path.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.written.report.display())
    }
}

/// The report analysis.
pub struct Report;

impl Analysis for Report {
    const NAME: &'static str = "report";
    type Request = ReportRequest;
    type Result = ReportResult;

    /// Refuses a folder that a run is writing (it holds the folder's lock).
    fn run(request: &ReportRequest, _context: &Context<'_>) -> Result<ReportResult, Failure> {
        let _lock = match request.dir.is_dir() {
            true => Some(
                rolldyn_output::FolderLock::acquire(&request.dir)
                    .map_err(|e| Failure::Input(e.to_string()))?,
            ),
            false => None,
        };
        Ok(ReportResult {
            written: rolldyn_report::report_folder(&request.dir)?,
        })
    }
}
