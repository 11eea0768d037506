//! Tables written as CSV and Parquet read back with the same values.

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::RowAccessor;
use rolldyn_output::{Formats, TableWriter};

#[test]
fn csv_and_parquet_round_trip_across_row_groups() {
    let dir = std::env::temp_dir().join(format!("rolldyn-output-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let names = vec!["time_s".to_string(), "cage speed (rad/s)".to_string()];
    let mut w = TableWriter::create(&dir, "series", &names, Formats::default()).unwrap();
    assert_eq!(w.names()[1], "cage_speed__rad_s_");
    for k in 0..10_000 {
        w.write_row(&[k as f64 * 1e-5, 300.0 + k as f64]).unwrap();
    }
    assert!(w.write_row(&[1.0]).is_err());
    w.finish().unwrap();
    let csv = std::fs::read_to_string(dir.join("series.csv")).unwrap();
    assert_eq!(csv.lines().count(), 10_001);
    let reader =
        SerializedFileReader::new(std::fs::File::open(dir.join("series.parquet")).unwrap())
            .unwrap();
    let meta = reader.metadata();
    assert_eq!(meta.file_metadata().num_rows(), 10_000);
    assert_eq!(meta.num_row_groups(), 3);
    let last = reader.get_row_iter(None).unwrap().last().unwrap().unwrap();
    assert_eq!(last.get_double(1).unwrap(), 300.0 + 9_999.0);
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn dropped_writer_leaves_a_readable_file() {
    let dir = std::env::temp_dir().join(format!("rolldyn-output-drop-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    {
        let mut w =
            TableWriter::create(&dir, "partial", &["a".to_string()], Formats::default()).unwrap();
        w.write_row(&[1.0]).unwrap();
    }
    let reader =
        SerializedFileReader::new(std::fs::File::open(dir.join("partial.parquet")).unwrap())
            .unwrap();
    assert_eq!(reader.metadata().file_metadata().num_rows(), 1);
    std::fs::remove_dir_all(dir).ok();
}

/// docs/outputs.md: a value that is not finite is an empty CSV field and a Parquet null.
#[test]
fn non_finite_values_are_empty_csv_fields_and_parquet_nulls() {
    let dir = std::env::temp_dir().join(format!("rolldyn-output-nan-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let names = vec!["a".to_string(), "b".to_string()];
    let mut w = TableWriter::create(&dir, "gaps", &names, Formats::default()).unwrap();
    w.write_row(&[1.0, f64::NAN]).unwrap();
    w.write_row(&[f64::INFINITY, 2.0]).unwrap();
    w.finish().unwrap();
    let csv = std::fs::read_to_string(dir.join("gaps.csv")).unwrap();
    assert_eq!(csv.lines().collect::<Vec<_>>(), ["a,b", "1e0,", ",2e0"]);
    let reader =
        SerializedFileReader::new(std::fs::File::open(dir.join("gaps.parquet")).unwrap()).unwrap();
    let rows: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(|r| r.unwrap())
        .collect();
    assert_eq!(rows[0].get_double(0).unwrap(), 1.0);
    assert!(rows[0].get_double(1).is_err());
    assert!(rows[1].get_double(0).is_err());
    assert_eq!(rows[1].get_double(1).unwrap(), 2.0);
    std::fs::remove_dir_all(dir).ok();
}
