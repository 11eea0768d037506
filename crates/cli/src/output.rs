//! Writing results: JSON on stdout, CSV files, output folders.

use crate::failure::Failure;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Prints `value` as pretty JSON on stdout; a closed pipe (`| head`) is not an error. Under
/// [`crate::api`] the value is handed to the caller instead.
pub fn print_json<T: Serialize>(value: &T) -> Result<(), Failure> {
    use std::io::Write;
    if crate::api::capturing() {
        let value = serde_json::to_value(value).map_err(|e| Failure::Run(e.to_string()))?;
        crate::api::capture(value);
        return Ok(());
    }
    let text = serde_json::to_string_pretty(value).map_err(|e| Failure::Run(e.to_string()))?;
    match writeln!(std::io::stdout().lock(), "{text}") {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e.into()),
        _ => Ok(()),
    }
}

/// Creates the output folder (and parents) and returns it.
pub fn out_dir(dir: &Path) -> Result<PathBuf, Failure> {
    std::fs::create_dir_all(dir).map_err(|e| {
        Failure::Run(format!(
            "cannot create output folder {}: {e}",
            dir.display()
        ))
    })?;
    Ok(dir.to_path_buf())
}

/// Writes a CSV file with a header row and numeric rows.
pub fn write_csv(
    path: &Path,
    header: &[&str],
    rows: impl Iterator<Item = Vec<f64>>,
) -> Result<(), Failure> {
    let fail = |e: csv::Error| Failure::Run(format!("cannot write {}: {e}", path.display()));
    let mut writer = csv::Writer::from_path(path).map_err(fail)?;
    writer.write_record(header).map_err(fail)?;
    for row in rows {
        writer
            .write_record(row.iter().map(|&v| rolldyn_output::csv_field(v)))
            .map_err(fail)?;
    }
    writer.flush()?;
    Ok(())
}

/// Loads a model file, or the embedded default model when `path` is `None`; under
/// [`crate::api`] with a model given, that model.
pub fn load_model(path: Option<&Path>) -> Result<rolldyn_model::Model, Failure> {
    if let Some(model) = crate::api::given_model() {
        return Ok(model);
    }
    Ok(match path {
        Some(path) => rolldyn_model::load(path)?,
        None => rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "<embedded 2002834.toml>")?,
    })
}
