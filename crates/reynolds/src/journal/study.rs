//! Grid-convergence and parameter studies for the journal bearing (callable from a CLI `study`
//! command).

use super::{JournalBearing, JournalOperating, JournalOptions, solve_eccentricity};
use crate::error::Result;
use crate::viscosity::Isoviscous;

/// One row of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyRow {
    /// Length/diameter ratio.
    pub l_over_d: f64,
    /// Eccentricity ratio.
    pub eccentricity: f64,
    /// Grid (circumferential × axial nodes).
    pub grid: (usize, usize),
    /// Sommerfeld number.
    pub sommerfeld: f64,
    /// Attitude, degrees.
    pub attitude_deg: f64,
    /// Friction variable (R/c)f.
    pub friction_variable: f64,
    /// Side-flow variable Q_s/(R c N L).
    pub side_flow_variable: f64,
    /// Load / (2RL p_max).
    pub pressure_ratio: f64,
    /// Relative change of S against the next finer grid (NaN-free: 0 for the finest).
    pub sommerfeld_change: f64,
    /// Direct solves.
    pub iterations: usize,
    /// Wall time, s.
    pub solve_time_s: f64,
}

/// Dimensionless journal-bearing chart (Raimondi–Boyd variables) for each L/D and ε on each grid
/// of `grids` (coarse to fine); reports the change of S against the next finer grid. Rigid,
/// isothermal, Reynolds cavitation, no coefficients.
pub fn grid_convergence(
    l_over_d: &[f64],
    eccentricities: &[f64],
    grids: &[(usize, usize)],
) -> Result<Vec<StudyRow>> {
    let mut rows = Vec::new();
    let (r, c, mu, rpm) = (0.025, 50e-6, 0.05, 3000.0);
    let op = JournalOperating::rpm(rpm, 313.15);
    let visc = Isoviscous { mu };
    for &ld in l_over_d {
        let b = JournalBearing::new(r, 2.0 * r * ld, c);
        for &eps in eccentricities {
            let mut block = Vec::new();
            for &(nt, nz) in grids {
                let opt = JournalOptions {
                    n_circumferential: nt,
                    n_axial: nz,
                    coefficients: false,
                    ..Default::default()
                };
                let res = solve_eccentricity(&b, &visc, &op, eps, &opt)?;
                let n = rpm / 60.0;
                block.push(StudyRow {
                    l_over_d: ld,
                    eccentricity: eps,
                    grid: (nt, nz),
                    sommerfeld: res.sommerfeld,
                    attitude_deg: res.attitude_deg,
                    friction_variable: res.friction_variable,
                    side_flow_variable: res.side_flow_m3_s / (r * c * n * b.length),
                    pressure_ratio: res.load_n / (2.0 * r * b.length * res.max_pressure_pa),
                    sommerfeld_change: 0.0,
                    iterations: res.iterations,
                    solve_time_s: res.solve_time_s,
                });
            }
            for k in 0..block.len().saturating_sub(1) {
                let fine = block[k + 1].sommerfeld;
                block[k].sommerfeld_change = (block[k].sommerfeld - fine) / fine;
            }
            rows.extend(block);
        }
    }
    Ok(rows)
}
