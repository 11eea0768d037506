//! Helpers shared by the end-to-end tests: run the binary, find examples, read JSON.

use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs `rolldyn` with `args` from the crate folder.
pub fn rolldyn(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("rolldyn runs")
}

/// Path of an example file.
pub fn example(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
        .display()
        .to_string()
}

/// The JSON printed by a successful run.
pub fn json(output: &Output) -> serde_json::Value {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("stdout is JSON")
}
