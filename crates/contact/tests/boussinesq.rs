//! Tests of the Boussinesq / modified-Hartnett contact solver (seed 004, SPEC §2.5, V-05).
//!
//! Each tolerance is stated and justified next to its assertion.

use rolldyn_contact::boussinesq::dense::{solve_approach_dense, solve_force_dense};
use rolldyn_contact::boussinesq::influence::influence_coefficient_log;
use rolldyn_contact::boussinesq::{
    BoussinesqOptions, BoussinesqSolver, ConvolutionMode, Convolver, Grid, InfluenceTable,
    StopRule, combined_compliance, direct_convolution, influence_coefficient,
};

/// Counts heap allocations of the current thread (tests run in parallel threads).
struct CountingAlloc;

thread_local! {
    static ALLOCS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

unsafe impl std::alloc::GlobalAlloc for CountingAlloc {
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        let _ = ALLOCS.try_with(|c| c.set(c.get() + 1));
        unsafe { std::alloc::System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: std::alloc::Layout) {
        unsafe { std::alloc::System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: std::alloc::Layout, size: usize) -> *mut u8 {
        let _ = ALLOCS.try_with(|c| c.set(c.get() + 1));
        unsafe { std::alloc::System.realloc(ptr, layout, size) }
    }
}

#[global_allocator]
static GLOBAL: CountingAlloc = CountingAlloc;

fn allocations() -> usize {
    ALLOCS.with(|c| c.get())
}

const E: f64 = 201e9;
const NU: f64 = 0.3;

fn compliance() -> f64 {
    combined_compliance(E, NU, E, NU)
}

/// Deterministic pseudo-random numbers in [0, 1) (64-bit LCG, high bits).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// Crowned roller of length 7.5 mm (like [004] profile no. 2): straight 4 mm, circular crown
/// with 3.2 µm drop at |x| = 3.25 mm, then a 0.6 mm chamfer arc; 1 mm gap beyond the ends.
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

const R_RED: f64 = 3.139e-3; // R' of roller Ø7.5 on raceway Ø38.5 (SPEC V-04)

fn roller_gap(x: f64, y: f64) -> f64 {
    crowned_drop(x) + y * y / (2.0 * R_RED)
}

fn rel_max_diff(a: &[f64], b: &[f64]) -> f64 {
    let m = b.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0_f64, |d, (x, y)| d.max((x - y).abs()))
        / m
}

#[test]
fn influence_asinh_equals_seed_log_form_and_is_symmetric() {
    let c = compliance();
    let (b, a) = (0.75e-5, 1.25e-5); // rectangular cell: 15 µm (x) × 25 µm (y)
    let pts = [
        (0.0, 0.0),
        (0.3e-5, 0.1e-5),
        (2.0e-5, 0.0),
        (0.0, 7.5e-5),
        (1.5e-5, 5.0e-5),
        (3.7e-4, 1.1e-4),
        (1.0e-3, 2.5e-5),
    ];
    let mut worst = 0.0_f64;
    for &(x, y) in &pts {
        let f = influence_coefficient(x, y, b, a, c);
        let fl = influence_coefficient_log(x, y, b, a, c);
        worst = worst.max(((f - fl) / fl).abs());
        // Same closed form, different grouping of logs: agreement to round-off. The far
        // point (1 mm ≈ 70 cells) loses ~3 digits to cancellation in the corner sum, so
        // 1e-11 relative is the justified bound (observed ≤ 1e-13 near, ~1e-12 far).
        assert!(
            ((f - fl) / fl).abs() < 1e-11,
            "({x}, {y}): asinh {f} vs log {fl}"
        );
        // f is even in x̄ and ȳ (exactly, by construction of the corner function).
        for (sx, sy) in [(-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
            let g = influence_coefficient(sx * x, sy * y, b, a, c);
            assert!(((g - f) / f).abs() < 1e-14, "symmetry at ({x}, {y})");
        }
        assert!(f.is_finite() && f > 0.0);
    }
    println!("asinh vs log form: max rel. difference {worst:.1e}");
    // Self term finite and equal to Johnson's closed form for a rectangle:
    // f(0,0) = 2C [b asinh(a/b) + a asinh(b/a)]·2.
    let f00 = influence_coefficient(0.0, 0.0, b, a, c);
    let j = 4.0 * c * (b * (a / b).asinh() + a * (b / a).asinh());
    assert!(((f00 - j) / j).abs() < 1e-14);
    // Far field → point load C·ΔS/r (relative error O((cell/r)²) ≈ 1e-4 at 100 cells).
    let r: f64 = 1.5e-3;
    let far = influence_coefficient(r, 0.0, b, a, c);
    assert!((far / (c * 4.0 * a * b / r) - 1.0).abs() < 1e-4);
}

#[test]
fn fft_convolution_equals_direct_sum() {
    let c = compliance();
    let mut seed = 42;
    let mut worst = 0.0_f64;
    for &(nx, ny) in &[
        (1, 1),
        (7, 1),
        (1, 6),
        (10, 4),
        (13, 5),
        (16, 9),
        (33, 30),
        (24, 27),
    ] {
        let grid = Grid::centered(nx, ny, 2.0e-5, 3.0e-5).unwrap();
        let table = InfluenceTable::new(&grid, c);
        let p: Vec<f64> = (0..grid.len()).map(|_| 1e9 * lcg(&mut seed)).collect();
        let mut u_dir = vec![0.0; grid.len()];
        direct_convolution(&table, &p, &mut u_dir);
        for mode in [ConvolutionMode::Fft2d, ConvolutionMode::FftXDirectY] {
            let mut conv = Convolver::new(&table, mode);
            let mut u = vec![0.0; grid.len()];
            conv.apply(&p, &mut u);
            // Twice to check that no state leaks between calls.
            conv.apply(&p, &mut u);
            let e = rel_max_diff(&u, &u_dir);
            worst = worst.max(e);
            // FFT round-off is O(ε log N) ≈ 1e-15; the linear (zero-padded) convolution is
            // exact, so any wrap-around error would show up as O(1e-2).
            assert!(e < 1e-12, "{nx}x{ny} {mode:?}: rel. error {e:e}");
        }
    }
    println!("FFT vs direct convolution: max rel. error {worst:.1e}");
}

/// Options converging far below the default tolerance, for the comparisons with exact
/// references (dense solution, mutual inverses) whose bounds assume a fully converged CG.
fn tight() -> BoussinesqOptions {
    BoussinesqOptions {
        stop: StopRule::RelativeGap(1e-10),
        ..Default::default()
    }
}

fn small_grid(nx: usize, ny: usize) -> Grid {
    // Whole roller length along x, ±0.1 mm across (Hertz half-width ≈ 0.075 mm at 1167 N).
    Grid::centered_extent(nx, ny, 7.6e-3, 0.2e-3).unwrap()
}

#[test]
fn cg_equals_dense_reference_force_mode() {
    for &(nx, ny, q) in &[(21, 7, 1167.0), (40, 9, 1167.0), (40, 9, 300.0)] {
        let grid = small_grid(nx, ny);
        let gap = grid.eval(roller_gap);
        let mut s = BoussinesqSolver::new(grid, compliance(), tight()).unwrap();
        let cg = s.solve_force(&gap, q).unwrap();
        let dense = solve_force_dense(&grid, s.influence_table(), &gap, q, 1e-13).unwrap();
        assert!(cg.converged && dense.converged);
        let ep = rel_max_diff(&cg.pressure, &dense.pressure);
        let ea = (cg.approach_m / dense.approach_m - 1.0).abs();
        let ef = (cg.force_n / dense.force_n - 1.0).abs();
        println!(
            "{nx}x{ny} Q={q}: it {} p err {ep:.2e} alpha err {ea:.2e} force err {ef:.2e} res {:.1e}",
            cg.iterations, cg.residual
        );
        // Both solve the same discrete LCP; CG stops at a relative gap < 1e-10, dense
        // is exact to round-off: 1e-6 relative leaves a wide margin (observed < 1e-9).
        assert!(ep < 1e-6 && ea < 1e-6 && ef < 1e-6, "{nx}x{ny}");
    }
}

#[test]
fn cg_equals_dense_reference_approach_mode() {
    for &(nx, ny, alpha) in &[(21, 7, 5.0e-6), (40, 9, 5.5e-6), (40, 9, 2.0e-6)] {
        let grid = small_grid(nx, ny);
        let gap = grid.eval(roller_gap);
        let mut s = BoussinesqSolver::new(grid, compliance(), tight()).unwrap();
        let cg = s.solve_approach(&gap, alpha).unwrap();
        let dense = solve_approach_dense(&grid, s.influence_table(), &gap, alpha).unwrap();
        assert!(cg.converged && dense.converged);
        let ep = rel_max_diff(&cg.pressure, &dense.pressure);
        let ef = (cg.force_n / dense.force_n - 1.0).abs();
        println!(
            "{nx}x{ny} alpha={alpha}: it {} Q {:.2} p err {ep:.2e} force err {ef:.2e}",
            cg.iterations, cg.force_n
        );
        // Same justification as the force-mode test.
        assert!(ep < 1e-6 && ef < 1e-6, "{nx}x{ny}");
    }
}

#[test]
fn v05_sphere_on_flat_matches_hertz() {
    // SPEC V-05: R = 10 mm, Q = 100 N, E = 201 GPa, ν = 0.3 both bodies.
    let (r, q) = (10e-3, 100.0);
    let e_star = E / (2.0 * (1.0 - NU * NU));
    let a = (3.0 * q * r / (4.0 * e_star)).cbrt();
    let (delta_h, pmax_h) = (a * a / r, 3.0 * q / (2.0 * std::f64::consts::PI * a * a));
    assert!((delta_h / 3.586e-6 - 1.0).abs() < 1e-3);
    assert!((pmax_h / 1.331e9 - 1.0).abs() < 1e-3);
    // 65 × 65 square cells over ±1.25 a (a/dx ≈ 26); odd n puts a cell on the axis.
    let n = 65;
    let grid = Grid::centered_extent(n, n, 2.5 * a, 2.5 * a).unwrap();
    let gap = grid.eval(|x, y| (x * x + y * y) / (2.0 * r));
    let mut s = BoussinesqSolver::new(grid, compliance(), BoussinesqOptions::default()).unwrap();
    let sol = s.solve_force(&gap, q).unwrap();
    let ed = sol.approach_m / delta_h - 1.0;
    let ep = sol.max_pressure_pa / pmax_h - 1.0;
    let ea = (sol.contact_area_m2() / (std::f64::consts::PI * a * a)) - 1.0;
    println!(
        "V-05 {n}x{n}: it {} approach {:.4} um ({ed:+.2e}), pmax {:.4} GPa ({ep:+.2e}), area {ea:+.2e}",
        sol.iterations,
        sol.approach_m * 1e6,
        sol.max_pressure_pa * 1e-9
    );
    assert!(sol.converged);
    // Discretisation error of piecewise-constant cells at a/dx ≈ 26 is a few 1e-3; the
    // spec asks ≈ 1 %.
    assert!(ed.abs() < 0.01 && ep.abs() < 0.01);
    // Contact area: boundary cells are counted whole, error ~ 2dx/a ≈ 8 %.
    assert!(ea.abs() < 0.1);
    assert!((sol.pressure_at_middle() - sol.max_pressure_pa).abs() < 1e-6 * pmax_h);
}

#[test]
fn hertz_line_contact_mid_length() {
    // Straight cylinder, R' = 3.139 mm, length 4 mm, E = 201 GPa, ν = 0.3, Q = 622.4 N
    // (q = 155.6 N/mm, the 1167 N / 7.5 mm load): b ≈ 0.075 mm.
    let (len, q) = (4.0e-3, 1167.0 * 4.0 / 7.5);
    let e_prime = E / (1.0 - NU * NU);
    let grid = Grid::centered_extent(41, 41, len, 0.2e-3).unwrap(); // dy = 4.9 µm: 31 cells over 2b
    let gap = grid.eval(|_, y| y * y / (2.0 * R_RED));
    let mut s = BoussinesqSolver::new(grid, compliance(), BoussinesqOptions::default()).unwrap();
    let sol = s.solve_force(&gap, q).unwrap();
    assert!(sol.converged);
    let ic = grid.central_column();
    // Load per length carried by the middle slice (the ends of a straight roller carry more).
    let q_mid: f64 = (0..grid.ny).map(|j| sol.pressure_at(ic, j)).sum::<f64>() * grid.dy;
    let p_hertz = (q_mid * e_prime / (2.0 * std::f64::consts::PI * R_RED)).sqrt();
    let b_hertz = (8.0 * q_mid * R_RED / (std::f64::consts::PI * e_prime)).sqrt();
    let p_nominal = (q / len * e_prime / (2.0 * std::f64::consts::PI * R_RED)).sqrt();
    let rows_in_contact = (0..grid.ny)
        .filter(|&j| sol.pressure_at(ic, j) > 0.0)
        .count();
    let half_width_mid = 0.5 * rows_in_contact as f64 * grid.dy;
    let eb = half_width_mid / b_hertz - 1.0;
    let ep = sol.pressure_at_middle() / p_hertz - 1.0;
    println!(
        "line: it {} p_mid {:.2} MPa, Hertz(q_mid) {:.2} MPa ({ep:+.2e}), Hertz(Q/L) {:.2} MPa, \
         q_mid/(Q/L) {:.4}, mid half-width {:.4} vs Hertz {:.4} mm ({eb:+.2e}), max half-width {:.4} mm",
        sol.iterations,
        sol.pressure_at_middle() * 1e-6,
        p_hertz * 1e-6,
        p_nominal * 1e-6,
        q_mid / (q / len),
        half_width_mid * 1e3,
        b_hertz * 1e3,
        sol.max_half_width_m() * 1e3
    );
    // 31 cells across the Hertz width: collocation error of the peak well below 1 %;
    // the end effect on the *local* relation p(q_mid) is O((b/L)²) ≈ 3e-4.
    assert!(ep.abs() < 0.01);
    // Half-width from whole cells: ±1 cell (dy/b ≈ 6.5 %).
    assert!(eb.abs() < 0.07);
    assert!(!sol.touches_edge_y);
    // The ends of a straight roller carry more load (edge peaks): q_mid < Q/L.
    assert!(q_mid < q / len);
}

#[test]
fn force_and_approach_modes_are_mutual_inverses() {
    let grid = Grid::centered_extent(64, 15, 7.6e-3, 0.2e-3).unwrap();
    let gap = grid.eval(|x, y| roller_gap(x, y) + 1e-4 * x); // with a tilt term
    let mut s = BoussinesqSolver::new(grid, compliance(), tight()).unwrap();
    let f = s.solve_force(&gap, 1167.0).unwrap();
    let a = s.solve_approach(&gap, f.approach_m).unwrap();
    assert!(f.converged && a.converged);
    let ep = rel_max_diff(&a.pressure, &f.pressure);
    let ef = a.force_n / 1167.0 - 1.0;
    println!(
        "inverse: it {} / {}, alpha {:.4} um, force err {ef:.2e}, p err {ep:.2e}",
        f.iterations,
        a.iterations,
        f.approach_m * 1e6
    );
    // Both converge to a relative gap < 1e-10 on the same LCP: 1e-7 relative is ample.
    assert!(ef.abs() < 1e-7 && ep < 1e-7);
    // And back: the force solve reproduces the approach.
    let f2 = s.solve_force(&gap, a.force_n).unwrap();
    assert!((f2.approach_m / f.approach_m - 1.0).abs() < 1e-7);
}

#[test]
fn convolution_modes_give_same_solution_and_warm_start() {
    let grid = Grid::centered_extent(96, 11, 7.6e-3, 0.2e-3).unwrap();
    let gap = grid.eval(roller_gap);
    let mut sols = Vec::new();
    for mode in [ConvolutionMode::Fft2d, ConvolutionMode::FftXDirectY] {
        let opt = BoussinesqOptions {
            convolution: mode,
            ..tight()
        };
        let mut s = BoussinesqSolver::new(grid, compliance(), opt).unwrap();
        assert_eq!(s.convolution_mode(), mode);
        let sol = s.solve_force(&gap, 1167.0).unwrap();
        assert!(sol.converged);
        // Warm start from the converged field: the solution is already a fixed point.
        let warm = s
            .solve_force_with_guess(&gap, 1167.0, &sol.pressure)
            .unwrap();
        assert!(
            warm.converged && warm.iterations <= 3,
            "warm: {}",
            warm.iterations
        );
        // Both at a relative gap < 1e-10 on the same LCP.
        assert!(rel_max_diff(&warm.pressure, &sol.pressure) < 1e-8);
        sols.push(sol);
    }
    // Two evaluations of the same linear operator (differences ~1e-15): solutions agree to
    // the CG tolerance.
    assert!(rel_max_diff(&sols[0].pressure, &sols[1].pressure) < 1e-8);
    let s = &sols[0];
    // Derived outputs are consistent.
    assert!((s.mean_pressure_pa() * s.contact_area_m2() - 1167.0).abs() < 1e-9 * 1167.0);
    assert!(s.concentration_factor() > 1.0);
    assert_eq!(s.central_line().len(), grid.nx);
    assert!(s.contact_length_m() > 6.0e-3 && s.contact_length_m() <= 7.6e-3);
    assert!(s.max_half_width_m() > 0.05e-3 && s.max_half_width_m() < 0.1e-3);
    assert!(!s.touches_edge_x && !s.touches_edge_y);
}

#[test]
fn degenerate_inputs_and_non_convergence_are_reported() {
    let grid = Grid::centered_extent(32, 9, 7.6e-3, 0.2e-3).unwrap();
    let gap = grid.eval(roller_gap);
    let mut s = BoussinesqSolver::new(grid, compliance(), BoussinesqOptions::default()).unwrap();
    // No load / no interference: zero pressure, converged.
    let z = s.solve_force(&gap, 0.0).unwrap();
    assert!(z.converged && z.force_n == 0.0 && z.cells_in_contact == 0);
    let z = s.solve_approach(&gap, -1e-6).unwrap();
    assert!(z.converged && z.force_n == 0.0);
    // Invalid inputs are errors, not NaN.
    assert!(s.solve_force(&gap[1..], 100.0).is_err());
    assert!(s.solve_force(&gap, f64::NAN).is_err());
    assert!(s.solve_force(&gap, -1.0).is_err());
    let mut bad = gap.clone();
    bad[5] = f64::NAN;
    assert!(s.solve_approach(&bad, 1e-6).is_err());
    assert!(BoussinesqSolver::new(grid, -1.0, BoussinesqOptions::default()).is_err());
    let opt = BoussinesqOptions {
        stop: StopRule::RelativeGap(0.0),
        ..Default::default()
    };
    assert!(BoussinesqSolver::new(grid, compliance(), opt).is_err());
    // Iteration limit: flagged, finite, force still balanced.
    let opt = BoussinesqOptions {
        max_iterations: 3,
        ..Default::default()
    };
    let mut s = BoussinesqSolver::new(grid, compliance(), opt).unwrap();
    let r = s.solve_force(&gap, 1167.0).unwrap();
    assert!(!r.converged && r.iterations == 3);
    assert!(r.pressure.iter().all(|p| p.is_finite() && *p >= 0.0));
    assert!(r.approach_m.is_finite() && r.residual.is_finite());
    assert!((r.force_n / 1167.0 - 1.0).abs() < 1e-12);
}

#[test]
fn iteration_loop_does_not_allocate() {
    let grid = Grid::centered_extent(64, 20, 7.6e-3, 0.2e-3).unwrap();
    let gap = grid.eval(roller_gap);
    let table = InfluenceTable::new(&grid, compliance());
    for mode in [ConvolutionMode::Fft2d, ConvolutionMode::FftXDirectY] {
        let mut conv = Convolver::new(&table, mode);
        let p = vec![1e9; grid.len()];
        let mut u = vec![0.0; grid.len()];
        conv.apply(&p, &mut u);
        let before = allocations();
        for _ in 0..3 {
            conv.apply(&p, &mut u);
        }
        assert_eq!(
            allocations(),
            before,
            "{mode:?}: Convolver::apply allocated"
        );
    }
    // A solve allocates only its result: the count must not depend on the iterations done
    // (tolerance unreachable, so both runs stop at max_iterations).
    let mut counts = Vec::new();
    for max_iterations in [5, 40] {
        let opt = BoussinesqOptions {
            stop: StopRule::RelativeGap(1e-300),
            max_iterations,
            ..Default::default()
        };
        let mut s = BoussinesqSolver::new(grid, compliance(), opt).unwrap();
        let before = allocations();
        let r = s.solve_force(&gap, 1167.0).unwrap();
        counts.push(allocations() - before);
        assert_eq!(r.iterations, max_iterations);
    }
    assert_eq!(counts[0], counts[1], "allocations per solve: {counts:?}");
}

/// Issue 40 item 5: the relative-gap stop rule (default) gives the same approach and pressures
/// as the former pressure-change rule at `ε < 1e-10` on the seed 004 grids, with fewer
/// iterations. Crowned 32206 roller (3.2 µm) on its inner raceway at 1167 N: 350 × 9 and
/// 350 × 15 square cells of 0.0214 mm (seed 004 Table 2), 1024 × 64 over 7.6 × 0.4 mm.
#[test]
fn gap_stop_rule_matches_pressure_change_rule() {
    let side = 0.0214e-3;
    let grids = [
        Grid::centered(350, 9, side, side).unwrap(),
        Grid::centered(350, 15, side, side).unwrap(),
        Grid::centered_extent(1024, 64, 7.6e-3, 0.4e-3).unwrap(),
    ];
    for grid in grids {
        let gap = grid.eval(roller_gap);
        let solve = |stop| {
            let opt = BoussinesqOptions {
                stop,
                ..Default::default()
            };
            let mut s = BoussinesqSolver::new(grid, compliance(), opt).unwrap();
            s.solve_force(&gap, 1167.0).unwrap()
        };
        let former = solve(StopRule::PressureChange(1e-10));
        let gap_rule = solve(StopRule::default());
        assert!(former.converged && gap_rule.converged);
        let ea = (gap_rule.approach_m / former.approach_m - 1.0).abs();
        let ep = rel_max_diff(&gap_rule.pressure, &former.pressure);
        let em = (gap_rule.max_pressure_pa / former.max_pressure_pa - 1.0).abs();
        println!(
            "{}x{}: iterations {} -> {}, convolutions {} -> {}, approach {ea:.1e}, \
             pressures {ep:.1e}, p_max {em:.1e}, residual {:.1e} -> {:.1e}",
            grid.nx,
            grid.ny,
            former.iterations,
            gap_rule.iterations,
            former.convolutions,
            gap_rule.convolutions,
            former.residual,
            gap_rule.residual
        );
        // The bound is 5e-4 (0.05 %). Observed: approach ≤ 2.2e-9, largest pressure
        // difference ≤ 7.7e-6 p_max (1024 × 64), p_max ≤ 1.7e-7; asserted 10× below the
        // issue's bound for the pressures (6× above the largest observed) and 1e-7 for the
        // approach.
        assert!(
            ea < 1e-7 && ep < 5e-5 && em < 5e-5,
            "{}x{}",
            grid.nx,
            grid.ny
        );
        // A converged result passes its own test on the returned (exact) displacement.
        assert!(gap_rule.residual < rolldyn_contact::boussinesq::solver::DEFAULT_GAP_TOLERANCE);
        assert!(gap_rule.iterations < former.iterations);
    }
}
