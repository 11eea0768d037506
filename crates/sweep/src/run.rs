//! Running variants in parallel, with shards and resume, and collecting their summaries.

use crate::file::{SweepError, SweepFile, Variant};
use rayon::prelude::*;
use rolldyn_numerics::hash::fnv1a;
use rolldyn_output::{Column, Values, csv_field, write_parquet_table};
use rolldyn_plot::{Labels, Series, line_plot};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;

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

/// The analysis of one variant: its summary figures (SI) or an error message.
pub type VariantAnalysis<'a> =
    dyn Fn(&Variant, rolldyn_model::Model) -> Result<BTreeMap<String, f64>, String> + Sync + 'a;

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
    pub summary: Option<BTreeMap<String, f64>>,
    pub error: Option<String>,
    pub wall_time_s: f64,
    /// [`fingerprint`] of the inputs this result was computed from (empty in older files).
    #[serde(default)]
    pub fingerprint: String,
    /// This run replaced a stored result computed from other inputs (not stored).
    #[serde(skip)]
    pub inputs_changed: bool,
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
/// cannot be read.
fn stored(out: &Path, name: &str) -> Result<Option<VariantOutcome>, String> {
    let path = variant_file(out, name);
    let text = match std::fs::read_to_string(&path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        read => read.map_err(|e| format!("cannot read {}: {e}", path.display()))?,
    };
    serde_json::from_str(&text)
        .map(Some)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))
}

/// A variant to run now, with its fingerprint and whether a stored result had other inputs.
struct Planned<'a> {
    index: usize,
    variant: &'a Variant,
    fingerprint: String,
    inputs_changed: bool,
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
            let previous = stored(&options.out_dir, &variant.name).ok().flatten();
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
            })
        })
        .collect()
}

/// Runs the selected variants with `analysis` (one call per variant; it must be thread-safe and
/// single-threaded inside). Each outcome is written as soon as it finishes; `progress` is called
/// after every variant. Returns the outcomes of the variants run now.
pub fn run(
    sweep: &SweepFile,
    options: &RunOptions,
    analysis: &VariantAnalysis<'_>,
    progress: &(dyn Fn(&VariantOutcome) + Sync),
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
    let outcomes: Vec<Result<VariantOutcome, SweepError>> = pool.install(|| {
        selected
            .par_iter()
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
                };
                let path = variant_file(&options.out_dir, &variant.name);
                let tmp = path.with_extension("json.tmp");
                let text = serde_json::to_string_pretty(&outcome).unwrap_or_default();
                std::fs::write(&tmp, text)
                    .and_then(|_| std::fs::rename(&tmp, &path))
                    .map_err(|e| {
                        SweepError::new(
                            &sweep.path,
                            variant.name.clone(),
                            format!("cannot write {}: {e}", path.display()),
                        )
                    })?;
                progress(&outcome);
                Ok(outcome)
            })
            .collect()
    });
    outcomes.into_iter().collect()
}

/// A row of the summary: a stored outcome, or why its values are blank.
struct SummaryRow {
    name: String,
    index: usize,
    summary: Option<BTreeMap<String, f64>>,
    error: Option<String>,
}

/// The summary rows of the variants that have a result file in `options.out_dir`, in the order
/// of the sweep file. A result computed from other inputs than the variant's current ones
/// ([`fingerprint`]) or an unreadable file gives a row without values that says so.
fn summary_rows(sweep: &SweepFile, options: &RunOptions) -> Vec<SummaryRow> {
    let blank = |name: &str, index, error: String| SummaryRow {
        name: name.to_string(),
        index,
        summary: None,
        error: Some(error),
    };
    sweep
        .variants
        .iter()
        .enumerate()
        .filter_map(|(index, variant)| {
            match stored(&options.out_dir, &variant.name) {
            Ok(None) => None,
            Err(e) => Some(blank(&variant.name, index, e)),
            Ok(Some(o)) if o.fingerprint != fingerprint(sweep, variant, &options.settings) => {
                Some(blank(
                    &variant.name,
                    index,
                    "stale: the inputs changed since this result; run the sweep again with --resume"
                        .into(),
                ))
            }
            Ok(Some(o)) => Some(SummaryRow {
                name: o.name,
                index,
                summary: o.summary,
                error: o.error,
            }),
        }
        })
        .collect()
}

/// The summary table, column by column: the variant names and indices, the figures (NaN where
/// a row has none), the errors.
struct SummaryTable {
    names: Vec<Option<String>>,
    indices: Vec<f64>,
    columns: Vec<String>,
    values: Vec<Vec<f64>>,
    errors: Vec<Option<String>>,
}

impl SummaryTable {
    fn new(rows: Vec<SummaryRow>) -> Self {
        let mut columns: Vec<String> = rows
            .iter()
            .filter_map(|r| r.summary.as_ref())
            .flat_map(|s| s.keys().cloned())
            .collect();
        columns.sort();
        columns.dedup();
        let values = columns
            .iter()
            .map(|c| {
                rows.iter()
                    .map(|r| r.summary.as_ref().and_then(|s| s.get(c)).copied())
                    .map(|v| v.unwrap_or(f64::NAN))
                    .collect()
            })
            .collect();
        Self {
            names: rows.iter().map(|r| Some(r.name.clone())).collect(),
            indices: rows.iter().map(|r| r.index as f64).collect(),
            columns,
            values,
            errors: rows.into_iter().map(|r| r.error).collect(),
        }
    }

    /// `summary.csv`: variant, index, the figures (empty when missing), error.
    fn write_csv(&self, path: &Path) -> Result<(), String> {
        let mut csv = csv::Writer::from_path(path).map_err(|e| e.to_string())?;
        let mut header = vec!["variant", "index"];
        header.extend(self.columns.iter().map(String::as_str));
        header.push("error");
        csv.write_record(&header).map_err(|e| e.to_string())?;
        for (row, name) in self.names.iter().enumerate() {
            let mut record = vec![
                name.clone().unwrap_or_default(),
                self.indices[row].to_string(),
            ];
            record.extend(self.values.iter().map(|column| csv_field(column[row])));
            record.push(self.errors[row].clone().unwrap_or_default());
            csv.write_record(&record).map_err(|e| e.to_string())?;
        }
        csv.flush().map_err(|e| e.to_string())
    }

    /// `summary.parquet`, with the columns of the CSV.
    fn write_parquet(&self, path: &Path) -> Result<(), String> {
        let mut table = vec![
            Column {
                name: "variant",
                values: Values::Text(&self.names),
            },
            Column {
                name: "index",
                values: Values::Numbers(&self.indices),
            },
        ];
        table.extend(self.columns.iter().zip(&self.values).map(|(c, v)| Column {
            name: c,
            values: Values::Numbers(v),
        }));
        table.push(Column {
            name: "error",
            values: Values::Text(&self.errors),
        });
        write_parquet_table(path, &table).map_err(|e| e.to_string())
    }

    /// `<column>.svg` in `dir` for every figure: its value per variant.
    fn plot(&self, dir: &Path) -> Result<(), String> {
        for (column, values) in self.columns.iter().zip(&self.values) {
            let points: Vec<(f64, f64)> = self
                .indices
                .iter()
                .zip(values)
                .map(|(i, v)| (i + 1.0, *v))
                .filter(|p| p.1.is_finite())
                .collect();
            if points.is_empty() {
                continue;
            }
            line_plot(
                &dir.join(format!("{column}.svg")),
                &Labels {
                    title: &format!("{column} per variant"),
                    x: "variant (order in the sweep file)",
                    y: column,
                },
                &[Series {
                    label: "",
                    points: &points,
                }],
            )
            .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}

/// Collects every variant with a result in `options.out_dir` into `summary.csv` and
/// `summary.parquet` (variant, index, the summary columns, error) and one SVG per summary column
/// (value per variant, like seed 000 Figs 3.13–3.30). Returns the number of rows.
pub fn collect(sweep: &SweepFile, options: &RunOptions) -> Result<usize, SweepError> {
    let dir = &options.out_dir;
    let table = SummaryTable::new(summary_rows(sweep, options));
    table
        .write_csv(&dir.join("summary.csv"))
        .and_then(|_| table.write_parquet(&dir.join("summary.parquet")))
        .and_then(|_| table.plot(dir))
        .map_err(|e| SweepError::new(&sweep.path, "", e))?;
    Ok(table.names.len())
}
