//! Parameter sweeps: a table of variants of one model, each overriding any model-file keys,
//! run in parallel, one summary row per variant.
//!
//! The file format, the analyses and the outputs are documented in `docs/sweep-format.md`.
//!
//! A sweep file (TOML) names the base model (relative to the sweep file), the analysis and its
//! settings, and the variants:
//!
//! ```toml
//! model = "../2002834.toml"
//! analysis = "simulate"          # or "skid", "wear", "fatigue"
//! duration = "5rev"              # simulate: simulated time; wear: the life ("25000h")
//! discard = "1rev"               # simulate only: revolutions left out of the summary (default 1)
//! period = "1905h"               # wear only: recalculation period, or "auto" (default 1905h)
//! method = "direct"             # wear: or "averaged"; fatigue: "frame" (default) or "calculix"
//! variants_from = "table-3.1.toml"  # optional: named variants a variant may start from
//!
//! [[variant]]
//! name = "14-bar-ra-0.8"
//! like = "14"                    # the overrides of variant 14 of `variants_from`, then these
//! "cage.roughness_ra" = "0.8 um"
//!
//! [[variant]]
//! name = "11"
//! "clearance.radial" = "0 mm"
//! "misalignment.inner_ring" = "4 arcmin"
//! ```
//!
//! Running a sweep ([`run`]) writes `variants/<name>.json` for every finished variant (written
//! to a temporary file and renamed, so an interrupted sweep loses only the variants in flight)
//! with the [`fingerprint`] of its inputs, skips with `resume` the finished variants whose
//! inputs did not change, runs every n-th variant with a shard `k/n`, and collects all stored
//! variants into `summary.csv`, `summary.parquet` and one SVG per summary column ([`collect`]):
//! the variant name, one column per varied model key ([`varied_columns`]), the index, the
//! figures ([`Figure`]: whole numbers stay integers), the error.
//!
//! [`frozen`] runs the frozen time points of a start-up (seed 000 §3.1.2) the same way.

mod file;
pub mod frozen;
mod run;
mod summary;

pub use file::{
    Analysis, OverrideError, SweepError, SweepFile, Variant, apply_overrides, model_with_overrides,
};
pub use run::{
    Figure, RunOptions, Shard, VariantAnalysis, VariantOutcome, VariantProgress, fingerprint, run,
};
pub use summary::{Summary, SummaryColumn, SummaryValues, collect, varied_columns};
