//! Writing results to files: output folders, CSV tables.

use crate::failure::Failure;
use std::path::{Path, PathBuf};

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
