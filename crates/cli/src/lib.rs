//! The `rolldyn` program's command line: each command parses its flags into a request of the
//! `rolldyn` library, runs it and prints the result (text, or JSON with `--json`). The analyses
//! and their orchestration live in the library; the Python package calls the same library.

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod commands;
pub use rolldyn::failure;
pub mod output;

use clap::{Parser, Subcommand};
use failure::Failure;

/// Roller-bearing dynamics, contact and lubrication simulator.
#[derive(Parser)]
#[command(name = "rolldyn", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Run the most complete analysis available on the embedded default model (bearing 2002834).
    Demo(commands::demo::Args),
    /// Validate a model file and print its derived quantities.
    Check(commands::check::Args),
    /// Write a cylindrical roller bearing model from an ISO designation (NU2215) or from its
    /// boundary dimensions, by cited design rules.
    New(commands::new::Args),
    /// Roller–raceway contact pressure: Boussinesq solver, slice model or Hertz.
    Contact(commands::contact::Args),
    /// Lubricant library: properties of every built-in oil at a temperature.
    Oils(commands::oils::Args),
    /// Traction curve, critical slip (scuffing criterion) and film of a lubricated contact.
    Traction(commands::traction::Args),
    /// Film thickness, film parameter Λ and lubrication regime of a contact.
    Film(commands::film::Args),
    /// Quasi-static roller and cage skidding; sweeps over speed or load.
    Skid(commands::skid::Args),
    /// Quasi-static load distribution of a double-row tapered bearing (radial, axial load,
    /// tilting moment or misalignment): roller, rib loads and load zones per row.
    Loads(commands::loads::Args),
    /// Rating life: ISO 281 C_r, L10, L_nm, ISO 76 s0, ISO/TS 16281 L10r from the slice loads;
    /// duty cycles by Palmgren–Miner.
    Life(commands::life::Args),
    /// Time-domain 6-DOF dynamics of a cylindrical roller bearing.
    Simulate(commands::simulate::Args),
    /// Run a table of model variants in parallel (any model key can vary).
    Sweep(commands::sweep::Args),
    /// Dynamics speed benchmark: simulated time / wall time on one thread, repeated runs.
    Bench(commands::bench::Args),
    /// Engine start-up: dynamics at the frozen time points of the model's schedules.
    Startup(commands::startup::Args),
    /// Wear of raceways, rollers, cage bars, roller ends and ribs over the bearing's life.
    Wear(commands::wear::Args),
    /// Cage high-cycle fatigue from one steady revolution of the dynamics (frame or CalculiX
    /// stresses, rainflow, S–N, Miner, inclusion); `fatigue rainflow` counts a stress history.
    Fatigue(commands::fatigue::Args),
    /// Re-run a seed's validation study and write its tables and plots.
    Study(commands::study::Args),
    /// Finite journal bearing by the Reynolds equation: load, attitude, friction, K and C.
    Journal(commands::journal::Args),
    /// Lubricated roller–plate line contact (rigid, piezoviscous or full EHL) and load steps.
    EhlLine(commands::ehl_line::Args),
    /// Self-contained HTML report (DIR/report.html) of an output folder of simulate, sweep,
    /// wear or fatigue.
    Report(commands::report::Args),
}

/// Runs one command.
pub fn execute(command: Command) -> Result<(), Failure> {
    match command {
        Command::Demo(args) => commands::demo::run(args),
        Command::Check(args) => commands::check::run(args),
        Command::New(args) => commands::new::run(args),
        Command::Contact(args) => commands::contact::run(args),
        Command::Study(args) => commands::study::run(args),
        Command::Sweep(args) => commands::sweep::run(args),
        Command::Bench(args) => commands::bench::run(args),
        Command::Startup(args) => commands::startup::run(args),
        Command::Wear(args) => commands::wear::run(args),
        Command::Fatigue(args) => commands::fatigue::run(args),
        Command::Loads(args) => commands::loads::run(args),
        Command::Life(args) => commands::life::run(args),
        Command::Simulate(args) => commands::simulate::run(args),
        Command::Skid(args) => commands::skid::run(args),
        Command::Oils(args) => commands::oils::run(args),
        Command::Traction(args) => commands::traction::run(args),
        Command::Film(args) => commands::film::run(args),
        Command::Journal(args) => commands::journal::run(args),
        Command::EhlLine(args) => commands::ehl_line::run(args),
        Command::Report(args) => commands::report::run(args),
    }
}
