//! What a caller sees of a long analysis while it runs: progress, and a way to stop it.

/// How far a long analysis has come: `done` of `total` in `unit` (simulated seconds for a
/// dynamics run, variants for a sweep, wear periods, fatigue stages…).
#[derive(Clone, Debug, PartialEq)]
pub struct Progress {
    pub done: f64,
    pub total: f64,
    pub unit: &'static str,
    /// What runs now ("variant 3 of 12: z22"), when the analysis says.
    pub message: Option<String>,
}

impl Progress {
    /// `done / total`, within [0, 1].
    pub fn fraction(&self) -> f64 {
        if self.total > 0.0 {
            (self.done / self.total).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// Receives the progress of a long analysis and may stop it (Ctrl-C). Called from the
/// analysis' threads (a sweep runs variants in parallel), often: an observer keeps its own
/// rate limit.
pub trait Observer: Sync {
    /// The analysis has come this far.
    fn progress(&self, _progress: &Progress) {}
    /// A warning the analysis gives without stopping (a temperature outside an oil's range):
    /// the command line prints it on stderr, Python raises a `UserWarning`.
    fn warning(&self, message: &str) {
        use std::io::Write;
        // a closed or full stderr loses the warning, never the run
        let _ = writeln!(std::io::stderr().lock(), "rolldyn: warning: {message}");
    }
    /// Whether the caller asks the analysis to stop; a long analysis asks between its steps
    /// (or variants, or periods) and ends with a [`crate::Failure::Run`] that says it was
    /// interrupted, keeping what it wrote.
    fn stop_requested(&self) -> bool {
        false
    }
}

/// An observer that watches nothing: no progress shown, never stops.
pub struct Unobserved;

impl Observer for Unobserved {}
