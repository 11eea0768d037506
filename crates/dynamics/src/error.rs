//! Errors of the dynamics engine. No function of this crate panics on bad input or on a failed
//! integration: every failure is a [`DynError`] carrying a diagnosis.

use std::fmt;

/// Failure of a dynamics run or of its set-up.
#[derive(Debug, Clone, PartialEq)]
pub enum DynError {
    /// An input is missing, not finite or out of range (`what` names the input).
    InvalidInput(String),
    /// A state component or its derivative became NaN/∞.
    NonFinite {
        /// simulated time of the last accepted state, s
        time_s: f64,
        /// body and state component (e.g. "roller 3 spin (L_z)")
        component: String,
        /// step size tried, s
        step_s: f64,
    },
    /// The error-controlled step size fell below `IntegratorSettings::min_step_s`.
    StepSizeCollapse {
        /// simulated time, s
        time_s: f64,
        /// step size, s
        step_s: f64,
        /// state component with the largest scaled error in the last rejected step
        component: String,
    },
    /// A body left its physical envelope (e.g. roller through a raceway, cage through a land).
    Divergence {
        /// simulated time, s
        time_s: f64,
        /// body and contact
        body: String,
        /// what happened
        detail: String,
        /// last step size, s
        step_s: f64,
    },
    /// The step budget `IntegratorSettings::max_steps` of one `run_until` call was used up.
    StepBudgetExhausted {
        /// simulated time reached, s
        time_s: f64,
        /// steps taken
        steps: u64,
    },
    /// A checkpoint could not be read or does not belong to this simulation.
    Checkpoint(String),
    /// The caller's progress callback asked to stop (e.g. Ctrl-C in Python); the state is the
    /// last accepted one.
    Interrupted {
        /// simulated time reached, s
        time_s: f64,
    },
}

impl fmt::Display for DynError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DynError::InvalidInput(w) => write!(f, "invalid dynamics input: {w}"),
            DynError::NonFinite {
                time_s,
                component,
                step_s,
            } => write!(
                f,
                "non-finite value in {component} at t = {time_s:.9} s (step {step_s:.3e} s)"
            ),
            DynError::StepSizeCollapse {
                time_s,
                step_s,
                component,
            } => write!(
                f,
                "step size collapsed to {step_s:.3e} s at t = {time_s:.9} s; the error is driven by {component}"
            ),
            DynError::Divergence {
                time_s,
                body,
                detail,
                step_s,
            } => write!(
                f,
                "divergence at t = {time_s:.9} s in {body}: {detail} (last step {step_s:.3e} s)"
            ),
            DynError::StepBudgetExhausted { time_s, steps } => write!(
                f,
                "step budget exhausted after {steps} steps at t = {time_s:.9} s"
            ),
            DynError::Checkpoint(w) => write!(f, "checkpoint: {w}"),
            DynError::Interrupted { time_s } => write!(f, "interrupted at t = {time_s:.9} s"),
        }
    }
}

impl std::error::Error for DynError {}
