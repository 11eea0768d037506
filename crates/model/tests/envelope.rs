//! Issue 38 item 6: the cage inside the rings' envelope, and the notes a designer gets when a
//! stated value differs from the one the drawing implies.

use rolldyn_geometry::BearingModel;
use rolldyn_model::parse;

const GOOD: &str = rolldyn_model::DEFAULT_MODEL;

/// The default model (bearing 2002834) with `from` replaced by `to` (exactly once).
fn edited(edits: &[(&str, &str)]) -> String {
    let mut text = GOOD.to_string();
    for (from, to) in edits {
        assert_eq!(text.matches(from).count(), 1, "test setup: '{from}'");
        text = text.replace(from, to);
    }
    text
}

fn notes(text: &str) -> Vec<rolldyn_geometry::DesignNote> {
    let model = parse(text, "m.toml").expect("valid model");
    match &model.bearing {
        BearingModel::Cylindrical(b) => b.design_notes(),
        _ => unreachable!(),
    }
}

#[test]
fn a_cage_bore_below_the_inner_ribs_it_overlaps_is_rejected() {
    // The cage (20 mm) is wider than the inner ring's rib spacing (11.05 mm): its bore must
    // clear the rib rims Ø173 mm.
    let text = edited(&[
        (
            r#"inner_diameter = "173.5 mm""#,
            r#"inner_diameter = "172 mm""#,
        ),
        (
            r#"floating_clearance = "0.5 mm""#,
            r#"floating_clearance = "0.1 mm""#,
        ),
    ]);
    let message = parse(&text, "bad.toml").unwrap_err().to_string();
    assert!(message.contains("cage.inner_diameter"), "{message}");
    assert!(message.contains("rib rim Ø173.000 mm"), "{message}");
    assert!(message.contains("wider than the rib spacing"), "{message}");
}

#[test]
fn a_cage_outside_diameter_above_outer_ribs_it_overlaps_is_rejected() {
    // Give the outer ring ribs at Ø192 mm 11.05 mm apart: the 20 mm wide cage overlaps them,
    // its Ø194 mm outside diameter runs into them.
    let text = edited(&[(
        r#"material = "roller-steel"
roughness_ra = "0.2 um"         # ASSUMED
"#,
        r#"material = "roller-steel"
roughness_ra = "0.2 um"         # ASSUMED
rib_spacing = "11.0505 mm"
ribs = [{ side = "left", diameter = "192 mm" }, { side = "right", diameter = "192 mm" }]
"#,
    )]);
    let message = parse(&text, "bad.toml").unwrap_err().to_string();
    assert!(message.contains("cage.outer_diameter"), "{message}");
    assert!(
        message.contains("outer_ring rib rim Ø192.000 mm"),
        "{message}"
    );
}

#[test]
fn a_stated_clearance_other_than_the_raceways_is_noted_with_both_values() {
    // 2002834: D_o − d_i − 2 D_w = 0 beside the stated 9 µm.
    let found = notes(GOOD);
    let note = found
        .iter()
        .find(|n| n.key == "clearance.radial")
        .expect("a clearance note");
    assert!(note.text.contains("9.0 µm"), "{}", note.text);
    assert!(note.text.contains("0.0 µm"), "{}", note.text);
    // Raceways that imply the stated clearance: no note.
    let text = edited(&[(
        r#"raceway_diameter = "195 mm"     # flag F-02: d_i + 2 D_w"#,
        r#"raceway_diameter = "195.009 mm""#,
    )]);
    assert!(notes(&text).iter().all(|n| n.key != "clearance.radial"));
}

#[test]
fn a_land_away_from_the_ring_rim_is_noted() {
    // 1032930: inner-land guided on the rib rims Ø154.4 mm (no separate guiding land).
    const START_UP: &str = include_str!("../../../examples/1032930.toml");
    let found = |text: &str| match parse(text, "m.toml").expect("valid").bearing {
        BearingModel::Cylindrical(b) => b.design_notes(),
        _ => unreachable!(),
    };
    assert!(
        found(START_UP)
            .iter()
            .all(|n| n.key != "cage.floating_clearance")
    );
    let from = r#"floating_clearance = "0.4 mm""#;
    assert_eq!(START_UP.matches(from).count(), 1);
    let text = START_UP.replace(from, r#"floating_clearance = "0.2 mm""#);
    let notes = found(&text);
    let note = notes
        .iter()
        .find(|n| n.key == "cage.floating_clearance")
        .expect("a land note");
    assert!(note.text.contains("Ø154.600 mm"), "{}", note.text);
    assert!(note.text.contains("Ø154.400 mm"), "{}", note.text);
}
