//! `rolldyn study seed004 [--out DIR]`: re-runs a seed's validation study, prints its tables
//! (Markdown, as in VALIDATION.md) and writes CSV tables and SVG plots.

use crate::failure::Failure;
use rolldyn::contact::plot_pressure_map;
use rolldyn::output::{out_dir, write_csv};
use rolldyn_geometry::BearingModel;
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_quasistatic::QuasiStaticOptions;
use rolldyn_quasistatic::studies::{self, NviTraction, StudyRow};
use rolldyn_units::{Length, Quantity};
use rolldyn_validation::rib_shape::{self, POSITION_BIN_M, POSITION_BINS, RibShapeRow};
use rolldyn_validation::seed004::{self, LOADS_N, PROFILES, TILTS_ARCMIN};
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Study {
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

#[derive(clap::Args)]
pub struct Args {
    #[arg(value_enum)]
    pub study: Study,
    /// Model file of `end-rib-limit` (a double-row tapered bearing).
    pub model: Option<PathBuf>,
    /// Folder for CSV tables and SVG plots.
    #[arg(long, default_value = "docs/validation")]
    pub out: PathBuf,
    /// Cage revolutions per variant for `rib-shape` (the first is discarded as start transient).
    #[arg(long, default_value_t = 4.0)]
    pub revolutions: f64,
    /// Print JSON instead of the tables (`end-rib-limit`).
    #[arg(long)]
    pub json: bool,
    /// Square cell size of the tangent-plane grid of `end-rib-limit`, e.g. `0.025mm`.
    #[arg(long, default_value = "0.05mm")]
    pub cell: Quantity<Length>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    if args.model.is_some() && !matches!(args.study, Study::EndRibLimit) {
        return Err(Failure::Input(
            "a model file is read by `study end-rib-limit` only".into(),
        ));
    }
    let dir = out_dir(&args.out)?;
    match args.study {
        Study::EndRibLimit => {
            super::end_rib_limit::run(args.model.as_deref(), &dir, args.json, args.cell.si())
        }
        Study::Seed004 => seed004_study(&dir),
        Study::Skidding => skidding_study(&dir),
        Study::RibShape => rib_shape_study(&dir, args.revolutions),
    }
}

fn mm_mpa(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.0 * 1e3, p.1 * 1e-6)).collect()
}

fn seed004_study(dir: &Path) -> Result<(), Failure> {
    grid_study(dir)?;
    profile_study(dir)?;
    concentration_study(dir)?;
    slices_study(dir)
}

fn grid_study(dir: &Path) -> Result<(), Failure> {
    println!("## V-01 seed 004 Table 2 at 1167 N (crowned 3.2 µm, no skew)\n");
    println!(
        "| grid | seed approach mm | rolldyn | err | seed p_max MPa | rolldyn | err | seed p_mid MPa | rolldyn | err | iterations | solve ms |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    let rows = seed004::grid_study(1167.0);
    let err = |a: f64, b: f64| 100.0 * (a - b) / b;
    let mut series = Vec::new();
    for (seed, r) in &rows {
        println!(
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
    write_csv(
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
    println!(
        "\nAt the stated 2334 N (150/3): approach {:.5} mm, p_max {:.0} MPa, p_mid {:.0} MPa.\n",
        stated.approach_m * 1e3,
        stated.max_pressure_pa * 1e-6,
        stated.mid_pressure_pa * 1e-6
    );
    Ok(())
}

fn profile_study(dir: &Path) -> Result<(), Failure> {
    let cases = seed004::profile_study(150, 15, 0.45e-3);
    println!("## V-02 profile study (150 × 15 cells over 7.5 × 0.45 mm)\n");
    println!("| profile | load N | skew ′ | p_max MPa | p_mid MPa | K | edge ratio |");
    println!("|---|---|---|---|---|---|---|");
    for c in &cases {
        println!(
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
    write_csv(
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
    println!();
    Ok(())
}

fn concentration_study(dir: &Path) -> Result<(), Failure> {
    let loads: Vec<f64> = (2..=24).map(|k| 125.0 * k as f64).collect();
    let k = seed004::concentration_vs_load(&loads, 300, 61, 0.45e-3);
    println!("## V-02 concentration factor K = p_max/p̄ vs load, no skew (300 × 61 cells)\n");
    print!("| load N |");
    PROFILES.iter().for_each(|p| print!(" {} |", p.1));
    println!("\n|---|---|---|---|---|---|");
    for (i, q) in loads.iter().enumerate() {
        print!("| {q:.0} |");
        k.iter().for_each(|rows| print!(" {:.3} |", rows[i].1));
        println!();
    }
    write_csv(
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
    println!();
    Ok(())
}

fn slices_study(dir: &Path) -> Result<(), Failure> {
    println!(
        "## Slices (ISO/TS 16281 laminae, 30 slices) vs Boussinesq (150 × 15), 1167 N, no skew\n"
    );
    println!(
        "| profile | approach slices µm | Boussinesq µm | diff | p_max slices MPa | Boussinesq MPa | diff |"
    );
    println!("|---|---|---|---|---|---|---|");
    let mut rows = Vec::new();
    for (index, profile) in PROFILES.iter().enumerate() {
        let s = seed004::slices_vs_boussinesq(index, 1167.0, 150, 15, 0.45e-3);
        let diff = |a: f64, b: f64| 100.0 * (a - b) / b;
        println!(
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
    write_csv(
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
    println!("\nPlots and CSV tables written to {}", dir.display());
    Ok(())
}

fn skid_rows_csv(path: &Path, rows: &[StudyRow]) -> Result<(), Failure> {
    let nan = f64::NAN;
    write_csv(
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

/// Cage slip (%) of `rows` grouped by inner speed, against `x(row)`.
fn slip_curves(rows: &[StudyRow], x: impl Fn(&StudyRow) -> f64) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut speeds: Vec<f64> = rows.iter().map(|r| r.inner_speed_rpm).collect();
    speeds.dedup();
    speeds
        .iter()
        .map(|&n| {
            let points = rows
                .iter()
                .filter(|r| r.inner_speed_rpm == n)
                .filter_map(|r| r.cage_slip.map(|s| (x(r), 100.0 * s)))
                .collect();
            (format!("{n:.0} rpm"), points)
        })
        .collect()
}

fn skidding_study(dir: &Path) -> Result<(), Failure> {
    let options = QuasiStaticOptions::default();
    let model = rolldyn_model::parse(
        include_str!("../../../../examples/obrien-taylor.toml"),
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
        println!("{name}: {value}");
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
        skid_rows_csv(&dir.join(format!("{stem}.csv")), &rows)?;
        // Per speed the study runs the load series (aligned), then the misalignment series at
        // 201 N.
        let loads = studies::OBRIEN_TAYLOR_LOADS_N.len();
        let mut seen = std::collections::HashMap::new();
        let (aligned, tilted): (Vec<StudyRow>, Vec<StudyRow>) = rows.into_iter().partition(|r| {
            let count = seen.entry(r.inner_speed_rpm.to_bits()).or_insert(0usize);
            *count += 1;
            *count <= loads
        });
        println!("## V-06 O'Brien–Taylor, quasi-static, {label}\n");
        println!("| speed rpm | oil °C | load N | cage slip % | max roller load N | failed |");
        println!("|---|---|---|---|---|---|");
        for r in &aligned {
            println!(
                "| {:.0} | {:.1} | {:.0} | {} | {} | {} |",
                r.inner_speed_rpm,
                r.temperature_c,
                r.radial_load_n,
                r.cage_slip
                    .map_or("—".into(), |s| format!("{:.4}", 100.0 * s)),
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
                y: "cage slip, %",
            },
            &Series::from_pairs(&curves),
        )?;
        let curves = slip_curves(&tilted, |r| r.misalignment_arcmin);
        line_plot(
            &dir.join(format!("{stem}-misalignment.svg")),
            &Labels {
                title: &format!("O'Brien–Taylor cage slip vs misalignment at 201 N, {label}"),
                x: "misalignment, arcmin",
                y: "cage slip, %",
            },
            &Series::from_pairs(&curves),
        )?;
        println!();
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
        skid_rows_csv(&dir.join(format!("{stem}.csv")), rows)?;
        println!("## V-18 intershaft (assumed geometry), {title}\n");
        println!("| inner rpm | outer rpm | load N | cage slip | max outer slide-roll | failed |");
        println!("|---|---|---|---|---|---|");
        for r in rows.iter() {
            println!(
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
        println!();
    }
    println!("Plots and CSV tables written to {}", dir.display());
    Ok(())
}

/// Seed 000 §3.1.1.7 (SPEC V-21): rib-shape study, `rib-shape.csv` and `rib-shape.svg` in `dir`.
fn rib_shape_study(dir: &Path, revolutions: f64) -> Result<(), Failure> {
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
    println!(
        "## Seed 000 §3.1.1.7 rib shape, 2002834 ({} cage revolutions, the first discarded)\n",
        revolutions
    );
    println!(
        "| variant | rib face | misalignment ′ | mean edge distance mm | min mm | force share on the edge | max force N | mean sliding m/s | max sliding m/s | μ | power W (mean / max) | film share | |yaw| mrad | |pitch| mrad |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let arcmin = |rad: f64| rad.to_degrees() * 60.0;
    let rows = rib_shape::run(sweep, &settings, &|_| true, &mut |r| {
        println!(
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
    write_csv(
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
    println!("\nCSV table and plot written to {}", dir.display());
    Ok(())
}
