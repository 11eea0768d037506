//! `rolldyn wear`: a model's life run end to end — conditions, the life loop, the tables and
//! plots, the worn model — and the answer the command prints (docs/outputs.md "wear").

use crate::WearError;
use crate::bearing_data::ribs_on_inner_ring;
use crate::life::{LifeInputs, LifeState, PeriodRecord, StopReason, halved_period_check, run_life};
use crate::rates::{CONTACT_KINDS, ContactDiagnostics};
use crate::report::{WearTables, WearTablesNote};
use crate::settings::{PeriodControl, WearMethod, WearSettings};
use crate::surface::PerSurface;
use crate::worn_model::write_worn_model;
use rolldyn_model::Model;
use rolldyn_output::run_state::{StateFile, fingerprint};
use rolldyn_setup::Overrides;
use serde::Serialize;
use std::collections::BTreeMap;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The stored state of a life run with an output folder: where the life loop stands and the
/// rows of its tables.
#[derive(serde::Serialize, serde::Deserialize)]
struct StoredLife {
    life: LifeState,
    tables: WearTablesNote,
}

/// One period in the answer.
#[derive(Debug, Clone, Serialize)]
pub struct PeriodSummary {
    pub time_h: f64,
    pub period_h: f64,
    pub max_depth_m: PerSurface<f64>,
    pub max_rate_m_s: PerSurface<f64>,
    pub clearance_increase_m: f64,
    pub halvings: u32,
}

impl From<&PeriodRecord> for PeriodSummary {
    fn from(p: &PeriodRecord) -> Self {
        Self {
            time_h: p.time_h,
            period_h: p.period_h,
            max_depth_m: p.max_depth_m,
            max_rate_m_s: p.max_rate_m_s,
            clearance_increase_m: p.clearance_increase_m,
            halvings: p.halvings,
        }
    }
}

/// The automatic period's convergence evidence (SPEC §6.6).
#[derive(Debug, Clone, Serialize)]
pub struct Convergence {
    /// the first period of the check run (every accepted period halved), h
    pub halved_period_h: f64,
    pub max_depth_halved_m: PerSurface<f64>,
    /// depth with the accepted periods over depth with the halved one, minus 1
    pub relative_difference: PerSurface<f64>,
}

/// What `rolldyn wear` prints with `--json`.
#[derive(Debug, Clone, Serialize)]
pub struct WearAnswer {
    pub model: String,
    pub method: &'static str,
    pub requested_life_h: f64,
    /// cage revolutions recorded per period, and discarded before them
    pub revolutions: u32,
    pub settle_revolutions: u32,
    /// life reached, h
    pub life_h: f64,
    pub stop: StopReason,
    pub periods: Vec<PeriodSummary>,
    pub max_depth_m: PerSurface<f64>,
    /// the part of the roller's deepest wear that the cage bar caused, m
    pub roller_depth_from_bar_m: f64,
    pub clearance_increase_m: f64,
    /// what the first period's rates came from, per contact kind (the unworn bearing)
    pub initial_contacts: BTreeMap<&'static str, ContactDiagnostics>,
    pub convergence: Option<Convergence>,
    pub wall_time_s: f64,
    pub dynamics_wall_s: f64,
    pub wear_wall_s: f64,
    pub output_folder: Option<String>,
    pub files: Vec<String>,
}

/// The file of an output folder that holds the stored state of its life run
/// ([`rolldyn_output::run_state`]), replaced after every period.
pub const STATE_FILE: &str = "wear.state";

/// Runs the life of `model` and writes its outputs into `out` (when given), storing the run's
/// state there after every period; with `resume`, continues the run whose state `out` holds
/// (from the start when it holds none). `progress` sees each accepted period and may end the
/// run there (the answer's `stop` is then [`StopReason::Interrupted`], the outputs are those
/// of the periods run).
pub fn run_wear(
    model: &Model,
    overrides: &Overrides,
    settings: &WearSettings,
    out: Option<&Path>,
    resume: bool,
    progress: &mut dyn FnMut(&PeriodRecord) -> ControlFlow<()>,
) -> Result<WearAnswer, WearError> {
    let wall = Instant::now();
    let bearing = model
        .bearing
        .require_cylindrical("wear")
        .map_err(|reason| WearError::Input(format!("{}: {reason}", model.source.file)))?;
    let input = |e: rolldyn_setup::SetupError| WearError::Input(e.0);
    let lubrication = rolldyn_setup::quasi_static::lubrication(model, "wear").map_err(input)?;
    let conditions = rolldyn_setup::conditions(overrides, model).map_err(input)?;
    let inputs = LifeInputs {
        bearing,
        lubrication,
        dynamics: &model.dynamics,
        conditions: &conditions,
    };
    let output_error = |e: String| WearError::Numerical(e);
    let positions = bearing.roller.slices().position;
    let inputs_text = format!(
        "wear\n{bearing:?}\n{lubrication:?}\n{:?}\n{conditions:?}\n{settings:?}",
        model.dynamics
    );
    let store = out.map(|dir| StateFile::new(dir.join(STATE_FILE), fingerprint(&inputs_text)));
    let stored: Option<StoredLife> = match (&store, resume) {
        (Some(store), true) => store.load().map_err(|e| WearError::Input(e.to_string()))?,
        (None, true) => {
            return Err(WearError::Input(
                "--resume continues the run of an output folder: give --out".into(),
            ));
        }
        (_, false) => None,
    };
    let mut tables = out
        .map(|dir| match &stored {
            Some(s) => WearTables::resume(dir, &positions, &s.tables, &s.life.periods).map_err(
                |e| {
                    WearError::Input(format!(
                        "{e} (--resume continues the output folder of the run that stored {STATE_FILE})"
                    ))
                },
            ),
            None => WearTables::create(dir, &positions).map_err(|e| output_error(e.to_string())),
        })
        .transpose()?;
    let mut table_error = None;
    let locate = |e: WearError| match e {
        WearError::Key { key, reason } => {
            WearError::Input(model.source.error(&key, reason).to_string())
        }
        e => e,
    };
    let run = run_life(&inputs, settings, stored.map(|s| s.life), &mut |state| {
        let record = state.periods.last().expect("a period was accepted");
        if let (Some(t), None) = (tables.as_mut(), &table_error) {
            let stored = t
                .period(record, &state.depth)
                .map_err(|e| e.to_string())
                .and_then(|_| {
                    let life = StoredLife {
                        life: state.clone(),
                        tables: t.note(),
                    };
                    store
                        .as_ref()
                        .map_or(Ok(()), |s| s.store(&life).map_err(|e| e.to_string()))
                });
            if let Err(e) = stored {
                table_error = Some(e);
                // what is not stored cannot be resumed: stop here
                return ControlFlow::Break(());
            }
        }
        progress(record)
    })
    .map_err(locate)?;
    if let Some(e) = table_error {
        return Err(output_error(e));
    }
    let convergence = match &settings.period {
        _ if run.stop == StopReason::Interrupted => None,
        PeriodControl::Auto { .. } => {
            let (check, difference) = halved_period_check(&inputs, settings, &run)?;
            Some(Convergence {
                halved_period_h: check.periods.first().map_or(0.0, |p| p.period_h),
                max_depth_halved_m: check.depth.max_per_surface(),
                relative_difference: difference,
            })
        }
        PeriodControl::Fixed(_) | PeriodControl::Schedule(_) => None,
    };
    let mut files: Vec<PathBuf> = Vec::new();
    if let (Some(dir), Some(t)) = (out, tables) {
        files.extend(
            t.finish(&run.depth)
                .map_err(|e| output_error(e.to_string()))?,
        );
        let note = format!(
            "{} worn by `rolldyn wear` over {:.0} h ({} periods); written from {}",
            bearing.name,
            run.life_h,
            run.periods.len(),
            model.source.file
        );
        files.extend(write_worn_model(
            model.source.text(),
            &run.worn,
            ribs_on_inner_ring(bearing),
            dir,
            &note,
        )?);
    }
    let (dynamics, wear): (f64, f64) = run.periods.iter().fold((0.0, 0.0), |(d, w), p| {
        (d + p.dynamics_wall_s, w + p.wear_wall_s)
    });
    Ok(WearAnswer {
        model: model.source.file.clone(),
        method: match settings.method {
            WearMethod::Direct => "direct",
            WearMethod::Averaged => "averaged",
        },
        requested_life_h: settings.life_s / 3600.0,
        revolutions: settings.revolutions,
        settle_revolutions: settings.settle_revolutions,
        life_h: run.life_h,
        stop: run.stop.clone(),
        periods: run.periods.iter().map(PeriodSummary::from).collect(),
        max_depth_m: run.depth.max_per_surface(),
        roller_depth_from_bar_m: run.depth.roller_at_bar.iter().copied().fold(0.0, f64::max),
        initial_contacts: run
            .periods
            .first()
            .map(|p| CONTACT_KINDS.into_iter().zip(p.contacts).collect())
            .unwrap_or_default(),
        clearance_increase_m: run.depth.clearance_increase(),
        convergence,
        wall_time_s: wall.elapsed().as_secs_f64(),
        dynamics_wall_s: dynamics,
        wear_wall_s: wear,
        output_folder: out.map(|d| d.display().to_string()),
        files: files.iter().map(|f| f.display().to_string()).collect(),
    })
}
