//! `rolldyn wear MODEL.toml`: Archard wear of the raceways, rollers, cage bars, roller ends and
//! ribs over the bearing's life, fed back into the geometry period by period (seed 000 §2.4,
//! docs/theory.md §8; library: `rolldyn_wear::study`).

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::{load_model, print_json};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rolldyn::output::out_dir;
use rolldyn::run_record::{ModelOrigin, finish_out_folder};
use rolldyn_report::RunKind;
use rolldyn_units::{Length, Quantity, Time};
use rolldyn_wear::study::run_wear;
use rolldyn_wear::{
    ExposureWidth, OperabilityLimits, PeriodControl, PressureModel, Surface, WearError, WearMethod,
    WearSettings,
};
use std::path::PathBuf;
use std::str::FromStr;

/// A fixed recalculation period (`1905h`) or `auto`.
#[derive(Clone, Copy, Debug)]
pub enum PeriodArg {
    Fixed(f64),
    Auto,
}

impl FromStr for PeriodArg {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        if text.trim() == "auto" {
            return Ok(PeriodArg::Auto);
        }
        let p = Quantity::<Time>::parse(text)
            .map_err(|e| e.to_string())?
            .si();
        if p > 0.0 && p.is_finite() {
            Ok(PeriodArg::Fixed(p))
        } else {
            Err(format!(
                "'{text}': the period must be positive (e.g. 1905h) or auto"
            ))
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// step by step over the recorded revolutions (seed 000 §2.4.1)
    Direct,
    /// equivalent force and mean sliding speed (seed 000 §2.4.2)
    Averaged,
}

impl MethodArg {
    pub fn method(self) -> WearMethod {
        match self {
            MethodArg::Direct => WearMethod::Direct,
            MethodArg::Averaged => WearMethod::Averaged,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ExposureArg {
    /// the full contact width 2b (physical)
    Full,
    /// the half-width b as seed 000 eq. (3.1) is printed
    Half,
}

impl ExposureArg {
    pub fn width(self) -> ExposureWidth {
        match self {
            ExposureArg::Full => ExposureWidth::Full,
            ExposureArg::Half => ExposureWidth::Half,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PressureArg {
    /// the slices' Hertz line contacts
    Slices,
    /// the Boussinesq solver at the raceway's equivalent force (with --method averaged)
    Boussinesq,
}

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with [lubricant], [operating] and the materials' meyer_hardness; the
    /// embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Life to reach (e.g. 25000h; default 25000h, a double-row tapered bearing 11429h as seed
    /// 000 §3.2.4).
    #[arg(long)]
    pub life: Option<Quantity<Time>>,
    /// Recalculation period: a time (1905h) or `auto` (starts at 1905 h, halves the period when
    /// a wear rate changes by more than 50 % between periods or reverses its trend).
    #[arg(long, default_value = "1905h")]
    pub period: PeriodArg,
    /// Wear method (default direct; a double-row tapered bearing averaged, as seed 000 §3.2.3
    /// continues after comparing both).
    #[arg(long, value_enum)]
    pub method: Option<MethodArg>,
    /// Cage revolutions recorded per period (after --settle discarded ones).
    #[arg(long, default_value_t = 10)]
    pub revolutions: u32,
    /// Cage revolutions run and discarded before recording.
    #[arg(long, default_value_t = 10)]
    pub settle: u32,
    /// Mean pressure on the raceway wear lines (docs/theory.md §8.5).
    #[arg(long, value_enum, default_value = "slices")]
    pub pressure: PressureArg,
    /// Width a surface point spends under the contact (seed 000 eq. 3.1, flag F-47).
    #[arg(long, value_enum, default_value = "full")]
    pub exposure_width: ExposureArg,
    /// Read the hardness as the seed did (its kgf/mm² numbers as MPa, flag F-45).
    #[arg(long)]
    pub seed_literal_hardness: bool,
    /// Stop when the operating radial clearance has grown by this much (e.g. 30um).
    #[arg(long)]
    pub max_clearance_increase: Option<Quantity<Length>>,
    /// Stop when any surface is worn this deep (e.g. 0.1mm).
    #[arg(long)]
    pub max_depth: Option<Quantity<Length>>,
    /// Double-row tapered bearing: dynamics time run and discarded from the seated start before
    /// each window (default 10ms).
    #[arg(long)]
    pub window_settle: Option<Quantity<Time>>,
    /// Double-row tapered bearing: dynamics time recorded per period (default 20ms).
    #[arg(long)]
    pub window: Option<Quantity<Time>>,
    /// Output folder: tables, plots and the worn model (default `out/<model name>-wear`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the HTML report of the output folder (`report.html`) at the end of the run.
    #[arg(long)]
    pub report: bool,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

impl Args {
    fn settings(&self) -> Result<WearSettings, Failure> {
        let life_s = self.life.map_or(25_000.0 * 3600.0, |l| l.si());
        if !(life_s > 0.0 && life_s.is_finite()) {
            return Err(Failure::Input("--life must be positive".into()));
        }
        if self.revolutions == 0 {
            return Err(Failure::Input("--revolutions must be at least 1".into()));
        }
        let hour = 3600.0;
        let settings = WearSettings {
            method: self.method.unwrap_or(MethodArg::Direct).method(),
            life_s,
            period: match self.period {
                PeriodArg::Fixed(p) => PeriodControl::Fixed(p),
                PeriodArg::Auto => PeriodControl::auto(1905.0 * hour),
            },
            revolutions: self.revolutions,
            settle_revolutions: self.settle,
            exposure_width: self.exposure_width.width(),
            seed_literal_hardness: self.seed_literal_hardness,
            pressure_model: match self.pressure {
                PressureArg::Slices => PressureModel::Slices,
                PressureArg::Boussinesq => PressureModel::Boussinesq,
            },
            limits: OperabilityLimits {
                clearance_increase_m: self.max_clearance_increase.map(|q| q.si()),
                depth_m: self.max_depth.map(|q| q.si()),
            },
            ..WearSettings::default()
        };
        settings.validate().map_err(Failure::Input)?;
        Ok(settings)
    }
}

pub(super) fn progress_bar(quiet: bool, life_h: f64) -> ProgressBar {
    let bar =
        ProgressBar::with_draw_target(Some(life_h.ceil() as u64), ProgressDrawTarget::stderr());
    if quiet {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} h  {msg}  [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar
}

/// `--out`, or `out/<model file stem>-wear` (`default_name` for the embedded model), created.
pub(super) fn output_folder(args: &Args, default_name: &str) -> Result<PathBuf, Failure> {
    let name = args
        .model
        .as_deref()
        .and_then(|p| p.file_stem())
        .map_or(default_name.into(), |s| s.to_string_lossy().into_owned());
    out_dir(
        &args
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from(format!("out/{name}-wear"))),
    )
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?;
    if let rolldyn_geometry::BearingModel::Tapered(_) = model.bearing {
        return super::wear_tapered::run(&args, &model);
    }
    let settings = args.settings()?;
    let overrides = args.operating.overrides();
    let dir = output_folder(&args, "2002834")?;
    let bar = progress_bar(args.quiet || args.json, settings.life_s / 3600.0);
    let answer = run_wear(&model, &overrides, &settings, Some(&dir), &mut |p| {
        bar.set_position(p.time_h.round() as u64);
        bar.set_message(format!(
            "period {} ({:.0} h): roller {:.2} µm, inner raceway {:.2} µm, bar {:.2} µm",
            p.index,
            p.period_h,
            p.max_depth_m.get(Surface::Roller) * 1e6,
            p.max_depth_m.get(Surface::InnerRaceway) * 1e6,
            p.max_depth_m.get(Surface::CageBar) * 1e6,
        ));
    })
    .map_err(|e| match e {
        e @ (WearError::Input(_) | WearError::Key { .. }) => Failure::Input(e.to_string()),
        WearError::Numerical(m) => Failure::Run(format!(
            "{m} (the periods computed so far are in {})",
            dir.display()
        )),
    })?;
    bar.finish_and_clear();
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
        "{}: {} method, {:.0} h of {:.0} h ({:?}); {} cage revolutions recorded per period after {}",
        answer.model,
        answer.method,
        answer.life_h,
        answer.requested_life_h,
        answer.stop,
        answer.revolutions,
        answer.settle_revolutions
    );
    println!(
        "{:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "time h", "roller", "inner", "outer", "bar", "end", "rib", "ΔG_r"
    );
    for p in &answer.periods {
        let d = |s| p.max_depth_m.get(s) * 1e6;
        println!(
            "{:>10.0} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3}",
            p.time_h,
            d(Surface::Roller),
            d(Surface::InnerRaceway),
            d(Surface::OuterRaceway),
            d(Surface::CageBar),
            d(Surface::RollerEnd),
            d(Surface::Rib),
            p.clearance_increase_m * 1e6
        );
    }
    println!(
        "(depths in µm)  wall {:.1} s: dynamics {:.1} s, wear {:.1} s",
        answer.wall_time_s, answer.dynamics_wall_s, answer.wear_wall_s
    );
    if let Some(c) = &answer.convergence {
        println!(
            "convergence: with every period halved (the first {:.0} h) the depths are",
            c.halved_period_h
        );
        for (s, d) in c.relative_difference.iter() {
            println!(
                "  {:<14} {:.3} µm ({:+.1} % from the accepted periods)",
                s.name(),
                c.max_depth_halved_m.get(s) * 1e6,
                -d / (1.0 + d) * 100.0
            );
        }
    }
    println!(
        "outputs and the worn model (worn.toml) in {}",
        dir.display()
    );
    Ok(())
}
