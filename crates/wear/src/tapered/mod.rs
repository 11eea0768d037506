//! Wear of the double-row tapered roller bearing (seed 000 §3.2.2–3.2.4; SPEC §6.8 V-23…V-25;
//! docs/theory.md §8.10): the roller on the cone and the cup on wear lines (the slice centres of
//! the roller), the large end on the large rib, by the direct and the averaged method, from a
//! short window of the tapered dynamics; the worn depths fed back into the bearing every
//! period.
//!
//! - [`settings`]: the knobs and their defaults;
//! - [`recorder`]: the dynamics' contact record → direct and averaged rates;
//! - [`life`]: the life loop with a fixed period; [`report`]: its tables and plots.

pub mod life;
pub mod recorder;
pub mod report;
pub mod settings;

pub use life::{
    TaperedLife, TaperedLifeState, TaperedPeriod, WindowRates, run_tapered_life,
    run_tapered_life_from, tapered_rates, wear_lines, worn_further,
};
pub use recorder::{TaperedDiagnostics, TaperedRates, TaperedWearData, TaperedWearRecorder};
pub use report::write_tapered_report;
pub use settings::TaperedWearSettings;
