//! Cage fatigue on the cage's own material (docs/theory.md §10.5): the seed cage's silver-plated
//! curve, a brass cage's curve, and a coating factor refused on an unplated cage.

use rolldyn::{Context, Failure, ModelSource, Unobserved, run_json};
use std::path::PathBuf;

fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

/// The embedded model with its cage made of unplated CuZn40Pb2, written to a file.
fn brass_cage_model() -> PathBuf {
    let text = rolldyn_model::DEFAULT_MODEL
        .replacen("material = \"cage-steel\"", "material = \"cuzn40pb2\"", 1)
        .replacen("plating = \"silver\"", "", 1);
    let dir = std::env::temp_dir().join(format!("rolldyn-brass-cage-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("brass.toml");
    std::fs::write(&path, text).unwrap();
    path
}

const ONE_REVOLUTION: &str = r#"{"revolutions": 1, "operating": {"misalignment": "11 arcmin"}}"#;

#[test]
fn the_seed_cage_uses_its_silver_plated_seed_curve() {
    let context = Context::new(ModelSource::Embedded, &Unobserved);
    let answer = run_json("fatigue", ONE_REVOLUTION, &context).unwrap();
    let sn = &summary(&answer)["sn"];
    assert_eq!(sn["material"], "cage-steel");
    assert_eq!(sn["coating_factor"], 1.5);
    assert!(sn["curve_source"].as_str().unwrap().contains("40khn2ma-sh"));
    assert!(
        answer.text.contains("coating factor 1.5 from cage.plating"),
        "{}",
        answer.text
    );
}

#[test]
fn a_brass_cage_uses_the_brass_curve_and_refuses_a_coating_factor() {
    let path = brass_cage_model();
    let context = Context::new(ModelSource::File(path.clone()), &Unobserved);
    let answer = run_json("fatigue", ONE_REVOLUTION, &context).unwrap();
    let s = summary(&answer);
    assert_eq!(s["sn"]["material"], "cuzn40pb2");
    assert_eq!(s["sn"]["coating_factor"], 1.0);
    assert_eq!(s["sn"]["ultimate_strength_pa"], 430e6);
    assert!(
        s["sn"]["curve_source"]
            .as_str()
            .unwrap()
            .contains("ESTIMATED")
    );
    let margin = s["endurance_margin"].as_f64().unwrap();
    assert!(margin > 0.0 && margin.is_finite(), "{margin}");
    assert!(answer.text.contains("cuzn40pb2"), "{}", answer.text);

    let request = r#"{"revolutions": 1, "coating_factor": 1.5}"#;
    let Err(Failure::Input(message)) = run_json("fatigue", request, &context) else {
        panic!("a coating factor on an unplated cage is bad input")
    };
    assert!(message.contains("cage.plating"), "{message}");
    std::fs::remove_dir_all(path.parent().unwrap()).ok();
}
