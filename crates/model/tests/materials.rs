//! Built-in materials by name, a `[materials]` table's own S–N curve or `fatigue_like`, the cage
//! plating, and the seed bearings' cages (docs/model-format.md `[materials]`).

use rolldyn_geometry::material_database;
use rolldyn_geometry::{CylindricalRollerBearing, Material, Plating};
use rolldyn_model::{DEFAULT_MODEL, parse};
use std::path::Path;

fn cylindrical(text: &str) -> CylindricalRollerBearing {
    let model = parse(text, "test.toml").unwrap();
    model.bearing.require_cylindrical("test").unwrap().clone()
}

fn cage_material(text: &str) -> Material {
    cylindrical(text).cage.unwrap().material
}

/// The default model with its first `from` replaced by `to`.
fn edited(from: &str, to: &str) -> String {
    assert!(DEFAULT_MODEL.contains(from), "test setup: '{from}'");
    DEFAULT_MODEL.replacen(from, to, 1)
}

fn error(text: &str) -> String {
    parse(text, "bad.toml")
        .expect_err("must be rejected")
        .to_string()
}

#[test]
fn a_part_names_a_built_in_material_without_a_table() {
    let brass = cage_material(&edited(
        "material = \"cage-steel\"",
        "material = \"cuzn40pb2\"",
    ));
    let record = material_database::find("cuzn40pb2").unwrap();
    assert_eq!(brass, record.material());
    assert_eq!(brass.youngs_modulus, 96e9);
    let fatigue = brass.fatigue.unwrap();
    assert_eq!(fatigue.ultimate_strength, 430e6);
    assert!(fatigue.source.contains("ESTIMATED"), "{}", fatigue.source);
    // an alias
    let text = edited("material = \"cage-steel\"", "material = \"aisi-52100\"");
    assert_eq!(cage_material(&text), Material::bearing_steel());
}

#[test]
fn an_unknown_material_lists_the_built_in_ones() {
    let m = error(&edited(
        "material = \"cage-steel\"",
        "material = \"unobtainium\"",
    ));
    assert!(m.contains("cage.material"), "{m}");
    for name in [
        "pa66-gf25",
        "peek",
        "cual10ni5fe4",
        "aisi-4140",
        "cage-steel",
    ] {
        assert!(m.contains(name), "{name}: {m}");
    }
}

#[test]
fn the_seed_cage_is_silver_plated_with_the_seed_curve() {
    let cage = cylindrical(DEFAULT_MODEL).cage.unwrap();
    assert_eq!(cage.plating, Some(Plating::Silver));
    let seed = material_database::find("40khn2ma-sh").unwrap().material();
    assert_eq!(cage.material.fatigue, seed.fatigue);
    // its own table keeps its elastic data, which are the database entry's
    assert_eq!(cage.material.youngs_modulus, seed.youngs_modulus);
    assert_eq!(cage.material.meyer_hardness, seed.meyer_hardness);
}

#[test]
fn bearing_1032930_keeps_the_bearing_steel_cage_data_with_the_seed_curve() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/1032930.toml");
    let model = rolldyn_model::load(&path).unwrap();
    let cage = model
        .bearing
        .require_cylindrical("test")
        .unwrap()
        .cage
        .clone()
        .unwrap();
    let steel = Material::bearing_steel();
    let m = &cage.material;
    assert_eq!(
        (
            m.youngs_modulus,
            m.poisson_ratio,
            m.density,
            m.meyer_hardness
        ),
        (
            steel.youngs_modulus,
            steel.poisson_ratio,
            steel.density,
            steel.meyer_hardness
        )
    );
    assert_eq!(
        m.fatigue,
        material_database::find("40khn2ma-sh")
            .unwrap()
            .material()
            .fatigue
    );
    assert_eq!(cage.plating, Some(Plating::Silver));
}

const OWN_CURVE: &str = "fatigue_like = \"40khn2ma-sh\"     # S–N";

#[test]
fn a_table_gives_its_own_sn_curve() {
    let text = edited(
        OWN_CURVE,
        "ultimate_strength = \"1000 MPa\"\nsn_curve = { cycles = [1e3, 1e5, 1e7], amplitude = [\"800 MPa\", \"500 MPa\", \"400 MPa\"], source = \"test data\" }\n#",
    );
    let fatigue = cage_material(&text).fatigue.unwrap();
    assert_eq!(fatigue.ultimate_strength, 1000e6);
    assert_eq!(
        fatigue.sn_curve,
        vec![(1e3, 800e6), (1e5, 500e6), (1e7, 400e6)]
    );
    assert_eq!(fatigue.source, "materials.cage-steel.sn_curve: test data");
}

#[test]
fn a_bad_fatigue_table_names_its_key() {
    for (to, key) in [
        (
            "sn_curve = { cycles = [1e3, 1e7], amplitude = [\"800 MPa\", \"400 MPa\"], source = \"x\" }\n#",
            "materials.cage-steel.ultimate_strength",
        ),
        (
            "ultimate_strength = \"1 GPa\"\n#",
            "materials.cage-steel.sn_curve",
        ),
        (
            "ultimate_strength = \"1 GPa\"\nsn_curve = { cycles = [1e3, 1e7], amplitude = [\"400 MPa\", \"800 MPa\"], source = \"x\" }\n#",
            "materials.cage-steel.sn_curve",
        ),
        (
            "ultimate_strength = \"1 GPa\"\nsn_curve = { cycles = [1e3, 1e7], amplitude = [\"800 MPa\"], source = \"x\" }\n#",
            "materials.cage-steel.sn_curve",
        ),
        (
            "fatigue_like = \"gold\"\n#",
            "materials.cage-steel.fatigue_like",
        ),
        (
            "fatigue_like = \"peek\"\nultimate_strength = \"1 GPa\"\n#",
            "materials.cage-steel.fatigue_like",
        ),
    ] {
        let m = error(&edited(OWN_CURVE, to));
        assert!(m.contains(key), "{key}: {m}");
    }
}

#[test]
fn the_file_s_table_takes_precedence_over_a_built_in_name() {
    let text = edited(
        "[materials.cage-steel]",
        "[materials.peek]\nyoungs_modulus = \"4 GPa\"\npoisson_ratio = 0.4\ndensity = \"1300 kg/m3\"\n\n[materials.cage-steel]",
    )
    .replacen("material = \"cage-steel\"", "material = \"peek\"", 1);
    let peek = cage_material(&text);
    assert_eq!(peek.youngs_modulus, 4e9);
    assert_eq!(peek.fatigue, None);
}

#[test]
fn an_unknown_plating_is_refused() {
    let m = error(&edited("plating = \"silver\"", "plating = \"gold\""));
    assert!(m.contains("plating") && m.contains("silver"), "{m}");
}
