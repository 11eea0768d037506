//! The life loop (seed 000 §2.4.1 step 7, §3.2.3; docs/theory.md §8.8): dynamics of the current
//! geometry → wear rates → depth over a period → worn geometry → dynamics …, until the
//! requested life or an operability limit; with the automatic period, a period whose rates
//! change too much is halved and recomputed.

use crate::WearError;
use crate::bearing_data::WearData;
use crate::rates::{ContactDiagnostics, SurfaceWear};
use crate::recorder::WearRecorder;
use crate::settings::{PeriodControl, WearSettings};
use crate::surface::{PerSurface, Surface};
use crate::worn::worn_bearing;
use rolldyn_dynamics::conditions::OperatingConditions;
use rolldyn_dynamics::output::NullSink;
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_model::{DynamicsInputs, Lubrication};
use std::ops::ControlFlow;
use std::time::Instant;

/// One period of the life loop.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PeriodRecord {
    /// 1, 2, …
    pub index: usize,
    /// operating time at the end of the period, h
    pub time_h: f64,
    pub period_h: f64,
    /// largest wear rate of each surface during the period, m/s of depth
    pub max_rate_m_s: PerSurface<f64>,
    /// largest accumulated depth of each surface at the end of the period, m
    pub max_depth_m: PerSurface<f64>,
    /// operating radial clearance increase at the end of the period, m
    pub clearance_increase_m: f64,
    /// mean cage speed of the dynamics run, rad/s
    pub cage_speed_rad_s: f64,
    /// cage revolutions in the period
    pub revolutions: f64,
    /// inner raceway, outer raceway, cage bar, rib: what the rates came from
    pub contacts: [ContactDiagnostics; 4],
    /// periods halved before this one was accepted
    pub halvings: u32,
    pub dynamics_wall_s: f64,
    pub wear_wall_s: f64,
}

/// What ended the run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    LifeReached,
    ClearanceLimit,
    DepthLimit(Surface),
    /// The caller asked the run to stop (Ctrl-C) after the last period.
    Interrupted,
}

/// The result of a life run.
#[derive(Debug, Clone)]
pub struct LifeRun {
    pub periods: Vec<PeriodRecord>,
    /// accumulated depth at the end, m
    pub depth: SurfaceWear,
    /// the unworn slice centres the roller and raceway lines sit at, m
    pub line_positions_m: Vec<f64>,
    pub worn: CylindricalRollerBearing,
    pub life_h: f64,
    pub stop: StopReason,
}

/// The bearing, oil, dynamics inputs and conditions a life run works on.
pub struct LifeInputs<'a> {
    pub bearing: &'a CylindricalRollerBearing,
    pub lubrication: &'a Lubrication,
    pub dynamics: &'a DynamicsInputs,
    pub conditions: &'a OperatingConditions,
}

/// The wear rates of one geometry and what they cost.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct RatesRun {
    pub rates: SurfaceWear,
    /// mean cage speed over the recorded revolutions, rad/s
    pub cage_speed_rad_s: f64,
    /// wall time of the dynamics (set-up and integration), s
    pub dynamics_s: f64,
    /// wall time of the wear computation (geometry update and the recorder), s
    pub wear_s: f64,
}

/// Rates of the bearing worn by `depth`: a dynamics run of `settings.settle_revolutions`
/// discarded and `settings.revolutions` recorded cage revolutions.
pub fn rates_of(
    inputs: &LifeInputs,
    positions: &[f64],
    depth: &SurfaceWear,
    settings: &WearSettings,
) -> Result<RatesRun, WearError> {
    let wall = Instant::now();
    let bearing = worn_bearing(inputs.bearing, positions, depth)?;
    let data = WearData::new(
        &bearing,
        &inputs.lubrication.oil,
        inputs.conditions.temperatures.cage_k,
        settings,
    )?;
    let geometry_s = wall.elapsed().as_secs_f64();
    let prepared = rolldyn_setup::prepare_with(
        &bearing,
        inputs.lubrication,
        inputs.dynamics,
        inputs.conditions.clone(),
        settings.output_step_s,
        None,
    )
    .map_err(|e| WearError::Input(e.0))?;
    let revolution = prepared.revolution_s.ok_or_else(|| {
        WearError::Input("wear needs a running bearing: the rings do not turn at t = 0".into())
    })?;
    let mut sim = prepared.simulation;
    let settle = settings.settle_revolutions as f64 * revolution;
    let numerical = |e: rolldyn_dynamics::DynError| WearError::Numerical(e.to_string());
    sim.run_until(settle, &mut NullSink, &mut |_| {})
        .map_err(numerical)?;
    let mut recorder = WearRecorder::new(&data, settings);
    let end = settle + settings.revolutions as f64 * revolution;
    sim.run_until(end, &mut recorder, &mut |_| {})
        .map_err(numerical)?;
    if recorder.samples() == 0 {
        return Err(WearError::Numerical(
            "the dynamics gave no output step to record".into(),
        ));
    }
    let total = wall.elapsed().as_secs_f64();
    let wear_s = geometry_s + recorder.wall_s();
    Ok(RatesRun {
        rates: recorder.rates()?,
        cage_speed_rad_s: recorder.mean_cage_speed(),
        dynamics_s: total - wear_s,
        wear_s,
    })
}

/// Relative change of each surface's largest rate from `before` to `after` (0 when both are 0).
fn rate_changes(before: &PerSurface<f64>, after: &PerSurface<f64>) -> PerSurface<f64> {
    PerSurface::from_fn(|s| {
        let (a, b) = (before.get(s), after.get(s));
        if a > 0.0 {
            b / a - 1.0
        } else if b > 0.0 {
            1.0
        } else {
            0.0
        }
    })
}

/// Whether the automatic control rejects a period whose rates changed by `change` after the
/// previous period's `previous_change`: a change beyond the threshold, or a trend reversal
/// larger than the noise on both sides.
fn period_too_long(
    control: &PeriodControl,
    change: &PerSurface<f64>,
    previous_change: Option<&PerSurface<f64>>,
) -> bool {
    let PeriodControl::Auto {
        change_threshold,
        trend_noise,
        ..
    } = *control
    else {
        return false;
    };
    change.iter().any(|(s, c)| {
        let reversal = previous_change.is_some_and(|p| {
            let p = p.get(s);
            p * c < 0.0 && p.abs() > trend_noise && c.abs() > trend_noise
        });
        c.abs() > change_threshold || reversal
    })
}

/// A rate change that halving the period shrinks to less than this fraction is caused by the
/// period (explicit steps in operating time: the change is about proportional to the step, so
/// halving gives ½); one that stays above it is not, and no longer halves the period.
const PERIOD_SENSITIVITY: f64 = 0.75;

/// Whether the automatic control may double the period after a period whose rates changed by
/// `change`: every change within a quarter of the threshold.
fn steady(control: &PeriodControl, change: &PerSurface<f64>) -> bool {
    match control {
        PeriodControl::Auto {
            change_threshold, ..
        } => change
            .iter()
            .all(|(_, c)| c.abs() < 0.25 * change_threshold),
        _ => false,
    }
}

/// The limit `depth` violates, if any.
fn limit_reached(settings: &WearSettings, depth: &SurfaceWear) -> Option<StopReason> {
    let limits = &settings.limits;
    if limits
        .clearance_increase_m
        .is_some_and(|l| depth.clearance_increase() > l)
    {
        return Some(StopReason::ClearanceLimit);
    }
    let deepest = Surface::ALL
        .into_iter()
        .find(|&s| limits.depth_m.is_some_and(|l| depth.max(s) > l));
    deepest.map(StopReason::DepthLimit)
}

/// Where a life run stands after an accepted period: everything the loop needs to go on (a
/// resumable run stores it after every period and gives it back to [`run_life`]).
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct LifeState {
    /// the accepted periods so far
    pub periods: Vec<PeriodRecord>,
    /// accumulated depth, m
    pub depth: SurfaceWear,
    /// the rates of the geometry worn by `depth`
    pub current: RatesRun,
    /// operating time, s
    pub time_s: f64,
    /// the next period (before a schedule or the automatic control changes it), s
    pub period_s: f64,
    /// the rate changes of the last accepted period (automatic control)
    pub previous_change: Option<PerSurface<f64>>,
    /// surfaces whose rate change did not shrink when a period was halved: not caused by the
    /// period's length (jumps between coexisting dynamic regimes, scatter); they no longer
    /// decide the period for the rest of the run
    pub insensitive: PerSurface<bool>,
}

/// Runs the life loop from the unworn bearing, or from `start` (a state [`run_life`] gave to
/// `on_period` of a run with the same inputs and settings); `on_period` sees the state after
/// every accepted period (for streaming outputs, stored state and progress) and may end the
/// run there ([`StopReason::Interrupted`]).
pub fn run_life(
    inputs: &LifeInputs,
    settings: &WearSettings,
    start: Option<LifeState>,
    on_period: &mut dyn FnMut(&LifeState) -> ControlFlow<()>,
) -> Result<LifeRun, WearError> {
    settings.validate().map_err(WearError::Input)?;
    let hour = 3600.0;
    let positions = inputs.bearing.roller.slices().position;
    let lines = positions.len();
    let resumed = start.is_some();
    let mut state = match start {
        Some(state) => state,
        None => {
            let depth = SurfaceWear::zero(lines, settings.angle_bins, inputs.bearing.roller_count);
            LifeState {
                periods: Vec::new(),
                current: rates_of(inputs, &positions, &depth, settings)?,
                depth,
                time_s: 0.0,
                period_s: settings.period.initial_s(),
                previous_change: None,
                insensitive: PerSurface::from_fn(|_| false),
            }
        }
    };
    // the first period books the run at the unworn geometry too
    let (mut dynamics_s, mut wear_s) = match resumed {
        true => (0.0, 0.0),
        false => (state.current.dynamics_s, state.current.wear_s),
    };
    let minimum = match &settings.period {
        PeriodControl::Auto { minimum_s, .. } => *minimum_s,
        _ => f64::INFINITY,
    };
    // a resumed run may have stopped at a limit
    let mut stop = limit_reached(settings, &state.depth).filter(|_| resumed);
    while stop.is_none() && state.time_s < settings.life_s * (1.0 - 1e-12) {
        let time = state.time_s;
        if let PeriodControl::Schedule(list) = &settings.period {
            state.period_s = list[state.periods.len().min(list.len() - 1)];
        }
        let mut period = state.period_s;
        let current = &state.current;
        let mut halvings = 0;
        let mut trial_change: Option<PerSurface<f64>> = None;
        let (next_depth, next, step) = loop {
            let step = period.min(settings.life_s - time);
            let mut trial = state.depth.clone();
            trial.add_scaled(&current.rates, step);
            let next = rates_of(inputs, &positions, &trial, settings)?;
            dynamics_s += next.dynamics_s;
            wear_s += next.wear_s;
            let raw = rate_changes(
                &current.rates.max_per_surface(),
                &next.rates.max_per_surface(),
            );
            if let Some(before) = &trial_change {
                for (s, c) in raw.iter() {
                    if c.abs() > PERIOD_SENSITIVITY * before.get(s).abs() {
                        state.insensitive.set(s, true);
                    }
                }
            }
            trial_change = Some(raw);
            let change = PerSurface::from_fn(|s| {
                if state.insensitive.get(s) {
                    0.0
                } else {
                    raw.get(s)
                }
            });
            if period / 2.0 >= minimum
                && period_too_long(&settings.period, &change, state.previous_change.as_ref())
            {
                period /= 2.0;
                halvings += 1;
                continue;
            }
            if halvings == 0 && steady(&settings.period, &change) {
                period = (2.0 * period).min(settings.period.initial_s());
            }
            state.previous_change = Some(change);
            break (trial, next, step);
        };
        let time = time + step;
        let record = PeriodRecord {
            index: state.periods.len() + 1,
            time_h: time / hour,
            period_h: step / hour,
            max_rate_m_s: current.rates.max_per_surface(),
            max_depth_m: next_depth.max_per_surface(),
            clearance_increase_m: next_depth.clearance_increase(),
            cage_speed_rad_s: current.cage_speed_rad_s,
            revolutions: current.cage_speed_rad_s * step / std::f64::consts::TAU,
            contacts: current.rates.diagnostics,
            halvings,
            dynamics_wall_s: dynamics_s,
            wear_wall_s: wear_s,
        };
        state.periods.push(record);
        (state.depth, state.current, state.time_s, state.period_s) =
            (next_depth, next, time, period);
        (dynamics_s, wear_s) = (0.0, 0.0);
        let flow = on_period(&state);
        stop = limit_reached(settings, &state.depth)
            .or(flow.is_break().then_some(StopReason::Interrupted));
    }
    let worn = worn_bearing(inputs.bearing, &positions, &state.depth)?;
    Ok(LifeRun {
        periods: state.periods,
        depth: state.depth,
        line_positions_m: positions,
        worn,
        life_h: state.time_s / hour,
        stop: stop.unwrap_or(StopReason::LifeReached),
    })
}

/// The convergence evidence of a life run (SPEC §6.6): the same life with every period of
/// `run` replaced by two of half its length, and the relative difference of each surface's
/// final depth (`run` against the halved run).
pub fn halved_period_check(
    inputs: &LifeInputs,
    settings: &WearSettings,
    run: &LifeRun,
) -> Result<(LifeRun, PerSurface<f64>), WearError> {
    let halves = run
        .periods
        .iter()
        .flat_map(|p| [0.5 * p.period_h * 3600.0; 2])
        .collect();
    let halved = WearSettings {
        period: PeriodControl::Schedule(halves),
        life_s: run.life_h * 3600.0,
        limits: Default::default(),
        ..settings.clone()
    };
    let check = run_life(inputs, &halved, None, &mut |_| ControlFlow::Continue(()))?;
    let difference = PerSurface::from_fn(|s| {
        let (a, b) = (run.depth.max(s), check.depth.max(s));
        if b > 0.0 { a / b - 1.0 } else { 0.0 }
    });
    Ok((check, difference))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rates(roller: f64, bar: f64) -> PerSurface<f64> {
        PerSurface::from_fn(|s| match s {
            Surface::Roller => roller,
            Surface::CageBar => bar,
            _ => 0.0,
        })
    }

    #[test]
    fn a_fixed_period_is_never_halved() {
        let change = rate_changes(&rates(1.0, 1.0), &rates(10.0, 1.0));
        assert!(!period_too_long(&PeriodControl::Fixed(1.0), &change, None));
    }

    #[test]
    fn the_automatic_period_halves_on_a_large_change_or_a_reversal() {
        let auto = PeriodControl::auto(1905.0 * 3600.0);
        let small = rate_changes(&rates(1.0, 1.0), &rates(1.2, 1.0));
        assert!((small.get(Surface::Roller) - 0.2).abs() < 1e-12);
        assert!(!period_too_long(&auto, &small, None));
        let large = rate_changes(&rates(1.0, 1.0), &rates(1.0, 0.4));
        assert!(period_too_long(&auto, &large, None));
        // the roller rate fell by 20 %, then rises by 20 %: a reversal beyond the noise
        let fell = rate_changes(&rates(1.0, 1.0), &rates(0.8, 1.0));
        assert!(period_too_long(&auto, &small, Some(&fell)));
        // reversals within the noise (5 %) are not trends
        let noise = rate_changes(&rates(1.0, 1.0), &rates(0.95, 1.0));
        let back = rate_changes(&rates(1.0, 1.0), &rates(1.05, 1.0));
        assert!(!period_too_long(&auto, &back, Some(&noise)));
        // a surface that starts wearing counts as a full change
        let starts = rate_changes(&rates(1.0, 0.0), &rates(1.0, 1.0));
        assert_eq!(starts.get(Surface::CageBar), 1.0);
    }

    #[test]
    fn the_automatic_period_grows_back_only_when_steady() {
        let auto = PeriodControl::auto(1905.0 * 3600.0);
        let calm = rate_changes(&rates(1.0, 1.0), &rates(1.1, 0.95));
        assert!(steady(&auto, &calm));
        let moving = rate_changes(&rates(1.0, 1.0), &rates(1.2, 1.0));
        assert!(!steady(&auto, &moving));
        assert!(!steady(&PeriodControl::Fixed(1.0), &calm));
    }

    #[test]
    fn limits_name_what_was_reached() {
        let mut depth = SurfaceWear::zero(2, 4, 3);
        depth.rib = 50e-6;
        let mut settings = WearSettings::default();
        assert_eq!(limit_reached(&settings, &depth), None);
        settings.limits.depth_m = Some(40e-6);
        assert_eq!(
            limit_reached(&settings, &depth),
            Some(StopReason::DepthLimit(Surface::Rib))
        );
        depth.roller = vec![10e-6, 0.0];
        settings.limits.clearance_increase_m = Some(30e-6);
        assert_eq!(
            limit_reached(&settings, &depth),
            Some(StopReason::ClearanceLimit)
        );
    }
}
