//! `[inner_ring.raceway_wear]`: a model file naming a wear-map CSV next to it.

use rolldyn_model::{BearingModel, DEFAULT_MODEL, RACEWAY_WEAR_HEADER};
use std::f64::consts::PI;

/// A temporary directory holding `model.toml` (the default model with a wear map on the inner
/// ring) and `wear.csv` with `csv` as its text.
fn model_dir(name: &str, csv: &str) -> std::path::PathBuf {
    model_dir_of(name, DEFAULT_MODEL, csv)
}

/// As [`model_dir`] with the model text `model`.
fn model_dir_of(name: &str, model: &str, csv: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("wear.csv"), csv).unwrap();
    let text = format!("{model}\n[inner_ring.raceway_wear]\nfile = \"wear.csv\"\n");
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

/// A roller-raceway model reads the map of its one ring, and the roller–raceway contact adds
/// the map's circumferential mean to the profile drop.
#[test]
fn a_roller_raceway_model_reads_its_map_into_the_contact() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/contact/32206-straight.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let csv = format!("{RACEWAY_WEAR_HEADER}\n0,90,1\n0,270,3\n");
    let dir = model_dir_of("wear-map-pair", &text, &csv);
    let worn = rolldyn_model::load(&dir.join("model.toml")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let unworn = rolldyn_model::parse(&text, path).unwrap();
    let contact = |m: &rolldyn_model::Model| {
        rolldyn_contact::roller_raceway::RollerRacewayContact::from_model(&m.bearing, true, 0.0)
            .unwrap()
    };
    let (a, b) = (contact(&unworn), contact(&worn));
    for x in [-4e-3, 0.0, 3e-3] {
        assert!(
            (b.profile_drop(x) - a.profile_drop(x) - 2e-6).abs() < 1e-15,
            "{x}"
        );
    }
}
