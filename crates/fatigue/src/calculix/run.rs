//! Running gmsh and ccx in a scratch directory.

use super::{CalculixError, CalculixSettings};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A scratch directory, removed on drop unless the settings keep it.
pub struct WorkDir {
    pub path: PathBuf,
    keep: bool,
}

impl WorkDir {
    /// A fresh directory named after the process and the fingerprint of the model.
    pub fn create(fingerprint: u64, settings: &CalculixSettings) -> Result<WorkDir, CalculixError> {
        let path = std::env::temp_dir().join(format!(
            "rolldyn-calculix-{}-{fingerprint:016x}",
            std::process::id()
        ));
        std::fs::create_dir_all(&path).map_err(|e| CalculixError::Io(path.clone(), e))?;
        Ok(WorkDir {
            path,
            keep: settings.keep_work_dir,
        })
    }
}

impl Drop for WorkDir {
    fn drop(&mut self) {
        if !self.keep {
            let _ = std::fs::remove_dir_all(&self.path);
        }
    }
}

/// Meshes `cage.geo` in `dir` into `cage.inp`.
pub fn run_gmsh(dir: &Path, settings: &CalculixSettings) -> Result<(), CalculixError> {
    let mut command = Command::new(&settings.gmsh);
    command.current_dir(dir).args([
        "-3", "-nt", "1", "cage.geo", "-format", "inp", "-o", "cage.inp",
    ]);
    run(command, &settings.gmsh, |out| out.contains("Error   :"))
}

/// Solves `cage.inp`'s deck `deck.inp` in `dir` with ccx.
pub fn run_ccx(dir: &Path, settings: &CalculixSettings) -> Result<(), CalculixError> {
    let mut command = Command::new(&settings.ccx);
    command
        .current_dir(dir)
        .env("OMP_NUM_THREADS", settings.threads.to_string())
        .env("CCX_NPROC_EQUATION_SOLVER", settings.threads.to_string())
        .args(["-i", "deck"]);
    run(command, &settings.ccx, |out| out.contains("*ERROR"))
}

/// Runs `command`; a missing executable, a failed exit or `failed(output)` is an error that
/// quotes the last lines of the output.
fn run(
    mut command: Command,
    program: &str,
    failed: impl Fn(&str) -> bool,
) -> Result<(), CalculixError> {
    let output = command.output().map_err(|e| match e.kind() {
        std::io::ErrorKind::NotFound => CalculixError::Missing(program.to_string()),
        _ => CalculixError::Failed(program.to_string(), e.to_string()),
    })?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    if output.status.success() && !failed(&text) {
        return Ok(());
    }
    let lines: Vec<&str> = text.lines().collect();
    let tail = lines[lines.len().saturating_sub(15)..].join("\n");
    Err(CalculixError::Failed(program.to_string(), tail))
}
