//! `rolldyn::run_json("skid", …)`: a point and a sweep from JSON requests with units, and an
//! unknown field refused by name.

use rolldyn::{Context, ModelSource, run_json};
use std::path::PathBuf;

fn model(name: &str) -> ModelSource {
    ModelSource::File(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name),
    )
}

fn context() -> Context<'static> {
    Context::new(model("obrien-taylor.toml"), &rolldyn::Unobserved)
}

#[test]
fn point_and_sweep_from_json() {
    let point = run_json(
        "skid",
        r#"{"radial_load": "300 N", "cage_land": "short"}"#,
        &context(),
    )
    .unwrap();
    assert_eq!(summary_of(&point)["radial_load_n"], 300.0);
    assert_eq!(
        summary_of(&point)["cage_land_model"],
        "short (Ocvirk) journal bearing"
    );
    let slip = summary_of(&point)["cage_slip"].as_f64().unwrap();
    assert!(slip.is_finite() && slip.abs() < 1.0, "{slip}");
    assert_eq!(point.tables[0].name, "rollers");
    assert_eq!(point.tables[0].rows(), 13);

    let sweep = run_json(
        "skid",
        r#"{"radial_load": ["100 N", 300, "500N"]}"#,
        &context(),
    )
    .unwrap();
    assert_eq!(summary_of(&sweep)["variable"], "radial_load_n");
    assert_eq!(summary_of(&sweep)["points"].as_array().unwrap().len(), 3);
    let table = &sweep.tables[0];
    assert_eq!(table.columns[0].name, "radial_load_n");
    assert_eq!(table.rows(), 3);
    let range = run_json(
        "skid",
        r#"{"radial_load": "100N..500N:200N", "temperatures": {"inner": "47.3C"}}"#,
        &context(),
    )
    .unwrap();
    assert_eq!(summary_of(&range)["points"].as_array().unwrap().len(), 3);
}

#[test]
fn unknown_field_and_bad_part_are_refused_by_name() {
    let e = run_json("skid", r#"{"radial_lod": "300 N"}"#, &context()).unwrap_err();
    assert!(e.to_string().contains("radial_lod"), "{e}");
    assert_eq!(e.exit_code(), 2);
    let e = run_json("skid", r#"{"temperatures": {"lid": 300}}"#, &context()).unwrap_err();
    assert!(e.to_string().contains("lid"), "{e}");
}

/// The answer's summary as JSON.
fn summary_of(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}
