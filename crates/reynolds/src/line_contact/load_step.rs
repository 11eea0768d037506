//! A load step on a lubricated roller (SPEC §8.5, seed 002 §3.2 and §5): from the steady state
//! at load W₁ the load per length jumps to W₂ at t = 0 and M ḧ + λ(h) ḣ − W₀(h) = −W₂ℓ
//! (seed (5.7)) is integrated with W₀(h), λ(h), p_max(h) tabulated by the full steady solver
//! over both static states. The film variable is the rigid approach h₀ (= h_m when rigid).

use super::load_damping::LoadDampingTable;
use super::transient::{Tabulated, TransientOptions, TransientSample, simulate};
use super::{Constraint, LineContactOptions, LineContactResult, LubricatedLineContact, solve};
use crate::error::{Result, ReynoldsError, positive};
use crate::viscosity::Viscosity;

/// Density of a steel roller, kg/m³ (the default mass πR²ℓρ).
pub const STEEL_DENSITY: f64 = 7850.0;

/// Films tabulated between the two static states.
const TABLE_POINTS: usize = 11;

/// The table spans [0.7 min(h₁, h₂), 1.3 max(h₁, h₂)].
const TABLE_MARGIN: (f64, f64) = (0.7, 1.3);

/// What the load step is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadStep {
    /// Load per length after the step W₂, N/m.
    pub to: f64,
    /// Simulated time after the step, s.
    pub duration: f64,
    /// Roller length carrying the load ℓ, m.
    pub contact_length: f64,
    /// Roller mass M, kg; `None`: a steel cylinder πR²ℓ·[`STEEL_DENSITY`].
    pub mass: Option<f64>,
    /// The history is thinned to at most this many samples (first and last kept).
    pub max_samples: usize,
}

/// The film history after the step and its summary.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadStepResult {
    /// Load per length before the step W₁, N/m.
    pub initial_load_per_length_n_per_m: f64,
    /// Roller mass used, kg.
    pub mass_kg: f64,
    /// Rigid approach before the step h₁, m.
    pub initial_film_m: f64,
    /// Rigid approach at the end of the run, m.
    pub final_film_m: f64,
    /// Static rigid approach at the new load h₂, m.
    pub static_film_at_new_load_m: f64,
    /// Smallest film of the (thinned) history, m.
    pub min_film_m: f64,
    /// Largest quasi-steady maximum pressure of the (thinned) history, Pa.
    pub peak_pressure_pa: f64,
    /// Maximum pressure at the end of the run, Pa.
    pub final_pressure_pa: f64,
    /// Films of the W₀, λ, p_max table.
    pub table_points: usize,
    /// The (thinned) history.
    pub samples: Vec<TransientSample>,
}

/// Simulates `step` from the steady solution `start` of `contact` (solved with `options`,
/// which must have no squeeze velocity).
pub fn load_step(
    contact: &LubricatedLineContact,
    viscosity: &dyn Viscosity,
    options: &LineContactOptions,
    start: &LineContactResult,
    step: &LoadStep,
) -> Result<LoadStepResult> {
    let w2 = positive("load per length after the step", step.to)?;
    if options.squeeze_velocity != 0.0 {
        return Err(ReynoldsError::InvalidInput {
            what: "load step",
            reason: "it starts from a steady state: the squeeze velocity must be 0".into(),
        });
    }
    positive("load-step duration", step.duration)?;
    let ell = positive("contact length", step.contact_length)?;
    let r = contact.radius;
    let mass = positive(
        "roller mass",
        step.mass
            .unwrap_or(STEEL_DENSITY * std::f64::consts::PI * r * r * ell),
    )?;
    let h1 = start.rigid_approach_m;
    let quiet = LineContactOptions {
        damping: false,
        ..*options
    };
    let h2 = solve(contact, viscosity, Constraint::LoadPerLength(w2), &quiet)?.rigid_approach_m;
    if !(h1 > 0.0 && h2 > 0.0) {
        return Err(ReynoldsError::InvalidInput {
            what: "load step",
            reason: format!(
                "W₀, λ are tabulated over the rigid approach h₀, which must stay > 0 \
                 (got {h1:.3e} m → {h2:.3e} m); use rigid bodies or a lighter load"
            ),
        });
    }
    let (lo, hi) = (TABLE_MARGIN.0 * h1.min(h2), TABLE_MARGIN.1 * h1.max(h2));
    let films: Vec<f64> = (0..TABLE_POINTS)
        .map(|k| lo * (hi / lo).powf(k as f64 / (TABLE_POINTS - 1) as f64))
        .collect();
    let table = LoadDampingTable::build(contact, viscosity, &films, options)?;
    let film = Tabulated {
        table: &table,
        length: ell,
        v: contact.sum_speed(),
        r,
    };
    let force = |_: f64| w2 * ell;
    let samples = simulate(
        &film,
        mass,
        &force,
        h1,
        0.0,
        step.duration,
        &TransientOptions::default(),
    )?;
    if samples.iter().any(|s| s.h <= lo || s.h >= hi) {
        return Err(ReynoldsError::OutOfRange(format!(
            "the film left the tabulated range {lo:.3e}…{hi:.3e} m during the load step \
             (inertia overshoot); shorten the duration or reduce the step"
        )));
    }
    let samples = thin(samples, step.max_samples);
    let last = *samples
        .last()
        .expect("a transient history starts with the initial state");
    Ok(LoadStepResult {
        initial_load_per_length_n_per_m: start.load_per_length_n_per_m,
        mass_kg: mass,
        initial_film_m: h1,
        final_film_m: last.h,
        static_film_at_new_load_m: h2,
        min_film_m: samples.iter().map(|s| s.h).fold(f64::INFINITY, f64::min),
        peak_pressure_pa: samples.iter().map(|s| s.p_max).fold(0.0, f64::max),
        final_pressure_pa: last.p_max,
        table_points: TABLE_POINTS,
        samples,
    })
}

/// Every k-th sample so that at most about `max` remain, the last one always kept.
fn thin(samples: Vec<TransientSample>, max: usize) -> Vec<TransientSample> {
    let Some(&last) = samples.last() else {
        return samples;
    };
    if samples.len() <= max {
        return samples;
    }
    let every = samples.len().div_ceil(max.max(1));
    let mut kept: Vec<TransientSample> = samples.into_iter().step_by(every).collect();
    if kept.last() != Some(&last) {
        kept.push(last);
    }
    kept
}
