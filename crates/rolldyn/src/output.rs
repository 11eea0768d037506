//! Writing results to files: output folders, CSV tables, files replaced in place.

use crate::failure::Failure;
use rolldyn_output::{ColumnKind, FolderLock, FolderLockError, ReplaceError};
use std::path::{Path, PathBuf};

/// Creates the output folder `--out` (and parents) and locks it for this run until the
/// returned lock (which derefs to the folder) is dropped; a folder another run writes is
/// refused as bad input.
pub fn out_dir(dir: &Path) -> Result<FolderLock, Failure> {
    FolderLock::acquire(dir).map_err(lock_failure)
}

/// [`out_dir`] for a run that shares its folder with others writing other files of it (the
/// shards of a sweep that do not collect).
pub fn shared_out_dir(dir: &Path) -> Result<FolderLock, Failure> {
    FolderLock::acquire_shared(dir).map_err(lock_failure)
}

fn lock_failure(e: FolderLockError) -> Failure {
    match e {
        FolderLockError::Busy { .. } => Failure::Input(format!("--out {e}")),
        FolderLockError::Io { .. } => Failure::Run(e.to_string()),
    }
}

/// Creates a folder inside a locked output folder, or a cache shared between runs, and returns
/// it.
pub fn sub_dir(dir: &Path) -> Result<PathBuf, Failure> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Failure::Run(format!("cannot create folder {}: {e}", dir.display())))?;
    Ok(dir.to_path_buf())
}

/// A refusal of [`rolldyn_output::replace_file_atomically`] as a failure: a target that is not
/// a regular file is bad input of the option `flag` that named it.
pub fn replace_failure(flag: &str, e: ReplaceError) -> Failure {
    match e {
        ReplaceError::NotRegularFile { .. } => Failure::Input(format!("{flag}: {e}")),
        ReplaceError::Io { .. } => Failure::Run(e.to_string()),
    }
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
