//! Geometry validation errors, naming the model key they concern.

/// An impossible or inconsistent geometry. `key` is the dotted model-file path of the value at
/// fault (e.g. `roller.length`) so that the model reader can point at the file line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{key}: {reason}")]
pub struct GeometryError {
    pub key: String,
    pub reason: String,
}

impl GeometryError {
    pub fn new(key: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            key: key.into(),
            reason: reason.into(),
        }
    }
}

/// Checks that a value is finite and strictly positive; the error names `key`.
pub fn require_positive(key: &str, value: f64) -> Result<(), GeometryError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(GeometryError::new(
            key,
            format!("must be positive, got {value}"),
        ))
    }
}
