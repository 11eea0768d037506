//! Benchmarks of the Boussinesq contact solver (seed 004 Table 2 grid, SPEC §2.5 / V-01).
//!
//! (a) 350 × 9 square cells of 0.0214 mm (Table 2 finest grid), crowned roller, Q = 1167 N
//!     (flag F-08), force-controlled. Target ≤ 20 ms.
//! (b) 1024 × 64 cells over 7.6 mm × 0.4 mm, same gap, Q = 1167 N. Target ≤ 0.3 s.
//! (c) 4096 × 256 cells over the same extent (issue 40 item 5), in its own group of ten
//!     samples without warm-up: about ten solves of a few seconds each.

use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_contact::boussinesq::{
    BoussinesqOptions, BoussinesqSolver, ConvolutionMode, Convolver, Grid, InfluenceTable,
    combined_compliance,
};
use std::hint::black_box;
use std::time::Duration;

const R_RED: f64 = 3.139e-3; // R' roller Ø7.5 mm / inner raceway Ø38.5 mm (SPEC V-04)

/// Crowned roller 7.5 mm: straight 4 mm, circular crown with 3.2 µm drop at |x| = 3.25 mm,
/// chamfer arc R 0.6 mm to the ends; 1 mm gap beyond the ends.
fn crowned_drop(x: f64) -> f64 {
    let (lc2, xc, drop_c, rf, half) = (2.0e-3, 3.25e-3, 3.2e-6, 0.6e-3, 3.75e-3);
    let ax = x.abs();
    let rc = (xc - lc2) * (xc - lc2) / (2.0 * drop_c);
    if ax <= lc2 {
        0.0
    } else if ax <= xc {
        (ax - lc2) * (ax - lc2) / (2.0 * rc)
    } else if ax <= half {
        let d = ax - xc;
        drop_c + d * (xc - lc2) / rc + rf - (rf * rf - d * d).sqrt()
    } else {
        1e-3
    }
}

fn case(c: &mut Criterion, name: &str, grid: Grid, q: f64) {
    let gap = grid.eval(|x, y| crowned_drop(x) + y * y / (2.0 * R_RED));
    let compliance = combined_compliance(201e9, 0.3, 201e9, 0.3);
    let mut solver = BoussinesqSolver::new(grid, compliance, BoussinesqOptions::default()).unwrap();
    let sol = solver.solve_force(&gap, q).unwrap();
    println!(
        "{name}: {}x{} cells, mode {:?}, nfx {}, iterations {}, convolutions {}, converged {}, residual {:.1e}, \
         approach {:.5} mm, p_max {:.0} MPa, p_mid {:.0} MPa, contact cells {}",
        grid.nx,
        grid.ny,
        solver.convolution_mode(),
        solver_fft_len(&solver),
        sol.iterations,
        sol.convolutions,
        sol.converged,
        sol.residual,
        sol.approach_m * 1e3,
        sol.max_pressure_pa * 1e-6,
        sol.pressure_at_middle() * 1e-6,
        sol.cells_in_contact
    );
    c.bench_function(name, |b| {
        b.iter(|| black_box(solver.solve_force(black_box(&gap), q).unwrap().iterations))
    });
}

fn solver_fft_len(s: &BoussinesqSolver) -> usize {
    let g = s.grid();
    rolldyn_contact::boussinesq::convolution::fast_fft_len(2 * g.nx - 1)
}

fn benches(c: &mut Criterion) {
    let side = 0.0214e-3;
    case(
        c,
        "boussinesq_350x9_table2_1167N",
        Grid::centered(350, 9, side, side).unwrap(),
        1167.0,
    );
    case(
        c,
        "boussinesq_1024x64_1167N",
        Grid::centered_extent(1024, 64, 7.6e-3, 0.4e-3).unwrap(),
        1167.0,
    );
}

fn large_grid(c: &mut Criterion) {
    case(
        c,
        "boussinesq_4096x256_1167N",
        Grid::centered_extent(4096, 256, 7.6e-3, 0.4e-3).unwrap(),
        1167.0,
    );
}

/// One `u = f * p` evaluation, both modes (used to choose `AUTO_DIRECT_Y_MAX_NY`).
fn convolutions(c: &mut Criterion) {
    let compliance = combined_compliance(201e9, 0.3, 201e9, 0.3);
    for &(nx, ny) in &[
        (350, 3),
        (350, 5),
        (350, 9),
        (1024, 16),
        (1024, 24),
        (1024, 32),
        (1024, 64),
    ] {
        let grid = Grid::centered_extent(nx, ny, 7.6e-3, 0.4e-3).unwrap();
        let table = InfluenceTable::new(&grid, compliance);
        let p: Vec<f64> = (0..grid.len()).map(|k| 1e9 * ((k % 7) as f64)).collect();
        let mut u = vec![0.0; grid.len()];
        for mode in [ConvolutionMode::FftXDirectY, ConvolutionMode::Fft2d] {
            let mut conv = Convolver::new(&table, mode);
            c.bench_function(&format!("convolution_{nx}x{ny}_{mode:?}"), |b| {
                b.iter(|| conv.apply(black_box(&p), &mut u))
            });
        }
    }
}

criterion_group! {
    name = group;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = benches, convolutions
}
criterion_group! {
    name = large;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(1))
        .measurement_time(Duration::from_secs(1));
    targets = large_grid
}
criterion_main!(group, large);
