//! Unit parsing: every spelling the model files and CLI flags promise.

use rolldyn_units::*;

fn si<D: Dim>(text: &str) -> f64 {
    Quantity::<D>::parse(text)
        .unwrap_or_else(|e| panic!("{text}: {e}"))
        .si()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1e-300)
}

#[test]
fn issue_examples_parse_to_si() {
    assert!(close(si::<Length>("165 mm"), 0.165));
    assert!(close(si::<Length>("15 µm"), 15e-6));
    assert!(close(si::<Length>("15 μm"), 15e-6)); // Greek mu as well as the micro sign
    assert!(close(si::<Length>("15 um"), 15e-6));
    assert!(close(
        si::<AngularSpeed>("6371 rpm"),
        6371.0 * std::f64::consts::PI / 30.0
    ));
    assert!(close(si::<Angle>("4 arcmin"), 4.0 * ARCMIN));
    assert!(close(si::<Angle>("4′"), 4.0 * ARCMIN));
    assert!(close(si::<Temperature>("100 °C"), 373.15));
    assert!(close(si::<Temperature>("100 C"), 373.15));
    assert!(close(si::<Temperature>("-20 degC"), 253.15));
    assert!(close(si::<Force>("1167 N"), 1167.0));
    assert!(close(si::<Pressure>("1 GPa"), 1e9));
    assert!(close(si::<Speed>("2.5 m/s"), 2.5));
    assert!(close(si::<DynamicViscosity>("0.024 Pa s"), 0.024));
    assert!(close(si::<DynamicViscosity>("0.05Pas"), 0.05));
    assert!(close(si::<DynamicViscosity>("24 mPa·s"), 0.024));
    assert!(close(si::<KinematicViscosity>("320 cSt"), 320e-6));
    assert!(close(si::<KinematicViscosity>("320 mm²/s"), 320e-6));
    assert!(close(
        si::<RotationalDamping>("0.662 N·mm/(rad/ms)"),
        6.62e-7
    ));
}

#[test]
fn no_space_and_exponents() {
    assert!(close(si::<Pressure>("1GPa"), 1e9));
    assert!(close(si::<Length>("1.5e-3m"), 1.5e-3));
    assert!(close(si::<Length>("2E2 um"), 2e-4));
    assert!(close(si::<Length>("-0.006 mm"), -6e-6));
}

#[test]
fn plain_numbers_are_si_and_a_text_needs_its_unit() {
    assert!(close(si::<Dimensionless>("0.3"), 0.3));
    for (bare, example) in [("15", "15 kN"), ("5000", "5000 rpm"), ("300", "300 C")] {
        let err = match example.split_once(' ').unwrap().1 {
            "kN" => Quantity::<Force>::parse(bare).map(|_| ()),
            "rpm" => Quantity::<AngularSpeed>::parse(bare).map(|_| ()),
            _ => Quantity::<Temperature>::parse(bare).map(|_| ()),
        }
        .unwrap_err();
        assert!(matches!(err, UnitError::MissingUnit { .. }), "{err}");
        assert!(err.to_string().contains(example), "{err}");
    }
    let parsed: std::collections::BTreeMap<String, Quantity<Length>> =
        toml::from_str("a = 0.01\nb = 2\nc = \"3 mm\"").unwrap();
    assert!(close(parsed["a"].si(), 0.01));
    assert!(close(parsed["b"].si(), 2.0));
    assert!(close(parsed["c"].si(), 0.003));
}

#[test]
fn wrong_dimension_is_an_error() {
    let err = Quantity::<Force>::parse("10 mm").unwrap_err();
    assert!(matches!(err, UnitError::WrongDimension { .. }), "{err}");
    assert!(err.to_string().contains("a length"), "{err}");
    assert!(err.to_string().contains("a force"), "{err}");
}

#[test]
fn garbage_is_an_error() {
    assert!(Quantity::<Length>::parse("").is_err());
    assert!(Quantity::<Length>::parse("mm").is_err());
    assert!(Quantity::<Length>::parse("12 furlongs").is_err());
    assert!(Quantity::<Length>::parse("NaN mm").is_err());
    assert!(Quantity::<Length>::parse("inf").is_err());
    let nan: Result<std::collections::BTreeMap<String, Quantity<Length>>, _> =
        toml::from_str("a = nan");
    assert!(nan.is_err());
}

#[test]
fn ranges() {
    let r: QuantityRange<AngularSpeed> = "1500rpm..4500rpm:500rpm".parse().unwrap();
    assert_eq!(r.values.len(), 7);
    assert!(close(r.values[6].si(), 4500.0 * RPM));
    let r: QuantityRange<Temperature> = "40C,50C,60C".parse().unwrap();
    assert_eq!(r.values.len(), 3);
    assert!("1..2".parse::<QuantityRange<Force>>().is_err());
}

#[test]
fn reversed_ranges_and_negative_steps_are_refused() {
    for text in ["700N..100N:50N", "100N..700N:-50N", "700N..100N:-50N"] {
        let err = text
            .parse::<QuantityRange<Force>>()
            .unwrap_err()
            .to_string();
        assert!(err.contains(text), "{err}");
    }
}

#[test]
fn a_temperature_step_is_a_difference() {
    // 10C as a step is 10 K, not 283.15 K (which gave one point only)
    let r: QuantityRange<Temperature> = "40C..80C:10C".parse().unwrap();
    assert_eq!(r.values.len(), 5);
    assert!(close(r.values[4].si(), 353.15));
}

#[test]
fn temperatures_below_absolute_zero_are_refused() {
    for text in ["-300C", "-1 K", "-273.16 degC"] {
        let err = text
            .parse::<Quantity<Temperature>>()
            .unwrap_err()
            .to_string();
        assert!(err.contains("absolute zero"), "{text}: {err}");
    }
    assert!(si::<Temperature>("-273.15 C").abs() < 1e-9);
}
