//! Wear of the contact surfaces of a roller bearing and its feedback into the geometry over the
//! bearing's life (seed 000 §2.4, §3.1.1.5–3.1.1.7; docs/theory.md §8).
//!
//! - [`law`]: Archard's law (seed 000 eq. 2.34), hardness conversions and the life conversion;
//! - [`coefficient`]: the wear coefficient as a function of the film parameter Λ;
//! - [`averaged`]: the averaged-parameter method (seed 000 eqs. 2.35–2.37);
//! - [`wear_line`], [`bar_load`]: the mean pressure on a wear line through a contact patch;
//! - [`recorder`]: the direct and averaged methods as a sink of the dynamics' output steps;
//! - [`rates`]: wear (depth or rate) on every wear line of every [`surface`];
//! - [`worn`]: the worn geometry; [`life`]: the life loop; [`settings`]: its knobs;
//! - [`tapered`]: the same for the double-row tapered bearing (seed 000 §3.2.2–3.2.4).

pub mod averaged;
pub mod bar_load;
pub mod bearing_data;
pub mod boussinesq_lines;
pub mod coefficient;
pub mod law;
pub mod life;
pub mod rates;
pub mod recorder;
pub mod report;
pub mod settings;
pub mod study;
pub mod surface;
pub mod tapered;
pub mod wear_line;
pub mod worn;
pub mod worn_model;

pub use life::{
    LifeInputs, LifeRun, LifeState, PeriodRecord, StopReason, halved_period_check, run_life,
};
pub use rates::SurfaceWear;
pub use settings::{
    ExposureWidth, OperabilityLimits, PeriodControl, PressureModel, WearMethod, WearSettings,
};
pub use surface::{PerSurface, Surface};

/// Why a wear calculation stopped.
#[derive(Debug, thiserror::Error)]
pub enum WearError {
    /// bad or missing input (exit code 2)
    #[error("{0}")]
    Input(String),
    /// a model-file key that is missing or unusable for wear (exit code 2; the caller names
    /// the file)
    #[error("{key} — {reason}")]
    Key { key: String, reason: String },
    /// the dynamics failed (exit code 1)
    #[error("{0}")]
    Numerical(String),
}
