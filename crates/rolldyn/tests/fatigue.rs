//! The fatigue and rainflow analyses through `rolldyn::run_json`: the cage life of the embedded
//! model from a request with a unit string, rainflow counting of a file, a stop request,
//! unknown fields.

use rolldyn::{Context, Failure, ModelSource, Observer, Unobserved, run_json};

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

#[test]
fn the_cage_life_of_the_embedded_model() {
    let context = Context::new(ModelSource::Embedded, &Unobserved);
    let request = r#"{"revolutions": 1, "fillet_radius": "0.5 mm", "operating": {"misalignment": "11 arcmin"}}"#;
    let answer = run_json("fatigue", request, &context).unwrap();
    assert_eq!(summary(&answer)["load_sets"], 180);
    assert!(summary(&answer)["max_stress_pa"].as_f64().unwrap() > 0.0);
    assert_eq!(answer.tables[0].name, "cycles");
    assert!(answer.text.contains("cage fatigue by the Frame model"));
}

#[test]
fn rainflow_counts_a_history_file() {
    let dir = std::env::temp_dir().join(format!("rolldyn-lib-rainflow-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("h.csv");
    std::fs::write(&file, "stress\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n").unwrap();
    let request = serde_json::json!({"history": file}).to_string();
    let answer = run_json("rainflow", &request, &Context::default()).unwrap();
    let total: f64 = summary(&answer)["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["count"].as_f64().unwrap())
        .sum();
    assert_eq!(total, 4.0);
    assert_eq!(answer.tables[0].columns[0].name, "range");
    std::fs::remove_dir_all(dir).ok();
}

struct Stop;

impl Observer for Stop {
    fn stop_requested(&self) -> bool {
        true
    }
}

#[test]
fn a_stop_request_ends_fatigue_before_its_next_stage() {
    let context = Context::new(ModelSource::Embedded, &Stop);
    let Err(Failure::Run(message)) = run_json("fatigue", "{}", &context) else {
        panic!("an interrupted analysis is a failed run")
    };
    assert!(message.contains("interrupted"), "{message}");
}

#[test]
fn unknown_fields_are_refused_by_name() {
    for (analysis, request, field) in [
        ("fatigue", r#"{"revolution": 1}"#, "revolution"),
        (
            "rainflow",
            r#"{"history": "h.csv", "periodical": true}"#,
            "periodical",
        ),
    ] {
        let Err(Failure::Input(message)) = run_json(analysis, request, &Context::default()) else {
            panic!("{analysis}: an unknown field is bad input")
        };
        assert!(message.contains(field), "{message}");
    }
}
