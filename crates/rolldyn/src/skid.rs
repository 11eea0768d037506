//! Skid: quasi-static roller and cage skidding (SPEC §5, seed 001) at one operating point, or a
//! sweep over the inner-ring speed, the outer-ring speed or the radial load.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::observer::Progress;
use crate::output::{out_dir, write_csv, write_table_csv};
use crate::table::{Table, Tables};
use rolldyn_model::{Model, Temperatures};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::{QuasiStaticConditions, QuasiStaticOptions, SweepPoint, SweepVariable};
use rolldyn_setup::quasi_static::{
    LandChoice, QuasiStaticOverrides, RacewayFriction, cage_land_model, quasi_static_conditions,
};
use rolldyn_units::{AngularSpeed, Dim, Force, Quantity, QuantityRange, Temperature};
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::marker::PhantomData;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The raceway friction model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum FrictionName {
    /// Muraki EHL traction with the mixed-friction blend (seed 000), rheology from the model.
    #[default]
    Muraki,
    /// Asperity fraction + film shear + flash temperature (seed 001).
    Seed001,
}

/// The cage–guiding-land model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum LandName {
    /// Finite journal bearing (docs/theory.md §7.5).
    #[default]
    Finite,
    /// Short (Ocvirk) journal bearing.
    Short,
}

/// One value or several (a sweep) of a quantity: a number in SI, a text with units — one value,
/// a list `a,b,c` or a range `start..end:step` — or a list of numbers and texts.
#[derive(Clone, Debug, PartialEq)]
pub struct Values<D: Dim>(pub Vec<Quantity<D>>);

impl<D: Dim> Values<D> {
    /// The values, SI.
    pub fn si(&self) -> Vec<f64> {
        self.0.iter().map(|q| q.si()).collect()
    }
}

impl<D: Dim> FromStr for Values<D> {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        QuantityRange::<D>::from_str(text)
            .map(|r| Self(r.values))
            .map_err(|e| e.to_string())
    }
}

impl<'de, D: Dim> Deserialize<'de> for Values<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        struct ValuesVisitor<D>(PhantomData<D>);
        impl<'de, D: Dim> Visitor<'de> for ValuesVisitor<D> {
            type Value = Values<D>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(
                    f,
                    "a number in {}, a text with units (one value, a list a,b,c or a range \
                     start..end:step) or a list of values",
                    D::DIMENSION.si_symbol()
                )
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                if !v.is_finite() {
                    return Err(E::custom(format!("{v} is not a finite number")));
                }
                Ok(Values(vec![Quantity::from_si(v)]))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(Values(vec![Quantity::from_si(v as f64)]))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(Values(vec![Quantity::from_si(v as f64)]))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                v.parse().map_err(E::custom)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut values = Vec::new();
                while let Some(q) = seq.next_element::<Quantity<D>>()? {
                    values.push(q);
                }
                if values.is_empty() {
                    return Err(de::Error::custom("an empty list of values"));
                }
                Ok(Values(values))
            }
        }
        deserializer.deserialize_any(ValuesVisitor(PhantomData))
    }
}

/// The parts whose temperatures can be given.
const PARTS: [&str; 7] = [
    "oil", "inner", "outer", "rollers", "cage", "shaft", "housing",
];

/// Part temperatures (parts not given take the oil temperature): a text
/// `inner=47.3C,outer=43C,cage=45C,oil=45C` or a map `{"inner": "47.3C", "outer": 316.15}`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PartTemperatures(pub Temperatures);

impl PartTemperatures {
    /// Sets part `part` to `t` kelvin (within the plausibility bounds).
    fn set(&mut self, part: &str, t: f64) -> Result<(), String> {
        rolldyn_model::bounds::check_temperature(&format!("--temperatures {part}"), t)
            .map_err(|e| e.to_string())?;
        let parts = &mut self.0;
        let slot = match part {
            "oil" => &mut parts.oil,
            "inner" => &mut parts.inner_ring,
            "outer" => &mut parts.outer_ring,
            "rollers" => &mut parts.rollers,
            "cage" => &mut parts.cage,
            "shaft" => &mut parts.shaft,
            "housing" => &mut parts.housing,
            part => {
                return Err(format!(
                    "unknown part '{part}' (known: {})",
                    PARTS.join(", ")
                ));
            }
        };
        *slot = Some(t);
        Ok(())
    }
}

impl FromStr for PartTemperatures {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let mut parts = Self::default();
        for item in text.split(',') {
            let (part, value) = item
                .split_once('=')
                .ok_or_else(|| format!("'{item}': expected part=temperature, e.g. inner=47.3C"))?;
            let t = Quantity::<Temperature>::parse(value)
                .map_err(|e| e.to_string())?
                .si();
            parts.set(part.trim(), t)?;
        }
        Ok(parts)
    }
}

impl<'de> Deserialize<'de> for PartTemperatures {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct PartsVisitor;
        impl<'de> Visitor<'de> for PartsVisitor {
            type Value = PartTemperatures;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(
                    f,
                    "part temperatures as a text inner=47.3C,outer=43C or a map of {}",
                    PARTS.join(", ")
                )
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                v.parse().map_err(E::custom)
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let mut parts = PartTemperatures::default();
                while let Some((part, t)) = map.next_entry::<String, Quantity<Temperature>>()? {
                    parts.set(&part, t.si()).map_err(de::Error::custom)?;
                }
                Ok(parts)
            }
        }
        deserializer.deserialize_any(PartsVisitor)
    }
}

/// A skid analysis: the operating point's overrides (a sweep where one of them has several
/// values) and the models.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SkidRequest {
    /// Inner-ring speed, or a sweep `1500rpm..4500rpm:500rpm`.
    pub speed: Option<Values<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings), or a sweep.
    pub outer_speed: Option<Values<AngularSpeed>>,
    /// Radial load, or a sweep `100N..700N:50N`.
    pub radial_load: Option<Values<Force>>,
    /// Part temperatures; parts not given take the oil temperature.
    pub temperatures: Option<PartTemperatures>,
    pub friction: FrictionName,
    /// Cage–guiding-land model.
    pub cage_land: LandName,
    /// Folder for the table: a point's `rollers.csv`, a sweep's `skid_sweep.csv` and plot
    /// (SVG).
    pub out: Option<PathBuf>,
}

/// The values of a field, SI.
fn values<D: Dim>(given: &Option<Values<D>>) -> Option<Vec<f64>> {
    given.as_ref().map(Values::si)
}

/// The first value of a field (the operating point of a sweep), SI.
fn single<D: Dim>(given: &Option<Values<D>>) -> Option<f64> {
    values(given).and_then(|v| v.first().copied())
}

/// Every value of a swept field within the plausibility bounds (the first one is checked with
/// the operating point).
fn check_every_value(request: &SkidRequest, model: &Model) -> Result<(), Failure> {
    let speeds = values(&request.speed)
        .unwrap_or_default()
        .into_iter()
        .map(|w| rolldyn_setup::FlagValues {
            speed: Some(w),
            ..Default::default()
        });
    let outer = values(&request.outer_speed)
        .unwrap_or_default()
        .into_iter()
        .map(|w| rolldyn_setup::FlagValues {
            outer_speed: Some(w),
            ..Default::default()
        });
    let loads = values(&request.radial_load)
        .unwrap_or_default()
        .into_iter()
        .map(|f| rolldyn_setup::FlagValues {
            radial_load: Some(f),
            ..Default::default()
        });
    for flags in speeds.chain(outer).chain(loads) {
        flags.check(model)?;
    }
    Ok(())
}

/// The operating point of the model file, overridden by the request (first value of a sweep).
fn conditions(request: &SkidRequest, model: &Model) -> Result<QuasiStaticConditions, Failure> {
    let overrides = QuasiStaticOverrides {
        speed: single(&request.speed),
        outer_speed: single(&request.outer_speed),
        radial_load: single(&request.radial_load),
        temperatures: request.temperatures.unwrap_or_default().0,
        friction: match request.friction {
            FrictionName::Muraki => RacewayFriction::Muraki,
            FrictionName::Seed001 => RacewayFriction::Seed001,
        },
    };
    Ok(quasi_static_conditions(model, &overrides)?)
}

/// The variable swept and its values (SI), with its key (name and unit) and plot label.
struct Swept {
    variable: SweepVariable,
    key: &'static str,
    label: &'static str,
    values: Vec<f64>,
}

/// The swept value as printed and plotted: rpm for speeds, N for the load.
fn shown(variable: SweepVariable, v: f64) -> f64 {
    if variable != SweepVariable::RadialLoad {
        v * 30.0 / std::f64::consts::PI
    } else {
        v
    }
}

/// The field given with more than one value, if any (a single value only overrides the
/// operating point); more than one swept field is an error.
fn swept(request: &SkidRequest) -> Result<Option<Swept>, Failure> {
    let mut swept: Vec<Swept> = [
        (
            SweepVariable::InnerSpeed,
            "inner_speed_rad_s",
            "inner-ring speed, rpm",
            values(&request.speed),
        ),
        (
            SweepVariable::OuterSpeed,
            "outer_speed_rad_s",
            "outer-ring speed, rpm",
            values(&request.outer_speed),
        ),
        (
            SweepVariable::RadialLoad,
            "radial_load_n",
            "radial load, N",
            values(&request.radial_load),
        ),
    ]
    .into_iter()
    .filter_map(|(variable, key, label, values)| {
        values.filter(|v| v.len() > 1).map(|values| Swept {
            variable,
            key,
            label,
            values,
        })
    })
    .collect();
    match swept.len() {
        0 => Ok(None),
        1 => Ok(swept.pop()),
        _ => Err(Failure::Input(
            "sweep one variable at a time (--speed, --outer-speed or --radial-load)".into(),
        )),
    }
}

/// One point of a sweep; the value fields are `None` where the point failed.
#[derive(Clone, Debug, Serialize)]
pub struct SweepRow {
    /// The swept variable's value, SI (the unit is in the sweep's `variable`).
    pub value: f64,
    pub cage_slip: Option<f64>,
    pub cage_speed_rad_s: Option<f64>,
    pub epicyclic_cage_speed_rad_s: Option<f64>,
    pub max_roller_load_n: Option<f64>,
    pub power_loss_w: Option<f64>,
    pub min_scuffing_margin: Option<f64>,
    pub error: Option<String>,
}

impl SweepRow {
    fn new(p: &SweepPoint) -> Self {
        match &p.result {
            Ok(r) => SweepRow {
                value: p.value,
                cage_slip: Some(r.cage_slip),
                cage_speed_rad_s: Some(r.cage_speed_rad_s),
                epicyclic_cage_speed_rad_s: Some(r.epicyclic_cage_speed_rad_s),
                max_roller_load_n: Some(r.max_roller_load_n),
                power_loss_w: Some(r.power_loss_w),
                min_scuffing_margin: r.min_scuffing_margin,
                error: None,
            },
            Err(e) => SweepRow {
                value: p.value,
                cage_slip: None,
                cage_speed_rad_s: None,
                epicyclic_cage_speed_rad_s: None,
                max_roller_load_n: None,
                power_loss_w: None,
                min_scuffing_margin: None,
                error: Some(e.to_string()),
            },
        }
    }

    /// The row's numbers in the order of [`SWEEP_COLUMNS`], NaN where the point failed.
    fn numbers(&self) -> [f64; 7] {
        let nan = f64::NAN;
        [
            self.value,
            self.cage_slip.unwrap_or(nan),
            self.cage_speed_rad_s.unwrap_or(nan),
            self.epicyclic_cage_speed_rad_s.unwrap_or(nan),
            self.max_roller_load_n.unwrap_or(nan),
            self.power_loss_w.unwrap_or(nan),
            self.min_scuffing_margin.unwrap_or(nan),
        ]
    }
}

/// The columns of the sweep table after the swept variable's.
const SWEEP_COLUMNS: [&str; 6] = [
    "cage_slip",
    "cage_speed_rad_s",
    "epicyclic_cage_speed_rad_s",
    "max_roller_load_n",
    "power_loss_w",
    "min_scuffing_margin",
];

/// A skid result: one operating point or a sweep.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum SkidResult {
    /// Boxed: a point carries every roller's contacts.
    Point(Box<SkidPoint>),
    Sweep(SkidSweep),
}

/// One operating point.
#[derive(Clone, Debug, Serialize)]
pub struct SkidPoint {
    #[serde(flatten)]
    pub result: rolldyn_quasistatic::SkidResult,
    /// The bearing's name, for the text heading.
    #[serde(skip)]
    pub model: String,
}

/// A sweep: the varied variable (its name with its unit, e.g. `radial_load_n`) and one row per
/// value.
#[derive(Clone, Debug, Serialize)]
pub struct SkidSweep {
    pub variable: &'static str,
    pub points: Vec<SweepRow>,
    /// The bearing's name, the plot label of the variable and the drag laws, for the text.
    #[serde(skip)]
    pub model: String,
    #[serde(skip)]
    label: &'static str,
    #[serde(skip)]
    swept: SweepVariable,
    #[serde(skip)]
    drag_law: String,
}

impl Tables for SkidResult {
    /// A point: its `rollers`; a sweep: `skid_sweep`, the swept variable first.
    fn tables(&self) -> Vec<Table> {
        match self {
            Self::Point(p) => vec![rollers_table(&p.result)],
            Self::Sweep(s) => vec![s.table()],
        }
    }
}

/// One row per roller of a point.
fn rollers_table(r: &rolldyn_quasistatic::SkidResult) -> Table {
    let col = |f: &dyn Fn(&rolldyn_quasistatic::RollerResult) -> f64| {
        r.rollers.iter().map(f).collect::<Vec<f64>>()
    };
    let nan = f64::NAN;
    Table::new("rollers")
        .integer("roller", r.rollers.iter().map(|x| x.index as i64).collect())
        .real("azimuth_rad", col(&|x| x.azimuth_rad))
        .text(
            "zone",
            r.rollers
                .iter()
                .map(|x| match x.zone {
                    rolldyn_quasistatic::Zone::Loaded => "loaded".into(),
                    rolldyn_quasistatic::Zone::Unloaded => "unloaded".into(),
                })
                .collect(),
        )
        .real("spin_rad_s", col(&|x| x.spin_rad_s))
        .real("slip", col(&|x| x.slip))
        .real("centrifugal_force_n", col(&|x| x.centrifugal_force_n))
        .real("tilt_rad", col(&|x| x.tilt_rad))
        .real("inner_normal_force_n", col(&|x| x.inner.normal_force_n))
        .real("inner_max_pressure_pa", col(&|x| x.inner.max_pressure_pa))
        .real(
            "inner_sliding_speed_m_s",
            col(&|x| x.inner.sliding_speed_m_s),
        )
        .real(
            "inner_friction_coefficient",
            col(&|x| x.inner.friction_coefficient),
        )
        .real(
            "inner_film_central_m",
            col(&|x| x.inner.film_central_m.unwrap_or(nan)),
        )
        .real(
            "inner_scuffing_margin",
            col(&|x| x.inner.scuffing_margin.unwrap_or(nan)),
        )
        .real("outer_normal_force_n", col(&|x| x.outer.normal_force_n))
        .real("outer_max_pressure_pa", col(&|x| x.outer.max_pressure_pa))
        .real(
            "outer_sliding_speed_m_s",
            col(&|x| x.outer.sliding_speed_m_s),
        )
        .real(
            "outer_friction_coefficient",
            col(&|x| x.outer.friction_coefficient),
        )
        .real(
            "outer_film_central_m",
            col(&|x| x.outer.film_central_m.unwrap_or(nan)),
        )
        .real(
            "outer_scuffing_margin",
            col(&|x| x.outer.scuffing_margin.unwrap_or(nan)),
        )
        .real("bar_normal_force_n", col(&|x| x.bar.normal_force_n))
        .real("bar_push_n", col(&|x| x.bar.push_n))
        .real("rib_force_n", col(&|x| x.rib_force_n))
        .real("power_w", col(&|x| x.power_w))
}

impl SkidSweep {
    /// The sweep table: the swept variable (SI), the results (NaN where a point failed) and
    /// the error of a failed point.
    fn table(&self) -> Table {
        let names: Vec<String> = std::iter::once(self.variable)
            .chain(SWEEP_COLUMNS)
            .map(String::from)
            .collect();
        let numbers: Vec<f64> = self.points.iter().flat_map(SweepRow::numbers).collect();
        let mut table = Table::from_rows("skid_sweep", &names, &numbers);
        table = table.text(
            "error",
            self.points
                .iter()
                .map(|r| r.error.clone().unwrap_or_default())
                .collect(),
        );
        table
    }

    /// The sweep table (skid_sweep.csv, empty fields where a point failed) and the cage-slip
    /// plot (cage_slip.svg) in `dir`.
    fn write_files(&self, dir: &Path) -> Result<(), Failure> {
        let header: Vec<&str> = std::iter::once(self.variable)
            .chain(SWEEP_COLUMNS)
            .collect();
        write_csv(
            &dir.join("skid_sweep.csv"),
            &header,
            self.points.iter().map(|r| r.numbers().to_vec()),
        )?;
        let points: Vec<(f64, f64)> = self
            .points
            .iter()
            .filter_map(|r| r.cage_slip.map(|s| (self.shown(r.value), s)))
            .collect();
        line_plot(
            &dir.join("cage_slip.svg"),
            &Labels {
                title: &format!("{}: cage slip (quasi-static)", self.model),
                x: self.label,
                y: "cage slip ε0",
            },
            &[Series {
                label: "",
                points: &points,
            }],
        )?;
        Ok(())
    }

    fn shown(&self, v: f64) -> f64 {
        shown(self.swept, v)
    }
}

impl fmt::Display for SkidResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Point(p) => p.fmt(f),
            Self::Sweep(s) => s.fmt(f),
        }
    }
}

impl fmt::Display for SkidSweep {
    /// The sweep as a text table (speeds in rpm).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}: quasi-static cage slip, sweep over {}",
            self.model, self.label
        )?;
        write!(f, "  drag laws: {}", self.drag_law)?;
        for r in &self.points {
            match (r.cage_slip, &r.error) {
                (Some(s), _) => write!(
                    f,
                    "\n  {:>10.1}  slip {:>9.5}  cage {:>8.2} rad/s  max roller load {:>8.1} N  loss {:>7.2} W",
                    self.shown(r.value),
                    s,
                    r.cage_speed_rad_s.unwrap_or(f64::NAN),
                    r.max_roller_load_n.unwrap_or(f64::NAN),
                    r.power_loss_w.unwrap_or(f64::NAN)
                )?,
                (None, e) => write!(
                    f,
                    "\n  {:>10.1}  failed: {}",
                    self.shown(r.value),
                    e.as_deref().unwrap_or("")
                )?,
            }
        }
        Ok(())
    }
}

impl fmt::Display for SkidPoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.result;
        write!(f, "{}: quasi-static skidding", self.model)?;
        let mut line = |label: &str, value: String| write!(f, "\n  {label:<32} {value}");
        line("cage speed", format!("{:.2} rad/s", r.cage_speed_rad_s))?;
        line(
            "epicyclic cage speed",
            format!("{:.2} rad/s", r.epicyclic_cage_speed_rad_s),
        )?;
        line("cage slip ε0", format!("{:.5}", r.cage_slip))?;
        line(
            "max roller load",
            format!(
                "{:.1} N ({} rollers loaded)",
                r.max_roller_load_n, r.loaded_rollers
            ),
        )?;
        line(
            "operating clearance",
            format!("{:.4} mm", r.operating_clearance_m * 1e3),
        )?;
        line("power loss", format!("{:.2} W", r.power_loss_w))?;
        line("drag laws", r.cage_drag_law.clone())?;
        line(
            "min scuffing margin s_cr/s",
            r.min_scuffing_margin
                .map_or("no maximum in range".into(), |m| format!("{m:.2}")),
        )?;
        line("solve time", format!("{:.2} ms", r.solve_time_s * 1e3))
    }
}

/// A quasi-static failure: rejected input names the model file (bad input), a failed iteration
/// or contact solve is a failed run.
fn solve_failure(model: &Model, e: rolldyn_quasistatic::QsError) -> Failure {
    use rolldyn_quasistatic::QsError::*;
    match e {
        InvalidInput(_) | Geometry(_) => {
            Failure::Input(model.source.error("", e.to_string()).to_string())
        }
        Lubrication(_) => {
            Failure::Input(model.source.error("lubricant", e.to_string()).to_string())
        }
        Contact(_) | NotConverged { .. } => Failure::Run(e.to_string()),
    }
}

/// The skid analysis.
pub struct Skid;

impl Analysis for Skid {
    const NAME: &'static str = "skid";
    type Request = SkidRequest;
    type Result = SkidResult;

    /// Solves the operating point, or the sweep; a sweep writes its table and plot to `out`.
    fn run(request: &SkidRequest, context: &Context<'_>) -> Result<SkidResult, Failure> {
        let model = context.model.load()?;
        let bearing = model
            .bearing
            .require_cylindrical("skid")
            .map_err(|reason| Failure::Input(format!("{}: {reason}", model.bearing.name())))?;
        check_every_value(request, &model)?;
        let base = conditions(request, &model)?;
        let options = QuasiStaticOptions::default();
        let land = cage_land_model(
            bearing,
            match request.cage_land {
                LandName::Finite => LandChoice::Finite,
                LandName::Short => LandChoice::Short,
            },
        );
        let name = model.bearing.name().to_string();
        let Some(swept) = swept(request)? else {
            let result =
                rolldyn_quasistatic::solve_with_land_model(bearing, &base, &options, land.as_ref())
                    .map_err(|e| solve_failure(&model, e))?;
            if let Some(dir) = &request.out {
                write_table_csv(&out_dir(dir)?.join("rollers.csv"), &rollers_table(&result))?;
            }
            return Ok(SkidResult::Point(Box::new(SkidPoint {
                result,
                model: name,
            })));
        };
        let total = swept.values.len() as f64;
        context.observer.progress(&Progress {
            done: 0.0,
            total,
            unit: "points",
            message: None,
        });
        let points = rolldyn_quasistatic::sweep(
            bearing,
            &base,
            &options,
            land.as_ref(),
            swept.variable,
            &swept.values,
        );
        context.observer.progress(&Progress {
            done: total,
            total,
            unit: "points",
            message: None,
        });
        if let Some(e) = rolldyn_quasistatic::sweep::all_failed(&points) {
            return Err(Failure::Input(format!(
                "every point of the sweep failed: {e}"
            )));
        }
        let sweep = SkidSweep {
            variable: swept.key,
            points: points.iter().map(SweepRow::new).collect(),
            model: name,
            label: swept.label,
            swept: swept.variable,
            drag_law: points
                .iter()
                .find_map(|p| p.result.as_ref().ok().map(|r| r.cage_drag_law.clone()))
                .unwrap_or_default(),
        };
        if let Some(dir) = &request.out {
            sweep.write_files(&out_dir(dir)?)?;
        }
        Ok(SkidResult::Sweep(sweep))
    }
}
