//! `[inner_ring.raceway_wear]`: a model file naming a wear-map CSV next to it.

use rolldyn_model::{BearingModel, DEFAULT_MODEL, RACEWAY_WEAR_HEADER};
use std::f64::consts::PI;

/// A temporary directory holding `model.toml` (the default model with a wear map on the inner
/// ring) and `wear.csv` with `csv` as its text.
fn model_dir(name: &str, csv: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("wear.csv"), csv).unwrap();
    let text = format!("{DEFAULT_MODEL}\n[inner_ring.raceway_wear]\nfile = \"wear.csv\"\n");
    std::fs::write(dir.join("model.toml"), text).unwrap();
    dir
}

#[test]
fn the_inner_ring_reads_its_wear_map() {
    // axial lines −5 and +5 mm, two bins centred at 90° and 270°
    let csv = format!("{RACEWAY_WEAR_HEADER}\n-5,90,2\n-5,270,4\n5,90,6\n5,270,8\n");
    let dir = model_dir("wear-map", &csv);
    let model = rolldyn_model::load(&dir.join("model.toml")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let BearingModel::Cylindrical(b) = model.bearing else {
        panic!("2002834 is cylindrical")
    };
    let map = b.inner_ring.raceway_wear.as_ref().unwrap();
    assert_eq!(map.angle_bins(), 2);
    assert!((map.depth(-5e-3, 0.5 * PI) - 2e-6).abs() < 1e-15);
    assert!((map.depth(0.0, 1.5 * PI) - 6e-6).abs() < 1e-15);
    // the axisymmetric reading: the circumferential mean on top of the (absent) profile
    let profile = b
        .inner_ring
        .raceway_profile
        .as_ref()
        .map_or(0.0, |p| p.drop(5e-3));
    assert!((b.inner_ring.raceway_drop(5e-3) - profile - 7e-6).abs() < 1e-15);
    assert!(b.outer_ring.raceway_wear.is_none());
}

#[test]
fn a_bad_row_names_the_file_and_the_line() {
    let csv = format!("{RACEWAY_WEAR_HEADER}\n-5,90,2\n-5,270,oops\n");
    let dir = model_dir("wear-map-bad", &csv);
    let e = rolldyn_model::load(&dir.join("model.toml")).unwrap_err();
    std::fs::remove_dir_all(&dir).unwrap();
    let line = e.to_string();
    assert_eq!(e.key, "inner_ring.raceway_wear.file");
    assert!(line.contains("wear.csv: line 3: `oops`"), "{line}");
    assert!(!line.contains('\n'), "{line}");
}
