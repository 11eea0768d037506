//! `rolldyn startup`: frozen start-up points of bearing 1032930 (seed 000 §3.1.2, V-08) with a
//! very short dynamic run per point.

mod common;

use common::{example, json, rolldyn};

#[test]
fn startup_runs_frozen_points_and_writes_tables() {
    let out = std::env::temp_dir().join(format!("rolldyn-startup-{}", std::process::id()));
    let out_arg = out.display().to_string();
    let model = example("1032930.toml");
    let output = rolldyn(&[
        "startup",
        &model,
        "--points",
        "1,3",
        "--revolutions",
        "1",
        "--jobs",
        "2",
        "--json",
        "--quiet",
        "--out",
        &out_arg,
    ]);
    let v = json(&output);
    assert_eq!(v["model"], "1032930");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    // point 1: t = 0, zero speed, skipped but with its frozen loads (weight + gearbox before
    // cut-off, SPEC §3.7)
    let p1 = &points[0];
    assert_eq!(p1["label"], "1");
    assert!(p1["note"].as_str().unwrap().contains("skipped"));
    assert!((p1["fixed_load_n"].as_f64().unwrap() - 4287.6).abs() < 1e-9);
    assert!(p1["cage_slip_dynamic"].is_null());
    // point 3: after starter cut-off; speed on the ASSUMED linear schedule, gearbox 406.5 N,
    // unbalance U ω² = 3.1625e-3 kg·m · ω²
    let p3 = &points[1];
    let w = p3["inner_speed_rad_s"].as_f64().unwrap();
    let rpm_expected = 6300.0 + (9175.0 - 6300.0) * (85.2988 - 82.0988) / (270.4988 - 82.0988);
    assert!((w * 30.0 / std::f64::consts::PI - rpm_expected).abs() < 1e-6);
    assert!((p3["fixed_load_n"].as_f64().unwrap() - 985.3).abs() < 1e-9);
    assert!((p3["rotating_load_n"].as_f64().unwrap() - 3.1625e-3 * w * w).abs() < 1e-6);
    assert!((p3["clearance_m"].as_f64().unwrap() - 1.92e-6).abs() < 1e-12);
    assert!((p3["oil_temperature_k"].as_f64().unwrap() - 323.15).abs() < 1e-9);
    assert_eq!(p3["revolutions"].as_f64().unwrap(), 1.0);
    let slip = p3["cage_slip_dynamic"].as_f64().unwrap();
    assert!(slip.abs() < 0.5, "{slip}");
    assert!(p3["cage_slip_quasi_static"].as_f64().unwrap().is_finite());
    assert!(p3["max_roller_load_n"].as_f64().unwrap() > 0.0);
    let csv = std::fs::read_to_string(out.join("startup.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3);
    assert!(csv.lines().nth(2).unwrap().starts_with("3,85.2988,"));
    for file in [
        "startup.parquet",
        "startup_cage_slip.svg",
        "startup_conditions.svg",
    ] {
        assert!(out.join(file).exists(), "{file}");
    }
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn startup_bad_input_exits_2() {
    let model = example("1032930.toml");
    let output = rolldyn(&["startup", &model, "--points", "42", "--quiet"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("--points") && stderr.contains("42"),
        "{stderr}"
    );
    let output = rolldyn(&["startup", &model, "--revolutions", "0", "--quiet"]);
    assert_eq!(output.status.code(), Some(2));
    // a start-up from rest cannot be simulated for a number of cage revolutions
    let output = rolldyn(&["simulate", &model, "--quiet"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("starts at rest"), "{stderr}");
    // the default model has no [startup] section
    let output = rolldyn(&["startup", &example("2002834.toml"), "--quiet"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("[startup]"), "{stderr}");
}
