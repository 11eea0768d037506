//! Dense reference solver: seed 004 Algorithm A (approach → pressure, active set with a dense
//! Cholesky solve) and Algorithm B (force → approach, secant / regula falsi, flag F-13).
//! SPEC §2.5. O(N³): for tests and small grids only.

use super::influence::InfluenceTable;
use super::{BoussinesqError, Grid};

/// Result of the dense reference solver.
#[derive(Debug, Clone)]
pub struct DenseSolution {
    /// Pressure per cell, Pa (x fastest, like [`Grid::index`]).
    pub pressure: Vec<f64>,
    /// Rigid approach `α`, m.
    pub approach_m: f64,
    /// Total force `ΔS Σ p`, N (seed 004 eq. (6)).
    pub force_n: f64,
    /// Active-set passes of the last Algorithm A call.
    pub active_set_passes: usize,
    /// Algorithm A calls made by Algorithm B (1 for an approach-controlled solve).
    pub force_evaluations: usize,
    /// Whether the active set / secant iteration met its tolerance.
    pub converged: bool,
}

/// Full symmetric influence matrix `f_ij` (row-major `N × N`, `N = nx·ny`), seed 004 eq. (4).
pub fn influence_matrix(table: &InfluenceTable) -> Vec<f64> {
    let (nx, ny) = (table.nx(), table.ny());
    let n = nx * ny;
    let mut a = vec![0.0; n * n];
    for j in 0..ny {
        for i in 0..nx {
            let r = j * nx + i;
            for jp in 0..ny {
                for ip in 0..nx {
                    a[r * n + jp * nx + ip] =
                        table.get(i as isize - ip as isize, j as isize - jp as isize);
                }
            }
        }
    }
    a
}

/// In-place Cholesky factorisation `A = L Lᵀ` of a dense SPD `n × n` matrix (lower triangle
/// overwritten by `L`). Returns false if a pivot is not positive.
pub fn cholesky_factor(a: &mut [f64], n: usize) -> bool {
    for j in 0..n {
        let mut d = a[j * n + j];
        for k in 0..j {
            d -= a[j * n + k] * a[j * n + k];
        }
        if d.is_nan() || d <= 0.0 {
            return false;
        }
        let d = d.sqrt();
        a[j * n + j] = d;
        for i in j + 1..n {
            let (ri, rj) = (i * n, j * n);
            let mut s = a[ri + j];
            for k in 0..j {
                s -= a[ri + k] * a[rj + k];
            }
            a[ri + j] = s / d;
        }
    }
    true
}

/// Solve `L Lᵀ x = b` in place with the factor from [`cholesky_factor`].
pub fn cholesky_solve(l: &[f64], n: usize, b: &mut [f64]) {
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i * n + k] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= l[k * n + i] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
}

fn check(grid: &Grid, table: &InfluenceTable, gap: &[f64]) -> Result<(), BoussinesqError> {
    if table.nx() != grid.nx || table.ny() != grid.ny {
        return Err(BoussinesqError::InvalidGrid(
            "influence table built for another grid".into(),
        ));
    }
    if gap.len() != grid.len() {
        return Err(BoussinesqError::LengthMismatch {
            expected: grid.len(),
            got: gap.len(),
        });
    }
    if let Some(i) = gap.iter().position(|v| !v.is_finite()) {
        return Err(BoussinesqError::NonFiniteGap(i));
    }
    Ok(())
}

/// Algorithm A on a pre-built matrix. Returns (pressure, passes, converged).
fn algorithm_a(f: &[f64], n: usize, gap: &[f64], alpha: f64) -> (Vec<f64>, usize, bool) {
    // Steps 1–2: K1 = K − α, active set = interpenetrating cells.
    let mut active: Vec<usize> = (0..n).filter(|&i| gap[i] - alpha < 0.0).collect();
    let mut p = vec![0.0; n];
    let scale = gap
        .iter()
        .map(|g| (g - alpha).abs())
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let max_passes = 4 * n + 10;
    for pass in 1..=max_passes {
        p.fill(0.0);
        if active.is_empty() {
            return (p, pass, true);
        }
        // Step 3: system (004-4) restricted to the active set, D_i = −K1_i.
        let m = active.len();
        let mut a = vec![0.0; m * m];
        for (r, &i) in active.iter().enumerate() {
            for (c, &j) in active.iter().enumerate() {
                a[r * m + c] = f[i * n + j];
            }
        }
        let mut x: Vec<f64> = active.iter().map(|&i| alpha - gap[i]).collect();
        // Step 4: dense direct solve (Cholesky, the matrix is SPD).
        if !cholesky_factor(&mut a, m) {
            return (p, pass, false);
        }
        cholesky_solve(&a, m, &mut x);
        // Step 5: drop cells with negative pressure and repeat.
        if x.iter().any(|&v| v < 0.0) {
            active = active
                .iter()
                .zip(&x)
                .filter(|&(_, &v)| v >= 0.0)
                .map(|(&i, _)| i)
                .collect();
            continue;
        }
        for (&i, &v) in active.iter().zip(&x) {
            p[i] = v;
        }
        // Extension (SPEC §2.5 "may optionally verify"): re-admit cells that still
        // interpenetrate, K1 + u < 0, outside the active set.
        let mut added = false;
        let mut is_active = vec![false; n];
        for &i in &active {
            is_active[i] = true;
        }
        for i in 0..n {
            if is_active[i] {
                continue;
            }
            let u: f64 = active.iter().map(|&j| f[i * n + j] * p[j]).sum();
            if gap[i] - alpha + u < -1e-13 * scale {
                active.push(i);
                added = true;
            }
        }
        if !added {
            // Step 6.
            return (p, pass, true);
        }
        active.sort_unstable();
    }
    (p, max_passes, false)
}

/// Seed 004 Algorithm A: pressure for a prescribed approach `alpha` (m).
pub fn solve_approach_dense(
    grid: &Grid,
    table: &InfluenceTable,
    gap: &[f64],
    alpha: f64,
) -> Result<DenseSolution, BoussinesqError> {
    check(grid, table, gap)?;
    if !alpha.is_finite() {
        return Err(BoussinesqError::InvalidLoad(alpha));
    }
    let f = influence_matrix(table);
    let (p, passes, converged) = algorithm_a(&f, grid.len(), gap, alpha);
    let force = grid.cell_area() * p.iter().sum::<f64>();
    Ok(DenseSolution {
        pressure: p,
        approach_m: alpha,
        force_n: force,
        active_set_passes: passes,
        force_evaluations: 1,
        converged,
    })
}

/// Seed 004 Algorithm B: approach and pressure for a prescribed force `q` (N), iterating
/// Algorithm A on `α` until `|Q − Q(α)| / Q < rel_tol` (flag F-13: secant with an Illinois
/// regula-falsi bracket and bisection fallback).
pub fn solve_force_dense(
    grid: &Grid,
    table: &InfluenceTable,
    gap: &[f64],
    q: f64,
    rel_tol: f64,
) -> Result<DenseSolution, BoussinesqError> {
    check(grid, table, gap)?;
    if !(q.is_finite() && q >= 0.0) {
        return Err(BoussinesqError::InvalidLoad(q));
    }
    let n = grid.len();
    let ds = grid.cell_area();
    let f = influence_matrix(table);
    let h_min = gap.iter().copied().fold(f64::INFINITY, f64::min);
    let evals_cell = std::cell::Cell::new(0usize);
    let eval = |alpha: f64| {
        evals_cell.set(evals_cell.get() + 1);
        let (p, passes, ok) = algorithm_a(&f, n, gap, alpha);
        let force = ds * p.iter().sum::<f64>();
        (force, p, passes, ok)
    };
    let done = |alpha: f64, (force, p, passes, ok): (f64, Vec<f64>, usize, bool), evals, conv| {
        DenseSolution {
            pressure: p,
            approach_m: alpha,
            force_n: force,
            active_set_passes: passes,
            force_evaluations: evals,
            converged: ok && conv,
        }
    };
    if q == 0.0 {
        let r = eval(h_min);
        return Ok(done(h_min, r, 1, true));
    }
    // Bracket: Q(h_min) = 0 < q; grow the upper end from the single-cell estimate.
    let (mut a_lo, mut q_lo) = (h_min, 0.0);
    let mut step = table.self_coefficient() * q / ds;
    let (mut a_hi, mut q_hi);
    loop {
        a_hi = h_min + step;
        let r = eval(a_hi);
        let evals = evals_cell.get();
        q_hi = r.0;
        if q_hi >= q {
            if (q_hi - q).abs() <= rel_tol * q {
                return Ok(done(a_hi, r, evals, true));
            }
            break;
        }
        (a_lo, q_lo) = (a_hi, q_hi);
        step *= 2.0;
        if evals > 200 {
            return Ok(done(a_hi, r, evals, false));
        }
    }
    // Illinois regula falsi on Q(α) − q (monotone in α).
    let mut side = 0i8;
    let (mut w_lo, mut w_hi) = (1.0, 1.0);
    for _ in 0..200 {
        let (fl, fh) = ((q_lo - q) * w_lo, (q_hi - q) * w_hi);
        let mut a = a_lo - fl * (a_hi - a_lo) / (fh - fl);
        if !(a > a_lo && a < a_hi) {
            a = 0.5 * (a_lo + a_hi);
        }
        let r = eval(a);
        let evals = evals_cell.get();
        let qa = r.0;
        if (qa - q).abs() <= rel_tol * q || (a_hi - a_lo) <= 4.0 * f64::EPSILON * a.abs() {
            return Ok(done(a, r, evals, true));
        }
        if qa < q {
            (a_lo, q_lo) = (a, qa);
            w_lo = 1.0;
            w_hi = if side == -1 { 0.5 * w_hi } else { 1.0 };
            side = -1;
        } else {
            (a_hi, q_hi) = (a, qa);
            w_hi = 1.0;
            w_lo = if side == 1 { 0.5 * w_lo } else { 1.0 };
            side = 1;
        }
    }
    let a = 0.5 * (a_lo + a_hi);
    let r = eval(a);
    Ok(done(a, r, evals_cell.get(), false))
}
