//! Issue 22 item 6: errors found after loading name the file and key (or the flag) at fault,
//! like load-time errors, and blame the input that is wrong.

use rolldyn_setup::quasi_static::{QuasiStaticOverrides, quasi_static_conditions};
use rolldyn_setup::{Overrides, conditions};

fn model(text: &str) -> rolldyn_model::Model {
    rolldyn_model::parse(text, "m.toml").expect("a valid model")
}

fn default_model() -> rolldyn_model::Model {
    model(rolldyn_model::DEFAULT_MODEL)
}

#[test]
fn a_bad_oil_temperature_blames_the_oil_temperature() {
    let overrides = Overrides {
        oil_temperature: Some(-26.85),
        ..Overrides::default()
    };
    let m = conditions(&overrides, &default_model()).unwrap_err().0;
    assert!(m.starts_with("--oil-temperature:"), "{m}");
    assert!(!m.contains("--radial-load"), "{m}");
}

#[test]
fn absurd_speed_overrides_name_the_flag() {
    let overrides = Overrides {
        speed: Some(1e30),
        ..Overrides::default()
    };
    let m = conditions(&overrides, &default_model()).unwrap_err().0;
    assert!(m.starts_with("--speed:"), "{m}");
    let overrides = QuasiStaticOverrides {
        outer_speed: Some(-1e30),
        ..QuasiStaticOverrides::default()
    };
    let m = quasi_static_conditions(&default_model(), &overrides)
        .unwrap_err()
        .0;
    assert!(m.starts_with("--outer-speed:"), "{m}");
}

#[test]
fn a_missing_oil_property_names_the_file_and_the_lubricant() {
    let text = rolldyn_model::DEFAULT_MODEL.replacen(
        "density = \"930 kg/m3\"                 # ASSUMED",
        "",
        1,
    );
    let model = model(&text);
    let line = text.lines().position(|l| l == "[lubricant]").unwrap() + 1;
    let m = quasi_static_conditions(&model, &QuasiStaticOverrides::default())
        .unwrap_err()
        .0;
    assert!(m.starts_with(&format!("m.toml:{line}:")), "{m}");
    assert!(m.contains("lubricant — ") && m.contains("density"), "{m}");
    let Err(e) = rolldyn_setup::prepare(&model, &Overrides::default(), 1e-4, None) else {
        panic!("an oil without density sets up");
    };
    let m = e.0;
    assert!(m.starts_with(&format!("m.toml:{line}:")), "{m}");
}

#[test]
fn a_missing_operating_value_names_the_file_and_key() {
    let text = rolldyn_model::DEFAULT_MODEL.replacen("inner_speed = \"8163 rpm\"", "", 1);
    let m = conditions(&Overrides::default(), &model(&text))
        .unwrap_err()
        .0;
    assert!(
        m.starts_with("m.toml:") && m.contains("operating.inner_speed — "),
        "{m}"
    );
}
