//! Life: rating life of a cylindrical or double-row tapered roller bearing (theory "Rating
//! life"): ISO 281:2007 C_r, P, L10 and L_nm = a1 a_ISO L10 (κ from the model's oil, e_C from
//! the contamination level, C_u from C0r), ISO 76 C0r and s0, and the ISO/TS 16281 reference
//! rating life L10r of each ring and the bearing from the lamina (slice) loads of the
//! quasi-static load distribution with its clearance, misalignment and roller profile. A duty
//! cycle of several operating points is combined by Palmgren–Miner.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::loads::{LoadsRequest, load_case};
use crate::operating::{LoadDirectionName, Operating};
use crate::table::{Table, Tables};
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing, DoubleRowTaperedBearing};
use rolldyn_lubrication::Lubricant;
use rolldyn_model::{Model, Temperatures};
use rolldyn_quasistatic::tapered::{TaperedLoadSettings, TiltCondition, solve_tapered_loads};
use rolldyn_quasistatic::{
    LoadCase, LoadModel, QsError, QuasiStaticOptions, operating_geometry, rating_geometry,
};
use rolldyn_rating::duty::{DutyCondition, palmgren_miner};
use rolldyn_rating::iso76;
use rolldyn_rating::iso281::{self, ContaminationLevel, EquivalentLoad};
use rolldyn_rating::ts16281::{self, RingMotion};
use rolldyn_rating::{RatingError, RollerBearingGeometry};
use rolldyn_setup::FlagValues;
use rolldyn_setup::quasi_static::{QuasiStaticOverrides, RacewayFriction, quasi_static_conditions};
use rolldyn_units::{AngularSpeed, Force, KinematicViscosity, Length, Quantity, Temperature};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;

/// Reliability of the basic rating life (ISO 281: L10, a1 = 1).
const BASIC_RELIABILITY_PERCENT: f64 = 90.0;

/// Contamination level taken when the request names none.
const DEFAULT_CONTAMINATION: ContaminationLevel = ContaminationLevel::NormalCleanliness;

/// One operating condition of a duty cycle: its share of the time and the values that differ
/// from the request's operating point (each `None` keeps it).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DutyRow {
    /// Share of the operating time: fractions or hours, normalised by their sum.
    pub time: f64,
    pub speed: Option<Quantity<AngularSpeed>>,
    pub radial_load: Option<Quantity<Force>>,
    pub axial_load: Option<Quantity<Force>>,
    pub oil_temperature: Option<Quantity<Temperature>>,
}

impl std::str::FromStr for DutyRow {
    type Err = String;
    /// A row as on the command line: `time=0.3,speed=5000rpm,radial-load=15kN` (keys `time`,
    /// `speed`, `radial-load`, `axial-load`, `oil-temperature`; `time` required).
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        /// A quantity with its unit (a bare number is refused, as on every dimensional flag).
        fn quantity<D: rolldyn_units::Dim>(v: &str) -> Result<Option<Quantity<D>>, String> {
            Quantity::<D>::parse(v).map(Some).map_err(|e| e.to_string())
        }
        let mut row = DutyRow {
            time: f64::NAN,
            ..DutyRow::default()
        };
        for part in text.split(',') {
            let (key, value) = part
                .split_once('=')
                .ok_or_else(|| format!("'{part}': expected key=value, e.g. time=0.3"))?;
            let value = value.trim();
            match key.trim() {
                "time" => {
                    row.time = value
                        .parse()
                        .map_err(|_| format!("time={value}: expected a number (share or hours)"))?
                }
                "speed" => row.speed = quantity(value)?,
                "radial-load" => row.radial_load = quantity(value)?,
                "axial-load" => row.axial_load = quantity(value)?,
                "oil-temperature" => row.oil_temperature = quantity(value)?,
                other => {
                    return Err(format!(
                        "'{other}': keys are time, speed, radial-load, axial-load, oil-temperature"
                    ));
                }
            }
        }
        if row.time.is_nan() {
            return Err(format!(
                "'{text}': give time=… (a share of the time or hours)"
            ));
        }
        Ok(row)
    }
}

/// A rating-life analysis.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LifeRequest {
    /// Overrides of the model's `[operating]` and `[misalignment]` (speed, outer speed, radial
    /// and axial load, load direction, oil temperature, misalignment).
    pub operating: Operating,
    /// Diametral operating clearance of a cylindrical bearing, replacing the one derived from
    /// the model's clearance, fits and temperatures (negative: preload).
    pub clearance: Option<Quantity<Length>>,
    /// Contamination level of ISO 281 Table 13 (default normal cleanliness, named in the
    /// result); e_C is the low end of its range.
    pub contamination: Option<ContaminationLevel>,
    /// e_C given directly (0…1), instead of a level.
    pub contamination_factor: Option<f64>,
    /// Reliability [%] of the modified life, one of ISO 281 Table 12 (default 90).
    pub reliability: Option<f64>,
    /// Kinematic viscosity of the oil at its operating temperature, replacing the model oil's.
    pub viscosity: Option<Quantity<KinematicViscosity>>,
    /// Duty cycle: one life per row, combined by Palmgren–Miner; empty = the operating point.
    pub duty: Vec<DutyRow>,
}

/// The ratings of the bearing and the dimensions they come from.
#[derive(Clone, Debug, Serialize)]
pub struct Ratings {
    /// D_we, L_we, α, D_pw, Z, i (ISO 281 §3).
    pub roller_diameter_m: f64,
    pub effective_length_m: f64,
    pub contact_angle_rad: f64,
    pub pitch_diameter_m: f64,
    pub rollers_per_row: usize,
    pub rows: usize,
    /// f_c of ISO 281 Table 7.
    pub fc: f64,
    /// Basic dynamic radial load rating C_r (ISO 281 §7.1) [N].
    pub dynamic_n: f64,
    /// Basic static radial load rating C0r (ISO 76) [N].
    pub static_n: f64,
    /// Fatigue load limit C_u (ISO 281 Annex B, simplified) [N].
    pub fatigue_limit_n: f64,
    /// Lamina length and the lamina ratings on the inner and outer ring (ISO/TS 16281) [m, N].
    pub lamina_length_m: f64,
    pub lamina_inner_n: f64,
    pub lamina_outer_n: f64,
}

/// The lives of one operating condition.
#[derive(Clone, Debug, Serialize)]
pub struct ConditionLife {
    /// Share of the time (normalised).
    pub time_share: f64,
    pub inner_speed_rad_s: f64,
    pub outer_speed_rad_s: f64,
    pub radial_load_n: f64,
    pub axial_load_n: f64,
    /// The equivalent dynamic load P and its X, Y, e (ISO 281 §7.2).
    pub equivalent_load: EquivalentLoad,
    /// Equivalent static load P0r (ISO 76) and s0 = C0r/P0r.
    pub static_load_n: f64,
    pub s0: f64,
    /// L10 = (C_r/P)^{10/3} [revolutions, h].
    pub l10_rev: f64,
    pub l10_h: f64,
    pub oil_temperature_k: f64,
    /// Operating kinematic viscosity ν and reference viscosity ν1 (ISO 281 §9.3.3) [m²/s].
    pub viscosity_m2_s: f64,
    pub nu1_m2_s: f64,
    pub kappa: f64,
    /// e_C C_u / P.
    pub ec_cu_over_p: f64,
    /// a_ISO (`None` when κ < 0.1 lies outside ISO 281) and whether it reached 50.
    pub a_iso: Option<f64>,
    pub a_iso_capped: bool,
    /// L_nm = a1 a_ISO L10 [revolutions, h].
    pub l_nm_rev: Option<f64>,
    pub l_nm_h: Option<f64>,
    /// Diametral operating clearance of a cylindrical bearing; the axial clearance of a
    /// tapered one [m].
    pub clearance_m: f64,
    /// Which clearance `clearance_m` is.
    pub clearance_kind: &'static str,
    /// Misalignment of the inner ring imposed on the load distribution (`None`: a tapered
    /// bearing free of moment) [rad].
    pub misalignment_rad: Option<f64>,
    /// ISO/TS 16281 reference rating lives of the inner ring, the outer ring and the bearing
    /// [revolutions], the bearing's in hours.
    pub l10r_inner_rev: f64,
    pub l10r_outer_rev: f64,
    pub l10r_rev: f64,
    pub l10r_h: f64,
    /// Why a value above is `null` (docs/outputs.md): an infinite life or s0 is unlimited (no
    /// load in the condition); absent when every value is finite.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub non_finite: BTreeMap<&'static str, String>,
    /// Lamina loads: per (row, roller, lamina), inner and outer ring [N].
    #[serde(skip)]
    laminae: LaminaLoads,
}

/// A combined life of the duty cycle.
#[derive(Clone, Debug, Serialize)]
pub struct DutyLives {
    pub l10_rev: f64,
    pub l10_h: f64,
    pub l_nm_rev: Option<f64>,
    pub l_nm_h: Option<f64>,
    pub l10r_rev: f64,
    pub l10r_h: f64,
    /// Why a value above is `null` (docs/outputs.md): an infinite life or s0 is unlimited (no
    /// load in the condition); absent when every value is finite.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub non_finite: BTreeMap<&'static str, String>,
}

/// The rating lives of the bearing.
#[derive(Clone, Debug, Serialize)]
pub struct LifeResult {
    pub model: String,
    /// `cylindrical` or `double-row tapered`.
    pub kind: &'static str,
    pub ratings: Ratings,
    pub reliability_percent: f64,
    pub a1: f64,
    /// The contamination level (`None`: e_C given directly) and e_C.
    pub contamination: Option<ContaminationLevel>,
    pub e_c: f64,
    /// The oil whose viscosity gives κ.
    pub oil: String,
    /// Each default that stood in for an input and changes the answer, named.
    pub defaults: Vec<String>,
    /// The smallest s0 of the conditions.
    pub s0: f64,
    /// The lives: of the only condition, or of the duty cycle combined by Palmgren–Miner.
    pub lives: DutyLives,
    /// One entry per condition (per duty row).
    pub conditions: Vec<ConditionLife>,
    /// Why a value above is `null` (docs/outputs.md): an infinite life or s0 is unlimited (no
    /// load in the condition); absent when every value is finite.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub non_finite: BTreeMap<&'static str, String>,
}

/// The `non_finite` reasons of `values` (JSON key, value): +∞ is an unlimited life or safety
/// (no load), anything else not finite the policy's default reason.
fn non_finite_reasons(values: &[(&'static str, Option<f64>)]) -> BTreeMap<&'static str, String> {
    values
        .iter()
        .filter_map(|&(key, value)| Some((key, value?)))
        .filter(|(_, value)| !value.is_finite())
        .map(|(key, value)| {
            let reason = if value == f64::INFINITY {
                "unlimited: no load in this condition".to_string()
            } else {
                rolldyn_output::default_reason(value).to_string()
            };
            (key, reason)
        })
        .collect()
}

/// The lamina loads of one condition, flattened: index (row, roller, lamina).
#[derive(Clone, Debug, Default)]
struct LaminaLoads {
    row: Vec<i64>,
    roller: Vec<i64>,
    lamina: Vec<i64>,
    inner_n: Vec<f64>,
    outer_n: Vec<f64>,
}

/// The analysis.
pub struct Life;

impl Analysis for Life {
    const NAME: &'static str = "life";
    type Request = LifeRequest;
    type Result = LifeResult;

    fn run(request: &LifeRequest, context: &Context<'_>) -> Result<LifeResult, Failure> {
        let model = context.model.load()?;
        let bearing = Bearing::of(&model)?;
        let geometry = bearing.rating_geometry();
        let rating = |e: RatingError| Failure::Input(format!("{}: {e}", model.source.file));
        let dynamic = iso281::dynamic_radial_rating(&geometry).map_err(rating)?;
        let fc = iso281::geometry_factor(geometry.gamma()).map_err(rating)?;
        let static_n = iso76::static_radial_rating(&geometry);
        let dpw = geometry.pitch_diameter_m;
        let lamina_length_m = bearing.lamina_length();
        let lamina = ts16281::lamina_ratings(&geometry, lamina_length_m);
        let ratings = Ratings {
            roller_diameter_m: geometry.roller_diameter_m,
            effective_length_m: geometry.effective_length_m,
            contact_angle_rad: geometry.contact_angle_rad,
            pitch_diameter_m: dpw,
            rollers_per_row: geometry.rollers_per_row,
            rows: geometry.rows,
            fc,
            dynamic_n: dynamic,
            static_n,
            fatigue_limit_n: iso281::fatigue_load_limit(static_n, dpw),
            lamina_length_m,
            lamina_inner_n: lamina.inner_n,
            lamina_outer_n: lamina.outer_n,
        };

        let mut defaults = Vec::new();
        let reliability_percent = request.reliability.unwrap_or_else(|| {
            defaults.push(format!(
                "reliability {BASIC_RELIABILITY_PERCENT} % (a1 = 1): no --reliability given"
            ));
            BASIC_RELIABILITY_PERCENT
        });
        let a1 = iso281::reliability_factor(reliability_percent)
            .map_err(|e| Failure::Input(format!("--reliability: {e}")))?;
        let (contamination, e_c) = contamination(request, dpw, &mut defaults)?;
        let lubricant = model.lubrication.as_ref().map(|l| &l.oil).ok_or_else(|| {
            Failure::Input(
                model
                    .source
                    .error("lubricant", "life needs a [lubricant] section (κ = ν/ν1)")
                    .to_string(),
            )
        })?;

        let rows: Vec<DutyRow> = if request.duty.is_empty() {
            vec![DutyRow {
                time: 1.0,
                ..DutyRow::default()
            }]
        } else {
            request.duty.clone()
        };
        let total_time: f64 = rows.iter().map(|r| r.time).sum();
        if rows.iter().any(|r| !(r.time >= 0.0 && r.time.is_finite())) || !(total_time > 0.0) {
            return Err(Failure::Input(
                "--duty: every time share must be ≥ 0 and their sum positive".into(),
            ));
        }
        let factors = Factors {
            a1,
            e_c,
            oil: lubricant,
            ratings: &ratings,
            geometry: &geometry,
        };
        let mut conditions = Vec::with_capacity(rows.len());
        for (index, row) in rows.iter().enumerate() {
            let in_row = |failure| in_duty_row(request, index, failure);
            let point = OperatingPoint::of(request, row, &model).map_err(in_row)?;
            let mut life = condition_life(&bearing, &point, request, &factors, &model, context)
                .map_err(in_row)?;
            life.time_share = row.time / total_time;
            conditions.push(life);
        }
        let lives = combined(&conditions)?;
        let s0 = conditions
            .iter()
            .map(|c| c.s0)
            .fold(f64::INFINITY, f64::min);
        Ok(LifeResult {
            model: model.bearing.name().to_string(),
            kind: bearing.kind(),
            s0,
            ratings,
            reliability_percent,
            a1,
            contamination,
            e_c,
            oil: lubricant.name.clone(),
            defaults,
            lives,
            conditions,
            non_finite: non_finite_reasons(&[("s0", Some(s0))]),
        })
    }
}

/// The contamination level and e_C of the request (a level, a factor, or the default level,
/// which is named in `defaults`).
fn contamination(
    request: &LifeRequest,
    dpw: f64,
    defaults: &mut Vec<String>,
) -> Result<(Option<ContaminationLevel>, f64), Failure> {
    match (request.contamination, request.contamination_factor) {
        (Some(_), Some(_)) => Err(Failure::Input(
            "--contamination, --contamination-factor: give one".into(),
        )),
        (None, Some(e)) if (0.0..=1.0).contains(&e) => Ok((None, e)),
        (None, Some(e)) => Err(Failure::Input(format!(
            "--contamination-factor: {e} outside 0…1 (ISO 281 Table 13)"
        ))),
        (level, None) => {
            let level = level.unwrap_or_else(|| {
                let (lo, hi) = DEFAULT_CONTAMINATION.factor_range(dpw);
                defaults.push(format!(
                    "contamination {} (ISO 281 Table 13, e_C {lo}…{hi}, taken {lo}): no --contamination given",
                    DEFAULT_CONTAMINATION.name()
                ));
                DEFAULT_CONTAMINATION
            });
            Ok((Some(level), iso281::contamination_factor(level, dpw)))
        }
    }
}

/// The bearing of the model, by kind.
enum Bearing<'m> {
    Cylindrical(&'m CylindricalRollerBearing),
    Tapered(&'m DoubleRowTaperedBearing),
}

impl<'m> Bearing<'m> {
    fn of(model: &'m Model) -> Result<Self, Failure> {
        match &model.bearing {
            BearingModel::Cylindrical(b) => Ok(Self::Cylindrical(b)),
            BearingModel::Tapered(b) => Ok(Self::Tapered(b)),
            BearingModel::RollerRaceway(_) => Err(Failure::Input(
                model
                    .source
                    .error(
                        "bearing.kind",
                        "`life` rates a cylindrical or a double-row tapered bearing, not a single roller–raceway pair",
                    )
                    .to_string(),
            )),
        }
    }

    fn kind(&self) -> &'static str {
        match self {
            Self::Cylindrical(_) => "cylindrical",
            Self::Tapered(_) => "double-row tapered",
        }
    }

    /// D_we, L_we, α, D_pw, Z, i: a tapered bearing's α is its cup angle, D_we the mean roller
    /// diameter and L_we the working length between the end chamfers.
    fn rating_geometry(&self) -> RollerBearingGeometry {
        match self {
            Self::Cylindrical(b) => rating_geometry(b),
            Self::Tapered(b) => RollerBearingGeometry {
                roller_diameter_m: b.roller.mean_diameter,
                effective_length_m: 2.0 * b.roller.working_half_length(),
                contact_angle_rad: b.cup_angle(),
                pitch_diameter_m: b.pitch_diameter,
                rollers_per_row: b.rollers_per_row,
                rows: 2,
            },
        }
    }

    /// Length of one slice of the load distribution: an ISO/TS 16281 lamina.
    fn lamina_length(&self) -> f64 {
        match self {
            Self::Cylindrical(b) => b.roller.length / b.roller.slice_count.max(1) as f64,
            Self::Tapered(b) => {
                2.0 * b.roller.working_half_length() / b.roller.slice_count.max(1) as f64
            }
        }
    }
}

/// One operating point: the model's, overridden by the request, overridden by a duty row.
struct OperatingPoint {
    inner_speed: f64,
    outer_speed: f64,
    radial_load: f64,
    axial_load: f64,
    oil_temperature: f64,
    load_rotates: bool,
    /// The request's overrides with the row's applied (for the load-distribution set-ups).
    operating: Operating,
}

/// A bad-input failure of duty row `index` (0-based) named by its `--duty` row: the row's values
/// are checked like the flags of the same name, whose names the message keeps.
fn in_duty_row(request: &LifeRequest, index: usize, failure: Failure) -> Failure {
    match failure {
        Failure::Input(m) if !request.duty.is_empty() => {
            Failure::Input(format!("--duty row {}: {m}", index + 1))
        }
        other => other,
    }
}

impl OperatingPoint {
    fn of(request: &LifeRequest, row: &DutyRow, model: &Model) -> Result<Self, Failure> {
        let mut operating = request.operating.clone();
        operating.speed = row.speed.or(operating.speed);
        operating.radial_load = row.radial_load.or(operating.radial_load);
        operating.axial_load = row.axial_load.or(operating.axial_load);
        operating.oil_temperature = row.oil_temperature.or(operating.oil_temperature);
        let o = operating.overrides();
        FlagValues {
            speed: o.speed,
            outer_speed: o.outer_speed,
            radial_load: o.radial_load,
            oil_temperature: o.oil_temperature,
        }
        .check(model)?;
        let op = &model.operating;
        let missing = |flag: &str, key: &str| {
            Failure::Input(
                model
                    .source
                    .error(key, format!("life needs it: give {flag} or {key}"))
                    .to_string(),
            )
        };
        Ok(Self {
            inner_speed: o
                .speed
                .or(op.inner_speed)
                .ok_or_else(|| missing("--speed", "operating.inner_speed"))?,
            outer_speed: o.outer_speed.or(op.outer_speed).unwrap_or(0.0),
            radial_load: o
                .radial_load
                .or(op.radial_load)
                .ok_or_else(|| missing("--radial-load", "operating.radial_load"))?,
            axial_load: o.axial_load.or(op.axial_load).unwrap_or(0.0),
            oil_temperature: o
                .oil_temperature
                .or(op.temperatures.oil)
                .ok_or_else(|| missing("--oil-temperature", "operating.temperatures.oil"))?,
            load_rotates: match operating.load_direction {
                Some(LoadDirectionName::Rotating) => true,
                Some(LoadDirectionName::Fixed) => false,
                None => op.load_rotates,
            },
            operating,
        })
    }

    /// Speed of the rotating ring relative to the other [rad/s].
    fn relative_speed(&self) -> f64 {
        (self.inner_speed - self.outer_speed).abs()
    }

    /// How a ring turning at `speed` moves relative to the load (which turns with the inner
    /// ring or stands still).
    fn motion(&self, speed: f64) -> RingMotion {
        let load_speed = if self.load_rotates {
            self.inner_speed
        } else {
            0.0
        };
        if speed == load_speed {
            RingMotion::StationaryRelativeToLoad
        } else {
            RingMotion::RotatingRelativeToLoad
        }
    }
}

/// What every condition shares: a1, e_C, the oil, the ratings.
struct Factors<'a> {
    a1: f64,
    e_c: f64,
    oil: &'a Lubricant,
    ratings: &'a Ratings,
    geometry: &'a RollerBearingGeometry,
}

/// The lives of one operating point.
fn condition_life(
    bearing: &Bearing<'_>,
    point: &OperatingPoint,
    request: &LifeRequest,
    factors: &Factors<'_>,
    model: &Model,
    context: &Context<'_>,
) -> Result<ConditionLife, Failure> {
    let g = factors.geometry;
    let r = factors.ratings;
    let alpha = g.contact_angle_rad;
    if alpha == 0.0 && point.axial_load != 0.0 {
        context.observer.warning(&format!(
            "axial load {:.0} N: ISO 281 rates a cylindrical bearing for radial load only (P = F_r); the rib load is not in its life",
            point.axial_load
        ));
    }
    let equivalent_load =
        iso281::equivalent_dynamic_load(point.radial_load, point.axial_load, alpha, g.rows);
    let p = equivalent_load.load_n;
    let static_load_n =
        iso76::equivalent_static_load(point.radial_load, point.axial_load, alpha, g.rows);
    let speed = point.relative_speed();
    let l10_rev = iso281::basic_rating_life(r.dynamic_n, p);

    let viscosity_m2_s = match request.viscosity {
        Some(v) => v.si(),
        None => factors
            .oil
            .kinematic_viscosity(point.oil_temperature)
            .map_err(|e| {
                Failure::Input(model.source.error("lubricant", e.to_string()).to_string())
            })?,
    };
    let nu1_m2_s = iso281::reference_viscosity(speed, g.pitch_diameter_m)
        .map_err(|e| Failure::Input(format!("--speed: {e}")))?;
    let kappa = viscosity_m2_s / nu1_m2_s;
    let ec_cu_over_p = if p > 0.0 {
        factors.e_c * r.fatigue_limit_n / p
    } else {
        f64::INFINITY
    };
    let modification = match iso281::life_modification_factor(kappa, ec_cu_over_p) {
        Ok(m) => Some(m),
        Err(e) => {
            context
                .observer
                .warning(&format!("{e}: no modified life L_nm"));
            None
        }
    };
    let l_nm_rev = modification.map(|m| factors.a1 * m.a_iso * l10_rev);

    let distribution = match bearing {
        Bearing::Cylindrical(b) => cylindrical_laminae(b, point, request, model, context)?,
        Bearing::Tapered(b) => tapered_laminae(b, point, model)?,
    };
    let (l10r_inner_rev, l10r_outer_rev) = ring_lives(&distribution.laminae, point, r);
    let l10r_rev = ts16281::bearing_life(l10r_inner_rev, l10r_outer_rev);
    let mut life = ConditionLife {
        time_share: 1.0,
        inner_speed_rad_s: point.inner_speed,
        outer_speed_rad_s: point.outer_speed,
        radial_load_n: point.radial_load,
        axial_load_n: point.axial_load,
        equivalent_load,
        static_load_n,
        s0: iso76::static_safety(r.static_n, static_load_n),
        l10_rev,
        l10_h: iso281::hours(l10_rev, speed),
        oil_temperature_k: point.oil_temperature,
        viscosity_m2_s,
        nu1_m2_s,
        kappa,
        ec_cu_over_p,
        a_iso: modification.map(|m| m.a_iso),
        a_iso_capped: modification.is_some_and(|m| m.capped),
        l_nm_rev,
        l_nm_h: l_nm_rev.map(|l| iso281::hours(l, speed)),
        clearance_m: distribution.clearance_m,
        clearance_kind: distribution.clearance_kind,
        misalignment_rad: distribution.misalignment_rad,
        l10r_inner_rev,
        l10r_outer_rev,
        l10r_rev,
        l10r_h: iso281::hours(l10r_rev, speed),
        non_finite: BTreeMap::new(),
        laminae: distribution.laminae,
    };
    life.non_finite = non_finite_reasons(&[
        ("s0", Some(life.s0)),
        ("l10_rev", Some(life.l10_rev)),
        ("l10_h", Some(life.l10_h)),
        ("kappa", Some(life.kappa)),
        ("ec_cu_over_p", Some(life.ec_cu_over_p)),
        ("a_iso", life.a_iso),
        ("l_nm_rev", life.l_nm_rev),
        ("l_nm_h", life.l_nm_h),
        ("l10r_inner_rev", Some(life.l10r_inner_rev)),
        ("l10r_outer_rev", Some(life.l10r_outer_rev)),
        ("l10r_rev", Some(life.l10r_rev)),
        ("l10r_h", Some(life.l10r_h)),
    ]);
    Ok(life)
}

/// A load distribution's lamina loads and what it was solved with.
struct Distribution {
    laminae: LaminaLoads,
    clearance_m: f64,
    clearance_kind: &'static str,
    misalignment_rad: Option<f64>,
}

/// Lamina loads of a cylindrical bearing: the frictionless slice load distribution
/// (`rolldyn_quasistatic::load_distribution`) at the operating clearance the quasi-static
/// model derives (or the request's), the misalignment in the plane of the load, no
/// centrifugal force (the ratings' static load distribution).
fn cylindrical_laminae(
    bearing: &CylindricalRollerBearing,
    point: &OperatingPoint,
    request: &LifeRequest,
    model: &Model,
    context: &Context<'_>,
) -> Result<Distribution, Failure> {
    let qs = |e: QsError| qs_failure(model, e);
    let clearance_m = match request.clearance {
        Some(c) => c.si(),
        None => {
            let conditions = quasi_static_conditions(
                model,
                &QuasiStaticOverrides {
                    speed: Some(point.inner_speed),
                    outer_speed: Some(point.outer_speed),
                    radial_load: Some(point.radial_load),
                    temperatures: Temperatures {
                        oil: Some(point.oil_temperature),
                        ..Temperatures::default()
                    },
                    friction: RacewayFriction::Seed001,
                },
            )?;
            let cage = bearing.epicyclic_cage_speed(point.inner_speed, point.outer_speed);
            let geometry = operating_geometry(bearing, &conditions, cage);
            for w in &geometry.warnings {
                context.observer.warning(w);
            }
            geometry.clearance.operating_m
        }
    };
    let misalignment_rad = point
        .operating
        .misalignment
        .map_or(bearing.misalignment.inner_ring_tilt, |m| m.si());
    let options = QuasiStaticOptions::default();
    let load_model = LoadModel::new(bearing, options.slice_law).map_err(qs)?;
    let case = LoadCase {
        radial_load_n: point.radial_load,
        diametral_clearance_m: clearance_m,
        misalignment_rad,
        misalignment_azimuth_rad: 0.0,
        centrifugal_force_n: 0.0,
        roller_phase_rad: 0.0,
    };
    let solved = load_model.solve(&case, None, &options).map_err(qs)?;
    let mut laminae = LaminaLoads::default();
    for (j, roller) in solved.rollers.iter().enumerate() {
        let [inner, outer] = load_model.slice_loads(roller);
        laminae.push(0, j, &inner, &outer);
    }
    Ok(Distribution {
        laminae,
        clearance_m,
        clearance_kind: "diametral operating",
        misalignment_rad: Some(misalignment_rad),
    })
}

/// Lamina loads of a double-row tapered bearing: the slice loads of its quasi-static load
/// distribution (`rolldyn_quasistatic::tapered`, as `rolldyn loads`) at rest (no centrifugal
/// force: the ratings' static load distribution).
fn tapered_laminae(
    bearing: &DoubleRowTaperedBearing,
    point: &OperatingPoint,
    model: &Model,
) -> Result<Distribution, Failure> {
    if point.outer_speed != 0.0 {
        return Err(Failure::Input(
            "--outer-speed: the tapered load distribution has a fixed cup".into(),
        ));
    }
    let operating = Operating {
        speed: None,
        outer_speed: None,
        load_direction: None,
        oil_temperature: None,
        radial_load: Some(Quantity::from_si(point.radial_load)),
        axial_load: Some(Quantity::from_si(point.axial_load)),
        ..point.operating.clone()
    };
    let mut case = load_case(
        &LoadsRequest {
            operating,
            ..LoadsRequest::default()
        },
        model,
    )?;
    // at rest: no centrifugal force in the ratings' load distribution
    case.inner_speed_rad_s = 0.0;
    let solved = solve_tapered_loads(bearing, &case, &TaperedLoadSettings::default())
        .map_err(|e| qs_failure(model, e))?;
    let mut laminae = LaminaLoads::default();
    for (roller, [cone, cup]) in solved.rollers.iter().zip(&solved.slice_loads_n) {
        laminae.push(roller.row, roller.index, cone, cup);
    }
    Ok(Distribution {
        laminae,
        clearance_m: bearing.axial_clearance,
        clearance_kind: "axial (mounted)",
        misalignment_rad: match case.tilt {
            TiltCondition::Imposed(t) => Some(t),
            TiltCondition::Moment(_) => None,
        },
    })
}

impl LaminaLoads {
    fn push(&mut self, row: usize, roller: usize, inner: &[f64], outer: &[f64]) {
        for (k, (qi, qe)) in inner.iter().zip(outer).enumerate() {
            self.row.push(row as i64);
            self.roller.push(roller as i64);
            self.lamina.push(k as i64);
            self.inner_n.push(*qi);
            self.outer_n.push(*qe);
        }
    }

    /// The loads of each (row, lamina) over the row's rollers, for the inner and outer ring.
    fn by_row_and_lamina(&self) -> Vec<(Vec<f64>, Vec<f64>)> {
        let mut keys: Vec<(i64, i64)> = self
            .row
            .iter()
            .copied()
            .zip(self.lamina.iter().copied())
            .collect();
        keys.sort_unstable();
        keys.dedup();
        keys.iter()
            .map(|key| {
                let at = (0..self.row.len()).filter(|&i| (self.row[i], self.lamina[i]) == *key);
                at.map(|i| (self.inner_n[i], self.outer_n[i])).unzip()
            })
            .collect()
    }
}

/// ISO/TS 16281 lives of the inner and the outer ring from the lamina loads [revolutions].
fn ring_lives(laminae: &LaminaLoads, point: &OperatingPoint, ratings: &Ratings) -> (f64, f64) {
    let inner_motion = point.motion(point.inner_speed);
    let outer_motion = point.motion(point.outer_speed);
    let (inner, outer): (Vec<f64>, Vec<f64>) = laminae
        .by_row_and_lamina()
        .iter()
        .map(|(qi, qe)| {
            (
                ts16281::equivalent_lamina_load(qi, inner_motion),
                ts16281::equivalent_lamina_load(qe, outer_motion),
            )
        })
        .unzip();
    (
        ts16281::ring_life(ratings.lamina_inner_n, &inner),
        ts16281::ring_life(ratings.lamina_outer_n, &outer),
    )
}

/// The conditions' lives combined by Palmgren–Miner (one condition: its own).
fn combined(conditions: &[ConditionLife]) -> Result<DutyLives, Failure> {
    let miner = |life: &dyn Fn(&ConditionLife) -> f64| {
        palmgren_miner(
            &conditions
                .iter()
                .map(|c| DutyCondition {
                    time_weight: c.time_share,
                    speed_rad_s: (c.inner_speed_rad_s - c.outer_speed_rad_s).abs(),
                    life_revolutions: life(c),
                })
                .collect::<Vec<_>>(),
        )
        .ok_or_else(|| Failure::Input("--duty: the cycle makes no revolutions".into()))
    };
    let l10 = miner(&|c| c.l10_rev)?;
    let l10r = miner(&|c| c.l10r_rev)?;
    let l_nm = if conditions.iter().all(|c| c.l_nm_rev.is_some()) {
        Some(miner(&|c| c.l_nm_rev.unwrap_or(f64::NAN))?)
    } else {
        None
    };
    let non_finite = non_finite_reasons(&[
        ("l10_rev", Some(l10.revolutions)),
        ("l10_h", Some(l10.hours)),
        ("l_nm_rev", l_nm.map(|l| l.revolutions)),
        ("l_nm_h", l_nm.map(|l| l.hours)),
        ("l10r_rev", Some(l10r.revolutions)),
        ("l10r_h", Some(l10r.hours)),
    ]);
    Ok(DutyLives {
        l10_rev: l10.revolutions,
        l10_h: l10.hours,
        l_nm_rev: l_nm.map(|l| l.revolutions),
        l_nm_h: l_nm.map(|l| l.hours),
        l10r_rev: l10r.revolutions,
        l10r_h: l10r.hours,
        non_finite,
    })
}

fn qs_failure(model: &Model, e: QsError) -> Failure {
    match e {
        QsError::Contact(_) | QsError::NotConverged { .. } => Failure::Run(e.to_string()),
        _ => Failure::Input(model.source.error("", e.to_string()).to_string()),
    }
}

impl Tables for LifeResult {
    /// `conditions`: one row per operating condition; `slices`: the lamina loads of every
    /// condition (row, roller, lamina).
    fn tables(&self) -> Vec<Table> {
        let c = &self.conditions;
        let col = |f: &dyn Fn(&ConditionLife) -> f64| c.iter().map(f).collect::<Vec<f64>>();
        let nan = f64::NAN;
        let conditions = Table::new("conditions")
            .integer("condition", (0..c.len() as i64).collect())
            .real("time_share", col(&|x| x.time_share))
            .real(
                "inner_speed_rpm",
                col(&|x| x.inner_speed_rad_s * 30.0 / std::f64::consts::PI),
            )
            .real("radial_load_n", col(&|x| x.radial_load_n))
            .real("axial_load_n", col(&|x| x.axial_load_n))
            .real("p_n", col(&|x| x.equivalent_load.load_n))
            .real("s0", col(&|x| x.s0))
            .real("l10_h", col(&|x| x.l10_h))
            .real("kappa", col(&|x| x.kappa))
            .real("a_iso", col(&|x| x.a_iso.unwrap_or(nan)))
            .real("l_nm_h", col(&|x| x.l_nm_h.unwrap_or(nan)))
            .real(
                "l10r_inner_h",
                col(&|x| {
                    iso281::hours(
                        x.l10r_inner_rev,
                        (x.inner_speed_rad_s - x.outer_speed_rad_s).abs(),
                    )
                }),
            )
            .real(
                "l10r_outer_h",
                col(&|x| {
                    iso281::hours(
                        x.l10r_outer_rev,
                        (x.inner_speed_rad_s - x.outer_speed_rad_s).abs(),
                    )
                }),
            )
            .real("l10r_h", col(&|x| x.l10r_h));
        let mut slices = Table::new("slices");
        let (mut cond, mut row, mut roller, mut lamina, mut inner, mut outer) =
            (vec![], vec![], vec![], vec![], vec![], vec![]);
        for (k, x) in c.iter().enumerate() {
            let l = &x.laminae;
            cond.extend(std::iter::repeat_n(k as i64, l.row.len()));
            row.extend(&l.row);
            roller.extend(&l.roller);
            lamina.extend(&l.lamina);
            inner.extend(&l.inner_n);
            outer.extend(&l.outer_n);
        }
        slices = slices
            .integer("condition", cond)
            .integer("row", row)
            .integer("roller", roller)
            .integer("lamina", lamina)
            .real("inner_n", inner)
            .real("outer_n", outer);
        vec![conditions, slices]
    }
}

fn kn(n: f64) -> f64 {
    n / 1e3
}

/// Revolutions as 10⁶ revolutions and hours as text.
fn life_text(rev: f64, h: f64) -> String {
    if rev.is_infinite() {
        "unlimited".into()
    } else {
        format!("{:.4} · 10⁶ rev, {:.0} h", rev / 1e6, h)
    }
}

impl fmt::Display for LifeResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.ratings;
        writeln!(
            f,
            "{} — {} roller bearing, rating life",
            self.model, self.kind
        )?;
        writeln!(
            f,
            "  D_we {:.3} mm, L_we {:.3} mm, α {:.3}°, D_pw {:.2} mm, Z {} × {} row(s), f_c {:.2}",
            r.roller_diameter_m * 1e3,
            r.effective_length_m * 1e3,
            r.contact_angle_rad.to_degrees(),
            r.pitch_diameter_m * 1e3,
            r.rollers_per_row,
            r.rows,
            r.fc
        )?;
        writeln!(
            f,
            "  C_r {:.1} kN (ISO 281), C0r {:.1} kN (ISO 76), C_u {:.2} kN",
            kn(r.dynamic_n),
            kn(r.static_n),
            kn(r.fatigue_limit_n)
        )?;
        writeln!(
            f,
            "  reliability {} % (a1 {}), e_C {}{}, oil {}",
            self.reliability_percent,
            self.a1,
            self.e_c,
            self.contamination
                .map_or(String::new(), |c| format!(" ({})", c.name())),
            self.oil
        )?;
        for d in &self.defaults {
            writeln!(f, "  default: {d}")?;
        }
        for (k, c) in self.conditions.iter().enumerate() {
            if self.conditions.len() > 1 {
                writeln!(
                    f,
                    "  condition {k} ({:.1} % of the time)",
                    100.0 * c.time_share
                )?;
            }
            writeln!(
                f,
                "    {:.0} rpm, F_r {:.2} kN, F_a {:.2} kN → P {:.2} kN (X {}, Y {:.3}), P0r {:.2} kN, s0 {:.2}",
                c.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
                kn(c.radial_load_n),
                kn(c.axial_load_n),
                kn(c.equivalent_load.load_n),
                c.equivalent_load.x,
                c.equivalent_load.y,
                kn(c.static_load_n),
                c.s0
            )?;
            writeln!(
                f,
                "    oil {:.1} °C: ν {:.2} mm²/s, ν1 {:.2} mm²/s, κ {:.3}; e_C C_u/P {:.4}, a_ISO {}",
                c.oil_temperature_k - 273.15,
                c.viscosity_m2_s * 1e6,
                c.nu1_m2_s * 1e6,
                c.kappa,
                c.ec_cu_over_p,
                c.a_iso.map_or("—".into(), |a| format!(
                    "{a:.3}{}",
                    if c.a_iso_capped { " (cap)" } else { "" }
                ))
            )?;
            writeln!(f, "    L10   {}", life_text(c.l10_rev, c.l10_h))?;
            if let (Some(rev), Some(h)) = (c.l_nm_rev, c.l_nm_h) {
                writeln!(f, "    L_nm  {}", life_text(rev, h))?;
            }
            writeln!(
                f,
                "    L10r  {} (ISO/TS 16281; inner ring {:.4}, outer ring {:.4} · 10⁶ rev) — {} clearance {:.1} µm, misalignment {}",
                life_text(c.l10r_rev, c.l10r_h),
                c.l10r_inner_rev / 1e6,
                c.l10r_outer_rev / 1e6,
                c.clearance_kind,
                c.clearance_m * 1e6,
                c.misalignment_rad
                    .map_or("free (no moment)".into(), |m| format!(
                        "{:.2}′",
                        m.to_degrees() * 60.0
                    ))
            )?;
        }
        if self.conditions.len() > 1 {
            let l = &self.lives;
            writeln!(f, "  duty cycle (Palmgren–Miner)")?;
            writeln!(f, "    L10   {}", life_text(l.l10_rev, l.l10_h))?;
            if let (Some(rev), Some(h)) = (l.l_nm_rev, l.l_nm_h) {
                writeln!(f, "    L_nm  {}", life_text(rev, h))?;
            }
            writeln!(f, "    L10r  {}", life_text(l.l10r_rev, l.l10r_h))?;
        }
        write!(f, "  s0 {:.2}", self.s0)
    }
}
