//! `rolldyn traction`: traction curve μ(s), critical slip and film of a lubricated contact
//! (SPEC §4.5, §4.8; seed 000 Figs 2.8, 2.10, 2.11).

use super::oil_args::OilArgs;
use super::rig_args::RigArgs;
use crate::failure::Failure;
use crate::output::print_json;
use rolldyn::output::{out_dir, write_csv};
use rolldyn_lubrication::{
    ContactState, CriticalSlip, MurakiSettings, Rheology, SlipSearch, TractionModel, critical_slip,
    traction,
};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_units::{Pressure, Quantity, QuantityRange, Speed, Temperature};
use serde::Serialize;
use std::path::PathBuf;

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum RheologyName {
    /// Thermal visco-elastic Eyring (Muraki, seed 000 eq. 1.8).
    ViscoElastic,
    /// No self-heating (seed 000 Fig. 2.13 curve 4).
    Isothermal,
    /// Elastic term only, μ = Γ s b/(h p̄) (as for NVI 65), capped at 0.1.
    LinearElastic,
}

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub oil: OilArgs,
    #[command(flatten)]
    pub rig: RigArgs,
    /// Oil temperature; a comma list overlays curves (`--temperature 40C,60C,100C`).
    #[arg(
        long,
        allow_hyphen_values = true,
        alias = "temperatures",
        default_value = "40C"
    )]
    pub temperature: QuantityRange<Temperature>,
    /// Maximum Hertz pressure; a list or range gives s_cr against pressure (`0.6GPa..2GPa:0.2GPa`).
    #[arg(
        long,
        allow_hyphen_values = true,
        alias = "max-pressures",
        default_value = "1GPa"
    )]
    pub max_pressure: QuantityRange<Pressure>,
    /// Rolling (entrainment) speed u.
    #[arg(long, allow_hyphen_values = true, default_value = "2.5m/s")]
    pub rolling_speed: Quantity<Speed>,
    /// Largest slip of the curve.
    #[arg(long, default_value = "0.5")]
    pub slip_max: f64,
    /// Points of the curve.
    #[arg(long, default_value = "101")]
    pub points: usize,
    #[arg(long, value_enum, default_value = "visco-elastic")]
    pub rheology: RheologyName,
    #[arg(long)]
    pub json: bool,
    /// Write the curves (CSV) and plots (SVG) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

#[derive(Serialize, Clone, Copy)]
struct CurvePoint {
    slip: f64,
    traction: f64,
}

#[derive(Serialize)]
struct Case {
    temperature_k: f64,
    max_pressure_pa: f64,
    load_n: f64,
    rolling_speed_m_s: f64,
    critical_slip: Option<f64>,
    max_traction: Option<f64>,
    no_maximum_reason: Option<String>,
    film_thickness_m: f64,
    lambda: f64,
    warnings: Vec<&'static str>,
    curve: Vec<CurvePoint>,
}

#[derive(Serialize)]
struct Answer<'a> {
    oil: &'a str,
    rheology: &'static str,
    #[serde(flatten)]
    first: &'a Case,
    cases: &'a [Case],
}

fn model(args: &Args) -> Result<TractionModel, Failure> {
    let oil = args.oil.choice().load()?;
    let rheology = match args.rheology {
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

fn evaluate(args: &Args, model: &TractionModel, t: f64, p_max: f64) -> Result<Case, Failure> {
    let (geometry, r, e) = args.rig.rig().geometry()?;
    let u = args.rolling_speed.si();
    let state = ContactState {
        normal_force_n: args.rig.rig().load_for_max_pressure(p_max)?,
        geometry,
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: u,
        sliding_speed_m_s: 0.0,
        temperature_k: t,
        roughness_ra_m: [0.0, 0.0],
        film_thickness_m: None,
    };
    let n = args.points.max(2);
    let at = |s: f64| {
        let mut st = state;
        st.sliding_speed_m_s = s * u;
        traction(&st, model)
    };
    let curve = (0..n)
        .map(|k| {
            let slip = args.slip_max * k as f64 / (n - 1) as f64;
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
    Ok(Case {
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

pub fn run(args: Args) -> Result<(), Failure> {
    if !(args.slip_max > 0.0 && args.slip_max <= 2.0) {
        return Err(Failure::Input("--slip-max must lie in (0, 2]".into()));
    }
    if args.rolling_speed.si() < 0.0 {
        return Err(Failure::Input(
            "--rolling-speed must not be negative".into(),
        ));
    }
    let model = model(&args)?;
    let oil = model
        .config()
        .oil
        .as_ref()
        .map_or("", |o| o.name.as_str())
        .to_string();
    let mut cases = Vec::new();
    for t in &args.temperature.values {
        if let Some(oil) = &model.config().oil {
            args.oil
                .choice()
                .check_temperature(oil, t.si(), &rolldyn::Context::default())?;
        }
        for p in &args.max_pressure.values {
            if !(p.si() > 0.0) {
                return Err(Failure::Input("--max-pressure must be positive".into()));
            }
            cases.push(evaluate(&args, &model, t.si(), p.si())?);
        }
    }
    if let Some(dir) = &args.out {
        write_outputs(&out_dir(dir)?, &cases)?;
    }
    if args.json {
        let rheology = match args.rheology {
            RheologyName::ViscoElastic => "visco-elastic",
            RheologyName::Isothermal => "isothermal",
            RheologyName::LinearElastic => "linear-elastic",
        };
        return print_json(&Answer {
            oil: &oil,
            rheology,
            first: &cases[0],
            cases: &cases,
        });
    }
    println!("{oil}: traction at u = {:.3} m/s", args.rolling_speed.si());
    println!(
        "  {:>8} {:>10} {:>9} {:>12} {:>11} {:>10}",
        "T °C", "p_max GPa", "load N", "film µm", "s_cr", "μ_max"
    );
    for c in &cases {
        println!(
            "  {:>8.1} {:>10.3} {:>9.2} {:>12.4} {:>11} {:>10}",
            c.temperature_k - 273.15,
            c.max_pressure_pa * 1e-9,
            c.load_n,
            c.film_thickness_m * 1e6,
            c.critical_slip.map_or("none".into(), |s| format!("{s:.4}")),
            c.max_traction.map_or("—".into(), |m| format!("{m:.4}"))
        );
        if let Some(reason) = &c.no_maximum_reason {
            println!("           {reason}");
        }
    }
    Ok(())
}

fn label(c: &Case) -> String {
    format!(
        "{:.0} °C, {:.2} GPa",
        c.temperature_k - 273.15,
        c.max_pressure_pa * 1e-9
    )
}

fn write_outputs(dir: &std::path::Path, cases: &[Case]) -> Result<(), Failure> {
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
                label(c),
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
