//! Issue 27: `run.json` and the HTML report (`--report`, `rolldyn report DIR`) of the output
//! folders of tiny real runs of `simulate` (cylindrical and tapered), `sweep`, `wear`
//! (cylindrical and tapered) and `fatigue`.

mod common;
use common::{example, json, rolldyn};
use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-report-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn succeeds(args: &[&str]) {
    let out = rolldyn(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn manifest(dir: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(dir.join("run.json")).expect("run.json written");
    serde_json::from_str(&text).expect("run.json is JSON")
}

/// The report of `dir`: inline plots, a warnings section, and nothing fetched from a network
/// (the only URLs are the SVG namespaces, which name and fetch nothing).
fn self_contained_report(dir: &Path) -> String {
    let html = std::fs::read_to_string(dir.join("report.html")).expect("report.html written");
    assert!(html.contains("<svg"), "no inline plot");
    assert!(html.contains("id=\"warnings\""));
    assert!(!html.contains("<img"));
    let lower = html.to_lowercase();
    for fetch in [
        "src=\"http",
        "href=\"http",
        "src='http",
        "href='http",
        "url(http",
        "<script src",
    ] {
        assert!(!lower.contains(fetch), "{fetch} in {}", dir.display());
    }
    let without_namespaces = lower
        .replace("xmlns=\"http://www.w3.org/2000/svg\"", "")
        .replace("xmlns:xlink=\"http://www.w3.org/1999/xlink\"", "");
    assert!(!without_namespaces.contains("http://") && !without_namespaces.contains("https://"));
    html
}

#[test]
fn simulate_writes_its_manifest_and_report() {
    let dir = scratch("simulate");
    let out = dir.display().to_string();
    let model = example("2002834.toml");
    succeeds(&[
        "simulate",
        &model,
        "--duration",
        "0.5rev",
        "--speed",
        "8163rpm",
        "--out",
        &out,
        "--report",
        "--quiet",
    ]);
    let m = manifest(&dir);
    assert_eq!(m["kind"], "simulate");
    assert_eq!(m["rolldyn_version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(m["model_file"], model.as_str());
    assert!(m["model_text"].as_str().unwrap().contains("[bearing]"));
    assert_eq!(m["overrides"]["--speed"], "8163rpm");
    assert_eq!(m["overrides"]["--duration"], "0.5rev");
    assert!(m["overrides"].get("--out").is_none());
    assert!(m["command"][1] == "simulate");
    assert!(m["summary"]["cage_slip_mean"].is_number());
    let html = self_contained_report(&dir);
    assert!(html.contains("As seed 000 Table 3.2") && html.contains("cage – guiding land"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_sweep_report_has_a_sortable_variant_table_linking_to_the_variants() {
    let dir = scratch("sweep");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("two.toml");
    std::fs::write(
        &file,
        format!(
            "model = {:?}\nanalysis = \"skid\"\n\n[[variant]]\nname = \"light\"\n\"operating.radial_load\" = \"200 N\"\n\n[[variant]]\nname = \"heavy\"\n\"operating.radial_load\" = \"2 kN\"\n",
            example("2002834.toml")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    succeeds(&[
        "sweep",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    let m = manifest(&out);
    assert_eq!(m["kind"], "sweep");
    assert_eq!(m["summary"]["variants"], 2);
    assert!(m["model_text"].as_str().unwrap().contains("[[variant]]"));
    let answer = json(&rolldyn(&["report", out.to_str().unwrap(), "--json"]));
    assert_eq!(answer["kind"], "sweep");
    assert!(answer["warnings"].is_array());
    let html = self_contained_report(&out);
    assert!(html.contains("<table id=\"variants-table\" class=\"sortable\">"));
    assert!(html.contains("href=\"#variant-0\"") && html.contains("id=\"variant-1\""));
    assert!(html.contains("addEventListener(\"click\""));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn wear_and_fatigue_write_their_manifest_and_report() {
    let wear = scratch("wear");
    succeeds(&[
        "wear",
        "--life",
        "2h",
        "--period",
        "1h",
        "--revolutions",
        "1",
        "--settle",
        "1",
        "--out",
        wear.to_str().unwrap(),
        "--report",
        "--quiet",
    ]);
    assert_eq!(manifest(&wear)["kind"], "wear");
    assert_eq!(manifest(&wear)["model_file"], serde_json::Value::Null);
    assert!(self_contained_report(&wear).contains("periods.csv"));

    let fatigue = scratch("fatigue");
    succeeds(&[
        "fatigue",
        "--revolutions",
        "1",
        "--out",
        fatigue.to_str().unwrap(),
        "--report",
    ]);
    let m = manifest(&fatigue);
    assert_eq!(m["kind"], "fatigue");
    assert!(m["summary"]["damage_per_revolution"].is_number());
    assert!(self_contained_report(&fatigue).contains("sn-diagram.svg"));
    for dir in [wear, fatigue] {
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn the_tapered_bearing_writes_manifests_too() {
    let tapered = example("tapered-cassette.toml");
    let simulate = scratch("tapered-simulate");
    succeeds(&[
        "simulate",
        &tapered,
        "--duration",
        "0.3ms",
        "--out",
        simulate.to_str().unwrap(),
        "--report",
        "--quiet",
    ]);
    assert_eq!(manifest(&simulate)["kind"], "simulate");
    self_contained_report(&simulate);
    let wear = scratch("tapered-wear");
    succeeds(&[
        "wear",
        &tapered,
        "--life",
        "500h",
        "--period",
        "500h",
        "--window-settle",
        "0.1ms",
        "--window",
        "0.2ms",
        "--out",
        wear.to_str().unwrap(),
        "--report",
        "--quiet",
    ]);
    assert_eq!(manifest(&wear)["kind"], "wear");
    self_contained_report(&wear);
    for dir in [simulate, wear] {
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn a_missing_folder_and_a_report_without_out_folder_are_bad_input() {
    let out = rolldyn(&["report", "/nonexistent/rolldyn-out"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("/nonexistent/rolldyn-out"), "{stderr}");
    for args in [
        &["simulate", "--duration", "0.5rev", "--report"][..],
        &["fatigue", "--revolutions", "1", "--report"][..],
    ] {
        let out = rolldyn(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains("--out"),
            "{args:?}"
        );
    }
}
