//! The summary of a tapered run over its steady part (seed 000 §3.2.1): the spectrum of the
//! inner ring's axial motion against the roller-pass frequencies, the cages' speeds and their
//! mutual lag, the load sharing of the rows, sliding and slip, rib forces and regimes.

use super::model::TaperedModel;
use super::sample::TaperedSample;
use std::f64::consts::{PI, TAU};

/// Frequency range and resolution of the axial-motion spectrum, Hz.
const SPECTRUM_RANGE_HZ: (f64, f64) = (20.0, 600.0);
const SPECTRUM_STEP_HZ: f64 = 0.25;
/// Share of the run treated as start transient.
const TRANSIENT_SHARE: f64 = 0.4;

/// Summary of a run (SI units; speeds rad/s, frequencies Hz).
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedSummary {
    /// rollers (and cage pockets) per row
    pub rollers_per_row: usize,
    /// start of the steady window, s
    pub steady_from_s: f64,
    /// epicyclic roller-pass frequencies on the cup and on the cone, Hz
    pub pass_frequency_outer_hz: f64,
    pub pass_frequency_inner_hz: f64,
    /// largest peaks of the inner ring's axial-displacement spectrum: (frequency Hz, amplitude m)
    pub axial_peaks: Vec<(f64, f64)>,
    /// peak-to-peak axial and radial (|x,y| range) motion of the inner ring, m
    pub axial_range_m: f64,
    pub radial_range_m: f64,
    /// mean inner-ring centre, m
    pub inner_ring_mean: [f64; 3],
    /// mean cage speeds, rad/s, and the epicyclic cage speed
    pub cage_speed_mean: [f64; 2],
    pub cage_speed_epicyclic: f64,
    /// lag of cage 1 behind cage 0 at the end, as a fraction of the pocket pitch (0…1)
    pub cage_lag_pitch_fraction: f64,
    /// mean number of rollers within 10 % of the row's largest load, per row
    pub rollers_near_max_mean: [f64; 2],
    /// share of samples with one roller at the maximum in one row and two in the other
    pub one_and_two_share: f64,
    /// largest roller load on the cone per row, N
    pub max_cone_load: [f64; 2],
    /// largest large-end ↔ rib force per row, N
    pub max_rib_force: [f64; 2],
    /// mean load-weighted sliding speed on cone and cup per row, m/s
    pub cone_sliding_mean: [f64; 2],
    pub cup_sliding_mean: [f64; 2],
    /// largest relative slip of a loaded slice
    pub max_slip: f64,
    /// share of loaded large-rib contacts in EHL
    pub rib_ehl_share: f64,
}

/// Summary of `samples` from `steady_from_s` (`None`: [`steady_window`]).
pub fn summarise(
    model: &TaperedModel,
    samples: &[TaperedSample],
    steady_from_s: Option<f64>,
) -> TaperedSummary {
    let w = match steady_from_s {
        Some(t0) => {
            let start = samples.partition_point(|s| s.time_s < t0);
            &samples[start.min(samples.len().saturating_sub(1))..]
        }
        None => steady_window(samples),
    };
    let m = w.len().max(1) as f64;
    let (fo, fi) = model
        .bearing
        .pass_frequencies(model.conditions.inner_speed.speed(0.0));
    let mean = |f: &dyn Fn(&TaperedSample) -> f64| w.iter().map(f).sum::<f64>() / m;
    let max = |f: &dyn Fn(&TaperedSample) -> f64| w.iter().map(f).fold(f64::MIN, f64::max);
    let min = |f: &dyn Fn(&TaperedSample) -> f64| w.iter().map(f).fold(f64::MAX, f64::min);
    let inner_ring_mean = [0, 1, 2].map(|i| mean(&|s| s.inner_ring[i]));
    let radial = |s: &TaperedSample| {
        (s.inner_ring[0] - inner_ring_mean[0]).hypot(s.inner_ring[1] - inner_ring_mean[1])
    };
    let pitch = TAU / model.z as f64;
    let last = w.last();
    let lag = last.map_or(0.0, |s| {
        (s.cage_angle[0] - s.cage_angle[1]).rem_euclid(pitch) / pitch
    });
    let one_and_two = w
        .iter()
        .filter(|s| {
            let r = s.rollers_near_max;
            (r[0] == 1 && r[1] == 2) || (r[0] == 2 && r[1] == 1)
        })
        .count() as f64
        / m;
    TaperedSummary {
        rollers_per_row: model.z,
        steady_from_s: w.first().map_or(0.0, |s| s.time_s),
        pass_frequency_outer_hz: fo,
        pass_frequency_inner_hz: fi,
        axial_peaks: spectrum_peaks(w, 3),
        axial_range_m: max(&|s| s.inner_ring[2]) - min(&|s| s.inner_ring[2]),
        radial_range_m: 2.0 * max(&radial),
        inner_ring_mean,
        cage_speed_mean: [0, 1].map(|k| mean(&|s| s.cage_speed[k])),
        cage_speed_epicyclic: model.epicyclic_cage_speed,
        cage_lag_pitch_fraction: lag,
        rollers_near_max_mean: [0, 1].map(|k| mean(&|s| s.rollers_near_max[k] as f64)),
        one_and_two_share: one_and_two,
        max_cone_load: [0, 1].map(|k| max(&|s| s.max_cone_load[k])),
        max_rib_force: [0, 1].map(|k| max(&|s| s.max_rib_force[k])),
        cone_sliding_mean: [0, 1].map(|k| mean(&|s| s.cone_sliding[k])),
        cup_sliding_mean: [0, 1].map(|k| mean(&|s| s.cup_sliding[k])),
        max_slip: max(&|s| s.max_slip),
        rib_ehl_share: mean(&|s| s.rib_ehl_share),
    }
}

/// The samples after the start transient (the last 1 − [`TRANSIENT_SHARE`] of the run), over
/// which the summary is taken.
pub fn steady_window(samples: &[TaperedSample]) -> &[TaperedSample] {
    let n = samples.len();
    let start = ((n as f64) * TRANSIENT_SHARE) as usize;
    &samples[start.min(n.saturating_sub(1))..]
}

/// The `count` largest local maxima of [`axial_spectrum`].
pub fn spectrum_peaks(w: &[TaperedSample], count: usize) -> Vec<(f64, f64)> {
    let amp = axial_spectrum(w);
    if amp.len() < 3 {
        return Vec::new();
    }
    let mut peaks: Vec<(f64, f64)> = (1..amp.len() - 1)
        .filter(|&i| amp[i].1 > amp[i - 1].1 && amp[i].1 >= amp[i + 1].1)
        .map(|i| amp[i])
        .collect();
    peaks.sort_by(|a, b| b.1.total_cmp(&a.1));
    peaks.truncate(count);
    peaks
}

/// The Hann-windowed amplitude spectrum (frequency Hz, amplitude m) of the inner ring's axial
/// displacement (mean removed) over [`SPECTRUM_RANGE_HZ`] — a direct DFT at each frequency, so
/// the resolution does not depend on the record length (its bandwidth does: ≈ 2/T); empty for
/// fewer than 8 samples.
pub fn axial_spectrum(w: &[TaperedSample]) -> Vec<(f64, f64)> {
    if w.len() < 8 {
        return Vec::new();
    }
    let n = w.len();
    let mean = w.iter().map(|s| s.inner_ring[2]).sum::<f64>() / n as f64;
    let t0 = w[0].time_s;
    let hann: Vec<f64> = (0..n)
        .map(|i| 0.5 - 0.5 * (TAU * i as f64 / (n - 1) as f64).cos())
        .collect();
    let gain: f64 = hann.iter().sum::<f64>();
    let steps = ((SPECTRUM_RANGE_HZ.1 - SPECTRUM_RANGE_HZ.0) / SPECTRUM_STEP_HZ) as usize;
    (0..=steps)
        .map(|k| {
            let f = SPECTRUM_RANGE_HZ.0 + k as f64 * SPECTRUM_STEP_HZ;
            let (mut re, mut im) = (0.0, 0.0);
            for (s, h) in w.iter().zip(&hann) {
                let (sn, cs) = (2.0 * PI * f * (s.time_s - t0)).sin_cos();
                let x = (s.inner_ring[2] - mean) * h;
                re += x * cs;
                im -= x * sn;
            }
            (f, 2.0 * re.hypot(im) / gain)
        })
        .collect()
}
