//! `rolldyn`: the command-line front end. It parses arguments, calls the library crates and
//! formats their results; it owns no physics.

use clap::Parser;
use rolldyn_cli::{Cli, execute};
use std::process::ExitCode;

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
    let result = execute(cli.command);
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
