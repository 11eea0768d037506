//! The knobs of the tapered wear calculation, with their defaults and the reasons for them.

use crate::averaged::SEED_EQUIVALENT_FORCE_EXPONENT;
use crate::coefficient::WearCoefficient;
use crate::settings::{ExposureWidth, WearMethod};
use rolldyn_dynamics::settings::{IntegratorMethod, IntegratorSettings};

/// Settings of a tapered wear calculation.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedWearSettings {
    /// which rates drive the life loop (both are always computed and reported)
    pub method: WearMethod,
    /// life to reach, s (seed 000 §3.2.4: 11 429 h)
    pub life_s: f64,
    /// fixed recalculation period, s (seed 000 §3.2.3: 1905 h stable, 3810 h unstable)
    pub period_s: f64,
    /// dynamics run and discarded from the seated start, s. Default 10 ms: 1.4 roller passes
    /// on the cone, after which the roller loads repeat (VALIDATION.md "Tapered wear")
    pub settle_s: f64,
    /// dynamics window recorded per period, s. Default 20 ms: 2.8 roller passes on the cone;
    /// the 2 × 23 rollers sit at all azimuths, so the window's ensemble covers the loaded zone
    pub window_s: f64,
    /// output step of the dynamics, s (50 µs: 140 samples per roller pass)
    pub sample_interval_s: f64,
    /// wear lines along the roller and the raceways: the slice centres of a roller cut into
    /// this many slices (seed 000 §3.2.3: 9 lines)
    pub wear_lines: usize,
    /// factor on the raceway film for grease (seed 000 §3.2.3: film −30 % for the partial
    /// starvation of grease, k about ×2 by Fig. 2.17)
    pub raceway_film_factor: f64,
    /// k(Λ) and the boundary-friction k
    pub coefficient: WearCoefficient,
    /// exponent of the equivalent force (seed 000 eq. 2.36)
    pub equivalent_force_exponent: f64,
    pub exposure_width: ExposureWidth,
    /// the seed's literal hardness (kgf/mm² read as MPa, flag F-45)
    pub seed_literal_hardness: bool,
    /// the integrator of the dynamics windows (Rosenbrock-W: about 4× faster than Dormand–
    /// Prince on this model with the VG 220 oil)
    pub integrator: IntegratorSettings,
}

impl Default for TaperedWearSettings {
    fn default() -> Self {
        let hour = 3600.0;
        Self {
            method: WearMethod::Averaged,
            life_s: 11_429.0 * hour,
            period_s: 1905.0 * hour,
            settle_s: 0.01,
            window_s: 0.02,
            sample_interval_s: 5e-5,
            wear_lines: 9,
            raceway_film_factor: 0.7,
            coefficient: WearCoefficient::seed_default(),
            equivalent_force_exponent: SEED_EQUIVALENT_FORCE_EXPONENT,
            exposure_width: ExposureWidth::Full,
            seed_literal_hardness: false,
            integrator: IntegratorSettings {
                tolerance: 1e-5,
                method: IntegratorMethod::RosenbrockW,
                ..IntegratorSettings::default()
            },
        }
    }
}
