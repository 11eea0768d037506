//! A small table of text and number columns written to Parquet in one go (e.g. a sweep summary:
//! variant names, figures, error messages). Column names are sanitised and checked for
//! collisions like those of [`TableWriter`](crate::TableWriter); numbers that are not finite and
//! missing texts are nulls (docs/outputs.md).

use crate::{OutputError, column_name, column_names, fail};
use parquet::basic::Compression;
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::parser::parse_message_type;
use std::fs::File;
use std::path::Path;
use std::sync::Arc;

/// The values of one column, one per row.
pub enum Values<'a> {
    /// UTF-8 strings; `None` is a null.
    Text(&'a [Option<String>]),
    /// Doubles; a value that is not finite is a null.
    Numbers(&'a [f64]),
    /// Whole numbers (an index, a count; Parquet INT64); `None` is a null.
    Integers(&'a [Option<i64>]),
}

/// A named column of a [`write_parquet_table`].
pub struct Column<'a> {
    pub name: &'a str,
    pub values: Values<'a>,
}

/// Writes `columns` (all of the same length) as one row group to the Parquet file `path`.
pub fn write_parquet_table(path: &Path, columns: &[Column<'_>]) -> Result<(), OutputError> {
    let given: Vec<String> = columns.iter().map(|c| c.name.to_string()).collect();
    let names = column_names(&given).map_err(|e| fail(path, e))?;
    let fields: String = columns
        .iter()
        .zip(&names)
        .map(|(c, name)| match c.values {
            Values::Text(_) => format!("OPTIONAL BYTE_ARRAY {name} (UTF8); "),
            Values::Numbers(_) => format!("OPTIONAL DOUBLE {name}; "),
            Values::Integers(_) => format!("OPTIONAL INT64 {name}; "),
        })
        .collect();
    let stem = path.file_stem().map(|s| s.to_string_lossy().to_string());
    let message = column_name(stem.as_deref().unwrap_or("table"));
    let schema = parse_message_type(&format!("message {message} {{ {fields}}}"))
        .map_err(|e| fail(path, e))?;
    let props = WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .build();
    let file = File::create(path).map_err(|e| fail(path, e))?;
    let mut writer = SerializedFileWriter::new(file, Arc::new(schema), Arc::new(props))
        .map_err(|e| fail(path, e))?;
    let mut group = writer.next_row_group().map_err(|e| fail(path, e))?;
    for column in columns {
        let mut sink = group
            .next_column()
            .map_err(|e| fail(path, e))?
            .ok_or_else(|| fail(path, "fewer columns in the file than given"))?;
        match column.values {
            Values::Text(texts) => {
                let present: Vec<ByteArray> = texts
                    .iter()
                    .flatten()
                    .map(|t| ByteArray::from(t.as_str()))
                    .collect();
                let levels: Vec<i16> = texts.iter().map(|t| i16::from(t.is_some())).collect();
                sink.typed::<ByteArrayType>()
                    .write_batch(&present, Some(&levels), None)
            }
            Values::Numbers(numbers) => {
                let present: Vec<f64> = numbers.iter().copied().filter(|v| v.is_finite()).collect();
                let levels: Vec<i16> = numbers.iter().map(|v| i16::from(v.is_finite())).collect();
                sink.typed::<DoubleType>()
                    .write_batch(&present, Some(&levels), None)
            }
            Values::Integers(numbers) => {
                let present: Vec<i64> = numbers.iter().flatten().copied().collect();
                let levels: Vec<i16> = numbers.iter().map(|v| i16::from(v.is_some())).collect();
                sink.typed::<Int64Type>()
                    .write_batch(&present, Some(&levels), None)
            }
        }
        .map_err(|e| fail(path, e))?;
        sink.close().map_err(|e| fail(path, e))?;
    }
    group.close().map_err(|e| fail(path, e))?;
    writer.close().map_err(|e| fail(path, e))?;
    Ok(())
}
