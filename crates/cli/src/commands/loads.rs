//! `rolldyn loads MODEL.toml`: quasi-static load distribution of a double-row tapered bearing
//! under radial and axial load with a tilting moment or an imposed misalignment
//! (`rolldyn::loads`); `--out` writes the per-roller table and a plot of the roller loads.

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::loads::{Loads, LoadsRequest};
use rolldyn_units::{Moment, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) of a double-row tapered bearing.
    pub model: PathBuf,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Tilting moment on the inner rings in the plane of the bearing axis and the radial load,
    /// e.g. 2000Nm (the tilt is then solved; excludes --misalignment).
    #[arg(long, allow_hyphen_values = true)]
    pub moment: Option<Quantity<Moment>>,
    /// Angular offset of row 1's rollers against row 0's as a fraction of the roller pitch,
    /// 0 ≤ f < 1 (0: a roller of each row on the load line; 0.5: the seed's stable state, one
    /// roller on the load line in one row and two straddling it in the other).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub row_offset: f64,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// Folder for the per-roller table (CSV, Parquet) and the roller-load plot (SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = LoadsRequest {
        operating: args.operating.operating(),
        moment: args.moment,
        row_offset: args.row_offset,
        out: args.out,
    };
    run_and_print::<Loads>(&request, Some(&args.model), args.json)
}
