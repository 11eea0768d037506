//! `rolldyn study seed004|skidding|rib-shape|end-rib-limit [--out DIR]`: re-runs a seed's
//! validation study, prints its tables (Markdown, as in VALIDATION.md) and writes CSV tables and
//! SVG plots (library: `rolldyn::study`).

use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::study::{Study, StudyName, StudyRequest, StudyResult};
use rolldyn_units::{Length, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    #[arg(value_enum)]
    pub study: StudyName,
    /// Model file of `end-rib-limit` (a double-row tapered bearing).
    pub model: Option<PathBuf>,
    /// Folder for CSV tables and SVG plots.
    #[arg(long, default_value = "docs/validation")]
    pub out: PathBuf,
    /// Cage revolutions per variant for `rib-shape` (the first is discarded as start transient).
    #[arg(long, default_value_t = 4.0)]
    pub revolutions: f64,
    /// Print JSON instead of the tables (`end-rib-limit`).
    #[arg(long)]
    pub json: bool,
    /// Square cell size of the tangent-plane grid of `end-rib-limit`, e.g. `0.025mm`.
    #[arg(long, default_value = "0.05mm")]
    pub cell: Quantity<Length>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = StudyRequest {
        study: args.study,
        out: args.out,
        revolutions: args.revolutions,
        cell: args.cell,
    };
    let bar = Bar::new(args.json, "study");
    let result = Study::run(&request, &context(args.model.as_deref(), &bar));
    bar.finish();
    match result? {
        result @ StudyResult::EndRibLimit(_) if args.json => print_json(&result),
        result => print_text(&result.to_string()),
    }
}
