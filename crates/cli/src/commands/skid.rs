//! `rolldyn skid MODEL.toml`: quasi-static roller and cage skidding (SPEC §5, seed 001) at one
//! operating point, or a sweep over speed, outer-ring speed or radial load.

use crate::failure::Failure;
use crate::output::{load_model, out_dir, print_json, write_csv};
use rolldyn_geometry::BearingModel;
use rolldyn_lubrication::{FilmFormula, MurakiSettings};
use rolldyn_model::Model;
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::sweep::{SweepPoint, SweepVariable, apply};
use rolldyn_quasistatic::{
    CageLandModel, FiniteLand, FrictionModel, OperatingConditions, QuasiStaticOptions,
    ShortBearing, SkidResult,
};
use rolldyn_units::{AngularSpeed, Force, Quantity, QuantityRange, Temperature};
use serde::Serialize;
use std::path::PathBuf;

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FrictionName {
    /// Muraki EHL traction with the mixed-friction blend (seed 000), rheology from the model.
    Muraki,
    /// Asperity fraction + film shear + flash temperature (seed 001).
    Seed001,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LandName {
    /// Finite journal bearing (Reynolds crate table, SPEC §8.6).
    Finite,
    /// Short (Ocvirk) journal bearing.
    Short,
}

impl Args {
    /// The model's own operating point (no flags), Muraki friction, finite land model.
    pub(crate) fn from_model_only() -> Self {
        Self {
            model: None,
            speed: None,
            outer_speed: None,
            radial_load: None,
            temperatures: None,
            friction: FrictionName::Muraki,
            cage_land: LandName::Finite,
            json: false,
            out: None,
        }
    }
}

#[derive(clap::Args)]
pub struct Args {
    /// Model file with [lubricant] (and optionally [operating]); the embedded 2002834 model when
    /// omitted.
    pub model: Option<PathBuf>,
    /// Inner-ring speed, or a sweep `1500rpm..4500rpm:500rpm`.
    #[arg(long)]
    pub speed: Option<QuantityRange<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings), or a sweep.
    #[arg(long)]
    pub outer_speed: Option<QuantityRange<AngularSpeed>>,
    /// Radial load, or a sweep `100N..700N:50N`.
    #[arg(long)]
    pub radial_load: Option<QuantityRange<Force>>,
    /// Part temperatures, e.g. `inner=47.3C,outer=43C,cage=45C,oil=45C` (parts not given take
    /// the oil temperature).
    #[arg(long, value_parser = parse_temperatures)]
    pub temperatures: Option<Vec<(String, f64)>>,
    #[arg(long, value_enum, default_value = "muraki")]
    pub friction: FrictionName,
    /// Cage–guiding-land model.
    #[arg(long, value_enum, default_value = "finite")]
    pub cage_land: LandName,
    #[arg(long)]
    pub json: bool,
    /// Folder for the sweep table (CSV) and plot (SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

const PARTS: [&str; 7] = [
    "oil", "inner", "outer", "rollers", "cage", "shaft", "housing",
];

fn parse_temperatures(text: &str) -> Result<Vec<(String, f64)>, String> {
    text.split(',')
        .map(|item| {
            let (part, value) = item
                .split_once('=')
                .ok_or_else(|| format!("'{item}': expected part=temperature, e.g. inner=47.3C"))?;
            let part = part.trim();
            if !PARTS.contains(&part) {
                return Err(format!(
                    "unknown part '{part}' (known: {})",
                    PARTS.join(", ")
                ));
            }
            let t = Quantity::<Temperature>::parse(value)
                .map_err(|e| e.to_string())?
                .si();
            if t <= 0.0 {
                return Err(format!("'{item}' is below absolute zero"));
            }
            Ok((part.to_string(), t))
        })
        .collect()
}

fn single<D: rolldyn_units::Dim>(range: &Option<QuantityRange<D>>) -> Option<f64> {
    range
        .as_ref()
        .and_then(|r| r.values.first())
        .map(|q| q.si())
}

/// The operating point of the model file, overridden by the flags (first value of a sweep).
pub(crate) fn conditions(args: &Args, model: &Model) -> Result<OperatingConditions, Failure> {
    let op = &model.operating;
    let name = model.bearing.name();
    let lubrication = model
        .lubrication
        .as_ref()
        .ok_or_else(|| Failure::Input(format!("{name}: skid needs a [lubricant] section")))?;
    let inner = single(&args.speed).or(op.inner_speed).ok_or_else(|| {
        Failure::Input("no inner-ring speed: give --speed or operating.inner_speed".into())
    })?;
    let outer = single(&args.outer_speed).or(op.outer_speed).unwrap_or(0.0);
    let load = single(&args.radial_load)
        .or(op.radial_load)
        .ok_or_else(|| {
            Failure::Input("no radial load: give --radial-load or operating.radial_load".into())
        })?;
    let given = |part: &str| {
        args.temperatures
            .as_ref()
            .and_then(|list| list.iter().find(|(p, _)| p == part).map(|(_, t)| *t))
    };
    let t = &op.temperatures;
    let oil = given("oil").or(t.oil).ok_or_else(|| {
        Failure::Input(
            "no oil temperature: give --temperatures oil=… or operating.temperatures.oil".into(),
        )
    })?;
    let mut c = OperatingConditions::new(inner, outer, load, lubrication.oil.clone(), oil);
    let part = |name: &str, file: Option<f64>| given(name).or(file).unwrap_or(oil);
    c.temperatures.inner_ring = part("inner", t.inner_ring);
    c.temperatures.outer_ring = part("outer", t.outer_ring);
    c.temperatures.rollers = part("rollers", t.rollers);
    c.temperatures.cage = part("cage", t.cage);
    c.temperatures.shaft = part("shaft", t.shaft);
    c.temperatures.housing = part("housing", t.housing);
    let tilt = model.bearing.misalignment().inner_ring_tilt;
    c.misalignment_rad = (tilt != 0.0).then_some(tilt);
    c.friction = match args.friction {
        FrictionName::Muraki => FrictionModel::Muraki {
            settings: MurakiSettings {
                rheology: lubrication.rheology,
                ..MurakiSettings::default()
            },
            mixed: None,
            film: FilmFormula::Auto,
        },
        FrictionName::Seed001 => FrictionModel::Seed001(Default::default()),
    };
    Ok(c)
}

/// One row of a sweep table / JSON.
#[derive(Serialize)]
struct SweepRow {
    value: f64,
    cage_slip: Option<f64>,
    cage_speed_rad_s: Option<f64>,
    epicyclic_cage_speed_rad_s: Option<f64>,
    max_roller_load_n: Option<f64>,
    power_loss_w: Option<f64>,
    min_scuffing_margin: Option<f64>,
    error: Option<String>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?;
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Err(Failure::Input(format!(
            "{}: skid needs a complete bearing (bearing.kind = \"cylindrical\")",
            model.bearing.name()
        )));
    };
    let base = conditions(&args, &model)?;
    let options = QuasiStaticOptions::default();
    let land: Box<dyn CageLandModel> = match args.cage_land {
        LandName::Finite => {
            Box::new(FiniteLand::new(bearing.cage.as_ref().is_some_and(|c| {
                c.guidance == rolldyn_geometry::CageGuidance::InnerLand
            })))
        }
        LandName::Short => Box::new(ShortBearing::default()),
    };
    let solve = |c: &OperatingConditions, o: &QuasiStaticOptions| {
        rolldyn_quasistatic::solve_with_land_model(bearing, c, o, land.as_ref())
    };
    let swept: Vec<(SweepVariable, &str, &str, Vec<f64>)> = [
        (
            SweepVariable::InnerSpeed,
            "inner_speed_rad_s",
            "inner-ring speed, rpm",
            args.speed
                .as_ref()
                .map(|r| r.values.iter().map(|q| q.si()).collect::<Vec<_>>()),
        ),
        (
            SweepVariable::OuterSpeed,
            "outer_speed_rad_s",
            "outer-ring speed, rpm",
            args.outer_speed
                .as_ref()
                .map(|r| r.values.iter().map(|q| q.si()).collect()),
        ),
        (
            SweepVariable::RadialLoad,
            "radial_load_n",
            "radial load, N",
            args.radial_load
                .as_ref()
                .map(|r| r.values.iter().map(|q| q.si()).collect()),
        ),
    ]
    .into_iter()
    .filter_map(|(v, key, label, values)| {
        values
            .filter(|v| v.len() > 1)
            .map(|values| (v, key, label, values))
    })
    .collect();
    match swept.as_slice() {
        [] => {
            let result = rolldyn_quasistatic::solve(bearing, &base, &options)
                .map_err(|e| Failure::Run(e.to_string()))?;
            if args.json {
                print_json(&result)
            } else {
                print_point(model.bearing.name(), &result);
                Ok(())
            }
        }
        [(variable, key, label, values)] => {
            // Each point starts from the previous point's cage slip (as `sweep::sweep` does).
            let mut warm = options.clone();
            let points: Vec<SweepPoint> = values
                .iter()
                .map(|&value| {
                    let result = solve(&apply(&base, *variable, value), &warm);
                    if let Ok(r) = &result {
                        warm.initial_cage_slip = r.cage_slip;
                    }
                    SweepPoint { value, result }
                })
                .collect();
            if let Some(Err(e)) = points
                .iter()
                .map(|p| &p.result)
                .find(|r| r.is_err())
                .filter(|_| points.iter().all(|p| p.result.is_err()))
            {
                return Err(Failure::Input(format!(
                    "every point of the sweep failed: {e}"
                )));
            }
            let rows: Vec<SweepRow> = points
                .iter()
                .map(|p| match &p.result {
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
                })
                .collect();
            let is_speed = *variable != SweepVariable::RadialLoad;
            let shown = |v: f64| {
                if is_speed {
                    v * 30.0 / std::f64::consts::PI
                } else {
                    v
                }
            };
            if let Some(dir) = &args.out {
                let dir = out_dir(dir)?;
                let nan = f64::NAN;
                write_csv(
                    &dir.join("skid_sweep.csv"),
                    &[
                        key,
                        "cage_slip",
                        "cage_speed_rad_s",
                        "epicyclic_cage_speed_rad_s",
                        "max_roller_load_n",
                        "power_loss_w",
                        "min_scuffing_margin",
                    ],
                    rows.iter().map(|r| {
                        vec![
                            r.value,
                            r.cage_slip.unwrap_or(nan),
                            r.cage_speed_rad_s.unwrap_or(nan),
                            r.epicyclic_cage_speed_rad_s.unwrap_or(nan),
                            r.max_roller_load_n.unwrap_or(nan),
                            r.power_loss_w.unwrap_or(nan),
                            r.min_scuffing_margin.unwrap_or(nan),
                        ]
                    }),
                )?;
                let points: Vec<(f64, f64)> = rows
                    .iter()
                    .filter_map(|r| r.cage_slip.map(|s| (shown(r.value), s)))
                    .collect();
                line_plot(
                    &dir.join("cage_slip.svg"),
                    &Labels {
                        title: &format!("{}: cage slip (quasi-static)", model.bearing.name()),
                        x: label,
                        y: "cage slip ε0",
                    },
                    &[Series {
                        label: "",
                        points: &points,
                    }],
                )?;
            }
            if args.json {
                return print_json(&serde_json::json!({ "variable": key, "points": rows }));
            }
            println!(
                "{}: quasi-static cage slip, sweep over {label}",
                model.bearing.name()
            );
            for r in &rows {
                match (r.cage_slip, &r.error) {
                    (Some(s), _) => println!(
                        "  {:>10.1}  slip {:>9.5}  cage {:>8.2} rad/s  max roller load {:>8.1} N  loss {:>7.2} W",
                        shown(r.value),
                        s,
                        r.cage_speed_rad_s.unwrap_or(f64::NAN),
                        r.max_roller_load_n.unwrap_or(f64::NAN),
                        r.power_loss_w.unwrap_or(f64::NAN)
                    ),
                    (None, e) => println!(
                        "  {:>10.1}  failed: {}",
                        shown(r.value),
                        e.as_deref().unwrap_or("")
                    ),
                }
            }
            Ok(())
        }
        _ => Err(Failure::Input(
            "sweep one variable at a time (--speed, --outer-speed or --radial-load)".into(),
        )),
    }
}

fn print_point(name: &str, r: &SkidResult) {
    println!("{name}: quasi-static skidding");
    let line = |label: &str, value: String| println!("  {label:<32} {value}");
    line("cage speed", format!("{:.2} rad/s", r.cage_speed_rad_s));
    line(
        "epicyclic cage speed",
        format!("{:.2} rad/s", r.epicyclic_cage_speed_rad_s),
    );
    line("cage slip ε0", format!("{:.5}", r.cage_slip));
    line(
        "max roller load",
        format!(
            "{:.1} N ({} rollers loaded)",
            r.max_roller_load_n, r.loaded_rollers
        ),
    );
    line(
        "operating clearance",
        format!("{:.4} mm", r.operating_clearance_m * 1e3),
    );
    line("power loss", format!("{:.2} W", r.power_loss_w));
    line(
        "min scuffing margin s_cr/s",
        r.min_scuffing_margin
            .map_or("no maximum in range".into(), |m| format!("{m:.2}")),
    );
    line("solve time", format!("{:.2} ms", r.solve_time_s * 1e3));
}
