//! `rolldyn report DIR`: the self-contained HTML report of an output folder of `simulate`,
//! `sweep`, `wear` or `fatigue`.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::report::{Report, ReportRequest};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Output folder of `simulate`, `sweep`, `wear` or `fatigue` (`--out`).
    pub dir: PathBuf,
    /// Print the report's path, the kind of run and the warnings as JSON.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    run_and_print::<Report>(&ReportRequest { dir: args.dir }, None, args.json)
}
