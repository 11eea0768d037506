//! Grid-convergence study of the line-contact solver (callable from a CLI `study` command).

use super::analytic;
use super::{Compliance, Constraint, LineContactOptions, LubricatedLineContact, solve};
use crate::compliance::half_space::HalfSpace;
use crate::error::Result;
use crate::viscosity::{Density, Isoviscous, Roelands};

/// One row of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct LineStudyRow {
    /// Case name.
    pub case: &'static str,
    /// Nodes.
    pub nodes: usize,
    /// Load per length, N/m.
    pub load_per_length_n_per_m: f64,
    /// Maximum pressure, Pa.
    pub max_pressure_pa: f64,
    /// Minimum film, m.
    pub min_film_m: f64,
    /// Central film, m.
    pub central_film_m: f64,
    /// Exit coordinate, m.
    pub outlet_position_m: f64,
    /// Reference value of the case's key quantity (analytic load for the rigid case; 0 if none).
    pub reference: f64,
    /// Newton iterations.
    pub iterations: usize,
    /// Wall time, s.
    pub solve_time_s: f64,
}

/// Runs (a) the rigid isoviscous contact of seed 002 §3.5 (h_m = 1 µm, exact load reference)
/// and (b) an EHL contact (R = 10 mm, u_m = 1 m/s, 3×10⁵ N/m, Roelands + Dowson–Higginson) on
/// each node count in `nodes`.
pub fn grid_convergence(nodes: &[usize]) -> Result<Vec<LineStudyRow>> {
    let mut rows = Vec::new();
    let rigid = LubricatedLineContact::new(0.005, 7.0);
    let (w0, _) = analytic::load_coefficients()?;
    let h = 1e-6;
    let wref = w0 * analytic::pressure_scale(0.024, 7.0, 0.005, h) * (0.005 * h).sqrt();
    let mut ehl = LubricatedLineContact::new(0.01, 2.0);
    ehl.compliance = Compliance::HalfSpace(HalfSpace::pair(2.06e11, 0.3, 2.06e11, 0.3, 1.0));
    ehl.density = Density::DowsonHigginson;
    let vis = Roelands::from_alpha(0.04, 2e-8);
    for &n in nodes {
        let opt = LineContactOptions {
            nodes: n,
            damping: false,
            ..Default::default()
        };
        let a = solve(
            &rigid,
            &Isoviscous { mu: 0.024 },
            Constraint::MinFilm(h),
            &opt,
        )?;
        let b = solve(&ehl, &vis, Constraint::LoadPerLength(3e5), &opt)?;
        for (case, r, reference) in [
            ("rigid isoviscous h_m = 1 µm", a, wref),
            ("EHL 3e5 N/m", b, 0.0),
        ] {
            rows.push(LineStudyRow {
                case,
                nodes: n,
                load_per_length_n_per_m: r.load_per_length_n_per_m,
                max_pressure_pa: r.max_pressure_pa,
                min_film_m: r.min_film_m,
                central_film_m: r.central_film_m,
                outlet_position_m: r.outlet_position_m,
                reference,
                iterations: r.iterations,
                solve_time_s: r.solve_time_s,
            });
        }
    }
    Ok(rows)
}
