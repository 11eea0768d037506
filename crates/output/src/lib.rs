//! Streaming tables of `f64` columns written as CSV and/or Parquet; a column of whole numbers
//! (an index, a count, a flag) is declared [`ColumnKind::Integer`] and written as integers
//! (`3`, Parquet INT64), not `3e0`.
//!
//! A [`TableWriter`] receives one row at a time and never holds more than one Parquet row group
//! (default 4096 rows) in memory, so a long simulation streams to disk. Rows written before a
//! failure stay readable: call [`TableWriter::finish`] on the error path too (it writes the
//! Parquet footer); dropping an unfinished writer also finishes it, best effort. A process that
//! is killed leaves a Parquet file without footer, but its CSV file holds every row up to the
//! last [`TableWriter::flush`]: [`TableWriter::resume`] continues the table from there and
//! rebuilds the Parquet file. A value that is not finite is written as an empty CSV field and a
//! Parquet null ([`non_finite`]).
//!
//! The rules of every file rolldyn writes live here too: one writer per output folder
//! ([`FolderLock`]), files replaced only when regular and never half-written
//! ([`replace_file_atomically`]), and checksums of what is read back ([`checksum`]).

pub mod checksum;
pub mod folder_lock;
pub mod mixed_table;
pub mod non_finite;
pub mod replace;
pub mod run_state;
pub mod size;

pub use checksum::{ChecksumError, checksum_hex, seal_json, verify_sealed_json};
pub use folder_lock::{FolderLock, FolderLockError, LOCK_FILE};
pub use mixed_table::{Column, Values, write_parquet_table};
pub use non_finite::{csv_field, csv_integer, default_reason, mark_non_finite};
pub use replace::{ReplaceError, ensure_replaceable, replace_file_atomically};
pub use run_state::{StateError, StateFile};
pub use size::{ByteSize, estimated_table_bytes};

use parquet::basic::Compression;
use parquet::data_type::{DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::parser::parse_message_type;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Writing a table failed.
#[derive(Debug, Clone, thiserror::Error)]
#[error("cannot write {path}: {reason}")]
pub struct OutputError {
    pub path: String,
    pub reason: String,
}

fn fail(path: &Path, e: impl std::fmt::Display) -> OutputError {
    OutputError {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

/// Which files a [`TableWriter`] produces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Formats {
    pub csv: bool,
    pub parquet: bool,
}

impl Default for Formats {
    fn default() -> Self {
        Self {
            csv: true,
            parquet: true,
        }
    }
}

/// What a column holds: real numbers, or whole numbers (rounded when written).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColumnKind {
    #[default]
    Real,
    Integer,
}

/// The columns that count or index (rows, rollers, revolutions, load sets, variants): whole
/// numbers wherever a table has them.
pub const WHOLE_NUMBER_COLUMNS: [&str; 7] = [
    "row",
    "roller",
    "revolution",
    "precession",
    "steady",
    "set",
    "index",
];

impl ColumnKind {
    /// The kind of a column by its name: [`WHOLE_NUMBER_COLUMNS`] are integers, the rest real.
    pub fn of_column(name: &str) -> Self {
        match WHOLE_NUMBER_COLUMNS.contains(&name) {
            true => Self::Integer,
            false => Self::Real,
        }
    }

    /// The kinds of `names`, by [`ColumnKind::of_column`].
    pub fn of_columns(names: &[String]) -> Vec<Self> {
        names.iter().map(|n| Self::of_column(n)).collect()
    }

    /// The CSV field of `value` in a column of this kind (empty when it is not finite).
    pub fn csv_field(self, value: f64) -> String {
        match self {
            Self::Real => csv_field(value),
            Self::Integer => csv_integer(value),
        }
    }

    /// `value` as this kind stores it (whole numbers rounded).
    fn stored(self, value: f64) -> f64 {
        match self {
            Self::Real => value,
            Self::Integer => value.round(),
        }
    }
}

struct ParquetSink {
    path: PathBuf,
    writer: SerializedFileWriter<File>,
    /// Column-major buffer of the current row group: the finite values of each column and the
    /// definition level of each row (1 value, 0 null).
    columns: Vec<(Vec<f64>, Vec<i16>)>,
    kinds: Vec<ColumnKind>,
}

impl ParquetSink {
    fn flush(&mut self) -> Result<(), OutputError> {
        if self.columns.first().is_none_or(|c| c.1.is_empty()) {
            return Ok(());
        }
        let path = self.path.clone();
        let mut group = self.writer.next_row_group().map_err(|e| fail(&path, e))?;
        let mut k = 0;
        while let Some(mut column) = group.next_column().map_err(|e| fail(&path, e))? {
            let (values, levels) = &mut self.columns[k];
            match self.kinds[k] {
                ColumnKind::Real => {
                    column
                        .typed::<DoubleType>()
                        .write_batch(values, Some(levels), None)
                }
                ColumnKind::Integer => {
                    let whole: Vec<i64> = values.iter().map(|v| v.round() as i64).collect();
                    column
                        .typed::<Int64Type>()
                        .write_batch(&whole, Some(levels), None)
                }
            }
            .map_err(|e| fail(&path, e))?;
            column.close().map_err(|e| fail(&path, e))?;
            values.clear();
            levels.clear();
            k += 1;
        }
        group.close().map_err(|e| fail(&path, e))?;
        Ok(())
    }
}

/// A table of named `f64` columns streamed to `<stem>.csv` and/or `<stem>.parquet`.
pub struct TableWriter {
    names: Vec<String>,
    kinds: Vec<ColumnKind>,
    csv: Option<(PathBuf, csv::Writer<File>)>,
    parquet: Option<ParquetSink>,
    row_group_rows: usize,
    rows: usize,
    digest: RowDigest,
    finished: bool,
}

/// A digest of the rows of a table as they read back from its CSV file (a value that is not
/// finite counts as NaN), so that a resumed table can be recognised. Deterministic within a
/// rolldyn version (SipHash with fixed keys).
#[derive(Clone, Default)]
struct RowDigest(std::collections::hash_map::DefaultHasher);

impl RowDigest {
    fn add(&mut self, row: &[f64]) {
        use std::hash::Hasher;
        for &v in row {
            let v = if v.is_finite() { v } else { f64::NAN };
            self.0.write_u64(v.to_bits());
        }
    }
    fn value(&self) -> u64 {
        use std::hash::Hasher;
        self.0.finish()
    }
}

/// The rows of an interrupted table that a resume keeps: how many, and the
/// digest of the table after them ([`TableWriter::kept`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct KeptRows {
    pub rows: usize,
    pub digest: u64,
}

/// A Parquet-safe column name: letters, digits and `_` only.
fn column_name(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, 'c');
    }
    out
}

/// The Parquet-safe names of `names`, in order; two names that become the same are refused,
/// naming both.
fn column_names(names: &[String]) -> Result<Vec<String>, String> {
    let safe: Vec<String> = names.iter().map(|n| column_name(n)).collect();
    for (i, name) in safe.iter().enumerate() {
        if let Some(j) = safe[..i].iter().position(|earlier| earlier == name) {
            return Err(format!(
                "the columns '{}' and '{}' both become '{name}' in the table",
                names[j], names[i]
            ));
        }
    }
    Ok(safe)
}

impl TableWriter {
    /// Creates `<dir>/<stem>.csv` and/or `<dir>/<stem>.parquet` with the given column names
    /// (sanitised for Parquet; names that collide once sanitised are refused); the
    /// [`WHOLE_NUMBER_COLUMNS`] among them hold integers.
    pub fn create(
        dir: &Path,
        stem: &str,
        names: &[String],
        formats: Formats,
    ) -> Result<Self, OutputError> {
        Self::create_typed(dir, stem, names, &ColumnKind::of_columns(names), formats)
    }

    /// [`TableWriter::create`] with the kind of each column (`kinds[k]` for `names[k]`;
    /// columns past the end of `kinds` are real).
    pub fn create_typed(
        dir: &Path,
        stem: &str,
        names: &[String],
        kinds: &[ColumnKind],
        formats: Formats,
    ) -> Result<Self, OutputError> {
        let mut table = Self::without_csv(dir, stem, names, kinds, formats)?;
        if formats.csv {
            let path = dir.join(format!("{stem}.csv"));
            let mut writer = csv::Writer::from_path(&path).map_err(|e| fail(&path, e))?;
            writer
                .write_record(&table.names)
                .map_err(|e| fail(&path, e))?;
            table.csv = Some((path, writer));
        }
        Ok(table)
    }

    /// Continues the table of an interrupted run in `dir` after its first `kept.rows` rows:
    /// the CSV (the record of the run, which must hold them under the same header and with the
    /// same digest) is cut after them — dropping later rows and a partial last line — and the
    /// Parquet file is rebuilt from them; `on_row` sees each kept row (to rebuild what the
    /// caller derives from the rows). Writing then goes on as if the run had never stopped.
    /// Nothing is changed when the CSV file does not fit. With no rows kept the table starts
    /// anew. Column kinds as [`TableWriter::create`].
    pub fn resume(
        dir: &Path,
        stem: &str,
        names: &[String],
        formats: Formats,
        kept: KeptRows,
        on_row: impl FnMut(&[f64]),
    ) -> Result<Self, OutputError> {
        Self::resume_typed(
            dir,
            stem,
            names,
            &ColumnKind::of_columns(names),
            formats,
            kept,
            on_row,
        )
    }

    /// [`TableWriter::resume`] with the kind of each column (as [`TableWriter::create_typed`]).
    pub fn resume_typed(
        dir: &Path,
        stem: &str,
        names: &[String],
        kinds: &[ColumnKind],
        formats: Formats,
        kept: KeptRows,
        mut on_row: impl FnMut(&[f64]),
    ) -> Result<Self, OutputError> {
        let keep_rows = kept.rows;
        if keep_rows == 0 {
            return Self::create_typed(dir, stem, names, kinds, formats);
        }
        let path = dir.join(format!("{stem}.csv"));
        if !formats.csv {
            return Err(fail(&path, "a table is resumed from its CSV file"));
        }
        let names: Vec<String> = names.iter().map(|n| column_name(n)).collect();
        // the first pass checks the CSV file, so that nothing is changed when it does not fit
        let mut digest = RowDigest::default();
        let end = read_rows(&path, &names, keep_rows, |row| {
            digest.add(row);
            Ok(())
        })?;
        if digest.value() != kept.digest {
            return Err(fail(
                &path,
                "its rows differ from those of the interrupted run (the folder of another run?)",
            ));
        }
        let mut table = Self::without_csv(dir, stem, &names, kinds, formats)?;
        read_rows(&path, &names, keep_rows, |row| {
            table.push_parquet(row)?;
            on_row(row);
            Ok(())
        })?;
        table.rows = keep_rows;
        table.digest = digest;
        let file = std::fs::OpenOptions::new()
            .append(true)
            .open(&path)
            .map_err(|e| fail(&path, e))?;
        file.set_len(end).map_err(|e| fail(&path, e))?;
        table.csv = Some((path, csv::Writer::from_writer(file)));
        Ok(table)
    }

    /// The table with its Parquet file (when asked for) and no CSV file yet.
    fn without_csv(
        dir: &Path,
        stem: &str,
        names: &[String],
        kinds: &[ColumnKind],
        formats: Formats,
    ) -> Result<Self, OutputError> {
        let names = column_names(names).map_err(|e| fail(&dir.join(stem), e))?;
        let kinds: Vec<ColumnKind> = (0..names.len())
            .map(|k| kinds.get(k).copied().unwrap_or_default())
            .collect();
        let parquet = if formats.parquet {
            let path = dir.join(format!("{stem}.parquet"));
            let fields: String = names
                .iter()
                .zip(&kinds)
                .map(|(n, kind)| match kind {
                    ColumnKind::Real => format!("OPTIONAL DOUBLE {n}; "),
                    ColumnKind::Integer => format!("OPTIONAL INT64 {n}; "),
                })
                .collect();
            let schema = parse_message_type(&format!(
                "message {stem_name} {{ {fields}}}",
                stem_name = column_name(stem)
            ))
            .map_err(|e| fail(&path, e))?;
            let props = WriterProperties::builder()
                .set_compression(Compression::SNAPPY)
                .build();
            let file = File::create(&path).map_err(|e| fail(&path, e))?;
            let writer = SerializedFileWriter::new(file, Arc::new(schema), Arc::new(props))
                .map_err(|e| fail(&path, e))?;
            Some(ParquetSink {
                path,
                writer,
                columns: vec![(Vec::new(), Vec::new()); names.len()],
                kinds: kinds.clone(),
            })
        } else {
            None
        };
        Ok(Self {
            names,
            kinds,
            csv: None,
            parquet,
            row_group_rows: 4096,
            rows: 0,
            digest: RowDigest::default(),
            finished: false,
        })
    }

    /// Column names as written (sanitised for Parquet).
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The kind of each column.
    pub fn kinds(&self) -> &[ColumnKind] {
        &self.kinds
    }

    /// Rows written so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Digest of the rows written so far (with [`TableWriter::rows`], what
    /// [`TableWriter::resume`] checks).
    pub fn kept(&self) -> KeptRows {
        KeptRows {
            rows: self.rows,
            digest: self.digest.value(),
        }
    }

    /// Appends one row; `values.len()` must equal the number of columns.
    pub fn write_row(&mut self, values: &[f64]) -> Result<(), OutputError> {
        if values.len() != self.names.len() {
            let path = self.csv.as_ref().map(|c| c.0.clone()).unwrap_or_default();
            return Err(fail(
                &path,
                format!(
                    "row of {} values for {} columns",
                    values.len(),
                    self.names.len()
                ),
            ));
        }
        let stored: Vec<f64>;
        let values = match self.kinds.contains(&ColumnKind::Integer) {
            true => {
                stored = values
                    .iter()
                    .zip(&self.kinds)
                    .map(|(&v, kind)| kind.stored(v))
                    .collect();
                &stored[..]
            }
            false => values,
        };
        if let Some((path, writer)) = &mut self.csv {
            writer
                .write_record(
                    values
                        .iter()
                        .zip(&self.kinds)
                        .map(|(&v, kind)| kind.csv_field(v)),
                )
                .map_err(|e| fail(path, e))?;
        }
        self.push_parquet(values)?;
        self.digest.add(values);
        self.rows += 1;
        Ok(())
    }

    /// Adds a row to the Parquet row group, written out when full.
    fn push_parquet(&mut self, values: &[f64]) -> Result<(), OutputError> {
        if let Some(sink) = &mut self.parquet {
            for ((column, levels), &v) in sink.columns.iter_mut().zip(values) {
                levels.push(i16::from(v.is_finite()));
                if v.is_finite() {
                    column.push(v);
                }
            }
            if sink.columns[0].1.len() >= self.row_group_rows {
                sink.flush()?;
            }
        }
        Ok(())
    }

    /// Hands the CSV rows written so far to the operating system, so that they survive the
    /// process (the Parquet file is complete only after [`TableWriter::finish`]).
    pub fn flush(&mut self) -> Result<(), OutputError> {
        if let Some((path, writer)) = &mut self.csv {
            writer.flush().map_err(|e| fail(path, e))?;
        }
        Ok(())
    }

    /// Flushes the last row group, writes the Parquet footer and closes the files.
    pub fn finish(mut self) -> Result<(), OutputError> {
        self.close()
    }

    fn close(&mut self) -> Result<(), OutputError> {
        if self.finished {
            return Ok(());
        }
        self.finished = true;
        if let Some((path, writer)) = &mut self.csv {
            writer.flush().map_err(|e| fail(path, e))?;
        }
        if let Some(mut sink) = self.parquet.take() {
            sink.flush()?;
            let path = sink.path.clone();
            sink.writer.close().map_err(|e| fail(&path, e))?;
        }
        Ok(())
    }
}

/// Reads the first `keep_rows` rows of the CSV file at `path`, which must have the header
/// `names`, into `on_row`; returns the byte offset where they end. Fails when the file holds
/// fewer complete rows (a last line cut short does not count).
fn read_rows(
    path: &Path,
    names: &[String],
    keep_rows: usize,
    mut on_row: impl FnMut(&[f64]) -> Result<(), OutputError>,
) -> Result<u64, OutputError> {
    let mut reader = csv::ReaderBuilder::new()
        .flexible(true)
        .from_path(path)
        .map_err(|e| {
            fail(
                path,
                format!("no table of the interrupted run to continue ({e})"),
            )
        })?;
    let header = reader.headers().map_err(|e| fail(path, e))?;
    if !header.iter().eq(names.iter()) {
        return Err(fail(path, "the header differs from this run's columns"));
    }
    let mut record = csv::StringRecord::new();
    let mut values = vec![0.0; names.len()];
    let (mut rows, mut end) = (0, reader.position().byte());
    while rows < keep_rows
        && reader.read_record(&mut record).map_err(|e| fail(path, e))?
        && record.len() == values.len()
    {
        for (value, field) in values.iter_mut().zip(&record) {
            *value = parse_field(field).ok_or_else(|| {
                fail(path, format!("row {}: '{field}' is not a number", rows + 1))
            })?;
        }
        rows += 1;
        end = reader.position().byte();
        if rows < keep_rows || ends_a_line(path, end)? {
            on_row(&values)?;
        } else {
            rows -= 1;
        }
    }
    if rows < keep_rows {
        return Err(fail(
            path,
            format!("{rows} complete rows where {keep_rows} are needed"),
        ));
    }
    Ok(end)
}

/// The value of a CSV field as written by [`csv_field`]: empty is not finite.
fn parse_field(field: &str) -> Option<f64> {
    if field.is_empty() {
        Some(f64::NAN)
    } else {
        field.parse().ok()
    }
}

/// Whether the byte before `offset` of the file at `path` ends a line (the last row of a file
/// cut by a kill does not).
fn ends_a_line(path: &Path, offset: u64) -> Result<bool, OutputError> {
    use std::io::{Read, Seek, SeekFrom};
    let Some(last) = offset.checked_sub(1) else {
        return Ok(false);
    };
    let mut file = File::open(path).map_err(|e| fail(path, e))?;
    let mut byte = [0u8];
    file.seek(SeekFrom::Start(last))
        .and_then(|_| file.read_exact(&mut byte))
        .map_err(|e| fail(path, e))?;
    Ok(byte[0] == b'\n')
}

impl Drop for TableWriter {
    fn drop(&mut self) {
        // Best effort: an error on this path has no one to report to; finish() reports it.
        let _ = self.close();
    }
}
