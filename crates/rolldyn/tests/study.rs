//! The study analysis through `rolldyn::run_json`: the end–rib limit study of the tapered
//! example on a coarse grid from a request with a unit string; a model file refused by the other
//! studies; an unknown field.

use rolldyn::{Context, Failure, ModelSource, Unobserved, run_json};
use std::path::PathBuf;

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

fn tapered() -> ModelSource {
    ModelSource::File(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/tapered-cassette.toml"),
    )
}

#[test]
fn the_end_rib_limit_study_on_a_coarse_grid() {
    let out = std::env::temp_dir().join(format!("rolldyn-lib-study-{}", std::process::id()));
    let context = Context::new(tapered(), &Unobserved);
    let request = serde_json::json!({"study": "end-rib-limit", "out": out, "cell": "0.25 mm"});
    let answer = run_json("study", &request.to_string(), &context).unwrap();
    let summary = summary(&answer);
    assert_eq!(summary["cell_m"], 0.25e-3);
    let limits = summary["limits"].as_array().unwrap();
    assert_eq!(limits.len(), 8);
    assert!(limits[0]["limit_force_n"].as_f64().unwrap() > 0.0);
    assert!(answer.tables.iter().any(|t| t.name == "end-rib-limit"));
    assert!(out.join("end-rib-limit/end-rib-limit.csv").is_file());
    std::fs::remove_dir_all(out).ok();
}

#[test]
fn a_model_file_is_read_by_end_rib_limit_only_and_unknown_fields_are_refused() {
    let context = Context::new(tapered(), &Unobserved);
    let Err(Failure::Input(message)) =
        run_json("study", r#"{"study": "seed004", "out": "/tmp"}"#, &context)
    else {
        panic!("bad input")
    };
    assert!(message.contains("is read by"), "{message}");
    let Err(Failure::Input(message)) = run_json(
        "study",
        r#"{"study": "seed004", "cells": "1 mm"}"#,
        &Context::default(),
    ) else {
        panic!("bad input")
    };
    assert!(message.contains("cells"), "{message}");
}
