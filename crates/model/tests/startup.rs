//! Start-up keys of `[operating]` and `[startup]` (SPEC §3.7, seed 000 §3.1.2): parsing of the
//! 1032930 example and one-line errors for bad input.

use rolldyn_model::{load, parse};
use std::path::Path;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn example() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/1032930.toml");
    std::fs::read_to_string(path).unwrap()
}

/// Replaces the first occurrence of `from` in the 1032930 example and returns the error text.
fn error_after(from: &str, to: &str) -> String {
    let good = example();
    assert!(good.contains(from), "test setup: '{from}' not in 1032930");
    let err = parse(&good.replacen(from, to, 1), "bad.toml").expect_err("must be rejected");
    let message = err.to_string();
    assert!(!message.contains('\n'), "one line expected: {message}");
    assert!(message.starts_with("bad.toml:"), "{message}");
    message
}

#[test]
fn example_1032930_start_up_keys() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/1032930.toml");
    let m = load(&path).unwrap();
    // SPEC §3.7: U = 3162.5 g·mm = 3.1625e-3 kg·m
    assert!((m.operating.unbalance.unwrap() - 3.1625e-3).abs() < 1e-15);
    assert_eq!(m.operating.unbalance_phase, 0.0);
    assert!(m.operating.inner_speed.is_none());
    let s = &m.schedules;
    let speed = s.speed.as_ref().unwrap();
    assert_eq!(speed.len(), 3);
    assert_eq!(speed[1].0, 82.0988);
    assert!((speed[1].1 - 6300.0 * RPM).abs() < 1e-9);
    assert!((speed[2].1 - 9175.0 * RPM).abs() < 1e-9);
    let clearance = s.clearance.as_ref().unwrap();
    assert_eq!(clearance.len(), 9);
    assert!((clearance[8].1 + 5e-6).abs() < 1e-15);
    let oil = s.oil_temperature.as_ref().unwrap();
    assert!((oil[1].1 - 322.15).abs() < 1e-9 && (oil[8].1 - 353.15).abs() < 1e-9);
    assert_eq!(s.loads.len(), 2);
    let weight = &s.loads[0];
    assert_eq!(weight.name.as_deref(), Some("rotor weight share"));
    assert_eq!((weight.magnitude, weight.step), (578.8, None));
    assert!((weight.direction - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    let gearbox = &s.loads[1];
    assert_eq!(gearbox.magnitude, 3708.8);
    assert_eq!(gearbox.step, Some((406.5, 82.0988)));
    let startup = m.startup.as_ref().unwrap();
    let times: Vec<f64> = startup.points.iter().map(|p| p.time).collect();
    assert_eq!(
        times,
        [
            0.0, 82.0988, 85.2988, 101.8988, 109.4988, 144.2988, 160.2988, 184.2988, 270.4988
        ]
    );
    assert_eq!(startup.points[1].label, "2");
    assert_eq!(startup.revolutions, 100.0);
    assert_eq!(startup.average_revolutions, Some(30.0));
    assert!(m.lubrication.is_some());
}

#[test]
fn loads_default_downwards_and_startup_defaults() {
    let text = example()
        .replacen("direction = \"270 deg\"\n", "", 1)
        .replacen(
            "labels = [\"1\", \"2\", \"3\", \"4\", \"5\", \"6\", \"7\", \"8\", \"9\"]\n",
            "",
            1,
        )
        .replacen("revolutions = 100", "revolutions = 12.0\n#", 1)
        .replacen("average_revolutions = 30", "average_revolutions = 3", 1);
    let m = parse(&text, "ok.toml").unwrap();
    assert!((m.schedules.loads[0].direction - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    let startup = m.startup.unwrap();
    assert_eq!(startup.points[8].label, "9");
    assert_eq!(startup.revolutions, 12.0);
    assert_eq!(startup.average_revolutions, Some(3.0));
    let text = example().replacen("revolutions = 100", "#", 1).replacen(
        "average_revolutions = 30",
        "#",
        1,
    );
    let startup = parse(&text, "ok.toml").unwrap().startup.unwrap();
    assert_eq!(
        startup.revolutions,
        rolldyn_model::DEFAULT_STARTUP_REVOLUTIONS
    );
    assert_eq!(startup.average_revolutions, None);
}

#[test]
fn unbalance_needs_an_unbalance_unit() {
    let m = error_after("unbalance = \"3162.5 g*mm\"", "unbalance = \"3162.5 g\"");
    assert!(
        m.contains("operating.unbalance") && m.contains("unbalance"),
        "{m}"
    );
    let m = error_after("unbalance = \"3162.5 g*mm\"", "unbalance = \"-1 g*mm\"");
    assert!(
        m.contains("operating.unbalance") && m.contains("negative"),
        "{m}"
    );
}

#[test]
fn unknown_keys_in_new_tables() {
    let m = error_after("after = \"406.5 N\"", "after = \"406.5 N\"\nwhen = \"3 s\"");
    assert!(
        m.contains("operating.loads[1].when") && m.contains("unknown key"),
        "{m}"
    );
    let m = error_after("revolutions = 100", "revolutions = 100\nsteps = 3");
    assert!(
        m.contains("startup.steps") && m.contains("unknown key"),
        "{m}"
    );
    let m = error_after(
        "[operating.speed_schedule]\n",
        "[operating.speed_schedule]\nrpm = 3\n",
    );
    assert!(m.contains("operating.speed_schedule.rpm"), "{m}");
}

#[test]
fn load_step_needs_both_after_and_at() {
    let m = error_after("at = \"82.0988 s\"\n", "");
    assert!(
        m.contains("operating.loads[1].after") && m.contains("`at`"),
        "{m}"
    );
    let m = error_after("after = \"406.5 N\"\n", "");
    assert!(
        m.contains("operating.loads[1].at") && m.contains("`after`"),
        "{m}"
    );
    let m = error_after("at = \"82.0988 s\"", "at = \"82.0988 N\"");
    assert!(
        m.contains("operating.loads[1].at") && m.contains("a time"),
        "{m}"
    );
    let m = error_after("magnitude = \"578.8 N\"", "magnitude = \"-578.8 N\"");
    assert!(
        m.contains("operating.loads[0].magnitude") && m.contains("negative"),
        "{m}"
    );
}

#[test]
fn schedules_need_matching_increasing_points() {
    let m = error_after(
        "speed = [\"0 rpm\", \"6300 rpm\", \"9175 rpm\"]",
        "speed = [\"0 rpm\", \"6300 rpm\"]",
    );
    assert!(
        m.contains("operating.speed_schedule.speed") && m.contains("2 values for 3 times"),
        "{m}"
    );
    let m = error_after(
        "time = [\"0 s\", \"82.0988 s\", \"270.4988 s\"]",
        "time = [\"0 s\", \"300 s\", \"270.4988 s\"]",
    );
    assert!(
        m.contains("operating.speed_schedule.time") && m.contains("increase strictly"),
        "{m}"
    );
    let m = error_after(
        "speed = [\"0 rpm\", \"6300 rpm\", \"9175 rpm\"]",
        "speed = [\"0 rpm\", \"6300 N\", \"9175 rpm\"]",
    );
    assert!(m.contains("operating.speed_schedule.speed[1]"), "{m}");
    let m = error_after("\"-5.0 um\"]", "\"-50 um\"]");
    assert!(
        m.contains("operating.clearance_schedule.radial") && m.contains("interference"),
        "{m}"
    );
    let m = error_after("\"80 C\"]", "\"-300 C\"]");
    assert!(
        m.contains("operating.oil_temperature_schedule.oil") && m.contains("absolute zero"),
        "{m}"
    );
}

#[test]
fn constant_and_schedule_together_are_ambiguous() {
    let m = error_after(
        "outer_speed = \"0 rpm\"",
        "outer_speed = \"0 rpm\"\ninner_speed = \"6300 rpm\"",
    );
    assert!(
        m.contains("operating.speed_schedule") && m.contains("not both"),
        "{m}"
    );
    let m = error_after(
        "outer_speed = \"0 rpm\"",
        "outer_speed = \"0 rpm\"\ntemperatures = { oil = \"50 C\" }",
    );
    assert!(
        m.contains("operating.oil_temperature_schedule") && m.contains("not both"),
        "{m}"
    );
}

#[test]
fn frozen_points_are_checked() {
    let m = error_after(
        "frozen_points = [\"0 s\", \"82.0988 s\"",
        "frozen_points = [\"90 s\", \"82.0988 s\"",
    );
    assert!(
        m.contains("startup.frozen_points") && m.contains("increase strictly"),
        "{m}"
    );
    let m = error_after("labels = [\"1\", \"2\",", "labels = [\"2\",");
    assert!(
        m.contains("startup.labels") && m.contains("8 labels for 9"),
        "{m}"
    );
    let m = error_after("labels = [\"1\", \"2\",", "labels = [\"1\", \"1\",");
    assert!(
        m.contains("startup.labels[1]") && m.contains("twice"),
        "{m}"
    );
    let m = error_after("revolutions = 100", "revolutions = 0");
    assert!(m.contains("startup.revolutions"), "{m}");
    let m = error_after("revolutions = 100", "revolutions = 4\n#");
    assert!(m.contains("startup.average_revolutions"), "{m}");
    let m = error_after("frozen_points = [", "frozen_points = [\"1 rpm\", ");
    assert!(
        m.contains("startup.frozen_points[0]") && m.contains("a time"),
        "{m}"
    );
}
