//! Traction: the Muraki thermal EHL traction curve μ(s), the critical slip (scuffing
//! criterion) and the film of a lubricated contact (SPEC §4.5, §4.8; seed 000 eq. 1.8,
//! Figs 2.8, 2.10, 2.11), over lists of temperatures and maximum pressures.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::oil::{OilChoice, Rig};
use crate::output::{out_dir, write_csv};
use crate::table::{Table, Tables};
use rolldyn_lubrication::{
    ContactState, CriticalSlip, MurakiSettings, Rheology, SlipSearch, TractionModel, critical_slip,
    traction,
};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_units::{Dim, Pressure, Quantity, QuantityRange, Speed, Temperature};
use serde::de::{self, Deserializer};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};

/// The rheology of the traction law.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum RheologyName {
    /// Thermal visco-elastic Eyring (Muraki, seed 000 eq. 1.8).
    #[default]
    ViscoElastic,
    /// No self-heating (seed 000 Fig. 2.13 curve 4).
    Isothermal,
    /// Elastic term only, μ = Γ s b/(h p̄) (as for NVI 65), capped at 0.1.
    LinearElastic,
}

impl RheologyName {
    /// The name as the request and the command line write it.
    pub fn name(self) -> &'static str {
        match self {
            Self::ViscoElastic => "visco-elastic",
            Self::Isothermal => "isothermal",
            Self::LinearElastic => "linear-elastic",
        }
    }
}

/// A traction analysis: the oil, the test contact, and the operating points (every
/// temperature with every maximum pressure).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TractionRequest {
    #[serde(default)]
    pub oil: OilChoice,
    #[serde(default)]
    pub rig: Rig,
    /// Oil temperatures: one (`"40C"`), a list (`["40C", "60C"]`, `"40C,60C"`) or a range
    /// (`"40C..100C:20C"`); several overlay curves.
    #[serde(default = "forty_celsius", deserialize_with = "quantity_list")]
    pub temperature: Vec<Quantity<Temperature>>,
    /// Maximum Hertz pressures, given like `temperature`; several give s_cr against pressure.
    #[serde(default = "one_gigapascal", deserialize_with = "quantity_list")]
    pub max_pressure: Vec<Quantity<Pressure>>,
    /// Rolling (entrainment) speed u.
    #[serde(default = "rolling_speed")]
    pub rolling_speed: Quantity<Speed>,
    /// Largest slip of the curve.
    #[serde(default = "slip_max")]
    pub slip_max: f64,
    /// Points of the curve.
    #[serde(default = "points")]
    pub points: usize,
    #[serde(default)]
    pub rheology: RheologyName,
    /// Folder for the curves (CSV) and plots (SVG).
    #[serde(default)]
    pub out: Option<PathBuf>,
}

fn forty_celsius() -> Vec<Quantity<Temperature>> {
    vec![Quantity::from_si(313.15)]
}

fn one_gigapascal() -> Vec<Quantity<Pressure>> {
    vec![Quantity::from_si(1e9)]
}

fn rolling_speed() -> Quantity<Speed> {
    Quantity::from_si(2.5)
}

fn slip_max() -> f64 {
    0.5
}

fn points() -> usize {
    101
}

/// Quantities given as one number or text (a value, a comma list or a range
/// `start..end:step`, as on the command line), or as a list of numbers and texts.
pub fn quantity_list<'de, D: Dim, De: Deserializer<'de>>(
    deserializer: De,
) -> Result<Vec<Quantity<D>>, De::Error> {
    #[derive(Deserialize)]
    #[serde(untagged, bound = "")]
    enum Given<D: Dim> {
        Text(String),
        One(Quantity<D>),
        Many(Vec<Quantity<D>>),
    }
    Ok(match Given::<D>::deserialize(deserializer)? {
        Given::Text(text) => {
            text.parse::<QuantityRange<D>>()
                .map_err(de::Error::custom)?
                .values
        }
        Given::One(q) => vec![q],
        Given::Many(list) => list,
    })
}

/// A point of a traction curve.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CurvePoint {
    pub slip: f64,
    pub traction: f64,
}

/// One operating point: the critical slip, the film and the curve.
#[derive(Clone, Debug, Serialize)]
pub struct TractionCase {
    pub temperature_k: f64,
    pub max_pressure_pa: f64,
    pub load_n: f64,
    pub rolling_speed_m_s: f64,
    pub critical_slip: Option<f64>,
    pub max_traction: Option<f64>,
    pub no_maximum_reason: Option<String>,
    pub film_thickness_m: f64,
    pub lambda: f64,
    pub warnings: Vec<&'static str>,
    pub curve: Vec<CurvePoint>,
}

impl TractionCase {
    /// The curve's label in the plots.
    fn label(&self) -> String {
        format!(
            "{:.0} °C, {:.2} GPa",
            self.temperature_k - 273.15,
            self.max_pressure_pa * 1e-9
        )
    }
}

/// The traction curves; serialised with the first case's fields at the top level (the
/// single-point answer) and every case in `cases`.
#[derive(Clone, Debug)]
pub struct TractionResult {
    pub oil: String,
    pub rheology: &'static str,
    /// At least one case.
    pub cases: Vec<TractionCase>,
}

impl Serialize for TractionResult {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Answer<'a> {
            oil: &'a str,
            rheology: &'static str,
            #[serde(flatten)]
            first: &'a TractionCase,
            cases: &'a [TractionCase],
        }
        Answer {
            oil: &self.oil,
            rheology: self.rheology,
            first: &self.cases[0],
            cases: &self.cases,
        }
        .serialize(serializer)
    }
}

impl Tables for TractionResult {
    /// `traction`: the curves (temperature_k, max_pressure_pa, slip, traction), as
    /// `traction.csv`; `cases`: one row per operating point (NaN where no maximum).
    fn tables(&self) -> Vec<Table> {
        let along = |f: fn(&TractionCase, &CurvePoint) -> f64| {
            self.cases
                .iter()
                .flat_map(|c| c.curve.iter().map(move |p| f(c, p)))
                .collect()
        };
        let per_case = |f: fn(&TractionCase) -> f64| self.cases.iter().map(f).collect();
        vec![
            Table::new("traction")
                .real("temperature_k", along(|c, _| c.temperature_k))
                .real("max_pressure_pa", along(|c, _| c.max_pressure_pa))
                .real("slip", along(|_, p| p.slip))
                .real("traction", along(|_, p| p.traction)),
            Table::new("cases")
                .real("temperature_k", per_case(|c| c.temperature_k))
                .real("max_pressure_pa", per_case(|c| c.max_pressure_pa))
                .real("load_n", per_case(|c| c.load_n))
                .real("rolling_speed_m_s", per_case(|c| c.rolling_speed_m_s))
                .real(
                    "critical_slip",
                    per_case(|c| c.critical_slip.unwrap_or(f64::NAN)),
                )
                .real(
                    "max_traction",
                    per_case(|c| c.max_traction.unwrap_or(f64::NAN)),
                )
                .real("film_thickness_m", per_case(|c| c.film_thickness_m))
                .real("lambda", per_case(|c| c.lambda)),
        ]
    }
}

impl fmt::Display for TractionResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: traction at u = {:.3} m/s\n  {:>8} {:>10} {:>9} {:>12} {:>11} {:>10}",
            self.oil,
            self.cases[0].rolling_speed_m_s,
            "T °C",
            "p_max GPa",
            "load N",
            "film µm",
            "s_cr",
            "μ_max"
        )?;
        for c in &self.cases {
            write!(
                f,
                "\n  {:>8.1} {:>10.3} {:>9.2} {:>12.4} {:>11} {:>10}",
                c.temperature_k - 273.15,
                c.max_pressure_pa * 1e-9,
                c.load_n,
                c.film_thickness_m * 1e6,
                c.critical_slip.map_or("none".into(), |s| format!("{s:.4}")),
                c.max_traction.map_or("—".into(), |m| format!("{m:.4}"))
            )?;
            if let Some(reason) = &c.no_maximum_reason {
                write!(f, "\n           {reason}")?;
            }
        }
        Ok(())
    }
}

/// The traction analysis.
pub struct Traction;

impl Analysis for Traction {
    const NAME: &'static str = "traction";
    type Request = TractionRequest;
    type Result = TractionResult;

    fn run(request: &TractionRequest, context: &Context<'_>) -> Result<TractionResult, Failure> {
        if !(request.slip_max > 0.0 && request.slip_max <= 2.0) {
            return Err(Failure::Input("--slip-max must lie in (0, 2]".into()));
        }
        if request.rolling_speed.si() < 0.0 {
            return Err(Failure::Input(
                "--rolling-speed must not be negative".into(),
            ));
        }
        rolldyn_model::bounds::check_rolling_speed("--rolling-speed", request.rolling_speed.si())
            .map_err(|e| Failure::Input(e.to_string()))?;
        if request.temperature.is_empty() || request.max_pressure.is_empty() {
            return Err(Failure::Input(
                "--temperature and --max-pressure need at least one value each".into(),
            ));
        }
        let model = model(&request.oil, request.rheology)?;
        let oil = model
            .config()
            .oil
            .as_ref()
            .map_or("", |o| o.name.as_str())
            .to_string();
        let mut cases = Vec::new();
        for t in &request.temperature {
            if let Some(oil) = &model.config().oil {
                request.oil.check_temperature(oil, t.si(), context)?;
            }
            for p in &request.max_pressure {
                if !(p.si() > 0.0) {
                    return Err(Failure::Input("--max-pressure must be positive".into()));
                }
                if let Some(reason) = rolldyn_model::bounds::pressure_beyond_materials(p.si()) {
                    return Err(Failure::Input(format!("--max-pressure: {reason}")));
                }
                cases.push(evaluate(request, &model, t.si(), p.si())?);
            }
        }
        if let Some(dir) = &request.out {
            write_outputs(&out_dir(dir)?, &cases)?;
        }
        Ok(TractionResult {
            oil,
            rheology: request.rheology.name(),
            cases,
        })
    }
}

/// The traction law of the oil with the rheology.
fn model(oil: &OilChoice, rheology: RheologyName) -> Result<TractionModel, Failure> {
    let oil = oil.load()?;
    let rheology = match rheology {
        RheologyName::ViscoElastic => Rheology::ViscoElastic,
        RheologyName::Isothermal => Rheology::Isothermal,
        RheologyName::LinearElastic => Rheology::LinearElastic { cap: 0.1 },
    };
    TractionModel::lubricated(
        oil,
        MurakiSettings {
            rheology,
            ..MurakiSettings::default()
        },
    )
    .map_err(|e| Failure::Input(e.to_string()))
}

/// The curve, critical slip and film at temperature `t` (K) and maximum pressure `p_max` (Pa).
fn evaluate(
    request: &TractionRequest,
    model: &TractionModel,
    t: f64,
    p_max: f64,
) -> Result<TractionCase, Failure> {
    let (geometry, r, e) = request.rig.geometry()?;
    let u = request.rolling_speed.si();
    let state = ContactState {
        normal_force_n: request.rig.load_for_max_pressure(p_max)?,
        geometry,
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: u,
        sliding_speed_m_s: 0.0,
        temperature_k: t,
        roughness_ra_m: [0.0, 0.0],
        film_thickness_m: None,
    };
    let n = request.points.max(2);
    let at = |s: f64| {
        let mut st = state;
        st.sliding_speed_m_s = s * u;
        traction(&st, model)
    };
    let curve = (0..n)
        .map(|k| {
            let slip = request.slip_max * k as f64 / (n - 1) as f64;
            CurvePoint {
                slip,
                traction: at(slip).coefficient,
            }
        })
        .collect();
    let rolling = at(0.0);
    let (critical, maximum, reason) = if u > 0.0 {
        match critical_slip(&state, model, &SlipSearch::default())
            .map_err(|e| Failure::Run(e.to_string()))?
        {
            CriticalSlip::Maximum {
                slip, coefficient, ..
            } => (Some(slip), Some(coefficient), None),
            CriticalSlip::NoMaximumInRange {
                reason,
                slip_at_end,
                ..
            } => (
                None,
                None,
                Some(format!(
                    "no maximum in range: {reason:?} at s = {slip_at_end:.3}"
                )),
            ),
        }
    } else {
        (
            None,
            None,
            Some("zero rolling speed: slip is undefined".to_string()),
        )
    };
    Ok(TractionCase {
        temperature_k: t,
        max_pressure_pa: p_max,
        load_n: state.normal_force_n,
        rolling_speed_m_s: u,
        critical_slip: critical,
        max_traction: maximum,
        no_maximum_reason: reason,
        film_thickness_m: rolling.film_central_m,
        lambda: rolling.lambda,
        warnings: rolling.warnings.names(),
        curve,
    })
}

/// Writes `traction.csv`, `traction.svg` and, when a temperature has several pressures,
/// `critical_slip_vs_pressure.svg`.
fn write_outputs(dir: &Path, cases: &[TractionCase]) -> Result<(), Failure> {
    write_csv(
        &dir.join("traction.csv"),
        &["temperature_k", "max_pressure_pa", "slip", "traction"],
        cases.iter().flat_map(|c| {
            c.curve
                .iter()
                .map(|p| vec![c.temperature_k, c.max_pressure_pa, p.slip, p.traction])
        }),
    )?;
    let curves: Vec<(String, Vec<(f64, f64)>)> = cases
        .iter()
        .map(|c| {
            (
                c.label(),
                c.curve.iter().map(|p| (p.slip, p.traction)).collect(),
            )
        })
        .collect();
    line_plot(
        &dir.join("traction.svg"),
        &Labels {
            title: "Traction coefficient against relative slip",
            x: "relative slip s = v/u",
            y: "traction coefficient μ",
        },
        &Series::from_pairs(&curves),
    )?;
    let mut temperatures: Vec<f64> = cases.iter().map(|c| c.temperature_k).collect();
    temperatures.dedup();
    let by_pressure: Vec<(String, Vec<(f64, f64)>)> = temperatures
        .iter()
        .map(|&t| {
            let points = cases
                .iter()
                .filter(|c| c.temperature_k == t)
                .filter_map(|c| c.critical_slip.map(|s| (c.max_pressure_pa * 1e-9, s)))
                .collect();
            (format!("{:.0} °C", t - 273.15), points)
        })
        .collect();
    if by_pressure.iter().any(|(_, p)| p.len() > 1) {
        line_plot(
            &dir.join("critical_slip_vs_pressure.svg"),
            &Labels {
                title: "Critical relative slip against maximum contact pressure",
                x: "maximum Hertz pressure, GPa",
                y: "critical slip s_cr",
            },
            &Series::from_pairs(&by_pressure),
        )?;
    }
    Ok(())
}
