//! `rolldyn fatigue rainflow HISTORY.csv`: rainflow cycle counting of a stress history (ASTM
//! E1049; library: `rolldyn_fatigue`).

use crate::failure::Failure;
use crate::output::print_json;
use rolldyn_fatigue::{Cycle, HistoryKind, rainflow, read_history_csv};
use serde::Serialize;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: FatigueCommand,
}

#[derive(clap::Subcommand)]
pub enum FatigueCommand {
    /// Rainflow cycle counting (ASTM E1049 four-point) of a stress history in a CSV file.
    Rainflow(RainflowArgs),
}

#[derive(clap::Args)]
pub struct RainflowArgs {
    /// CSV file: one value per row (first column, or `--column` of a file with a header row).
    pub history: PathBuf,
    /// Column to count (by its header name).
    #[arg(long)]
    pub column: Option<String>,
    /// The file is one period of a repeating history (every cycle closes); otherwise the
    /// residue counts as half cycles.
    #[arg(long)]
    pub periodic: bool,
    /// Print the cycles as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(Serialize)]
struct Answer<'a> {
    history: String,
    periodic: bool,
    values: usize,
    cycles: &'a [Cycle],
}

pub fn run(args: Args) -> Result<(), Failure> {
    match args.command {
        FatigueCommand::Rainflow(a) => run_rainflow(a),
    }
}

fn run_rainflow(args: RainflowArgs) -> Result<(), Failure> {
    let file = args.history.display().to_string();
    let bad = |e: String| Failure::Input(format!("{file}: {e}"));
    let text = rolldyn_model::read_input_file(&args.history).map_err(bad)?;
    let values = read_history_csv(&text, args.column.as_deref()).map_err(bad)?;
    let kind = if args.periodic {
        HistoryKind::Periodic
    } else {
        HistoryKind::NonPeriodic
    };
    let cycles = rainflow(&values, kind);
    if args.json {
        return print_json(&Answer {
            history: file,
            periodic: args.periodic,
            values: values.len(),
            cycles: &cycles,
        });
    }
    println!(
        "{file}: {} values, {} cycles ({})",
        values.len(),
        cycles.iter().map(|c| c.count).sum::<f64>(),
        if args.periodic {
            "periodic"
        } else {
            "non-periodic, residue as half cycles"
        }
    );
    println!("{:>14} {:>14} {:>6}", "range", "mean", "count");
    for c in &cycles {
        println!("{:>14.6e} {:>14.6e} {:>6}", c.range, c.mean, c.count);
    }
    Ok(())
}
