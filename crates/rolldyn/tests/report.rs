//! `report` through `rolldyn::run_json`: the report of an output folder, a missing folder and
//! an unknown field refused.

use rolldyn::run_record::{Invocation, ModelOrigin, finish_out_folder};
use rolldyn::{Context, run_json};
use rolldyn_report::RunKind;

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

#[test]
fn report_writes_the_html_of_an_output_folder() {
    let dir = std::env::temp_dir().join(format!("rolldyn-lib-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let answer_of_run = serde_json::json!({"model": "2002834", "duration_s": 0.01});
    finish_out_folder(
        &dir,
        RunKind::Simulate,
        ModelOrigin::None,
        &Invocation::default(),
        &answer_of_run,
        false,
    )
    .unwrap();
    let request = serde_json::json!({ "dir": dir }).to_string();
    let answer = run_json("report", &request, &Context::default()).unwrap();
    assert_eq!(summary(&answer)["kind"], "simulate");
    assert!(summary(&answer)["warnings"].is_array());
    assert!(dir.join("report.html").is_file());
    assert_eq!(answer.text, dir.join("report.html").display().to_string());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn report_refuses_a_missing_folder_and_an_unknown_field() {
    let failure = run_json(
        "report",
        r#"{"dir": "/nonexistent/rolldyn-out"}"#,
        &Context::default(),
    )
    .unwrap_err();
    assert_eq!(failure.exit_code(), 2);
    assert!(failure.to_string().contains("/nonexistent/rolldyn-out"));
    let failure = run_json(
        "report",
        r#"{"dir": "x", "folder": "y"}"#,
        &Context::default(),
    )
    .unwrap_err();
    assert!(failure.to_string().contains("folder"), "{failure}");
}
