//! Issue 39, silent wrong answers: a contact grid that cannot resolve the contact (N6),
//! implausible oil-file values (N12), absurd loads and speeds (N14), wear-map depths (N15) and
//! the geometry values still accepted. Each is refused with exit 2 naming the file, line and key
//! or the flag (README "Exit codes", docs/model-format.md "Plausibility bounds").

mod common;

use common::{example, rolldyn};
use std::path::{Path, PathBuf};

/// A fresh temporary folder for `name`.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-bounds-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A copy of the default model with `from` replaced by `to` (and `extra` appended) in `dir`.
fn model_in(dir: &Path, from: &str, to: &str, extra: &str) -> String {
    let text = std::fs::read_to_string(example("2002834.toml")).unwrap();
    assert!(text.contains(from), "test setup: '{from}'");
    let path = dir.join("m.toml");
    std::fs::write(&path, format!("{}\n{extra}", text.replacen(from, to, 1))).unwrap();
    path.display().to_string()
}

/// The exit code and the last line of stderr.
fn run(args: &[&str]) -> (i32, String) {
    let out = rolldyn(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let last = stderr.lines().last().unwrap_or("").to_string();
    (out.status.code().expect("an exit code"), last)
}

/// Exit 2 with one short line containing every one of `expected`.
fn refused(args: &[&str], expected: &[&str]) {
    let (code, line) = run(args);
    assert_eq!(code, 2, "{args:?}: {line}");
    for e in expected {
        assert!(line.contains(e), "{args:?}: `{e}` not in: {line}");
    }
    assert!(line.len() < 400, "a long message: {line}");
}

/// The line number (1-based) of the first line of `file` containing `text`.
fn line_of(file: &str, text: &str) -> usize {
    let text_of_file = std::fs::read_to_string(file).unwrap();
    1 + text_of_file
        .lines()
        .position(|l| l.contains(text))
        .unwrap_or_else(|| panic!("{text} in {file}"))
}

#[test]
fn n6_a_grid_that_cannot_resolve_the_contact_is_refused() {
    let model = example("2002834.toml");
    for cells in ["1x1", "5x5", "150x3"] {
        refused(
            &[
                "contact", &model, "--load", "1000N", "--cells", cells, "--json",
            ],
            &[
                &format!("--cells {cells}: the grid cannot resolve"),
                "at least 4 cells across 2b",
                "(--cells 252x5)",
            ],
        );
    }
    refused(
        &[
            "contact", &model, "--load", "1000N", "--cells", "150x9", "--width", "0.1mm",
        ],
        &["(--width 0.1925mm --cells 150x5)"],
    );
    // the grid the message asks for and the default grid resolve the contact: within 2 % of a
    // grid with 16 cells across 2b (docs/theory.md §2.6)
    let pressure = |extra: &[&str]| {
        let mut args = vec!["contact", &model, "--load", "1000N", "--json"];
        args.extend_from_slice(extra);
        common::json(&rolldyn(&args))["max_pressure_pa"]
            .as_f64()
            .unwrap()
    };
    let fine = pressure(&["--cells", "1006x48"]);
    for grid in [&["--cells", "252x5"][..], &[]] {
        let p = pressure(grid);
        assert!((p / fine - 1.0).abs() < 0.02, "{grid:?}: {p} vs {fine}");
    }
}

#[test]
fn n12_an_implausible_oil_value_names_the_oil_file_line_and_key() {
    let dir = folder("oil");
    let oil = std::fs::read_to_string(example("oils/vg220-mineral.toml")).unwrap();
    let bad = oil.replace("shear_modulus = \"3 GPa\"", "shear_modulus = \"3e15 GPa\"");
    assert_ne!(bad, oil, "test setup");
    let oil_file = dir.join("oil.toml").display().to_string();
    std::fs::write(&oil_file, bad).unwrap();
    let line = line_of(&oil_file, "shear_modulus =");
    let located = format!("oil.toml:{line}:");
    refused(
        &["oils", "--oil-file", &oil_file],
        &[&located, "shear_modulus", "implausible"],
    );
    let model = model_in(&dir, "oil = \"vnii-np-50-1-4u\"", "file = \"oil.toml\"", "");
    refused(
        &["skid", &model],
        &[&located, "shear_modulus", "lubricant.file"],
    );
    // the model's own override of the density
    let model = model_in(
        &dir,
        "density = \"930 kg/m3\"",
        "density = \"9e11 kg/m3\"",
        "",
    );
    let line = line_of(&model, "density = \"9e11");
    refused(
        &["skid", &model],
        &[
            &format!("m.toml:{line}:"),
            "lubricant.density",
            "implausible",
        ],
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn n12_a_law_negative_inside_its_range_names_the_oil_not_the_temperature() {
    let dir = folder("law");
    let oil = std::fs::read_to_string(example("oils/vg220-mineral.toml")).unwrap();
    // ρ = 3950 − 180 T + 2 T² (°C): positive at 20, 70 and 120 °C, negative near 45 °C
    let bad = oil.replace("coeffs = [899.75, -0.65]", "coeffs = [3950.0, -180.0, 2.0]");
    assert_ne!(bad, oil, "test setup");
    let oil_file = dir.join("oil.toml").display().to_string();
    std::fs::write(&oil_file, bad).unwrap();
    let line = line_of(&oil_file, "density =");
    let (code, message) = run(&["oils", "--oil-file", &oil_file, "--temperature", "45C"]);
    assert_eq!(code, 2, "{message}");
    assert!(
        message.contains(&format!("oil.toml:{line}:")) && message.contains("density"),
        "{message}"
    );
    assert!(!message.contains("--temperature"), "{message}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn n14_absurd_loads_and_speeds_are_refused_by_every_command() {
    let model = example("2002834.toml");
    for load in ["1e300N", "1e8N"] {
        refused(
            &["skid", &model, "--radial-load", load],
            &["--radial-load", "Hertz pressure", "10 GPa"],
        );
    }
    refused(
        &[
            "simulate",
            &model,
            "--radial-load",
            "1e300N",
            "--duration",
            "0.01rev",
        ],
        &["--radial-load", "Hertz pressure"],
    );
    refused(
        &["film", "--load", "100N", "--rolling-speed", "1e300m/s"],
        &["--rolling-speed", "1.0000e300 m/s", "implausible"],
    );
    refused(
        &["film", "--load", "1e12N", "--rolling-speed", "2m/s"],
        &["--load", "10 GPa"],
    );
    refused(
        &[
            "traction",
            "--max-pressure",
            "50GPa",
            "--rolling-speed",
            "2m/s",
        ],
        &["--max-pressure", "10 GPa"],
    );
    refused(
        &["contact", &model, "--load", "1e300N"],
        &["--load 1.0000e300 N", "10 GPa"],
    );
    let dir = folder("load");
    let file = model_in(
        &dir,
        "radial_load = \"1600 N\"",
        "radial_load = \"1e9 N\"",
        "",
    );
    let line = line_of(&file, "radial_load = \"1e9 N\"");
    refused(
        &["check", &file],
        &[
            &format!("m.toml:{line}:"),
            "operating.radial_load",
            "Hertz pressure",
        ],
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn n15_a_wear_map_deeper_than_a_working_bearing_names_map_line_and_column() {
    let dir = folder("wear");
    std::fs::write(
        dir.join("wear.csv"),
        "axial_mm,angle_deg,depth_um\n-5,180,2\n5,180,1e6\n",
    )
    .unwrap();
    let model = model_in(
        &dir,
        "[inner_ring.guiding_land]",
        "[inner_ring.raceway_wear]\nfile = \"wear.csv\"\n\n[inner_ring.guiding_land]",
        "",
    );
    for command in ["check", "skid"] {
        refused(
            &[command, &model],
            &[
                "inner_ring.raceway_wear.file",
                "wear.csv: line 3: depth_um",
                "implausible",
            ],
        );
    }
    std::fs::write(
        dir.join("wear.csv"),
        "axial_mm,angle_deg,depth_um\n-5,180,1e308\n5,180,1\n",
    )
    .unwrap();
    refused(&["skid", &model], &["wear.csv: line 2: depth_um"]);
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn still_accepted_geometry_values_are_refused_with_their_key() {
    let dir = folder("geometry");
    let cases = [
        (
            "outside_diameter = \"215 mm\"",
            "outside_diameter = \"1e23 mm\"",
            "outer_ring.outside_diameter",
        ),
        (
            "outside_diameter = \"215 mm\"",
            "outside_diameter = \"900 mm\"",
            "outer_ring.outside_diameter",
        ),
        (
            "edge_break = \"0.3 mm\"           # ASSUMED\n\n[[inner_ring.ribs]]",
            "edge_break = \"1e308 mm\"\n\n[[inner_ring.ribs]]",
            "inner_ring.ribs[0].edge_break",
        ),
        (
            "radial = \"0.009 mm\"",
            "radial = \"1e7 mm\"",
            "clearance.radial",
        ),
        (
            "width = \"5 mm\"",
            "width = \"1e7 mm\"",
            "inner_ring.guiding_land.width",
        ),
        (
            "radius = \"0.6 mm\" }",
            "radius = \"1e7 mm\" }",
            "roller.profile.chamfer.radius",
        ),
        (
            "fillet_radius = \"0.5 mm\"",
            "fillet_radius = \"1e7 mm\"",
            "cage.pocket.fillet_radius",
        ),
    ];
    for (from, to, key) in cases {
        let model = model_in(&dir, from, to, "");
        let line = line_of(&model, to.lines().next().unwrap());
        refused(
            &["check", &model],
            &[&format!("m.toml:{line}:"), key, "implausible"],
        );
    }
    std::fs::remove_dir_all(dir).ok();
}
