//! `rolldyn contact MODEL.toml --load 1167N`: roller–raceway contact pressure.

use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::contact::{Contact, ContactRequest, LawName, Method, Raceway, parse_cells};
use rolldyn_units::{Angle, Force, Length, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML); the embedded default model when omitted.
    pub model: Option<PathBuf>,
    /// Roller load, e.g. `1167N`.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Quantity<Force>,
    /// Roller tilt relative to the raceway, e.g. `4arcmin` (added to the model's misalignment).
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub tilt: Quantity<Angle>,
    /// Boussinesq grid: cells along the roller × cells across, e.g. `350x9` (seed 004 Table 2);
    /// at least 4 cells across the Hertz contact width 2b on a grid 1.1 × 2b wide. Default:
    /// 150 cells along, 6 across 2b on a grid 1.5 × 2b wide.
    #[arg(long, value_parser = parse_cells)]
    pub cells: Option<(usize, usize)>,
    /// Total transverse extent of the Boussinesq grid (default: square cells with `--cells`,
    /// flag F-12 of docs/theory.md).
    #[arg(long, allow_hyphen_values = true)]
    pub width: Option<Quantity<Length>>,
    #[arg(long, value_enum, default_value = "boussinesq")]
    pub method: Method,
    /// Raceway of a bearing model to load (a roller-raceway model has only one).
    #[arg(long, value_enum, default_value = "inner")]
    pub raceway: Raceway,
    /// Slice law of the slice method: seed 000 eqs (2.3)/(2.4), or ISO/TS 16281 laminae.
    #[arg(long, value_enum, default_value = "seed")]
    pub slice_law: LawName,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Write the pressure map and central line (CSV) and their plots (SVG) to this folder.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = ContactRequest {
        load: args.load,
        tilt: args.tilt,
        cells: args.cells,
        width: args.width,
        method: args.method,
        raceway: args.raceway,
        slice_law: args.slice_law,
        out: args.out,
    };
    let observer = Bar::hidden();
    let result = Contact::run(&request, &context(args.model.as_deref(), &observer))?;
    if args.json {
        print_json(&result)?;
    } else {
        print_text(&result.to_string())?;
    }
    // a solution that did not converge is shown, then fails
    result.convergence()
}
