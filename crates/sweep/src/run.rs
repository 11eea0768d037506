//! Running variants in parallel, with shards and resume, and collecting their summaries.

use crate::file::{SweepError, SweepFile, Variant};
use rayon::prelude::*;
use rolldyn_numerics::hash::fnv1a;
use rolldyn_output::{replace_file_atomically, seal_json, verify_sealed_json};
use serde::{Deserialize, Deserializer, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Run every n-th variant: shard `k/n` takes variants `i` with `i mod n = k − 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl FromStr for Shard {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let (k, n) = text
            .split_once('/')
            .ok_or_else(|| format!("'{text}': expected k/n, e.g. 2/8"))?;
        let (k, n): (usize, usize) = (
            k.trim()
                .parse()
                .map_err(|_| format!("'{text}': k is not a whole number"))?,
            n.trim()
                .parse()
                .map_err(|_| format!("'{text}': n is not a whole number"))?,
        );
        if n == 0 || k == 0 || k > n {
            return Err(format!("'{text}': need 1 ≤ k ≤ n"));
        }
        Ok(Self {
            index: k - 1,
            count: n,
        })
    }
}

impl<'de> Deserialize<'de> for Shard {
    /// `"k/n"`, as on the command line.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        String::deserialize(deserializer)?
            .parse()
            .map_err(serde::de::Error::custom)
    }
}

/// One summary figure of a variant: a whole number (a count, a flag as 0/1) or a real number
/// (SI). A variant file written as `1.0` reads back as real, `1` as whole.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Figure {
    Integer(i64),
    Real(f64),
}

impl Figure {
    pub fn as_f64(self) -> f64 {
        match self {
            Self::Integer(n) => n as f64,
            Self::Real(x) => x,
        }
    }
}

/// The analysis of one variant: its summary figures (SI) or an error message.
pub type VariantAnalysis<'a> =
    dyn Fn(&Variant, rolldyn_model::Model) -> Result<BTreeMap<String, Figure>, String> + Sync + 'a;

/// Called after every variant of a run with its outcome, the variants finished so far in this
/// run and the variants this run started with.
pub type VariantProgress<'a> = dyn Fn(&VariantOutcome, usize, usize) + Sync + 'a;

/// How to run a sweep.
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// Output folder (variants/, summary.*).
    pub out_dir: PathBuf,
    /// Parallel jobs (≥ 1).
    pub jobs: usize,
    pub shard: Option<Shard>,
    /// Skip variants already finished in `out_dir` with the same inputs ([`fingerprint`]).
    pub resume: bool,
    /// The analysis settings that decide a result besides the sweep file (solver options and
    /// tolerances), as text: part of every variant's [`fingerprint`].
    pub settings: String,
}

/// The stored result of one variant (`variants/<name>.json`).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct VariantOutcome {
    pub name: String,
    /// Position of the variant in the sweep file.
    pub index: usize,
    /// Summary figures (SI), `None` when the variant failed.
    pub summary: Option<BTreeMap<String, Figure>>,
    pub error: Option<String>,
    pub wall_time_s: f64,
    /// [`fingerprint`] of the inputs this result was computed from (empty in older files).
    #[serde(default)]
    pub fingerprint: String,
    /// This run replaced a stored result computed from other inputs (not stored).
    #[serde(skip)]
    pub inputs_changed: bool,
    /// Why this run replaced a stored result it could not trust: `"… damaged: checksum
    /// mismatch"`, an unreadable file (not stored).
    #[serde(skip)]
    pub replaced_damaged: Option<String>,
}

/// Fingerprint (16 hex digits) of everything that decides the result of `variant`: the program
/// version, the analysis and duration of the sweep file, `settings` ([`RunOptions`]) and the
/// variant's model with its overrides, fully resolved (defaults applied, oil file read).
pub fn fingerprint(sweep: &SweepFile, variant: &Variant, settings: &str) -> String {
    let model = match sweep.model_of(variant) {
        Ok(model) => format!("{model:?}"),
        Err(e) => e.to_string(),
    };
    let inputs = format!(
        "rolldyn {}\n{:?}\n{:?}\n{:?}\n{settings}\n{model}",
        env!("CARGO_PKG_VERSION"),
        sweep.analysis,
        sweep.duration,
        sweep.discard
    );
    format!("{:016x}", fnv1a(inputs.as_bytes()))
}

fn variant_file(out: &Path, name: &str) -> PathBuf {
    out.join("variants").join(format!("{name}.json"))
}

/// The stored outcome of variant `name`: `None` when it has no file, an error when its file
/// cannot be read or does not match its checksum (`"…: damaged: checksum mismatch"`).
pub(crate) fn stored(out: &Path, name: &str) -> Result<Option<VariantOutcome>, String> {
    let path = variant_file(out, name);
    let text = match std::fs::read_to_string(&path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        read => read.map_err(|e| format!("cannot read {}: {e}", path.display()))?,
    };
    let outcome =
        serde_json::from_str(&text).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    verify_sealed_json(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(Some(outcome))
}

/// A variant to run now, with its fingerprint, whether a stored result had other inputs and
/// why a stored result could not be trusted.
struct Planned<'a> {
    index: usize,
    variant: &'a Variant,
    fingerprint: String,
    inputs_changed: bool,
    replaced_damaged: Option<String>,
}

/// The variants of this run: those of the shard, without (with `resume`) the finished ones
/// whose inputs did not change.
fn plan<'a>(sweep: &'a SweepFile, options: &RunOptions) -> Vec<Planned<'a>> {
    sweep
        .variants
        .iter()
        .enumerate()
        .filter(|(i, _)| options.shard.is_none_or(|s| i % s.count == s.index))
        .filter_map(|(index, variant)| {
            let fingerprint = fingerprint(sweep, variant, &options.settings);
            let (previous, replaced_damaged) = match stored(&options.out_dir, &variant.name) {
                Ok(previous) => (previous, None),
                Err(damaged) => (None, options.resume.then_some(damaged)),
            };
            let same_inputs = previous.as_ref().map(|p| p.fingerprint == fingerprint);
            let finished = previous.is_some_and(|p| p.summary.is_some());
            if options.resume && finished && same_inputs == Some(true) {
                return None;
            }
            Some(Planned {
                index,
                variant,
                fingerprint,
                inputs_changed: same_inputs == Some(false),
                replaced_damaged,
            })
        })
        .collect()
}

/// Runs the selected variants with `analysis` (one call per variant; it must be thread-safe and
/// single-threaded inside). Each outcome is written as soon as it finishes; `progress` is called
/// after every variant. Once `stop` returns true no further variant starts (those running
/// finish and are stored, so that `resume` continues). Returns the outcomes of the variants
/// run now.
pub fn run(
    sweep: &SweepFile,
    options: &RunOptions,
    analysis: &VariantAnalysis<'_>,
    progress: &VariantProgress<'_>,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<Vec<VariantOutcome>, SweepError> {
    let dir = options.out_dir.join("variants");
    std::fs::create_dir_all(&dir).map_err(|e| {
        SweepError::new(
            &sweep.path,
            "",
            format!("cannot create {}: {e}", dir.display()),
        )
    })?;
    let selected = plan(sweep, options);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| SweepError::new(&sweep.path, "", e.to_string()))?;
    let done = AtomicUsize::new(0);
    let outcomes: Vec<Result<VariantOutcome, SweepError>> = pool.install(|| {
        selected
            .par_iter()
            .filter(|_| !stop())
            .map(|planned| {
                let variant = planned.variant;
                let start = std::time::Instant::now();
                let result = sweep
                    .model_of(variant)
                    .map_err(|e| e.to_string())
                    .and_then(|model| analysis(variant, model));
                let outcome = VariantOutcome {
                    name: variant.name.clone(),
                    index: planned.index,
                    summary: result.as_ref().ok().cloned(),
                    error: result.err(),
                    wall_time_s: start.elapsed().as_secs_f64(),
                    fingerprint: planned.fingerprint.clone(),
                    inputs_changed: planned.inputs_changed,
                    replaced_damaged: planned.replaced_damaged.clone(),
                };
                let path = variant_file(&options.out_dir, &variant.name);
                let fail =
                    |reason: String| SweepError::new(&sweep.path, variant.name.clone(), reason);
                let text = seal_json(&outcome)
                    .map_err(|e| fail(format!("cannot write {}: {e}", path.display())))?;
                replace_file_atomically(&path, text.as_bytes()).map_err(|e| fail(e.to_string()))?;
                progress(
                    &outcome,
                    done.fetch_add(1, Ordering::SeqCst) + 1,
                    selected.len(),
                );
                Ok(outcome)
            })
            .collect()
    });
    outcomes.into_iter().collect()
}
