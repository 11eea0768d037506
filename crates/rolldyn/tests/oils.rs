//! `oils` through `rolldyn::run_json`: the library at a temperature with its unit, as rows
//! and as a table, an unknown field refused by name.

use rolldyn::{ColumnValues, Context, Failure, run_json};

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

#[test]
fn oils_lists_the_library_at_a_temperature_with_unit() {
    let answer = run_json("oils", r#"{"temperature": "60 C"}"#, &Context::default()).unwrap();
    let all = summary(&answer);
    let rows = all.as_array().unwrap();
    let pao = rows.iter().find(|o| o["name"] == "pao1-vg320").unwrap();
    assert!((pao["temperature_k"].as_f64().unwrap() - 333.15).abs() < 1e-9);
    assert!(rows.iter().any(|o| o["name"] == "nvi65"));
    let table = &answer.tables[0];
    assert_eq!(table.name, "oils");
    assert_eq!(table.rows(), rows.len());
    let eta = table
        .columns
        .iter()
        .find(|c| c.name == "dynamic_viscosity_pa_s")
        .unwrap();
    let ColumnValues::Real(eta) = &eta.values else {
        panic!("viscosities are numbers");
    };
    let k = rows.iter().position(|o| o["name"] == "pao1-vg320").unwrap();
    assert_eq!(Some(eta[k]), pao["dynamic_viscosity_pa_s"].as_f64());
}

#[test]
fn oils_refuses_an_unknown_field_by_name() {
    let failure = run_json("oils", r#"{"temprature": "60 C"}"#, &Context::default()).unwrap_err();
    assert!(matches!(failure, Failure::Input(_)));
    assert!(failure.to_string().contains("temprature"), "{failure}");
}
