//! `rolldyn demo`: the most complete analysis available, on the embedded default model.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::demo::{Demo, DemoRequest};

#[derive(clap::Args)]
pub struct Args {
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Cage revolutions of the dynamics run.
    #[arg(long, default_value = "2")]
    pub revolutions: f64,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = DemoRequest {
        revolutions: args.revolutions,
    };
    run_and_print::<Demo>(&request, None, args.json)
}
