//! The double-row tapered bearing model file (docs/model-format.md "Double-row tapered bearing").

use rolldyn_model::{BearingModel, parse};
use std::path::Path;

const ARCMIN: f64 = std::f64::consts::PI / 10_800.0;

/// The example's path: its oil file is named relative to it.
fn example_path() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/tapered-cassette.toml")
        .display()
        .to_string()
}

fn example_text() -> String {
    std::fs::read_to_string(example_path()).unwrap()
}

#[test]
fn the_cassette_example_reads_as_the_seed_bearing() {
    let model = parse(&example_text(), &example_path()).unwrap_or_else(|e| panic!("{e}"));
    let BearingModel::Tapered(b) = &model.bearing else {
        panic!("not a tapered bearing");
    };
    assert_eq!(b.rollers_per_row, 23);
    assert!((b.roller.half_angle - 53.0 * ARCMIN).abs() < 1e-15);
    assert!((b.roller.mean_diameter - 21.4e-3).abs() < 1e-15);
    assert!((b.axial_clearance - 0.34e-3).abs() < 1e-15);
    assert!((b.roller_axis_angle().to_degrees() - 8.285).abs() < 1e-3);
    assert!(b.apex_mismatch() < 1e-12);
    assert!(b.cage.mass > 0.05 && b.cage.mass < 0.3, "{}", b.cage.mass);
    assert_eq!(model.operating.radial_load, Some(118_862.0));
    assert_eq!(model.operating.axial_load, Some(0.0));
    let w = model.operating.inner_speed.unwrap();
    assert!((w - 663.0 * std::f64::consts::PI / 30.0).abs() < 1e-12);
    assert_eq!(
        model.lubrication.unwrap().oil.name,
        "vg220-mineral-grease-base"
    );
}

/// Bad input names the file, the line and the key.
#[test]
fn errors_point_at_the_key() {
    let text = example_text();
    let cases = [
        (
            "face = \"conical\"",
            "face = \"concave\"",
            "large_rib.face_radius",
        ),
        (
            "rollers_per_row = 23",
            "rollers_per_row = 31",
            "bearing.rollers_per_row",
        ),
        (
            "half_angle = \"53 arcmin\"",
            "half_angle = \"-53 arcmin\"",
            "roller.half_angle",
        ),
        (
            "gap = \"0.3 mm\"",
            "gap = \"0.3 mm\"\nwidth = \"1 mm\"",
            "small_rib.width",
        ),
        (
            "height = \"5.5 mm\"",
            "height = \"30 mm\"",
            "large_rib.height",
        ),
    ];
    for (from, to, key) in cases {
        assert!(text.contains(from), "{from}");
        let bad = text.replacen(from, to, 1);
        let e = parse(&bad, "bad.toml").unwrap_err();
        assert_eq!(e.key, key, "{e}");
        let shown = e.to_string();
        assert!(shown.starts_with("bad.toml:"), "{shown}");
        if key != "large_rib.face_radius" {
            assert!(e.position.is_some(), "{shown}");
        }
    }
}

#[test]
fn keys_the_tapered_dynamics_does_not_read_are_refused() {
    let cases = [
        (
            format!("{}\n[dynamics]\ncage_drag = 0.001\n", example_text()),
            "dynamics",
        ),
        (
            example_text().replace("outer_speed = \"0 rpm\"", "outer_speed = \"100 rpm\""),
            "operating.outer_speed",
        ),
    ];
    for (text, key) in cases {
        let e = parse(&text, &example_path()).unwrap_err().to_string();
        assert!(e.contains(key), "{e}");
    }
}
