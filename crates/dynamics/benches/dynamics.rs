#![allow(clippy::field_reassign_with_default, clippy::needless_range_loop)]
//! Dynamics benchmarks (2002834, 18 rollers × 10 slices, 6371 rpm, 500 N, EHL traction with the
//! PAO VG 320 Muraki model): right-hand-side cost with EHL traction and with a trivial
//! two-level law (the difference is the traction share), and simulated time per wall time with
//! both integrators (DOPRI5 at its default τ = 1e-6, Rosenbrock-W at τ = 1e-5, the tolerance at
//! which it matches DOPRI5's accuracy in the start phase — docs/dynamics-integrator.md).

use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_dynamics::*;
use rolldyn_lubrication::traction::{FrictionLaw, TractionConfig, TwoLevelLaw};
use rolldyn_lubrication::{TractionModel, lubricant_by_name};
use std::hint::black_box;

fn bearing() -> rolldyn_geometry::CylindricalRollerBearing {
    let mut b = rolldyn_model::default_cylindrical_bearing();
    b.roller.slice_count = 10;
    b
}

fn sim(traction: TractionModel) -> Simulation {
    sim_with(traction, IntegratorMethod::Dopri5, None)
}

/// `tolerance`: `None` → the method's benchmark tolerance (DOPRI5 default 1e-6, W-method 1e-5).
fn sim_with(
    traction: TractionModel,
    method: IntegratorMethod,
    tolerance: Option<f64>,
) -> Simulation {
    let b = bearing();
    let mut cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut set = DynamicsSettings::default();
    set.output_step_s = 0.0;
    set.integrator.method = method;
    if method == IntegratorMethod::RosenbrockW {
        set.integrator.tolerance = 1e-5;
    }
    if let Some(tol) = tolerance {
        set.integrator.tolerance = tol;
    }
    Simulation::new(
        &b,
        cond,
        ContactParameters::for_bearing(&b),
        set,
        RacewayTraction::same(traction),
    )
    .unwrap()
}

fn ehl() -> TractionModel {
    TractionModel::muraki(lubricant_by_name("pao1-vg320").unwrap()).unwrap()
}

fn bench(c: &mut Criterion) {
    let mut s = sim(ehl());
    // leave the exact start state: 2 ms of running
    s.run_until(2e-3, &mut NullSink, &mut |_| {}).unwrap();
    let mut dy = vec![0.0; s.state().len()];
    c.bench_function("rhs_2002834_18x10_ehl", |b| {
        b.iter(|| s.evaluate_derivative(black_box(&mut dy)))
    });
    let two = TractionModel::new(TractionConfig {
        oil: None,
        law: FrictionLaw::TwoLevel(TwoLevelLaw {
            mu_s: 0.05,
            mu_d: 0.05,
            v_s: 1e-2,
            v_d: 2e-2,
        }),
        ..TractionConfig::default()
    })
    .unwrap();
    let mut s2 = sim(two);
    s2.run_until(2e-3, &mut NullSink, &mut |_| {}).unwrap();
    c.bench_function("rhs_2002834_18x10_two_level", |b| {
        b.iter(|| s2.evaluate_derivative(black_box(&mut dy)))
    });
    let mut g = c.benchmark_group("simulate");
    g.sample_size(10);
    g.bench_function("2002834_6371rpm_10ms", |b| {
        b.iter(|| {
            let mut s = sim(ehl());
            let r = s.run_until(0.01, &mut NullSink, &mut |_| {}).unwrap();
            black_box(r.steps)
        })
    });
    g.bench_function("2002834_6371rpm_10ms_rosenbrock_w", |b| {
        b.iter(|| {
            let mut s = sim_with(ehl(), IntegratorMethod::RosenbrockW, None);
            let r = s.run_until(0.01, &mut NullSink, &mut |_| {}).unwrap();
            black_box(r.steps)
        })
    });
    g.finish();
    // one longer run per method for the headline figure, and DOPRI5 at τ = 1e-5 (the accuracy
    // trade-off of docs/dynamics-integrator.md)
    for (method, tolerance) in [
        (IntegratorMethod::Dopri5, None),
        (IntegratorMethod::Dopri5, Some(1e-5)),
        (IntegratorMethod::RosenbrockW, None),
    ] {
        headline(method, tolerance);
    }
}

fn headline(method: IntegratorMethod, tolerance: Option<f64>) {
    let mut s = sim_with(ehl(), method, tolerance);
    let r = s.run_until(0.04, &mut NullSink, &mut |_| {}).unwrap();
    println!(
        "{method:?} τ = {tolerance:?}: 2002834 6371 rpm, 0.04 s simulated: wall {:.2} s → simulated/wall = {:.3}; {} steps ({} rejected), {} RHS, {} Jacobians, mean step {:.2} µs, most limiting: {:?}",
        r.wall_time_s,
        r.simulated_time_s / r.wall_time_s,
        r.steps,
        r.rejected_steps,
        r.rhs_evaluations,
        s.stats().jacobian_evaluations,
        1e6 * r.simulated_time_s / r.steps as f64,
        s.most_limiting_component()
    );
    println!("summary: {r:?}");
}

criterion_group!(benches, bench);
criterion_main!(benches);
