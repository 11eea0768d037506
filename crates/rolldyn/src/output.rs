//! Writing results to files: output folders, CSV tables.

use crate::failure::Failure;
use rolldyn_output::ColumnKind;
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

/// Writes a CSV file with a header row and numeric rows (the whole-number columns,
/// [`rolldyn_output::WHOLE_NUMBER_COLUMNS`], as integers).
pub fn write_csv(
    path: &Path,
    header: &[&str],
    rows: impl Iterator<Item = Vec<f64>>,
) -> Result<(), Failure> {
    let fail = |e: csv::Error| Failure::Run(format!("cannot write {}: {e}", path.display()));
    let mut writer = csv::Writer::from_path(path).map_err(fail)?;
    writer.write_record(header).map_err(fail)?;
    let kinds: Vec<ColumnKind> = header.iter().map(|n| ColumnKind::of_column(n)).collect();
    for row in rows {
        writer
            .write_record(row.iter().zip(&kinds).map(|(&v, kind)| kind.csv_field(v)))
            .map_err(fail)?;
    }
    writer.flush()?;
    Ok(())
}

/// Writes a result's table as CSV (numbers as [`write_csv`] writes them, text as it is).
pub fn write_table_csv(path: &Path, table: &crate::table::Table) -> Result<(), Failure> {
    use crate::table::ColumnValues;
    let fail = |e: csv::Error| Failure::Run(format!("cannot write {}: {e}", path.display()));
    let mut writer = csv::Writer::from_path(path).map_err(fail)?;
    writer
        .write_record(table.columns.iter().map(|c| c.name.as_str()))
        .map_err(fail)?;
    for row in 0..table.rows() {
        writer
            .write_record(table.columns.iter().map(|c| match &c.values {
                ColumnValues::Real(v) => ColumnKind::Real.csv_field(v[row]),
                ColumnValues::Integer(v) => v[row].to_string(),
                ColumnValues::Text(v) => v[row].clone(),
            }))
            .map_err(fail)?;
    }
    writer.flush()?;
    Ok(())
}
