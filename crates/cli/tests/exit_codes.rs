//! Issue 22: one exit-code convention for every command (README "Exit codes"): 2 for bad input
//! named by file and key or flag, 1 for a numerical failure with a diagnosis, 0 for success.

mod common;

use common::rolldyn;
use std::path::PathBuf;

/// A copy of the default model with `from` replaced by `to`, in a fresh temporary folder.
fn mutated_model(name: &str, from: &str, to: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-exit-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(common::example("2002834.toml")).unwrap();
    assert!(text.contains(from), "test setup: '{from}'");
    let path = dir.join("m.toml");
    std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
    path
}

/// The exit code and the last line of stderr.
fn run(args: &[&str]) -> (i32, String) {
    let out = rolldyn(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let last = stderr.lines().last().unwrap_or("").to_string();
    (out.status.code().expect("an exit code"), last)
}

#[test]
fn skid_exits_2_on_bad_input_naming_file_and_key() {
    let path = mutated_model(
        "nooil",
        "density = \"930 kg/m3\"                 # ASSUMED",
        "",
    );
    let file = path.display().to_string();
    let (code, line) = run(&["skid", &file]);
    assert_eq!(code, 2, "{line}");
    assert!(
        line.contains(&format!("{file}:")) && line.contains("lubricant — "),
        "{line}"
    );
    let (code, line) = run(&[
        "skid",
        &common::example("2002834.toml"),
        "--speed",
        "1e30rpm",
    ]);
    assert_eq!(code, 2, "{line}");
    assert!(line.contains("--speed:"), "{line}");
}

#[test]
fn absurd_models_exit_2_in_check_and_skid() {
    let path = mutated_model(
        "cage",
        "width = \"20 mm\"                 # ASSUMED\nmaterial = \"cage-steel\"",
        "width = \"1e308 mm\"\nmaterial = \"cage-steel\"",
    );
    let file = path.display().to_string();
    for command in ["check", "skid"] {
        let (code, line) = run(&[command, &file]);
        assert_eq!(code, 2, "{command}: {line}");
        assert!(line.contains("cage.width — "), "{line}");
    }
}

#[test]
fn a_bad_oil_temperature_blames_its_flag() {
    let out = rolldyn(&[
        "simulate",
        &common::example("2002834.toml"),
        "--oil-temperature=-300C",
        "--duration",
        "1ms",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("--oil-temperature") && !stderr.contains("--radial-load"),
        "{stderr}"
    );
}

#[test]
fn a_huge_bad_value_gives_a_short_message() {
    let huge = format!("radial = \"{} mm\"", "9".repeat(200_000));
    let path = mutated_model("huge", "radial = \"0.009 mm\"", &huge);
    let out = rolldyn(&["check", &path.display().to_string()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        out.stderr.len() < 1000,
        "{} bytes of stderr",
        out.stderr.len()
    );
}

#[cfg(unix)]
#[test]
fn check_of_dev_zero_exits_2_quickly() {
    let start = std::time::Instant::now();
    let (code, line) = run(&["check", "/dev/zero"]);
    assert_eq!(code, 2, "{line}");
    assert!(
        line.contains("/dev/zero: ") && line.contains("larger than"),
        "{line}"
    );
    assert!(start.elapsed().as_secs_f64() < 10.0);
}

#[test]
fn a_valid_model_exits_0() {
    let out = rolldyn(&["check", &common::example("2002834.toml"), "--json"]);
    assert_eq!(common::json(&out)["name"], "2002834");
}

#[test]
fn flag_values_out_of_bounds_exit_2_naming_the_flag() {
    let model = common::example("2002834.toml");
    for args in [
        vec!["check", &model, "--speed", "1e30rpm"],
        vec!["skid", &model, "--speed", "1000rpm..1e30rpm:1e29rpm"],
        vec!["skid", &model, "--radial-load=-5N"],
    ] {
        let (code, line) = run(&args);
        assert_eq!(code, 2, "{args:?}: {line}");
        assert!(
            line.contains("--speed:") || line.contains("--radial-load:"),
            "{line}"
        );
    }
}

#[test]
fn wear_exits_2_naming_the_missing_hardness_and_bad_flags() {
    let path = mutated_model(
        "nohardness",
        "meyer_hardness = \"305 kgf/mm2\"  # flag F-45",
        "",
    );
    let file = path.display().to_string();
    let (code, line) = run(&["wear", &file, "--life", "10h", "--quiet"]);
    assert_eq!(code, 2, "{line}");
    assert!(
        line.contains(&file) && line.contains("materials.cage-steel.meyer_hardness"),
        "{line}"
    );
    let (code, line) = run(&["wear", "--period", "soon"]);
    assert_eq!(code, 2, "{line}");
    let (code, line) = run(&["wear", "--life", "-5h"]);
    assert_eq!(code, 2, "{line}");
    let (code, line) = run(&["wear", "--pressure", "boussinesq", "--method", "direct"]);
    assert_eq!(code, 2, "{line}");
    assert!(line.contains("--method averaged"), "{line}");
}

#[test]
fn fatigue_rainflow_counts_a_csv_and_names_a_bad_line() {
    let dir = std::env::temp_dir().join(format!("rolldyn-rainflow-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("h.csv");
    std::fs::write(&good, "stress\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n").unwrap();
    let out = rolldyn(&["fatigue", "rainflow", &good.display().to_string(), "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let total: f64 = json["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["count"].as_f64().unwrap())
        .sum();
    assert_eq!(total, 4.0);
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "1\n2\nx\n").unwrap();
    let file = bad.display().to_string();
    let (code, line) = run(&["fatigue", "rainflow", &file]);
    assert_eq!(code, 2, "{line}");
    assert!(line.contains(&file) && line.contains("line 3"), "{line}");
}

#[test]
fn end_rib_limit_study_exits_2_on_a_cylindrical_model_a_missing_file_or_a_bad_cell() {
    let cylindrical = common::example("2002834.toml");
    let tapered = common::example("tapered-cassette.toml");
    let out = std::env::temp_dir().join(format!("rolldyn-exit-{}-erl", std::process::id()));
    let out = out.to_str().unwrap();
    for (args, expected) in [
        (
            vec!["study", "end-rib-limit", &cylindrical, "--out", out],
            "double-row tapered",
        ),
        (
            vec!["study", "end-rib-limit", "no-such-model.toml", "--out", out],
            "not found",
        ),
        (
            vec![
                "study",
                "end-rib-limit",
                &tapered,
                "--out",
                out,
                "--cell",
                "2mm",
            ],
            "--cell",
        ),
        (
            vec!["study", "seed004", &tapered, "--out", out],
            "is read by",
        ),
    ] {
        let (code, line) = run(&args);
        assert_eq!(code, 2, "{args:?}: {line}");
        assert!(line.contains(expected), "{args:?}: {line}");
    }
}
