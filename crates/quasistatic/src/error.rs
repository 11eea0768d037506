//! Errors of the quasi-static model. No solver returns NaN: every failure is one of these.

use std::fmt;

/// One named residual reported with a convergence failure.
#[derive(Debug, Clone, PartialEq)]
pub struct Residual {
    /// What the residual measures (e.g. "cage moment / scale").
    pub name: String,
    /// Its last value.
    pub value: f64,
}

/// Why a quasi-static point could not be solved.
#[derive(Debug, Clone, PartialEq)]
pub enum QsError {
    /// An input is outside its physical domain (names the input and the reason).
    InvalidInput(String),
    /// The bearing geometry is inconsistent.
    Geometry(String),
    /// The lubricant lacks a property the chosen friction model needs, or the model is invalid.
    Lubrication(String),
    /// The contact (slice) model failed.
    Contact(String),
    /// An iteration did not converge; carries the last residuals.
    NotConverged {
        /// Which iteration ("load distribution", "roller 3 moment", "cage moment").
        stage: String,
        /// Evaluations / iterations used.
        iterations: usize,
        /// Last residuals.
        residuals: Vec<Residual>,
    },
}

impl fmt::Display for QsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QsError::InvalidInput(m) => write!(f, "invalid input: {m}"),
            QsError::Geometry(m) => write!(f, "bearing geometry: {m}"),
            QsError::Lubrication(m) => write!(f, "lubrication model: {m}"),
            QsError::Contact(m) => write!(f, "contact model: {m}"),
            QsError::NotConverged {
                stage,
                iterations,
                residuals,
            } => {
                write!(
                    f,
                    "quasi-static {stage} did not converge after {iterations} iterations; last residuals:"
                )?;
                for r in residuals {
                    write!(f, " {} = {:.3e};", r.name, r.value)?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for QsError {}

impl QsError {
    /// Shorthand for a one-residual convergence failure.
    pub(crate) fn not_converged(
        stage: impl Into<String>,
        iterations: usize,
        residuals: &[(&str, f64)],
    ) -> Self {
        QsError::NotConverged {
            stage: stage.into(),
            iterations,
            residuals: residuals
                .iter()
                .map(|(n, v)| Residual {
                    name: (*n).to_string(),
                    value: *v,
                })
                .collect(),
        }
    }
}
