//! `rolldyn::run_json("loads", …)`: the tapered load distribution from a JSON request with
//! units, and an unknown field refused by name.

use rolldyn::{Context, ModelSource, run_json};
use std::path::PathBuf;

fn context() -> Context<'static> {
    Context::new(
        ModelSource::File(
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/tapered-cassette.toml"),
        ),
        &rolldyn::Unobserved,
    )
}

#[test]
fn seed_case_1_from_json() {
    let answer = run_json(
        "loads",
        r#"{"operating": {"radial_load": "118.862 kN"}}"#,
        &context(),
    )
    .unwrap();
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    assert_eq!(summary["radial_load_n"], 118_862.0);
    for row in summary["result"]["rows"].as_array().unwrap() {
        let q = row["max_cup_n"].as_f64().unwrap();
        assert!((q / 14_900.0 - 1.0).abs() < 0.02, "{q}");
    }
    let rollers = &answer.tables[0];
    assert_eq!(rollers.name, "tapered_loads");
    assert_eq!(rollers.columns[4].name, "cup_n");
    assert_eq!(answer.tables[1].rows(), 2);
}

#[test]
fn unknown_field_is_refused_by_name() {
    let e = run_json("loads", r#"{"row_ofset": 0.5}"#, &context()).unwrap_err();
    assert!(e.to_string().contains("row_ofset"), "{e}");
    let e = run_json(
        "loads",
        r#"{"operating": {"radial_lod": "1 kN"}}"#,
        &context(),
    )
    .unwrap_err();
    assert!(e.to_string().contains("radial_lod"), "{e}");
}
