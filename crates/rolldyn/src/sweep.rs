//! Sweeps: a table of model variants (docs/sweep-format.md) run in parallel, one summary row
//! per variant — its name, the varied model keys, its figures — in `summary.csv` and
//! `summary.parquet`, and one plot per figure (seed 000 Figs 3.13–3.30).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::observer::Progress;
use crate::operating::{Duration, jobs_or_cores};
use crate::run_record::{ModelOrigin, finish_out_folder};
use crate::table::{Table, Tables};
use crate::wear::{DEFAULT_MAX_PERIODS, LifeOrPeriod, check_life_and_period};
use rolldyn_dynamics::SummaryValue;
use rolldyn_dynamics::output::NullSink;
use rolldyn_dynamics::tapered::{TaperedRunSettings, run as run_tapered, summary_entries};
use rolldyn_fatigue::study::{FatigueSettings, StressModelKind, evaluate, record_loads};
use rolldyn_quasistatic::QuasiStaticOptions;
use rolldyn_report::RunKind;
use rolldyn_setup::{Overrides, prepare};
use rolldyn_sweep::{
    Analysis as VariantKind, Figure, RunOptions, Shard, Summary, SummaryValues, SweepError,
    SweepFile, Variant, VariantOutcome, collect, run as run_sweep, varied_columns,
};
use rolldyn_wear::WearSettings;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

/// A sweep file run (or collected).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepRequest {
    /// The sweep file (TOML, docs/sweep-format.md).
    pub sweep: PathBuf,
    /// Parallel jobs, at least 1 (default: the number of cores).
    #[serde(default)]
    pub jobs: Option<usize>,
    /// Output folder (default `out/<sweep file name>`).
    #[serde(default)]
    pub out: Option<PathBuf>,
    /// Run every n-th variant only (`"k/n"`).
    #[serde(default)]
    pub shard: Option<Shard>,
    /// Skip variants already finished in the output folder from the same inputs.
    #[serde(default)]
    pub resume: bool,
    /// Run the variants but leave `summary.*` alone (shards running at the same time).
    #[serde(default)]
    pub no_collect: bool,
    /// Run nothing: collect the stored variants into `summary.*`.
    #[serde(default)]
    pub collect_only: bool,
    /// Write the HTML report of the output folder at the end of the run.
    #[serde(default)]
    pub report: bool,
}

impl SweepRequest {
    /// A run of the sweep file `sweep` with every option at its default.
    pub fn new(sweep: impl Into<PathBuf>) -> Self {
        Self {
            sweep: sweep.into(),
            jobs: None,
            out: None,
            shard: None,
            resume: false,
            no_collect: false,
            collect_only: false,
            report: false,
        }
    }
}

/// What a sweep did (its `run.json` summary).
#[derive(Clone, Debug, Serialize)]
pub struct SweepResult {
    pub sweep: String,
    pub analysis: String,
    /// The variants of the sweep file.
    pub variants: usize,
    /// The variants run now.
    pub ran: usize,
    pub failed: usize,
    pub collected: String,
    pub out: String,
    /// The summary columns of the varied model keys (`operating.radial_load_n`), in the order
    /// of the sweep file.
    pub varied: Vec<String>,
    /// The variants rerun because their inputs changed.
    #[serde(skip)]
    pub changed: Vec<String>,
    /// The summary table (absent with `no_collect`).
    #[serde(skip)]
    pub summary: Option<Summary>,
}

impl Tables for SweepResult {
    /// The summary as a table `summary`: a column with a blank is real (NaN) when numeric.
    fn tables(&self) -> Vec<Table> {
        let Some(summary) = &self.summary else {
            return Vec::new();
        };
        let mut table = Table::new("summary");
        for c in &summary.columns {
            table = match &c.values {
                SummaryValues::Text(v) => table.text(
                    &c.name,
                    v.iter().map(|s| s.clone().unwrap_or_default()).collect(),
                ),
                SummaryValues::Integer(v) if v.iter().all(Option::is_some) => {
                    table.integer(&c.name, v.iter().flatten().copied().collect())
                }
                SummaryValues::Integer(v) => table.real(
                    &c.name,
                    v.iter().map(|n| n.map_or(f64::NAN, |n| n as f64)).collect(),
                ),
                SummaryValues::Real(v) => table.real(&c.name, v.clone()),
            };
        }
        vec![table]
    }
}

impl fmt::Display for SweepResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let changed = if self.changed.is_empty() {
            String::new()
        } else {
            format!(
                "; rerun because their inputs changed: {}",
                self.changed.join(", ")
            )
        };
        write!(
            f,
            "{}: ran {} of {} variants ({} failed{changed}); {}",
            self.sweep, self.ran, self.variants, self.failed, self.collected
        )
    }
}

/// Numeric and boolean (1/0) fields of a JSON object as summary figures (whole JSON numbers
/// and flags as integers).
fn figures(value: &serde_json::Value) -> BTreeMap<String, Figure> {
    value
        .as_object()
        .map(|o| {
            o.iter()
                .filter_map(|(k, v)| {
                    let figure = match v {
                        serde_json::Value::Bool(b) => Figure::Integer(i64::from(*b)),
                        v if v.is_i64() => Figure::Integer(v.as_i64()?),
                        v => Figure::Real(v.as_f64()?),
                    };
                    Some((k.clone(), figure))
                })
                .collect()
        })
        .unwrap_or_default()
}

/// Real figures, without those that are not finite (an empty field of the table).
fn finite(pairs: impl IntoIterator<Item = (String, f64)>) -> BTreeMap<String, Figure> {
    pairs
        .into_iter()
        .filter(|(_, v)| v.is_finite())
        .map(|(k, v)| (k, Figure::Real(v)))
        .collect()
}

/// The run summary of a variant's dynamics (`analysis = "simulate"`).
fn simulate(
    duration: Duration,
    discard: Option<u32>,
    model: rolldyn_model::Model,
) -> Result<BTreeMap<String, Figure>, String> {
    if let rolldyn_geometry::BearingModel::Tapered(_) = &model.bearing {
        return simulate_tapered(duration, discard, &model);
    }
    let (mut sim, revolution) =
        prepare(&model, &Overrides::default(), 0.0, None).map_err(|e| e.to_string())?;
    if let Some(n) = discard {
        sim.set_discard_revolutions(n);
    }
    let summary = sim
        .run_until(duration.end_time(revolution)?, &mut NullSink, &mut |_| {})
        .map_err(|e| format!("the simulation stopped: {e}"))?;
    // a figure that is not finite is absent from the row (an empty field of the table)
    Ok(summary
        .fields()
        .into_iter()
        .filter_map(|(k, v)| {
            let figure = match v {
                SummaryValue::Real(x) if x.is_finite() => Figure::Real(x),
                SummaryValue::Real(_) => return None,
                SummaryValue::Count(n) => Figure::Integer(i64::try_from(n).ok()?),
                SummaryValue::Flag(b) => Figure::Integer(i64::from(b)),
            };
            Some((k.to_string(), figure))
        })
        .collect())
}

/// [`simulate`] of a double-row tapered bearing: the run summary of its own dynamics, taken
/// after the `discard` cage revolutions (default: the last 60 % of the run).
fn simulate_tapered(
    duration: Duration,
    discard: Option<u32>,
    model: &rolldyn_model::Model,
) -> Result<BTreeMap<String, Figure>, String> {
    let tm =
        rolldyn_setup::prepare_tapered(model, &Overrides::default()).map_err(|e| e.to_string())?;
    let revolution = std::f64::consts::TAU / tm.epicyclic_cage_speed.abs();
    let settings = TaperedRunSettings {
        duration_s: duration.end_time(Some(revolution))?,
        steady_from_s: discard.map(|n| f64::from(n) * revolution),
        ..TaperedRunSettings::default()
    };
    let outcome =
        run_tapered(&tm, &settings, |_| {}).map_err(|e| format!("the simulation stopped: {e}"))?;
    Ok(finite(summary_entries(&outcome.summary)))
}

/// The quasi-static skidding of a variant (`analysis = "skid"`).
fn skid(model: rolldyn_model::Model) -> Result<BTreeMap<String, Figure>, String> {
    let bearing = model.bearing.require_cylindrical("skid")?;
    use rolldyn_setup::quasi_static::{
        QuasiStaticOverrides, matching_land_model, quasi_static_conditions,
    };
    let c = quasi_static_conditions(&model, &QuasiStaticOverrides::default())
        .map_err(|e| e.to_string())?;
    let land = matching_land_model(bearing, &model.dynamics);
    let result = rolldyn_quasistatic::solve_with_land_model(
        bearing,
        &c,
        &QuasiStaticOptions::default(),
        land.as_ref(),
    )
    .map_err(|e| e.to_string())?;
    Ok(figures(
        &serde_json::to_value(&result).map_err(|e| e.to_string())?,
    ))
}

/// The life run of one variant (`analysis = "wear"`): the depths at the end as its row; its
/// tables, plots and worn model go to `out` (`<sweep out>/variants/<name>-wear`).
fn wear(
    settings: &WearSettings,
    model: rolldyn_model::Model,
    out: &Path,
) -> Result<BTreeMap<String, Figure>, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let answer = rolldyn_wear::study::run_wear(
        &model,
        &Overrides::default(),
        settings,
        Some(out),
        false,
        &mut |_| ControlFlow::Continue(()),
    )
    .map_err(|e| e.to_string())?;
    let mut row: Vec<(String, f64)> = answer
        .max_depth_m
        .iter()
        .map(|(s, d)| (format!("max_depth_{}_m", s.name()), d))
        .collect();
    row.push(("life_h".into(), answer.life_h));
    row.push(("clearance_increase_m".into(), answer.clearance_increase_m));
    row.push((
        "roller_depth_from_bar_m".into(),
        answer.roller_depth_from_bar_m,
    ));
    for (kind, c) in &answer.initial_contacts {
        for (name, v) in [
            ("equivalent_force_n", c.equivalent_force_n),
            ("mean_sliding_speed_m_s", c.mean_sliding_speed_m_s),
            ("contact_fraction", c.contact_fraction),
            ("mean_lambda", c.mean_lambda),
        ] {
            row.push((format!("{kind}_{name}"), v));
        }
    }
    let mut row = finite(row);
    row.insert(
        "periods".into(),
        Figure::Integer(answer.periods.len() as i64),
    );
    Ok(row)
}

/// The life of the cage of one variant (`analysis = "fatigue"`): life, damage, stresses and the
/// revolution's largest contact forces (seed 000 Table 3.2) as its row; the report files go to
/// `out` (`<sweep out>/variants/<name>-fatigue`).
fn fatigue(
    settings: &FatigueSettings,
    model: rolldyn_model::Model,
    out: &Path,
    cache: &Path,
) -> Result<BTreeMap<String, Figure>, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let (export, maxima, _) = record_loads(
        &model,
        &Overrides::default(),
        settings,
        None,
        &mut |_, _| std::ops::ControlFlow::Continue(()),
    )
    .map_err(|e| e.to_string())?;
    let unit =
        crate::fatigue::unit_stresses(&export, settings, cache).map_err(|e| e.to_string())?;
    let result = evaluate(&unit, &export, Some(maxima), settings)?;
    rolldyn_fatigue::report::write_report(out, &export, &result)?;
    let a = &result.answer;
    Ok(finite(
        [
            ("life_revolutions", a.life_revolutions),
            ("life_hours", a.life_hours),
            ("lg_life_revolutions", a.life_revolutions.log10()),
            (
                "extrapolated_life_revolutions",
                a.extrapolated_life_revolutions,
            ),
            (
                "lg_extrapolated_life_revolutions",
                a.extrapolated_life_revolutions.log10(),
            ),
            ("damage_per_revolution", a.damage_per_revolution),
            ("max_stress_pa", a.max_stress_pa),
            ("endurance_margin", a.endurance_margin),
            ("cage_speed_rpm", a.cage_speed_rpm),
            ("max_cage_land_force_n", maxima.max_cage_land_force_n),
            ("max_roller_cage_force_n", maxima.max_roller_cage_force_n),
            (
                "max_roller_raceway_force_n",
                maxima.max_roller_raceway_force_n,
            ),
        ]
        .map(|(k, v)| (k.to_string(), v)),
    ))
}

/// The fatigue settings of a `fatigue` sweep: its `method` names the stress model.
fn fatigue_settings(sweep: &SweepFile) -> Result<FatigueSettings, SweepError> {
    let stress_model = match (sweep.analysis, sweep.method.as_deref()) {
        (VariantKind::Fatigue, Some("calculix")) => StressModelKind::Calculix,
        (VariantKind::Fatigue, None | Some("frame")) | (_, _) => StressModelKind::Frame,
    };
    if sweep.analysis == VariantKind::Fatigue
        && let Some(other) = sweep
            .method
            .as_deref()
            .filter(|m| !["frame", "calculix"].contains(m))
    {
        return Err(sweep.error("method", format!("'{other}' is not frame or calculix")));
    }
    Ok(FatigueSettings {
        stress_model,
        ..FatigueSettings::default()
    })
}

/// The wear settings of a `wear` sweep: its `duration` is the life, its `period` the period,
/// checked as the `wear` command checks `--life` and `--period` (at most
/// [`DEFAULT_MAX_PERIODS`] periods).
fn wear_settings(sweep: &SweepFile) -> Result<WearSettings, SweepError> {
    let defaults = WearSettings::default();
    if sweep.analysis != VariantKind::Wear {
        return Ok(defaults);
    }
    let life_s = match sweep.duration.as_deref() {
        Some(text) => rolldyn_units::Quantity::<rolldyn_units::Time>::parse(text)
            .map_err(|e| sweep.error("duration", format!("(the life) {e}")))?
            .si(),
        None => defaults.life_s,
    };
    let period = match sweep
        .period
        .as_deref()
        .map(str::parse::<crate::wear::Period>)
        .transpose()
        .map_err(|e| sweep.error("period", e))?
    {
        None => defaults.period,
        Some(p) => p.control(),
    };
    check_life_and_period(life_s, &period, DEFAULT_MAX_PERIODS).map_err(
        |(at, reason)| match at {
            LifeOrPeriod::Life => sweep.error("duration", format!("(the life) {reason}")),
            LifeOrPeriod::Period => sweep.error("period", reason),
        },
    )?;
    let method = match sweep.method.as_deref() {
        None | Some("direct") => rolldyn_wear::WearMethod::Direct,
        Some("averaged") => rolldyn_wear::WearMethod::Averaged,
        Some(other) => {
            return Err(sweep.error("method", format!("'{other}' is not direct or averaged")));
        }
    };
    Ok(WearSettings {
        life_s,
        period,
        method,
        ..defaults
    })
}

/// The revolution count of a sweep file's `discard` (`"5rev"`).
fn discarded_revolutions(text: &str) -> Result<u32, String> {
    text.trim()
        .strip_suffix("rev")
        .and_then(|n| n.trim().parse().ok())
        .ok_or_else(|| {
            format!("'{text}' is not a whole number of cage revolutions such as \"5rev\"")
        })
}

/// The settings of the analysis beyond the sweep file (solver defaults and tolerances) for the
/// variants' fingerprints.
fn settings(
    analysis: VariantKind,
    duration: Duration,
    wear: &WearSettings,
    fatigue: &FatigueSettings,
) -> String {
    match analysis {
        VariantKind::Wear => format!(
            "{wear:?}; {:?}",
            rolldyn_dynamics::DynamicsSettings::default()
        ),
        VariantKind::Simulate => format!(
            "duration {duration:?}; {:?}",
            rolldyn_dynamics::DynamicsSettings::default()
        ),
        VariantKind::Skid => format!("finite cage land; {:?}", QuasiStaticOptions::default()),
        VariantKind::Fatigue => format!(
            "{:?}; {:?}",
            fatigue,
            rolldyn_dynamics::DynamicsSettings::default()
        ),
    }
}

/// The sweep analysis.
pub struct Sweep;

impl Analysis for Sweep {
    const NAME: &'static str = "sweep";
    type Request = SweepRequest;
    type Result = SweepResult;

    fn run(request: &SweepRequest, context: &Context<'_>) -> Result<SweepResult, Failure> {
        if request.jobs == Some(0) {
            return Err(Failure::Input("--jobs must be at least 1".into()));
        }
        if request.no_collect && request.collect_only {
            return Err(Failure::Input(
                "--no-collect and --collect-only exclude each other".into(),
            ));
        }
        let file = &request.sweep;
        let input = |e: SweepError| Failure::Input(e.to_string());
        let sweep = SweepFile::load(file).map_err(input)?;
        let bad = |key: &str, reason: String| input(sweep.error(key, reason));
        let wear_settings = wear_settings(&sweep).map_err(input)?;
        let fatigue_settings = fatigue_settings(&sweep).map_err(input)?;
        let duration: Duration = match sweep.analysis {
            VariantKind::Wear | VariantKind::Fatigue => "1rev".parse(),
            _ => sweep.duration.as_deref().unwrap_or("5rev").parse(),
        }
        .map_err(|e: String| bad("duration", e))?;
        let discard = sweep
            .discard
            .as_deref()
            .map(discarded_revolutions)
            .transpose()
            .map_err(|e| bad("discard", e))?;
        if let (Some(n), Duration::CageRevolutions(total)) = (discard, duration)
            && f64::from(n) >= total
        {
            return Err(bad(
                "discard",
                format!("{n} revolutions leave nothing of the {total} simulated"),
            ));
        }
        let stem = file
            .file_stem()
            .map_or("sweep".into(), |s| s.to_string_lossy().to_string());
        let out_dir = request
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out").join(stem));
        if request.collect_only && !out_dir.is_dir() {
            let flag = if request.out.is_some() {
                "--out"
            } else {
                "--collect-only"
            };
            return Err(Failure::Input(format!(
                "{flag}: {} is not a folder: nothing to collect (run the sweep into it first)",
                out_dir.display()
            )));
        }
        // shards that do not collect write their own variants only and share the folder
        let _lock = if request.shard.is_some() && request.no_collect {
            crate::output::shared_out_dir(&out_dir)?
        } else {
            crate::output::out_dir(&out_dir)?
        };
        let analysis = sweep.analysis;
        let cache_dir = out_dir.join("calculix-cache");
        let variants_dir = out_dir.join("variants");
        let analyse = |v: &Variant, model: rolldyn_model::Model| match analysis {
            VariantKind::Simulate => simulate(duration, discard, model),
            VariantKind::Skid => skid(model),
            VariantKind::Wear => wear(
                &wear_settings,
                model,
                &variants_dir.join(format!("{}-wear", v.name)),
            ),
            VariantKind::Fatigue => fatigue(
                &fatigue_settings,
                model,
                &variants_dir.join(format!("{}-fatigue", v.name)),
                &cache_dir,
            ),
        };
        let progress = |o: &VariantOutcome, done: usize, total: usize| {
            if let Some(damaged) = &o.replaced_damaged {
                context.observer.warning(&format!(
                    "variant {}: the stored result was not reused ({damaged}); it was run again",
                    o.name
                ));
            }
            if let Some(e) = &o.error {
                context
                    .observer
                    .warning(&format!("variant {} failed: {e}", o.name));
            }
            context.observer.progress(&Progress {
                done: done as f64,
                total: total as f64,
                unit: "variants",
                message: Some(o.name.clone()),
            });
        };
        let options = RunOptions {
            out_dir: out_dir.clone(),
            jobs: jobs_or_cores(request.jobs),
            shard: request.shard,
            resume: request.resume,
            settings: settings(analysis, duration, &wear_settings, &fatigue_settings),
        };
        let outcomes = if request.collect_only {
            Vec::new()
        } else {
            run_sweep(&sweep, &options, &analyse, &progress, &|| {
                context.observer.stop_requested()
            })
            .map_err(|e| Failure::Run(e.to_string()))?
        };
        let summary = if request.no_collect {
            None
        } else {
            Some(collect(&sweep, &options).map_err(|e| Failure::Run(e.to_string()))?)
        };
        if !request.collect_only && context.observer.stop_requested() {
            return Err(Failure::Run(format!(
                "{}: sweep interrupted after {} variants; the finished ones are stored in {}: run it again with --resume to continue",
                file.display(),
                outcomes.len(),
                variants_dir.display()
            )));
        }
        let failed = outcomes.iter().filter(|o| o.error.is_some()).count();
        let result = SweepResult {
            sweep: file.display().to_string(),
            analysis: format!("{analysis:?}").to_lowercase(),
            variants: sweep.variants.len(),
            ran: outcomes.len(),
            failed,
            collected: match &summary {
                None => "not collected (--no-collect)".to_string(),
                Some(s) => format!(
                    "{} collected in {}",
                    s.rows,
                    out_dir.join("summary.csv").display()
                ),
            },
            out: out_dir.display().to_string(),
            varied: varied_columns(&sweep).into_iter().map(|c| c.name).collect(),
            changed: outcomes
                .iter()
                .filter(|o| o.inputs_changed)
                .map(|o| o.name.clone())
                .collect(),
            summary,
        };
        finish_out_folder(
            &out_dir,
            RunKind::Sweep,
            ModelOrigin::File(file),
            &context.invocation,
            &result,
            request.report,
        )?;
        if failed > 0 && failed == outcomes.len() {
            return Err(Failure::Run(
                "every variant failed; see the variants/*.json files".into(),
            ));
        }
        Ok(result)
    }
}
