//! Wear: Archard wear of the raceways, rollers, cage bars, roller ends and ribs over the
//! bearing's life, fed back into the geometry period by period (seed 000 §2.4, docs/theory.md
//! §8); on a double-row tapered bearing short dynamics windows per period (seed 000
//! §3.2.2–3.2.4, docs/theory.md §8.9).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::observer::Progress;
use crate::operating::{Operating, seconds_or_text};
use crate::output::out_dir;
use crate::run_record::{ModelOrigin, finish_out_folder};
use crate::table::{Table, Tables};
use rolldyn_output::run_state::{StateFile, fingerprint};
use rolldyn_report::RunKind;
use rolldyn_units::{Length, Quantity, Time};
use rolldyn_wear::study::{STATE_FILE, WearAnswer, run_wear};
use rolldyn_wear::tapered::{
    TaperedPeriod, TaperedWearSettings, run_tapered_life_from, write_tapered_report,
};
use rolldyn_wear::{
    ExposureWidth, OperabilityLimits, PeriodControl, PressureModel, StopReason, Surface, WearError,
    WearMethod, WearSettings,
};
use serde::de::Deserializer;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::ops::ControlFlow;
use std::path::PathBuf;
use std::str::FromStr;

const HOUR: f64 = 3600.0;
const UM: f64 = 1e6;

/// The recalculation period: fixed (`"1905h"`) or `"auto"` (starts at 1905 h, halves the
/// period when a wear rate changes by more than 50 % between periods or reverses its trend).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Period {
    /// A fixed period, s.
    Fixed(f64),
    Auto,
}

impl Default for Period {
    /// Seed 000 §2.4: 1905 h.
    fn default() -> Self {
        Period::Fixed(1905.0 * HOUR)
    }
}

impl FromStr for Period {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        if text.trim() == "auto" {
            return Ok(Period::Auto);
        }
        let p = Quantity::<Time>::parse(text)
            .map_err(|e| e.to_string())?
            .si();
        Period::Fixed(p).checked(text)
    }
}

impl Period {
    fn checked(self, text: &str) -> Result<Self, String> {
        match self {
            Period::Fixed(p) if !(p > 0.0 && p.is_finite()) => Err(format!(
                "'{text}': the period must be positive (e.g. 1905h) or auto"
            )),
            _ => Ok(self),
        }
    }

    /// The period control of the cylindrical life loop.
    pub fn control(self) -> PeriodControl {
        match self {
            Period::Fixed(p) => PeriodControl::Fixed(p),
            Period::Auto => PeriodControl::auto(1905.0 * HOUR),
        }
    }
}

/// Default of `--max-periods`, the ceiling of the recalculation periods a wear run plans:
/// every period runs 20 cage revolutions of dynamics (seconds to minutes each), so 10 000
/// periods are days of computing, while seed 000's life takes 13 periods of 1905 h.
pub const DEFAULT_MAX_PERIODS: u64 = 10_000;

/// The value of a wear run at fault: its life (`--life`, a sweep's `duration`) or its period
/// (`--period`, a sweep's `period`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LifeOrPeriod {
    Life,
    Period,
}

/// The one check of a wear run's life and period, for the `wear` command and wear sweeps: the
/// life `life_s` positive and finite, and at most `max_periods` recalculation periods (with
/// an automatic period, the count if it stayed at its smallest period). The error names the
/// value at fault and why (without the flag or key, which the caller names).
pub fn check_life_and_period(
    life_s: f64,
    period: &PeriodControl,
    max_periods: u64,
) -> Result<(), (LifeOrPeriod, String)> {
    if !(life_s > 0.0 && life_s.is_finite()) {
        return Err((
            LifeOrPeriod::Life,
            format!(
                "{:e} h: the life must be positive and finite",
                life_s / HOUR
            ),
        ));
    }
    let (shortest_s, how) = match period {
        PeriodControl::Fixed(p) => (*p, ""),
        PeriodControl::Schedule(periods) => (
            periods.iter().copied().fold(f64::INFINITY, f64::min),
            " at its shortest",
        ),
        PeriodControl::Auto { minimum_s, .. } => (*minimum_s, " at the smallest automatic period"),
    };
    if !(shortest_s > 0.0 && shortest_s.is_finite()) {
        return Err((
            LifeOrPeriod::Period,
            format!("{shortest_s:e} s: the period must be positive (e.g. 1905h) or auto"),
        ));
    }
    let count = (life_s / shortest_s).ceil();
    if count > max_periods as f64 {
        // in decades: the count of a tiny period overflows f64 (1e-308 h: 2.5e312 periods)
        let decades = life_s.log10() - shortest_s.log10();
        let count = if count < 1e15 {
            format!("{count:.0}")
        } else {
            let exponent = decades.floor();
            format!("{:.3}e{exponent}", 10f64.powf(decades - exponent))
        };
        return Err((
            LifeOrPeriod::Period,
            format!(
                "{count} periods ({:.4e} h of life / {:.4e} h{how}) are more than {max_periods} \
                 (--max-periods): choose a longer period or a shorter life, or raise --max-periods",
                life_s / HOUR,
                shortest_s / HOUR
            ),
        ));
    }
    Ok(())
}

impl<'de> Deserialize<'de> for Period {
    /// `"auto"`, a time with units (`"1905h"`) or a number of seconds.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        seconds_or_text(deserializer, |s| Period::Fixed(s).checked(&s.to_string()))
    }
}

/// The wear method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum MethodName {
    /// step by step over the recorded revolutions (seed 000 §2.4.1)
    Direct,
    /// equivalent force and mean sliding speed (seed 000 §2.4.2)
    Averaged,
}

impl MethodName {
    pub fn method(self) -> WearMethod {
        match self {
            MethodName::Direct => WearMethod::Direct,
            MethodName::Averaged => WearMethod::Averaged,
        }
    }
}

/// The width a surface point spends under the contact (seed 000 eq. 3.1, flag F-47).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum ExposureName {
    /// the full contact width 2b (physical)
    #[default]
    Full,
    /// the half-width b as seed 000 eq. (3.1) is printed
    Half,
}

impl ExposureName {
    pub fn width(self) -> ExposureWidth {
        match self {
            ExposureName::Full => ExposureWidth::Full,
            ExposureName::Half => ExposureWidth::Half,
        }
    }
}

/// The mean pressure on the raceway wear lines (docs/theory.md §8.5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum PressureName {
    /// the slices' Hertz line contacts
    #[default]
    Slices,
    /// the Boussinesq solver at the raceway's equivalent force (with method averaged)
    Boussinesq,
}

/// A wear life of the context's model.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WearRequest {
    /// Overrides of the model's operating point.
    pub operating: Operating,
    /// Life to reach (default 25000 h, a double-row tapered bearing 11429 h as seed 000
    /// §3.2.4).
    pub life: Option<Quantity<Time>>,
    pub period: Period,
    /// Default direct; a double-row tapered bearing averaged (seed 000 §3.2.3).
    pub method: Option<MethodName>,
    /// Cage revolutions recorded per period (after `settle` discarded ones).
    pub revolutions: u32,
    /// Cage revolutions run and discarded before recording.
    pub settle: u32,
    pub pressure: PressureName,
    pub exposure_width: ExposureName,
    /// Read the hardness as the seed did (its kgf/mm² numbers as MPa, flag F-45).
    pub seed_literal_hardness: bool,
    /// Stop when the operating radial clearance has grown by this much.
    pub max_clearance_increase: Option<Quantity<Length>>,
    /// Stop when any surface is worn this deep.
    pub max_depth: Option<Quantity<Length>>,
    /// Double-row tapered bearing: dynamics time run and discarded before each window
    /// (default 10 ms).
    pub window_settle: Option<Quantity<Time>>,
    /// Double-row tapered bearing: dynamics time recorded per period (default 20 ms).
    pub window: Option<Quantity<Time>>,
    /// Output folder: tables, plots and the worn model (default `out/<model name>-wear`).
    pub out: Option<PathBuf>,
    /// Write the HTML report of the output folder at the end of the run.
    pub report: bool,
    /// The most recalculation periods the life may take (default [`DEFAULT_MAX_PERIODS`]).
    pub max_periods: u64,
    /// Continue the run whose state the output folder holds (`wear.state`, stored after every
    /// period) with the same inputs: the periods done are kept, the tables cut back to them;
    /// a folder without a stored state starts from the beginning.
    pub resume: bool,
}

impl Default for WearRequest {
    fn default() -> Self {
        Self {
            operating: Operating::default(),
            life: None,
            period: Period::default(),
            method: None,
            revolutions: 10,
            settle: 10,
            pressure: PressureName::Slices,
            exposure_width: ExposureName::Full,
            seed_literal_hardness: false,
            max_clearance_increase: None,
            max_depth: None,
            window_settle: None,
            window: None,
            out: None,
            report: false,
            max_periods: DEFAULT_MAX_PERIODS,
            resume: false,
        }
    }
}

impl WearRequest {
    /// The settings of the cylindrical life run.
    pub fn settings(&self) -> Result<WearSettings, Failure> {
        let life_s = self.life.map_or(25_000.0 * HOUR, |l| l.si());
        let period = self.period.control();
        check_life_and_period(life_s, &period, self.max_periods).map_err(flag_failure)?;
        if self.revolutions == 0 {
            return Err(Failure::Input("--revolutions must be at least 1".into()));
        }
        let settings = WearSettings {
            method: self.method.unwrap_or(MethodName::Direct).method(),
            life_s,
            period,
            revolutions: self.revolutions,
            settle_revolutions: self.settle,
            exposure_width: self.exposure_width.width(),
            seed_literal_hardness: self.seed_literal_hardness,
            pressure_model: match self.pressure {
                PressureName::Slices => PressureModel::Slices,
                PressureName::Boussinesq => PressureModel::Boussinesq,
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

    /// The settings of the tapered life run; options of the cylindrical calculation that do
    /// not apply are refused.
    pub fn tapered_settings(&self) -> Result<TaperedWearSettings, Failure> {
        let defaults = TaperedWearSettings::default();
        let period_s = match self.period {
            Period::Fixed(p) => p,
            Period::Auto => {
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
        let life_s = self.life.map_or(defaults.life_s, |l| l.si());
        check_life_and_period(life_s, &PeriodControl::Fixed(period_s), self.max_periods)
            .map_err(flag_failure)?;
        Ok(TaperedWearSettings {
            method: self.method.unwrap_or(MethodName::Averaged).method(),
            life_s,
            period_s,
            settle_s: positive(
                self.window_settle.map(|t| t.si()),
                "--window-settle",
                defaults.settle_s,
            )?,
            window_s: positive(self.window.map(|t| t.si()), "--window", defaults.window_s)?,
            exposure_width: self.exposure_width.width(),
            seed_literal_hardness: self.seed_literal_hardness,
            ..defaults
        })
    }
}

/// A refused life or period as the input failure naming its flag.
fn flag_failure((at, reason): (LifeOrPeriod, String)) -> Failure {
    let flag = match at {
        LifeOrPeriod::Life => "--life",
        LifeOrPeriod::Period => "--period",
    };
    Failure::Input(format!("{flag}: {reason}"))
}

/// A wear failure as an analysis failure.
pub fn failure(e: WearError) -> Failure {
    match e {
        e @ (WearError::Input(_) | WearError::Key { .. }) => Failure::Input(e.to_string()),
        WearError::Numerical(m) => Failure::Run(m),
    }
}

/// The life of a cylindrical bearing (`rolldyn_wear::study::WearAnswer`) or of a double-row
/// tapered one.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum WearResult {
    Cylindrical(Box<WearAnswer>),
    Tapered(Box<TaperedWearResult>),
}

/// The deepest wear of each tapered surface, µm.
#[derive(Clone, Debug, Serialize)]
pub struct TaperedDepths {
    pub roller: f64,
    pub cone: f64,
    pub cup: f64,
    pub roller_end: f64,
    pub rib: f64,
}

/// The mean rib force of the unworn bearing's window and of the last one, N.
#[derive(Clone, Debug, Serialize)]
pub struct RibForces {
    pub unworn: Option<f64>,
    pub end: f64,
}

/// One period of a tapered life (text and table only).
#[derive(Clone, Debug)]
pub struct TaperedPeriodRow {
    pub time_h: f64,
    pub depth_um: TaperedDepths,
    pub rib_force_mean_n: f64,
    pub yaw_max_deg: f64,
}

/// The life of a double-row tapered bearing.
#[derive(Clone, Debug, Serialize)]
pub struct TaperedWearResult {
    pub model: String,
    pub method: String,
    pub life_h: f64,
    pub period_h: f64,
    /// The number of periods.
    pub periods: usize,
    pub window_settle_s: f64,
    pub window_s: f64,
    pub wear_lines: usize,
    pub max_depth_um: TaperedDepths,
    pub rib_force_mean_n: RibForces,
    pub yaw_max_deg: f64,
    pub pitch_max_deg: f64,
    pub wall_time_s: f64,
    pub out: String,
    pub plots: Vec<String>,
    #[serde(skip)]
    pub rows: Vec<TaperedPeriodRow>,
}

fn deepest(line: &[(f64, f64)]) -> f64 {
    line.iter().map(|x| x.1).fold(0.0, f64::max)
}

fn depths(w: &rolldyn_geometry::TaperedWear) -> TaperedDepths {
    TaperedDepths {
        roller: deepest(&w.roller) * UM,
        cone: deepest(&w.cone) * UM,
        cup: deepest(&w.cup) * UM,
        roller_end: w.large_end * UM,
        rib: w.large_rib * UM,
    }
}

impl Tables for WearResult {
    fn tables(&self) -> Vec<Table> {
        match self {
            WearResult::Cylindrical(a) => {
                let column = |f: &dyn Fn(&rolldyn_wear::study::PeriodSummary) -> f64| {
                    a.periods.iter().map(f).collect::<Vec<f64>>()
                };
                let mut table = Table::new("periods")
                    .real("time_h", column(&|p| p.time_h))
                    .real("period_h", column(&|p| p.period_h));
                for s in Surface::ALL {
                    table = table.real(
                        format!("max_depth_{}_m", s.name()),
                        column(&|p| p.max_depth_m.get(s)),
                    );
                }
                vec![table.real("clearance_increase_m", column(&|p| p.clearance_increase_m))]
            }
            WearResult::Tapered(t) => {
                let column = |f: &dyn Fn(&TaperedPeriodRow) -> f64| {
                    t.rows.iter().map(f).collect::<Vec<f64>>()
                };
                vec![
                    Table::new("periods")
                        .real("time_h", column(&|p| p.time_h))
                        .real("max_depth_roller_um", column(&|p| p.depth_um.roller))
                        .real("max_depth_cone_um", column(&|p| p.depth_um.cone))
                        .real("max_depth_cup_um", column(&|p| p.depth_um.cup))
                        .real(
                            "max_depth_roller_end_um",
                            column(&|p| p.depth_um.roller_end),
                        )
                        .real("max_depth_rib_um", column(&|p| p.depth_um.rib))
                        .real("rib_force_mean_n", column(&|p| p.rib_force_mean_n))
                        .real("yaw_max_deg", column(&|p| p.yaw_max_deg)),
                ]
            }
        }
    }
}

impl fmt::Display for WearResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WearResult::Cylindrical(a) => cylindrical_text(f, a),
            WearResult::Tapered(t) => tapered_text(f, t),
        }
    }
}

fn cylindrical_text(f: &mut fmt::Formatter<'_>, answer: &WearAnswer) -> fmt::Result {
    writeln!(
        f,
        "{}: {} method, {:.0} h of {:.0} h ({:?}); {} cage revolutions recorded per period after {}",
        answer.model,
        answer.method,
        answer.life_h,
        answer.requested_life_h,
        answer.stop,
        answer.revolutions,
        answer.settle_revolutions
    )?;
    writeln!(
        f,
        "{:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "time h", "roller", "inner", "outer", "bar", "end", "rib", "ΔG_r"
    )?;
    for p in &answer.periods {
        let d = |s| p.max_depth_m.get(s) * UM;
        writeln!(
            f,
            "{:>10.0} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3} {:>9.3}",
            p.time_h,
            d(Surface::Roller),
            d(Surface::InnerRaceway),
            d(Surface::OuterRaceway),
            d(Surface::CageBar),
            d(Surface::RollerEnd),
            d(Surface::Rib),
            p.clearance_increase_m * UM
        )?;
    }
    writeln!(
        f,
        "(depths in µm)  wall {:.1} s: dynamics {:.1} s, wear {:.1} s",
        answer.wall_time_s, answer.dynamics_wall_s, answer.wear_wall_s
    )?;
    if let Some(c) = &answer.convergence {
        writeln!(
            f,
            "convergence: with every period halved (the first {:.0} h) the depths are",
            c.halved_period_h
        )?;
        for (s, d) in c.relative_difference.iter() {
            writeln!(
                f,
                "  {:<14} {:.3} µm ({:+.1} % from the accepted periods)",
                s.name(),
                c.max_depth_halved_m.get(s) * UM,
                -d / (1.0 + d) * 100.0
            )?;
        }
    }
    write!(
        f,
        "outputs and the worn model (worn.toml) in {}",
        answer.output_folder.as_deref().unwrap_or_default()
    )
}

fn tapered_text(f: &mut fmt::Formatter<'_>, t: &TaperedWearResult) -> fmt::Result {
    writeln!(
        f,
        "{}: double-row tapered, {} method, {:.0} h in {} periods of {:.0} h; dynamics window \
         {:.1} ms after {:.1} ms",
        t.model,
        // as the method's Debug name: Averaged, Direct
        {
            let mut m = t.method.clone();
            if let Some(first) = m.get_mut(0..1) {
                first.make_ascii_uppercase();
            }
            m
        },
        t.life_h,
        t.periods,
        t.period_h,
        t.window_s * 1e3,
        t.window_settle_s * 1e3
    )?;
    writeln!(
        f,
        "{:>8} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10} {:>9}",
        "time h", "roller", "cone", "cup", "end", "rib", "rib F, N", "yaw max°"
    )?;
    for p in &t.rows {
        let d = &p.depth_um;
        writeln!(
            f,
            "{:>8.0} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>10.1} {:>9.4}",
            p.time_h,
            d.roller,
            d.cone,
            d.cup,
            d.roller_end,
            d.rib,
            p.rib_force_mean_n,
            p.yaw_max_deg
        )?;
    }
    writeln!(
        f,
        "(depths at the end of each period in µm; rib force and yaw of the window at its start) \
         at the end: rib force {:.1} N, yaw max {:.4}°, pitch max {:.4}°",
        t.rib_force_mean_n.end, t.yaw_max_deg, t.pitch_max_deg
    )?;
    write!(
        f,
        "wall {:.1} s; tables and plots in {}",
        t.wall_time_s, t.out
    )
}

/// The wear analysis.
pub struct Wear;

impl Analysis for Wear {
    const NAME: &'static str = "wear";
    type Request = WearRequest;
    type Result = WearResult;

    fn run(request: &WearRequest, context: &Context<'_>) -> Result<WearResult, Failure> {
        let model = context.model.load()?;
        let tapered = matches!(model.bearing, rolldyn_geometry::BearingModel::Tapered(_));
        let result = if tapered {
            WearResult::Tapered(Box::new(run_tapered(request, context, &model)?))
        } else {
            WearResult::Cylindrical(Box::new(run_cylindrical(request, context, &model)?))
        };
        let dir = output_folder(request, context, tapered);
        finish_out_folder(
            &dir,
            RunKind::Wear,
            ModelOrigin::Source(&context.model),
            &context.invocation,
            &result,
            request.report,
        )?;
        Ok(result)
    }
}

/// `out`, or `out/<model file stem>-wear` (`2002834`, or `tapered` for a tapered bearing, when
/// the model is not a file).
fn output_folder(request: &WearRequest, context: &Context<'_>, tapered: bool) -> PathBuf {
    let name = context
        .model
        .file()
        .and_then(|p| p.file_stem())
        .map_or(if tapered { "tapered" } else { "2002834" }.into(), |s| {
            s.to_string_lossy().into_owned()
        });
    request
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("out/{name}-wear")))
}

/// Progress through the life, and the caller's stop request.
fn period_done(
    context: &Context<'_>,
    time_h: f64,
    life_h: f64,
    message: String,
) -> ControlFlow<()> {
    context.observer.progress(&Progress {
        done: time_h,
        total: life_h,
        unit: "h",
        message: Some(message),
    });
    if context.observer.stop_requested() {
        ControlFlow::Break(())
    } else {
        ControlFlow::Continue(())
    }
}

fn interrupted(periods: usize, time_h: f64, dir: &std::path::Path) -> Failure {
    Failure::Run(format!(
        "wear interrupted after {periods} periods ({time_h:.0} h); the periods computed so far are in {}",
        dir.display()
    ))
}

fn run_cylindrical(
    request: &WearRequest,
    context: &Context<'_>,
    model: &rolldyn_model::Model,
) -> Result<WearAnswer, Failure> {
    let settings = request.settings()?;
    let dir = out_dir(&output_folder(request, context, false))?;
    let life_h = settings.life_s / HOUR;
    let answer = run_wear(
        model,
        &request.operating.overrides(),
        &settings,
        Some(&dir),
        request.resume,
        &mut |p| {
            let message = format!(
                "period {} ({:.0} h): roller {:.2} µm, inner raceway {:.2} µm, bar {:.2} µm",
                p.index,
                p.period_h,
                p.max_depth_m.get(Surface::Roller) * UM,
                p.max_depth_m.get(Surface::InnerRaceway) * UM,
                p.max_depth_m.get(Surface::CageBar) * UM,
            );
            period_done(context, p.time_h, life_h, message)
        },
    )
    .map_err(|e| match e {
        WearError::Numerical(m) => Failure::Run(format!(
            "{m} (the periods computed so far are in {})",
            dir.display()
        )),
        e => failure(e),
    })?;
    if answer.stop == StopReason::Interrupted {
        return Err(interrupted(answer.periods.len(), answer.life_h, &dir));
    }
    Ok(answer)
}

/// The one-line progress message of a tapered period.
fn period_message(p: &TaperedPeriod) -> String {
    let d = depths(&p.wear);
    format!(
        "period {} ({:.0} h): roller {:.3} µm, cone {:.3} µm, end {:.3} µm, rib {:.3} µm",
        p.index, p.period_h, d.roller, d.cone, d.roller_end, d.rib
    )
}

fn run_tapered(
    request: &WearRequest,
    context: &Context<'_>,
    model: &rolldyn_model::Model,
) -> Result<TaperedWearResult, Failure> {
    let settings = request.tapered_settings()?;
    let base = rolldyn_setup::prepare_tapered(model, &request.operating.overrides())?;
    let dir = out_dir(&output_folder(request, context, true))?;
    let wall = std::time::Instant::now();
    let life_h = settings.life_s / HOUR;
    let store = StateFile::new(
        dir.join(STATE_FILE),
        fingerprint(&format!("tapered wear\n{base:?}\n{settings:?}")),
    );
    let start = match request.resume {
        true => store.load().map_err(|e| Failure::Input(e.to_string()))?,
        false => None,
    };
    let mut stored = Ok(());
    let life = run_tapered_life_from(&base, &settings, start, &mut |state| {
        stored = store.store(state);
        let p = state.periods.last().expect("a period ended");
        match stored {
            // what is not stored cannot be resumed: stop here
            Err(_) => ControlFlow::Break(()),
            Ok(()) => period_done(context, p.time_h, life_h, period_message(p)),
        }
    })
    .map_err(failure)?;
    stored.map_err(|e| Failure::Run(e.to_string()))?;
    let plots = write_tapered_report(&dir, &life, settings.method)
        .map_err(|e| Failure::Run(e.to_string()))?;
    if life.life_h < life_h * (1.0 - 1e-9) && context.observer.stop_requested() {
        return Err(interrupted(life.periods.len(), life.life_h, &dir));
    }
    let end = &life.last_window.diagnostics;
    Ok(TaperedWearResult {
        model: model.bearing.name().to_string(),
        method: format!("{:?}", settings.method).to_lowercase(),
        life_h: life.life_h,
        period_h: settings.period_s / HOUR,
        periods: life.periods.len(),
        window_settle_s: settings.settle_s,
        window_s: settings.window_s,
        wear_lines: settings.wear_lines,
        max_depth_um: life.periods.last().map_or(
            TaperedDepths {
                roller: 0.0,
                cone: 0.0,
                cup: 0.0,
                roller_end: 0.0,
                rib: 0.0,
            },
            |p| depths(&p.wear),
        ),
        rib_force_mean_n: RibForces {
            unworn: life
                .periods
                .first()
                .map(|p| p.rates.diagnostics.rib_force_mean_n),
            end: end.rib_force_mean_n,
        },
        yaw_max_deg: end.yaw_max_rad.to_degrees(),
        pitch_max_deg: end.pitch_max_rad.to_degrees(),
        wall_time_s: wall.elapsed().as_secs_f64(),
        out: dir.display().to_string(),
        plots: plots.iter().map(|p| p.display().to_string()).collect(),
        rows: life
            .periods
            .iter()
            .map(|p| TaperedPeriodRow {
                time_h: p.time_h,
                depth_um: depths(&p.wear),
                rib_force_mean_n: p.rates.diagnostics.rib_force_mean_n,
                yaw_max_deg: p.rates.diagnostics.yaw_max_rad.to_degrees(),
            })
            .collect(),
    })
}
