//! `startup` through `rolldyn::run_json`: bearing 1032930's frozen point 1 (zero speed,
//! skipped with its frozen loads).

use rolldyn::{Context, Failure, ModelSource, Unobserved, run_json};
use std::path::PathBuf;

fn model() -> ModelSource {
    ModelSource::File(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/1032930.toml"))
}

#[test]
fn a_frozen_point_at_rest_keeps_its_loads() {
    let out = std::env::temp_dir().join(format!("rolldyn-lib-startup-{}", std::process::id()));
    let request = serde_json::json!({"points": ["1"], "revolutions": 1, "jobs": 1, "out": out});
    let context = Context::new(model(), &Unobserved);
    let answer = run_json("startup", &request.to_string(), &context).expect("startup runs");
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    let p1 = &summary["points"][0];
    assert!(p1["note"].as_str().unwrap().contains("skipped"));
    assert!((p1["fixed_load_n"].as_f64().unwrap() - 4287.6).abs() < 1e-9);
    assert_eq!(answer.tables[0].name, "startup");
    assert_eq!(answer.tables[0].rows(), 1);
    assert!(out.join("startup.csv").exists());
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn an_unknown_field_is_refused_by_name() {
    let context = Context::new(model(), &Unobserved);
    let failure = run_json("startup", r#"{"point": ["1"]}"#, &context).unwrap_err();
    assert!(
        matches!(&failure, Failure::Input(m) if m.contains("point")),
        "{failure:?}"
    );
}
