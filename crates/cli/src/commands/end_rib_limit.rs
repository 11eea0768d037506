//! `rolldyn study end-rib-limit [MODEL.toml]`: limit force of the roller large end on the cone's
//! large rib against the reduced curvature (seed 000 §3.2.2, Figs. 3.84–3.88; SPEC §6.7).

use crate::failure::Failure;
use crate::output::{load_model, print_json};
use rolldyn::output::{out_dir, write_csv};
use rolldyn_geometry::{BearingModel, DoubleRowTaperedBearing, TaperedRibFace};
use rolldyn_plot::{Field, Labels, Series, heat_map_outlined, line_plot};
use rolldyn_validation::end_rib_limit::{
    self, HertzCheck, LimitRow, PressureMap, SEED_PRESSURE_MAPS, Settings, face_label, face_slug,
};
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// Force of the Hertz check: well inside the projection of every seed rib face, N.
const HERTZ_CHECK_FORCE_N: f64 = 500.0;

#[derive(Serialize)]
struct LimitJson {
    case: usize,
    rib_face: String,
    reduced_curvature_1_m: f64,
    circumferential_reduced_curvature_1_m: f64,
    margin_m: f64,
    limit_force_n: f64,
    limit_bracket_n: (f64, f64),
    limit_force_axial_profile_n: f64,
    hertz_limit_force_n: f64,
}

#[derive(Serialize)]
struct MapJson {
    rib_face: String,
    force_n: f64,
    max_pressure_pa: f64,
    contact_cells: usize,
    projection_share: f64,
    reaches_boundary: bool,
}

#[derive(Serialize)]
struct StudyJson {
    model: String,
    cell_m: f64,
    limits: Vec<LimitJson>,
    pressure_maps: Vec<MapJson>,
    run_time_s: f64,
}

/// Runs the study on `model` (default [`end_rib_limit::DEFAULT_MODEL`]) and writes its tables
/// and plots into `dir/end-rib-limit`, on square cells of `cell_m`.
pub fn run(model: Option<&Path>, dir: &Path, json: bool, cell_m: f64) -> Result<(), Failure> {
    if !(cell_m > 0.0 && cell_m <= 0.5e-3) {
        return Err(Failure::Input(format!(
            "--cell {:.4} mm: need a cell above 0 and at most 0.5 mm",
            cell_m * 1e3
        )));
    }
    let path = model.unwrap_or(Path::new(end_rib_limit::DEFAULT_MODEL));
    if !path.is_file() {
        return Err(Failure::Input(format!(
            "{}: not found — give a tapered model or run from the workspace root",
            path.display()
        )));
    }
    let bearing = match load_model(Some(path))?.bearing {
        BearingModel::Tapered(b) => b,
        _ => {
            return Err(Failure::Input(format!(
                "{}: the end–rib limit study needs a double-row tapered bearing \
                 (bearing.kind = \"double-row-tapered\")",
                path.display()
            )));
        }
    };
    let dir = out_dir(&dir.join("end-rib-limit"))?;
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
    write_limit_outputs(&dir, &rows)?;
    for map in &maps {
        write_map_outputs(&dir, map)?;
    }
    if json {
        return print_json(&StudyJson {
            model: path.display().to_string(),
            cell_m: settings.cell_m,
            limits: rows.iter().map(limit_json).collect(),
            pressure_maps: maps.iter().map(map_json).collect(),
            run_time_s,
        });
    }
    print_tables(&bearing, &rows, &maps, &check, &settings);
    println!(
        "\nrun time {run_time_s:.1} s; CSV tables and plots written to {}",
        dir.display()
    );
    Ok(())
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
    bearing: &DoubleRowTaperedBearing,
    rows: &[LimitRow],
    maps: &[PressureMap],
    check: &HertzCheck,
    settings: &Settings,
) {
    println!(
        "## Seed 000 §3.2.2 end–rib limit force, {} (cells {:.3} mm, bracket ±{:.2} %)\n",
        bearing.name,
        settings.cell_m * 1e3,
        50.0 * settings.force_tolerance
    );
    println!(
        "| case | rib face | Σρ 1/m | Σρ circumferential 1/m | margin mm | limit N (Boussinesq) | limit N (axial profile only) | Hertz criterion N |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for r in rows {
        println!(
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
    println!(
        "\n| rib face | force N | p_max MPa | patch / projection cells | reaches the boundary |"
    );
    println!("|---|---|---|---|---|");
    for m in maps {
        println!(
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
    println!(
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

fn write_limit_outputs(dir: &Path, rows: &[LimitRow]) -> Result<(), Failure> {
    write_csv(
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

fn write_map_outputs(dir: &Path, map: &PressureMap) -> Result<(), Failure> {
    let (pair, s) = (&map.pair, &map.solution);
    let g = pair.grid;
    let blocks = BlockMap::of(map);
    let centre = |k: usize, lo: f64| lo + (k as f64 + 0.5) * blocks.size;
    let name = format!("pressure-{}-{:.0}N", face_slug(pair.face), s.force_n);
    write_csv(
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
    heat_map_outlined(
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
        &outline,
    )?;
    Ok(())
}
