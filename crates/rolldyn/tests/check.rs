//! `check` through `rolldyn::run_json`: a speed with its unit, the derived quantities, an
//! unknown field refused by name.

use rolldyn::{Context, Failure, ModelSource, Unobserved, run_json};
use std::path::PathBuf;

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

fn example(name: &str) -> ModelSource {
    ModelSource::File(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name),
    )
}

#[test]
fn check_gives_the_epicyclic_cage_speed_at_a_speed_with_unit() {
    let context = Context::new(example("2002834.toml"), &Unobserved);
    let answer = run_json("check", r#"{"speed": "6371 rpm"}"#, &context).unwrap();
    let v = &summary(&answer);
    assert!((v["pitch_diameter_m"].as_f64().unwrap() - 0.18).abs() < 1e-12);
    // ω_i d_i/(d_i + D_o) on the rolling diameters 165 and 165 + 30 + 0.009 mm
    let cage = v["epicyclic_cage_speed_rad_s"].as_f64().unwrap();
    assert!((cage - 305.778).abs() < 0.001, "{cage}");
    assert_eq!(v["cage_pocket"]["circumferential_stop"], "outer lip");
    assert!(
        answer.text.contains("epicyclic cage speed"),
        "{}",
        answer.text
    );
    assert!(answer.tables.is_empty());
}

#[test]
fn check_of_a_tapered_model_answers_its_dimensions() {
    let context = Context::new(example("tapered-cassette.toml"), &Unobserved);
    let answer = run_json("check", "{}", &context).unwrap();
    assert_eq!(summary(&answer)["kind"], "double-row tapered");
    assert!(summary(&answer)["rollers_per_row"].as_u64().unwrap() > 0);
}

#[test]
fn check_refuses_an_unknown_field_by_name() {
    let failure = run_json("check", r#"{"sped": "6371 rpm"}"#, &Context::default()).unwrap_err();
    assert!(matches!(failure, Failure::Input(_)));
    assert!(failure.to_string().contains("sped"), "{failure}");
}
