//! `rolldyn traction`: traction curve μ(s), critical slip and film of a lubricated contact
//! (SPEC §4.5, §4.8; seed 000 Figs 2.8, 2.10, 2.11).

use super::oil_args::OilArgs;
use super::rig_args::RigArgs;
use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::traction::{RheologyName, Traction, TractionRequest};
use rolldyn_units::{Pressure, Quantity, QuantityRange, Speed, Temperature};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub oil: OilArgs,
    #[command(flatten)]
    pub rig: RigArgs,
    /// Oil temperature; a comma list overlays curves (`--temperature 40C,60C,100C`).
    #[arg(
        long,
        allow_hyphen_values = true,
        alias = "temperatures",
        default_value = "40C"
    )]
    pub temperature: QuantityRange<Temperature>,
    /// Maximum Hertz pressure; a list or range gives s_cr against pressure (`0.6GPa..2GPa:0.2GPa`).
    #[arg(
        long,
        allow_hyphen_values = true,
        alias = "max-pressures",
        default_value = "1GPa"
    )]
    pub max_pressure: QuantityRange<Pressure>,
    /// Rolling (entrainment) speed u.
    #[arg(long, allow_hyphen_values = true, default_value = "2.5m/s")]
    pub rolling_speed: Quantity<Speed>,
    /// Largest slip of the curve.
    #[arg(long, default_value = "0.5")]
    pub slip_max: f64,
    /// Points of the curve.
    #[arg(long, default_value = "101")]
    pub points: usize,
    #[arg(long, value_enum, default_value = "visco-elastic")]
    pub rheology: RheologyName,
    #[arg(long)]
    pub json: bool,
    /// Write the curves (CSV) and plots (SVG) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = TractionRequest {
        oil: args.oil.choice(),
        rig: args.rig.rig(),
        temperature: args.temperature.values,
        max_pressure: args.max_pressure.values,
        rolling_speed: args.rolling_speed,
        slip_max: args.slip_max,
        points: args.points,
        rheology: args.rheology,
        out: args.out,
    };
    run_and_print::<Traction>(&request, None, args.json)
}
