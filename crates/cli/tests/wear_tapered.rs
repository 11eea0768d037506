//! `rolldyn wear` on the double-row tapered example: one short period end to end (tables,
//! plots, JSON) and the flags it refuses.

mod common;
use common::{example, json, rolldyn};

#[test]
fn one_short_period_writes_tables_plots_and_json() {
    let dir = std::env::temp_dir().join(format!("rolldyn-wear-tapered-{}", std::process::id()));
    let out = rolldyn(&[
        "wear",
        &example("tapered-cassette.toml"),
        "--life",
        "500h",
        "--period",
        "500h",
        "--window-settle",
        "0.1ms",
        "--window",
        "0.2ms",
        "--out",
        &dir.display().to_string(),
        "--json",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let answer = json(&out);
    assert_eq!(answer["periods"], 1);
    assert_eq!(answer["wear_lines"], 9);
    assert_eq!(answer["method"], "averaged");
    assert!(answer["max_depth_um"]["roller_end"].as_f64().unwrap() > 0.0);
    for file in [
        "tapered-windows.csv",
        "tapered-windows.parquet",
        "tapered-lines.csv",
        "tapered-roller-lines.svg",
        "tapered-rib-force.svg",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_automatic_period_is_refused_on_the_tapered_bearing() {
    let out = rolldyn(&[
        "wear",
        &example("tapered-cassette.toml"),
        "--period",
        "auto",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("1905h"), "{err}");
}
