//! Simulate: the time-domain 6-DOF dynamics of a cylindrical roller bearing (SPEC §3) or of a
//! double-row tapered bearing (seed 000 §3.2, docs/theory.md §12), with its output folder
//! (tables, plots, `run.json`, report), checkpoints and resume, and the cage-load export.
//!
//! Progress is reported in simulated seconds after every accepted step (every sample for a
//! tapered bearing); an observer that asks to stop ends the run there with a
//! [`Failure::Run`] saying it was interrupted, what was written kept.

mod cage_loads;
mod checkpoint;
mod cylindrical;
mod request;
mod result;
mod sinks;
mod tapered;

pub use request::{IntegratorName, SimulateRequest, check_row_offset};
pub use result::{Run, SimulateResult, StepLimit, step_limits, summary_json, summary_text};

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use rolldyn_geometry::BearingModel;

/// The dynamics analysis.
pub struct Simulate;

impl Analysis for Simulate {
    const NAME: &'static str = "simulate";
    type Request = SimulateRequest;
    type Result = SimulateResult;

    fn run(request: &SimulateRequest, context: &Context<'_>) -> Result<SimulateResult, Failure> {
        request.check()?;
        let model = context.model.load()?;
        match &model.bearing {
            BearingModel::Tapered(_) => tapered::run(request, &model, context),
            _ => cylindrical::run(request, &model, context),
        }
    }
}
