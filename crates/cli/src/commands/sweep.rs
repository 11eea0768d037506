//! `rolldyn sweep SWEEP.toml`: a table of model variants run in parallel, one summary row per
//! variant (CSV + Parquet) and one plot per summary column (seed 000 Figs 3.13–3.30).

use super::jobs_args::JobsArgs;
use super::simulate::Duration;
use crate::failure::Failure;
use rolldyn::run_record::{ModelOrigin, finish_out_folder};
use rolldyn_dynamics::output::NullSink;
use rolldyn_dynamics::tapered::{TaperedRunSettings, run as run_tapered, summary_entries};
use rolldyn_quasistatic::QuasiStaticOptions;
use rolldyn_report::RunKind;
use rolldyn_setup::{Overrides, prepare};
use rolldyn_sweep::{
    Analysis, RunOptions, Shard, SweepFile, Variant, VariantOutcome, collect, run as run_sweep,
};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

#[derive(clap::Args)]
pub struct Args {
    /// Sweep file (TOML): base model, analysis and [[variant]] tables (see rolldyn-sweep docs).
    pub sweep: PathBuf,
    #[command(flatten)]
    pub jobs: JobsArgs,
    /// Output folder (default `out/<sweep file name>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Run every n-th variant only (`k/n`), e.g. one cluster array job of n.
    #[arg(long)]
    pub shard: Option<Shard>,
    /// Skip variants already finished in the output folder from the same inputs (model,
    /// overrides, duration, solver settings, program version); rerun the others.
    #[arg(long)]
    pub resume: bool,
    /// Run the variants but leave `summary.*` alone: for shards running at the same time (a
    /// Slurm array, Dask tasks), collected afterwards with `--collect-only`.
    #[arg(long, conflicts_with = "collect_only")]
    pub no_collect: bool,
    /// Run nothing: collect the variants stored in the output folder into `summary.*` (a stored
    /// result whose inputs changed is marked stale).
    #[arg(long)]
    pub collect_only: bool,
    /// No per-variant progress lines.
    #[arg(long)]
    pub quiet: bool,
    /// Write the HTML report of the output folder (`report.html`) at the end of the run.
    #[arg(long)]
    pub report: bool,
}

/// Numeric and boolean (1/0) fields of a JSON object as a summary row.
fn numbers(value: &serde_json::Value) -> BTreeMap<String, f64> {
    value
        .as_object()
        .map(|o| {
            o.iter()
                .filter_map(|(k, v)| {
                    v.as_f64()
                        .or_else(|| v.as_bool().map(|b| f64::from(u8::from(b))))
                        .map(|x| (k.clone(), x))
                })
                .collect()
        })
        .unwrap_or_default()
}

fn simulate(
    duration: Duration,
    discard: Option<u32>,
    model: rolldyn_model::Model,
) -> Result<BTreeMap<String, f64>, String> {
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
        .columns()
        .into_iter()
        .filter(|(_, v)| v.is_finite())
        .map(|(k, v)| (k.to_string(), v))
        .collect())
}

/// [`simulate`] of a double-row tapered bearing: the run summary of its own dynamics, taken
/// after the `discard` cage revolutions (default: the last 60 % of the run).
fn simulate_tapered(
    duration: Duration,
    discard: Option<u32>,
    model: &rolldyn_model::Model,
) -> Result<BTreeMap<String, f64>, String> {
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
    Ok(summary_entries(&outcome.summary)
        .into_iter()
        .filter(|(_, v)| v.is_finite())
        .collect())
}

fn skid(model: rolldyn_model::Model) -> Result<BTreeMap<String, f64>, String> {
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
    Ok(numbers(
        &serde_json::to_value(&result).map_err(|e| e.to_string())?,
    ))
}

/// The life run of one variant (`analysis = "wear"`): the depths at the end as its row; its
/// tables, plots and worn model go to `out` (`<sweep out>/variants/<name>-wear`).
fn wear(
    settings: &rolldyn_wear::WearSettings,
    model: rolldyn_model::Model,
    out: &std::path::Path,
) -> Result<BTreeMap<String, f64>, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let answer = rolldyn_wear::study::run_wear(
        &model,
        &Overrides::default(),
        settings,
        Some(out),
        &mut |_| {},
    )
    .map_err(|e| e.to_string())?;
    let mut row: BTreeMap<String, f64> = answer
        .max_depth_m
        .iter()
        .map(|(s, d)| (format!("max_depth_{}_m", s.name()), d))
        .collect();
    row.insert("life_h".into(), answer.life_h);
    row.insert("clearance_increase_m".into(), answer.clearance_increase_m);
    row.insert("periods".into(), answer.periods.len() as f64);
    row.insert(
        "roller_depth_from_bar_m".into(),
        answer.roller_depth_from_bar_m,
    );
    for (kind, c) in &answer.initial_contacts {
        for (name, v) in [
            ("equivalent_force_n", c.equivalent_force_n),
            ("mean_sliding_speed_m_s", c.mean_sliding_speed_m_s),
            ("contact_fraction", c.contact_fraction),
            ("mean_lambda", c.mean_lambda),
        ] {
            row.insert(format!("{kind}_{name}"), v);
        }
    }
    row.retain(|_, v| v.is_finite());
    Ok(row)
}

/// The life of the cage of one variant (`analysis = "fatigue"`): life, damage, stresses and the
/// revolution's largest contact forces (seed 000 Table 3.2) as its row; the report files go to
/// `out` (`<sweep out>/variants/<name>-fatigue`).
fn fatigue(
    settings: &rolldyn_fatigue::study::FatigueSettings,
    model: rolldyn_model::Model,
    out: &std::path::Path,
    cache: &std::path::Path,
) -> Result<BTreeMap<String, f64>, String> {
    use rolldyn_fatigue::study::{StressModelKind, evaluate, record_loads};
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let (export, maxima, _) =
        record_loads(&model, &Overrides::default(), settings).map_err(|e| e.to_string())?;
    let cage = &export.header.cage;
    let z = export.header.bar_station_z_m;
    let unit = match settings.stress_model {
        StressModelKind::Frame => rolldyn_fatigue::frame::unit_stresses(cage, z, &settings.frame)
            .map_err(|e| e.to_string())?,
        StressModelKind::Calculix => {
            std::fs::create_dir_all(cache)
                .map_err(|e| format!("cannot create {}: {e}", cache.display()))?;
            rolldyn_fatigue::calculix::unit_stresses(
                cage,
                z,
                &rolldyn_fatigue::calculix::CalculixSettings::default(),
                Some(cache),
            )
            .map_err(|e| e.to_string())?
        }
    };
    let result = evaluate(&unit, &export, Some(maxima), settings)?;
    rolldyn_fatigue::report::write_report(out, &export, &result, settings)?;
    let a = &result.answer;
    let mut row = BTreeMap::new();
    for (name, v) in [
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
    ] {
        row.insert(name.to_string(), v);
    }
    row.retain(|_, v| v.is_finite());
    Ok(row)
}

/// The fatigue settings of a `fatigue` sweep: its `method` names the stress model.
fn fatigue_settings(sweep: &SweepFile) -> Result<rolldyn_fatigue::study::FatigueSettings, String> {
    use rolldyn_fatigue::study::{FatigueSettings, StressModelKind};
    let stress_model = match (sweep.analysis, sweep.method.as_deref()) {
        (Analysis::Fatigue, Some("calculix")) => StressModelKind::Calculix,
        (Analysis::Fatigue, None | Some("frame")) | (_, _) => StressModelKind::Frame,
    };
    if sweep.analysis == Analysis::Fatigue
        && let Some(other) = sweep
            .method
            .as_deref()
            .filter(|m| !["frame", "calculix"].contains(m))
    {
        return Err(format!("method — '{other}' is not frame or calculix"));
    }
    Ok(FatigueSettings {
        stress_model,
        ..FatigueSettings::default()
    })
}

/// The wear settings of a `wear` sweep: its `duration` is the life, its `period` the period.
fn wear_settings(sweep: &SweepFile) -> Result<rolldyn_wear::WearSettings, String> {
    use super::wear::PeriodArg;
    use rolldyn_wear::PeriodControl;
    let defaults = rolldyn_wear::WearSettings::default();
    if sweep.analysis != Analysis::Wear {
        return Ok(defaults);
    }
    let life_s = match sweep.duration.as_deref() {
        Some(text) => rolldyn_units::Quantity::<rolldyn_units::Time>::parse(text)
            .map_err(|e| format!("duration (the life) — {e}"))?
            .si(),
        None => defaults.life_s,
    };
    let period = match sweep
        .period
        .as_deref()
        .map(str::parse::<PeriodArg>)
        .transpose()?
    {
        None => defaults.period,
        Some(PeriodArg::Fixed(p)) => PeriodControl::Fixed(p),
        Some(PeriodArg::Auto) => PeriodControl::auto(defaults.period.initial_s()),
    };
    let method = match sweep.method.as_deref() {
        None | Some("direct") => rolldyn_wear::WearMethod::Direct,
        Some("averaged") => rolldyn_wear::WearMethod::Averaged,
        Some(other) => return Err(format!("method — '{other}' is not direct or averaged")),
    };
    Ok(rolldyn_wear::WearSettings {
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
    analysis: Analysis,
    duration: Duration,
    wear: &rolldyn_wear::WearSettings,
    fatigue: &rolldyn_fatigue::study::FatigueSettings,
) -> String {
    match analysis {
        Analysis::Wear => format!(
            "{wear:?}; {:?}",
            rolldyn_dynamics::DynamicsSettings::default()
        ),
        Analysis::Simulate => format!(
            "duration {duration:?}; {:?}",
            rolldyn_dynamics::DynamicsSettings::default()
        ),
        Analysis::Skid => format!("finite cage land; {:?}", QuasiStaticOptions::default()),
        Analysis::Fatigue => format!(
            "{:?}; {:?}",
            fatigue,
            rolldyn_dynamics::DynamicsSettings::default()
        ),
    }
}

pub fn run(args: Args) -> Result<(), Failure> {
    let sweep = SweepFile::load(&args.sweep).map_err(|e| Failure::Input(e.to_string()))?;
    let bad = |e: String| Failure::Input(format!("{}: {e}", args.sweep.display()));
    let wear_settings = wear_settings(&sweep).map_err(bad)?;
    let fatigue_settings = fatigue_settings(&sweep).map_err(bad)?;
    let duration: Duration = match sweep.analysis {
        Analysis::Wear | Analysis::Fatigue => "1rev".parse(),
        _ => sweep.duration.as_deref().unwrap_or("5rev").parse(),
    }
    .map_err(|e: String| bad(format!("duration — {e}")))?;
    let discard = sweep
        .discard
        .as_deref()
        .map(discarded_revolutions)
        .transpose()
        .map_err(|e| Failure::Input(format!("{}: discard — {e}", args.sweep.display())))?;
    if let (Some(n), Duration::CageRevolutions(total)) = (discard, duration)
        && f64::from(n) >= total
    {
        return Err(Failure::Input(format!(
            "{}: discard — {n} revolutions leave nothing of the {total} simulated",
            args.sweep.display()
        )));
    }
    let stem = args
        .sweep
        .file_stem()
        .map_or("sweep".into(), |s| s.to_string_lossy().to_string());
    let out_dir = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out").join(stem));
    let analysis = sweep.analysis;
    let wear_settings_ref = &wear_settings;
    let fatigue_settings_ref = &fatigue_settings;
    let cache_dir = out_dir.join("calculix-cache");
    let variants_dir = out_dir.join("variants");
    let analyse = move |v: &Variant, model: rolldyn_model::Model| match analysis {
        Analysis::Simulate => simulate(duration, discard, model),
        Analysis::Skid => skid(model),
        Analysis::Wear => wear(
            wear_settings_ref,
            model,
            &variants_dir.join(format!("{}-wear", v.name)),
        ),
        Analysis::Fatigue => fatigue(
            fatigue_settings_ref,
            model,
            &variants_dir.join(format!("{}-fatigue", v.name)),
            &cache_dir,
        ),
    };
    let done = AtomicUsize::new(0);
    let total = sweep.variants.len();
    let quiet = args.quiet;
    let progress = |o: &VariantOutcome| {
        let n = done.fetch_add(1, Ordering::SeqCst) + 1;
        if !quiet {
            match &o.error {
                None => eprintln!("[{n}] variant {} done in {:.1} s", o.name, o.wall_time_s),
                Some(e) => eprintln!("[{n}] variant {} failed: {e}", o.name),
            }
        }
    };
    let options = RunOptions {
        out_dir: out_dir.clone(),
        jobs: args.jobs.count(),
        shard: args.shard,
        resume: args.resume,
        settings: settings(analysis, duration, &wear_settings, &fatigue_settings),
    };
    let outcomes = if args.collect_only {
        Vec::new()
    } else {
        run_sweep(&sweep, &options, &analyse, &progress).map_err(|e| Failure::Run(e.to_string()))?
    };
    let collected = if args.no_collect {
        0
    } else {
        collect(&sweep, &options).map_err(|e| Failure::Run(e.to_string()))?
    };
    let failed = outcomes.iter().filter(|o| o.error.is_some()).count();
    let changed: Vec<&str> = outcomes
        .iter()
        .filter(|o| o.inputs_changed)
        .map(|o| o.name.as_str())
        .collect();
    let changed = if changed.is_empty() {
        String::new()
    } else {
        format!(
            "; rerun because their inputs changed: {}",
            changed.join(", ")
        )
    };
    let collected = match args.no_collect {
        true => "not collected (--no-collect)".to_string(),
        false => format!(
            "{collected} collected in {}",
            out_dir.join("summary.csv").display()
        ),
    };
    println!(
        "{}: ran {} of {total} variants ({failed} failed{changed}); {collected}",
        args.sweep.display(),
        outcomes.len(),
    );
    let answer = serde_json::json!({
        "sweep": args.sweep.display().to_string(),
        "analysis": format!("{analysis:?}").to_lowercase(),
        "variants": total,
        "ran": outcomes.len(),
        "failed": failed,
        "collected": collected,
        "out": out_dir.display().to_string(),
    });
    let sweep_file = ModelOrigin::File(&args.sweep);
    finish_out_folder(
        &out_dir,
        RunKind::Sweep,
        sweep_file,
        &crate::output::invocation(),
        &answer,
        args.report,
    )?;
    if failed > 0 && failed == outcomes.len() {
        return Err(Failure::Run(
            "every variant failed; see the variants/*.json files".into(),
        ));
    }
    Ok(())
}
