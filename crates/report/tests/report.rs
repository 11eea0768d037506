//! The report of hand-made output folders: kind inference, warnings and their thresholds,
//! escaping of the folder's texts.

use rolldyn_report::{Level, ReportError, RunKind, RunManifest, report_folder};
use std::path::{Path, PathBuf};

/// A fresh scratch folder, removed when dropped.
struct Scratch(PathBuf);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn scratch(name: &str) -> Scratch {
    let dir = std::env::temp_dir().join(format!("rolldyn-report-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    Scratch(dir)
}

const PLOT: &str = "<?xml version=\"1.0\"?>\n<svg width=\"10\" height=\"10\" \
                    xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"5\" height=\"5\"/></svg>";

fn simulate_folder(name: &str, summary: serde_json::Value) -> Scratch {
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
        files: None,
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
    let written = report_folder(&dir).unwrap();
    let warnings = written.warnings;
    let has = |text: &str| warnings.iter().any(|w| w.contains(text));
    assert!(has("scuffing predicted"), "{warnings:?}");
    assert!(has("not converged (inner.converged)"), "{warnings:?}");
    assert!(has("not converged (points[0].converged)"), "{warnings:?}");
    // a value the run did not define (no whirl) is no warning; the land contact of a cage
    // without roller–cage force to compare with is a note
    assert!(!has("whirl_ratio"), "{warnings:?}");
    let level_of = |text: &str| {
        written
            .findings
            .iter()
            .find(|f| f.text.contains(text))
            .map(|f| f.level)
    };
    assert_eq!(level_of("scuffing predicted"), Some(Level::Error));
    assert_eq!(level_of("guiding land"), Some(Level::Note));
    let html = std::fs::read_to_string(&written.report).unwrap();
    assert!(html.contains("class=\"finding error\""), "{html}");
    assert!(html.find("id=\"headline\"") < html.find("id=\"warnings\""));
}

/// A land-guided cage on its land is a note; pressed on it harder than its rollers drive it, a
/// warning; a diverged value is an error; a healthy run shows neither error nor warning box.
#[test]
fn findings_have_levels_that_fit_the_bearing() {
    let healthy = simulate_folder(
        "healthy",
        serde_json::json!({
            "model": "2002834",
            "cage_slip_mean": -0.0031,
            "min_scuffing_margin": null,
            "max_cage_land_force_n": 28.5,
            "max_roller_cage_force_n": 224.0,
            "whirl_ratio": null,
            "non_finite": {
                "min_scuffing_margin": "no scuffing-margin maximum in the run",
                "whirl_ratio": "the cage centre does not orbit (no whirl)"
            }
        }),
    );
    let written = report_folder(&healthy).unwrap();
    assert!(written.warnings.is_empty(), "{:?}", written.warnings);
    assert!(
        written
            .findings
            .iter()
            .any(|f| f.level == Level::Note && f.text.contains("guiding land"))
    );
    let html = std::fs::read_to_string(&written.report).unwrap();
    assert!(
        !html.contains("finding error") && !html.contains("finding warning"),
        "{html}"
    );
    assert!(html.contains("class=\"finding note\""));
    assert!(
        html.contains("-0.003100"),
        "slip shown as the fraction it is: {html}"
    );
    assert!(html.contains("(the cage centre does not orbit (no whirl))"));

    let pressed = simulate_folder(
        "pressed",
        serde_json::json!({
            "max_cage_land_force_n": 300.0,
            "max_roller_cage_force_n": 100.0,
            "max_inner_contact_force_n": null,
            "non_finite": {"max_inner_contact_force_n": "diverged"}
        }),
    );
    let written = report_folder(&pressed).unwrap();
    let level_of = |text: &str| {
        written
            .findings
            .iter()
            .find(|f| f.text.contains(text))
            .map(|f| f.level)
    };
    assert_eq!(level_of("pressed on its land"), Some(Level::Warning));
    let undriven = simulate_folder(
        "undriven",
        serde_json::json!({"max_cage_land_force_n": 160.0, "max_roller_cage_force_n": 0.0}),
    );
    let written = report_folder(&undriven).unwrap();
    assert!(written.warnings.is_empty(), "{:?}", written.warnings);
    assert_eq!(level_of("max_inner_contact_force_n"), Some(Level::Error));
}

/// The sweep table carries the varied parameters first (the answer's `varied` list), marked.
#[test]
fn the_sweep_table_leads_with_the_varied_parameters() {
    let dir = scratch("sweep");
    std::fs::create_dir_all(dir.join("variants")).unwrap();
    std::fs::write(
        dir.join("summary.csv"),
        "variant,index,cage_slip_mean,roller.count,error\nn18,0,0.01,18,\nn24,1,0.02,24,\n",
    )
    .unwrap();
    RunManifest {
        kind: RunKind::Sweep,
        rolldyn_version: "0.1.0".into(),
        command: vec!["rolldyn".into(), "sweep".into()],
        model_file: Some("sweep.toml".into()),
        model_text: None,
        overrides: Default::default(),
        summary: serde_json::json!({"variants": 2, "varied": ["roller.count"]}),
        files: None,
    }
    .write(&dir)
    .unwrap();
    let written = report_folder(&dir).unwrap();
    assert!(written.warnings.is_empty(), "{:?}", written.warnings);
    let html = std::fs::read_to_string(&written.report).unwrap();
    let table = &html[html.find("id=\"variants-table\"").unwrap()..];
    let header = &table[..table.find("</thead>").unwrap()];
    let variant = header.find(">variant<").unwrap();
    let varied = header
        .find("class=\"varied\" title=\"sort by roller.count\"")
        .unwrap();
    let slip = header.find(">cage_slip_mean<").unwrap();
    assert!(variant < varied && varied < slip, "{header}");
    assert!(html.contains("roller.count"));
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

/// An SVG that can run code in the reader's browser.
const HOSTILE: &str = "<svg xmlns=\"http://www.w3.org/2000/svg\" onload=\"alert(1)\">\
                       <script>alert(2)</script><foreignObject><iframe src=\"https://example.org\">\
                       </iframe></foreignObject></svg>";

/// Nothing of `HOSTILE` reached the page.
fn assert_no_hostile_markup(html: &str) {
    for hostile in ["<script>alert", "onload=", "<iframe", "foreignObject"] {
        assert!(!html.contains(hostile), "{hostile} in the report");
    }
}

#[test]
fn n5_only_the_svg_files_run_json_lists_unchanged_are_inlined() {
    let dir = simulate_folder("hostile", serde_json::json!({"model": "2002834"}));
    std::fs::write(dir.join("load_zone.svg"), PLOT).unwrap();
    let mut manifest = RunManifest::read(&dir).unwrap().unwrap();
    manifest.files = Some(rolldyn_report::plot_checksums(&dir).unwrap());
    manifest.write(&dir).unwrap();
    std::fs::write(dir.join("cage_slip.svg"), HOSTILE).unwrap();
    std::fs::write(dir.join("added.svg"), HOSTILE).unwrap();
    let written = report_folder(&dir).unwrap();
    let html = std::fs::read_to_string(&written.report).unwrap();
    assert_no_hostile_markup(&html);
    assert!(
        html.contains("<svg width=\"10\""),
        "the listed plot is shown"
    );
    let has = |text: &str| written.warnings.iter().any(|w| w.contains(text));
    assert!(
        has("plot cage_slip.svg not shown: changed since the run wrote it"),
        "{:?}",
        written.warnings
    );
    assert!(
        has("plot added.svg not shown: not written by the run"),
        "{:?}",
        written.warnings
    );
}

#[test]
fn n5_without_a_manifest_only_plain_drawings_are_inlined() {
    let dir = scratch("hostile-old");
    std::fs::write(dir.join("periods.csv"), "period,time_h\n1,1905\n").unwrap();
    std::fs::write(dir.join("rates.svg"), PLOT).unwrap();
    std::fs::write(dir.join("hostile.svg"), HOSTILE).unwrap();
    let written = report_folder(&dir).unwrap();
    let html = std::fs::read_to_string(&written.report).unwrap();
    assert_no_hostile_markup(&html);
    assert!(
        html.contains("<svg width=\"10\""),
        "the plain plot is shown"
    );
    assert!(
        written
            .warnings
            .iter()
            .any(|w| w.contains("plot hostile.svg not shown: not a plain drawing")),
        "{:?}",
        written.warnings
    );
}
