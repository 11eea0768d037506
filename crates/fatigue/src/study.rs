//! `rolldyn fatigue`: the life of a machined cage from one steady revolution of the dynamics
//! (seed 000 §2.5; theory §10): load export → unit stresses → stress histories at the fillets →
//! rainflow → S–N and Miner → life and critical location, and with an inclusion the life at the
//! critical location with the inclusion's local stresses.

use crate::cage::{CageGeometry, FilletPoint};
use crate::cage_material::{CageMaterial, SnChoice, SnUsed, resolve};
use crate::calculix::CalculixSettings;
use crate::damage::{DamageBreakdown, life_hours, miner_damage};
use crate::frame::{FilletFactors, FrameSettings, fillet_factors};
use crate::inclusion::{InclusionModel, InclusionSettings};
use crate::loads::{CageLoadExport, ExportHeader, FORMAT, VERSION};
use crate::mean_stress::MeanStressCorrection;
use crate::rainflow::{Cycle, HistoryKind, rainflow};
use crate::recorder::{CageLoadRecorder, export_output_step};
use crate::sn::{BelowKnee, SnSettings};
use crate::unit_stresses::{Stress, UnitStresses, signed_von_mises};
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_output::non_finite::default_reason;
use serde::Serialize;
use std::collections::BTreeMap;
use std::ops::ControlFlow;

// at its old path too (the `rolldyn fatigue` command names it here); it lives with the export
pub use crate::loads::RevolutionMaxima;

/// Which cage stress model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StressModelKind {
    /// the embedded beam frame ([`crate::frame`])
    Frame,
    /// the gmsh + CalculiX solid model ([`crate::calculix`])
    Calculix,
}

/// Knobs of a fatigue evaluation.
#[derive(Debug, Clone)]
pub struct FatigueSettings {
    pub stress_model: StressModelKind,
    /// cage revolutions simulated and discarded before the recorded one; default 8 (the cage
    /// speed of the 2002834 model settles within 5)
    pub settle_revolutions: u32,
    /// output samples per 2° load set (each set is the nearest sample); default 4
    pub samples_per_set: f64,
    /// radius of the window-corner fillet, m, overriding the model's `cage.pocket.fillet_radius`
    /// (`None`: the model's)
    pub fillet_radius_m: Option<f64>,
    pub frame: FrameSettings,
    /// the S–N curve's overrides and knock-downs (the curve itself is the cage material's)
    pub sn: SnChoice,
    pub mean_stress: MeanStressCorrection,
    /// the inclusion at the critical location, if any
    pub inclusion: Option<InclusionSettings>,
    /// the solid model's mesh and executables (used with [`StressModelKind::Calculix`])
    pub calculix: CalculixSettings,
}

impl Default for FatigueSettings {
    fn default() -> Self {
        Self {
            stress_model: StressModelKind::Frame,
            settle_revolutions: 8,
            samples_per_set: 4.0,
            fillet_radius_m: None,
            frame: FrameSettings::default(),
            sn: SnChoice::default(),
            mean_stress: MeanStressCorrection::default(),
            inclusion: None,
            calculix: CalculixSettings::default(),
        }
    }
}

/// The stress safety factor the cage must meet: the seed's "1.5" (seed 000 §3.1.1.8) read as a
/// requirement on [`FatigueAnswer::stress_safety_factor`], not a measured margin.
pub const REQUIRED_STRESS_SAFETY_FACTOR: f64 = 1.5;

/// The cage of `bearing` as the stress models see it: its ring, material and pocket profile,
/// with the fillet radius `fillet_radius_m` when given (else the model's).
pub fn cage_geometry(
    bearing: &CylindricalRollerBearing,
    fillet_radius_m: Option<f64>,
) -> Result<CageGeometry, String> {
    let cage = bearing
        .cage
        .as_ref()
        .ok_or("cage fatigue needs a cage ([cage] in the model)")?;
    let ctx = bearing.pocket_context(cage);
    let play = cage.pocket.play(&ctx).map_err(|e| e.to_string())?;
    let walls = cage.pocket.walls(&ctx).map_err(|e| e.to_string())?;
    // the contact point snapped onto the flank the stress models mesh (they do not round the
    // lip edge): the window's half-width at the contact radius
    let [rho, _] = play.circumferential_contact;
    let geometry = CageGeometry {
        pockets: ctx.pockets,
        inner_radius: ctx.cage_inner_radius,
        outer_radius: ctx.cage_outer_radius,
        width: cage.width,
        pocket: cage.pocket,
        roller_radius: ctx.roller_radius,
        pitch_radius: ctx.pitch_radius,
        bar_contact: [rho, walls.half_window_at(rho)],
        youngs_modulus: cage.material.youngs_modulus,
        poisson_ratio: cage.material.poisson_ratio,
        density: cage.material.density,
    }
    .with_fillet_radius(fillet_radius_m);
    let problems = geometry.problems();
    if problems.is_empty() {
        Ok(geometry)
    } else {
        Err(format!("[cage]: {}", problems.join("; ")))
    }
}

/// The fatigue of one fillet point.
#[derive(Debug, Clone, Serialize)]
pub struct PointFatigue {
    pub location: String,
    /// position of the fillet corner in cage coordinates, m
    pub point_m: [f64; 3],
    pub max_stress_pa: f64,
    pub min_stress_pa: f64,
    pub damage_per_revolution: f64,
}

/// The element sizes of the solid model a fatigue answer was computed with.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SolidMesh {
    /// largest element size away from the fillets, m
    pub mesh_size_m: f64,
    /// element size at the fillet corners, m
    pub fillet_mesh_size_m: f64,
}

impl SolidMesh {
    /// The mesh of `settings`.
    pub fn of(settings: &CalculixSettings) -> Self {
        Self {
            mesh_size_m: settings.mesh_size,
            fillet_mesh_size_m: settings.fillet_mesh_size,
        }
    }
}

/// The answer of a fatigue evaluation (`rolldyn fatigue --json`).
#[derive(Debug, Clone, Serialize)]
pub struct FatigueAnswer {
    pub stress_model: StressModelKind,
    pub load_sets: usize,
    pub cage_speed_rpm: f64,
    /// the fillet stress-concentration factors of the frame model
    pub stress_concentration: FilletFactors,
    /// the element sizes of the CalculiX solid model (`None` with the frame model)
    pub solid_mesh: Option<SolidMesh>,
    pub damage_per_revolution: f64,
    /// cage revolutions to failure (∞ → null)
    pub life_revolutions: f64,
    pub life_hours: f64,
    /// the life with the S–N curve's last slope continued below the knee (no endurance
    /// limit): finite for any cycling stress, the figure that ranks variants whose cycles all
    /// lie below the knee, revolutions
    pub extrapolated_life_revolutions: f64,
    /// the fillet with the largest damage (or the largest |stress| when nothing is damaged)
    pub critical_location: String,
    pub critical_point_m: [f64; 3],
    /// largest |signed von Mises| over the fillets and the revolution, Pa
    pub max_stress_pa: f64,
    /// allowable amplitude at the knee of the S–N curve over the largest equivalent amplitude at
    /// the critical location: ≥ 1 means no damage (seed 000 §3.1.1.8 "stress margin")
    pub endurance_margin: f64,
    /// the stress safety factor the cage meets: the endurance margin times the safety factor
    /// already applied to the S–N curve (the margin on the coated curve alone)
    pub stress_safety_factor: f64,
    pub maxima: Option<RevolutionMaxima>,
    /// the S–N curve used: the cage material's (or the run's file), its coating factor and
    /// their sources
    pub sn: SnUsed,
    pub inclusion_life_revolutions: Option<f64>,
    pub inclusion_max_stress_pa: Option<f64>,
    /// the worst point on the inclusion's surface, in the ellipsoid axes (by default radial,
    /// circumferential, axial)
    pub inclusion_location: Option<String>,
    /// the endurance margin of the worst point on the inclusion's surface
    pub inclusion_endurance_margin: Option<f64>,
    pub points: Vec<PointFatigue>,
    /// why a value of this level prints as `null` (docs/outputs.md: the one policy for values
    /// that are not finite numbers)
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub non_finite: BTreeMap<&'static str, String>,
}

impl FatigueAnswer {
    /// The reasons of the values that print as `null`: an infinite life is unlimited (no cycle
    /// above the S–N curve's knee), any other non-finite value gets the usual reason.
    fn non_finite_reasons(&self) -> BTreeMap<&'static str, String> {
        let unlimited = "unlimited: no cycle above the knee of the S–N curve";
        let values = [
            ("damage_per_revolution", self.damage_per_revolution),
            ("life_revolutions", self.life_revolutions),
            ("life_hours", self.life_hours),
            (
                "extrapolated_life_revolutions",
                self.extrapolated_life_revolutions,
            ),
            ("max_stress_pa", self.max_stress_pa),
            ("endurance_margin", self.endurance_margin),
            ("stress_safety_factor", self.stress_safety_factor),
            (
                "inclusion_life_revolutions",
                self.inclusion_life_revolutions.unwrap_or(0.0),
            ),
            (
                "inclusion_max_stress_pa",
                self.inclusion_max_stress_pa.unwrap_or(0.0),
            ),
            (
                "inclusion_endurance_margin",
                self.inclusion_endurance_margin.unwrap_or(0.0),
            ),
        ];
        values
            .into_iter()
            .filter(|(_, value)| !value.is_finite())
            .map(|(key, value)| {
                let reason = match value == f64::INFINITY && key.contains("life") {
                    true => unlimited.to_string(),
                    false => default_reason(value).to_string(),
                };
                (key, reason)
            })
            .collect()
    }
}

/// Everything a fatigue evaluation computed, for the report files.
pub struct FatigueResult {
    pub answer: FatigueAnswer,
    /// stress tensors at the critical location over the revolution
    pub critical_history: Vec<Stress>,
    pub critical_cycles: Vec<Cycle>,
    pub critical_damage: DamageBreakdown,
    pub cage_angle_deg: Vec<f64>,
}

/// The signed von Mises history of a tensor history.
fn signed(history: &[Stress]) -> Vec<f64> {
    history.iter().map(signed_von_mises).collect()
}

/// The largest equivalent fully reversed amplitude of the counted cycles, Pa.
fn largest_equivalent_amplitude(damage: &DamageBreakdown) -> f64 {
    damage
        .cycles
        .iter()
        .map(|c| c.equivalent_amplitude_pa)
        .fold(0.0, f64::max)
}

/// The allowable amplitude at the knee of the S–N curve (coating and safety factors applied), Pa.
fn endurance_amplitude(sn: &SnUsed) -> f64 {
    let (_, knee) = sn.curve.knee();
    knee / sn.curve.settings().knock_down()
}

/// Rainflow and Miner of one periodic history.
fn damage_of(history: &[f64], sn: &SnUsed) -> (Vec<Cycle>, DamageBreakdown) {
    let cycles = rainflow(history, HistoryKind::Periodic);
    let damage = miner_damage(&cycles, &sn.curve, &sn.mean_stress);
    (cycles, damage)
}

/// The fatigue of the cage from its load export and unit stresses.
pub fn evaluate(
    unit: &UnitStresses,
    export: &CageLoadExport,
    maxima: Option<RevolutionMaxima>,
    settings: &FatigueSettings,
) -> Result<FatigueResult, String> {
    if !unit.consistent() || unit.cage.pockets != export.header.cage.pockets {
        return Err("the unit stresses do not belong to the exported cage".into());
    }
    let histories = crate::superpose::stress_histories(unit, export);
    let points = FilletPoint::all(unit.cage.pockets);
    let sn = resolve(
        export.header.cage_material.as_ref(),
        &settings.sn,
        settings.mean_stress,
    )?;
    let extrapolating = SnUsed {
        curve: sn
            .curve
            .clone()
            .with_settings(SnSettings {
                below_knee: BelowKnee::Extrapolate,
                ..*sn.curve.settings()
            })
            .map_err(|e| e.to_string())?,
        ..sn.clone()
    };
    let mut extrapolated_damage: f64 = 0.0;
    let mut fatigue = Vec::with_capacity(points.len());
    let mut worst = (0usize, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for (i, (p, h)) in points.iter().zip(&histories).enumerate() {
        let s = signed(h);
        if let Some(set) = s.iter().position(|x| !x.is_finite()) {
            return Err(format!(
                "the stress at {} is not finite in load set {set} (cage angle {}°): the loads \
                 or the unit stresses overflow; no life is computed from it",
                p.label(),
                export.sets.get(set).map_or(f64::NAN, |s| s.cage_angle_deg)
            ));
        }
        let (_, d) = damage_of(&s, &sn);
        let (_, e) = damage_of(&s, &extrapolating);
        extrapolated_damage = extrapolated_damage.max(e.damage_per_repeat);
        let max = s.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b));
        let min = s.iter().fold(f64::INFINITY, |a, &b| a.min(b));
        let peak = max.abs().max(min.abs());
        if (d.damage_per_repeat, peak) > (worst.1, worst.2) {
            worst = (i, d.damage_per_repeat, peak);
        }
        fatigue.push(PointFatigue {
            location: p.label(),
            point_m: p.corner(&unit.cage),
            max_stress_pa: max,
            min_stress_pa: min,
            damage_per_revolution: d.damage_per_repeat,
        });
    }
    let critical = worst.0;
    let critical_signed = signed(&histories[critical]);
    let (cycles, breakdown) = damage_of(&critical_signed, &sn);
    let max_stress = fatigue
        .iter()
        .map(|p| p.max_stress_pa.abs().max(p.min_stress_pa.abs()))
        .fold(0.0, f64::max);
    let largest_equivalent = largest_equivalent_amplitude(&breakdown);
    let endurance = endurance_amplitude(&sn);
    let cage_speed_rpm = export.header.cage_speed_rpm;
    let omega = cage_speed_rpm * std::f64::consts::TAU / 60.0;
    let life = breakdown.life_repeats;
    let mut answer = FatigueAnswer {
        stress_model: settings.stress_model,
        load_sets: export.sets.len(),
        cage_speed_rpm,
        stress_concentration: fillet_factors(&unit.cage, &settings.frame),
        solid_mesh: match settings.stress_model {
            StressModelKind::Frame => None,
            StressModelKind::Calculix => Some(SolidMesh::of(&settings.calculix)),
        },
        damage_per_revolution: breakdown.damage_per_repeat,
        life_revolutions: life,
        life_hours: life_hours(life, omega),
        extrapolated_life_revolutions: 1.0 / extrapolated_damage,
        critical_location: fatigue[critical].location.clone(),
        critical_point_m: fatigue[critical].point_m,
        max_stress_pa: max_stress,
        endurance_margin: endurance / largest_equivalent,
        stress_safety_factor: endurance / largest_equivalent * sn.stress_safety_factor,
        maxima,
        sn,
        inclusion_life_revolutions: None,
        inclusion_max_stress_pa: None,
        inclusion_location: None,
        inclusion_endurance_margin: None,
        points: fatigue,
        non_finite: BTreeMap::new(),
    };
    if let Some(inclusion) = &settings.inclusion {
        inclusion_fatigue(&unit.cage, inclusion, &histories[critical], &mut answer)?;
    }
    answer.non_finite = answer.non_finite_reasons();
    Ok(FatigueResult {
        answer,
        critical_history: histories[critical].clone(),
        critical_cycles: cycles,
        critical_damage: breakdown,
        cage_angle_deg: export.sets.iter().map(|s| s.cage_angle_deg).collect(),
    })
}

/// The life at the critical location with the inclusion there: the matrix stress history at
/// every sample point of the inclusion's surface, counted and damaged like a fillet's.
fn inclusion_fatigue(
    cage: &CageGeometry,
    inclusion: &InclusionSettings,
    remote: &[Stress],
    answer: &mut FatigueAnswer,
) -> Result<(), String> {
    let model = InclusionModel::new(inclusion, cage.youngs_modulus, cage.poisson_ratio)?;
    let remote: Vec<[f64; 6]> = remote
        .iter()
        .map(|s| model.remote_from_cylindrical(s))
        .collect();
    let mut worst: Option<(f64, f64, String)> = None;
    let mut largest_equivalent: f64 = 0.0;
    for (point, history) in model.matrix_stress_histories(&remote) {
        let s = signed(&history);
        let (_, d) = damage_of(&s, &answer.sn);
        largest_equivalent = largest_equivalent.max(largest_equivalent_amplitude(&d));
        let peak = s.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
        if worst
            .as_ref()
            .is_none_or(|w| (d.damage_per_repeat, peak) > (w.0, w.1))
        {
            let [x, y, z] = point.position.map(|v| v * 1e6);
            let label = format!("({x:.2}, {y:.2}, {z:.2}) µm in the ellipsoid axes");
            worst = Some((d.damage_per_repeat, peak, label));
        }
    }
    if let Some((damage, peak, location)) = worst {
        answer.inclusion_life_revolutions = Some(1.0 / damage);
        answer.inclusion_max_stress_pa = Some(peak);
        answer.inclusion_location = Some(location);
        answer.inclusion_endurance_margin =
            Some(endurance_amplitude(&answer.sn) / largest_equivalent);
    }
    Ok(())
}

/// The header of an export of `cage` of `cage_material` at the mean cage speed
/// `cage_speed_rad_s`.
pub fn export_header(
    model: &str,
    cage: &CageGeometry,
    cage_material: Option<CageMaterial>,
    bar_station_z_m: f64,
    cage_speed_rad_s: f64,
) -> ExportHeader {
    ExportHeader {
        format: FORMAT.into(),
        version: VERSION,
        units: "SI: N, m, s, rad; cage_angle_deg in degrees".into(),
        model: model.into(),
        cage: cage.clone(),
        cage_material,
        bar_station_z_m,
        cage_speed_rpm: cage_speed_rad_s.abs() * 60.0 / std::f64::consts::TAU,
    }
}

/// The dynamics checkpoints of a resumable fatigue run's settling: the one to start from (of
/// an interrupted run with the same inputs) and where each new one goes (after every settling
/// revolution; an error stops the run).
pub struct SettleCheckpoints<'a> {
    pub start: Option<Vec<u8>>,
    pub store: &'a mut dyn FnMut(&[u8]) -> Result<(), String>,
}

/// A model's dynamics run to its load export: `settle_revolutions` discarded (checkpointed
/// after each one with `checkpoints`), then recorded until the cage has turned a full revolution
/// (at most three epicyclic periods). `watch(t, t_settled)` is called after every accepted step
/// with the simulated time and the end of the settling; `Break` stops the run
/// ([`FatigueError::Interrupted`]).
pub fn record_loads(
    model: &rolldyn_model::Model,
    overrides: &rolldyn_setup::Overrides,
    settings: &FatigueSettings,
    checkpoints: Option<SettleCheckpoints>,
    watch: &mut dyn FnMut(f64, f64) -> ControlFlow<()>,
) -> Result<(CageLoadExport, RevolutionMaxima, CageGeometry), FatigueError> {
    let bearing = model
        .bearing
        .require_cylindrical("cage fatigue")
        .map_err(|reason| FatigueError::Input(format!("{}: {reason}", model.source.file)))?;
    let cage = cage_geometry(bearing, settings.fillet_radius_m)
        .map_err(|e| FatigueError::Input(format!("{}: {e}", model.source.file)))?;
    let input = |e: rolldyn_setup::SetupError| FatigueError::Input(e.0);
    let lubrication = rolldyn_setup::quasi_static::lubrication(model, "fatigue").map_err(input)?;
    let conditions = rolldyn_setup::conditions(overrides, model).map_err(input)?;
    let epicyclic = bearing.epicyclic_cage_speed(
        conditions.inner_speed.speed(0.0),
        conditions.outer_speed.speed(0.0),
    );
    if epicyclic == 0.0 {
        return Err(FatigueError::Input(
            "cage fatigue needs a running bearing: the rings do not turn at t = 0".into(),
        ));
    }
    let step = export_output_step(epicyclic, settings.samples_per_set);
    let prepared = rolldyn_setup::prepare_with(
        bearing,
        lubrication,
        &model.dynamics,
        conditions,
        step,
        None,
    )
    .map_err(input)?;
    let period = std::f64::consts::TAU / epicyclic.abs();
    let mut sim = prepared.simulation;
    let numerical = |e: rolldyn_dynamics::DynError| match e {
        rolldyn_dynamics::DynError::Interrupted { .. } => FatigueError::Interrupted,
        e => FatigueError::Numerical(e.to_string()),
    };
    let settle = settings.settle_revolutions as f64 * period;
    let mut watched = |t: f64| watch(t, settle);
    let mut checkpoints = checkpoints;
    if let Some(bytes) = checkpoints.as_mut().and_then(|c| c.start.take()) {
        sim.restore(&bytes)
            .map_err(|e| FatigueError::Input(format!("the stored dynamics: {e}")))?;
    }
    // revolution by revolution: a run split into pieces is the same run bit for bit
    while sim.time() < settle {
        let target = (sim.time() + period).min(settle);
        sim.run_until_interruptible(
            target,
            &mut rolldyn_dynamics::output::NullSink,
            &mut watched,
        )
        .map_err(numerical)?;
        if let Some(c) = checkpoints.as_mut() {
            (c.store)(&sim.checkpoint()).map_err(FatigueError::Numerical)?;
        }
    }
    let mut recorder = CageLoadRecorder::default();
    let mut end = settle;
    let sets = loop {
        end += 0.25 * period;
        sim.run_until_interruptible(end, &mut recorder, &mut watched)
            .map_err(numerical)?;
        match recorder.last_revolution() {
            Ok(sets) => break sets,
            Err(e) if end > settle + 3.0 * period => return Err(FatigueError::Numerical(e)),
            Err(_) => {}
        }
    };
    let turned = sets.last().map_or(0.0, |s| s.time_s) - sets.first().map_or(0.0, |s| s.time_s);
    let cage_speed = std::f64::consts::TAU * (1.0 - 1.0 / sets.len() as f64) / turned.max(1e-12);
    let export = CageLoadExport {
        header: export_header(
            &model.source.file,
            &cage,
            CageMaterial::of(bearing),
            bearing.roller.bar_contact_half_span(),
            cage_speed,
        ),
        sets,
    };
    let maxima = recorder.maxima();
    Ok((export, maxima, cage))
}

/// Why a fatigue evaluation failed: bad input (exit 2) or a numerical failure (exit 1).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FatigueError {
    #[error("{0}")]
    Input(String),
    #[error("{0}")]
    Numerical(String),
    /// The caller stopped the dynamics run.
    #[error("the dynamics run was interrupted")]
    Interrupted,
}
