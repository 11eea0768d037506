//! `traction` through `rolldyn::run_json`: the seed 000 critical slip from quantities with
//! units, the curves as a table, lists of temperatures, an unknown field refused by name.

use rolldyn::{Context, Failure, run_json};

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

#[test]
fn traction_reproduces_the_seed_critical_slip_range() {
    let request = r#"{"temperature": "40 C", "max_pressure": "1 GPa", "rolling_speed": "2.5 m/s"}"#;
    let answer = run_json("traction", request, &Context::default()).unwrap();
    // Seed 000 §2.2: computed 0.16, measured 0.19 (SPEC V-12).
    let s = summary(&answer)["critical_slip"].as_f64().unwrap();
    assert!((0.14..=0.19).contains(&s), "{s}");
    assert_eq!(summary(&answer)["cases"].as_array().unwrap().len(), 1);
    let curves = answer.tables.iter().find(|t| t.name == "traction").unwrap();
    assert_eq!(curves.rows(), 101);
}

#[test]
fn traction_takes_lists_and_ranges_of_operating_points() {
    let request = r#"{"temperature": ["40C", 333.15], "max_pressure": "0.8GPa..1.2GPa:0.2GPa"}"#;
    let answer = run_json("traction", request, &Context::default()).unwrap();
    assert_eq!(summary(&answer)["cases"].as_array().unwrap().len(), 6);
    let cases = answer.tables.iter().find(|t| t.name == "cases").unwrap();
    assert_eq!(cases.rows(), 6);
}

#[test]
fn traction_refuses_an_unknown_field_by_name() {
    let failure = run_json(
        "traction",
        r#"{"rolling_sped": "2 m/s"}"#,
        &Context::default(),
    )
    .unwrap_err();
    assert!(matches!(failure, Failure::Input(_)));
    assert!(failure.to_string().contains("rolling_sped"), "{failure}");
}
