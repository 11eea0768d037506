//! Every knob of the wear calculation, with its default and the reason for it (docs/theory.md §8).

use crate::averaged::SEED_EQUIVALENT_FORCE_EXPONENT;
use crate::coefficient::WearCoefficient;

/// How the wear rates of a period are obtained from the dynamics (seed 000 §2.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WearMethod {
    /// step by step: every output step's force, sliding speed and film give a rate on each wear
    /// line, averaged over the recorded revolutions (seed 000 §2.4.1)
    Direct,
    /// one equivalent force (seed 000 eq. 2.36) and mean sliding speed (2.37) per contact over
    /// the recorded revolutions (seed 000 §2.4.2; valid for Hertz-like contacts only)
    Averaged,
}

/// Which contact width a surface point spends under the contact (the exposure fraction
/// w_c/ρ of seed 000 eq. 3.1, flag F-47).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExposureWidth {
    /// the full contact width 2b: a point of the surface is under the patch while the whole
    /// patch passes over it (the physical reading; the volume removed per unit length is then
    /// k q v / H whatever the pressure shape)
    Full,
    /// the half-width b, as eq. (3.1) is printed (reproduces the seed's arithmetic)
    Half,
}

impl ExposureWidth {
    /// Exposed width for a contact of half-width `half_width`, m.
    pub fn width(self, half_width: f64) -> f64 {
        match self {
            ExposureWidth::Full => 2.0 * half_width,
            ExposureWidth::Half => half_width,
        }
    }
}

/// Where the mean pressure on the raceway wear lines comes from (docs/theory.md §8.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PressureModel {
    /// the slices' Hertz line contacts under the dynamics' slice forces
    Slices,
    /// the Boussinesq solver (seed 004) on the roller's profile at the raceway's equivalent
    /// force — where the edges matter; with the averaged method only (one solve per raceway and
    /// period, as the seed's FE contact at the equivalent force)
    Boussinesq,
}

/// How long the geometry is held fixed between two dynamics runs (seed 000 §3.2.3).
#[derive(Debug, Clone, PartialEq)]
pub enum PeriodControl {
    /// a fixed recalculation period, s
    Fixed(f64),
    /// these periods in turn, the last one repeated, s (the replay of a run's periods)
    Schedule(Vec<f64>),
    /// start with `initial_s`; halve the period when a surface's wear rate changes by more
    /// than `change_threshold` (relative) between periods or reverses its trend by more than
    /// `trend_noise`; never below `minimum_s`. After a period whose rates all changed by less
    /// than a quarter of the threshold the period doubles again, up to `initial_s`. A surface
    /// whose change does not shrink when the period is halved is not period-driven and no
    /// longer decides the period (docs/theory.md §8.8)
    Auto {
        initial_s: f64,
        change_threshold: f64,
        trend_noise: f64,
        minimum_s: f64,
    },
}

impl PeriodControl {
    /// The automatic control with the default threshold (a rate change over 50 %).
    pub fn auto(initial_s: f64) -> Self {
        PeriodControl::Auto {
            initial_s,
            change_threshold: 0.5,
            // between two periods the statistics of 10 recorded revolutions scatter by a few
            // per cent: a reversal smaller than 10 % is noise, not a trend
            trend_noise: 0.1,
            minimum_s: initial_s / 64.0,
        }
    }

    pub fn initial_s(&self) -> f64 {
        match self {
            PeriodControl::Fixed(p) => *p,
            PeriodControl::Schedule(periods) => periods.first().copied().unwrap_or(f64::INFINITY),
            PeriodControl::Auto { initial_s, .. } => *initial_s,
        }
    }
}

/// When the bearing stops being operable (SPEC §6.3 step 7): limits a user sets; `None` = no
/// limit (the run goes to the requested life).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OperabilityLimits {
    /// largest increase of the operating radial clearance, m
    pub clearance_increase_m: Option<f64>,
    /// largest wear depth on any surface, m
    pub depth_m: Option<f64>,
}

/// Settings of a wear calculation.
#[derive(Debug, Clone, PartialEq)]
pub struct WearSettings {
    pub method: WearMethod,
    /// life to reach, s (seed 000: 25 000 h)
    pub life_s: f64,
    pub period: PeriodControl,
    /// cage revolutions recorded per period. Default 10: the cage slip and the contact forces
    /// of 2002834 repeat within 1 % from one 10-revolution window to the next (VALIDATION.md
    /// V-07, discard study)
    pub revolutions: u32,
    /// cage revolutions run and discarded before recording, from the quasi-static start.
    /// Default 10: the slip settles in about 10 revolutions (VALIDATION.md V-07)
    pub settle_revolutions: u32,
    /// dynamics output step, s: the sampling of forces and speeds. Default 0.05 ms (a roller
    /// of 2002834 crosses the 5° of a wear-map bin in 0.4 ms at 8163 rpm: 8 samples per bin)
    pub output_step_s: f64,
    /// k(Λ) and the boundary-friction k (seed 000 Fig. 2.18)
    pub coefficient: WearCoefficient,
    /// exponent of the equivalent force (seed 000 eq. 2.36: 1/3; flag F-49)
    pub equivalent_force_exponent: f64,
    pub exposure_width: ExposureWidth,
    pub pressure_model: PressureModel,
    /// angular bins of the raceway wear maps. Default 72 (5°): the loaded zone of a rotating
    /// load spans ± 60–90° and is resolved by 25–35 bins
    pub angle_bins: usize,
    /// the seed's literal hardness (kgf/mm² read as MPa, flag F-45) instead of Pa
    pub seed_literal_hardness: bool,
    pub limits: OperabilityLimits,
}

impl WearSettings {
    /// Settings that cannot work together: one line naming the flags.
    pub fn validate(&self) -> Result<(), String> {
        if self.pressure_model == PressureModel::Boussinesq && self.method == WearMethod::Direct {
            return Err("--pressure boussinesq needs --method averaged (one Boussinesq solve per raceway and period at the equivalent force)".into());
        }
        Ok(())
    }
}

impl Default for WearSettings {
    fn default() -> Self {
        let hour = 3600.0;
        Self {
            method: WearMethod::Direct,
            life_s: 25_000.0 * hour,
            period: PeriodControl::Fixed(1905.0 * hour),
            revolutions: 10,
            settle_revolutions: 10,
            output_step_s: 5e-5,
            coefficient: WearCoefficient::seed_default(),
            equivalent_force_exponent: SEED_EQUIVALENT_FORCE_EXPONENT,
            exposure_width: ExposureWidth::Full,
            pressure_model: PressureModel::Slices,
            angle_bins: 72,
            seed_literal_hardness: false,
            limits: OperabilityLimits::default(),
        }
    }
}
