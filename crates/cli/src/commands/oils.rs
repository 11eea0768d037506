//! `rolldyn oils [--temperature 40C] [--json]`: the lubricant library with properties at a
//! temperature.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::oils::{Oils, OilsRequest};
use rolldyn_units::{Quantity, Temperature};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Temperature at which the properties are evaluated (where every oil's laws give finite,
    /// positive values).
    #[arg(long, default_value = "40C", allow_hyphen_values = true)]
    pub temperature: Quantity<Temperature>,
    /// Also list a user oil file (TOML).
    #[arg(long)]
    pub oil_file: Option<PathBuf>,
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = OilsRequest {
        temperature: args.temperature,
        oil_file: args.oil_file,
    };
    run_and_print::<Oils>(&request, None, args.json)
}
