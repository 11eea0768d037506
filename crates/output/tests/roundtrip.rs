//! Tables written as CSV and Parquet read back with the same values.

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::RowAccessor;
use rolldyn_output::{Formats, KeptRows, TableWriter};

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

fn row(k: usize) -> [f64; 2] {
    [
        k as f64 * 1e-5,
        if k.is_multiple_of(3) {
            f64::NAN
        } else {
            0.1 * k as f64
        },
    ]
}

/// A table whose writer was killed (rows flushed, then a partial line, no Parquet footer) is
/// resumed after its first rows: the CSV is cut there, the Parquet rebuilt from it, and the
/// files end equal to those of an uninterrupted writer.
#[test]
fn resumed_table_equals_an_uninterrupted_one() {
    let dir = std::env::temp_dir().join(format!("rolldyn-output-resume-{}", std::process::id()));
    let (whole, killed) = (dir.join("whole"), dir.join("killed"));
    std::fs::create_dir_all(&whole).unwrap();
    std::fs::create_dir_all(&killed).unwrap();
    let names = vec!["t".to_string(), "x".to_string()];
    let rows = 5000;
    let mut w = TableWriter::create(&whole, "series", &names, Formats::default()).unwrap();
    for k in 0..rows {
        w.write_row(&row(k)).unwrap();
    }
    w.finish().unwrap();
    let mut w = TableWriter::create(&killed, "series", &names, Formats::default()).unwrap();
    let mut checkpoint = w.kept();
    for k in 0..4300 {
        w.write_row(&row(k)).unwrap();
        if k == 4099 {
            checkpoint = w.kept();
        }
    }
    w.flush().unwrap();
    std::mem::forget(w);
    let csv = killed.join("series.csv");
    let mut partial = std::fs::read(&csv).unwrap();
    partial.extend_from_slice(b"4.3e-2,4");
    std::fs::write(&csv, partial).unwrap();
    let mut replayed = Vec::new();
    let mut resume = |keep| {
        replayed.clear();
        TableWriter::resume(&killed, "series", &names, Formats::default(), keep, |r| {
            replayed.push(r[0])
        })
    };
    let killed_files = |f: &str| std::fs::read(killed.join(f)).unwrap();
    let before = (killed_files("series.csv"), killed_files("series.parquet"));
    let short = resume(KeptRows {
        rows: 4301,
        ..checkpoint
    })
    .err()
    .expect("more rows than the CSV holds");
    assert!(
        short.reason.contains("4300 complete rows"),
        "{}",
        short.reason
    );
    let other_names = vec!["t".to_string(), "y".to_string()];
    let other = TableWriter::resume(
        &killed,
        "series",
        &other_names,
        Formats::default(),
        checkpoint,
        |_| {},
    );
    assert!(
        other
            .err()
            .expect("another header")
            .reason
            .contains("header")
    );
    let foreign = resume(KeptRows {
        digest: checkpoint.digest ^ 1,
        ..checkpoint
    });
    assert!(foreign.err().expect("other rows").reason.contains("differ"));
    let after = (killed_files("series.csv"), killed_files("series.parquet"));
    assert!(before == after, "a refused resume changed the files");
    let mut w = resume(checkpoint).unwrap();
    assert_eq!(w.kept(), checkpoint);
    assert!((0..4100).map(|k| row(k)[0]).eq(replayed.iter().copied()));
    for k in 4100..rows {
        w.write_row(&row(k)).unwrap();
    }
    w.finish().unwrap();
    for file in ["series.csv", "series.parquet"] {
        let a = std::fs::read(whole.join(file)).unwrap();
        assert!(a == std::fs::read(killed.join(file)).unwrap(), "{file}");
    }
    std::fs::remove_dir_all(dir).ok();
}

/// An index or a count is written as an integer (`3`, Parquet INT64), not `3e0`, and a table
/// with such columns resumes like any other.
#[test]
fn integer_columns_are_written_as_integers() {
    use rolldyn_output::ColumnKind;
    let dir = std::env::temp_dir().join(format!("rolldyn-output-int-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let names = vec!["roller".to_string(), "force_n".to_string()];
    let kinds = [ColumnKind::Integer, ColumnKind::Real];
    let mut w =
        TableWriter::create_typed(&dir, "ints", &names, &kinds, Formats::default()).unwrap();
    w.write_row(&[1.0, 2.5]).unwrap();
    w.write_row(&[2.0, f64::NAN]).unwrap();
    w.write_row(&[f64::NAN, 3.0]).unwrap();
    let kept = w.kept();
    w.write_row(&[4.0, 4.0]).unwrap();
    w.finish().unwrap();
    let csv = std::fs::read_to_string(dir.join("ints.csv")).unwrap();
    assert_eq!(
        csv.lines().collect::<Vec<_>>(),
        ["roller,force_n", "1,2.5e0", "2,", ",3e0", "4,4e0"]
    );
    let reader =
        SerializedFileReader::new(std::fs::File::open(dir.join("ints.parquet")).unwrap()).unwrap();
    let first = reader.get_row_iter(None).unwrap().next().unwrap().unwrap();
    assert_eq!(first.get_long(0).unwrap(), 1);
    let mut resumed = TableWriter::resume_typed(
        &dir,
        "ints",
        &names,
        &kinds,
        Formats::default(),
        kept,
        |_| {},
    )
    .unwrap();
    resumed.write_row(&[5.0, 5.0]).unwrap();
    resumed.finish().unwrap();
    let csv = std::fs::read_to_string(dir.join("ints.csv")).unwrap();
    assert_eq!(csv.lines().last(), Some("5,5e0"));
    std::fs::remove_dir_all(dir).ok();
}
