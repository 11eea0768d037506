//! `rolldyn::run_json("ehl-line", …)`: the rigid isoviscous contact of seed 002 §3.5 from a JSON
//! request with units, a load step's history as a table, and an unknown field refused by name.

use rolldyn::{Context, run_json};

const CONTACT: &str = r#""radius": "5mm", "viscosity": 0.024, "rolling_speed": "3.5 m/s""#;

/// W = 6 W₀′ μ V R / h, W₀′ = 0.40791 (Martin), within 0.5 %.
#[test]
fn martin_load_from_json() {
    let request = format!(r#"{{{CONTACT}, "min_film": "1 um"}}"#);
    let answer = run_json("ehl-line", &request, &Context::default()).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    let w = 6.0 * 0.40791 * 0.024 * 7.0 * 0.005 / 1e-6;
    let got = summary["load_per_length_n_per_m"].as_f64().unwrap();
    assert!((got / w - 1.0).abs() < 0.005, "{got} vs {w}");
    assert_eq!(answer.tables.len(), 1);
    assert_eq!(answer.tables[0].columns[1].name, "pressure_pa");
    assert_eq!(answer.tables[0].rows(), 1000);
}

#[test]
fn load_step_history_is_a_table() {
    let request =
        format!(r#"{{{CONTACT}, "load_per_length": "2kN/m", "step_to": "4kN/m", "nodes": 200}}"#);
    let answer = run_json("ehl-line", &request, &Context::default()).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    let samples = summary["transient"]["samples"].as_u64().unwrap() as usize;
    let history = &answer.tables[1];
    assert_eq!(history.name, "transient");
    assert_eq!(history.rows(), samples);
}

#[test]
fn unknown_field_is_refused_by_name() {
    let request = format!(r#"{{{CONTACT}, "min_flim": "1 um"}}"#);
    let e = run_json("ehl-line", &request, &Context::default()).unwrap_err();
    assert!(e.to_string().contains("min_flim"), "{e}");
}
