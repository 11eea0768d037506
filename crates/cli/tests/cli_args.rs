//! Command-line values that parse but make no sense are refused with exit code 2 and a message
//! naming the flag; negative quantities reach that validation instead of a parser error.

mod common;

use common::{example, json, rolldyn};
use std::process::Output;

/// Asserts exit code 2 and that stderr names every one of `words`.
fn refused(out: &Output, words: &[&str]) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    for word in words {
        assert!(stderr.contains(word), "'{word}' missing in: {stderr}");
    }
}

#[test]
fn negative_load_reaches_the_validation_naming_the_flag() {
    let model = example("2002834.toml");
    for load in ["-5N", "-5kN"] {
        let out = rolldyn(&["contact", &model, "--load", load, "--method", "hertz"]);
        refused(&out, &["--load", "positive"]);
        assert!(!String::from_utf8_lossy(&out.stderr).contains("tip:"));
    }
}

/// Issue 38: `--duration 5` ran 5 s instead of 5 revolutions, `--radial-load 15` gave 15 N,
/// `skid --speed 5000` was 5000 rad/s: a bare number on a dimensional flag is refused, naming
/// the flag and showing the value with a unit.
#[test]
fn bare_numbers_on_dimensional_flags_are_refused_with_an_example() {
    let model = example("2002834.toml");
    for (args, example) in [
        (&["simulate", &model, "--duration", "5"][..], "5rev"),
        (&["simulate", &model, "--radial-load", "15"], "15 kN"),
        (&["skid", &model, "--speed", "5000"], "5000 rpm"),
        (&["skid", &model, "--speed", "4000rpm,5000"], "5000 rpm"),
        (&["check", &model, "--speed", "5000"], "5000 rpm"),
        (&["oils", "--temperature", "40"], "40 C"),
        (&["wear", &model, "--period", "1905"], "1905 s"),
    ] {
        let flag = args.iter().find(|a| a.starts_with("--")).unwrap();
        refused(&rolldyn(args), &[flag, "no unit", example]);
    }
    // Zero is zero in every unit but a temperature's; dimensionless values stay bare.
    let out = rolldyn(&[
        "contact", &model, "--load", "1kN", "--tilt", "0", "--method", "hertz",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn negative_durations_reach_the_validation_naming_the_flag() {
    let model = example("2002834.toml");
    for (flag, value) in [("--duration", "-5rev"), ("--output-step", "-1ms")] {
        let out = rolldyn(&["simulate", &model, flag, value]);
        refused(&out, &[flag]);
        assert!(!String::from_utf8_lossy(&out.stderr).contains("tip:"));
    }
    let out = rolldyn(&["bench", "--duration", "-5rev"]);
    refused(&out, &["--duration"]);
}

#[test]
fn negative_tilt_is_a_value() {
    let v = json(&rolldyn(&[
        "contact",
        &example("2002834.toml"),
        "--load",
        "1kN",
        "--tilt",
        "-2arcmin",
        "--method",
        "hertz",
        "--json",
    ]));
    assert!(v["tilt_rad"].as_f64().unwrap() < 0.0);
}

#[test]
fn temperature_below_absolute_zero_is_refused() {
    for args in [
        &["oils", "--temperature=-300C"][..],
        &["oils", "--temperature", "-300C"],
    ] {
        refused(&rolldyn(args), &["--temperature", "absolute zero"]);
    }
}

#[test]
fn temperature_outside_an_oil_law_is_refused() {
    // the PAO1 viscosity law a·θᵇ needs θ > 0 °C; at −5 °C it printed NaN
    let out = rolldyn(&["oils", "--temperature", "-5C"]);
    refused(&out, &["--temperature", "pao1-vg320"]);
    assert!(!String::from_utf8_lossy(&out.stdout).contains("NaN"));
}

#[test]
fn contact_pressure_beyond_any_material_is_refused() {
    let out = rolldyn(&[
        "contact",
        &example("2002834.toml"),
        "--load",
        "1e30N",
        "--method",
        "hertz",
    ]);
    refused(&out, &["--load", "GPa"]);
}

#[test]
fn zero_jobs_are_refused() {
    // refused while parsing the flags, before the (missing) file is read
    for command in ["sweep", "startup"] {
        refused(
            &rolldyn(&[command, "missing.toml", "--jobs", "0"]),
            &["--jobs"],
        );
    }
}

#[test]
fn reversed_or_negative_step_ranges_are_refused() {
    let model = example("obrien-taylor.toml");
    for range in ["700N..100N:200N", "100N..700N:-200N"] {
        refused(
            &rolldyn(&["skid", &model, "--radial-load", range]),
            &["--radial-load", range],
        );
    }
}
