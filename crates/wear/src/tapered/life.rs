//! The life loop of the tapered bearing with a fixed period (seed 000 §2.4.1 steps 6–7,
//! §3.2.3–3.2.4): dynamics window of the current geometry → wear rates → depth over a period →
//! worn bearing → dynamics …, until the requested life.

use crate::WearError;
use crate::settings::WearMethod;
use crate::tapered::recorder::{
    TaperedDiagnostics, TaperedRates, TaperedWearData, TaperedWearRecorder,
};
use crate::tapered::settings::TaperedWearSettings;
use rolldyn_dynamics::tapered::{TaperedModel, TaperedRunSettings, run_recorded};
use rolldyn_geometry::TaperedWear;
use std::time::Instant;

/// The rates of one geometry by both methods and what they cost.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WindowRates {
    pub direct: TaperedRates,
    pub averaged: TaperedRates,
    pub diagnostics: TaperedDiagnostics,
    /// wall time of the dynamics window with its recorder, s; accepted steps
    pub wall_s: f64,
    pub steps: u64,
}

impl WindowRates {
    /// The rates of `method`.
    pub fn of(&self, method: WearMethod) -> &TaperedRates {
        match method {
            WearMethod::Direct => &self.direct,
            WearMethod::Averaged => &self.averaged,
        }
    }
}

/// One period of the loop: the rates of the geometry at its start, the depth at its end.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct TaperedPeriod {
    /// 1, 2, …
    pub index: usize,
    /// operating time at the end of the period and the period, h
    pub time_h: f64,
    pub period_h: f64,
    pub rates: WindowRates,
    pub wear: TaperedWear,
}

/// A life run.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedLife {
    pub periods: Vec<TaperedPeriod>,
    /// the rates of the geometry at the end of the life
    pub last_window: WindowRates,
    /// the wear lines (slice centres of the wear roller), m
    pub positions_m: Vec<f64>,
    pub life_h: f64,
}

/// `base`'s bearing with `wear`, its roller cut into the wear lines' slices, as a model.
fn worn_model(
    base: &TaperedModel,
    wear: &TaperedWear,
    settings: &TaperedWearSettings,
) -> Result<TaperedModel, WearError> {
    let mut bearing = base.bearing().clone();
    bearing.roller.slice_count = settings.wear_lines;
    bearing.wear = wear.clone();
    TaperedModel::new(
        &bearing,
        base.conditions.clone(),
        base.parameters,
        base.traction_model().clone(),
    )
    .map_err(|e| WearError::Input(e.to_string()))
}

/// The wear lines of `base` under `settings`: the slice centres of the wear roller, m.
pub fn wear_lines(base: &TaperedModel, settings: &TaperedWearSettings) -> Vec<f64> {
    let mut roller = base.bearing().roller.clone();
    roller.slice_count = settings.wear_lines;
    roller.slices().position
}

/// Rates of `base` worn by `wear`: `settings.settle_s` of dynamics from the seated start
/// discarded, `settings.window_s` recorded.
pub fn tapered_rates(
    base: &TaperedModel,
    wear: &TaperedWear,
    settings: &TaperedWearSettings,
) -> Result<WindowRates, WearError> {
    let wall = Instant::now();
    let model = worn_model(base, wear, settings)?;
    let data = TaperedWearData::new(&model, settings)?;
    let run_settings = TaperedRunSettings {
        duration_s: settings.settle_s + settings.window_s,
        sample_interval_s: settings.sample_interval_s,
        row1_offset_pitch: 0.0,
        steady_from_s: Some(settings.settle_s),
        integrator: settings.integrator,
    };
    let mut recorder = TaperedWearRecorder::new(&data, settings, settings.settle_s);
    let run = run_recorded(&model, &run_settings, Some(&mut recorder), |_| {
        std::ops::ControlFlow::Continue(())
    })
    .map_err(|e| WearError::Numerical(e.to_string()))?;
    Ok(WindowRates {
        direct: recorder.rates(WearMethod::Direct)?,
        averaged: recorder.rates(WearMethod::Averaged)?,
        diagnostics: recorder.diagnostics(),
        wall_s: wall.elapsed().as_secs_f64(),
        steps: run.steps,
    })
}

/// `wear` grown by `rates` over `period_s` on the lines `positions`.
pub fn worn_further(
    wear: &TaperedWear,
    positions: &[f64],
    rates: &TaperedRates,
    period_s: f64,
) -> TaperedWear {
    let lines = |before: &[(f64, f64)], rate: &[f64]| {
        positions
            .iter()
            .enumerate()
            .map(|(s, &x)| (x, before.get(s).map_or(0.0, |p| p.1) + rate[s] * period_s))
            .collect()
    };
    TaperedWear {
        roller: lines(&wear.roller, &rates.roller),
        cone: lines(&wear.cone, &rates.cone),
        cup: lines(&wear.cup, &rates.cup),
        large_end: wear.large_end + rates.roller_end * period_s,
        large_rib: wear.large_rib + rates.rib * period_s,
    }
}

/// Where a tapered life run stands after a period: everything the loop needs to go on (a
/// resumable run stores it after every period and gives it back to
/// [`run_tapered_life_from`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct TaperedLifeState {
    pub periods: Vec<TaperedPeriod>,
    /// accumulated wear
    pub wear: TaperedWear,
    /// the rates of the geometry worn by `wear`
    pub current: WindowRates,
    /// operating time, s
    pub time_s: f64,
}

/// Runs the loop; `on_period` sees every period as it ends and may end the run there (the
/// life then stops short of `settings.life_s`).
pub fn run_tapered_life(
    base: &TaperedModel,
    settings: &TaperedWearSettings,
    on_period: &mut dyn FnMut(&TaperedPeriod) -> std::ops::ControlFlow<()>,
) -> Result<TaperedLife, WearError> {
    run_tapered_life_from(base, settings, None, &mut |state| {
        on_period(state.periods.last().expect("a period ended"))
    })
}

/// [`run_tapered_life`] from the unworn bearing or from `start` (a state given to
/// `on_period` by a run with the same inputs and settings); `on_period` sees the state after
/// every period.
pub fn run_tapered_life_from(
    base: &TaperedModel,
    settings: &TaperedWearSettings,
    start: Option<TaperedLifeState>,
    on_period: &mut dyn FnMut(&TaperedLifeState) -> std::ops::ControlFlow<()>,
) -> Result<TaperedLife, WearError> {
    if !(settings.period_s > 0.0 && settings.life_s > 0.0) {
        return Err(WearError::Input(
            "the wear period and the life must be positive".into(),
        ));
    }
    let hour = 3600.0;
    let positions = wear_lines(base, settings);
    let mut state = match start {
        Some(state) => state,
        None => TaperedLifeState {
            periods: Vec::new(),
            current: tapered_rates(base, &TaperedWear::default(), settings)?,
            wear: TaperedWear::default(),
            time_s: 0.0,
        },
    };
    while state.time_s < settings.life_s * (1.0 - 1e-12) {
        let step = settings.period_s.min(settings.life_s - state.time_s);
        let wear = worn_further(
            &state.wear,
            &positions,
            state.current.of(settings.method),
            step,
        );
        let time = state.time_s + step;
        let next = tapered_rates(base, &wear, settings)?;
        let period = TaperedPeriod {
            index: state.periods.len() + 1,
            time_h: time / hour,
            period_h: step / hour,
            rates: std::mem::replace(&mut state.current, next),
            wear: wear.clone(),
        };
        state.periods.push(period);
        (state.wear, state.time_s) = (wear, time);
        if on_period(&state).is_break() {
            break;
        }
    }
    Ok(TaperedLife {
        periods: state.periods,
        last_window: state.current,
        positions_m: positions,
        life_h: state.time_s / hour,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_period_adds_rate_times_period_on_every_line() {
        let rates = TaperedRates {
            roller: vec![1e-15, 2e-15],
            cone: vec![3e-15, 0.0],
            cup: vec![0.0, 1e-16],
            roller_end: 1e-14,
            rib: 2e-14,
            ..TaperedRates::default()
        };
        let positions = [-0.01, 0.01];
        let once = worn_further(&TaperedWear::default(), &positions, &rates, 1e6);
        let twice = worn_further(&once, &positions, &rates, 1e6);
        assert_eq!(once.roller, vec![(-0.01, 1e-9), (0.01, 2e-9)]);
        assert_eq!(twice.cone, vec![(-0.01, 6e-9), (0.01, 0.0)]);
        assert!((twice.large_end - 2e-8).abs() < 1e-20);
        assert!((twice.end_rib_play() - 6e-8).abs() < 1e-20);
    }
}
