//! One pocket description feeds all four: the frame model's fillet stress, the bar section of
//! the roller–bar contact law, the cage mass and the solid model's window (issue 36 item 8).

use rolldyn_contact::cage_bar::BarLawInputs;
use rolldyn_fatigue::calculix::{CalculixSettings, geo_script, window_bands};
use rolldyn_fatigue::frame::{FrameSettings, unit_stresses};
use rolldyn_fatigue::study::cage_geometry;
use rolldyn_fatigue::{Face, FilletPoint, PocketSide};
use rolldyn_geometry::CylindricalRollerBearing;

/// The embedded 2002834 and a copy with the outer lips' window opened from 11.25 to 12.5 mm.
fn bearings() -> (CylindricalRollerBearing, CylindricalRollerBearing) {
    let base = rolldyn_model::default_cylindrical_bearing();
    let mut wider = base.clone();
    let lip = wider
        .cage
        .as_mut()
        .and_then(|c| c.pocket.outer_lip.as_mut())
        .expect("2002834 has outer lips");
    assert!((lip.window - 11.25e-3).abs() < 1e-12);
    lip.window = 12.5e-3;
    (base, wider)
}

/// Stress σ_zz at the outer fillet of bar 0 (rim 0, facing pocket 0) for a unit tangential
/// force at the `+` bar station of pocket 0 nearest to rim 0.
fn outer_fillet_stress(bearing: &CylindricalRollerBearing) -> f64 {
    let cage = cage_geometry(bearing, None).unwrap();
    let table = unit_stresses(&cage, 4.4e-3, &FrameSettings::default()).unwrap();
    let p = FilletPoint {
        bar: 0,
        rim: 0,
        side: PocketSide::Minus,
        face: Face::Outer,
    };
    table.unit(p, 2, 1, 0)[2]
}

#[test]
fn one_profile_key_moves_contact_stress_bar_section_and_mass() {
    let (base, wider) = bearings();
    // the fatigue cage's bar section is the contact law's, key for key
    for b in [&base, &wider] {
        let law = BarLawInputs::of_bearing(b, 0.01).unwrap();
        let fatigue = cage_geometry(b, None).unwrap().bar_section().unwrap();
        assert_eq!(law.compliance.bar.section, fatigue);
    }
    let section = |b: &CylindricalRollerBearing| {
        BarLawInputs::of_bearing(b, 0.01)
            .unwrap()
            .compliance
            .bar
            .section
    };
    let mass = |b: &CylindricalRollerBearing| {
        let cage = b.cage.as_ref().unwrap();
        cage.computed_mass_properties(&b.pocket_context(cage))
            .unwrap()
            .mass
    };
    // a wider lip window: a narrower bar at the lip and less cage; the lip's fillet moves
    // inwards (its stress `M z/I` falls with `z` faster than `I` does)
    let (s0, s1) = (section(&base), section(&wider));
    assert!(
        s1.area < s0.area && s1.width_outer < s0.width_outer,
        "{s0:?} {s1:?}"
    );
    assert_eq!(s1.width_inner, s0.width_inner);
    assert!(mass(&wider) < mass(&base));
    // the dynamics' roller–pocket contact reads the same walls (`Model::new` resolves
    // `cage.pocket` against the bearing): the roller's play to the lip grows
    let play = |b: &CylindricalRollerBearing| {
        let cage = b.cage.as_ref().unwrap();
        cage.pocket
            .play(&b.pocket_context(cage))
            .unwrap()
            .circumferential_per_side
    };
    assert!(play(&wider) > play(&base) + 0.5e-3);
    assert_ne!(base.pocket_walls(), wider.pocket_walls());
    let (f0, f1) = (outer_fillet_stress(&base), outer_fillet_stress(&wider));
    assert!(f0.is_finite() && f1.is_finite() && f0 != 0.0);
    assert!((f1 / f0 - 1.0).abs() > 0.01, "{f0:e} → {f1:e}");
}

#[test]
fn the_solid_model_cuts_the_lip_step() {
    let (base, wider) = bearings();
    let (c0, c1) = (
        cage_geometry(&base, None).unwrap(),
        cage_geometry(&wider, None).unwrap(),
    );
    // bore side: the faces' 19 mm; outside: the lips' window
    let b0 = window_bands(&c0);
    assert_eq!(b0.len(), 2);
    assert!((b0[0].2 - 9.5e-3).abs() < 1e-12 && (b0[1].2 - 5.625e-3).abs() < 1e-12);
    let b1 = window_bands(&c1);
    assert!((b1[1].2 - 6.25e-3).abs() < 1e-12);
    // the narrow band reaches down through the wide one; the wide one stops at the lip edge
    let lip_rho = (96.25e-3f64.powi(2) - 5.625e-3f64.powi(2)).sqrt();
    assert!((b0[0].1 - lip_rho).abs() < 1e-12 && b0[1].0 == b0[0].0);
    let settings = CalculixSettings::default();
    let (g0, g1) = (geo_script(&c0, &settings), geo_script(&c1, &settings));
    assert_ne!(g0, g1);
    assert!(g0.contains("window[1]") && g0.contains(&format!("{:e}", -5.625e-3)));
}
