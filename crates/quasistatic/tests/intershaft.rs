//! SPEC V-18 / §5.7 (seed 001): trends of the intershaft bearing 55-2672919Р5 — whose geometry
//! the seed does not give; `studies::intershaft_bearing` documents the stand-in used here —
//! with F_r = 50 N, rings at 47.3 / 43 °C, mounting clearance 0.043 mm and the seed 001
//! friction model (IPM-10 with assumed data).

mod common;

use rolldyn_quasistatic::studies::{self, StudyRow};
use rolldyn_quasistatic::{QuasiStaticOptions, solve};

fn print(rows: &[StudyRow], title: &str) {
    println!("{title}");
    println!(
        "| n_в, rpm | n_н, rpm | F_r, N | ε₀ | ω₀/ω₀₀ | G_op, µm | max |ε_w| (outer) | max s_i |"
    );
    for r in rows {
        let s = r.cage_slip.unwrap();
        println!(
            "| {:.0} | {:.0} | {} | {:.4} | {:.4} | {:.1} | {:.1e} | {:.3} |",
            r.inner_speed_rpm,
            r.outer_speed_rpm,
            r.radial_load_n,
            s,
            1.0 - s,
            r.operating_clearance_m.unwrap() * 1e6,
            r.max_outer_slide_roll.unwrap(),
            r.max_inner_slide_roll.unwrap(),
        );
    }
}

#[test]
fn v18_slip_grows_with_rotor_slip_cage_faster_than_epicyclic() {
    let b = studies::intershaft_bearing();
    let slips = [1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 6000.0, 7000.0];
    for load in [50.0, 500.0] {
        let rows = studies::intershaft_rotor_slip(&b, &slips, load, &QuasiStaticOptions::default());
        print(
            &rows,
            &format!("V-18 (a): n_н = 13 067 rpm, F_r = {load} N"),
        );
        assert!(rows.iter().all(|r| r.error.is_none()));
        let mut last = 0.0;
        for r in &rows {
            let s = r.cage_slip.unwrap();
            // the cage runs faster than epicyclic: negative slip
            assert!(s < 0.0, "{r:?}");
            // |ε₀| grows monotonically with the rotor slip (seed 001 Fig. 3)
            assert!(s.abs() > last, "{r:?}");
            last = s.abs();
            // the rollers roll on the driving outer ring with almost no slip
            assert!(r.max_outer_slide_roll.unwrap() < 5e-3, "{r:?}");
            assert!(r.max_outer_slide_roll.unwrap() < 0.1 * r.max_inner_slide_roll.unwrap());
        }
    }
}

#[test]
fn v18_slip_falls_with_radial_load() {
    let b = studies::intershaft_bearing();
    let loads = [50.0, 100.0, 200.0, 400.0, 800.0, 1600.0];
    let rows = studies::intershaft_load(&b, &loads, &QuasiStaticOptions::default());
    print(
        &rows,
        "V-18 (d): n_в = 5180 rpm, n_н = 11 313 rpm, outer ring 33 °C",
    );
    let mut last = f64::INFINITY;
    for r in &rows {
        let s = r.cage_slip.unwrap();
        assert!(s < 0.0);
        assert!(s.abs() <= last, "{r:?}");
        last = s.abs();
    }
    assert!(rows.last().unwrap().cage_slip.unwrap().abs() < 0.1 * rows[0].cage_slip.unwrap().abs());
}

#[test]
fn v18_all_rollers_drive_the_cage() {
    // seed 001: "in an intershaft bearing all rollers (even in the unloaded zone) are driving"
    let b = studies::intershaft_bearing();
    let c = studies::intershaft_conditions(8152.0, 13_067.0, 500.0);
    let r = solve(&b, &c, &QuasiStaticOptions::default()).unwrap();
    common::assert_finite(&r);
    let unloaded: Vec<_> = r
        .rollers
        .iter()
        .filter(|x| x.inner.normal_force_n == 0.0)
        .collect();
    assert!(!unloaded.is_empty());
    assert!(unloaded.iter().all(|x| x.bar.push_n > 0.0));
    assert!(
        r.cage.land_torque_n_m > 0.0,
        "the land of the faster outer ring drives the cage"
    );
    assert_eq!(r.roller_slip_reference, "outer");
}
