//! Bad model files give one-line errors naming the file, line, key and reason.

use rolldyn_model::parse;

const GOOD: &str = rolldyn_model::DEFAULT_MODEL;

/// Replaces the first occurrence of `from` in the default model and returns the error text.
fn error_after(from: &str, to: &str) -> String {
    assert!(
        GOOD.contains(from),
        "test setup: '{from}' not in the default model"
    );
    let text = GOOD.replacen(from, to, 1);
    let err = parse(&text, "bad.toml").expect_err("must be rejected");
    let message = err.to_string();
    assert!(!message.contains('\n'), "one line expected: {message}");
    assert!(message.starts_with("bad.toml:"), "{message}");
    message
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).unwrap() + 1
}

#[test]
fn unknown_key() {
    let m = error_after("slices = 10", "slices = 10\ncolour = \"red\"");
    assert!(
        m.contains("roller.colour") && m.contains("unknown key"),
        "{m}"
    );
    let line = line_of(
        &GOOD.replacen("slices = 10", "slices = 10\ncolour = \"red\"", 1),
        "colour",
    );
    assert!(m.contains(&format!("bad.toml:{line}:")), "{m}");
}

#[test]
fn wrong_unit_dimension() {
    let m = error_after("diameter = \"15 mm\"", "diameter = \"15 N\"");
    assert!(
        m.contains("roller.diameter") && m.contains("a force") && m.contains("a length"),
        "{m}"
    );
}

#[test]
fn unknown_unit() {
    let m = error_after("width = \"24 mm\"", "width = \"24 furlongs\"");
    assert!(
        m.contains("inner_ring.width") && m.contains("unknown unit"),
        "{m}"
    );
}

#[test]
fn missing_key() {
    let m = error_after("diameter = \"15 mm\"\n", "");
    assert!(
        m.contains("roller") && m.contains("missing key") && m.contains("diameter"),
        "{m}"
    );
}

#[test]
fn nan_and_negative_sizes() {
    let m = error_after("length = \"11 mm\"", "length = nan");
    assert!(m.contains("roller.length") && m.contains("finite"), "{m}");
    let m = error_after("length = \"11 mm\"", "length = \"-11 mm\"");
    assert!(m.contains("roller.length") && m.contains("positive"), "{m}");
}

#[test]
fn rollers_overlapping_on_the_pitch_circle() {
    let m = error_after("count = 18", "count = 40");
    assert!(
        m.contains("roller.count") && m.contains("overlap") && m.contains("at most 37"),
        "{m}"
    );
}

#[test]
fn roller_longer_than_the_space_between_ribs() {
    let m = error_after("rib_spacing = \"11.0505 mm\"", "rib_spacing = \"10.9 mm\"");
    assert!(
        m.contains("inner_ring.rib_spacing") && m.contains("longer than the space between ribs"),
        "{m}"
    );
}

#[test]
fn cage_pocket_smaller_than_the_roller() {
    let m = error_after("pocket_axial = \"11.25 mm\"", "pocket_axial = \"10 mm\"");
    assert!(
        m.contains("cage.pocket_axial") && m.contains("not longer than the roller"),
        "{m}"
    );
    let m = error_after("window = \"11.25 mm\"", "window = \"8 mm\"");
    assert!(
        m.contains("cage.pocket.outer_lip.window") && m.contains("does not fit its pocket"),
        "{m}"
    );
}

#[test]
fn negative_clearance_needs_preload_marking() {
    let m = error_after("radial = \"0.009 mm\"", "radial = \"-0.006 mm\"");
    assert!(
        m.contains("clearance.radial") && m.contains("preload"),
        "{m}"
    );
    let marked = GOOD.replacen(
        "radial = \"0.009 mm\"",
        "radial = \"-0.006 mm\"\npreload = true",
        1,
    );
    parse(&marked, "ok.toml").expect("a marked preload is accepted");
    let m = error_after(
        "radial = \"0.009 mm\"",
        "radial = \"-0.1 mm\"\npreload = true",
    );
    assert!(m.contains("interference"), "{m}");
}

#[test]
fn crown_drop_larger_than_the_roller_radius() {
    let m = error_after("drop = \"0.011 mm\"", "drop = \"8 mm\"");
    assert!(
        m.contains("roller.profile.drop") && m.contains("larger than the roller radius"),
        "{m}"
    );
}

#[test]
fn rollers_that_do_not_fit_between_raceways() {
    let m = error_after(
        "raceway_diameter = \"195 mm\"",
        "raceway_diameter = \"200 mm\"",
    );
    assert!(
        m.contains("roller.diameter") && m.contains("do not fit"),
        "{m}"
    );
}

#[test]
fn unknown_material_lists_known_ones() {
    let m = error_after("material = \"cage-steel\"", "material = \"unobtainium\"");
    assert!(
        m.contains("cage.material") && m.contains("bearing-steel") && m.contains("cage-steel"),
        "{m}"
    );
}

#[test]
fn syntax_error_has_a_position() {
    let err = parse("[bearing\nname = 1", "broken.toml").unwrap_err();
    assert!(err.to_string().starts_with("broken.toml:1:"), "{err}");
}

#[test]
fn wrong_profile_kind_is_named() {
    let m = error_after("kind = \"crowned\"", "kind = \"banana\"");
    assert!(m.contains("roller.profile") && m.contains("banana"), "{m}");
}

#[test]
fn lubricant_errors_name_the_key() {
    let m = error_after("oil = \"vnii-np-50-1-4u\"", "oil = \"castor\"");
    assert!(
        m.contains("lubricant.oil") && m.contains("pao1-vg320"),
        "{m}"
    );
    let m = error_after("density = \"930 kg/m3\"", "density = \"-930 kg/m3\"");
    assert!(m.contains("lubricant") && m.contains("density"), "{m}");
    let m = error_after("radial_load = \"1600 N\"", "radial_load = \"1000 mm\"");
    assert!(m.contains("operating.radial_load"), "{m}");
}
