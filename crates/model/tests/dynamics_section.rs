//! `[dynamics]`: cage drag and the SPEC Table 2.1 contact parameters, converted to SI; bad
//! values name their key.

use rolldyn_model::{CageLandLaw, EndFrictionLaw, RollerCageLaw, parse};

const GOOD: &str = rolldyn_model::DEFAULT_MODEL;

/// The default model with `extra` in place of its own `[dynamics.roller_cage]` (its last section).
fn with_dynamics(extra: &str) -> Result<rolldyn_model::Model, String> {
    let base = &GOOD[..GOOD
        .find("[dynamics.roller_cage]")
        .expect("the example's bar law")];
    parse(&format!("{base}\n{extra}"), "m.toml").map_err(|e| e.to_string())
}

#[test]
fn the_example_gives_the_seed_cage_drag() {
    let m = parse(GOOD, "2002834.toml").unwrap();
    // seed 000 §3.6: 662 N·mm/(rad/ms) = 6.62e-4 N·m·s/rad (SPEC F-22)
    let c = m.dynamics.cage_drag_n_m_s.unwrap();
    assert!((c - 6.62e-4).abs() < 1e-15, "{c}");
    // the pair-34 law is derived at load from the cage pocket (rolldyn-setup): not given
    assert_eq!(m.dynamics.roller_cage.k_p, None);
    assert_eq!(m.dynamics.roller_cage.exponent, None);
}

#[test]
fn pair_keys_convert_to_si() {
    let m = with_dynamics(
        r#"[dynamics.raceways]
damping = "0.3 Ns/mm"
damping_ramp = "2 um"
[dynamics.roller_cage]
stiffness = 5e8
exponent = 1.2
damping = "2000 Ns/m"
damping_ramp = "0.5 um"
friction = { static = 0.03, dynamic = 0.02, static_speed = "4 mm/s", dynamic_speed = "0.04 m/s" }
[dynamics.roller_end_rib]
friction_law = "kragelsky"
enabled = false
"#,
    )
    .unwrap();
    let d = &m.dynamics;
    assert_eq!(d.raceway_damping, Some(300.0));
    assert!((d.raceway_damping_ramp.unwrap() - 2e-6).abs() < 1e-18);
    let p = &d.roller_cage;
    assert_eq!(p.k_p, Some(5e8));
    assert_eq!(p.exponent, Some(1.2));
    assert_eq!(p.c_h, Some(2000.0));
    assert!((p.d.unwrap() - 5e-7).abs() < 1e-18);
    assert_eq!((p.mu_static, p.mu_dynamic), (Some(0.03), Some(0.02)));
    assert!((p.v_static.unwrap() - 4e-3).abs() < 1e-15);
    assert!((p.v_dynamic.unwrap() - 0.04).abs() < 1e-15);
    assert_eq!(
        d.roller_end_rib.friction_law,
        Some(EndFrictionLaw::Kragelsky)
    );
    assert_eq!(d.roller_end_rib.enabled, Some(false));
    assert_eq!(d.cage_land.k_p, None);
}

#[test]
fn bad_values_name_their_key() {
    for (text, key) in [
        (
            "[dynamics.roller_cage]\nstiffness = -1.0\n",
            "dynamics.roller_cage.stiffness",
        ),
        (
            "[dynamics.cage_land]\nexponent = 0.5\n",
            "dynamics.cage_land.exponent",
        ),
        (
            "[dynamics.roller_end_cage]\nfriction = { static_speed = \"5 mm/s\", dynamic_speed = \"5 mm/s\" }\n",
            "dynamics.roller_end_cage.friction.dynamic_speed",
        ),
        (
            "[dynamics.raceways]\ndamping = \"-3 Ns/m\"\n",
            "dynamics.raceways.damping",
        ),
        (
            "[dynamics.roller_cage]\nstifness = 1e9\n",
            "dynamics.roller_cage.stifness",
        ),
        (
            "[dynamics.roller_end_rib]\nfriction_law = \"sticky\"\n",
            "dynamics.roller_end_rib.friction_law",
        ),
    ] {
        let e = with_dynamics(text).expect_err(text);
        assert!(e.contains(key), "{text}: {e}");
        assert!(e.starts_with("m.toml:"), "{e}");
    }
}

/// `[dynamics] cage_land_law`: hydrodynamic by default, "contact" for the plain pair-14 law; any
/// other value is a one-line error at its key and line.
#[test]
fn cage_land_law_parses_and_names_a_bad_value() {
    let default = parse(GOOD, "m.toml").unwrap();
    assert_eq!(default.dynamics.cage_land_law, CageLandLaw::Hydrodynamic);
    let contact = GOOD.replace("[dynamics]\n", "[dynamics]\ncage_land_law = \"contact\"\n");
    assert_ne!(contact, GOOD, "the example has a [dynamics] table");
    let m = parse(&contact, "m.toml").unwrap();
    assert_eq!(m.dynamics.cage_land_law, CageLandLaw::Contact);
    let bad = GOOD.replace("[dynamics]\n", "[dynamics]\ncage_land_law = \"film\"\n");
    let e = parse(&bad, "m.toml").unwrap_err().to_string();
    let line = bad
        .lines()
        .position(|l| l.starts_with("cage_land_law"))
        .unwrap()
        + 1;
    assert!(e.starts_with(&format!("m.toml:{line}:")), "{e}");
    assert!(e.contains("dynamics.cage_land_law"), "{e}");
    assert!(e.contains("contact") && !e.contains('\n'), "{e}");
}

/// `[dynamics.roller_cage] law`: elastic by default, "lubricated" for the film law, the pair's
/// other keys kept; any other value is a one-line error naming the key.
#[test]
fn roller_cage_law_parses_and_names_a_bad_value() {
    let default = parse(GOOD, "m.toml").unwrap();
    assert_eq!(default.dynamics.roller_cage_law, RollerCageLaw::Elastic);
    let m =
        with_dynamics("[dynamics.roller_cage]\nlaw = \"lubricated\"\nstiffness = 7e8\n").unwrap();
    assert_eq!(m.dynamics.roller_cage_law, RollerCageLaw::Lubricated);
    assert_eq!(m.dynamics.roller_cage.k_p, Some(7e8));
    let m = with_dynamics("[dynamics.roller_cage]\nlaw = \"elastic\"\n").unwrap();
    assert_eq!(m.dynamics.roller_cage_law, RollerCageLaw::Elastic);
    let e = with_dynamics("[dynamics.roller_cage]\nlaw = \"oily\"\n").unwrap_err();
    assert!(e.contains("dynamics.roller_cage.law"), "{e}");
    assert!(e.contains("lubricated") && !e.contains('\n'), "{e}");
    let e = with_dynamics("[dynamics.roller_cage]\nlaw = \"lubricated\"\nexponent = 0.5\n")
        .unwrap_err();
    assert!(e.contains("dynamics.roller_cage.exponent"), "{e}");
}
