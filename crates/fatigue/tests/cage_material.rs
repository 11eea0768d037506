//! The S–N curve of a fatigue run comes from the cage's material and plating (theory §10.5):
//! no silent steel default, no coating factor on an unplated cage.

use rolldyn_fatigue::cage_material::{CageMaterial, SnChoice, resolve};
use rolldyn_fatigue::mean_stress::MeanStressCorrection;
use rolldyn_fatigue::sn::SnCurve;
use rolldyn_geometry::Plating;
use rolldyn_geometry::material_database::find;

fn built_in(name: &str, plating: Option<Plating>) -> CageMaterial {
    CageMaterial {
        name: name.into(),
        fatigue: find(name).unwrap().material().fatigue,
        plating,
    }
}

#[test]
fn the_silver_plated_seed_cage_reproduces_the_seed_curve() {
    let seed = built_in("40khn2ma-sh", Some(Plating::Silver));
    let sn = resolve(
        Some(&seed),
        &SnChoice::default(),
        MeanStressCorrection::None,
    )
    .unwrap();
    assert_eq!(sn.curve, SnCurve::aisi_4340());
    assert_eq!(sn.coating_factor, 1.5);
    assert!(
        sn.coating_source.contains("cage.plating"),
        "{}",
        sn.coating_source
    );
    assert!(
        sn.curve_source.contains("seed 000 §3.1.1.8"),
        "{}",
        sn.curve_source
    );
    assert_eq!(sn.ultimate_strength_pa, Some(1172e6));
}

#[test]
fn a_brass_cage_uses_the_brass_curve_unplated() {
    let brass = built_in("cuzn40pb2", None);
    let sn = resolve(
        Some(&brass),
        &SnChoice::default(),
        MeanStressCorrection::Goodman,
    )
    .unwrap();
    let expected = find("cuzn40pb2").unwrap().sn_curve.points();
    assert_eq!(sn.curve.points(), expected.as_slice());
    assert_eq!(sn.coating_factor, 1.0);
    assert_eq!(sn.mean_stress.ultimate_strength_pa, 430e6);
    assert!(
        sn.curve_source.starts_with("cuzn40pb2"),
        "{}",
        sn.curve_source
    );
}

#[test]
fn a_coating_factor_on_an_unplated_cage_is_refused_naming_cage_plating() {
    let brass = built_in("cuzn40pb2", None);
    let choice = SnChoice {
        coating_factor: Some(1.5),
        ..SnChoice::default()
    };
    let message = resolve(Some(&brass), &choice, MeanStressCorrection::None).unwrap_err();
    assert!(message.contains("cage.plating"), "{message}");
    // on a plated cage it replaces the plating's factor and says so
    let plated = built_in("40khn2ma-sh", Some(Plating::Silver));
    let choice = SnChoice {
        coating_factor: Some(1.2),
        ..SnChoice::default()
    };
    let sn = resolve(Some(&plated), &choice, MeanStressCorrection::None).unwrap();
    assert_eq!(sn.coating_factor, 1.2);
    assert!(
        sn.coating_source.contains("--coating-factor"),
        "{}",
        sn.coating_source
    );
}

#[test]
fn a_material_without_sn_data_is_an_error_naming_its_keys() {
    let bare = CageMaterial {
        name: "my-peek".into(),
        fatigue: None,
        plating: None,
    };
    let message = resolve(
        Some(&bare),
        &SnChoice::default(),
        MeanStressCorrection::None,
    )
    .unwrap_err();
    assert!(
        message.contains("cage.material") && message.contains("[materials.my-peek]"),
        "{message}"
    );
    // a curve file stands in, but Goodman then lacks σ_u
    let choice = SnChoice {
        curve: Some((SnCurve::aisi_4340(), "--sn-curve s.csv".into())),
        ..SnChoice::default()
    };
    let sn = resolve(Some(&bare), &choice, MeanStressCorrection::None).unwrap();
    assert_eq!(sn.curve_source, "--sn-curve s.csv");
    let message = resolve(Some(&bare), &choice, MeanStressCorrection::Gerber).unwrap_err();
    assert!(message.contains("ultimate_strength"), "{message}");
}

#[test]
fn an_export_without_its_cage_material_is_refused() {
    let message = resolve(None, &SnChoice::default(), MeanStressCorrection::None).unwrap_err();
    assert!(message.contains("export"), "{message}");
}
