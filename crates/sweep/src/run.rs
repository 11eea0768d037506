//! Running variants in parallel, with shards and resume, and collecting their summaries.

use crate::file::{SweepError, SweepFile, Variant};
use rayon::prelude::*;
use rolldyn_output::{Formats, TableWriter};
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
    /// Skip variants already finished in `out_dir`.
    pub resume: bool,
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
}

fn variant_file(out: &Path, name: &str) -> PathBuf {
    out.join("variants").join(format!("{name}.json"))
}

fn finished(out: &Path, name: &str) -> bool {
    std::fs::read_to_string(variant_file(out, name))
        .ok()
        .and_then(|t| serde_json::from_str::<VariantOutcome>(&t).ok())
        .is_some_and(|o| o.summary.is_some())
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
    let selected: Vec<(usize, &Variant)> = sweep
        .variants
        .iter()
        .enumerate()
        .filter(|(i, _)| options.shard.is_none_or(|s| i % s.count == s.index))
        .filter(|(_, v)| !(options.resume && finished(&options.out_dir, &v.name)))
        .collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| SweepError::new(&sweep.path, "", e.to_string()))?;
    let outcomes: Vec<Result<VariantOutcome, SweepError>> = pool.install(|| {
        selected
            .par_iter()
            .map(|&(index, variant)| {
                let start = std::time::Instant::now();
                let result = sweep
                    .model_of(variant)
                    .map_err(|e| e.to_string())
                    .and_then(|model| analysis(variant, model));
                let outcome = VariantOutcome {
                    name: variant.name.clone(),
                    index,
                    summary: result.as_ref().ok().cloned(),
                    error: result.err(),
                    wall_time_s: start.elapsed().as_secs_f64(),
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

/// Collects every finished variant in `out_dir` into `summary.csv` (with names and errors),
/// `summary.parquet` (numeric columns) and one SVG per summary column (value per variant, like
/// seed 000 Figs 3.13–3.30). Returns the number of variants collected.
pub fn collect(sweep: &SweepFile, out_dir: &Path) -> Result<usize, SweepError> {
    let fail = |e: String| SweepError::new(&sweep.path, "", e);
    let outcomes: Vec<VariantOutcome> = sweep
        .variants
        .iter()
        .filter_map(|v| std::fs::read_to_string(variant_file(out_dir, &v.name)).ok())
        .filter_map(|t| serde_json::from_str(&t).ok())
        .collect();
    let mut columns: Vec<String> = outcomes
        .iter()
        .filter_map(|o| o.summary.as_ref())
        .flat_map(|s| s.keys().cloned())
        .collect();
    columns.sort();
    columns.dedup();
    let mut csv =
        csv::Writer::from_path(out_dir.join("summary.csv")).map_err(|e| fail(e.to_string()))?;
    let mut header = vec!["variant".to_string(), "index".to_string()];
    header.extend(columns.iter().cloned());
    header.push("error".to_string());
    csv.write_record(&header).map_err(|e| fail(e.to_string()))?;
    let mut numeric = vec!["index".to_string()];
    numeric.extend(columns.iter().cloned());
    let mut parquet = TableWriter::create(
        out_dir,
        "summary",
        &numeric,
        Formats {
            csv: false,
            parquet: true,
        },
    )
    .map_err(|e| fail(e.to_string()))?;
    for o in &outcomes {
        let values: Vec<f64> = columns
            .iter()
            .map(|c| {
                o.summary
                    .as_ref()
                    .and_then(|s| s.get(c))
                    .copied()
                    .unwrap_or(f64::NAN)
            })
            .collect();
        let mut record = vec![o.name.clone(), o.index.to_string()];
        record.extend(values.iter().map(|v| format!("{v:e}")));
        record.push(o.error.clone().unwrap_or_default());
        csv.write_record(&record).map_err(|e| fail(e.to_string()))?;
        let mut row = vec![o.index as f64];
        row.extend(values);
        parquet.write_row(&row).map_err(|e| fail(e.to_string()))?;
    }
    csv.flush().map_err(|e| fail(e.to_string()))?;
    parquet.finish().map_err(|e| fail(e.to_string()))?;
    for column in &columns {
        let points: Vec<(f64, f64)> = outcomes
            .iter()
            .filter_map(|o| {
                o.summary
                    .as_ref()
                    .and_then(|s| s.get(column))
                    .map(|v| (o.index as f64 + 1.0, *v))
            })
            .filter(|p| p.1.is_finite())
            .collect();
        if points.is_empty() {
            continue;
        }
        line_plot(
            &out_dir.join(format!("{column}.svg")),
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
        .map_err(|e| fail(e.to_string()))?;
    }
    Ok(outcomes.len())
}
