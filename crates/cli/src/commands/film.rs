//! `rolldyn film`: central and minimum film thickness, Λ and regime of a lubricated contact.

use super::oil_args::OilArgs;
use super::rig_args::RigArgs;
use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::film::{Film, FilmRequest, FormulaName, LambdaName};
use rolldyn_units::{Force, Length, Quantity, Speed, Temperature};

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub oil: OilArgs,
    #[command(flatten)]
    pub rig: RigArgs,
    #[arg(long, allow_hyphen_values = true, default_value = "40C")]
    pub temperature: Quantity<Temperature>,
    /// Normal load of the contact.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Quantity<Force>,
    /// Rolling (entrainment) speed u.
    #[arg(long, allow_hyphen_values = true)]
    pub rolling_speed: Quantity<Speed>,
    /// Roughness Ra of the two surfaces, e.g. `0.32um,0.16um`.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_delimiter = ',',
        default_value = "0,0"
    )]
    pub roughness: Vec<Quantity<Length>>,
    #[arg(long, value_enum, default_value = "auto")]
    pub formula: FormulaName,
    #[arg(long, value_enum, default_value = "seed000")]
    pub lambda: LambdaName,
    /// Inlet starvation: multiply both films by this factor (1 = flooded).
    #[arg(long, default_value = "1", conflicts_with = "grease")]
    pub starvation: f64,
    /// Grease lubrication: starvation factor 0.7 (seed 000, −30 %).
    #[arg(long)]
    pub grease: bool,
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = FilmRequest {
        oil: args.oil.choice(),
        rig: args.rig.rig(),
        temperature: args.temperature,
        load: args.load,
        rolling_speed: args.rolling_speed,
        roughness: args.roughness,
        formula: args.formula,
        lambda: args.lambda,
        starvation: args.starvation,
        grease: args.grease,
    };
    run_and_print::<Film>(&request, None, args.json)
}
