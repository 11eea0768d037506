use std::fmt;

/// Errors of the lubrication library (configuration-time only: the hot path [`crate::traction()`]
/// never fails).
#[derive(Debug, Clone, PartialEq)]
pub enum LubError {
    /// An oil name not in the built-in library; carries the list of known names.
    UnknownOil {
        /// the name asked for
        name: String,
        /// the names the library knows
        known: Vec<&'static str>,
    },
    /// A property the selected model needs is not defined for this oil (the seeds do not give it).
    MissingProperty {
        /// oil name
        oil: String,
        /// which property (e.g. "eyring_stress (τ0)")
        property: &'static str,
    },
    /// An input value outside its physical domain.
    InvalidInput(String),
    /// A property of an oil outside its physical or plausible range
    /// ([`crate::plausible`]); `key` as in [`crate::OilProperty::key`] (or `temperature_range`,
    /// `roelands_z`).
    Property {
        /// oil name
        oil: String,
        /// the property at fault
        key: &'static str,
        /// why
        reason: String,
    },
}

impl fmt::Display for LubError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LubError::UnknownOil { name, known } => write!(
                f,
                "unknown lubricant '{name}'; known built-in oils: {}",
                known.join(", ")
            ),
            LubError::MissingProperty { oil, property } => write!(
                f,
                "lubricant '{oil}' has no {property}: the seeds do not give it; supply it in a user oil file"
            ),
            LubError::InvalidInput(s) => write!(f, "invalid input: {s}"),
            LubError::Property { oil, key, reason } => write!(f, "oil '{oil}': {key} {reason}"),
        }
    }
}

impl std::error::Error for LubError {}
