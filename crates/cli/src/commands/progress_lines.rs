//! An observer that prints the progress messages of a run one line each on stderr (`bench`'s
//! runs, `startup`'s points), or nothing when quiet.

use rolldyn::{Observer, Progress};

pub struct ProgressLines {
    pub quiet: bool,
}

impl Observer for ProgressLines {
    fn progress(&self, progress: &Progress) {
        if let (false, Some(message)) = (self.quiet, &progress.message) {
            crate::output::print_error_line(message);
        }
    }
}
