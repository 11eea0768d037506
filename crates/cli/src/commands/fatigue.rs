//! `rolldyn fatigue MODEL.toml`: the life of the cage from one steady revolution of the
//! dynamics (seed 000 §2.5, docs/theory.md §10); `rolldyn fatigue rainflow HISTORY.csv`:
//! rainflow cycle counting of any stress history (ASTM E1049). Library: `rolldyn_fatigue`.

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::{load_model, print_json};
use indicatif::{ProgressBar, ProgressDrawTarget};
use rolldyn::output::out_dir;
use rolldyn::run_record::{ModelOrigin, finish_out_folder};
use rolldyn_fatigue::damage::MeanStressSettings;
use rolldyn_fatigue::inclusion::{InclusionSettings, Interface};
use rolldyn_fatigue::mean_stress::MeanStressCorrection;
use rolldyn_fatigue::sn::{BelowKnee, SnCurve};
use rolldyn_fatigue::study::{
    FatigueError, FatigueSettings, REQUIRED_STRESS_SAFETY_FACTOR, RevolutionMaxima,
    StressModelKind, evaluate, record_loads,
};
use rolldyn_fatigue::{
    CageLoadExport, Cycle, HistoryKind, UnitStresses, rainflow, read_history_csv,
};
use rolldyn_report::RunKind;
use rolldyn_units::{Length, Quantity};
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum StressArg {
    /// the embedded beam frame with fillet stress-concentration factors (fast)
    Frame,
    /// a gmsh + CalculiX solid model (unit cases cached per cage geometry)
    Calculix,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum BelowKneeArg {
    /// the knee is an endurance limit: cycles below it do no damage
    NoDamage,
    /// the last segment's slope continues below the knee
    Extrapolate,
    /// Haibach: slope 2k − 1 below the knee
    Haibach,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MeanStressArg {
    /// the amplitude alone (the seed states no correction)
    None,
    Goodman,
    Gerber,
    /// Smith–Watson–Topper
    Swt,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum InterfaceArg {
    /// the interface opens where it would carry tension (the seed's contact interface)
    Debonded,
    /// perfectly bonded everywhere
    Bonded,
}

#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    #[command(subcommand)]
    pub command: Option<FatigueCommand>,
    /// Model file (TOML) with a [cage] and [lubricant]; the embedded 2002834 model when omitted.
    pub model: Option<PathBuf>,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Cage stress model.
    #[arg(long, value_enum, default_value = "frame")]
    pub stress: StressArg,
    /// Cage revolutions simulated and discarded before the recorded one.
    #[arg(long, default_value_t = 8)]
    pub revolutions: u32,
    /// Evaluate the Al₂O₃ inclusion (2 × 3.5 × 5 µm; interface debonded, or `--inclusion=bonded`) at
    /// the critical location too.
    #[arg(long, value_enum, num_args = 0..=1, require_equals = true, default_missing_value = "debonded")]
    pub inclusion: Option<InterfaceArg>,
    /// Mean-stress correction of the counted cycles.
    #[arg(long, value_enum, default_value = "none")]
    pub mean_stress: MeanStressArg,
    /// Radius of the window-corner fillet (e.g. 0.5mm), overriding the model's
    /// `cage.pocket.fillet_radius`.
    #[arg(long)]
    pub fillet_radius: Option<Quantity<Length>>,
    /// Stress-concentration factors of the frame model's fillets, `TENSION,BENDING` (default: from
    /// the fillet radius by Roark's shoulder-fillet charts).
    #[arg(long, value_parser = parse_factor_pair)]
    pub stress_concentration: Option<[f64; 2]>,
    /// The base S–N curve (fully reversed) as CSV rows `N, sigma_a_MPa` (default: AISI 4340
    /// through the seed's 480 MPa at 10⁶ cycles, docs/theory.md §10.5).
    #[arg(long)]
    pub sn_curve: Option<PathBuf>,
    /// Factor on the S–N curve for the silver plating (seed: 1.5).
    #[arg(long, default_value_t = 1.5)]
    pub coating_factor: f64,
    /// Safety factor on stress (applied to the S–N curve besides the coating factor).
    #[arg(long, default_value_t = 1.0)]
    pub safety_factor: f64,
    /// Cycles below the knee of the S–N curve (10⁷ cycles).
    #[arg(long, value_enum, default_value = "no-damage")]
    pub below_knee: BelowKneeArg,
    /// Read the cage loads from an export (`rolldyn simulate --cage-loads`) instead of running
    /// the dynamics.
    #[arg(long, conflicts_with = "model")]
    pub loads: Option<PathBuf>,
    /// Output folder: the load export, stress history, damage map and plots.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the HTML report of the `--out` folder (`report.html`) at the end of the run.
    #[arg(long, requires = "out")]
    pub report: bool,
    /// Folder of the cached CalculiX unit cases (default `out/calculix-cache`).
    #[arg(long)]
    pub cache: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(clap::Subcommand)]
pub enum FatigueCommand {
    /// Rainflow cycle counting (ASTM E1049 four-point) of a stress history in a CSV file.
    Rainflow(RainflowArgs),
}

#[derive(clap::Args)]
pub struct RainflowArgs {
    /// CSV file: one value per row (first column, or `--column` of a file with a header row).
    pub history: PathBuf,
    /// Column to count (by its header name).
    #[arg(long)]
    pub column: Option<String>,
    /// The file is one period of a repeating history (every cycle closes); otherwise the
    /// residue counts as half cycles.
    #[arg(long)]
    pub periodic: bool,
    /// Print the cycles as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(Serialize)]
struct RainflowAnswer<'a> {
    history: String,
    periodic: bool,
    values: usize,
    cycles: &'a [Cycle],
}

pub fn run(args: Args) -> Result<(), Failure> {
    match args.command {
        Some(FatigueCommand::Rainflow(a)) => run_rainflow(a),
        None => run_life(args),
    }
}

impl Args {
    fn settings(&self) -> Result<FatigueSettings, Failure> {
        let defaults = FatigueSettings::default();
        let sn_settings = rolldyn_fatigue::sn::SnSettings {
            coating_factor: self.coating_factor,
            stress_safety_factor: self.safety_factor,
            below_knee: match self.below_knee {
                BelowKneeArg::NoDamage => BelowKnee::NoDamage,
                BelowKneeArg::Extrapolate => BelowKnee::Extrapolate,
                BelowKneeArg::Haibach => BelowKnee::Haibach,
            },
        };
        let base = match &self.sn_curve {
            Some(path) => {
                let file = path.display().to_string();
                let text = rolldyn_model::read_input_file(path)
                    .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
                SnCurve::from_csv_text(&text).map_err(|e| Failure::Input(format!("{file}: {e}")))?
            }
            None => defaults.sn.clone(),
        };
        let sn = base
            .with_settings(sn_settings)
            .map_err(|e| Failure::Input(format!("--coating-factor/--safety-factor: {e}")))?;
        Ok(FatigueSettings {
            stress_model: match self.stress {
                StressArg::Frame => StressModelKind::Frame,
                StressArg::Calculix => StressModelKind::Calculix,
            },
            settle_revolutions: self.revolutions,
            frame: rolldyn_fatigue::frame::FrameSettings {
                stress_concentration: self.stress_concentration,
                ..defaults.frame.clone()
            },
            fillet_radius_m: self.fillet_radius.map(|f| f.si()),
            sn,
            inclusion: self.inclusion.map(|interface| InclusionSettings {
                interface: match interface {
                    InterfaceArg::Debonded => Interface::Debonded,
                    InterfaceArg::Bonded => Interface::Bonded,
                },
                ..InclusionSettings::default()
            }),
            mean_stress: MeanStressSettings {
                correction: match self.mean_stress {
                    MeanStressArg::None => MeanStressCorrection::None,
                    MeanStressArg::Goodman => MeanStressCorrection::Goodman,
                    MeanStressArg::Gerber => MeanStressCorrection::Gerber,
                    MeanStressArg::Swt => MeanStressCorrection::SmithWatsonTopper,
                },
                ..defaults.mean_stress
            },
            ..defaults
        })
    }
}

/// `2.5,2.0` → `[2.5, 2.0]`, both at least 1.
fn parse_factor_pair(text: &str) -> Result<[f64; 2], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("'{text}': {e}"))?;
    match values.as_slice() {
        &[t, b] if t >= 1.0 && b >= 1.0 && t.is_finite() && b.is_finite() => Ok([t, b]),
        _ => Err(format!(
            "'{text}': two factors ≥ 1, tension and bending, e.g. 2.5,2.0"
        )),
    }
}

fn failure(e: FatigueError) -> Failure {
    match e {
        FatigueError::Input(m) => Failure::Input(m),
        FatigueError::Numerical(m) => Failure::Run(m),
    }
}

fn run_life(args: Args) -> Result<(), Failure> {
    let wall = Instant::now();
    let settings = args.settings()?;
    let (mut export, maxima) = match &args.loads {
        Some(_) if args.operating.any() => {
            return Err(Failure::Input(
                "--loads: the operating point is that of the export; drop the operating overrides"
                    .into(),
            ));
        }
        Some(path) => {
            let export = CageLoadExport::read(path).map_err(Failure::Input)?;
            let maxima = RevolutionMaxima::of_export(&export);
            (export, Some(maxima))
        }
        None => {
            let model = load_model(args.model.as_deref())?;
            let (export, maxima, _) =
                record_loads(&model, &args.operating.overrides(), &settings).map_err(failure)?;
            (export, Some(maxima))
        }
    };
    // an export read back keeps its model's fillet unless the command line overrides it
    export.header.cage = export
        .header
        .cage
        .with_fillet_radius(settings.fillet_radius_m);
    let dynamics_s = wall.elapsed().as_secs_f64();
    let unit = unit_stresses(&args, &export, &settings)?;
    let result = evaluate(&unit, &export, maxima, &settings).map_err(Failure::Run)?;
    let files = match &args.out {
        Some(dir) => {
            let dir = out_dir(dir)?;
            rolldyn_fatigue::report::write_report(&dir, &export, &result, &settings)
                .map_err(Failure::Run)?
        }
        None => Vec::new(),
    };
    let answer = Answer {
        model: export.header.model.clone(),
        fatigue: &result.answer,
        dynamics_wall_s: dynamics_s,
        wall_time_s: wall.elapsed().as_secs_f64(),
        files: files.iter().map(|f| f.display().to_string()).collect(),
    };
    if let Some(dir) = &args.out {
        let model_source = rolldyn::ModelSource::file_or_embedded(args.model.as_deref());
        let model_file = match args.loads {
            Some(_) => ModelOrigin::None,
            None => ModelOrigin::Source(&model_source),
        };
        finish_out_folder(
            dir,
            RunKind::Fatigue,
            model_file,
            &crate::output::invocation(),
            &answer,
            args.report,
        )?;
    }
    if args.json {
        return print_json(&answer);
    }
    print_answer(&answer);
    Ok(())
}

fn unit_stresses(
    args: &Args,
    export: &CageLoadExport,
    settings: &FatigueSettings,
) -> Result<UnitStresses, Failure> {
    let cage = &export.header.cage;
    let z = export.header.bar_station_z_m;
    match settings.stress_model {
        StressModelKind::Frame => rolldyn_fatigue::frame::unit_stresses(cage, z, &settings.frame)
            .map_err(|e| Failure::Input(e.to_string())),
        StressModelKind::Calculix => {
            let cache = args
                .cache
                .clone()
                .unwrap_or_else(|| PathBuf::from("out/calculix-cache"));
            let cache = out_dir(&cache)?;
            let spinner = ProgressBar::new_spinner();
            if args.json {
                spinner.set_draw_target(ProgressDrawTarget::hidden());
            }
            spinner.set_message(format!(
                "CalculiX unit cases of this cage (from {} if solved before, else gmsh + ccx, about 2 min)",
                cache.display()
            ));
            spinner.enable_steady_tick(std::time::Duration::from_millis(200));
            let unit = rolldyn_fatigue::calculix::unit_stresses(
                cage,
                z,
                &rolldyn_fatigue::calculix::CalculixSettings::default(),
                Some(&cache),
            )
            .map_err(|e| Failure::Run(e.to_string()));
            spinner.finish_and_clear();
            unit
        }
    }
}

#[derive(Serialize)]
struct Answer<'a> {
    model: String,
    #[serde(flatten)]
    fatigue: &'a rolldyn_fatigue::study::FatigueAnswer,
    dynamics_wall_s: f64,
    wall_time_s: f64,
    files: Vec<String>,
}

fn print_answer(a: &Answer) {
    let f = a.fatigue;
    println!(
        "{}: cage fatigue by the {:?} model, {} load sets at {:.0} rpm",
        a.model, f.stress_model, f.load_sets, f.cage_speed_rpm
    );
    println!(
        "  critical location {}: largest |stress| {:.1} MPa, damage {:.3e} per revolution",
        f.critical_location,
        f.max_stress_pa * 1e-6,
        f.damage_per_revolution
    );
    if f.life_revolutions.is_finite() {
        println!(
            "  life {:.4e} revolutions = {:.4e} h",
            f.life_revolutions, f.life_hours
        );
    } else {
        println!("  no cycle above the endurance limit: unlimited life");
    }
    println!(
        "  endurance margin (knee amplitude / largest equivalent amplitude) {:.2}, stress safety factor {:.2}: required stress safety factor {} {}",
        f.endurance_margin,
        f.stress_safety_factor,
        REQUIRED_STRESS_SAFETY_FACTOR,
        if f.stress_safety_factor >= REQUIRED_STRESS_SAFETY_FACTOR {
            "met"
        } else {
            "not met"
        }
    );
    if let Some(life) = f.inclusion_life_revolutions {
        let life = if life.is_finite() {
            format!("{life:.4e} revolutions")
        } else {
            "unlimited".into()
        };
        println!(
            "  with the inclusion: life {life}, largest matrix stress {:.1} MPa, endurance margin {:.2}",
            f.inclusion_max_stress_pa.unwrap_or(f64::NAN) * 1e-6,
            f.inclusion_endurance_margin.unwrap_or(f64::NAN)
        );
    }
    println!(
        "  wall {:.1} s (dynamics {:.1} s)",
        a.wall_time_s, a.dynamics_wall_s
    );
    for file in &a.files {
        println!("  wrote {file}");
    }
}

fn run_rainflow(args: RainflowArgs) -> Result<(), Failure> {
    let file = args.history.display().to_string();
    let bad = |e: String| Failure::Input(format!("{file}: {e}"));
    let text = rolldyn_model::read_input_file(&args.history).map_err(bad)?;
    let values = read_history_csv(&text, args.column.as_deref()).map_err(bad)?;
    let kind = if args.periodic {
        HistoryKind::Periodic
    } else {
        HistoryKind::NonPeriodic
    };
    let cycles = rainflow(&values, kind);
    if args.json {
        return print_json(&RainflowAnswer {
            history: file,
            periodic: args.periodic,
            values: values.len(),
            cycles: &cycles,
        });
    }
    println!(
        "{file}: {} values, {} cycles ({})",
        values.len(),
        cycles.iter().map(|c| c.count).sum::<f64>(),
        if args.periodic {
            "periodic"
        } else {
            "non-periodic, residue as half cycles"
        }
    );
    println!("{:>14} {:>14} {:>6}", "range", "mean", "count");
    for c in &cycles {
        println!("{:>14.6e} {:>14.6e} {:>6}", c.range, c.mean, c.count);
    }
    Ok(())
}
