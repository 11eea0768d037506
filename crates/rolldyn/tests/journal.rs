//! `rolldyn::run_json("journal", …)`: a short bearing from a JSON request with units (the
//! Raimondi–Boyd point of the CLI test), and an unknown field refused by name.

use rolldyn::{Context, run_json};

const BEARING: &str = r#""radius": "25mm", "length": "50mm", "clearance": "50um",
    "viscosity": "0.05Pas", "speed": "3000rpm""#;

#[test]
fn raimondi_boyd_point_from_json() {
    let request =
        format!(r#"{{{BEARING}, "eccentricity": 0.6, "grid": "60x20", "no_coefficients": true}}"#);
    let answer = run_json("journal", &request, &Context::default()).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&answer.summary).unwrap();
    assert_eq!(summary["converged"], true);
    assert_eq!(summary["eccentricity"], 0.6);
    assert!(summary["stiffness_n_per_m"].is_null());
    let s = summary["sommerfeld"].as_f64().unwrap();
    // Raimondi–Boyd L/D = 1, ε = 0.6: S ≈ 0.121
    assert!((s / 0.121 - 1.0).abs() < 0.1, "{s}");
    let pressure = &answer.tables[0];
    assert_eq!(pressure.name, "pressure");
    assert_eq!(pressure.rows(), 60 * 20);
    assert_eq!(answer.tables[1].rows(), 60);
}

#[test]
fn unknown_field_is_refused_by_name() {
    let request = format!(r#"{{{BEARING}, "eccentricty": 0.6}}"#);
    let e = run_json("journal", &request, &Context::default()).unwrap_err();
    assert!(e.to_string().contains("eccentricty"), "{e}");
}
