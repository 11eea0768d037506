//! Cage slip measured over whole cage revolutions after steady state — the quantity of the
//! seed's cage-slip studies (SPEC V-06, seed 000 §2.3; V-08). The studies themselves build their
//! simulations from model files (`rolldyn-validation`).

use crate::error::DynError;
use crate::output::NullSink;
use crate::simulation::Simulation;

/// How long to run and what to average.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipWindow {
    /// Most cage revolutions simulated (transient + averaging window). The run stops earlier
    /// once steady state is detected and `average_revolutions` whole revolutions after it are
    /// complete.
    pub cage_revolutions: f64,
    /// Whole cage revolutions averaged after steady state (or, if steady state is not detected
    /// within `cage_revolutions`, the last ones run; [`SlipMeasurement::steady`] is then false).
    pub average_revolutions: u32,
    /// Steady state: the mean cage speed of two consecutive cage revolutions differs by less
    /// than this fraction of the epicyclic speed (default 2e-4 — below the slip being measured;
    /// the run default 1e-3 of `DynamicsSettings` is too coarse for slips ~1e-3).
    pub steady_tolerance: f64,
}

impl Default for SlipWindow {
    /// 16 revolutions at most, 4 averaged, steady at 2e-4.
    fn default() -> Self {
        Self {
            cage_revolutions: 16.0,
            average_revolutions: 4,
            steady_tolerance: 2e-4,
        }
    }
}

/// The cage slip of a running simulation over whole cage-revolution periods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipMeasurement {
    /// `1 − ω̄_c/ω_epi` over the averaging window
    pub cage_slip: f64,
    /// whole cage-revolution periods averaged
    pub revolutions_averaged: u32,
    /// steady state was detected before the window
    pub steady: bool,
    /// start of the window, s
    pub window_start_s: f64,
}

/// Runs `sim` one epicyclic cage-revolution period (`2π/epicyclic`) at a time until steady
/// state plus `settings.average_revolutions` periods (or `settings.cage_revolutions` in all) and
/// measures the cage slip `1 − ω̄_c/ω_epi` over the window, with `ω̄_c = Δφ/Δt` from the cage
/// angle φ at the window ends (seed 000 (2.19)): the cage's excursions inside the pocket and land
/// clearances cancel except for the change of position between the window ends.
pub fn measure_cage_slip(
    sim: &mut Simulation,
    epicyclic_rad_s: f64,
    settings: &SlipWindow,
) -> Result<SlipMeasurement, DynError> {
    let wc = epicyclic_rad_s.abs().max(1e-9);
    let rev_s = std::f64::consts::TAU / wc;
    let t_max = sim.time() + settings.cage_revolutions * rev_s;
    let k = settings.average_revolutions.max(1) as usize;
    // period means are Δφ/Δt (exact, no quadrature); steady once two consecutive period means
    // differ by less than `steady_tolerance` of the epicyclic speed
    let phi_index = sim.layout().cage() + crate::layout::cage::ANGLE;
    let mut marks = vec![(sim.time(), sim.state()[phi_index])];
    let speed = |a: (f64, f64), b: (f64, f64)| (b.1 - a.1) / (b.0 - a.0);
    let mut steady_after: Option<usize> = None;
    loop {
        let t_next = sim.time() + rev_s;
        sim.run_until(t_next, &mut NullSink, &mut |_| {})?;
        marks.push((sim.time(), sim.state()[phi_index]));
        let n = marks.len();
        if steady_after.is_none() && n >= 4 {
            let d = speed(marks[n - 2], marks[n - 1]) - speed(marks[n - 3], marks[n - 2]);
            if d.abs() < settings.steady_tolerance * wc {
                steady_after = Some(n - 1);
            }
        }
        if steady_after.is_some_and(|m| n > m + k) || sim.time() >= t_max {
            break;
        }
    }
    let n = marks.len();
    let (first, steady) = match steady_after {
        Some(m) if n > m + k => (m, true),
        _ => (n.saturating_sub(k + 1).max(1).min(n - 2), false),
    };
    let (a, b) = (marks[first], marks[n - 1]);
    Ok(SlipMeasurement {
        cage_slip: 1.0 - speed(a, b).abs() / wc,
        revolutions_averaged: (n - 1 - first) as u32,
        steady,
        window_start_s: a.0,
    })
}
