//! Parquet column names: sanitised names that collide are refused; tables with text columns.

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::RowAccessor;
use rolldyn_output::{Column, Formats, OutputError, TableWriter, Values, write_parquet_table};

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-output-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}

#[test]
fn sanitised_names_that_collide_are_refused() {
    let dir = scratch("collide");
    for (a, b) in [("load.inner", "load_inner"), ("1st", "c1st"), ("x", "x")] {
        let err = TableWriter::create(&dir, "t", &names(&[a, "ok", b]), Formats::default())
            .err()
            .map(|e: OutputError| e.to_string())
            .unwrap_or_default();
        assert!(err.contains(a) && err.contains(b), "{a}, {b}: '{err}'");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn text_and_number_columns_round_trip() {
    let dir = scratch("text");
    let path = dir.join("summary.parquet");
    let labels = [Some("v0".to_string()), Some("v1".to_string())];
    let errors = [None, Some("no solution".to_string())];
    let columns = [
        Column {
            name: "variant",
            values: Values::Text(&labels),
        },
        Column {
            name: "cage slip",
            values: Values::Numbers(&[0.01, f64::NAN]),
        },
        Column {
            name: "error",
            values: Values::Text(&errors),
        },
    ];
    write_parquet_table(&path, &columns).unwrap();
    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    let header: Vec<String> = reader
        .metadata()
        .file_metadata()
        .schema_descr()
        .columns()
        .iter()
        .map(|c| c.name().to_string())
        .collect();
    assert_eq!(header, ["variant", "cage_slip", "error"]);
    let rows: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(|r| r.unwrap())
        .collect();
    assert_eq!(rows[0].get_string(0).unwrap(), "v0");
    assert_eq!(rows[0].get_double(1).unwrap(), 0.01);
    assert!(rows[0].get_string(2).is_err());
    assert!(rows[1].get_double(1).is_err());
    assert_eq!(rows[1].get_string(2).unwrap(), "no solution");
    let clash = [
        Column {
            name: "error",
            values: Values::Numbers(&[1.0]),
        },
        Column {
            name: "error",
            values: Values::Text(&[None]),
        },
    ];
    assert!(write_parquet_table(&path, &clash).is_err());
    std::fs::remove_dir_all(dir).ok();
}
