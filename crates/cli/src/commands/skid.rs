//! `rolldyn skid MODEL.toml`: quasi-static roller and cage skidding (SPEC §5, seed 001) at one
//! operating point, or a sweep over speed, outer-ring speed or radial load.

use crate::failure::Failure;
use crate::output::{load_model, print_json};
use rolldyn::output::{out_dir, write_csv};
use rolldyn_model::{Model, Temperatures};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::{
    QuasiStaticConditions, QuasiStaticOptions, SkidResult, SweepPoint, SweepVariable,
};
use rolldyn_setup::quasi_static::{
    LandChoice, QuasiStaticOverrides, RacewayFriction, cage_land_model, quasi_static_conditions,
};
use rolldyn_units::{AngularSpeed, Force, Quantity, QuantityRange, Temperature};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FrictionName {
    /// Muraki EHL traction with the mixed-friction blend (seed 000), rheology from the model.
    Muraki,
    /// Asperity fraction + film shear + flash temperature (seed 001).
    Seed001,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LandName {
    /// Finite journal bearing (docs/theory.md §7.5).
    Finite,
    /// Short (Ocvirk) journal bearing.
    Short,
}

#[derive(clap::Args)]
pub struct Args {
    /// Model file with [lubricant] (and optionally [operating]); the embedded 2002834 model when
    /// omitted.
    pub model: Option<PathBuf>,
    /// Inner-ring speed, or a sweep `1500rpm..4500rpm:500rpm`.
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<QuantityRange<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings), or a sweep.
    #[arg(long, allow_hyphen_values = true)]
    pub outer_speed: Option<QuantityRange<AngularSpeed>>,
    /// Radial load, or a sweep `100N..700N:50N`.
    #[arg(long, allow_hyphen_values = true)]
    pub radial_load: Option<QuantityRange<Force>>,
    /// Part temperatures, e.g. `inner=47.3C,outer=43C,cage=45C,oil=45C` (parts not given take
    /// the oil temperature).
    #[arg(long, value_parser = parse_temperatures)]
    pub temperatures: Option<Temperatures>,
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

fn parse_temperatures(text: &str) -> Result<Temperatures, String> {
    let mut parts = Temperatures::default();
    for item in text.split(',') {
        let (part, value) = item
            .split_once('=')
            .ok_or_else(|| format!("'{item}': expected part=temperature, e.g. inner=47.3C"))?;
        let t = Quantity::<Temperature>::parse(value)
            .map_err(|e| e.to_string())?
            .si();
        rolldyn_model::bounds::check_temperature(&format!("--temperatures {}", part.trim()), t)
            .map_err(|e| e.to_string())?;
        let slot = match part.trim() {
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
    }
    Ok(parts)
}

/// The values of a flag, SI.
fn values<D: rolldyn_units::Dim>(range: &Option<QuantityRange<D>>) -> Option<Vec<f64>> {
    range
        .as_ref()
        .map(|r| r.values.iter().map(|q| q.si()).collect())
}

/// The first value of a flag (the operating point of a sweep), SI.
fn single<D: rolldyn_units::Dim>(range: &Option<QuantityRange<D>>) -> Option<f64> {
    values(range).and_then(|v| v.first().copied())
}

/// Every value of a swept flag within the plausibility bounds (the first one is checked with
/// the operating point).
fn check_every_flag_value(args: &Args, model: &Model) -> Result<(), Failure> {
    let speeds = values(&args.speed)
        .unwrap_or_default()
        .into_iter()
        .map(|w| rolldyn_setup::FlagValues {
            speed: Some(w),
            ..Default::default()
        });
    let outer = values(&args.outer_speed)
        .unwrap_or_default()
        .into_iter()
        .map(|w| rolldyn_setup::FlagValues {
            outer_speed: Some(w),
            ..Default::default()
        });
    let loads = values(&args.radial_load)
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

/// The operating point of the model file, overridden by the flags (first value of a sweep).
fn conditions(args: &Args, model: &Model) -> Result<QuasiStaticConditions, Failure> {
    let overrides = QuasiStaticOverrides {
        speed: single(&args.speed),
        outer_speed: single(&args.outer_speed),
        radial_load: single(&args.radial_load),
        temperatures: args.temperatures.unwrap_or_default(),
        friction: match args.friction {
            FrictionName::Muraki => RacewayFriction::Muraki,
            FrictionName::Seed001 => RacewayFriction::Seed001,
        },
    };
    Ok(quasi_static_conditions(model, &overrides)?)
}

/// The variable swept by the flags and its values (SI), with its JSON/CSV key and plot label.
struct Swept {
    variable: SweepVariable,
    key: &'static str,
    label: &'static str,
    values: Vec<f64>,
}

impl Swept {
    /// The swept value as printed and plotted: rpm for speeds, N for the load.
    fn shown(&self, v: f64) -> f64 {
        if self.variable != SweepVariable::RadialLoad {
            v * 30.0 / std::f64::consts::PI
        } else {
            v
        }
    }
}

/// The flag given with more than one value, if any (a single value only overrides the
/// operating point); more than one swept flag is an error.
fn swept(args: &Args) -> Result<Option<Swept>, Failure> {
    let mut swept: Vec<Swept> = [
        (
            SweepVariable::InnerSpeed,
            "inner_speed_rad_s",
            "inner-ring speed, rpm",
            values(&args.speed),
        ),
        (
            SweepVariable::OuterSpeed,
            "outer_speed_rad_s",
            "outer-ring speed, rpm",
            values(&args.outer_speed),
        ),
        (
            SweepVariable::RadialLoad,
            "radial_load_n",
            "radial load, N",
            values(&args.radial_load),
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
}

/// A quasi-static failure: rejected input names the model file (exit 2), a failed iteration
/// or contact solve is a failed run (exit 1).
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

/// Solves the operating point, or the sweep, and prints it (text or JSON); a sweep also writes
/// its table and plot to `--out`.
pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?;
    let bearing = model
        .bearing
        .require_cylindrical("skid")
        .map_err(|reason| Failure::Input(format!("{}: {reason}", model.bearing.name())))?;
    check_every_flag_value(&args, &model)?;
    let base = conditions(&args, &model)?;
    let options = QuasiStaticOptions::default();
    let land = cage_land_model(
        bearing,
        match args.cage_land {
            LandName::Finite => LandChoice::Finite,
            LandName::Short => LandChoice::Short,
        },
    );
    let name = model.bearing.name();
    let Some(swept) = swept(&args)? else {
        let result =
            rolldyn_quasistatic::solve_with_land_model(bearing, &base, &options, land.as_ref())
                .map_err(|e| solve_failure(&model, e))?;
        if args.json {
            return print_json(&result);
        }
        print_point(name, &result);
        return Ok(());
    };
    let points = rolldyn_quasistatic::sweep(
        bearing,
        &base,
        &options,
        land.as_ref(),
        swept.variable,
        &swept.values,
    );
    if let Some(e) = rolldyn_quasistatic::sweep::all_failed(&points) {
        return Err(Failure::Input(format!(
            "every point of the sweep failed: {e}"
        )));
    }
    let rows: Vec<SweepRow> = points.iter().map(SweepRow::new).collect();
    if let Some(dir) = &args.out {
        write_sweep_files(&out_dir(dir)?, name, &swept, &rows)?;
    }
    if args.json {
        return print_json(&serde_json::json!({ "variable": swept.key, "points": rows }));
    }
    let drag_law = points
        .iter()
        .find_map(|p| p.result.as_ref().ok().map(|r| r.cage_drag_law.clone()))
        .unwrap_or_default();
    print_sweep(name, &swept, &rows, &drag_law);
    Ok(())
}

/// The sweep table (skid_sweep.csv, NaN where a point failed) and the cage-slip plot
/// (cage_slip.svg) in `dir`.
fn write_sweep_files(
    dir: &Path,
    name: &str,
    swept: &Swept,
    rows: &[SweepRow],
) -> Result<(), Failure> {
    let nan = f64::NAN;
    write_csv(
        &dir.join("skid_sweep.csv"),
        &[
            swept.key,
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
        .filter_map(|r| r.cage_slip.map(|s| (swept.shown(r.value), s)))
        .collect();
    line_plot(
        &dir.join("cage_slip.svg"),
        &Labels {
            title: &format!("{name}: cage slip (quasi-static)"),
            x: swept.label,
            y: "cage slip ε0",
        },
        &[Series {
            label: "",
            points: &points,
        }],
    )?;
    Ok(())
}

/// The sweep as a text table (speeds in rpm).
fn print_sweep(name: &str, swept: &Swept, rows: &[SweepRow], drag_law: &str) {
    println!("{name}: quasi-static cage slip, sweep over {}", swept.label);
    println!("  drag laws: {drag_law}");
    for r in rows {
        match (r.cage_slip, &r.error) {
            (Some(s), _) => println!(
                "  {:>10.1}  slip {:>9.5}  cage {:>8.2} rad/s  max roller load {:>8.1} N  loss {:>7.2} W",
                swept.shown(r.value),
                s,
                r.cage_speed_rad_s.unwrap_or(f64::NAN),
                r.max_roller_load_n.unwrap_or(f64::NAN),
                r.power_loss_w.unwrap_or(f64::NAN)
            ),
            (None, e) => println!(
                "  {:>10.1}  failed: {}",
                swept.shown(r.value),
                e.as_deref().unwrap_or("")
            ),
        }
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
    line("drag laws", r.cage_drag_law.clone());
    line(
        "min scuffing margin s_cr/s",
        r.min_scuffing_margin
            .map_or("no maximum in range".into(), |m| format!("{m:.2}")),
    );
    line("solve time", format!("{:.2} ms", r.solve_time_s * 1e3));
}
