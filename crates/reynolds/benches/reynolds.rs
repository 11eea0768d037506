//! Benchmarks of the Reynolds solvers (issue 4 performance targets):
//! (a) journal bearing 120 × 40 with Reynolds cavitation, ε = 0.6, L/D = 1 — target ≤ 15 ms
//!     (an established Python + numba solver needs ≈ 0.16 s at 101 × 41 on one core here);
//!     also 101 × 41 and 201 × 81, JFO, the equilibrium search and the K/C coefficients;
//! (b) full EHL line contact, 1000 nodes, 3×10⁵ N/m (p_h = 1.0 GPa) — target ≤ 100 ms;
//! (c) cage–land force evaluation — target ≤ 1 µs.
//! A grid-convergence table with times is printed first.

use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_reynolds::cage_land::{CageLand, CageLandGeometry, CageLandOptions, LandPosition};
use rolldyn_reynolds::compliance::half_space::HalfSpace;
use rolldyn_reynolds::journal::{
    JournalBearing, JournalOperating, JournalOptions, solve_eccentricity, solve_load, study,
};
use rolldyn_reynolds::line_contact::{
    self, Compliance, Constraint, LineContactOptions, LubricatedLineContact,
};
use rolldyn_reynolds::{Cavitation, Density, Isoviscous, Roelands};
use std::hint::black_box;
use std::time::Duration;

fn tables() {
    println!("journal grid convergence (L/D = 1, ε = 0.6; Raimondi–Boyd S = 0.121):");
    println!(
        "{:>9} {:>9} {:>8} {:>8} {:>8} {:>6} {:>9}",
        "grid", "S", "phi_deg", "(R/c)f", "Qs", "iters", "time_ms"
    );
    if let Ok(rows) = study::grid_convergence(
        &[1.0],
        &[0.6],
        &[(60, 21), (101, 41), (120, 40), (201, 81), (240, 81)],
    ) {
        for r in rows {
            println!(
                "{:>4}x{:<4} {:>9.5} {:>8.3} {:>8.4} {:>8.4} {:>6} {:>9.2}",
                r.grid.0,
                r.grid.1,
                r.sommerfeld,
                r.attitude_deg,
                r.friction_variable,
                r.side_flow_variable,
                r.iterations,
                r.solve_time_s * 1e3
            );
        }
    }
    println!("line-contact grid convergence:");
    if let Ok(rows) = line_contact::study::grid_convergence(&[250, 500, 1000, 2000]) {
        for r in rows {
            println!(
                "{:<28} n={:>5} W={:>11.5e} pmax={:>11.5e} hmin={:>11.5e} hc={:>11.5e} xc={:>11.5e} it={:>3} {:>8.2} ms",
                r.case,
                r.nodes,
                r.load_per_length_n_per_m,
                r.max_pressure_pa,
                r.min_film_m,
                r.central_film_m,
                r.outlet_position_m,
                r.iterations,
                r.solve_time_s * 1e3
            );
        }
    }
}

fn journal(c: &mut Criterion) {
    tables();
    let b = JournalBearing::new(0.025, 0.05, 50e-6);
    let op = JournalOperating::rpm(3000.0, 313.15);
    let v = Isoviscous { mu: 0.05 };
    let mut g = c.benchmark_group("journal");
    g.sample_size(20).measurement_time(Duration::from_secs(4));
    for (nt, nz) in [(101, 41), (120, 40), (201, 81)] {
        let opt = JournalOptions {
            n_circumferential: nt,
            n_axial: nz,
            coefficients: false,
            ..Default::default()
        };
        g.bench_function(format!("reynolds_cavitation_{nt}x{nz}"), |bch| {
            bch.iter(|| black_box(solve_eccentricity(&b, &v, &op, 0.6, &opt).unwrap().load_n))
        });
    }
    let opt = JournalOptions::default();
    g.bench_function("reynolds_cavitation_120x40_with_KC", |bch| {
        bch.iter(|| black_box(solve_eccentricity(&b, &v, &op, 0.6, &opt).unwrap().load_n))
    });
    let jfo = JournalOptions {
        cavitation: Cavitation::Jfo,
        coefficients: false,
        ..Default::default()
    };
    g.bench_function("jfo_120x40", |bch| {
        bch.iter(|| black_box(solve_eccentricity(&b, &v, &op, 0.6, &jfo).unwrap().load_n))
    });
    let w = solve_eccentricity(&b, &v, &op, 0.6, &jfo).unwrap().load_n;
    let nc = JournalOptions {
        coefficients: false,
        ..Default::default()
    };
    g.bench_function("load_mode_120x40", |bch| {
        bch.iter(|| black_box(solve_load(&b, &v, &op, w, &nc).unwrap().eccentricity))
    });
    g.finish();
}

fn ehl(c: &mut Criterion) {
    let mut ct = LubricatedLineContact::new(0.01, 2.0);
    ct.compliance = Compliance::HalfSpace(HalfSpace::pair(2.06e11, 0.3, 2.06e11, 0.3, 1.0));
    ct.density = Density::DowsonHigginson;
    let vis = Roelands::from_alpha(0.04, 2e-8);
    let opt = LineContactOptions {
        damping: false,
        ..Default::default()
    };
    let mut g = c.benchmark_group("line_contact");
    g.sample_size(10).measurement_time(Duration::from_secs(6));
    g.bench_function("ehl_1000_nodes_3e5_n_per_m", |bch| {
        bch.iter(|| {
            black_box(
                line_contact::solve(&ct, &vis, Constraint::LoadPerLength(3e5), &opt)
                    .unwrap()
                    .min_film_m,
            )
        })
    });
    let rigid = LubricatedLineContact::new(0.005, 7.0);
    g.bench_function("rigid_1000_nodes_with_damping", |bch| {
        bch.iter(|| {
            black_box(
                line_contact::solve(
                    &rigid,
                    &Isoviscous { mu: 0.024 },
                    Constraint::MinFilm(1e-6),
                    &LineContactOptions::default(),
                )
                .unwrap()
                .load_per_length_n_per_m,
            )
        })
    });
    g.finish();
}

fn cage(c: &mut Criterion) {
    let geom = CageLandGeometry {
        radius: 0.05,
        width: 0.01,
        clearance: 1e-4,
        position: LandPosition::OuterRing,
    };
    let model = CageLand::new(geom, &CageLandOptions::default()).unwrap();
    let mut k = 0u64;
    c.bench_function("cage_land_evaluate", |bch| {
        bch.iter(|| {
            k = k.wrapping_add(1);
            let t = (k % 1000) as f64 * 1e-3;
            black_box(model.evaluate(
                black_box([0.6e-4 * t.cos(), 0.3e-4 * t.sin()]),
                black_box([1e-3 * t, -2e-3]),
                black_box(520.0),
                black_box(0.0),
                black_box(0.01),
            ))
        })
    });
}

criterion_group!(benches, journal, ehl, cage);
criterion_main!(benches);
