//! Every example model loads and validates; derived quantities are what the seeds imply.

use rolldyn_model::{BearingModel, load, parse};
use std::path::{Path, PathBuf};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

#[test]
fn every_example_loads() {
    let mut paths = vec![];
    for dir in [examples(), examples().join("contact")] {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            // sweep files (a `[[variant]]` table) are read by the sweep crate's tests
            let sweep = std::fs::read_to_string(&path).is_ok_and(|t| t.contains("[[variant]]"));
            if path.extension().is_some_and(|e| e == "toml") && !sweep {
                paths.push(path);
            }
        }
    }
    assert!(paths.len() >= 8, "{paths:?}");
    for path in paths {
        load(&path).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn default_model_is_2002834_per_spec_f02() {
    let BearingModel::Cylindrical(b) = parse(rolldyn_model::DEFAULT_MODEL, "default")
        .unwrap()
        .bearing
    else {
        panic!("cylindrical expected")
    };
    // SPEC F-02: d_m = 180 mm, zero geometric clearance, operating clearance from Table 3.1.
    assert!((b.pitch_diameter() - 0.180).abs() < 1e-12);
    assert!(b.geometric_clearance().abs() < 1e-12);
    assert!((b.clearance.radial - 9e-6).abs() < 1e-15);
    assert!((b.roller_rib_axial_clearance().unwrap() - 0.0505e-3).abs() < 1e-12);
    // Epicyclic cage speed at 6371 rpm on the rolling diameters d_i = 165 mm and
    // D_o = d_i + 2 D_w + G_r = 195.009 mm: ω_i d_i/(d_i + D_o) = 305.79 rad/s (the
    // pitch-diameter form ω_i/2 (1 − 15/180) = 305.80 rad/s ignores the 9 µm clearance).
    let wi = 6371.0 * std::f64::consts::PI / 30.0;
    let expected = wi * 0.165 / (0.165 + 0.195009);
    assert!((b.epicyclic_cage_speed(wi, 0.0) - expected).abs() < 1e-9);
    // Guiding land from the cage bore and floating clearance.
    let land = b.inner_ring.guiding_land.unwrap();
    assert!((land.diameter - 0.173).abs() < 1e-12);
}

#[test]
fn roller_mass_matches_a_cylinder_within_the_chamfer_loss() {
    let BearingModel::Cylindrical(b) = parse(rolldyn_model::DEFAULT_MODEL, "default")
        .unwrap()
        .bearing
    else {
        panic!()
    };
    let r = &b.roller;
    let cylinder = 7830.0 * std::f64::consts::PI * 0.0075f64.powi(2) * 0.011;
    let m = r.mass_properties.mass;
    // Chamfers 0.5 mm × 0.6 mm arcs remove ≈ 2–4 % of a 15 × 11 mm roller.
    assert!(m < cylinder && m > 0.95 * cylinder, "{m} vs {cylinder}");
    let ia = r.mass_properties.axial_inertia;
    assert!((ia / (0.5 * m * 0.0075f64.powi(2)) - 1.0).abs() < 0.03);
}

#[test]
fn contact_examples_have_the_seed004_profiles() {
    let drop_at = |name: &str, x: f64| {
        let m = load(&examples().join("contact").join(name)).unwrap();
        m.bearing
            .roller()
            .expect("a cylindrical roller")
            .profile
            .drop(x)
    };
    assert_eq!(drop_at("32206-straight.toml", 3.7e-3), 0.0);
    assert!((drop_at("32206-crowned-3.2um.toml", 3.25e-3) - 3.2e-6).abs() < 1e-12);
    assert!((drop_at("32206-crowned-6.5um.toml", 3.25e-3) - 6.5e-6).abs() < 1e-12);
    assert!((drop_at("32206-log-small.toml", 3.25e-3) - 2.05e-6).abs() < 0.01e-6);
    assert!((drop_at("32206-log-large.toml", 3.25e-3) - 10.3e-6).abs() < 0.05e-6);
}

#[test]
fn operating_and_lubricant_sections() {
    let m = load(&examples().join("obrien-taylor.toml")).unwrap();
    let op = m.operating;
    assert!((op.inner_speed.unwrap() - 4000.0 * std::f64::consts::PI / 30.0).abs() < 1e-9);
    assert_eq!(op.radial_load, Some(201.0));
    assert!(!op.load_rotates);
    assert!((op.temperatures.oil.unwrap() - 327.65).abs() < 1e-9);
    let lub = m.lubrication.unwrap();
    assert_eq!(lub.oil.name, "nvi65");
    lub.traction_model()
        .expect("NVI 65 with the linear-elastic law is complete");
    // 2002834: the seed's VNII NP 50-1-4u completed by the ASSUMED data-sheet values.
    let m = parse(rolldyn_model::DEFAULT_MODEL, "default").unwrap();
    assert!(m.operating.load_rotates);
    let oil = m.lubrication.unwrap().oil;
    let nu = oil.kinematic_viscosity(373.15).unwrap();
    assert!((nu / 3.2e-6 - 1.0).abs() < 1e-9, "{nu}");
}

/// The Johns–Gohar and polyline profile families load from a model file: the Johns–Gohar crown
/// grows monotonically toward the ends (design load 2 kN on the 32206 contact), the polyline is
/// interpolated linearly and may be asymmetric (worn profile).
#[test]
fn johns_gohar_and_polyline_profiles() {
    let base = std::fs::read_to_string(examples().join("contact/32206-straight.toml")).unwrap();
    let jg = base.replace(
        "kind = \"straight\"",
        "kind = \"johns-gohar\"\ndesign_load = \"2 kN\"\nchamfer = { axial = \"0.5 mm\", radial = \"0.5 mm\", radius = \"0.6 mm\" }",
    );
    let m = parse(&jg, "jg.toml").unwrap_or_else(|e| panic!("{e}"));
    let p = &m.bearing.roller().expect("a cylindrical roller").profile;
    let (z1, z2, z3) = (p.drop(1e-3), p.drop(2.5e-3), p.drop(3.2e-3));
    assert!(
        0.0 < z1 && z1 < z2 && z2 < z3 && z3 < 20e-6,
        "{z1} {z2} {z3}"
    );
    assert!((p.drop(-2.5e-3) - z2).abs() < 1e-15, "symmetric");
    let poly = base.replace(
        "kind = \"straight\"",
        "kind = \"polyline\"\nx = [\"-3.75 mm\", \"0 mm\", \"3.75 mm\"]\ndrop = [\"4 um\", \"0 um\", \"1 um\"]",
    );
    let m = parse(&poly, "poly.toml").unwrap_or_else(|e| panic!("{e}"));
    let p = &m.bearing.roller().expect("a cylindrical roller").profile;
    assert!((p.drop(-1.875e-3) - 2e-6).abs() < 1e-15 && (p.drop(1.875e-3) - 0.5e-6).abs() < 1e-15);
    let bad = base.replace(
        "kind = \"straight\"",
        "kind = \"polyline\"\nx = [\"1 mm\", \"0 mm\"]\ndrop = [\"1 um\", \"0 um\"]",
    );
    let e = parse(&bad, "bad.toml").unwrap_err().to_string();
    assert!(
        e.contains("roller.profile.x[1]") && e.contains("increase"),
        "{e}"
    );
}
