//! The solid model of the reference cage (2002834) at the default mesh: wall time, mesh size,
//! balance and the fillet stresses of a unit tangential bar force (theory §10.4). Minutes of
//! gmsh and ccx: run on demand with
//! `cargo test -p rolldyn-fatigue --test calculix_reference -- --ignored --nocapture`.

use rolldyn_fatigue::calculix::{CalculixSettings, solve};
use rolldyn_fatigue::study::cage_geometry;
use rolldyn_fatigue::{FilletPoint, STATIONS, Station, signed_von_mises};

#[test]
#[ignore = "solves the full reference cage with gmsh and ccx (about two minutes)"]
fn reference_cage_at_the_default_mesh() {
    // the embedded 2002834 model's cage with a 1 mm fillet
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
    let rolldyn_geometry::BearingModel::Cylindrical(bearing) = &model.bearing else {
        panic!("the embedded model is cylindrical");
    };
    let cage = cage_geometry(bearing, Some(1e-3)).unwrap();
    let settings = CalculixSettings::default();
    let solution = solve(&cage, 4.4e-3, &settings, None).unwrap();
    let r = &solution.report;
    println!("{r:#?}");
    let ring = cage.density * cage.mean_radius().powi(2);
    println!(
        "rim hoop / (rho R^2) = {:.3}",
        r.rim_hoop_per_spin_squared / ring
    );
    let spin = &solution.unit_stresses.per_unit_spin_squared;
    let scale = spin.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut scatter: f64 = 0.0;
    for p in FilletPoint::all(cage.pockets) {
        let first = spin[FilletPoint { bar: 0, ..p }.index()];
        for (a, b) in spin[p.index()].iter().zip(first) {
            scatter = scatter.max((a - b).abs() / scale);
        }
    }
    println!(
        "spin²: largest |σ| {scale:.1} Pa, bar-to-bar scatter {:.1} %",
        100.0 * scatter
    );
    let station = STATIONS
        .iter()
        .position(|s| {
            *s == Station::Bar {
                side: rolldyn_fatigue::PocketSide::Plus,
                end: 0,
            }
        })
        .unwrap();
    let table = &solution.unit_stresses;
    let mut rows: Vec<(FilletPoint, [f64; 6])> = FilletPoint::all(cage.pockets)
        .into_iter()
        .map(|p| (p, *table.unit(p, station, 1, 0)))
        .collect();
    let largest = |s: &[f64; 6]| s.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    rows.sort_by(|a, b| largest(&b.1).total_cmp(&largest(&a.1)));
    println!("| fillet point | σ_rr | σ_θθ | σ_zz | τ_rθ | τ_θz | τ_zr | signed vM | (kPa per N)");
    let loaded_bar = rows.iter().filter(|(p, _)| p.bar == 0);
    for (p, s) in rows.iter().take(12).chain(loaded_bar) {
        let k: Vec<String> = s.iter().map(|v| format!("{:.1}", v / 1e3)).collect();
        println!(
            "| {} | {} | {:.1} |",
            p.label(),
            k.join(" | "),
            signed_von_mises(s) / 1e3
        );
    }
    assert!(r.largest_reaction_ratio < 1e-3);
}
