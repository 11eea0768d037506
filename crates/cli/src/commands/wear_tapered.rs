//! `rolldyn wear` on a double-row tapered bearing (seed 000 §3.2.2–3.2.4; library:
//! `rolldyn_wear::tapered`): short dynamics windows per period, direct and averaged rates, the
//! fixed-period life loop, tables and plots.

use super::wear::{Args, MethodArg, PeriodArg, output_folder, progress_bar};
use crate::failure::Failure;
use crate::output::print_json;
use rolldyn::run_record::{ModelOrigin, finish_out_folder};
use rolldyn_report::RunKind;
use rolldyn_wear::WearError;
use rolldyn_wear::tapered::write_tapered_report;
use rolldyn_wear::tapered::{TaperedPeriod, TaperedWearSettings, run_tapered_life};

const HOUR: f64 = 3600.0;
const UM: f64 = 1e6;

/// The tapered settings the flags ask for; flags of the cylindrical calculation that do not
/// apply are refused.
fn settings(args: &Args) -> Result<TaperedWearSettings, Failure> {
    let defaults = TaperedWearSettings::default();
    let period_s = match args.period {
        PeriodArg::Fixed(p) => p,
        PeriodArg::Auto => {
            return Err(Failure::Input(
                "--period auto is not available for a double-row tapered bearing: give a fixed period (seed 000 §3.2.3: 1905h)".into(),
            ));
        }
    };
    let positive = |q: Option<f64>, flag: &str, default: f64| match q {
        Some(v) if !(v > 0.0 && v.is_finite()) => {
            Err(Failure::Input(format!("{flag} must be positive")))
        }
        Some(v) => Ok(v),
        None => Ok(default),
    };
    Ok(TaperedWearSettings {
        method: args.method.unwrap_or(MethodArg::Averaged).method(),
        life_s: positive(args.life.map(|l| l.si()), "--life", defaults.life_s)?,
        period_s,
        settle_s: positive(
            args.window_settle.map(|t| t.si()),
            "--window-settle",
            defaults.settle_s,
        )?,
        window_s: positive(args.window.map(|t| t.si()), "--window", defaults.window_s)?,
        exposure_width: args.exposure_width.width(),
        seed_literal_hardness: args.seed_literal_hardness,
        ..defaults
    })
}

fn wear_failure(e: WearError) -> Failure {
    match e {
        e @ (WearError::Input(_) | WearError::Key { .. }) => Failure::Input(e.to_string()),
        WearError::Numerical(m) => Failure::Run(m),
    }
}

/// The one-line progress message of a period.
fn period_message(p: &TaperedPeriod) -> String {
    let max = |l: &[(f64, f64)]| l.iter().map(|x| x.1).fold(0.0, f64::max) * UM;
    format!(
        "period {} ({:.0} h): roller {:.3} µm, cone {:.3} µm, end {:.3} µm, rib {:.3} µm",
        p.index,
        p.period_h,
        max(&p.wear.roller),
        max(&p.wear.cone),
        p.wear.large_end * UM,
        p.wear.large_rib * UM
    )
}

/// Runs the tapered life of `model` as `wear` asks.
pub fn run(args: &Args, model: &rolldyn_model::Model) -> Result<(), Failure> {
    let settings = settings(args)?;
    let base = rolldyn_setup::prepare_tapered(model, &args.operating.overrides())?;
    let dir = output_folder(args, "tapered")?;
    let bar = progress_bar(args.quiet || args.json, settings.life_s / HOUR);
    let wall = std::time::Instant::now();
    let life = run_tapered_life(&base, &settings, &mut |p| {
        bar.set_position(p.time_h.round() as u64);
        bar.set_message(period_message(p));
    })
    .map_err(wear_failure)?;
    bar.finish_and_clear();
    let plots = write_tapered_report(&dir, &life, settings.method)
        .map_err(|e| Failure::Run(e.to_string()))?;
    let wall_s = wall.elapsed().as_secs_f64();
    let last = life.periods.last();
    let max = |l: &[(f64, f64)]| l.iter().map(|x| x.1).fold(0.0, f64::max);
    let final_depth =
        |pick: &dyn Fn(&rolldyn_geometry::TaperedWear) -> f64| last.map_or(0.0, |p| pick(&p.wear));
    let first = life.periods.first().map(|p| &p.rates.diagnostics);
    let end = &life.last_window.diagnostics;
    let d = |x: f64| serde_json::json!(x);
    let answer = serde_json::json!({
        "model": model.bearing.name(),
        "method": format!("{:?}", settings.method).to_lowercase(),
        "life_h": life.life_h,
        "period_h": settings.period_s / HOUR,
        "periods": life.periods.len(),
        "window_settle_s": settings.settle_s,
        "window_s": settings.window_s,
        "wear_lines": settings.wear_lines,
        "max_depth_um": {
            "roller": d(final_depth(&|w| max(&w.roller)) * UM),
            "cone": d(final_depth(&|w| max(&w.cone)) * UM),
            "cup": d(final_depth(&|w| max(&w.cup)) * UM),
            "roller_end": d(final_depth(&|w| w.large_end) * UM),
            "rib": d(final_depth(&|w| w.large_rib) * UM),
        },
        "rib_force_mean_n": {
            "unworn": first.map(|f| f.rib_force_mean_n),
            "end": end.rib_force_mean_n,
        },
        "yaw_max_deg": end.yaw_max_rad.to_degrees(),
        "pitch_max_deg": end.pitch_max_rad.to_degrees(),
        "wall_time_s": wall_s,
        "out": dir.display().to_string(),
        "plots": plots.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
    });
    let model_source = rolldyn::ModelSource::file_or_embedded(args.model.as_deref());
    let model_file = ModelOrigin::Source(&model_source);
    finish_out_folder(
        &dir,
        RunKind::Wear,
        model_file,
        &crate::output::invocation(),
        &answer,
        args.report,
    )?;
    if args.json {
        return print_json(&answer);
    }
    println!(
        "{}: double-row tapered, {:?} method, {:.0} h in {} periods of {:.0} h; dynamics window \
         {:.1} ms after {:.1} ms",
        model.bearing.name(),
        settings.method,
        life.life_h,
        life.periods.len(),
        settings.period_s / HOUR,
        settings.window_s * 1e3,
        settings.settle_s * 1e3
    );
    println!(
        "{:>8} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10} {:>9}",
        "time h", "roller", "cone", "cup", "end", "rib", "rib F, N", "yaw max°"
    );
    for p in &life.periods {
        println!(
            "{:>8.0} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>10.1} {:>9.4}",
            p.time_h,
            max(&p.wear.roller) * UM,
            max(&p.wear.cone) * UM,
            max(&p.wear.cup) * UM,
            p.wear.large_end * UM,
            p.wear.large_rib * UM,
            p.rates.diagnostics.rib_force_mean_n,
            p.rates.diagnostics.yaw_max_rad.to_degrees()
        );
    }
    println!(
        "(depths at the end of each period in µm; rib force and yaw of the window at its start) \
         at the end: rib force {:.1} N, yaw max {:.4}°, pitch max {:.4}°",
        end.rib_force_mean_n,
        end.yaw_max_rad.to_degrees(),
        end.pitch_max_rad.to_degrees()
    );
    println!("wall {wall_s:.1} s; tables and plots in {}", dir.display());
    Ok(())
}
