//! `bench` through `rolldyn::run_json`.

use rolldyn::{Context, Failure, run_json};

#[test]
fn a_short_benchmark_times_its_run() {
    let request = r#"{"duration": "1 ms", "repeat": 1, "operating": {"speed": "4000 rpm"}}"#;
    let answer = run_json("bench", request, &Context::default()).expect("the benchmark runs");
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    let runs = summary["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 1);
    let simulated = runs[0]["simulated_time_s"].as_f64().unwrap();
    assert!((simulated - 1e-3).abs() < 1e-4, "{simulated}");
    assert_eq!(answer.tables[0].rows(), 1);
}

#[test]
fn an_unknown_field_is_refused_by_name() {
    let failure = run_json("bench", r#"{"repeats": 2}"#, &Context::default()).unwrap_err();
    assert!(
        matches!(&failure, Failure::Input(m) if m.contains("repeats")),
        "{failure:?}"
    );
    let failure = run_json("bench", r#"{"repeat": 0}"#, &Context::default()).unwrap_err();
    assert!(matches!(failure, Failure::Input(_)));
}
