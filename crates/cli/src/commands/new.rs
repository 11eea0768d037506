//! `rolldyn new`: a cylindrical roller bearing model file from an ISO designation or from its
//! boundary dimensions.

use crate::failure::Failure;
use crate::output::run_and_print;
use rolldyn::new_model::{CageName, ClearanceGroupName, NewModel, NewModelRequest, RibsName};
use rolldyn_units::{AngularSpeed, Force, Length, Quantity, Temperature};
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(
    after_help = "Examples:\n  rolldyn new NU2215 -o nu2215.toml\n  rolldyn new --bore 75mm --outside 130mm --width 31mm --roller-diameter 15mm \\\n      --roller-length 22mm --rollers 16 --cage brass --speed 5000rpm --radial-load 15kN -o b.toml"
)]
pub struct Args {
    /// ISO designation: NU, NJ, NUP or N with dimension series 10, 2, 22, 3, 23 and a bore code
    /// (NU2215, "NJ 310", N1012).
    pub designation: Option<String>,
    /// Boundary form: bore d.
    #[arg(long, requires_all = ["outside", "width"], conflicts_with = "designation")]
    pub bore: Option<Quantity<Length>>,
    /// Boundary form: outside diameter D.
    #[arg(long, requires_all = ["bore", "width"])]
    pub outside: Option<Quantity<Length>>,
    /// Boundary form: width B.
    #[arg(long, requires_all = ["bore", "outside"])]
    pub width: Option<Quantity<Length>>,
    /// Boundary form: which ring has the ribs.
    #[arg(long = "type", value_enum, ignore_case = true, requires = "bore")]
    pub ribs: Option<RibsName>,
    /// Roller diameter D_w from a catalogue (else estimated).
    #[arg(long)]
    pub roller_diameter: Option<Quantity<Length>>,
    /// Roller length L_w from a catalogue (else estimated).
    #[arg(long)]
    pub roller_length: Option<Quantity<Length>>,
    /// Number of rollers Z from a catalogue (else from the cage bar rule).
    #[arg(long)]
    pub rollers: Option<usize>,
    /// Cage material.
    #[arg(long, value_enum, default_value = "brass")]
    pub cage: CageName,
    /// Radial clearance group (ISO 5753-1).
    #[arg(long, value_enum, ignore_case = true, default_value = "CN")]
    pub clearance_group: ClearanceGroupName,
    /// Built-in oil (`rolldyn oils`).
    #[arg(long)]
    pub oil: Option<String>,
    /// Bearing name in the model (default: the designation, or type and d×D×B).
    #[arg(long)]
    pub name: Option<String>,
    /// Inner-ring speed to write as [operating] (with --radial-load).
    #[arg(long, requires = "radial_load")]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Radial load to write as [operating] (with --speed).
    #[arg(long, requires = "speed")]
    pub radial_load: Option<Quantity<Force>>,
    /// Oil temperature to write as [operating] (with --speed and --radial-load).
    #[arg(long, allow_hyphen_values = true, requires = "speed")]
    pub oil_temperature: Option<Quantity<Temperature>>,
    /// Write the model to FILE (else print it).
    #[arg(long, short = 'o')]
    pub out: Option<PathBuf>,
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = NewModelRequest {
        designation: args.designation,
        bore: args.bore,
        outside: args.outside,
        width: args.width,
        ribs: args.ribs,
        roller_diameter: args.roller_diameter,
        roller_length: args.roller_length,
        rollers: args.rollers,
        cage: args.cage,
        clearance_group: args.clearance_group,
        oil: args.oil,
        name: args.name,
        speed: args.speed,
        radial_load: args.radial_load,
        oil_temperature: args.oil_temperature,
        out: args.out,
    };
    run_and_print::<NewModel>(&request, None, args.json)
}
