//! `rolldyn`: the command-line front end. It parses arguments, calls the library crates and
//! formats their results; it owns no physics.

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod commands;
mod failure;
mod output;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Roller-bearing dynamics, contact and lubrication simulator.
#[derive(Parser)]
#[command(name = "rolldyn", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run the most complete analysis available on the embedded default model (bearing 2002834).
    Demo(commands::demo::Args),
    /// Validate a model file and print its derived quantities.
    Check(commands::check::Args),
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
}

fn main() -> ExitCode {
    // Rust ignores SIGPIPE, so printing into a closed pipe (`rolldyn … | head`) would panic;
    // restore the default action: the process ends quietly when the reader goes away.
    #[cfg(unix)]
    // SAFETY: called once at start-up, before any thread exists; SIG_DFL is a valid handler.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    if let Some(missing) = missing_cpu_features() {
        eprintln!(
            "error: this rolldyn was built for x86-64-v3 but the CPU lacks {missing}; rebuild \
             with RUSTFLAGS=\"-C target-cpu=x86-64\" cargo build --release (see .cargo/config.toml)"
        );
        return ExitCode::FAILURE;
    }
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Demo(args) => commands::demo::run(args),
        Command::Check(args) => commands::check::run(args),
        Command::Contact(args) => commands::contact::run(args),
        Command::Study(args) => commands::study::run(args),
        Command::Sweep(args) => commands::sweep::run(args),
        Command::Bench(args) => commands::bench::run(args),
        Command::Startup(args) => commands::startup::run(args),
        Command::Wear(args) => commands::wear::run(args),
        Command::Fatigue(args) => commands::fatigue::run(args),
        Command::Loads(args) => commands::loads::run(args),
        Command::Simulate(args) => commands::simulate::run(args),
        Command::Skid(args) => commands::skid::run(args),
        Command::Oils(args) => commands::oils::run(args),
        Command::Traction(args) => commands::traction::run(args),
        Command::Film(args) => commands::film::run(args),
        Command::Journal(args) => commands::journal::run(args),
        Command::EhlLine(args) => commands::ehl_line::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            // one readable line even when the failure quotes a huge bad value
            eprintln!(
                "rolldyn: {}",
                rolldyn_model::shorten_long_words(&failure.to_string())
            );
            ExitCode::from(failure.exit_code())
        }
    }
}

/// The instruction-set extensions this binary was compiled to assume (`.cargo/config.toml`)
/// that the CPU does not have, so that an old CPU gets a message instead of an illegal
/// instruction.
fn missing_cpu_features() -> Option<&'static str> {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return Some("AVX2");
        }
        if !std::arch::is_x86_feature_detected!("fma") {
            return Some("FMA");
        }
    }
    None
}
