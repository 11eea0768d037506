//! Loads: quasi-static load distribution of a double-row tapered bearing
//! (`rolldyn_quasistatic::tapered`, theory §6.8) under radial and axial load with a tilting
//! moment or an imposed misalignment: per row the ring displacements, the roller loads and the
//! load zone, and the balance checks. A cylindrical model is refused: its load distribution
//! runs inside `skid`.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::model_source::EMBEDDED_MODEL_NAME;
use crate::operating::Operating;
use crate::output::out_dir;
use crate::table::{Table, Tables};
use rolldyn_geometry::BearingModel;
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::QsError;
use rolldyn_quasistatic::tapered::{
    ROLLER_COLUMNS, TaperedLoadCase, TaperedLoadSettings, TaperedLoads, TiltCondition, roller_row,
    solve_tapered_loads,
};
use rolldyn_setup::FlagValues;
use rolldyn_units::{Moment, Quantity};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};

/// Largest accepted imposed misalignment: 1° (the seeds study 0…12′).
const MAX_MISALIGNMENT_RAD: f64 = std::f64::consts::PI / 180.0;

/// A load-distribution analysis: the operating point's overrides and the tilt condition.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LoadsRequest {
    /// Overrides of the model's `[operating]` and `[misalignment]` (speed, radial and axial
    /// load, misalignment; the others are refused).
    pub operating: Operating,
    /// Tilting moment on the inner rings in the plane of the bearing axis and the radial load
    /// (the tilt is then solved; excludes a misalignment).
    pub moment: Option<Quantity<Moment>>,
    /// Angular offset of row 1's rollers against row 0's as a fraction of the roller pitch,
    /// 0 ≤ f < 1.
    pub row_offset: f64,
    /// Folder for the per-roller table (CSV, Parquet) and the roller-load plot (SVG).
    pub out: Option<PathBuf>,
}

/// The load distribution and the load case it was solved for.
#[derive(Clone, Debug, Serialize)]
pub struct LoadsResult {
    pub model: String,
    pub radial_load_n: f64,
    pub axial_load_n: f64,
    pub inner_speed_rad_s: f64,
    /// The imposed misalignment (`None` when a moment was given).
    pub misalignment_rad: Option<f64>,
    pub result: TaperedLoads,
    /// Rollers per row and slices per roller, for the text.
    #[serde(skip)]
    rollers_per_row: usize,
    #[serde(skip)]
    slices: usize,
}

impl Tables for LoadsResult {
    /// `tapered_loads`: one row per roller (cone, cup and rib loads, edge loading); `rows`: one
    /// row per bearing row.
    fn tables(&self) -> Vec<Table> {
        let r = &self.result;
        let rollers: Vec<[f64; 11]> = r.rollers.iter().map(roller_row).collect();
        let mut table = Table::new("tapered_loads")
            .integer("row", r.rollers.iter().map(|x| x.row as i64).collect())
            .integer("roller", r.rollers.iter().map(|x| x.index as i64).collect());
        for (j, name) in ROLLER_COLUMNS.iter().enumerate().skip(2) {
            table = table.real(*name, rollers.iter().map(|x| x[j]).collect());
        }
        let rows = &r.rows;
        let rows_table = Table::new("rows")
            .integer("row", rows.iter().map(|x| x.row as i64).collect())
            .real("mid_z_m", rows.iter().map(|x| x.mid_z_m).collect())
            .real(
                "radial_displacement_x_m",
                rows.iter().map(|x| x.radial_displacement_m[0]).collect(),
            )
            .real(
                "radial_displacement_y_m",
                rows.iter().map(|x| x.radial_displacement_m[1]).collect(),
            )
            .real(
                "axial_displacement_m",
                rows.iter().map(|x| x.axial_displacement_m).collect(),
            )
            .real("tilt_x_rad", rows.iter().map(|x| x.tilt_rad[0]).collect())
            .real("tilt_y_rad", rows.iter().map(|x| x.tilt_rad[1]).collect())
            .integer(
                "loaded_rollers",
                rows.iter().map(|x| x.loaded_rollers as i64).collect(),
            )
            .real(
                "load_zone_half_angle_rad",
                rows.iter().map(|x| x.load_zone_half_angle_rad).collect(),
            )
            .integer(
                "max_roller",
                rows.iter().map(|x| x.max_roller as i64).collect(),
            )
            .real("max_cup_n", rows.iter().map(|x| x.max_cup_n).collect())
            .real("max_cone_n", rows.iter().map(|x| x.max_cone_n).collect())
            .real("max_rib_n", rows.iter().map(|x| x.max_rib_n).collect());
        vec![table, rows_table]
    }
}

/// The load analysis.
pub struct Loads;

impl Analysis for Loads {
    const NAME: &'static str = "loads";
    type Request = LoadsRequest;
    type Result = LoadsResult;

    fn run(request: &LoadsRequest, context: &Context<'_>) -> Result<LoadsResult, Failure> {
        let model = context.model.load()?;
        let BearingModel::Tapered(bearing) = &model.bearing else {
            let file = context
                .model
                .file()
                .map_or(EMBEDDED_MODEL_NAME.to_string(), |p| p.display().to_string());
            return Err(Failure::Input(format!(
                "{file}: bearing.kind: `loads` needs a double-row tapered bearing; the load distribution of a cylindrical bearing is part of `rolldyn skid`"
            )));
        };
        let case = load_case(request, &model)?;
        if !(0.0..1.0).contains(&request.row_offset) {
            return Err(Failure::Input(format!(
                "--row-offset: {} must lie in [0, 1) roller pitches",
                request.row_offset
            )));
        }
        let settings = TaperedLoadSettings {
            row1_offset_pitch: request.row_offset,
            ..TaperedLoadSettings::default()
        };
        let result = solve_tapered_loads(bearing, &case, &settings).map_err(|e| match e {
            QsError::NotConverged { .. } => Failure::Run(e.to_string()),
            _ => Failure::Input(e.to_string()),
        })?;
        if let Some(dir) = &request.out {
            write_outputs(&out_dir(dir)?, &result)?;
        }
        Ok(LoadsResult {
            model: model.bearing.name().to_string(),
            radial_load_n: case.radial_load_n,
            axial_load_n: case.axial_load_n,
            inner_speed_rad_s: case.inner_speed_rad_s,
            misalignment_rad: match case.tilt {
                TiltCondition::Imposed(t) => Some(t),
                TiltCondition::Moment(_) => None,
            },
            result,
            rollers_per_row: bearing.rollers_per_row,
            slices: bearing.roller.slice_count,
        })
    }
}

/// The load case from the model's `[operating]` and `[misalignment]` sections and the request.
pub(crate) fn load_case(
    request: &LoadsRequest,
    model: &rolldyn_model::Model,
) -> Result<TaperedLoadCase, Failure> {
    let o = request.operating.overrides();
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
    let tilt = match (request.moment, o.misalignment) {
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
            // an explicit misalignment imposes the tilt, 0 included (as the dynamics does);
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

impl fmt::Display for LoadsResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.result;
        let a = &r.checks.applied;
        writeln!(
            f,
            "{} — double-row tapered, quasi-static load distribution ({} Newton iterations)",
            self.model, r.iterations
        )?;
        writeln!(
            f,
            "  loads on the inner rings: F_r {:.0} N (+x), F_a {:.0} N (+z), M (x, y) ({:.1}, {:.1}) N·m{}",
            a[0],
            a[2],
            a[3],
            a[4],
            match self.misalignment_rad {
                Some(t) => format!(
                    " — the reaction to the imposed misalignment {:.2}′ about y",
                    arcmin(t)
                ),
                None => String::new(),
            }
        )?;
        writeln!(
            f,
            "  inner ring {:.1} rpm, cage {:.2} rad/s, centrifugal force {:.2} N per roller",
            self.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
            r.cage_speed_rad_s,
            r.centrifugal_force_n
        )?;
        let slices = self.slices as f64;
        for row in &r.rows {
            writeln!(
                f,
                "row {} (z = {:.2} mm): radial displacement ({:.3}, {:.3}) µm, axial {:.3} µm, tilt ({:.3}, {:.3})′",
                row.row,
                row.mid_z_m * 1e3,
                row.radial_displacement_m[0] * 1e6,
                row.radial_displacement_m[1] * 1e6,
                row.axial_displacement_m * 1e6,
                arcmin(row.tilt_rad[0]),
                arcmin(row.tilt_rad[1])
            )?;
            writeln!(
                f,
                "  loaded rollers {} of {}, load zone ±{:.1}°; most loaded roller {}: cup {:.0} N, cone {:.0} N, rib {:.0} N; cup carries ({:.0}, {:.0}, {:.0}) N",
                row.loaded_rollers,
                self.rollers_per_row,
                row.load_zone_half_angle_rad.to_degrees(),
                row.max_roller,
                row.max_cup_n,
                row.max_cone_n,
                row.max_rib_n,
                row.cup_force_n[0],
                row.cup_force_n[1],
                row.cup_force_n[2]
            )?;
            writeln!(
                f,
                "  {:>6} {:>9} {:>10} {:>10} {:>8} {:>12} {:>9}",
                "roller", "azimuth°", "cone N", "cup N", "rib N", "edge (cup)", "tilt′"
            )?;
            for x in r.rollers.iter().filter(|x| x.row == row.row) {
                let edge = if x.cup_n > 0.0 {
                    x.cup_slice_max_n * slices / x.cup_n
                } else {
                    0.0
                };
                writeln!(
                    f,
                    "  {:>6} {:>9.2} {:>10.1} {:>10.1} {:>8.1} {:>12.2} {:>9.3}",
                    x.index,
                    x.azimuth_rad.to_degrees(),
                    x.cone_n,
                    x.cup_n,
                    x.rib_n,
                    edge,
                    arcmin(x.tilt_rad)
                )?;
            }
        }
        let c = &r.checks;
        let five = |v: &[f64; 5]| {
            v.iter()
                .map(|x| format!("{x:.3e}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        writeln!(f, "sum checks (F_x, F_y, F_z [N], M_x, M_y [N·m]):")?;
        writeln!(
            f,
            "  inner ring: applied + cone and rib forces = ({})",
            five(&c.inner_ring_residual)
        )?;
        writeln!(
            f,
            "  cup side:   applied − cup forces − centrifugal = ({})",
            five(&c.cup_side_residual)
        )?;
        writeln!(f, "  largest relative residual {:.1e}", c.relative)?;
        write!(
            f,
            "  (edge = largest slice load × slices / roller load; 1 for an evenly loaded line)"
        )
    }
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
