//! `rolldyn loads MODEL.toml`: quasi-static load distribution of a double-row tapered bearing
//! (`rolldyn_quasistatic::tapered`) under radial and axial load with a tilting moment or an
//! imposed misalignment: per row the ring displacements, the roller loads and the load zone,
//! the balance checks; `--out` writes the per-roller table and a plot of the roller loads.
//! A cylindrical model is refused in one line: its load distribution runs inside
//! `rolldyn skid`.

use super::operating_args::OperatingArgs;
use crate::failure::Failure;
use crate::output::print_json;
use rolldyn::output::out_dir;
use rolldyn_geometry::{BearingModel, DoubleRowTaperedBearing};
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::QsError;
use rolldyn_quasistatic::tapered::{
    ROLLER_COLUMNS, TaperedLoadCase, TaperedLoadSettings, TaperedLoads, TiltCondition, roller_row,
    solve_tapered_loads,
};
use rolldyn_setup::FlagValues;
use rolldyn_units::{Moment, Quantity};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Largest accepted imposed misalignment: 1° (the seeds study 0…12′).
const MAX_MISALIGNMENT_RAD: f64 = std::f64::consts::PI / 180.0;

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) of a double-row tapered bearing.
    pub model: PathBuf,
    #[command(flatten)]
    pub operating: OperatingArgs,
    /// Tilting moment on the inner rings in the plane of the bearing axis and the radial load,
    /// e.g. 2000Nm (the tilt is then solved; excludes --misalignment).
    #[arg(long, allow_hyphen_values = true)]
    pub moment: Option<Quantity<Moment>>,
    /// Angular offset of row 1's rollers against row 0's as a fraction of the roller pitch,
    /// 0 ≤ f < 1 (0: a roller of each row on the load line; 0.5: the seed's stable state, one
    /// roller on the load line in one row and two straddling it in the other).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub row_offset: f64,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    /// Folder for the per-roller table (CSV, Parquet) and the roller-load plot (SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

#[derive(Serialize)]
struct Report<'a> {
    model: &'a str,
    radial_load_n: f64,
    axial_load_n: f64,
    inner_speed_rad_s: f64,
    misalignment_rad: Option<f64>,
    result: &'a TaperedLoads,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = crate::output::load_model(Some(&args.model))?;
    let BearingModel::Tapered(bearing) = &model.bearing else {
        return Err(Failure::Input(format!(
            "{}: bearing.kind: `loads` needs a double-row tapered bearing; the load distribution of a cylindrical bearing is part of `rolldyn skid`",
            args.model.display()
        )));
    };
    let case = load_case(&args, &model)?;
    if !(0.0..1.0).contains(&args.row_offset) {
        return Err(Failure::Input(format!(
            "--row-offset: {} must lie in [0, 1) roller pitches",
            args.row_offset
        )));
    }
    let settings = TaperedLoadSettings {
        row1_offset_pitch: args.row_offset,
        ..TaperedLoadSettings::default()
    };
    let result = solve_tapered_loads(bearing, &case, &settings).map_err(|e| match e {
        QsError::NotConverged { .. } => Failure::Run(e.to_string()),
        _ => Failure::Input(e.to_string()),
    })?;
    if let Some(dir) = &args.out {
        write_outputs(&out_dir(dir)?, &result)?;
    }
    let misalignment = match case.tilt {
        TiltCondition::Imposed(t) => Some(t),
        TiltCondition::Moment(_) => None,
    };
    if args.json {
        return print_json(&Report {
            model: model.bearing.name(),
            radial_load_n: case.radial_load_n,
            axial_load_n: case.axial_load_n,
            inner_speed_rad_s: case.inner_speed_rad_s,
            misalignment_rad: misalignment,
            result: &result,
        });
    }
    print_text(model.bearing.name(), bearing, &case, &result);
    Ok(())
}

/// The load case from the model's `[operating]` and `[misalignment]` sections and the flags.
fn load_case(args: &Args, model: &rolldyn_model::Model) -> Result<TaperedLoadCase, Failure> {
    let o = args.operating.overrides();
    for (flag, given) in [
        ("--outer-speed", o.outer_speed.is_some()),
        ("--load-direction", o.load_direction.is_some()),
        ("--oil-temperature", o.oil_temperature.is_some()),
    ] {
        if given {
            return Err(Failure::Input(format!(
                "{flag}: not used by `loads` (a fixed cup, a fixed radial load, no friction)"
            )));
        }
    }
    FlagValues {
        speed: o.speed,
        radial_load: o.radial_load,
        ..FlagValues::default()
    }
    .check(model)?;
    let op = &model.operating;
    let tilt = match (args.moment, o.misalignment) {
        (Some(_), Some(_)) => {
            return Err(Failure::Input(
                "--moment, --misalignment: give one — a moment leaves the tilt free, a misalignment imposes it".into(),
            ));
        }
        (Some(m), None) => TiltCondition::Moment([0.0, m.si()]),
        (None, given) => {
            let t = given.unwrap_or(model.bearing.misalignment().inner_ring_tilt);
            if !(t.abs() <= MAX_MISALIGNMENT_RAD) {
                return Err(Failure::Input(format!(
                    "--misalignment: {:.2}′ lies outside ±60′",
                    t.to_degrees() * 60.0
                )));
            }
            // an explicit --misalignment imposes the tilt, 0 included (as the dynamics does);
            // without it, a model without misalignment leaves the ring free of moment
            if t == 0.0 && given.is_none() {
                TiltCondition::Moment([0.0; 2])
            } else {
                TiltCondition::Imposed(t)
            }
        }
    };
    Ok(TaperedLoadCase {
        radial_load_n: o.radial_load.or(op.radial_load).unwrap_or(0.0),
        axial_load_n: o.axial_load.or(op.axial_load).unwrap_or(0.0),
        tilt,
        inner_speed_rad_s: o.speed.or(op.inner_speed).unwrap_or(0.0),
    })
}

fn arcmin(rad: f64) -> f64 {
    rad.to_degrees() * 60.0
}

fn print_text(name: &str, b: &DoubleRowTaperedBearing, case: &TaperedLoadCase, r: &TaperedLoads) {
    let a = &r.checks.applied;
    println!(
        "{name} — double-row tapered, quasi-static load distribution ({} Newton iterations)",
        r.iterations
    );
    println!(
        "  loads on the inner rings: F_r {:.0} N (+x), F_a {:.0} N (+z), M (x, y) ({:.1}, {:.1}) N·m{}",
        a[0],
        a[2],
        a[3],
        a[4],
        match case.tilt {
            TiltCondition::Imposed(t) => format!(
                " — the reaction to the imposed misalignment {:.2}′ about y",
                arcmin(t)
            ),
            TiltCondition::Moment(_) => String::new(),
        }
    );
    println!(
        "  inner ring {:.1} rpm, cage {:.2} rad/s, centrifugal force {:.2} N per roller",
        case.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
        r.cage_speed_rad_s,
        r.centrifugal_force_n
    );
    let slices = b.roller.slice_count as f64;
    for row in &r.rows {
        println!(
            "row {} (z = {:.2} mm): radial displacement ({:.3}, {:.3}) µm, axial {:.3} µm, tilt ({:.3}, {:.3})′",
            row.row,
            row.mid_z_m * 1e3,
            row.radial_displacement_m[0] * 1e6,
            row.radial_displacement_m[1] * 1e6,
            row.axial_displacement_m * 1e6,
            arcmin(row.tilt_rad[0]),
            arcmin(row.tilt_rad[1])
        );
        println!(
            "  loaded rollers {} of {}, load zone ±{:.1}°; most loaded roller {}: cup {:.0} N, cone {:.0} N, rib {:.0} N; cup carries ({:.0}, {:.0}, {:.0}) N",
            row.loaded_rollers,
            b.rollers_per_row,
            row.load_zone_half_angle_rad.to_degrees(),
            row.max_roller,
            row.max_cup_n,
            row.max_cone_n,
            row.max_rib_n,
            row.cup_force_n[0],
            row.cup_force_n[1],
            row.cup_force_n[2]
        );
        println!(
            "  {:>6} {:>9} {:>10} {:>10} {:>8} {:>12} {:>9}",
            "roller", "azimuth°", "cone N", "cup N", "rib N", "edge (cup)", "tilt′"
        );
        for x in r.rollers.iter().filter(|x| x.row == row.row) {
            let edge = if x.cup_n > 0.0 {
                x.cup_slice_max_n * slices / x.cup_n
            } else {
                0.0
            };
            println!(
                "  {:>6} {:>9.2} {:>10.1} {:>10.1} {:>8.1} {:>12.2} {:>9.3}",
                x.index,
                x.azimuth_rad.to_degrees(),
                x.cone_n,
                x.cup_n,
                x.rib_n,
                edge,
                arcmin(x.tilt_rad)
            );
        }
    }
    let c = &r.checks;
    let fmt = |v: &[f64; 5]| {
        v.iter()
            .map(|x| format!("{x:.3e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    println!("sum checks (F_x, F_y, F_z [N], M_x, M_y [N·m]):");
    println!(
        "  inner ring: applied + cone and rib forces = ({})",
        fmt(&c.inner_ring_residual)
    );
    println!(
        "  cup side:   applied − cup forces − centrifugal = ({})",
        fmt(&c.cup_side_residual)
    );
    println!("  largest relative residual {:.1e}", c.relative);
    println!("  (edge = largest slice load × slices / roller load; 1 for an evenly loaded line)");
}

/// `tapered_loads.csv`/`.parquet` and `roller_loads.svg` in `dir`.
fn write_outputs(dir: &Path, r: &TaperedLoads) -> Result<(), Failure> {
    let fail = |e: rolldyn_output::OutputError| Failure::Run(e.to_string());
    let names: Vec<String> = ROLLER_COLUMNS.iter().map(|s| s.to_string()).collect();
    let mut table =
        TableWriter::create(dir, "tapered_loads", &names, Formats::default()).map_err(fail)?;
    for x in &r.rollers {
        table.write_row(&roller_row(x)).map_err(fail)?;
    }
    table.finish().map_err(fail)?;
    let curves: Vec<(String, Vec<(f64, f64)>)> = (0..2)
        .map(|k| {
            let mut points: Vec<(f64, f64)> = r
                .rollers
                .iter()
                .filter(|x| x.row == k)
                .map(|x| (x.azimuth_rad.to_degrees(), x.cup_n))
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            (format!("row {k} (cup load)"), points)
        })
        .collect();
    line_plot(
        &dir.join("roller_loads.svg"),
        &Labels {
            title: "Roller loads on the cup vs azimuth from the radial load",
            x: "azimuth, °",
            y: "roller load, N",
        },
        &Series::from_pairs(&curves),
    )?;
    Ok(())
}
