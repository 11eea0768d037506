//! Validation studies: re-runs a seed's study, returns its tables (Markdown text as in
//! VALIDATION.md, and the CSV tables as columns) and writes CSV tables and SVG plots — seed 004
//! contact (V-01, V-02, slices vs Boussinesq), skidding (V-06, V-18), the rib shape of 2002834
//! (seed 000 §3.1.1.7) and the end–rib limit force of the tapered bearing (seed 000 §3.2.2,
//! Figs. 3.84–3.88; SPEC §6.7).

use crate::analysis::{Analysis, Context};
use crate::contact::plot_pressure_map;
use crate::failure::Failure;
use crate::model_source::ModelSource;
use crate::observer::Progress;
use crate::output::{out_dir, sub_dir, write_csv};
use crate::table::{Table, Tables};
use rolldyn_geometry::{BearingModel, DoubleRowTaperedBearing, TaperedRibFace};
use rolldyn_plot::{Field, Labels, MapLabels, Series, line_plot, map_plot};
use rolldyn_quasistatic::QuasiStaticOptions;
use rolldyn_quasistatic::studies::{self, NviTraction, StudyRow};
use rolldyn_units::{Length, Quantity};
use rolldyn_validation::end_rib_limit::{
    self, HertzCheck, LimitRow, PressureMap, SEED_PRESSURE_MAPS, Settings, face_label, face_slug,
};
use rolldyn_validation::rib_shape::{self, POSITION_BIN_M, POSITION_BINS, RibShapeRow};
use rolldyn_validation::seed004::{self, LOADS_N, PROFILES, TILTS_ARCMIN};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// A line of the study's text.
macro_rules! say {
    ($t:expr) => {
        $t.text.push('\n')
    };
    ($t:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($t.text, $($arg)*);
    }};
}

/// Text of the study without a line end.
macro_rules! put {
    ($t:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = write!($t.text, $($arg)*);
    }};
}

/// Which study.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum StudyName {
    /// Seed 004: grid study (V-01), profile study (V-02), slices vs Boussinesq.
    Seed004,
    /// Seed 000 V-06 and seed 001 V-18: quasi-static cage slip of the O'Brien–Taylor bearing and
    /// of an intershaft bearing.
    Skidding,
    /// Seed 000 §3.1.1.7: flat vs convex (R 430 mm, R 37.5 mm) inner-ring rib faces of 2002834 —
    /// where the roller end touches the rib and how fast it slides there (6-DOF dynamics of the
    /// variants of examples/2002834/rib-shape.toml; run from the workspace root).
    RibShape,
    /// Seed 000 §3.2.2: limit force of the roller large end on the cone's large rib against
    /// the reduced curvature (Boussinesq patch reaching the projection of the faces), with the
    /// pressure fields of Figs. 3.84–3.87; MODEL defaults to examples/tapered-cassette.toml.
    EndRibLimit,
}

/// A study; the model (of `end-rib-limit` only) is the context's, the file
/// `examples/tapered-cassette.toml` when the context gives none.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyRequest {
    pub study: StudyName,
    /// Folder for CSV tables and SVG plots.
    #[serde(default = "validation_folder")]
    pub out: PathBuf,
    /// Cage revolutions per variant for `rib-shape` (the first is discarded as start transient).
    #[serde(default = "four")]
    pub revolutions: f64,
    /// Square cell size of the tangent-plane grid of `end-rib-limit`.
    #[serde(default = "cell")]
    pub cell: Quantity<Length>,
}

fn validation_folder() -> PathBuf {
    PathBuf::from("docs/validation")
}

fn four() -> f64 {
    4.0
}

fn cell() -> Quantity<Length> {
    Quantity::from_si(0.05e-3)
}

/// The text and tables a study gathers as it runs.
#[derive(Default)]
struct Out {
    text: String,
    tables: Vec<Table>,
}

impl Out {
    /// Writes a CSV table and keeps it as a table named by its file stem.
    fn csv(
        &mut self,
        path: &Path,
        header: &[&str],
        rows: impl Iterator<Item = Vec<f64>>,
    ) -> Result<(), Failure> {
        let rows: Vec<Vec<f64>> = rows.collect();
        write_csv(path, header, rows.iter().cloned())?;
        let mut table = Table::new(
            path.file_stem()
                .map_or(String::new(), |s| s.to_string_lossy().into_owned()),
        );
        for (j, name) in header.iter().enumerate() {
            table = table.real(*name, rows.iter().map(|r| r[j]).collect());
        }
        self.tables.push(table);
        Ok(())
    }
}

/// The end–rib limit study's answer (what `study end-rib-limit --json` prints).
#[derive(Clone, Debug, Serialize)]
pub struct EndRibLimitResult {
    pub model: String,
    pub cell_m: f64,
    pub limits: Vec<LimitJson>,
    pub pressure_maps: Vec<MapJson>,
    pub run_time_s: f64,
    #[serde(skip)]
    pub text: String,
    #[serde(skip)]
    pub tables: Vec<Table>,
}

/// The tables of another study: its text and its CSV tables.
#[derive(Clone, Debug, Serialize)]
pub struct StudyTables {
    pub study: String,
    pub out: String,
    #[serde(skip)]
    pub text: String,
    #[serde(skip)]
    pub tables: Vec<Table>,
}

/// What a study found.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum StudyResult {
    EndRibLimit(EndRibLimitResult),
    Tables(StudyTables),
}

impl Tables for StudyResult {
    fn tables(&self) -> Vec<Table> {
        match self {
            StudyResult::EndRibLimit(r) => r.tables.clone(),
            StudyResult::Tables(r) => r.tables.clone(),
        }
    }
}

impl fmt::Display for StudyResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            StudyResult::EndRibLimit(r) => &r.text,
            StudyResult::Tables(r) => &r.text,
        };
        f.write_str(text.trim_end_matches('\n'))
    }
}

/// A validation study.
pub struct Study;

impl Analysis for Study {
    const NAME: &'static str = "study";
    type Request = StudyRequest;
    type Result = StudyResult;

    fn run(request: &StudyRequest, context: &Context<'_>) -> Result<StudyResult, Failure> {
        let model = match &context.model {
            ModelSource::Embedded => None,
            source => Some(
                source
                    .file()
                    .map(Path::to_path_buf)
                    .ok_or_else(|| Failure::Input("a study reads a model file".into()))?,
            ),
        };
        if model.is_some() && request.study != StudyName::EndRibLimit {
            return Err(Failure::Input(
                "a model file is read by `study end-rib-limit` only".into(),
            ));
        }
        let dir = out_dir(&request.out)?;
        let mut t = Out::default();
        if request.study == StudyName::EndRibLimit {
            let path = model.unwrap_or_else(|| PathBuf::from(end_rib_limit::DEFAULT_MODEL));
            let mut result = end_rib_limit(&path, &dir, request.cell.si(), &mut t)?;
            result.text = t.text;
            result.tables = t.tables;
            return Ok(StudyResult::EndRibLimit(result));
        }
        match request.study {
            StudyName::Seed004 => seed004_study(&dir, &mut t)?,
            StudyName::Skidding => skidding_study(&dir, &mut t)?,
            StudyName::RibShape => rib_shape_study(&dir, request.revolutions, &mut t, context)?,
            StudyName::EndRibLimit => unreachable!("answered above"),
        }
        Ok(StudyResult::Tables(StudyTables {
            study: format!("{:?}", request.study),
            out: dir.display().to_string(),
            text: t.text,
            tables: t.tables,
        }))
    }
}

fn mm_mpa(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.0 * 1e3, p.1 * 1e-6)).collect()
}

fn seed004_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    grid_study(dir, t)?;
    profile_study(dir, t)?;
    concentration_study(dir, t)?;
    slices_study(dir, t)
}

fn grid_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    say!(
        t,
        "## V-01 seed 004 Table 2 at 1167 N (crowned 3.2 µm, no skew)\n"
    );
    say!(
        t,
        "| grid | seed approach mm | rolldyn | err | seed p_max MPa | rolldyn | err | seed p_mid MPa | rolldyn | err | iterations | solve ms |"
    );
    say!(t, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    let rows = seed004::grid_study(1167.0);
    let err = |a: f64, b: f64| 100.0 * (a - b) / b;
    let mut series = Vec::new();
    for (seed, r) in &rows {
        say!(
            t,
            "| {}/{} | {:.6} | {:.6} | {:+.1} % | {:.0} | {:.0} | {:+.1} % | {:.0} | {:.0} | {:+.1} % | {} | {:.2} |",
            seed.cells_along,
            seed.cells_across,
            seed.approach_mm,
            r.approach_m * 1e3,
            err(r.approach_m * 1e3, seed.approach_mm),
            seed.max_pressure_mpa,
            r.max_pressure_pa * 1e-6,
            err(r.max_pressure_pa * 1e-6, seed.max_pressure_mpa),
            seed.mid_pressure_mpa,
            r.mid_pressure_pa * 1e-6,
            err(r.mid_pressure_pa * 1e-6, seed.mid_pressure_mpa),
            r.iterations,
            r.solve_time_s * 1e3
        );
        series.push((
            format!("{}/{}", seed.cells_along, seed.cells_across),
            mm_mpa(&r.central_line),
        ));
    }
    t.csv(
        &dir.join("v01-grid-study.csv"),
        &[
            "cells_along",
            "cells_across",
            "seed_approach_m",
            "approach_m",
            "seed_max_pressure_pa",
            "max_pressure_pa",
            "seed_mid_pressure_pa",
            "mid_pressure_pa",
            "iterations",
        ],
        rows.iter().map(|(s, r)| {
            vec![
                s.cells_along as f64,
                s.cells_across as f64,
                s.approach_mm * 1e-3,
                r.approach_m,
                s.max_pressure_mpa * 1e6,
                r.max_pressure_pa,
                s.mid_pressure_mpa * 1e6,
                r.mid_pressure_pa,
                r.iterations as f64,
            ]
        }),
    )?;
    let plotted = Series::from_pairs(&series);
    line_plot(
        &dir.join("v01-grid-study.svg"),
        &Labels {
            title: "Seed 004 Table 2 grids, crowned 3.2 µm, 1167 N: pressure along the contact line",
            x: "x along the roller, mm",
            y: "pressure, MPa",
        },
        &plotted,
    )?;
    let finest = &rows.last().expect("seven grids").1;
    if let Some(map) = &finest.map {
        plot_pressure_map(
            &dir.join("v01-pressure-map-350x9.svg"),
            "Pressure map, 350 × 9 cells, 1167 N, MPa",
            map,
        )?;
    }
    let stated = seed004::solve(seed004::TABLE2_PROFILE, 0.0, 2334.0, 150, 3);
    say!(
        t,
        "\nAt the stated 2334 N (150/3): approach {:.5} mm, p_max {:.0} MPa, p_mid {:.0} MPa.\n",
        stated.approach_m * 1e3,
        stated.max_pressure_pa * 1e-6,
        stated.mid_pressure_pa * 1e-6
    );
    Ok(())
}

fn profile_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    let cases = seed004::profile_study(150, 15, 0.45e-3);
    say!(
        t,
        "## V-02 profile study (150 × 15 cells over 7.5 × 0.45 mm)\n"
    );
    say!(
        t,
        "| profile | load N | skew ′ | p_max MPa | p_mid MPa | K | edge ratio |"
    );
    say!(t, "|---|---|---|---|---|---|---|");
    for c in &cases {
        say!(
            t,
            "| {} | {:.0} | {:.0} | {:.0} | {:.0} | {:.3} | {} |",
            PROFILES[c.profile].1,
            c.load_n,
            c.tilt_arcmin,
            c.report.max_pressure_pa * 1e-6,
            c.report.mid_pressure_pa * 1e-6,
            c.report.concentration_factor,
            c.edge_ratio(0.3)
                .map_or("middle unloaded".to_string(), |r| format!("{r:.3}"))
        );
    }
    t.csv(
        &dir.join("v02-profile-study.csv"),
        &[
            "profile",
            "load_n",
            "skew_arcmin",
            "max_pressure_pa",
            "mid_pressure_pa",
            "concentration_factor",
            "edge_ratio",
        ],
        cases.iter().map(|c| {
            vec![
                (c.profile + 1) as f64,
                c.load_n,
                c.tilt_arcmin,
                c.report.max_pressure_pa,
                c.report.mid_pressure_pa,
                c.report.concentration_factor,
                c.edge_ratio(0.3).unwrap_or(f64::NAN),
            ]
        }),
    )?;
    for load in LOADS_N {
        for tilt in TILTS_ARCMIN {
            let curves: Vec<(&str, Vec<(f64, f64)>)> = cases
                .iter()
                .filter(|c| c.load_n == load && c.tilt_arcmin == tilt)
                .map(|c| (PROFILES[c.profile].1, mm_mpa(&c.report.central_line)))
                .collect();
            let series = Series::from_pairs(&curves);
            line_plot(
                &dir.join(format!("v02-profiles-{load:.0}N-{tilt:.0}arcmin.svg")),
                &Labels {
                    title: &format!(
                        "Seed 004 profiles, {load:.0} N, skew {tilt:.0}′: pressure along the contact line"
                    ),
                    x: "x along the roller, mm",
                    y: "pressure, MPa",
                },
                &series,
            )?;
        }
    }
    say!(t);
    Ok(())
}

fn concentration_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    let loads: Vec<f64> = (2..=24).map(|k| 125.0 * k as f64).collect();
    let k = seed004::concentration_vs_load(&loads, 300, 61, 0.45e-3);
    say!(
        t,
        "## V-02 concentration factor K = p_max/p̄ vs load, no skew (300 × 61 cells)\n"
    );
    put!(t, "| load N |");
    PROFILES.iter().for_each(|p| put!(t, " {} |", p.1));
    say!(t, "\n|---|---|---|---|---|---|");
    for (i, q) in loads.iter().enumerate() {
        put!(t, "| {q:.0} |");
        k.iter().for_each(|rows| put!(t, " {:.3} |", rows[i].1));
        say!(t);
    }
    t.csv(
        &dir.join("v02-concentration-factor.csv"),
        &[
            "load_n",
            "k_straight",
            "k_crowned_3_2um",
            "k_crowned_6_5um",
            "k_log_small",
            "k_log_large",
        ],
        loads.iter().enumerate().map(|(i, &q)| {
            let mut row = vec![q];
            row.extend(k.iter().map(|rows| rows[i].1));
            row
        }),
    )?;
    let series: Vec<Series> = k
        .iter()
        .zip(PROFILES.iter())
        .map(|(rows, p)| Series {
            label: p.1,
            points: rows,
        })
        .collect();
    line_plot(
        &dir.join("v02-concentration-factor.svg"),
        &Labels {
            title: "Seed 004: stress concentration factor K = p_max / p_mean, no skew",
            x: "roller load, N",
            y: "K",
        },
        &series,
    )?;
    say!(t);
    Ok(())
}

fn slices_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    say!(
        t,
        "## Slices (ISO/TS 16281 laminae, 30 slices) vs Boussinesq (150 × 15), 1167 N, no skew\n"
    );
    say!(
        t,
        "| profile | approach slices µm | Boussinesq µm | diff | p_max slices MPa | Boussinesq MPa | diff |"
    );
    say!(t, "|---|---|---|---|---|---|---|");
    let mut rows = Vec::new();
    for (index, profile) in PROFILES.iter().enumerate() {
        let s = seed004::slices_vs_boussinesq(index, 1167.0, 150, 15, 0.45e-3);
        let diff = |a: f64, b: f64| 100.0 * (a - b) / b;
        say!(
            t,
            "| {} | {:.3} | {:.3} | {:+.1} % | {:.0} | {:.0} | {:+.1} % |",
            profile.1,
            s.slices.approach_m * 1e6,
            s.boussinesq.approach_m * 1e6,
            diff(s.slices.approach_m, s.boussinesq.approach_m),
            s.slices.max_pressure_pa * 1e-6,
            s.boussinesq.max_pressure_pa * 1e-6,
            diff(s.slices.max_pressure_pa, s.boussinesq.max_pressure_pa)
        );
        rows.push(vec![
            (index + 1) as f64,
            s.slices.approach_m,
            s.boussinesq.approach_m,
            s.slices.max_pressure_pa,
            s.boussinesq.max_pressure_pa,
        ]);
        let to_n_per_mm = |p: &[(f64, f64)]| {
            p.iter()
                .map(|q| (q.0 * 1e3, q.1 * 1e-3))
                .collect::<Vec<_>>()
        };
        let (a, b) = (
            to_n_per_mm(&s.slice_line_load),
            to_n_per_mm(&s.boussinesq_line_load),
        );
        line_plot(
            &dir.join(format!("slices-vs-boussinesq-{}.svg", index + 1)),
            &Labels {
                title: &format!("Load per length along the roller, {}, 1167 N", profile.1),
                x: "x along the roller, mm",
                y: "load per length, N/mm",
            },
            &[
                Series {
                    label: "slices (ISO/TS 16281)",
                    points: &a,
                },
                Series {
                    label: "Boussinesq",
                    points: &b,
                },
            ],
        )?;
    }
    t.csv(
        &dir.join("slices-vs-boussinesq.csv"),
        &[
            "profile",
            "approach_slices_m",
            "approach_boussinesq_m",
            "max_pressure_slices_pa",
            "max_pressure_boussinesq_pa",
        ],
        rows.into_iter(),
    )?;
    say!(t, "\nPlots and CSV tables written to {}", dir.display());
    Ok(())
}

fn skid_rows_csv(t: &mut Out, path: &Path, rows: &[StudyRow]) -> Result<(), Failure> {
    let nan = f64::NAN;
    t.csv(
        path,
        &[
            "inner_speed_rpm",
            "outer_speed_rpm",
            "radial_load_n",
            "misalignment_arcmin",
            "temperature_c",
            "cage_slip",
            "cage_speed_rad_s",
            "epicyclic_cage_speed_rad_s",
            "max_roller_load_n",
            "max_inner_slide_roll",
            "max_outer_slide_roll",
            "power_loss_w",
        ],
        rows.iter().map(|r| {
            vec![
                r.inner_speed_rpm,
                r.outer_speed_rpm,
                r.radial_load_n,
                r.misalignment_arcmin,
                r.temperature_c,
                r.cage_slip.unwrap_or(nan),
                r.cage_speed_rad_s.unwrap_or(nan),
                r.epicyclic_cage_speed_rad_s,
                r.max_roller_load_n.unwrap_or(nan),
                r.max_inner_slide_roll.unwrap_or(nan),
                r.max_outer_slide_roll.unwrap_or(nan),
                r.power_loss_w.unwrap_or(nan),
            ]
        }),
    )
}

/// Cage slip (fraction of the epicyclic speed) of `rows` grouped by inner speed, against `x(row)`.
fn slip_curves(rows: &[StudyRow], x: impl Fn(&StudyRow) -> f64) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut speeds: Vec<f64> = rows.iter().map(|r| r.inner_speed_rpm).collect();
    speeds.dedup();
    speeds
        .iter()
        .map(|&n| {
            let points = rows
                .iter()
                .filter(|r| r.inner_speed_rpm == n)
                .filter_map(|r| r.cage_slip.map(|s| (x(r), s)))
                .collect();
            (format!("{n:.0} rpm"), points)
        })
        .collect()
}

fn skidding_study(dir: &Path, t: &mut Out) -> Result<(), Failure> {
    let options = QuasiStaticOptions::default();
    let model = rolldyn_model::parse(
        include_str!("../../../examples/obrien-taylor.toml"),
        "examples/obrien-taylor.toml",
    )?;
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Err(Failure::Run(
            "the O'Brien–Taylor example is a cylindrical bearing".into(),
        ));
    };
    // the model's drag inputs (cage drag, oil volume fraction, roller drag) at each speed's oil
    // temperature, as the dynamics uses them
    let mut drag = std::collections::HashMap::new();
    for n in studies::OBRIEN_TAYLOR_SPEEDS_RPM {
        let t = studies::obrien_taylor_temperature_c(n) + 273.15;
        drag.insert(
            t.to_bits(),
            rolldyn_setup::quasi_static::drag_inputs(&model, t)?,
        );
    }
    for (name, value) in rolldyn_setup::drag_and_land_inputs(&model) {
        say!(t, "{name}: {value}");
    }
    for (traction, stem, label) in [
        (
            NviTraction::Seed000Elastic,
            "v06-obrien-taylor",
            "elastic-only traction (V-06 inputs)",
        ),
        (
            NviTraction::MaxwellEyring { tau0_pa: 5e6 },
            "v06-obrien-taylor-eyring",
            "Maxwell–Eyring traction, τ0 = 5 MPa (assumed)",
        ),
    ] {
        let rows =
            studies::obrien_taylor(bearing, traction, &options, &|t| drag[&t.to_bits()].clone());
        skid_rows_csv(t, &dir.join(format!("{stem}.csv")), &rows)?;
        // Per speed the study runs the load series (aligned), then the misalignment series at
        // 201 N.
        let loads = studies::OBRIEN_TAYLOR_LOADS_N.len();
        let mut seen = std::collections::HashMap::new();
        let (aligned, tilted): (Vec<StudyRow>, Vec<StudyRow>) = rows.into_iter().partition(|r| {
            let count = seen.entry(r.inner_speed_rpm.to_bits()).or_insert(0usize);
            *count += 1;
            *count <= loads
        });
        say!(t, "## V-06 O'Brien–Taylor, quasi-static, {label}\n");
        say!(
            t,
            "| speed rpm | oil °C | load N | cage slip | max roller load N | failed |"
        );
        say!(t, "|---|---|---|---|---|---|");
        for r in &aligned {
            say!(
                t,
                "| {:.0} | {:.1} | {:.0} | {} | {} | {} |",
                r.inner_speed_rpm,
                r.temperature_c,
                r.radial_load_n,
                r.cage_slip.map_or("—".into(), |s| format!("{:.6}", s)),
                r.max_roller_load_n
                    .map_or("—".into(), |q| format!("{q:.1}")),
                r.error.as_deref().unwrap_or("")
            );
        }
        let curves = slip_curves(&aligned, |r| r.radial_load_n);
        line_plot(
            &dir.join(format!("{stem}-load.svg")),
            &Labels {
                title: &format!("O'Brien–Taylor cage slip vs radial load, {label}"),
                x: "radial load, N",
                y: "cage slip (fraction)",
            },
            &Series::from_pairs(&curves),
        )?;
        let curves = slip_curves(&tilted, |r| r.misalignment_arcmin);
        line_plot(
            &dir.join(format!("{stem}-misalignment.svg")),
            &Labels {
                title: &format!("O'Brien–Taylor cage slip vs misalignment at 201 N, {label}"),
                x: "misalignment, arcmin",
                y: "cage slip (fraction)",
            },
            &Series::from_pairs(&curves),
        )?;
        say!(t);
    }
    let intershaft = studies::intershaft_bearing();
    let rotor = studies::intershaft_rotor_slip(
        &intershaft,
        &[1000.0, 2000.0, 4000.0, 6000.0, 8000.0],
        500.0,
        &options,
    );
    let load =
        studies::intershaft_load(&intershaft, &[50.0, 200.0, 400.0, 800.0, 1600.0], &options);
    for (rows, stem, title) in [
        (
            &rotor,
            "v18-intershaft-rotor-slip",
            "outer ring 13 067 rpm, 500 N",
        ),
        (&load, "v18-intershaft-load", "5180 / 11 313 rpm"),
    ] {
        skid_rows_csv(t, &dir.join(format!("{stem}.csv")), rows)?;
        say!(t, "## V-18 intershaft (assumed geometry), {title}\n");
        say!(
            t,
            "| inner rpm | outer rpm | load N | cage slip | max outer slide-roll | failed |"
        );
        say!(t, "|---|---|---|---|---|---|");
        for r in rows.iter() {
            say!(
                t,
                "| {:.0} | {:.0} | {:.0} | {} | {} | {} |",
                r.inner_speed_rpm,
                r.outer_speed_rpm,
                r.radial_load_n,
                r.cage_slip.map_or("—".into(), |s| format!("{s:.5}")),
                r.max_outer_slide_roll
                    .map_or("—".into(), |s| format!("{s:.2e}")),
                r.error.as_deref().unwrap_or("")
            );
        }
        say!(t);
    }
    say!(t, "Plots and CSV tables written to {}", dir.display());
    Ok(())
}

/// Seed 000 §3.1.1.7 (SPEC V-21): rib-shape study, `rib-shape.csv` and `rib-shape.svg` in `dir`.
fn rib_shape_study(
    dir: &Path,
    revolutions: f64,
    t: &mut Out,
    context: &Context<'_>,
) -> Result<(), Failure> {
    if !(revolutions > 1.0 && revolutions.is_finite()) {
        return Err(Failure::Input(format!(
            "--revolutions {revolutions}: need more than 1 (the first is discarded)"
        )));
    }
    let settings = rib_shape::Settings {
        revolutions,
        ..rib_shape::Settings::default()
    };
    let sweep = Path::new(rib_shape::SWEEP_FILE);
    if !sweep.is_file() {
        return Err(Failure::Input(format!(
            "{}: not found — run `rolldyn study rib-shape` from the workspace root",
            sweep.display()
        )));
    }
    say!(
        t,
        "## Seed 000 §3.1.1.7 rib shape, 2002834 ({} cage revolutions, the first discarded)\n",
        revolutions
    );
    say!(
        t,
        "| variant | rib face | misalignment ′ | mean edge distance mm | min mm | force share on the edge | max force N | mean sliding m/s | max sliding m/s | μ | power W (mean / max) | film share | |yaw| mrad | |pitch| mrad |"
    );
    say!(
        t,
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    let arcmin = |rad: f64| rad.to_degrees() * 60.0;
    let total = rolldyn_sweep::SweepFile::load(sweep).map_or(0, |s| s.variants.len());
    let mut done = 0;
    let rows = rib_shape::run(sweep, &settings, &|_| true, &mut |r| {
        done += 1;
        context.observer.progress(&Progress {
            done: f64::from(done),
            total: total as f64,
            unit: "variants",
            message: Some(r.variant.clone()),
        });
        say!(t,
            "| {} | {} | {:.0} | {:.3} | {:.3} | {:.3} | {:.1} | {:.2} | {:.2} | {:.3} | {:.2} / {:.1} | {:.2} | {:.2} | {:.2} |",
            r.variant,
            r.face_label(),
            arcmin(r.misalignment_rad),
            r.mean_edge_distance_m * 1e3,
            r.min_edge_distance_m * 1e3,
            r.edge_force_share,
            r.max_force_n,
            r.mean_sliding_m_s,
            r.max_sliding_m_s,
            r.mean_mu,
            r.mean_power_w,
            r.max_power_w,
            r.film_force_share,
            r.mean_abs_yaw_rad * 1e3,
            r.mean_abs_pitch_rad * 1e3
        );
    })
    .map_err(Failure::Run)?;
    let mut header: Vec<String> = RibShapeRow::COLUMNS.map(String::from).to_vec();
    header.extend((0..POSITION_BINS).map(|k| {
        format!(
            "force_share_{:.2}_{:.2}mm",
            k as f64 * POSITION_BIN_M * 1e3,
            (k + 1) as f64 * POSITION_BIN_M * 1e3
        )
    }));
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    t.csv(
        &dir.join("rib-shape.csv"),
        &header,
        rows.iter().map(|r| {
            let mut v = r.values().to_vec();
            v.extend(r.position_force_share);
            v
        }),
    )?;
    // One curve per misalignment through the variants in file order (flat → R 430 → R 37.5 →
    // R 37.5 with the crest moved toward the raceway): force-weighted mean position against mean
    // sliding speed; plus the sliding speed of each 0.25 mm position bin of every variant.
    let mut misalignments: Vec<f64> = rows.iter().map(|r| r.misalignment_rad).collect();
    misalignments.dedup();
    let mut curves: Vec<(String, Vec<(f64, f64)>)> = misalignments
        .iter()
        .map(|&m| {
            let points = rows
                .iter()
                .filter(|r| r.misalignment_rad == m)
                .map(|r| (r.mean_edge_distance_m * 1e3, r.mean_sliding_m_s))
                .collect();
            (
                format!(
                    "{:.0}′ misalignment: flat → R 430 → R 37.5 → R 37.5 crest −1 mm (means)",
                    arcmin(m)
                ),
                points,
            )
        })
        .collect();
    let mut local: Vec<(f64, f64)> = rows
        .iter()
        .flat_map(|r| {
            r.position_sliding_m_s
                .iter()
                .enumerate()
                .filter(|(_, v)| v.is_finite())
                .map(|(k, &v)| ((k as f64 + 0.5) * POSITION_BIN_M * 1e3, v))
        })
        .collect();
    local.sort_by(|a, b| a.0.total_cmp(&b.0));
    curves.push((
        "sliding speed at each contact position (0.25 mm bins, all variants)".into(),
        local,
    ));
    line_plot(
        &dir.join("rib-shape.svg"),
        &Labels {
            title: "2002834 roller end on the inner-ring rib (seed 000 §3.1.1.7)",
            x: "distance of the contact point from the rib edge, mm",
            y: "sliding speed at the contact, m/s",
        },
        &Series::from_pairs(&curves),
    )?;
    say!(t, "\nCSV table and plot written to {}", dir.display());
    Ok(())
}
/// Force of the Hertz check: well inside the projection of every seed rib face, N.
const HERTZ_CHECK_FORCE_N: f64 = 500.0;

/// One rib face's limit force.
#[derive(Clone, Debug, Serialize)]
pub struct LimitJson {
    pub case: usize,
    pub rib_face: String,
    pub reduced_curvature_1_m: f64,
    pub circumferential_reduced_curvature_1_m: f64,
    pub margin_m: f64,
    pub limit_force_n: f64,
    pub limit_bracket_n: (f64, f64),
    pub limit_force_axial_profile_n: f64,
    pub hertz_limit_force_n: f64,
}

/// One pressure map.
#[derive(Clone, Debug, Serialize)]
pub struct MapJson {
    pub rib_face: String,
    pub force_n: f64,
    pub max_pressure_pa: f64,
    pub contact_cells: usize,
    pub projection_share: f64,
    pub reaches_boundary: bool,
}

/// Runs the end–rib limit study on the model file `path` and writes its tables and plots into
/// `dir/end-rib-limit`, on square cells of `cell_m`.
fn end_rib_limit(
    path: &Path,
    dir: &Path,
    cell_m: f64,
    t: &mut Out,
) -> Result<EndRibLimitResult, Failure> {
    if !(cell_m > 0.0 && cell_m <= 0.5e-3) {
        return Err(Failure::Input(format!(
            "--cell {:.4} mm: need a cell above 0 and at most 0.5 mm",
            cell_m * 1e3
        )));
    }
    if !path.is_file() {
        return Err(Failure::Input(format!(
            "{}: not found — give a tapered model or run from the workspace root",
            path.display()
        )));
    }
    let bearing = match rolldyn_model::load(path)?.bearing {
        BearingModel::Tapered(b) => b,
        _ => {
            return Err(Failure::Input(format!(
                "{}: the end–rib limit study needs a double-row tapered bearing \
                 (bearing.kind = \"double-row-tapered\")",
                path.display()
            )));
        }
    };
    let dir = sub_dir(&dir.join("end-rib-limit"))?;
    let settings = Settings {
        cell_m,
        ..Settings::default()
    };
    let start = Instant::now();
    let fail = |e: rolldyn_contact::boussinesq::BoussinesqError| Failure::Run(e.to_string());
    let rows = end_rib_limit::seed_limit_table(&bearing, &settings).map_err(fail)?;
    let maps = SEED_PRESSURE_MAPS
        .iter()
        .map(|&(face, force)| end_rib_limit::pressure_map(&bearing, face, force, &settings))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let check = end_rib_limit::hertz_check(
        &bearing,
        TaperedRibFace::Conical,
        HERTZ_CHECK_FORCE_N,
        &settings,
    )
    .map_err(Failure::Run)?;
    let run_time_s = start.elapsed().as_secs_f64();
    write_limit_outputs(t, &dir, &rows)?;
    for map in &maps {
        write_map_outputs(t, &dir, map)?;
    }
    print_tables(t, &bearing, &rows, &maps, &check, &settings);
    say!(
        t,
        "\nrun time {run_time_s:.1} s; CSV tables and plots written to {}",
        dir.display()
    );
    Ok(EndRibLimitResult {
        model: path.display().to_string(),
        cell_m: settings.cell_m,
        limits: rows.iter().map(limit_json).collect(),
        pressure_maps: maps.iter().map(map_json).collect(),
        run_time_s,
        text: String::new(),
        tables: Vec::new(),
    })
}

fn limit_json(r: &LimitRow) -> LimitJson {
    LimitJson {
        case: r.case,
        rib_face: face_label(r.face),
        reduced_curvature_1_m: r.reduced_curvature,
        circumferential_reduced_curvature_1_m: r.circumferential_reduced_curvature,
        margin_m: r.margin_m,
        limit_force_n: r.limit.force_n(),
        limit_bracket_n: (r.limit.below_n, r.limit.above_n),
        limit_force_axial_profile_n: r.limit_axial_profile.force_n(),
        hertz_limit_force_n: r.hertz_limit_n,
    }
}

fn map_json(m: &PressureMap) -> MapJson {
    MapJson {
        rib_face: face_label(m.pair.face),
        force_n: m.solution.force_n,
        max_pressure_pa: m.solution.max_pressure_pa,
        contact_cells: m.solution.cells_in_contact,
        projection_share: m.projection_share,
        reaches_boundary: m.reaches_boundary,
    }
}

fn print_tables(
    t: &mut Out,
    bearing: &DoubleRowTaperedBearing,
    rows: &[LimitRow],
    maps: &[PressureMap],
    check: &HertzCheck,
    settings: &Settings,
) {
    say!(
        t,
        "## Seed 000 §3.2.2 end–rib limit force, {} (cells {:.3} mm, bracket ±{:.2} %)\n",
        bearing.name,
        settings.cell_m * 1e3,
        50.0 * settings.force_tolerance
    );
    say!(
        t,
        "| case | rib face | Σρ 1/m | Σρ circumferential 1/m | margin mm | limit N (Boussinesq) | limit N (axial profile only) | Hertz criterion N |"
    );
    say!(t, "|---|---|---|---|---|---|---|---|");
    for r in rows {
        say!(
            t,
            "| {} | {} | {:.4} | {:.4} | {:.3} | {:.0} | {:.0} | {:.0} |",
            r.case,
            face_label(r.face),
            r.reduced_curvature,
            r.circumferential_reduced_curvature,
            r.margin_m * 1e3,
            r.limit.force_n(),
            r.limit_axial_profile.force_n(),
            r.hertz_limit_n
        );
    }
    say!(
        t,
        "\n| rib face | force N | p_max MPa | patch / projection cells | reaches the boundary |"
    );
    say!(t, "|---|---|---|---|---|");
    for m in maps {
        say!(
            t,
            "| {} | {:.0} | {:.0} | {:.3} | {} |",
            face_label(m.pair.face),
            m.solution.force_n,
            m.solution.max_pressure_pa * 1e-6,
            m.projection_share,
            if m.reaches_boundary { "yes" } else { "no" }
        );
    }
    let (along_circle, up_the_rib) = check.semi_axes_m();
    let s = &check.map.solution;
    say!(
        t,
        "\nHertz check, {} rib at {:.0} N: p_max {:.1} / {:.1} MPa, semi-axes {:.3} × {:.3} / {:.3} × {:.3} mm, approach {:.2} / {:.2} µm (Boussinesq / Hertz)",
        face_label(check.map.pair.face),
        s.force_n,
        s.max_pressure_pa * 1e-6,
        check.hertz.max_pressure * 1e-6,
        along_circle * 1e3,
        up_the_rib * 1e3,
        check.hertz.semi_major * 1e3,
        check.hertz.semi_minor * 1e3,
        s.approach_m * 1e6,
        check.hertz.approach * 1e6
    );
}

fn write_limit_outputs(t: &mut Out, dir: &Path, rows: &[LimitRow]) -> Result<(), Failure> {
    t.csv(
        &dir.join("end-rib-limit.csv"),
        &LimitRow::COLUMNS,
        rows.iter().map(|r| r.values().to_vec()),
    )?;
    let mut sorted: Vec<&LimitRow> = rows.iter().collect();
    sorted.sort_by(|a, b| a.reduced_curvature.total_cmp(&b.reduced_curvature));
    let curve = |force: &dyn Fn(&LimitRow) -> f64| -> Vec<(f64, f64)> {
        sorted
            .iter()
            .map(|r| (r.reduced_curvature, force(r) * 1e-3))
            .collect()
    };
    let curves = [
        (
            "Boussinesq, true rib face (surface of revolution)",
            curve(&|r| r.limit.force_n()),
        ),
        (
            "Boussinesq, axial profile only (seed's Σρ)",
            curve(&|r| r.limit_axial_profile.force_n()),
        ),
        (
            "Hertz-spot criterion of the dynamics",
            curve(&|r| r.hertz_limit_n),
        ),
    ];
    line_plot(
        &dir.join("end-rib-limit.svg"),
        &Labels {
            title: "End–rib limit force (seed 000 Fig. 3.88)",
            x: "reduced curvature Σρ = 1/R_end − κ_rib, 1/m",
            y: "limit contact force, kN",
        },
        &Series::from_pairs(&curves),
    )?;
    Ok(())
}

/// Most blocks of a written pressure map: the solver's cells are merged into square blocks so
/// that the CSV and SVG stay ≈ 0.1–0.2 MB.
const MAP_BLOCKS: usize = 2500;

/// A pressure field merged into `block × block` cells, each holding the largest pressure of
/// its cells (so the patch outline and the edge peaks survive), and whether its centre cell is
/// in the projection.
struct BlockMap {
    nx: usize,
    ny: usize,
    /// block size, m
    size: f64,
    pressure: Vec<f64>,
    inside: Vec<bool>,
}

impl BlockMap {
    fn of(map: &PressureMap) -> Self {
        let g = map.pair.grid;
        let block = ((g.len() as f64 / MAP_BLOCKS as f64).sqrt().ceil() as usize).max(1);
        let (nx, ny) = (g.nx.div_ceil(block), g.ny.div_ceil(block));
        let mut pressure = vec![0.0f64; nx * ny];
        let mut inside = vec![false; nx * ny];
        for j in 0..g.ny {
            for i in 0..g.nx {
                let (k, b) = (g.index(i, j), (j / block) * nx + i / block);
                pressure[b] = pressure[b].max(map.solution.pressure[k]);
                if i % block == block / 2 && j % block == block / 2 {
                    inside[b] = map.pair.inside[k];
                }
            }
        }
        Self {
            nx,
            ny,
            size: block as f64 * g.dx,
            pressure,
            inside,
        }
    }
}

fn write_map_outputs(t: &mut Out, dir: &Path, map: &PressureMap) -> Result<(), Failure> {
    let (pair, s) = (&map.pair, &map.solution);
    let g = pair.grid;
    let blocks = BlockMap::of(map);
    let centre = |k: usize, lo: f64| lo + (k as f64 + 0.5) * blocks.size;
    let name = format!("pressure-{}-{:.0}N", face_slug(pair.face), s.force_n);
    t.csv(
        &dir.join(format!("{name}.csv")),
        &["v_m", "u_m", "max_pressure_pa", "inside_projection"],
        (0..blocks.ny).flat_map(|j| {
            let blocks = &blocks;
            (0..blocks.nx).map(move |i| {
                let b = j * blocks.nx + i;
                vec![
                    centre(i, g.x_min),
                    centre(j, g.y_min),
                    blocks.pressure[b],
                    f64::from(u8::from(blocks.inside[b])),
                ]
            })
        }),
    )?;
    let mpa: Vec<f64> = blocks.pressure.iter().map(|p| p * 1e-6).collect();
    let mm = |p: (f64, f64)| (p.0 * 1e3, p.1 * 1e3);
    let outline: Vec<[(f64, f64); 2]> = pair
        .outline()
        .iter()
        .map(|[a, b]| [mm(*a), mm(*b)])
        .collect();
    let title = format!(
        "{} rib, {:.0} N, Σρ {:.4} 1/m: pressure MPa",
        face_label(pair.face),
        s.force_n,
        pair.reduced_curvature()
    );
    map_plot(
        &dir.join(format!("{name}.svg")),
        &Labels {
            title: &title,
            x: "v along the rib circumference, mm",
            y: "u up the rib face from the initial contact, mm",
        },
        &Field {
            values: &mpa,
            nx: blocks.nx,
            ny: blocks.ny,
            extent: (
                g.x_min * 1e3,
                (g.x_min + blocks.nx as f64 * blocks.size) * 1e3,
                g.y_min * 1e3,
                (g.y_min + blocks.ny as f64 * blocks.size) * 1e3,
            ),
        },
        &MapLabels {
            value: "pressure, MPa",
            outline: &outline,
        },
    )?;
    Ok(())
}
