//! Benchmarks of the slice evaluation (SPEC §2.1) used in the dynamics inner loop.
//!
//! Budget: one evaluation of a 30-slice roller (slice forces into a buffer + Q, M and the 2×2
//! Jacobian) ≤ 1 µs. The inverse solvers are measured for information.

use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_contact::slices::{SliceLaw, SlicedRoller, SolveOptions};
use std::hint::black_box;

/// Crowned roller 7.5 mm: straight 4 mm, quadratic crown to 3.2 µm at the ends.
fn crown(x: f64) -> f64 {
    let a = x.abs();
    if a <= 2e-3 {
        0.0
    } else {
        3.2e-6 * ((a - 2e-3) / 1.75e-3).powi(2)
    }
}

fn inner_law() -> SliceLaw {
    SliceLaw::InnerRing {
        pitch_diameter: 46.0e-3,
        youngs_modulus: 201e9,
        poisson_ratio: 0.3,
    }
}

fn bench_slices(c: &mut Criterion) {
    let roller = SlicedRoller::uniform(inner_law(), 7.5e-3, 30, crown).unwrap();
    let iso = SlicedRoller::uniform(
        SliceLaw::IsoTs16281 {
            effective_length: 7.5e-3,
        },
        7.5e-3,
        30,
        crown,
    )
    .unwrap();
    let hertz15 = SlicedRoller::uniform(
        SliceLaw::Power {
            k_p: 3e9,
            exponent: 1.5,
        },
        7.5e-3,
        30,
        crown,
    )
    .unwrap();
    let mut forces = vec![0.0; 30];

    c.bench_function("slices/evaluate_30_full_load", |b| {
        b.iter(|| {
            black_box(roller.evaluate(black_box(6e-6), black_box(2e-4), black_box(&mut forces[..])))
        })
    });
    c.bench_function("slices/evaluate_30_partial_load", |b| {
        b.iter(|| {
            black_box(roller.evaluate(
                black_box(2e-6),
                black_box(2.5e-3),
                black_box(&mut forces[..]),
            ))
        })
    });
    c.bench_function("slices/evaluate_totals_30", |b| {
        b.iter(|| black_box(roller.evaluate_totals(black_box(6e-6), black_box(2e-4))))
    });
    c.bench_function("slices/evaluate_30_iso_ts_16281", |b| {
        b.iter(|| {
            black_box(iso.evaluate(black_box(6e-6), black_box(2e-4), black_box(&mut forces[..])))
        })
    });
    c.bench_function("slices/evaluate_30_power_1_5", |b| {
        b.iter(|| {
            black_box(hertz15.evaluate(
                black_box(6e-6),
                black_box(2e-4),
                black_box(&mut forces[..]),
            ))
        })
    });

    let opts = SolveOptions::default();
    let fwd = roller.evaluate_totals(3e-6, 1.5e-3);
    c.bench_function("slices/solve_approach_1d_30", |b| {
        b.iter(|| {
            black_box(
                roller
                    .solve_approach(black_box(fwd.force), black_box(1.5e-3), &opts)
                    .unwrap(),
            )
        })
    });
    c.bench_function("slices/solve_approach_tilt_2d_30", |b| {
        b.iter(|| {
            black_box(
                roller
                    .solve_approach_tilt(black_box(fwd.force), black_box(fwd.moment), &opts)
                    .unwrap(),
            )
        })
    });
}

criterion_group!(benches, bench_slices);
criterion_main!(benches);
