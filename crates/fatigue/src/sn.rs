//! The S–N (Wöhler) curve of the cage material (theory §10.5, seed 000 §3.1.1.8): a table of
//! (N, σ_a) points of the fully reversed (R = −1) base curve, interpolated linearly in
//! (lg N, lg σ_a), knocked down by the coating and the stress safety factor:
//! σ_a,allow(N) = σ_a,base(N) / (k_coat · k_safety).
//!
//! Outside the table: above the first point (the low-cycle side) the first segment's slope
//! continues; below the last point (the knee) [`BelowKnee`] decides.

use rolldyn_geometry::{FatigueStrength, first_invalid_sn_point};
use serde::{Deserialize, Serialize};

/// MPa → Pa (the unit of σ_a in a user's CSV table).
const MPA: f64 = 1e6;

// the seed's cage-steel constants live with its database entry (`40khn2ma-sh`)
pub use rolldyn_geometry::material_database::{
    AISI_4340_BASQUIN_EXPONENT, AISI_4340_FIRST_CYCLES, AISI_4340_KNEE_CYCLES,
    AISI_4340_ULTIMATE_STRENGTH_PA, SEED_FATIGUE_STRENGTH_CYCLES, SEED_FATIGUE_STRENGTH_PA,
};

/// What a cycle below the knee (the last table point) does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BelowKnee {
    /// no damage: the last point is an endurance limit (default, SPEC §7.5)
    #[default]
    NoDamage,
    /// the last segment's slope continues
    Extrapolate,
    /// Haibach: the inverse slope k of the last segment (N ∝ σ_a^−k) becomes 2k − 1
    Haibach,
}

/// Knock-downs and the knee treatment (flag F-55: coating and safety factor are separate).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SnSettings {
    /// a plating shifts the curve down by lg k_coat (silver, seed 000 §3.1.1.8: lg 1.5; a
    /// fatigue run takes it from `cage.plating`, [`crate::cage_material`])
    pub coating_factor: f64,
    /// stress margin (seed 000 §3.1.1.8: normative 1.5 … 2.5); 1.0 by default so that the seed's
    /// single lg 1.5 shift is reproduced (F-55 proposal)
    pub stress_safety_factor: f64,
    pub below_knee: BelowKnee,
}

impl Default for SnSettings {
    fn default() -> Self {
        Self {
            coating_factor: 1.5,
            stress_safety_factor: 1.0,
            below_knee: BelowKnee::NoDamage,
        }
    }
}

impl SnSettings {
    /// The divisor of the base curve's amplitudes, k_coat · k_safety.
    pub fn knock_down(&self) -> f64 {
        self.coating_factor * self.stress_safety_factor
    }
}

/// An S–N table or its settings that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SnError {
    #[error("an S–N curve needs at least two points, got {0}")]
    TooFewPoints(usize),
    #[error("S–N point {index}: {reason}")]
    Point { index: usize, reason: String },
    #[error("line {line}: {reason}")]
    Line { line: usize, reason: String },
    #[error("S–N settings: {0}")]
    Settings(String),
}

/// A fully reversed S–N curve: (N, σ_a [Pa]) points with N increasing and σ_a decreasing (built
/// only through the checking constructors, so it is not deserialisable).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SnCurve {
    points: Vec<(f64, f64)>,
    settings: SnSettings,
}

/// A point in (lg N, lg σ_a).
fn log_point(&(n, s): &(f64, f64)) -> (f64, f64) {
    (n.log10(), s.log10())
}

/// Slope d lg σ_a / d lg N of the segment from `a` to `b` (both `(N, σ_a)`).
fn log_slope(a: &(f64, f64), b: &(f64, f64)) -> f64 {
    let ((xa, ya), (xb, yb)) = (log_point(a), log_point(b));
    (yb - ya) / (xb - xa)
}

/// Haibach's slope below the knee: with k = −1/m the inverse slope of the last segment, k' =
/// 2k − 1 and the slope −1/k' (Haibach E., LBF Technische Mitteilung TM 50/70, 1970).
fn haibach_slope(last_slope: f64) -> f64 {
    -1.0 / (2.0 * (-1.0 / last_slope) - 1.0)
}

impl SnCurve {
    /// A curve from `(N, σ_a [Pa])` points with the default [`SnSettings`].
    pub fn new(points: Vec<(f64, f64)>) -> Result<Self, SnError> {
        if points.len() < 2 {
            return Err(SnError::TooFewPoints(points.len()));
        }
        if let Some((index, reason)) = first_invalid_sn_point(&points) {
            return Err(SnError::Point { index, reason });
        }
        Ok(Self {
            points,
            settings: SnSettings::default(),
        })
    }

    /// The same curve with `settings`; the factors must be finite and positive.
    pub fn with_settings(mut self, settings: SnSettings) -> Result<Self, SnError> {
        for (name, f) in [
            ("coating_factor", settings.coating_factor),
            ("stress_safety_factor", settings.stress_safety_factor),
        ] {
            if !(f.is_finite() && f > 0.0) {
                return Err(SnError::Settings(format!(
                    "{name} = {f} must be finite and positive"
                )));
            }
        }
        self.settings = settings;
        Ok(self)
    }

    /// The seed's cage-steel curve (database entry `40khn2ma-sh`, theory §10.5): the seed's 480
    /// MPa at 10⁶ cycles with the Basquin slope of AISI 4340 (Dowling 2013, Table 9.1),
    /// tabulated per decade from 10³ cycles to the knee at 10⁷ (383 MPa).
    pub fn aisi_4340() -> Self {
        let record = rolldyn_geometry::material_database::find("40khn2ma-sh")
            .expect("the database holds the seed's cage steel");
        Self::new(record.sn_curve.points()).expect("the Basquin table is monotone")
    }

    /// The base curve of a material's fatigue data, with the default [`SnSettings`].
    pub fn of_material(strength: &FatigueStrength) -> Result<Self, SnError> {
        Self::new(strength.sn_curve.clone())
    }

    /// A user's table from CSV text: rows `N, σ_a` with σ_a in MPa (a header row, blank lines
    /// and `#` comments are skipped); the error names the 1-based line and the reason.
    pub fn from_csv_text(text: &str) -> Result<Self, SnError> {
        let mut lines = Vec::new();
        let mut points = Vec::new();
        let rows = text
            .lines()
            .enumerate()
            .map(|(i, raw)| (i + 1, raw.split('#').next().unwrap_or("").trim()))
            .filter(|(_, row)| !row.is_empty());
        for (k, (line, row)) in rows.enumerate() {
            let numbers: Vec<Option<f64>> = row.split(',').map(|f| f.trim().parse().ok()).collect();
            match numbers.as_slice() {
                [None, ..] if k == 0 => {} // the header row
                [Some(n), Some(mpa)] => {
                    lines.push(line);
                    points.push((*n, mpa * MPA));
                }
                _ => {
                    return Err(SnError::Line {
                        line,
                        reason: format!("expected two numbers `N, σ_a in MPa`, found `{row}`"),
                    });
                }
            }
        }
        if points.len() < 2 {
            return Err(SnError::TooFewPoints(points.len()));
        }
        match first_invalid_sn_point(&points) {
            Some((index, reason)) => Err(SnError::Line {
                line: lines[index],
                reason,
            }),
            None => Self::new(points),
        }
    }

    /// The table as CSV text in the form [`Self::from_csv_text`] reads (σ_a in MPa).
    pub fn to_csv_text(&self) -> String {
        let rows = self
            .points
            .iter()
            .map(|(n, s)| format!("{n:e},{}\n", s / MPA));
        std::iter::once("N,sigma_a_MPa\n".to_string())
            .chain(rows)
            .collect()
    }

    /// The knock-downs and the knee treatment.
    pub fn settings(&self) -> &SnSettings {
        &self.settings
    }

    /// The table, `(N, σ_a [Pa])`.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// The last point: the knee.
    pub fn knee(&self) -> (f64, f64) {
        self.points[self.points.len() - 1]
    }

    /// Slope d lg σ_a / d lg N beyond the knee; `None` for a flat endurance limit.
    fn slope_below_knee(&self) -> Option<f64> {
        let n = self.points.len();
        let last = log_slope(&self.points[n - 2], &self.points[n - 1]);
        match self.settings.below_knee {
            BelowKnee::NoDamage => None,
            BelowKnee::Extrapolate => Some(last),
            BelowKnee::Haibach => Some(haibach_slope(last)),
        }
    }

    /// Segment `i` (from point `i` to `i + 1`): its first point in (lg N, lg σ_a) and its slope.
    fn segment(&self, i: usize) -> ((f64, f64), f64) {
        let (a, b) = (&self.points[i], &self.points[i + 1]);
        (log_point(a), log_slope(a, b))
    }

    /// The segment that applies: it starts at the last interior point that `passed` — the
    /// first segment when none has (the low-cycle side).
    fn segment_index(&self, passed: impl Fn(&(f64, f64)) -> bool) -> usize {
        (1..self.points.len() - 1)
            .take_while(|&i| passed(&self.points[i]))
            .last()
            .unwrap_or(0)
    }

    /// σ_a of the base curve at `cycles` (linear in lg N, lg σ_a; beyond the knee flat for
    /// [`BelowKnee::NoDamage`]), Pa.
    pub fn base_amplitude(&self, cycles: f64) -> f64 {
        let lg_n = cycles.log10();
        let (knee_n, knee_s) = self.knee();
        if cycles > knee_n {
            let slope = self.slope_below_knee().unwrap_or(0.0);
            return knee_s * 10f64.powf(slope * (lg_n - knee_n.log10()));
        }
        let ((x0, y0), slope) = self.segment(self.segment_index(|p| p.0 <= cycles));
        10f64.powf(y0 + slope * (lg_n - x0))
    }

    /// The allowable amplitude σ_a,base(N) / (k_coat · k_safety), Pa (seed 000 §3.1.1.8).
    pub fn allowable_amplitude(&self, cycles: f64) -> f64 {
        self.base_amplitude(cycles) / self.settings.knock_down()
    }

    /// Cycles to failure N at the equivalent fully reversed amplitude `amplitude` [Pa] on the
    /// allowable curve (the inverse of [`Self::allowable_amplitude`]); ∞ for no damage (zero
    /// amplitude, or below the knee with [`BelowKnee::NoDamage`]), 0 for an infinite amplitude.
    pub fn cycles_to_failure(&self, amplitude: f64) -> f64 {
        if amplitude <= 0.0 {
            return f64::INFINITY;
        }
        let base = amplitude * self.settings.knock_down();
        let lg_s = base.log10();
        let (knee_n, knee_s) = self.knee();
        if base < knee_s {
            return match self.slope_below_knee() {
                None => f64::INFINITY,
                Some(slope) => 10f64.powf(knee_n.log10() + (lg_s - knee_s.log10()) / slope),
            };
        }
        // σ_a decreases along the table
        let ((x0, y0), slope) = self.segment(self.segment_index(|p| p.1 >= base));
        10f64.powf(x0 + (lg_s - y0) / slope)
    }
}
