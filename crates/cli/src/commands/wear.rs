//! `rolldyn wear MODEL.toml`: Archard wear of the raceways, rollers, cage bars, roller ends and
//! ribs over the bearing's life, fed back into the geometry period by period (seed 000 §2.4,
//! docs/theory.md §8); double-row tapered bearings by short dynamics windows per period
//! (library: `rolldyn::wear`).

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text};
use rolldyn::Analysis;
use rolldyn::wear::{ExposureName, MethodName, Period, PressureName, Wear, WearRequest};
use rolldyn_units::{Length, Quantity, Time};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with [lubricant], [operating] and the materials' meyer_hardness; the
    /// embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Life to reach (e.g. 25000h; default 25000h, a double-row tapered bearing 11429h as seed
    /// 000 §3.2.4).
    #[arg(long)]
    pub life: Option<Quantity<Time>>,
    /// Recalculation period: a time (1905h) or `auto` (starts at 1905 h, halves the period when
    /// a wear rate changes by more than 50 % between periods or reverses its trend).
    #[arg(long, default_value = "1905h")]
    pub period: Period,
    /// Wear method (default direct; a double-row tapered bearing averaged, as seed 000 §3.2.3
    /// continues after comparing both).
    #[arg(long, value_enum)]
    pub method: Option<MethodName>,
    /// Cage revolutions recorded per period (after --settle discarded ones).
    #[arg(long, default_value_t = 10)]
    pub revolutions: u32,
    /// Cage revolutions run and discarded before recording.
    #[arg(long, default_value_t = 10)]
    pub settle: u32,
    /// Mean pressure on the raceway wear lines (docs/theory.md §8.5).
    #[arg(long, value_enum, default_value = "slices")]
    pub pressure: PressureName,
    /// Width a surface point spends under the contact (seed 000 eq. 3.1, flag F-47).
    #[arg(long, value_enum, default_value = "full")]
    pub exposure_width: ExposureName,
    /// Read the hardness as the seed did (its kgf/mm² numbers as MPa, flag F-45).
    #[arg(long)]
    pub seed_literal_hardness: bool,
    /// Stop when the operating radial clearance has grown by this much (e.g. 30um).
    #[arg(long)]
    pub max_clearance_increase: Option<Quantity<Length>>,
    /// Stop when any surface is worn this deep (e.g. 0.1mm).
    #[arg(long)]
    pub max_depth: Option<Quantity<Length>>,
    /// Double-row tapered bearing: dynamics time run and discarded from the seated start before
    /// each window (default 10ms).
    #[arg(long)]
    pub window_settle: Option<Quantity<Time>>,
    /// Double-row tapered bearing: dynamics time recorded per period (default 20ms).
    #[arg(long)]
    pub window: Option<Quantity<Time>>,
    /// Output folder: tables, plots and the worn model (default `out/<model name>-wear`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// The most recalculation periods the life may take (life / period; with `--period auto`
    /// life / its smallest period, 1905 h / 64): a larger count is refused before the run.
    #[arg(long, default_value_t = rolldyn::wear::DEFAULT_MAX_PERIODS)]
    pub max_periods: u64,
    /// Write the HTML report of the output folder (`report.html`) at the end of the run.
    #[arg(long)]
    pub report: bool,
    /// Continue the run killed or interrupted in the output folder (its `wear.state`, stored
    /// after every period), with the same model and options: the periods done are kept.
    #[arg(long)]
    pub resume: bool,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = WearRequest {
        operating: args.operating.operating(),
        life: args.life,
        period: args.period,
        method: args.method,
        revolutions: args.revolutions,
        settle: args.settle,
        pressure: args.pressure,
        exposure_width: args.exposure_width,
        seed_literal_hardness: args.seed_literal_hardness,
        max_clearance_increase: args.max_clearance_increase,
        max_depth: args.max_depth,
        window_settle: args.window_settle,
        window: args.window,
        out: args.out,
        report: args.report,
        max_periods: args.max_periods,
        resume: args.resume,
    };
    let bar = Bar::new(args.quiet || args.json, "wear");
    let result = Wear::run(&request, &context(args.model.as_deref(), &bar));
    bar.finish();
    let result = result?;
    if args.json {
        print_json(&result)
    } else {
        print_text(&result.to_string())
    }
}
