//! What `simulate` is asked: the operating point, the run's length and sampling, the integrator,
//! the output folder, checkpoints and the cage-load export.

use crate::failure::Failure;
use crate::operating::{Duration, Operating};
use rolldyn_dynamics::IntegratorMethod;
use rolldyn_dynamics::settings::DynamicsSettings;
use rolldyn_output::{ByteSize, estimated_table_bytes};
use rolldyn_units::{Quantity, Time};
use serde::Deserialize;
use serde::de::{self, Deserializer};
use std::path::PathBuf;

/// Integration method (`docs/dynamics-integrator.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum IntegratorName {
    /// explicit Dormand–Prince 5(4)
    Dopri5,
    /// linearly implicit Rosenbrock-W ROS34PW2, order 3(2)
    RosenbrockW,
}

impl IntegratorName {
    pub fn method(self) -> IntegratorMethod {
        match self {
            Self::Dopri5 => IntegratorMethod::Dopri5,
            Self::RosenbrockW => IntegratorMethod::RosenbrockW,
        }
    }
}

/// A dynamics run of the model (cylindrical, or double-row tapered).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SimulateRequest {
    /// Overrides of the model's operating point.
    pub operating: Operating,
    /// Simulated duration: cage revolutions (`"20rev"`) or a time (`"0.2s"`).
    pub duration: Duration,
    /// Interval of the time-series samples (at least the integrator's minimum step).
    pub output_step: Quantity<Time>,
    /// Largest estimated size of the `out` tables (bytes, or text such as `"20GB"`): a run
    /// whose tables would be larger is refused before it starts.
    #[serde(deserialize_with = "byte_size")]
    pub max_output: ByteSize,
    /// Relative tolerance of the integrator.
    pub tolerance: Option<f64>,
    /// Integration method (default: dopri5 for a cylindrical bearing, rosenbrock-w for a
    /// tapered one).
    pub integrator: Option<IntegratorName>,
    /// Write the state to this file every `checkpoint_interval` and at the end.
    pub checkpoint: Option<PathBuf>,
    /// Interval of the checkpoints (default one cage revolution).
    pub checkpoint_interval: Option<Duration>,
    /// Continue a run from a checkpoint file (bit for bit) up to `duration`; with `out`, the
    /// tables of that folder are continued.
    pub resume: Option<PathBuf>,
    /// Folder for the time series (CSV + Parquet), the plots (SVG) and `run.json`.
    pub out: Option<PathBuf>,
    /// Write the HTML report of `out` (`report.html`) at the end of the run.
    pub report: bool,
    /// Write the cage loads of the last cage revolution to this Parquet file (and its JSON
    /// header beside it; docs/outputs.md "Cage loads").
    pub cage_loads: Option<PathBuf>,
    /// Double-row tapered bearing: the initial turn of row 2's rollers and cage against row
    /// 1's, in pocket pitches, in [0, 1).
    pub row_offset: Option<f64>,
    /// Keep the bearing, rollers and revolutions tables (the tapered table) in the result.
    pub keep_tables: bool,
}

impl Default for SimulateRequest {
    fn default() -> Self {
        Self {
            operating: Operating::default(),
            duration: Duration::CageRevolutions(5.0),
            output_step: Quantity::from_si(0.05e-3),
            max_output: ByteSize(2e9),
            tolerance: None,
            integrator: None,
            checkpoint: None,
            checkpoint_interval: None,
            resume: None,
            out: None,
            report: false,
            cage_loads: None,
            row_offset: None,
            keep_tables: false,
        }
    }
}

/// A byte count: a number of bytes or text such as `"2GB"`.
fn byte_size<'de, D: Deserializer<'de>>(deserializer: D) -> Result<ByteSize, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Given {
        Bytes(f64),
        Text(String),
    }
    match Given::deserialize(deserializer)? {
        Given::Bytes(b) if b >= 0.0 && b.is_finite() => Ok(ByteSize(b)),
        Given::Bytes(b) => Err(de::Error::custom(format!("{b}: not a size in bytes"))),
        Given::Text(t) => t.parse().map_err(de::Error::custom),
    }
}

/// A row offset in pocket pitches: a fraction in [0, 1).
pub fn check_row_offset(value: f64) -> Result<f64, String> {
    if (0.0..1.0).contains(&value) {
        Ok(value)
    } else {
        Err(format!(
            "'{value}': give a fraction of the pocket pitch in [0, 1), e.g. 0.45"
        ))
    }
}

impl SimulateRequest {
    /// The output step in seconds: at least the integrator's minimum step (no sample can
    /// resolve less), so never zero.
    pub fn output_step_s(&self) -> Result<f64, Failure> {
        let floor = DynamicsSettings::default().integrator.min_step_s;
        match self.output_step.si() {
            s if s >= floor => Ok(s),
            s => Err(Failure::Input(format!(
                "--output-step {s:e} s: must be at least the integrator's minimum step, {floor:e} s"
            ))),
        }
    }

    /// Checks the options that do not depend on the model.
    pub(crate) fn check(&self) -> Result<(), Failure> {
        if self.report && self.out.is_none() {
            return Err(Failure::Input("--report needs --out".into()));
        }
        if self.checkpoint_interval.is_some() && self.checkpoint.is_none() {
            return Err(Failure::Input(
                "--checkpoint-interval needs --checkpoint".into(),
            ));
        }
        if let Some(path) = &self.checkpoint {
            rolldyn_output::ensure_replaceable(path)
                .map_err(|e| crate::output::replace_failure("--checkpoint", e))?;
        }
        if let Some(offset) = self.row_offset {
            check_row_offset(offset).map_err(|e| Failure::Input(format!("--row-offset {e}")))?;
        }
        Ok(())
    }

    /// Refuses (bad input) a run whose tables of `values` numbers in `samples` samples are
    /// estimated ([`estimated_table_bytes`]) to exceed `max_output`, before anything is written.
    pub(crate) fn check_output_size(
        &self,
        values: f64,
        samples: f64,
        t_end: f64,
        output_step: f64,
    ) -> Result<(), Failure> {
        let size = estimated_table_bytes(values);
        let max_output = self.max_output;
        if size <= max_output {
            return Ok(());
        }
        Err(Failure::Input(format!(
            "--out: {samples:.3e} samples (--output-step {output_step:e} s over {t_end:.6e} s) would take an estimated {size}, more than --max-output {max_output}: choose a larger --output-step or a shorter --duration, or raise --max-output"
        )))
    }
}
