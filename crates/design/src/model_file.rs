//! The designed bearing as a model file (docs/model-format.md): every value with its basis in a
//! comment (`# ESTIMATED: rule, source`, `# DERIVED: …`, or the standard's table).

use crate::rules::{Basis, BearingDesign, Dim, Lip};
use std::fmt::Write;

/// A length as the file writes it, in mm with at most 5 decimals (10 nm).
fn mm(x: f64) -> String {
    let s = format!("{:.5}", x * 1e3);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("\"{s} mm\"")
}

fn um(x: f64) -> String {
    let s = format!("{:.3}", x * 1e6);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("\"{s} um\"")
}

fn comment(basis: &Basis) -> String {
    match basis {
        Basis::Source(why) if why.is_empty() => String::new(),
        Basis::Source(why) => format!("# {why}"),
        Basis::Estimated(why) => format!("# ESTIMATED: {why}"),
        Basis::Derived(why) => format!("# DERIVED: {why}"),
    }
}

/// `key = value  # basis`, the comment aligned.
fn line(out: &mut String, key: &str, value: &str, basis: &Basis) {
    let assignment = format!("{key} = {value}");
    let note = comment(basis);
    if note.is_empty() {
        let _ = writeln!(out, "{assignment}");
    } else {
        let _ = writeln!(out, "{assignment:<31} {note}");
    }
}

fn length(out: &mut String, key: &str, dim: &Dim) {
    line(out, key, &mm(dim.value), &dim.basis);
}

fn roughness(out: &mut String, dim: &Dim) {
    line(out, "roughness_ra", &um(dim.value), &dim.basis);
}

/// The model file of `design`.
pub fn write(design: &BearingDesign) -> String {
    let mut out = String::new();
    heading(&mut out, design);
    rings(&mut out, design);
    roller(&mut out, design);
    cage(&mut out, design);
    clearance(&mut out, design);
    lubricant(&mut out, design);
    operating(&mut out, design);
    out
}

fn heading(out: &mut String, d: &BearingDesign) {
    let i = &d.input;
    let b = &i.boundary;
    let _ = writeln!(
        out,
        "# {} — single-row cylindrical roller bearing, type {}, written by `rolldyn new`.",
        i.name,
        i.ribs.letters()
    );
    let _ = writeln!(
        out,
        "# Boundary dimensions d × D × B = {} × {} × {} mm: {}.",
        b.bore * 1e3,
        b.outside * 1e3,
        b.width * 1e3,
        b.source
    );
    let _ = writeln!(
        out,
        "# The internal geometry follows the design rules of docs/theory.md \"A model from a \
         designation\":\n# values marked ESTIMATED are estimates by the rule named beside them; \
         replace them with the\n# manufacturer's values where known. The roller–cage contact \
         law is derived at load from\n# [cage.pocket] (docs/model-format.md, [dynamics.roller_cage])."
    );
    let _ = writeln!(
        out,
        "# Ring chamfer r_s min = {} mm ({}); ISO 582 gives the largest chamfer for it.",
        d.chamfer_min.value * 1e3,
        comment(&d.chamfer_min.basis).trim_start_matches("# ")
    );
    let _ = writeln!(out, "\n[bearing]");
    let _ = writeln!(out, "name = \"{}\"", i.name);
    let _ = writeln!(out, "kind = \"cylindrical\"");
    let _ = writeln!(
        out,
        "description = \"{}, {} × {} × {} mm, {} (rolldyn new)\"",
        i.name,
        b.bore * 1e3,
        b.outside * 1e3,
        b.width * 1e3,
        i.cage.description()
    );
}

fn ribs(out: &mut String, table: &str, dim: &Dim, sides: &[&str], edge_break: &Dim) {
    for side in sides {
        let _ = writeln!(out, "\n[[{table}.ribs]]");
        let _ = writeln!(out, "side = \"{side}\"");
        length(out, "diameter", dim);
        let _ = writeln!(out, "face = {{ kind = \"flat\" }}");
        length(out, "edge_break", edge_break);
    }
}

fn rings(out: &mut String, d: &BearingDesign) {
    let b = &d.input.boundary;
    let given = Basis::Source(b.source.clone());
    let (left, right) = d.input.ribs.other_ring_ribs();
    let other_sides: Vec<&str> = [("left", left), ("right", right)]
        .iter()
        .filter(|s| s.1)
        .map(|s| s.0)
        .collect();
    let both = ["left", "right"];
    // inner ring
    let _ = writeln!(out, "\n[inner_ring]");
    length(out, "raceway_diameter", &d.inner_raceway);
    line(out, "bore_diameter", &mm(b.bore), &given);
    line(out, "width", &mm(b.width), &given);
    let _ = writeln!(out, "material = \"bearing-steel\"");
    roughness(out, &d.raceway_ra);
    if !d.outer_guided() || other_sides.len() == 2 {
        length(out, "rib_spacing", &d.rib_spacing);
    }
    if d.outer_guided() {
        if let Some(rib) = &d.other_rib {
            ribs(out, "inner_ring", rib, &other_sides, &d.edge_break);
        }
    } else {
        ribs(out, "inner_ring", &d.guiding_rib, &both, &d.edge_break);
        let _ = writeln!(out, "\n[inner_ring.guiding_land]");
        length(out, "width", &d.land_width);
    }
    // outer ring
    let _ = writeln!(out, "\n[outer_ring]");
    length(out, "raceway_diameter", &d.outer_raceway);
    line(out, "outside_diameter", &mm(b.outside), &given);
    line(out, "width", &mm(b.width), &given);
    let _ = writeln!(out, "material = \"bearing-steel\"");
    roughness(out, &d.raceway_ra);
    if d.outer_guided() {
        length(out, "rib_spacing", &d.rib_spacing);
        ribs(out, "outer_ring", &d.guiding_rib, &both, &d.edge_break);
        let _ = writeln!(out, "\n[outer_ring.guiding_land]");
        length(out, "width", &d.land_width);
    }
}

fn roller(out: &mut String, d: &BearingDesign) {
    let _ = writeln!(out, "\n[roller]");
    line(
        out,
        "count",
        &d.roller_count.to_string(),
        &d.roller_count_basis,
    );
    length(out, "diameter", &d.roller_diameter);
    length(out, "length", &d.roller_length);
    line(
        out,
        "slices",
        "10",
        &Basis::Estimated("10 slices as the example models; more resolve the crown finer".into()),
    );
    let _ = writeln!(out, "material = \"bearing-steel\"");
    roughness(out, &d.roller_ra);
    length(out, "edge_break", &d.edge_break);
    let _ = writeln!(out, "end_face = {{ kind = \"flat\" }}");
    let _ = writeln!(out, "\n[roller.profile]");
    let _ = writeln!(out, "kind = \"crowned\"");
    length(out, "straight_length", &d.crown_straight);
    length(out, "drop", &d.crown_drop);
    let c = mm(d.roller_chamfer.value);
    line(
        out,
        "chamfer",
        &format!("{{ axial = {c}, radial = {c}, radius = {c} }}"),
        &d.roller_chamfer.basis,
    );
}

fn lip_table(lip: &Lip) -> String {
    format!(
        "{{ diameter = {}, window = {}, tip_radius = {} }}",
        mm(lip.diameter.value),
        mm(lip.window.value),
        mm(lip.tip_radius.value)
    )
}

fn cage(out: &mut String, d: &BearingDesign) {
    let _ = writeln!(out, "\n[cage]");
    let _ = writeln!(out, "# {}", d.input.cage.description());
    let guidance = if d.outer_guided() {
        "outer-land"
    } else {
        "inner-land"
    };
    line(
        out,
        "guidance",
        &format!("\"{guidance}\""),
        &Basis::Estimated(
            "centred on the rims of the two ribs of one ring (machined cages)".into(),
        ),
    );
    length(out, "floating_clearance", &d.floating_clearance);
    length(out, "pocket_axial", &d.pocket_axial);
    length(out, "inner_diameter", &d.cage_bore);
    length(out, "outer_diameter", &d.cage_outside);
    length(out, "width", &d.cage_width);
    let _ = writeln!(out, "material = \"{}\"", d.input.cage.material());
    roughness(out, &d.cage_ra);
    let _ = writeln!(out, "\n[cage.pocket]");
    let _ = writeln!(out, "faces = \"flat\"");
    length(out, "face_clearance", &d.face_clearance);
    if let Some(lip) = &d.lip {
        let key = if lip.at_bore {
            "inner_lip"
        } else {
            "outer_lip"
        };
        line(out, key, &lip_table(lip), &lip.diameter.basis);
    }
    if let Some(why) = &d.no_lip {
        let _ = writeln!(out, "# {why}");
    }
    length(out, "fillet_radius", &d.fillet_radius);
}

fn clearance(out: &mut String, d: &BearingDesign) {
    let _ = writeln!(out, "\n[clearance]");
    let _ = writeln!(
        out,
        "# Unmounted radial internal clearance; the raceway diameters above imply the same value.\n\
         # The quasi-static model derives the operating clearance from it (theory §6.1)."
    );
    line(out, "radial", &um(d.clearance.value), &d.clearance.basis);
}

fn lubricant(out: &mut String, d: &BearingDesign) {
    let _ = writeln!(out, "\n[lubricant]");
    let basis = match &d.input.oil {
        Some(_) => Basis::Source("built-in oil (`rolldyn oils`, docs/lubricants.md)".into()),
        None => Basis::Estimated(
            "ASSUMED: no --oil given; ISO VG 68 mineral (`rolldyn oils`): name your oil".into(),
        ),
    };
    line(out, "oil", &format!("\"{}\"", d.input.oil_name()), &basis);
}

fn operating(out: &mut String, d: &BearingDesign) {
    let Some(op) = d.input.operating else {
        let _ = writeln!(
            out,
            "\n# No [operating] section: no speed and load were given to `rolldyn new` (--speed,\n\
             # --radial-load, --oil-temperature). Give them to the analyses' flags or add [operating]\n\
             # with inner_speed, radial_load and temperatures.oil (docs/model-format.md)."
        );
        return;
    };
    let given = Basis::Source("given".into());
    let _ = writeln!(out, "\n[operating]");
    let _ = writeln!(
        out,
        "# Inner ring rotating, outer ring fixed, load fixed in space."
    );
    let rpm = op.speed * 60.0 / std::f64::consts::TAU;
    line(
        out,
        "inner_speed",
        &format!("\"{} rpm\"", trim(rpm)),
        &given,
    );
    let _ = writeln!(out, "outer_speed = \"0 rpm\"");
    line(
        out,
        "radial_load",
        &format!("\"{} N\"", trim(op.radial_load)),
        &given,
    );
    if let Some(t) = &d.oil_temperature {
        line(
            out,
            "temperatures",
            &format!("{{ oil = \"{} C\" }}", trim(t.value - 273.15)),
            &t.basis,
        );
    }
}

fn trim(x: f64) -> String {
    let s = format!("{x:.4}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}
