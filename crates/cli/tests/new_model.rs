//! Issue 38: `rolldyn new` writes a model on which check, skid, simulate, fatigue and wear run
//! without hand editing — from a designation and from the boundary form of issue 38's bearing
//! (d 75 / D 130 / B 31 mm, 16 rollers 15 × 22 mm, brass cage, 5000 rpm, 15 kN). The dynamics
//! runs are kept short (a fraction of a cage revolution) for the debug build.

#[allow(dead_code)] // example(): these tests write their own models
mod common;
use common::{json, rolldyn};
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-new-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn succeeds(args: &[&str]) -> String {
    let out = rolldyn(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn a_designation_gives_a_model_that_checks_and_skids() {
    let dir = scratch("designation");
    let file = dir.join("nu2215.toml").display().to_string();
    let said = succeeds(&["new", "NU2215", "-o", &file]);
    assert!(
        said.contains("wrote") && said.contains("16 rollers"),
        "{said}"
    );
    succeeds(&["check", &file]);
    let skid = json(&rolldyn(&[
        "skid",
        &file,
        "--speed",
        "5000rpm",
        "--radial-load",
        "15kN",
        "--temperatures",
        "oil=70C",
        "--json",
    ]));
    assert!(skid["cage_slip"].is_number(), "{skid}");
    // without -o the model goes to stdout
    let text = succeeds(&[
        "new",
        "NJ 310",
        "--cage",
        "steel",
        "--clearance-group",
        "C3",
    ]);
    assert!(text.contains("material = \"aisi-4340\""), "{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_boundary_form_runs_every_analysis() {
    let dir = scratch("boundary");
    let file = dir.join("bearing.toml").display().to_string();
    succeeds(&[
        "new",
        "--bore",
        "75mm",
        "--outside",
        "130mm",
        "--width",
        "31mm",
        "--roller-diameter",
        "15mm",
        "--roller-length",
        "22mm",
        "--rollers",
        "16",
        "--cage",
        "brass",
        "--speed",
        "5000rpm",
        "--radial-load",
        "15kN",
        "--oil-temperature",
        "70C",
        "-o",
        &file,
    ]);
    succeeds(&["check", &file]);
    succeeds(&["skid", &file]);
    // The dynamics at the written 15 kN is step-limited by the rollers' spin (375 000 steps for
    // two cage revolutions, 25 s in the release build, minutes in this debug build); the runs
    // below override the load to 2 kN (4 300 steps), which is all "runs without hand editing"
    // needs.
    let loads = dir.join("loads.parquet").display().to_string();
    let sim = json(&rolldyn(&[
        "simulate",
        &file,
        "--radial-load",
        "2kN",
        "--duration",
        "1.2rev",
        "--cage-loads",
        &loads,
        "--json",
        "--quiet",
    ]));
    assert!(
        sim["cage_slip_mean"].is_number() || sim.is_object(),
        "{sim}"
    );
    let fatigue = json(&rolldyn(&["fatigue", "--loads", &loads, "--json"]));
    assert!(fatigue["damage_per_revolution"].is_number(), "{fatigue}");
    let wear_dir = dir.join("wear").display().to_string();
    let wear = json(&rolldyn(&[
        "wear",
        &file,
        "--radial-load",
        "2kN",
        "--life",
        "500h",
        "--period",
        "500h",
        "--settle",
        "1",
        "--revolutions",
        "1",
        "--out",
        &wear_dir,
        "--json",
    ]));
    assert_eq!(wear["periods"].as_array().map(Vec::len), Some(1), "{wear}");
    assert_eq!(wear["stop"], "life_reached", "{wear}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_tapered_designation_is_refused_naming_the_model_kinds() {
    let out = rolldyn(&["new", "32215"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("double-row-tapered"), "{err}");
}
