//! Benchmarks of the quasi-static model (issue budget: one operating point ≤ 5 ms on one
//! core, a 100-point map ≤ 0.5 s).
//!
//! * `point/obrien-taylor` — O'Brien–Taylor bearing (13 rollers, 30 slices), 4000 rpm, 201 N,
//!   NVI 65 seed 000 traction (SPEC V-06), with scuffing margins;
//! * `point/intershaft` — intershaft stand-in (28 rollers, 20 slices), 8152/13 067 rpm, 500 N,
//!   seed 001 friction with the Blok flash-temperature iteration, with scuffing margins;
//! * `map/obrien-taylor-100` — 10 speeds × 10 loads, plain loop warm-started along each load
//!   series (what `rolldyn skid` sweeps do);
//! * `load-distribution/2002834-8arcmin` — the frictionless load distribution alone (18 rollers,
//!   30 slices, 8′ misalignment: 2-D roller equilibria).

use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_contact::roller_raceway::SliceLawChoice;
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use rolldyn_quasistatic::studies::{self, NviTraction};
use rolldyn_quasistatic::{LoadCase, LoadModel, QuasiStaticOptions, rpm, solve};
use std::hint::black_box;
use std::time::Duration;

fn example(name: &str) -> CylindricalRollerBearing {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    match rolldyn_model::load(&path).expect("example model").bearing {
        BearingModel::Cylindrical(b) => b,
        _ => panic!("{name} is not a cylindrical bearing"),
    }
}

fn bench(c: &mut Criterion) {
    let ot = studies::obrien_taylor_bearing(&example("obrien-taylor.toml"));
    let opts = QuasiStaticOptions::default();
    let cond = studies::obrien_taylor_conditions(4000.0, 201.0, 0.0, NviTraction::Seed000Elastic);
    c.bench_function("point/obrien-taylor", |b| {
        b.iter(|| solve(black_box(&ot), black_box(&cond), &opts).unwrap())
    });

    let is = studies::intershaft_bearing();
    let cond_is = studies::intershaft_conditions(8152.0, 13_067.0, 500.0);
    c.bench_function("point/intershaft", |b| {
        b.iter(|| solve(black_box(&is), black_box(&cond_is), &opts).unwrap())
    });

    let speeds: Vec<f64> = (0..10).map(|k| 1500.0 + 333.3 * k as f64).collect();
    let loads: Vec<f64> = (0..10).map(|k| 104.0 + 64.8 * k as f64).collect();
    c.bench_function("map/obrien-taylor-100", |b| {
        b.iter(|| {
            let mut slips = 0.0;
            for &n in &speeds {
                let mut o = opts.clone();
                for &f in &loads {
                    let mut cd =
                        studies::obrien_taylor_conditions(n, f, 0.0, NviTraction::Seed000Elastic);
                    cd.inner_speed_rad_s = rpm(n);
                    let r = solve(&ot, &cd, &o).unwrap();
                    o.initial_cage_slip = r.cage_slip;
                    slips += r.cage_slip;
                }
            }
            slips
        })
    });

    let b2002834 = example("2002834.toml");
    let model = LoadModel::new(&b2002834, SliceLawChoice::Seed).unwrap();
    let case = LoadCase {
        radial_load_n: 5000.0,
        diametral_clearance_m: 9e-6,
        misalignment_rad: (8.0f64 / 60.0).to_radians(),
        misalignment_azimuth_rad: 0.0,
        centrifugal_force_n: 50.0,
        roller_phase_rad: 0.0,
    };
    c.bench_function("load-distribution/2002834-8arcmin", |b| {
        b.iter(|| model.solve(black_box(&case), None, &opts).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    targets = bench
}
criterion_main!(benches);
