//! Why an analysis failed, and the exit code that says so.

use std::fmt;

/// An analysis failure: bad input (exit 2) or a failure while running (exit 1).
#[derive(Debug)]
pub enum Failure {
    /// The user's input is wrong: model file, flag value. Exit code 2.
    Input(String),
    /// The analysis or the output failed. Exit code 1.
    Run(String),
}

impl Failure {
    pub fn exit_code(&self) -> u8 {
        match self {
            Self::Input(_) => 2,
            Self::Run(_) => 1,
        }
    }
}

impl From<rolldyn_setup::SetupError> for Failure {
    /// A model that cannot be set up is bad input.
    fn from(e: rolldyn_setup::SetupError) -> Self {
        Self::Input(e.0)
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Input(m) | Self::Run(m) => f.write_str(m),
        }
    }
}

impl From<rolldyn_model::ModelError> for Failure {
    fn from(e: rolldyn_model::ModelError) -> Self {
        Self::Input(e.to_string())
    }
}

impl From<rolldyn_reynolds::ReynoldsError> for Failure {
    /// Rejected or unsolvable input is bad input; a failed iteration is a failed run.
    fn from(e: rolldyn_reynolds::ReynoldsError) -> Self {
        use rolldyn_reynolds::ReynoldsError::*;
        match e {
            InvalidInput { .. } | NoSolution(_) => Self::Input(e.to_string()),
            NotConverged { .. } | Singular(_) | OutOfRange(_) => Self::Run(e.to_string()),
        }
    }
}

impl From<rolldyn_plot::PlotError> for Failure {
    fn from(e: rolldyn_plot::PlotError) -> Self {
        Self::Run(e.to_string())
    }
}

impl From<std::io::Error> for Failure {
    fn from(e: std::io::Error) -> Self {
        Self::Run(e.to_string())
    }
}

impl From<rolldyn_report::ReportError> for Failure {
    /// A missing or foreign folder, a damaged `run.json`, or a `run.json` or `report.html`
    /// that is not a regular file is bad input.
    fn from(e: rolldyn_report::ReportError) -> Self {
        use rolldyn_output::ReplaceError;
        use rolldyn_report::ReportError::*;
        match e {
            Folder { .. } | Manifest { .. } | Replace(ReplaceError::NotRegularFile { .. }) => {
                Self::Input(e.to_string())
            }
            Io { .. } | Replace(ReplaceError::Io { .. }) => Self::Run(e.to_string()),
        }
    }
}

impl std::error::Error for Failure {}

impl From<serde_json::Error> for Failure {
    /// A result that cannot be written as JSON is a failed run.
    fn from(e: serde_json::Error) -> Self {
        Self::Run(e.to_string())
    }
}
