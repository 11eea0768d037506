//! `simulate` through the library's door for skins (`rolldyn::run_json`): the run manifest
//! records the caller's invocation, the tables kept in memory, the observer's stop.

use rolldyn::{Context, Failure, Invocation, ModelSource, Observer, Unobserved, run_json};
use rolldyn_dynamics::output_columns::{
    BEARING_COLUMNS, REVOLUTION_COLUMNS, ROLLER_COLUMNS, column_names,
};
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-lib-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn a_run_records_its_callers_invocation_and_the_embedded_model() {
    let dir = scratch("invocation");
    let invocation = Invocation {
        command: vec!["rolldyn.simulate".into(), "duration=0.5rev".into()],
        given: [("duration".to_string(), "0.5rev".to_string())].into(),
    };
    let context = Context {
        model: ModelSource::Embedded,
        invocation: invocation.clone(),
        observer: &Unobserved,
    };
    let request = serde_json::json!({
        "duration": "0.5rev",
        "output_step": "0.5 ms",
        "out": dir,
    });
    let answer = run_json("simulate", &request.to_string(), &context).expect("the run succeeds");
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).expect("JSON");
    let simulated = summary["simulated_time_s"].as_f64().unwrap();
    assert!(simulated > 1e-3 && simulated < 0.1, "{simulated}");
    assert_eq!(summary["output_folder"], dir.display().to_string());
    let text = std::fs::read_to_string(dir.join("run.json")).expect("run.json written");
    let manifest: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(manifest["command"][0], "rolldyn.simulate");
    assert_eq!(manifest["command"][1], "duration=0.5rev");
    assert_eq!(manifest["overrides"]["duration"], "0.5rev");
    assert_eq!(manifest["model_file"], serde_json::Value::Null);
    assert!(manifest["model_text"].as_str().unwrap().contains("2002834"));
    assert_eq!(manifest["summary"]["steps"], summary["steps"]);
    for file in ["bearing.csv", "rollers.parquet", "cage_speed.svg"] {
        assert!(dir.join(file).exists(), "{file}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn kept_tables_come_back_as_columns() {
    let request = r#"{"duration": "1.2rev", "output_step": "1ms", "keep_tables": true}"#;
    let answer = run_json("simulate", request, &Context::default()).expect("the run succeeds");
    let names: Vec<&str> = answer.tables.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, ["bearing", "rollers", "revolutions"]);
    let expected = [
        column_names(&BEARING_COLUMNS),
        column_names(&ROLLER_COLUMNS),
        column_names(&REVOLUTION_COLUMNS),
    ];
    for (table, columns) in answer.tables.iter().zip(expected) {
        assert!(table.rows() > 0, "{} is empty", table.name);
        let got: Vec<String> = table.columns.iter().map(|c| c.name.clone()).collect();
        assert_eq!(got, columns, "{}", table.name);
        assert!(table.columns.iter().all(|c| c.values.len() == table.rows()));
    }
    // every sample has a row per roller
    assert_eq!(answer.tables[1].rows() % answer.tables[0].rows(), 0);
}

/// An observer that asks to stop at once.
struct Stop;

impl Observer for Stop {
    fn stop_requested(&self) -> bool {
        true
    }
}

#[test]
fn a_run_asked_to_stop_ends_interrupted() {
    let context = Context::new(ModelSource::Embedded, &Stop);
    let failure = run_json("simulate", r#"{"duration": "2rev"}"#, &context).unwrap_err();
    assert!(
        matches!(&failure, Failure::Run(m) if m.contains("interrupted")),
        "{failure:?}"
    );
}

#[test]
fn an_unknown_field_is_refused_by_name() {
    let failure =
        run_json("simulate", r#"{"durration": "2rev"}"#, &Context::default()).unwrap_err();
    assert!(
        matches!(&failure, Failure::Input(m) if m.contains("durration")),
        "{failure:?}"
    );
    let failure = run_json(
        "simulate",
        r#"{"operating": {"sped": "4000 rpm"}}"#,
        &Context::default(),
    )
    .unwrap_err();
    assert!(failure.to_string().contains("sped"), "{failure}");
}
