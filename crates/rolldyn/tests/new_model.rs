//! `new`: every supported designation gives a model that loads and passes the checks (pocket
//! fit, cage inside its land and ribs, clearance implied by the raceways); the boundary form
//! with catalogue values; refusals name the input.

use rolldyn::new_model::{NewModel, NewModelRequest};
use rolldyn::{Analysis, Context, Failure};

fn request(json: &str) -> NewModelRequest {
    serde_json::from_str(json).unwrap()
}

fn new_model(json: &str) -> Result<rolldyn::new_model::NewModelResult, Failure> {
    NewModel::run(&request(json), &Context::default())
}

/// Every type (NU, NJ, NUP, N), dimension series (10, 2, 22, 3, 23) and bore code 04…40 of the
/// tables: the model written loads (rolldyn_model validates the geometry: pocket fit, cage in
/// the rings' envelope) and `check` has no design note (stated clearance = the raceways', land
/// on the rib rims, rib heights, cage width).
#[test]
fn every_supported_designation_gives_a_valid_model() {
    let mut models = 0;
    for kind in ["NU", "NJ", "NUP", "N"] {
        for series in ["10", "2", "22", "3", "23"] {
            for code in (4..=22).chain((24..=40).step_by(2)) {
                let designation = format!("{kind}{series}{code:02}");
                let json = format!(r#"{{"designation": "{designation}"}}"#);
                let result = match new_model(&json) {
                    Ok(result) => result,
                    Err(Failure::Input(e)) if e.contains("has no row") => continue,
                    Err(e) => panic!("{designation}: {e}"),
                };
                let model = rolldyn_model::parse(&result.toml, &designation).unwrap();
                let rolldyn_geometry::BearingModel::Cylindrical(bearing) = model.bearing else {
                    panic!("{designation}: not a cylindrical bearing");
                };
                let implied = bearing.geometric_clearance();
                assert!(
                    (implied - bearing.clearance.radial).abs() < 1e-9,
                    "{designation}: implied {implied} vs stated {}",
                    bearing.clearance.radial
                );
                assert!(implied > 0.0, "{designation}");
                let notes = bearing.design_notes();
                assert!(notes.is_empty(), "{designation}: {notes:?}");
                models += 1;
            }
        }
    }
    assert!(models >= 500, "{models} models");
}

#[test]
fn the_boundary_form_takes_catalogue_values_and_an_operating_point() {
    let result = new_model(
        r#"{"bore": "75 mm", "outside": "130 mm", "width": "31 mm", "roller_diameter": "15 mm",
            "roller_length": "22 mm", "rollers": 16, "cage": "brass", "speed": "5000 rpm",
            "radial_load": "15 kN", "oil_temperature": "70 C", "oil": "iso-vg-68-mineral"}"#,
    )
    .unwrap();
    assert_eq!(result.rollers, 16);
    assert_eq!(result.name, "NU75x130x31");
    assert!(result.warnings.is_empty());
    for line in [
        "inner_speed = \"5000 rpm\"",
        "radial_load = \"15000 N\"",
        "count = 16                      # given (--rollers)",
        "material = \"cuzn40pb2\"",
        "oil = \"iso-vg-68-mineral\"",
    ] {
        assert!(result.toml.contains(line), "{line}\n{}", result.toml);
    }
}

#[test]
fn a_missing_oil_temperature_is_assumed_and_warned() {
    let result =
        new_model(r#"{"designation": "NU2215", "speed": "5000 rpm", "radial_load": "15 kN"}"#)
            .unwrap();
    assert_eq!(result.warnings.len(), 2, "{:?}", result.warnings);
    assert!(result.toml.contains("ASSUMED 70 °C"));
    assert!(
        result.warnings[1].contains("no --oil"),
        "{:?}",
        result.warnings
    );
    assert!(result.toml.contains("# ESTIMATED: ASSUMED: no --oil given"));
}

#[test]
fn refusals_name_the_input() {
    for (json, expected) in [
        (r#"{"designation": "30215"}"#, "double-row-tapered"),
        (r#"{"designation": "NU2215", "bore": "75 mm"}"#, "not both"),
        (r#"{"bore": "75 mm", "outside": "130 mm"}"#, "all of --bore"),
        (
            r#"{"designation": "NU2215", "speed": "5000 rpm"}"#,
            "--radial-load",
        ),
        (
            r#"{"bore": "75 mm", "outside": "130 mm", "width": "31 mm", "roller_diameter": "30 mm"}"#,
            "--roller-diameter",
        ),
        (
            r#"{"designation": "NU2215", "rollers": 40}"#,
            "roller.count",
        ),
        (
            r#"{"designation": "NU2215", "oil": "no-such-oil"}"#,
            "no-such-oil",
        ),
    ] {
        let Err(Failure::Input(e)) = new_model(json) else {
            panic!("{json} is accepted");
        };
        assert!(e.contains(expected), "{json}: {e}");
    }
}
