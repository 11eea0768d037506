//! The report of hand-made output folders: kind inference, warnings and their thresholds,
//! escaping of the folder's texts.

use rolldyn_report::{ReportError, RunKind, RunManifest, report_folder};
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-report-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const PLOT: &str = "<?xml version=\"1.0\"?>\n<svg width=\"10\" height=\"10\" \
                    xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"5\" height=\"5\"/></svg>";

fn simulate_folder(name: &str, summary: serde_json::Value) -> PathBuf {
    let dir = scratch(name);
    std::fs::write(dir.join("bearing.csv"), "time_s,cage_slip\n0,0.1\n").unwrap();
    std::fs::write(dir.join("cage_slip.svg"), PLOT).unwrap();
    RunManifest {
        kind: RunKind::Simulate,
        rolldyn_version: "0.1.0".into(),
        command: vec!["rolldyn".into(), "simulate".into()],
        model_file: None,
        model_text: Some("name = \"<b>&\"".into()),
        overrides: [("--speed".to_string(), "8163rpm".to_string())].into(),
        summary,
    }
    .write(&dir)
    .unwrap();
    dir
}

#[test]
fn a_folder_without_manifest_has_its_kind_inferred_and_its_inputs_unknown() {
    let dir = scratch("inferred");
    std::fs::write(dir.join("periods.csv"), "period,time_h\n1,1905\n").unwrap();
    std::fs::write(dir.join("rates.svg"), PLOT).unwrap();
    let written = report_folder(&dir).unwrap();
    assert_eq!(written.kind, RunKind::Wear);
    let html = std::fs::read_to_string(&written.report).unwrap();
    assert!(html.contains("Inputs unknown"), "{html}");
    assert!(html.contains("<svg width=\"10\"") && !html.contains("<?xml"));
    assert!(html.contains("class=\"sortable\""));
}

#[test]
fn scuffing_land_contact_convergence_and_non_finite_values_are_warned() {
    let dir = simulate_folder(
        "warned",
        serde_json::json!({
            "model": "2002834",
            "min_scuffing_margin": 0.8,
            "max_cage_land_force_n": 3.5,
            "points": [{"converged": false}],
            "inner": {"converged": false},
            "whirl_ratio": null,
            "non_finite": {"whirl_ratio": "the cage centre does not orbit (no whirl)"}
        }),
    );
    let warnings = report_folder(&dir).unwrap().warnings;
    let has = |text: &str| warnings.iter().any(|w| w.contains(text));
    assert!(has("scuffing predicted"), "{warnings:?}");
    assert!(has("cage on its land"), "{warnings:?}");
    assert!(has("not converged (inner.converged)"), "{warnings:?}");
    assert!(has("not converged (points[0].converged)"), "{warnings:?}");
    assert!(has("not a finite number: whirl_ratio"), "{warnings:?}");
}

#[test]
fn the_scuffing_warning_follows_the_thresholds() {
    for (margin, expected) in [(1.2, Some("scuffing margin low")), (2.0, None)] {
        let dir = simulate_folder(
            &format!("margin-{margin}"),
            serde_json::json!({"min_scuffing_margin": margin, "max_cage_land_force_n": 0.0}),
        );
        let warnings = report_folder(&dir).unwrap().warnings;
        match expected {
            Some(text) => assert!(warnings.iter().any(|w| w.contains(text)), "{warnings:?}"),
            None => assert!(warnings.is_empty(), "{warnings:?}"),
        }
    }
}

#[test]
fn texts_from_the_folder_are_escaped() {
    let dir = simulate_folder(
        "escaped",
        serde_json::json!({"model": "<script>alert(1)</script>"}),
    );
    std::fs::write(dir.join("revolutions.csv"), "a<b,c\n<i>x</i>,1\n").unwrap();
    let html = std::fs::read_to_string(report_folder(&dir).unwrap().report).unwrap();
    assert!(!html.contains("<script>alert"), "{html}");
    assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
    assert!(html.contains("&lt;i&gt;x&lt;/i&gt;") && html.contains("a&lt;b"));
    assert!(html.contains("name = &quot;&lt;b&gt;&amp;&quot;"));
}

#[test]
fn a_missing_or_foreign_folder_is_refused() {
    let missing = std::env::temp_dir().join("rolldyn-report-no-such-folder");
    assert!(matches!(
        report_folder(&missing),
        Err(ReportError::Folder { .. })
    ));
    let empty = scratch("foreign");
    assert!(matches!(
        report_folder(&empty),
        Err(ReportError::Folder { .. })
    ));
}
