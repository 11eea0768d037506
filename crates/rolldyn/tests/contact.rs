//! `contact` through `rolldyn::run_json`: the seed 004 approach at a load with its unit, the
//! pressure map as a table, an unknown field refused by name.

use rolldyn::{ColumnValues, Context, Failure, ModelSource, Unobserved, run_json};
use std::path::PathBuf;

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

fn crowned_32206() -> ModelSource {
    ModelSource::File(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/contact/32206-crowned-3.2um.toml"),
    )
}

#[test]
fn contact_gives_the_seed_004_approach_and_the_pressure_map() {
    let context = Context::new(crowned_32206(), &Unobserved);
    for cells in [r#""350x9""#, "[350, 9]"] {
        let request = format!(r#"{{"load": "1167 N", "cells": {cells}}}"#);
        let answer = run_json("contact", &request, &context).unwrap();
        // SPEC F-08: ≈ 5.93 µm at 1167 N.
        let approach = summary(&answer)["approach_m"].as_f64().unwrap();
        assert!((approach / 5.93e-6 - 1.0).abs() < 0.01, "{approach}");
        assert_eq!(summary(&answer)["cells"], serde_json::json!([350, 9]));
        let map = answer
            .tables
            .iter()
            .find(|t| t.name == "pressure_map")
            .expect("a Boussinesq answer has its map");
        assert_eq!(map.rows(), 350 * 9);
        let names: Vec<&str> = map.columns.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["x_m", "y_m", "pressure_pa"]);
        let ColumnValues::Real(p) = &map.columns[2].values else {
            panic!("pressures are numbers");
        };
        let max = p.iter().cloned().fold(0.0, f64::max);
        let expected = summary(&answer)["max_pressure_pa"].as_f64().unwrap();
        assert!((max / expected - 1.0).abs() < 1e-9, "{max} vs {expected}");
    }
}

#[test]
fn contact_refuses_an_unknown_field_and_a_bad_grid() {
    let context = Context::new(crowned_32206(), &Unobserved);
    let failure = run_json("contact", r#"{"load": "1 kN", "lod": 1}"#, &context).unwrap_err();
    assert!(matches!(failure, Failure::Input(_)));
    assert!(failure.to_string().contains("lod"), "{failure}");
    let failure = run_json("contact", r#"{"load": 1000, "cells": [0, 3]}"#, &context).unwrap_err();
    assert!(failure.to_string().contains("1 to 8192"), "{failure}");
}

#[test]
fn n6_a_grid_that_cannot_resolve_the_contact_is_refused_and_the_default_grid_resolves_it() {
    let context = Context::new(crowned_32206(), &Unobserved);
    for cells in [r#""1x1""#, r#""5x5""#, r#""150x3""#] {
        let request = format!(r#"{{"load": "1167 N", "cells": {cells}}}"#);
        let failure = run_json("contact", &request, &context).unwrap_err();
        assert!(matches!(failure, Failure::Input(_)), "{failure}");
        assert!(failure.to_string().contains("--cells"), "{failure}");
    }
    let pressure = |request: &str| {
        let answer = run_json("contact", request, &context).unwrap();
        summary(&answer)["max_pressure_pa"].as_f64().unwrap()
    };
    let default = pressure(r#"{"load": "1167 N"}"#);
    let fine = pressure(r#"{"load": "1167 N", "cells": "1000x30"}"#);
    assert!((default / fine - 1.0).abs() < 0.01, "{default} vs {fine}");
}
