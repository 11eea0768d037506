//! `rolldyn fatigue MODEL.toml`: the life of the cage from one steady revolution of the
//! dynamics (seed 000 §2.5, docs/theory.md §10); `rolldyn fatigue rainflow HISTORY.csv`:
//! rainflow cycle counting of any stress history (ASTM E1049). Library: `rolldyn::fatigue`.

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::{Bar, context, print_json, print_text, run_and_print};
use rolldyn::Analysis;
use rolldyn::fatigue::{
    BelowKneeName, Fatigue, FatigueRequest, InterfaceName, MeanStressName, Rainflow,
    RainflowRequest, StressName, parse_factor_pair,
};
use rolldyn_units::{Length, Quantity};
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    #[command(subcommand)]
    pub command: Option<FatigueCommand>,
    /// Model file (TOML) with a [cage] and [lubricant]; the embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Cage stress model.
    #[arg(long, value_enum, default_value = "frame")]
    pub stress: StressName,
    /// Cage revolutions simulated and discarded before the recorded one.
    #[arg(long, default_value_t = 8)]
    pub revolutions: u32,
    /// Evaluate the Al₂O₃ inclusion (2 × 3.5 × 5 µm; interface debonded, or `--inclusion=bonded`) at
    /// the critical location too.
    #[arg(long, value_enum, num_args = 0..=1, require_equals = true, default_missing_value = "debonded")]
    pub inclusion: Option<InterfaceName>,
    /// Mean-stress correction of the counted cycles.
    #[arg(long, value_enum, default_value = "none")]
    pub mean_stress: MeanStressName,
    /// Radius of the window-corner fillet (e.g. 0.5mm), overriding the model's
    /// `cage.pocket.fillet_radius`.
    #[arg(long)]
    pub fillet_radius: Option<Quantity<Length>>,
    /// Largest element size of the CalculiX solid model away from the fillets (e.g. 6mm;
    /// default 8 mm). With --stress calculix.
    #[arg(long)]
    pub mesh_size: Option<Quantity<Length>>,
    /// Element size of the CalculiX solid model at the fillet corners (e.g. 0.4mm; default
    /// 0.6 mm). With --stress calculix.
    #[arg(long)]
    pub fillet_mesh_size: Option<Quantity<Length>>,
    /// Stress-concentration factors of the frame model's fillets, `TENSION,BENDING` (default: from
    /// the fillet radius by Roark's shoulder-fillet charts).
    #[arg(long, value_parser = parse_factor_pair)]
    pub stress_concentration: Option<[f64; 2]>,
    /// The base S–N curve (fully reversed) as CSV rows `N, sigma_a_MPa`, replacing the cage
    /// material's (default: the S–N curve of `cage.material`, docs/theory.md §10.5).
    #[arg(long)]
    pub sn_curve: Option<PathBuf>,
    /// Factor on the S–N curve replacing the plating's (default: from `cage.plating`, silver
    /// 1.5; 1 unplated). Refused on an unplated cage.
    #[arg(long)]
    pub coating_factor: Option<f64>,
    /// Safety factor on stress (applied to the S–N curve besides the coating factor).
    #[arg(long, default_value_t = 1.0)]
    pub safety_factor: f64,
    /// Cycles below the knee of the S–N curve (10⁷ cycles).
    #[arg(long, value_enum, default_value = "no-damage")]
    pub below_knee: BelowKneeName,
    /// Read the cage loads from an export (`rolldyn simulate --cage-loads`) instead of running
    /// the dynamics.
    #[arg(long, conflicts_with = "model")]
    pub loads: Option<PathBuf>,
    /// Output folder: the load export, stress history, damage map and plots.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the HTML report of the `--out` folder (`report.html`) at the end of the run.
    #[arg(long, requires = "out")]
    pub report: bool,
    /// Folder of the cached CalculiX unit cases (default `out/calculix-cache`).
    #[arg(long)]
    pub cache: Option<PathBuf>,
    /// Continue the run killed or interrupted in the `--out` folder (its `fatigue.state`: the
    /// dynamics after each settling revolution, then the recorded loads).
    #[arg(long, requires = "out", conflicts_with = "loads")]
    pub resume: bool,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

#[derive(clap::Subcommand)]
pub enum FatigueCommand {
    /// Rainflow cycle counting (ASTM E1049 four-point) of a stress history in a CSV file.
    Rainflow(RainflowArgs),
}

#[derive(clap::Args)]
pub struct RainflowArgs {
    /// CSV file: one value per row (first column, or `--column` of a file with a header row),
    /// read line by line, of any size.
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

pub fn run(args: Args) -> Result<(), Failure> {
    let Args {
        command,
        model,
        operating,
        stress,
        revolutions,
        inclusion,
        mean_stress,
        fillet_radius,
        mesh_size,
        fillet_mesh_size,
        stress_concentration,
        sn_curve,
        coating_factor,
        safety_factor,
        below_knee,
        loads,
        out,
        report,
        cache,
        resume,
        json,
        quiet,
    } = args;
    if let Some(FatigueCommand::Rainflow(a)) = command {
        let request = RainflowRequest {
            history: a.history,
            column: a.column,
            periodic: a.periodic,
        };
        return run_and_print::<Rainflow>(&request, None, a.json);
    }
    let request = FatigueRequest {
        operating: operating.operating(),
        stress,
        revolutions,
        inclusion,
        mean_stress,
        fillet_radius,
        mesh_size,
        fillet_mesh_size,
        stress_concentration,
        sn_curve,
        coating_factor,
        safety_factor,
        below_knee,
        loads,
        out,
        report,
        cache,
        resume,
    };
    let bar = Bar::new(quiet || json, "fatigue");
    let result = Fatigue::run(&request, &context(model.as_deref(), &bar));
    bar.finish();
    let result = result?;
    if json {
        print_json(&result)
    } else {
        print_text(&result.to_string())
    }
}
