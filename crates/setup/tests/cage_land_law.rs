//! Issue 23 item 4: `[dynamics] cage_land_law` reaches the simulation. With "contact" the land
//! is the plain pair-14 contact and the quasi-static start uses the matching contact land.

use rolldyn_dynamics::output::NullSink;
use rolldyn_setup::{Overrides, prepare_frozen};

/// 2002834 with a 2 µm floating clearance (the cage meets the land within the run) and the
/// given land law.
fn model(law: &str) -> rolldyn_model::Model {
    let text = rolldyn_model::DEFAULT_MODEL
        .replace(
            "floating_clearance = \"0.5 mm\"",
            "floating_clearance = \"0.002 mm\"",
        )
        .replace(
            "inner_diameter = \"173.5 mm\"",
            "inner_diameter = \"173.002 mm\"",
        )
        .replace(
            "[dynamics]\n",
            &format!("[dynamics]\ncage_land_law = \"{law}\"\n"),
        );
    rolldyn_model::parse(&text, "m.toml").expect("a valid model")
}

/// A 1 ms run of each law: the contact law presses the cage on the land (a land force, from
/// the contact alone) and starts from the contact land's quasi-static solution; the two laws
/// give different runs.
#[test]
fn the_contact_law_reaches_the_run_and_its_start() {
    let run = |law: &str| {
        let mut p = prepare_frozen(&model(law), &Overrides::default(), 0.0, 0.0, None)
            .expect("the model prepares");
        let qs = p.quasi_static.expect("the quasi-static start solves");
        let summary = p
            .simulation
            .run_until(1e-3, &mut NullSink, &mut |_| {})
            .expect("the run completes");
        (qs, summary)
    };
    let (qs_contact, contact) = run("contact");
    let (qs_film, film) = run("hydrodynamic");
    assert_eq!(
        qs_contact.cage_land_model,
        "plain contact, two-level friction (pair 14)"
    );
    assert_ne!(qs_film.cage_land_model, qs_contact.cage_land_model);
    assert!(contact.max_cage_land_force_n > 0.0, "{contact:?}");
    assert_ne!(contact.max_cage_land_force_n, film.max_cage_land_force_n);
}
