//! `rolldyn report DIR`: the self-contained HTML report of an output folder of `simulate`,
//! `sweep`, `wear` or `fatigue` (library: `rolldyn_report`).

use crate::failure::Failure;
use crate::output::print_json;
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
    let written = rolldyn_report::report_folder(&args.dir)?;
    if args.json {
        return print_json(&written);
    }
    println!("{}", written.report.display());
    Ok(())
}
