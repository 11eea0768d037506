//! `rolldyn`: the command-line front end. It parses arguments, calls the library crates and
//! formats their results; it owns no physics.

use clap::Parser;
use rolldyn_cli::output::{is_closed_pipe, print_error_line, write_failure};
use rolldyn_cli::{Cli, execute};
use std::process::ExitCode;

/// Every line goes through [`rolldyn_cli::output`]: a reader that went away (`rolldyn … |
/// head`, SIGPIPE ignored as Rust does) ends the output quietly with the run's own exit code;
/// a stdout that cannot be written (a full disk) is a failed run (exit 1, one line on stderr);
/// a stderr that cannot be written loses its lines, never the exit code.
fn main() -> ExitCode {
    if let Some(missing) = missing_cpu_features() {
        print_error_line(&format!(
            "error: this rolldyn was built for x86-64-v3 but the CPU lacks {missing}; rebuild \
             with RUSTFLAGS=\"-C target-cpu=x86-64\" cargo build --release (see .cargo/config.toml)"
        ));
        return ExitCode::FAILURE;
    }
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(usage) => return print_usage(&usage),
    };
    match execute(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            // one readable line even when the failure quotes a huge bad value
            print_error_line(&format!(
                "rolldyn: {}",
                rolldyn_model::shorten_long_words(&failure.to_string())
            ));
            ExitCode::from(failure.exit_code())
        }
    }
}

/// Prints clap's answer (help and version on stdout, a usage error on stderr) and returns its
/// exit code; help that cannot be written is a failed run.
fn print_usage(usage: &clap::Error) -> ExitCode {
    let code = ExitCode::from(u8::try_from(usage.exit_code()).unwrap_or(2));
    match usage.print() {
        Err(e) if !usage.use_stderr() && !is_closed_pipe(&e) => {
            print_error_line(&format!("rolldyn: {}", write_failure(&e)));
            ExitCode::FAILURE
        }
        _ => code,
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
