//! Fatigue plots (SVG): the S–N diagram with the counted cycles and the rainflow matrix.

use crate::damage::{CycleDamage, DamageBreakdown};
use crate::rainflow::Cycle;
use crate::sn::SnCurve;
use rolldyn_plot::{Field, Labels, MapLabels, PlotError, Series, log_log_plot, map_plot};
use std::path::Path;

/// Pa → MPa for the axes.
const PER_MPA: f64 = 1e-6;
/// Points per decade of N along the drawn curves.
const CURVE_POINTS_PER_DECADE: usize = 20;

/// The cycle range of the diagram: from a decade below the first table point to two decades past
/// the knee or the longest finite N_j, whichever is larger.
fn diagram_cycles(curve: &SnCurve, damage: &DamageBreakdown) -> (f64, f64) {
    let first = curve.points()[0].0 / 10.0;
    let longest = damage
        .cycles
        .iter()
        .map(|c| c.cycles_to_failure)
        .filter(|n| n.is_finite())
        .fold(curve.knee().0, f64::max);
    (first, 100.0 * longest)
}

/// `amplitude(N)` in MPa sampled log-uniformly over `[n0, n1]`.
fn sampled(n0: f64, n1: f64, amplitude: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let decades = (n1 / n0).log10();
    let count = (decades * CURVE_POINTS_PER_DECADE as f64).ceil() as usize;
    (0..=count)
        .map(|i| {
            let n = n0 * 10f64.powf(decades * i as f64 / count as f64);
            (n, amplitude(n) * PER_MPA)
        })
        .collect()
}

/// Writes the S–N diagram to `path`: the base and the allowable curve, the counted cycles at
/// (N_j, σ_ar,j), and the cycles that do no damage at the right edge.
pub fn sn_diagram(path: &Path, curve: &SnCurve, damage: &DamageBreakdown) -> Result<(), PlotError> {
    let (n0, n1) = diagram_cycles(curve, damage);
    let base = sampled(n0, n1, |n| curve.base_amplitude(n));
    let allowable = sampled(n0, n1, |n| curve.allowable_amplitude(n));
    let at = |c: &CycleDamage| {
        let n = if c.cycles_to_failure.is_finite() {
            c.cycles_to_failure
        } else {
            n1
        };
        (n, c.equivalent_amplitude_pa * PER_MPA)
    };
    let (damaging, harmless): (Vec<_>, Vec<_>) = damage.cycles.iter().partition(|c| c.damage > 0.0);
    let damaging: Vec<(f64, f64)> = damaging.into_iter().map(at).collect();
    let harmless: Vec<(f64, f64)> = harmless.into_iter().map(at).collect();
    let knock_down = format!("allowable (÷{:.3})", curve.settings().knock_down());
    log_log_plot(
        path,
        &Labels {
            title: "S–N curve and counted cycles",
            x: "cycles to failure N",
            y: "stress amplitude σ_a, MPa",
        },
        &[
            Series {
                label: "base curve (R = −1)",
                points: &base,
            },
            Series {
                label: &knock_down,
                points: &allowable,
            },
        ],
        &[
            Series {
                label: "counted cycles (N_j, σ_ar,j)",
                points: &damaging,
            },
            Series {
                label: "no damage (drawn at the right end)",
                points: &harmless,
            },
        ],
    )
}

/// Counts of cycles binned by mean (x) and range (y): a regular `bins × bins` grid over the
/// counted values, x-fastest (the layout of [`Field`]).
#[derive(Debug, Clone, PartialEq)]
pub struct RainflowMatrix {
    pub counts: Vec<f64>,
    pub bins: usize,
    /// (mean_min, mean_max, range_min, range_max), the unit of the cycles
    pub extent: (f64, f64, f64, f64),
}

impl RainflowMatrix {
    /// Bins `cycles` (weighted by their count) into `bins × bins` cells; the range axis starts at 0.
    pub fn from_cycles(cycles: &[Cycle], bins: usize) -> Self {
        let bins = bins.max(1);
        if cycles.is_empty() {
            return Self {
                counts: vec![0.0; bins * bins],
                bins,
                extent: (0.0, 1.0, 0.0, 1.0),
            };
        }
        let (m0, m1) = cycles
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                (lo.min(c.mean), hi.max(c.mean))
            });
        let r1 = cycles
            .iter()
            .fold(f64::MIN_POSITIVE, |hi, c| hi.max(c.range));
        // a single mean: a column one largest range wide around it
        let (m0, m1) = if m1 > m0 {
            (m0, m1)
        } else {
            (m0 - 0.5 * r1, m1 + 0.5 * r1)
        };
        let cell = |v: f64, lo: f64, hi: f64| {
            (((v - lo) / (hi - lo) * bins as f64) as usize).min(bins - 1)
        };
        let mut counts = vec![0.0; bins * bins];
        for c in cycles {
            counts[cell(c.range, 0.0, r1) * bins + cell(c.mean, m0, m1)] += c.count;
        }
        Self {
            counts,
            bins,
            extent: (m0, m1, 0.0, r1),
        }
    }
}

/// Writes the rainflow matrix of `cycles` (stresses in Pa, shown in MPa) to `path`: a heat map of
/// the counts over mean × range in `bins × bins` cells.
pub fn rainflow_matrix(path: &Path, cycles: &[Cycle], bins: usize) -> Result<(), PlotError> {
    let matrix = RainflowMatrix::from_cycles(cycles, bins);
    let (m0, m1, r0, r1) = matrix.extent;
    map_plot(
        path,
        &Labels {
            title: "Rainflow matrix",
            x: "mean σ_m, MPa",
            y: "range Δσ, MPa",
        },
        &Field {
            values: &matrix.counts,
            nx: matrix.bins,
            ny: matrix.bins,
            extent: (m0 * PER_MPA, m1 * PER_MPA, r0 * PER_MPA, r1 * PER_MPA),
        },
        &MapLabels {
            value: "cycles per repeat",
            outline: &[],
        },
    )
}
