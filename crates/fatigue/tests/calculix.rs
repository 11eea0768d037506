//! End-to-end solve of a small cage on a coarse mesh with gmsh and ccx (theory §10.4).

use rolldyn_fatigue::calculix::{CalculixSettings, solve};
use rolldyn_fatigue::{CageGeometry, Face, FilletPoint};

fn small_cage() -> CageGeometry {
    CageGeometry {
        pockets: 6,
        inner_radius: 20e-3,
        outer_radius: 25e-3,
        width: 12e-3,
        pocket: rolldyn_geometry::CagePocket {
            faces: rolldyn_geometry::PocketFaces::Flat,
            face_clearance: 1e-3,
            outer_lip: None,
            inner_lip: None,
            axial: 7e-3,
            fillet_radius: 0.8e-3,
        },
        roller_radius: 3e-3,
        pitch_radius: 22.5e-3,
        bar_contact: [22.5e-3, 3.5e-3],
        youngs_modulus: 211e9,
        poisson_ratio: 0.3,
        density: 7850.0,
    }
}

fn coarse() -> CalculixSettings {
    CalculixSettings {
        mesh_size: 3e-3,
        fillet_mesh_size: 0.8e-3,
        refinement_growth: 2e-3,
        ..CalculixSettings::default()
    }
}

#[test]
fn a_coarse_small_cage_is_balanced_consistent_and_cached() {
    let cage = small_cage();
    let cache = std::env::temp_dir().join(format!("rolldyn-calculix-test-{}", std::process::id()));
    let solution = solve(&cage, 2e-3, &coarse(), Some(&cache)).unwrap();
    let report = &solution.report;
    let table = &solution.unit_stresses;
    assert!(table.consistent() && table.model == "calculix");

    // (a) inertia relief: the supports carry (almost) nothing
    assert!(report.largest_reaction_ratio < 1e-3, "{report:?}");
    assert!(report.centrifugal_reaction_ratio < 1e-3, "{report:?}");

    // (b) the rim hoop stress of the spinning cage: the ring value ρ ω² R² raised by the bars
    // the rims carry (mass ratio about 2 here)
    let ring = cage.density * cage.mean_radius().powi(2);
    let hoop = report.rim_hoop_per_spin_squared / ring;
    assert!(
        (0.5..5.0).contains(&hoop),
        "rim hoop / ring theory = {hoop}"
    );

    // (c) cyclic consistency: the spin load and the mesh are the same at every pocket, so are
    // the stresses
    let spin = &table.per_unit_spin_squared;
    let scale = spin.iter().flatten().fold(0.0_f64, |m, s| m.max(s.abs()));
    for p in FilletPoint::all(cage.pockets) {
        let first = spin[FilletPoint { bar: 0, ..p }.index()];
        for (a, b) in spin[p.index()].iter().zip(first) {
            assert!((a - b).abs() < 1e-3 * scale, "{} {a} vs {b}", p.label());
        }
    }
    // a tangential force on a bar flank stresses that bar's fillets more than the opposite bar's
    let near = FilletPoint {
        bar: 0,
        rim: 0,
        side: rolldyn_fatigue::PocketSide::Minus,
        face: Face::Outer,
    };
    let far = FilletPoint { bar: 3, ..near };
    let tangential_on_bar0 = |p: FilletPoint| {
        table
            .unit(p, 2, 1, 0)
            .iter()
            .fold(0.0_f64, |m, s| m.max(s.abs()))
    };
    assert!(tangential_on_bar0(near) > 3.0 * tangential_on_bar0(far));

    // the cache answers without gmsh or ccx
    let offline = CalculixSettings {
        gmsh: "no-such-gmsh".into(),
        ccx: "no-such-ccx".into(),
        ..coarse()
    };
    let again = solve(&cage, 2e-3, &offline, Some(&cache)).unwrap();
    assert_eq!(again.report.nodes, report.nodes);
    let cached = again.unit_stresses.per_unit_force.iter().flatten();
    for (a, b) in cached.zip(table.per_unit_force.iter().flatten()) {
        assert!((a - b).abs() <= 1e-12 * b.abs(), "{a} vs {b}");
    }
    let missing = solve(&cage, 2.5e-3, &offline, Some(&cache))
        .unwrap_err()
        .to_string();
    assert!(
        missing.contains("no-such-gmsh") && missing.contains("apt-get install"),
        "{missing}"
    );
    std::fs::remove_dir_all(&cache).unwrap();
}
