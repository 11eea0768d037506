//! `rolldyn contact MODEL.toml --load 1167N`: roller–raceway contact pressure.

use crate::failure::Failure;
use crate::output::{load_model, print_json};
use rolldyn::output::{out_dir, write_csv};
use rolldyn_contact::boussinesq::BoussinesqOptions;
use rolldyn_contact::roller_raceway::{
    ContactMethod, ContactReport, PressureMap, RollerRacewayContact, SliceLawChoice,
};
use rolldyn_plot::{Field, Labels, Series, heat_map, line_plot};
use rolldyn_units::{Angle, Force, Length, Quantity};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Method {
    Boussinesq,
    Slices,
    Hertz,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Raceway {
    Inner,
    Outer,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum LawName {
    Seed,
    Iso,
}

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML); the embedded default model when omitted.
    pub model: Option<PathBuf>,
    /// Roller load, e.g. `1167N`.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Quantity<Force>,
    /// Roller tilt relative to the raceway, e.g. `4arcmin` (added to the model's misalignment).
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub tilt: Quantity<Angle>,
    /// Boussinesq grid: cells along the roller × cells across, e.g. `350x9` (seed 004 Table 2).
    #[arg(long, default_value = "150x3", value_parser = parse_cells)]
    pub cells: (usize, usize),
    /// Total transverse extent of the Boussinesq grid (default: square cells, flag F-12 of docs/theory.md).
    #[arg(long, allow_hyphen_values = true)]
    pub width: Option<Quantity<Length>>,
    #[arg(long, value_enum, default_value = "boussinesq")]
    pub method: Method,
    /// Raceway of a bearing model to load (a roller-raceway model has only one).
    #[arg(long, value_enum, default_value = "inner")]
    pub raceway: Raceway,
    /// Slice law of the slice method: seed 000 eqs (2.3)/(2.4), or ISO/TS 16281 laminae.
    #[arg(long, value_enum, default_value = "seed")]
    pub slice_law: LawName,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Write the pressure map and central line (CSV) and their plots (SVG) to this folder.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

fn parse_cells(text: &str) -> Result<(usize, usize), String> {
    let (nx, ny) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| format!("'{text}': expected NXxNY, e.g. 350x9"))?;
    let parse = |s: &str| {
        s.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=8192).contains(n))
            .ok_or_else(|| format!("'{text}': cell counts must be whole numbers from 1 to 8192"))
    };
    Ok((parse(nx)?, parse(ny)?))
}

/// The JSON answer of `rolldyn contact --json`.
#[derive(Serialize)]
pub struct ContactJson {
    model: String,
    method: &'static str,
    load_n: f64,
    tilt_rad: f64,
    cells: Option<[usize; 2]>,
    approach_m: f64,
    max_pressure_pa: f64,
    mid_pressure_pa: f64,
    mean_pressure_pa: f64,
    concentration_factor: f64,
    contact_length_m: f64,
    max_half_width_m: f64,
    cells_in_contact: usize,
    iterations: usize,
    converged: bool,
    solve_time_s: f64,
}

pub fn to_json(model: &str, report: &ContactReport, cells: Option<(usize, usize)>) -> ContactJson {
    ContactJson {
        model: model.to_string(),
        method: report.method.name(),
        load_n: report.load_n,
        tilt_rad: report.tilt_rad,
        cells: cells.map(|(a, b)| [a, b]),
        approach_m: report.approach_m,
        max_pressure_pa: report.max_pressure_pa,
        mid_pressure_pa: report.mid_pressure_pa,
        mean_pressure_pa: report.mean_pressure_pa,
        concentration_factor: report.concentration_factor,
        contact_length_m: report.contact_length_m,
        max_half_width_m: report.max_half_width_m,
        cells_in_contact: report.cells_in_contact,
        iterations: report.iterations,
        converged: report.converged,
        solve_time_s: report.solve_time_s,
    }
}

/// A maximum Hertz pressure above this is beyond the strength of any bearing material (bearing
/// steels yield near 4 GPa, ceramics fail below 10 GPa): the elastic contact does not apply, Pa.
pub const MAX_CREDIBLE_PRESSURE_PA: f64 = 10e9;

/// Solves one roller–raceway contact as the arguments say; a load whose Hertz pressure exceeds
/// [`MAX_CREDIBLE_PRESSURE_PA`] is refused as bad input.
pub fn solve(
    contact: &RollerRacewayContact,
    method: Method,
    load: f64,
    cells: (usize, usize),
    width: Option<f64>,
    law: LawName,
) -> Result<ContactReport, Failure> {
    if !(load > 0.0) {
        return Err(Failure::Input(format!(
            "--load must be positive, got {load} N"
        )));
    }
    let hertz_pressure = contact.hertz(load).max_pressure_pa;
    if !(hertz_pressure <= MAX_CREDIBLE_PRESSURE_PA) {
        return Err(Failure::Input(format!(
            "--load {load:e} N gives a Hertz pressure of {:.3e} GPa, beyond any bearing \
             material ({} GPa): the elastic contact model does not apply",
            hertz_pressure * 1e-9,
            MAX_CREDIBLE_PRESSURE_PA * 1e-9
        )));
    }
    let law = match law {
        LawName::Seed => SliceLawChoice::Seed,
        LawName::Iso => SliceLawChoice::Iso,
    };
    let report = match method {
        Method::Boussinesq => {
            contact.boussinesq(load, cells.0, cells.1, width, BoussinesqOptions::default())
        }
        Method::Slices => contact.slices(load, law),
        Method::Hertz => Ok(contact.hertz(load)),
    };
    report.map_err(|e| Failure::Run(e.to_string()))
}

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(args.model.as_deref())?.bearing;
    let tilt = args.tilt.si() + model.misalignment().inner_ring_tilt;
    let contact =
        RollerRacewayContact::from_model(&model, matches!(args.raceway, Raceway::Inner), tilt)
            .map_err(|e| Failure::Input(e.to_string()))?;
    let width = args.width.map(|w| w.si());
    let report = solve(
        &contact,
        args.method,
        args.load.si(),
        args.cells,
        width,
        args.slice_law,
    )?;
    let cells = (report.method == ContactMethod::Boussinesq).then_some(args.cells);
    if let Some(dir) = &args.out {
        write_outputs(&out_dir(dir)?, &report)?;
    }
    if args.json {
        print_json(&to_json(model.name(), &report, cells))?;
    } else {
        print_summary(model.name(), &report, cells);
    }
    if !report.converged {
        return Err(Failure::Run(format!(
            "the {} solution did not converge in {} iterations; results above are the last iterate",
            report.method.name(),
            report.iterations
        )));
    }
    Ok(())
}

pub fn print_summary(model: &str, r: &ContactReport, cells: Option<(usize, usize)>) {
    let grid = cells.map_or(String::new(), |(a, b)| format!(", {a}×{b} cells"));
    println!(
        "{model}: {} contact, load {:.1} N, tilt {:.2}′{grid}",
        r.method.name(),
        r.load_n,
        r.tilt_rad.to_degrees() * 60.0
    );
    println!("  approach                {:.3} µm", r.approach_m * 1e6);
    println!(
        "  max pressure            {:.0} MPa",
        r.max_pressure_pa * 1e-6
    );
    println!(
        "  pressure at mid-contact {:.0} MPa",
        r.mid_pressure_pa * 1e-6
    );
    println!(
        "  mean pressure           {:.0} MPa",
        r.mean_pressure_pa * 1e-6
    );
    println!("  concentration factor    {:.3}", r.concentration_factor);
    println!(
        "  contact length          {:.3} mm",
        r.contact_length_m * 1e3
    );
    println!(
        "  max half-width          {:.4} mm",
        r.max_half_width_m * 1e3
    );
    if r.method != ContactMethod::Hertz {
        println!("  loaded cells/slices     {}", r.cells_in_contact);
        println!("  iterations              {}", r.iterations);
    }
    println!("  solve time              {:.3} ms", r.solve_time_s * 1e3);
}

/// Writes `central_line.csv`, `central_line.svg` and, for Boussinesq, `pressure_map.csv` and
/// `pressure_map.svg` (like seed 004 Figs 5–6).
pub fn write_outputs(dir: &Path, r: &ContactReport) -> Result<(), Failure> {
    write_csv(
        &dir.join("central_line.csv"),
        &["x_m", "pressure_pa"],
        r.central_line.iter().map(|p| vec![p.0, p.1]),
    )?;
    let mm_mpa: Vec<(f64, f64)> = r
        .central_line
        .iter()
        .map(|p| (p.0 * 1e3, p.1 * 1e-6))
        .collect();
    line_plot(
        &dir.join("central_line.svg"),
        &Labels {
            title: &format!(
                "Pressure along the contact line, {:.0} N ({})",
                r.load_n,
                r.method.name()
            ),
            x: "x along the roller, mm",
            y: "pressure, MPa",
        },
        &[Series {
            label: "",
            points: &mm_mpa,
        }],
    )?;
    if let Some(map) = &r.map {
        let (x0, x1, y0, y1) = map.extent;
        let (dx, dy) = ((x1 - x0) / map.nx as f64, (y1 - y0) / map.ny as f64);
        write_csv(
            &dir.join("pressure_map.csv"),
            &["x_m", "y_m", "pressure_pa"],
            (0..map.ny).flat_map(|j| {
                (0..map.nx).map(move |i| {
                    vec![
                        x0 + (i as f64 + 0.5) * dx,
                        y0 + (j as f64 + 0.5) * dy,
                        map.pressure[j * map.nx + i],
                    ]
                })
            }),
        )?;
        plot_pressure_map(&dir.join("pressure_map.svg"), "Contact pressure, MPa", map)?;
    }
    Ok(())
}

/// SVG heat map of a pressure field in MPa over mm axes.
pub fn plot_pressure_map(path: &Path, title: &str, map: &PressureMap) -> Result<(), Failure> {
    let (x0, x1, y0, y1) = map.extent;
    let mpa: Vec<f64> = map.pressure.iter().map(|p| p * 1e-6).collect();
    heat_map(
        path,
        &Labels {
            title,
            x: "x along the roller, mm",
            y: "y rolling direction, mm",
        },
        &Field {
            values: &mpa,
            nx: map.nx,
            ny: map.ny,
            extent: (x0 * 1e3, x1 * 1e3, y0 * 1e3, y1 * 1e3),
        },
    )?;
    Ok(())
}
