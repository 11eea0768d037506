//! The frame model against the CalculiX solid model at the window-corner fillets of the 2002834
//! cage (VALIDATION.md "Cage fatigue", frame vs CalculiX): for the unit spin² and for every unit
//! station force of pocket 0, the signed von Mises stress of both models at the fillet where the
//! solid model's is largest.
//!
//! Run: `cargo run --release -p rolldyn-validation --example cage_stress_models -- CACHE_DIR`
//! (the CalculiX unit cases are solved once, ≈ 100 s on 2 cores, and cached in CACHE_DIR).

use rolldyn_fatigue::calculix::{CalculixSettings, unit_stresses as solid};
use rolldyn_fatigue::frame::{FrameSettings, unit_stresses as frame};
use rolldyn_fatigue::study::{FatigueSettings, cage_geometry};
use rolldyn_fatigue::{FilletPoint, STATIONS, UnitStresses, signed_von_mises};
use std::path::PathBuf;

/// Index of the fillet with the largest |signed von Mises| of `stresses`.
fn worst(stresses: &[[f64; 6]]) -> usize {
    (0..stresses.len())
        .max_by(|&a, &b| {
            signed_von_mises(&stresses[a])
                .abs()
                .total_cmp(&signed_von_mises(&stresses[b]).abs())
        })
        .unwrap_or(0)
}

fn row(label: &str, f: &[[f64; 6]], s: &[[f64; 6]], scale: f64) {
    let points = FilletPoint::all(f.len() / 8);
    let i = worst(s);
    let (vf, vs) = (
        signed_von_mises(&f[i]) * scale,
        signed_von_mises(&s[i]) * scale,
    );
    let j = worst(f);
    println!(
        "| {label} | {} | {vs:.2} | {vf:.2} | {:.2} | {} ({:.2}) |",
        points[i].label(),
        vf / vs,
        points[j].label(),
        signed_von_mises(&f[j]) * scale
    );
}

fn main() -> Result<(), String> {
    let cache = PathBuf::from(
        std::env::args()
            .nth(1)
            .ok_or("usage: cage_stress_models CACHE_DIR")?,
    );
    std::fs::create_dir_all(&cache).map_err(|e| e.to_string())?;
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml")
        .map_err(|e| e.to_string())?;
    let rolldyn_geometry::BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Err("the embedded model is cylindrical".into());
    };
    let cage = cage_geometry(bearing, FatigueSettings::default().fillet_radius_m)?;
    let z = bearing.roller.bar_contact_half_span();
    let f: UnitStresses = frame(&cage, z, &FrameSettings::default()).map_err(|e| e.to_string())?;
    let s: UnitStresses =
        solid(&cage, z, &CalculixSettings::default(), Some(&cache)).map_err(|e| e.to_string())?;
    let p = f.points();
    println!(
        "| case | fillet (largest in CalculiX) | CalculiX | frame | frame/CalculiX | largest in the frame |"
    );
    println!("|---|---|---|---|---|---|");
    let omega = 3762.0 * std::f64::consts::TAU / 60.0;
    row(
        "spin 3762 rpm, MPa",
        &f.per_unit_spin_squared,
        &s.per_unit_spin_squared,
        omega * omega * 1e-6,
    );
    let names = ["radial", "tangential", "axial"];
    for (k, station) in STATIONS.iter().enumerate() {
        for (c, name) in names.iter().enumerate() {
            let range = (3 * k + c) * p..(3 * k + c + 1) * p;
            row(
                &format!("{station:?} {name}, kPa/N"),
                &f.per_unit_force[range.clone()],
                &s.per_unit_force[range],
                1e-3,
            );
        }
    }
    Ok(())
}
