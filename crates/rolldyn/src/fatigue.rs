//! Cage high-cycle fatigue from one steady revolution of the dynamics (seed 000 §2.5,
//! docs/theory.md §10), and rainflow counting of any stress history (ASTM E1049).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::observer::Progress;
use crate::operating::Operating;
use crate::output::{out_dir, sub_dir};
use crate::run_record::{ModelOrigin, finish_out_folder};
use crate::table::{Table, Tables};
use rolldyn_fatigue::cage_material::{CageMaterial, SnChoice, resolve};
use rolldyn_fatigue::calculix::CalculixSettings;
use rolldyn_fatigue::inclusion::{InclusionSettings, Interface};
use rolldyn_fatigue::mean_stress::MeanStressCorrection;
use rolldyn_fatigue::sn::{BelowKnee, SnCurve};
use rolldyn_fatigue::study::{
    FatigueAnswer, FatigueError, FatigueSettings, REQUIRED_STRESS_SAFETY_FACTOR, RevolutionMaxima,
    SettleCheckpoints, StressModelKind, evaluate, record_loads,
};
use rolldyn_fatigue::{CageLoadExport, Cycle, HistoryKind, UnitStresses, rainflow_csv};
use rolldyn_output::run_state::{StateFile, fingerprint};
use rolldyn_report::RunKind;
use rolldyn_units::{Length, Quantity};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The cage stress model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum StressName {
    /// the embedded beam frame with fillet stress-concentration factors (fast)
    #[default]
    Frame,
    /// a gmsh + CalculiX solid model (unit cases cached per cage geometry)
    Calculix,
}

/// Cycles below the knee of the S–N curve.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum BelowKneeName {
    /// the knee is an endurance limit: cycles below it do no damage
    #[default]
    NoDamage,
    /// the last segment's slope continues below the knee
    Extrapolate,
    /// Haibach: slope 2k − 1 below the knee
    Haibach,
}

/// The mean-stress correction of the counted cycles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum MeanStressName {
    /// the amplitude alone (the seed states no correction)
    #[default]
    None,
    Goodman,
    Gerber,
    /// Smith–Watson–Topper
    Swt,
}

/// The interface of the Al₂O₃ inclusion with the steel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum InterfaceName {
    /// the interface opens where it would carry tension (the seed's contact interface)
    #[default]
    Debonded,
    /// perfectly bonded everywhere
    Bonded,
}

/// A cage fatigue analysis of the context's model (or of a load export).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FatigueRequest {
    /// Overrides of the model's operating point.
    pub operating: Operating,
    pub stress: StressName,
    /// Cage revolutions simulated and discarded before the recorded one.
    pub revolutions: u32,
    /// Evaluate the Al₂O₃ inclusion (2 × 3.5 × 5 µm) at the critical location too.
    pub inclusion: Option<InterfaceName>,
    pub mean_stress: MeanStressName,
    /// Radius of the window-corner fillet, overriding the model's `cage.pocket.fillet_radius`.
    pub fillet_radius: Option<Quantity<Length>>,
    /// Largest element size of the CalculiX solid model away from the fillets (default 8 mm).
    pub mesh_size: Option<Quantity<Length>>,
    /// Element size of the CalculiX solid model at the fillet corners (default 0.6 mm).
    pub fillet_mesh_size: Option<Quantity<Length>>,
    /// Stress-concentration factors of the frame model's fillets, `[tension, bending]`
    /// (default: from the fillet radius by Roark's charts).
    pub stress_concentration: Option<[f64; 2]>,
    /// The base S–N curve (fully reversed) as CSV rows `N, sigma_a_MPa`, replacing the cage
    /// material's (default: the curve of `cage.material`).
    pub sn_curve: Option<PathBuf>,
    /// Factor on the S–N curve replacing the plating's (default: from `cage.plating`, 1 when
    /// unplated); an error on an unplated cage.
    pub coating_factor: Option<f64>,
    /// Safety factor on stress (applied to the S–N curve besides the coating factor).
    pub safety_factor: f64,
    pub below_knee: BelowKneeName,
    /// Read the cage loads from an export (`simulate --cage-loads`) instead of running the
    /// dynamics.
    pub loads: Option<PathBuf>,
    /// Output folder: the load export, stress history, damage map and plots.
    pub out: Option<PathBuf>,
    /// Write the HTML report of the `out` folder at the end of the run.
    pub report: bool,
    /// Folder of the cached CalculiX unit cases (default `out/calculix-cache`).
    pub cache: Option<PathBuf>,
    /// Continue the run killed or interrupted in `out` from what it stored in
    /// `fatigue.state`: the dynamics after its last settling revolution, or the recorded load
    /// export (the CalculiX unit cases are cached apart).
    pub resume: bool,
}

/// The file of the output folder that holds the stored state of its fatigue run
/// ([`rolldyn_output::run_state`]), replaced after every settling revolution of the dynamics
/// and once the loads are recorded.
pub const STATE_FILE: &str = "fatigue.state";

/// What a fatigue run with an output folder stores as it goes.
#[derive(Serialize, Deserialize)]
enum StoredFatigue {
    /// The dynamics checkpoint after a settling revolution.
    Settling(Vec<u8>),
    /// The loads of the recorded revolution.
    Recorded {
        export: Box<CageLoadExport>,
        maxima: RevolutionMaxima,
    },
}

impl Default for FatigueRequest {
    fn default() -> Self {
        Self {
            operating: Operating::default(),
            stress: StressName::Frame,
            revolutions: 8,
            inclusion: None,
            mean_stress: MeanStressName::None,
            fillet_radius: None,
            mesh_size: None,
            fillet_mesh_size: None,
            stress_concentration: None,
            sn_curve: None,
            coating_factor: None,
            safety_factor: 1.0,
            below_knee: BelowKneeName::NoDamage,
            loads: None,
            out: None,
            report: false,
            cache: None,
            resume: false,
        }
    }
}

/// `2.5,2.0` → `[2.5, 2.0]`, both at least 1.
pub fn parse_factor_pair(text: &str) -> Result<[f64; 2], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("'{text}': {e}"))?;
    match values.as_slice() {
        &[t, b] => check_factor_pair([t, b]).map_err(|e| format!("'{text}': {e}")),
        _ => Err(format!(
            "'{text}': two factors ≥ 1, tension and bending, e.g. 2.5,2.0"
        )),
    }
}

fn check_factor_pair([t, b]: [f64; 2]) -> Result<[f64; 2], String> {
    if t >= 1.0 && b >= 1.0 && t.is_finite() && b.is_finite() {
        Ok([t, b])
    } else {
        Err("two factors ≥ 1, tension and bending, e.g. 2.5,2.0".into())
    }
}

/// The finest element a solid model of a cage may ask for, m: 0.05 mm meshes even a small
/// cage into tens of millions of nodes, beyond a workstation's memory.
pub const FINEST_SOLID_ELEMENT_M: f64 = 0.05e-3;

impl FatigueRequest {
    /// The CalculiX settings with the request's element sizes, checked: only with the CalculiX
    /// model, no element finer than [`FINEST_SOLID_ELEMENT_M`], the fillet elements no larger
    /// than the others (they refine the mesh).
    fn calculix_settings(&self) -> Result<CalculixSettings, Failure> {
        let defaults = CalculixSettings::default();
        let sizes = [
            ("--mesh-size", self.mesh_size, defaults.mesh_size),
            (
                "--fillet-mesh-size",
                self.fillet_mesh_size,
                defaults.fillet_mesh_size,
            ),
        ];
        let mut chosen = [0.0; 2];
        for ((flag, given, default), value) in sizes.into_iter().zip(&mut chosen) {
            if given.is_some() && self.stress != StressName::Calculix {
                return Err(Failure::Input(format!(
                    "{flag}: element sizes belong to the solid model (--stress calculix)"
                )));
            }
            *value = given.map_or(default, |q| q.si());
            if !(*value >= FINEST_SOLID_ELEMENT_M && value.is_finite()) {
                return Err(Failure::Input(format!(
                    "{flag} {} mm: at least 0.05 mm (finer meshes a cage into tens of millions of nodes)",
                    rolldyn_units::format_number(*value * 1e3)
                )));
            }
        }
        let [mesh_size, fillet_mesh_size] = chosen;
        if fillet_mesh_size > mesh_size {
            return Err(Failure::Input(format!(
                "--fillet-mesh-size {} mm is larger than --mesh-size {} mm: the fillet elements refine the mesh",
                rolldyn_units::format_number(fillet_mesh_size * 1e3),
                rolldyn_units::format_number(mesh_size * 1e3)
            )));
        }
        Ok(CalculixSettings {
            mesh_size,
            fillet_mesh_size,
            ..defaults
        })
    }

    /// The fatigue settings the request asks for.
    pub fn settings(&self) -> Result<FatigueSettings, Failure> {
        let defaults = FatigueSettings::default();
        let curve = match &self.sn_curve {
            Some(path) => {
                let file = path.display().to_string();
                let text = rolldyn_model::read_input_file(path)
                    .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
                let curve = SnCurve::from_csv_text(&text)
                    .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
                Some((curve, format!("--sn-curve {file}")))
            }
            None => None,
        };
        let sn = SnChoice {
            curve,
            coating_factor: self.coating_factor,
            stress_safety_factor: self.safety_factor,
            below_knee: match self.below_knee {
                BelowKneeName::NoDamage => BelowKnee::NoDamage,
                BelowKneeName::Extrapolate => BelowKnee::Extrapolate,
                BelowKneeName::Haibach => BelowKnee::Haibach,
            },
        };
        let stress_concentration = self
            .stress_concentration
            .map(check_factor_pair)
            .transpose()
            .map_err(|e| Failure::Input(format!("--stress-concentration: {e}")))?;
        Ok(FatigueSettings {
            stress_model: match self.stress {
                StressName::Frame => StressModelKind::Frame,
                StressName::Calculix => StressModelKind::Calculix,
            },
            settle_revolutions: self.revolutions,
            frame: rolldyn_fatigue::frame::FrameSettings {
                stress_concentration,
                ..defaults.frame.clone()
            },
            fillet_radius_m: self.fillet_radius.map(|f| f.si()),
            calculix: self.calculix_settings()?,
            sn,
            inclusion: self.inclusion.map(|interface| InclusionSettings {
                interface: match interface {
                    InterfaceName::Debonded => Interface::Debonded,
                    InterfaceName::Bonded => Interface::Bonded,
                },
                ..InclusionSettings::default()
            }),
            mean_stress: match self.mean_stress {
                MeanStressName::None => MeanStressCorrection::None,
                MeanStressName::Goodman => MeanStressCorrection::Goodman,
                MeanStressName::Gerber => MeanStressCorrection::Gerber,
                MeanStressName::Swt => MeanStressCorrection::SmithWatsonTopper,
            },
            ..defaults
        })
    }
}

/// A fatigue failure as an analysis failure: bad input or a failed run.
pub fn failure(e: FatigueError) -> Failure {
    match e {
        FatigueError::Input(m) => Failure::Input(m),
        FatigueError::Numerical(m) => Failure::Run(m),
        FatigueError::Interrupted => {
            Failure::Run("fatigue interrupted during the dynamics run".into())
        }
    }
}

/// The unit stresses of the exported cage by the settings' stress model; CalculiX cases are
/// cached in `cache` (created).
pub fn unit_stresses(
    export: &CageLoadExport,
    settings: &FatigueSettings,
    cache: &Path,
) -> Result<UnitStresses, Failure> {
    let cage = &export.header.cage;
    let z = export.header.bar_station_z_m;
    match settings.stress_model {
        StressModelKind::Frame => rolldyn_fatigue::frame::unit_stresses(cage, z, &settings.frame)
            .map_err(|e| Failure::Input(e.to_string())),
        StressModelKind::Calculix => rolldyn_fatigue::calculix::unit_stresses(
            cage,
            z,
            &settings.calculix,
            Some(&sub_dir(cache)?),
        )
        .map_err(|e| Failure::Run(e.to_string())),
    }
}

/// The cage's life: what `rolldyn fatigue --json` prints.
#[derive(Clone, Debug, Serialize)]
pub struct FatigueResult {
    pub model: String,
    #[serde(flatten)]
    pub fatigue: FatigueAnswer,
    pub dynamics_wall_s: f64,
    pub wall_time_s: f64,
    pub files: Vec<String>,
    /// Rainflow cycles of the critical location's equivalent stress.
    #[serde(skip)]
    pub critical_cycles: Vec<Cycle>,
}

impl Tables for FatigueResult {
    fn tables(&self) -> Vec<Table> {
        vec![cycles_table(&self.critical_cycles)]
    }
}

fn cycles_table(cycles: &[Cycle]) -> Table {
    Table::new("cycles")
        .real("range", cycles.iter().map(|c| c.range).collect())
        .real("mean", cycles.iter().map(|c| c.mean).collect())
        .real("count", cycles.iter().map(|c| c.count).collect())
}

impl fmt::Display for FatigueResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = &self.fatigue;
        writeln!(
            f,
            "{}: cage fatigue by the {:?} model, {} load sets at {:.0} rpm",
            self.model, a.stress_model, a.load_sets, a.cage_speed_rpm
        )?;
        writeln!(
            f,
            "  critical location {}: largest |stress| {:.1} MPa, damage {:.3e} per revolution",
            a.critical_location,
            a.max_stress_pa * 1e-6,
            a.damage_per_revolution
        )?;
        writeln!(
            f,
            "  S–N curve of cage.material \"{}\": {}; coating factor {} from {}",
            a.sn.material, a.sn.curve_source, a.sn.coating_factor, a.sn.coating_source
        )?;
        if a.life_revolutions.is_finite() {
            writeln!(
                f,
                "  life {:.4e} revolutions = {:.4e} h",
                a.life_revolutions, a.life_hours
            )?;
        } else {
            writeln!(f, "  no cycle above the endurance limit: unlimited life")?;
        }
        writeln!(
            f,
            "  endurance margin (knee amplitude / largest equivalent amplitude) {:.2}, stress safety factor {:.2}: required stress safety factor {} {}",
            a.endurance_margin,
            a.stress_safety_factor,
            REQUIRED_STRESS_SAFETY_FACTOR,
            if a.stress_safety_factor >= REQUIRED_STRESS_SAFETY_FACTOR {
                "met"
            } else {
                "not met"
            }
        )?;
        if let Some(life) = a.inclusion_life_revolutions {
            let life = if life.is_finite() {
                format!("{life:.4e} revolutions")
            } else {
                "unlimited".into()
            };
            writeln!(
                f,
                "  with the inclusion: life {life}, largest matrix stress {:.1} MPa, endurance margin {:.2}",
                a.inclusion_max_stress_pa.unwrap_or(f64::NAN) * 1e-6,
                a.inclusion_endurance_margin.unwrap_or(f64::NAN)
            )?;
        }
        write!(
            f,
            "  wall {:.1} s (dynamics {:.1} s)",
            self.wall_time_s, self.dynamics_wall_s
        )?;
        for file in &self.files {
            write!(f, "\n  wrote {file}")?;
        }
        Ok(())
    }
}

/// The S–N curve of `material` with the run's settings, resolved before the dynamics run so that
/// a missing curve or a coating factor on an unplated cage is bad input found at once.
fn check_sn(material: Option<&CageMaterial>, settings: &FatigueSettings) -> Result<(), Failure> {
    resolve(material, &settings.sn, settings.mean_stress)
        .map(|_| ())
        .map_err(Failure::Input)
}

/// The fatigue stages, for progress.
const STAGES: f64 = 4.0;

fn stage(context: &Context<'_>, done: f64, message: String) -> Result<(), Failure> {
    if context.observer.stop_requested() {
        return Err(Failure::Run(format!(
            "fatigue interrupted before {message}"
        )));
    }
    context.observer.progress(&Progress {
        done,
        total: STAGES,
        unit: "stages",
        message: Some(message),
    });
    Ok(())
}

/// The cage fatigue analysis.
pub struct Fatigue;

impl Analysis for Fatigue {
    const NAME: &'static str = "fatigue";
    type Request = FatigueRequest;
    type Result = FatigueResult;

    fn run(request: &FatigueRequest, context: &Context<'_>) -> Result<FatigueResult, Failure> {
        let wall = Instant::now();
        let settings = request.settings()?;
        if request.resume && request.loads.is_some() {
            return Err(Failure::Input(
                "--resume continues the dynamics of a run; with --loads there is none".into(),
            ));
        }
        if request.report && request.out.is_none() {
            return Err(Failure::Input(
                "--report needs an output folder (--out)".into(),
            ));
        }
        let out = request.out.as_deref().map(out_dir).transpose()?;
        let (mut export, maxima) = match &request.loads {
            Some(_) if request.operating.any() => {
                return Err(Failure::Input(
                    "--loads: the operating point is that of the export; drop the operating overrides"
                        .into(),
                ));
            }
            Some(path) => {
                let export = CageLoadExport::read(path).map_err(Failure::Input)?;
                check_sn(export.header.cage_material.as_ref(), &settings)?;
                let maxima = RevolutionMaxima::of_export(&export);
                (export, maxima)
            }
            None => {
                let model = context.model.load()?;
                if let Some(material) = model
                    .bearing
                    .require_cylindrical("cage fatigue")
                    .ok()
                    .and_then(CageMaterial::of)
                {
                    check_sn(Some(&material), &settings)?;
                }
                stage(
                    context,
                    0.0,
                    format!(
                        "dynamics: {} cage revolutions and the recorded one",
                        settings.settle_revolutions
                    ),
                )?;
                let mut watch = |t: f64, settled: f64| {
                    context.observer.progress(&Progress {
                        done: (t / settled.max(f64::MIN_POSITIVE)).min(1.0),
                        total: STAGES,
                        unit: "stages",
                        message: Some(format!("dynamics, t = {t:.4} s")),
                    });
                    if context.observer.stop_requested() {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                };
                let store = match &out {
                    Some(dir) => Some(StateFile::new(
                        dir.join(STATE_FILE),
                        fingerprint(&format!(
                            "fatigue\n{model:?}\n{:?}\n{settings:?}",
                            request.operating
                        )),
                    )),
                    None if request.resume => {
                        return Err(Failure::Input(
                            "--resume continues the run of an output folder: give --out".into(),
                        ));
                    }
                    None => None,
                };
                let stored = match (&store, request.resume) {
                    (Some(store), true) => {
                        store.load().map_err(|e| Failure::Input(e.to_string()))?
                    }
                    _ => None,
                };
                match stored {
                    Some(StoredFatigue::Recorded { export, maxima }) => (*export, maxima),
                    settling => {
                        let start = match settling {
                            Some(StoredFatigue::Settling(bytes)) => Some(bytes),
                            _ => None,
                        };
                        let mut store_dynamics = |bytes: &[u8]| match &store {
                            Some(s) => s
                                .store(&StoredFatigue::Settling(bytes.to_vec()))
                                .map_err(|e| e.to_string()),
                            None => Ok(()),
                        };
                        let checkpoints = store.is_some().then_some(SettleCheckpoints {
                            start,
                            store: &mut store_dynamics,
                        });
                        let (export, maxima, _) = record_loads(
                            &model,
                            &request.operating.overrides(),
                            &settings,
                            checkpoints,
                            &mut watch,
                        )
                        .map_err(failure)?;
                        if let Some(s) = &store {
                            let recorded = StoredFatigue::Recorded {
                                export: Box::new(export.clone()),
                                maxima,
                            };
                            s.store(&recorded)
                                .map_err(|e| Failure::Run(e.to_string()))?;
                        }
                        (export, maxima)
                    }
                }
            }
        };
        // an export read back keeps its model's fillet unless the request overrides it
        export.header.cage = export
            .header
            .cage
            .with_fillet_radius(settings.fillet_radius_m);
        let dynamics_s = wall.elapsed().as_secs_f64();
        let cache = request
            .cache
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/calculix-cache"));
        stage(
            context,
            1.0,
            match settings.stress_model {
                StressModelKind::Frame => "stresses: the beam frame's unit cases".into(),
                StressModelKind::Calculix => format!(
                    "stresses: CalculiX unit cases of this cage (from {} if solved before, else gmsh + ccx, about 2 min)",
                    cache.display()
                ),
            },
        )?;
        let unit = unit_stresses(&export, &settings, &cache)?;
        stage(context, 2.0, "damage: rainflow, S–N, Miner".into())?;
        let result = evaluate(&unit, &export, Some(maxima), &settings).map_err(Failure::Run)?;
        stage(context, 3.0, "report files".into())?;
        let files = match &out {
            Some(dir) => rolldyn_fatigue::report::write_report(dir, &export, &result)
                .map_err(Failure::Run)?,
            None => Vec::new(),
        };
        let answer = FatigueResult {
            model: export.header.model.clone(),
            fatigue: result.answer,
            dynamics_wall_s: dynamics_s,
            wall_time_s: wall.elapsed().as_secs_f64(),
            files: files.iter().map(|f| f.display().to_string()).collect(),
            critical_cycles: result.critical_cycles,
        };
        if let Some(dir) = &out {
            let model = match request.loads {
                Some(_) => ModelOrigin::None,
                None => ModelOrigin::Source(&context.model),
            };
            finish_out_folder(
                dir,
                RunKind::Fatigue,
                model,
                &context.invocation,
                &answer,
                request.report,
            )?;
        }
        Ok(answer)
    }
}

/// Rainflow counting of a stress history in a CSV file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RainflowRequest {
    /// CSV file: one value per row (the first column, or `column` of a file with a header),
    /// read line by line, of any size.
    pub history: PathBuf,
    /// Column to count (by its header name).
    #[serde(default)]
    pub column: Option<String>,
    /// The file is one period of a repeating history (every cycle closes); otherwise the
    /// residue counts as half cycles.
    #[serde(default)]
    pub periodic: bool,
}

/// The counted cycles.
#[derive(Clone, Debug, Serialize)]
pub struct RainflowResult {
    pub history: String,
    pub periodic: bool,
    pub values: usize,
    pub cycles: Vec<Cycle>,
}

impl Tables for RainflowResult {
    fn tables(&self) -> Vec<Table> {
        vec![cycles_table(&self.cycles)]
    }
}

impl fmt::Display for RainflowResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}: {} values, {} cycles ({})",
            self.history,
            self.values,
            self.cycles.iter().map(|c| c.count).sum::<f64>(),
            if self.periodic {
                "periodic"
            } else {
                "non-periodic, residue as half cycles"
            }
        )?;
        write!(f, "{:>14} {:>14} {:>6}", "range", "mean", "count")?;
        for c in &self.cycles {
            write!(f, "\n{:>14.6e} {:>14.6e} {:>6}", c.range, c.mean, c.count)?;
        }
        Ok(())
    }
}

/// Rainflow cycle counting (ASTM E1049 four-point).
pub struct Rainflow;

impl Analysis for Rainflow {
    const NAME: &'static str = "rainflow";
    type Request = RainflowRequest;
    type Result = RainflowResult;

    fn run(request: &RainflowRequest, _context: &Context<'_>) -> Result<RainflowResult, Failure> {
        let file = request.history.display().to_string();
        let kind = if request.periodic {
            HistoryKind::Periodic
        } else {
            HistoryKind::NonPeriodic
        };
        let counted = rainflow_csv(&request.history, request.column.as_deref(), kind)
            .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
        Ok(RainflowResult {
            cycles: counted.cycles,
            history: file,
            periodic: request.periodic,
            values: counted.values,
        })
    }
}
