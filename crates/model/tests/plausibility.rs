//! Issue 22 items 5–7: absurd values are rejected with the key at fault, errors blame the value
//! that is wrong, quote bad values briefly, and oversized files are refused.

use rolldyn_model::{MAX_INPUT_FILE_BYTES, load, parse};

const GOOD: &str = rolldyn_model::DEFAULT_MODEL;

/// The error of the default model with the `nth` occurrence of `from` replaced by `to`.
fn error_after(from: &str, nth: usize, to: &str) -> String {
    let at = GOOD
        .match_indices(from)
        .nth(nth)
        .unwrap_or_else(|| panic!("test setup: '{from}' #{nth} not in the default model"))
        .0;
    let text = format!("{}{to}{}", &GOOD[..at], &GOOD[at + from.len()..]);
    let message = parse(&text, "bad.toml")
        .expect_err("must be rejected")
        .to_string();
    assert!(message.starts_with("bad.toml:"), "{message}");
    message
}

fn assert_blames(message: &str, key: &str) {
    assert!(message.contains(&format!(" {key} — ")), "{message}");
}

#[test]
fn an_absurd_cage_width_is_rejected() {
    // [cage] width is the third `width = "20 mm"` (after inner_ring 24 mm and outer_ring 20 mm)
    let m = error_after(
        r#"width = "20 mm"                 # ASSUMED"#,
        1,
        r#"width = "1e308 mm""#,
    );
    assert_blames(&m, "cage.width");
}

#[test]
fn absurd_dimensions_masses_and_roughness_are_rejected() {
    for (from, to, key) in [
        (
            r#"width = "24 mm""#,
            r#"width = "1e6 mm""#,
            "inner_ring.width",
        ),
        (
            r#"width = "20 mm""#,
            r#"width = "1e6 mm""#,
            "outer_ring.width",
        ),
        (
            r#"outer_diameter = "194 mm""#,
            r#"outer_diameter = "1e5 mm""#,
            "cage.outer_diameter",
        ),
        (
            r#"roughness_ra = "0.16 um""#,
            r#"roughness_ra = "1 mm""#,
            "roller.roughness_ra",
        ),
        (
            r#"density = "7830 kg/m3""#,
            r#"density = "1e30 kg/m3""#,
            "materials.roller-steel.density",
        ),
        (
            r#"youngs_modulus = "211 GPa""#,
            r#"youngs_modulus = "1e-3 Pa""#,
            "materials.cage-steel.youngs_modulus",
        ),
    ] {
        assert_blames(&error_after(from, 0, to), key);
    }
    let with_mass = GOOD.replacen(
        "[cage]\n",
        "[cage]\nmass_properties = { mass = \"1e6 kg\" }\n",
        1,
    );
    let m = parse(&with_mass, "bad.toml").unwrap_err().to_string();
    assert_blames(&m, "cage.mass_properties.mass");
}

#[test]
fn a_third_rib_is_rejected() {
    let text = GOOD.replacen(
        "[inner_ring.guiding_land]",
        "[[inner_ring.ribs]]\nside = \"left\"\ndiameter = \"173 mm\"\nface = { kind = \"flat\" }\n\n[inner_ring.guiding_land]",
        1,
    );
    let m = parse(&text, "bad.toml").unwrap_err().to_string();
    assert_blames(&m, "inner_ring.ribs[2].side");
}

#[test]
fn absurd_speeds_and_temperatures_are_rejected_at_load() {
    let m = error_after(
        r#"inner_speed = "8163 rpm""#,
        0,
        r#"inner_speed = "1e30 rpm""#,
    );
    assert_blames(&m, "operating.inner_speed");
    let m = error_after(
        r#"temperatures = { oil = "100 C" }"#,
        0,
        r#"temperatures = { oil = "5000 C" }"#,
    );
    assert_blames(&m, "operating.temperatures.oil");
}

#[test]
fn a_zero_roller_diameter_blames_the_roller() {
    let m = error_after(r#"diameter = "15 mm""#, 0, r#"diameter = "0 mm""#);
    assert_blames(&m, "roller.diameter");
}

#[test]
fn a_huge_bad_value_is_quoted_briefly() {
    let huge = format!(r#"radial = "{} mm""#, "9".repeat(100_000));
    let m = error_after(r#"radial = "0.009 mm""#, 0, &huge);
    assert!(m.len() < 400, "{} bytes: {}", m.len(), &m[..400]);
    assert_blames(&m, "clearance.radial");
}

#[test]
fn an_oversized_file_is_refused() {
    let dir = std::env::temp_dir().join(format!("rolldyn-oversize-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("big.toml");
    let padding = "#".repeat(MAX_INPUT_FILE_BYTES as usize);
    std::fs::write(&path, format!("{GOOD}\n{padding}\n")).unwrap();
    let result = load(&path);
    std::fs::remove_dir_all(&dir).unwrap();
    let m = result
        .expect_err("an oversized file is refused")
        .to_string();
    assert!(m.contains("larger than"), "{m}");
}

#[cfg(unix)]
#[test]
fn dev_zero_is_refused_quickly() {
    let start = std::time::Instant::now();
    let m = load(std::path::Path::new("/dev/zero"))
        .expect_err("/dev/zero is no model")
        .to_string();
    assert!(m.starts_with("/dev/zero: "), "{m}");
    assert!(start.elapsed().as_secs_f64() < 5.0);
}
