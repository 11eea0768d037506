//! Contact: the pressure of one roller on a raceway by the Boussinesq solver (seed 004), the
//! slice model (seed 000 eqs 2.3/2.4 or ISO/TS 16281) or Hertz; its central line and map.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::output::{out_dir, write_csv};
use crate::table::{Table, Tables};
use rolldyn_contact::boussinesq::BoussinesqOptions;
use rolldyn_contact::roller_raceway::{
    ContactMethod, ContactReport, PressureMap, RollerRacewayContact, SliceLawChoice,
};
use rolldyn_model::bounds::pressure_beyond_materials;
use rolldyn_plot::{Field, Labels, MapLabels, Series, line_plot, map_plot};
use rolldyn_units::{Angle, Force, Length, Quantity, format_number};
use serde::de::{self, Deserializer};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};

/// How the contact is solved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    #[default]
    Boussinesq,
    Slices,
    Hertz,
}

/// Which raceway of a bearing model the roller loads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum Raceway {
    #[default]
    Inner,
    Outer,
}

/// The slice law of the slice method: seed 000 eqs (2.3)/(2.4), or ISO/TS 16281 laminae.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum LawName {
    #[default]
    Seed,
    Iso,
}

/// A contact analysis: a roller of the model, its load and tilt, and the method.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactRequest {
    /// Roller load.
    pub load: Quantity<Force>,
    /// Roller tilt relative to the raceway, added to the model's misalignment.
    #[serde(default = "no_tilt")]
    pub tilt: Quantity<Angle>,
    /// Boussinesq grid: cells along the roller × across (`"350x9"` or `[350, 9]`); default
    /// the grid [`grid`] derives from the Hertz contact width.
    #[serde(default, deserialize_with = "deserialize_cells")]
    pub cells: Option<(usize, usize)>,
    /// Total transverse extent of the Boussinesq grid (default: square cells with `cells`,
    /// flag F-12, else 1.5 × the Hertz contact width).
    #[serde(default)]
    pub width: Option<Quantity<Length>>,
    #[serde(default)]
    pub method: Method,
    /// Raceway of a bearing model (a roller–raceway model has only one).
    #[serde(default)]
    pub raceway: Raceway,
    #[serde(default)]
    pub slice_law: LawName,
    /// Folder for the central line and the pressure map (CSV and SVG).
    #[serde(default)]
    pub out: Option<PathBuf>,
}

fn no_tilt() -> Quantity<Angle> {
    Quantity::from_si(0.0)
}

/// A grid size `NXxNY` (`350x9`), each count from 1 to 8192.
pub fn parse_cells(text: &str) -> Result<(usize, usize), String> {
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

/// A grid size as text (`"350x9"`) or a pair (`[350, 9]`).
fn deserialize_cells<'de, D: Deserializer<'de>>(d: D) -> Result<Option<(usize, usize)>, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Given {
        Pair(u64, u64),
        Text(String),
    }
    let text = match Given::deserialize(d)? {
        Given::Pair(nx, ny) => format!("{nx}x{ny}"),
        Given::Text(text) => text,
    };
    parse_cells(&text).map(Some).map_err(de::Error::custom)
}

/// The contact's answer (SI units), the `--json` answer of `rolldyn contact`.
#[derive(Clone, Debug, Serialize)]
pub struct ContactResult {
    pub model: String,
    pub method: &'static str,
    pub load_n: f64,
    pub tilt_rad: f64,
    /// The Boussinesq grid (none for the other methods).
    pub cells: Option<[usize; 2]>,
    pub approach_m: f64,
    pub max_pressure_pa: f64,
    pub mid_pressure_pa: f64,
    pub mean_pressure_pa: f64,
    pub concentration_factor: f64,
    pub contact_length_m: f64,
    pub max_half_width_m: f64,
    pub cells_in_contact: usize,
    pub iterations: usize,
    pub converged: bool,
    pub solve_time_s: f64,
    /// Pressure along the central line: (x [m], p [Pa]).
    #[serde(skip)]
    pub central_line: Vec<(f64, f64)>,
    /// The pressure map (Boussinesq only).
    #[serde(skip)]
    pub map: Option<PressureMap>,
}

impl ContactResult {
    /// The answer for `report` on the model named `model` (with its Boussinesq grid).
    pub fn new(model: &str, report: ContactReport) -> Self {
        Self {
            model: model.to_string(),
            method: report.method.name(),
            load_n: report.load_n,
            tilt_rad: report.tilt_rad,
            cells: report.map.as_ref().map(|m| [m.nx, m.ny]),
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
            central_line: report.central_line,
            map: report.map,
        }
    }

    /// A failure when the solution did not converge (the result holds the last iterate).
    pub fn convergence(&self) -> Result<(), Failure> {
        if self.converged {
            return Ok(());
        }
        Err(Failure::Run(format!(
            "the {} solution did not converge in {} iterations; results above are the last iterate",
            self.method, self.iterations
        )))
    }
}

/// The answer for `report` (a copy), as [`ContactResult::new`].
pub fn to_json(model: &str, report: &ContactReport) -> ContactResult {
    ContactResult::new(model, report.clone())
}

/// The cells of a pressure map, x fastest: (x [m], y [m], p [Pa]) at the cell centres.
fn map_cells(map: &PressureMap) -> impl Iterator<Item = [f64; 3]> + '_ {
    let (x0, x1, y0, y1) = map.extent;
    let (dx, dy) = ((x1 - x0) / map.nx as f64, (y1 - y0) / map.ny as f64);
    (0..map.ny).flat_map(move |j| {
        (0..map.nx).map(move |i| {
            [
                x0 + (i as f64 + 0.5) * dx,
                y0 + (j as f64 + 0.5) * dy,
                map.pressure[j * map.nx + i],
            ]
        })
    })
}

impl Tables for ContactResult {
    /// `central_line` (x_m, pressure_pa) and, for Boussinesq, `pressure_map` (x_m, y_m,
    /// pressure_pa at the cell centres, x fastest: `cells[1]` rows of `cells[0]`).
    fn tables(&self) -> Vec<Table> {
        let mut tables = vec![
            Table::new("central_line")
                .real("x_m", self.central_line.iter().map(|p| p.0).collect())
                .real(
                    "pressure_pa",
                    self.central_line.iter().map(|p| p.1).collect(),
                ),
        ];
        if let Some(map) = &self.map {
            let cells: Vec<[f64; 3]> = map_cells(map).collect();
            let column = |k: usize| cells.iter().map(|c| c[k]).collect();
            tables.push(
                Table::new("pressure_map")
                    .real("x_m", column(0))
                    .real("y_m", column(1))
                    .real("pressure_pa", column(2)),
            );
        }
        tables
    }
}

impl fmt::Display for ContactResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let grid = self
            .cells
            .map_or(String::new(), |[a, b]| format!(", {a}×{b} cells"));
        writeln!(
            f,
            "{}: {} contact, load {:.1} N, tilt {:.2}′{grid}",
            self.model,
            self.method,
            self.load_n,
            self.tilt_rad.to_degrees() * 60.0
        )?;
        writeln!(
            f,
            "  approach                {:.3} µm",
            self.approach_m * 1e6
        )?;
        writeln!(
            f,
            "  max pressure            {:.0} MPa",
            self.max_pressure_pa * 1e-6
        )?;
        writeln!(
            f,
            "  pressure at mid-contact {:.0} MPa",
            self.mid_pressure_pa * 1e-6
        )?;
        writeln!(
            f,
            "  mean pressure           {:.0} MPa",
            self.mean_pressure_pa * 1e-6
        )?;
        writeln!(
            f,
            "  concentration factor    {:.3}",
            self.concentration_factor
        )?;
        writeln!(
            f,
            "  contact length          {:.3} mm",
            self.contact_length_m * 1e3
        )?;
        writeln!(
            f,
            "  max half-width          {:.4} mm",
            self.max_half_width_m * 1e3
        )?;
        if self.method != ContactMethod::Hertz.name() {
            writeln!(f, "  loaded cells/slices     {}", self.cells_in_contact)?;
            writeln!(f, "  iterations              {}", self.iterations)?;
        }
        write!(
            f,
            "  solve time              {:.3} ms",
            self.solve_time_s * 1e3
        )
    }
}

/// The fewest Boussinesq cells across the Hertz contact width 2b of a given grid. The
/// convergence study of docs/theory.md §2.6 (2002834 at 200, 1000 and 5000 N): with 4 cells
/// across and a grid 1.25 × 2b wide p_max and the mid pressure are within 1 % of a 16-cell
/// grid; with 2 cells they are off by up to 17 %, with one cell of the 1x1 grid by 99 %.
pub const MIN_CELLS_ACROSS_CONTACT: f64 = 4.0;
/// The narrowest given grid, in Hertz contact widths 2b: narrower grids squeeze the contact
/// (0.8 × 2b: +59 % on p_max); 1.1 keeps the seed 004 grid 350x9 of examples/contact.
pub const MIN_GRID_WIDTH_PER_CONTACT_WIDTH: f64 = 1.1;
/// The grid used when none is given: this many cells across 2b over
/// [`DEFAULT_GRID_WIDTH_PER_CONTACT_WIDTH`] × 2b, and [`DEFAULT_CELLS_ALONG`] cells along the
/// roller (within 1 % of the 16-cell grid in the study).
pub const DEFAULT_CELLS_ACROSS_CONTACT: f64 = 6.0;
/// The width of the default grid, in Hertz contact widths 2b.
pub const DEFAULT_GRID_WIDTH_PER_CONTACT_WIDTH: f64 = 1.5;
/// The cells along the roller of the default grid.
pub const DEFAULT_CELLS_ALONG: usize = 150;

/// The Boussinesq grid (cells, total transverse width [m]) for `load` [N]: a given grid
/// checked to resolve the contact, else the default grid derived from the Hertz contact width
/// 2b. A given grid with fewer than [`MIN_CELLS_ACROSS_CONTACT`] cells across 2b or narrower
/// than [`MIN_GRID_WIDTH_PER_CONTACT_WIDTH`] × 2b is refused: the message names `--cells`
/// (and `--width`) with the smallest grid that would do.
pub fn grid(
    contact: &RollerRacewayContact,
    load: f64,
    cells: Option<(usize, usize)>,
    width: Option<f64>,
) -> Result<((usize, usize), Option<f64>), Failure> {
    let contact_width = 2.0 * contact.hertz(load).max_half_width_m;
    let Some(cells) = cells else {
        let width = width.unwrap_or(DEFAULT_GRID_WIDTH_PER_CONTACT_WIDTH * contact_width);
        let across = (DEFAULT_CELLS_ACROSS_CONTACT * width / contact_width).ceil();
        return Ok((
            (DEFAULT_CELLS_ALONG, across.min(8192.0) as usize),
            Some(width),
        ));
    };
    let (_, dy) = contact.cell_size(cells.0, cells.1, width);
    let across = contact_width / dy;
    let grid_width = dy * cells.1 as f64;
    let narrowest = MIN_GRID_WIDTH_PER_CONTACT_WIDTH * contact_width;
    if across >= MIN_CELLS_ACROSS_CONTACT && grid_width >= narrowest {
        return Ok((cells, width));
    }
    let minimum = match width {
        None => {
            let along = (MIN_CELLS_ACROSS_CONTACT * contact.roller_length() / contact_width).ceil();
            let dy = contact.roller_length() / along;
            format!("--cells {along}x{}", (narrowest / dy).ceil())
        }
        Some(w) => {
            let w = w.max(narrowest);
            format!(
                "--width {:.4}mm --cells {}x{}",
                w * 1e3,
                cells.0,
                (MIN_CELLS_ACROSS_CONTACT * w / contact_width).ceil()
            )
        }
    };
    Err(Failure::Input(format!(
        "--cells {}x{}: the grid cannot resolve the contact of {} N: {:.2} cells across the \
         Hertz contact width 2b = {:.4} mm on a grid {:.4} mm wide; it needs at least \
         {MIN_CELLS_ACROSS_CONTACT} cells across 2b and a grid {MIN_GRID_WIDTH_PER_CONTACT_WIDTH} \
         × 2b wide ({minimum}), or leave --cells out for a grid derived from 2b",
        cells.0,
        cells.1,
        format_number(load),
        across,
        contact_width * 1e3,
        grid_width * 1e3
    )))
}

/// Solves one roller–raceway contact by `method` (Boussinesq on `cells` over `width`, see
/// [`grid`]); a load whose Hertz pressure exceeds
/// [`rolldyn_contact::hertz::MAX_CREDIBLE_PRESSURE_PA`] and a given grid that cannot resolve
/// the contact are refused as bad input.
pub fn solve(
    contact: &RollerRacewayContact,
    method: Method,
    load: f64,
    cells: Option<(usize, usize)>,
    width: Option<f64>,
    law: LawName,
) -> Result<ContactReport, Failure> {
    if !(load > 0.0) {
        return Err(Failure::Input(format!(
            "--load must be positive, got {} N",
            format_number(load)
        )));
    }
    if let Some(reason) = pressure_beyond_materials(contact.hertz(load).max_pressure_pa) {
        return Err(Failure::Input(format!(
            "--load {} N gives {reason}",
            format_number(load)
        )));
    }
    let law = match law {
        LawName::Seed => SliceLawChoice::Seed,
        LawName::Iso => SliceLawChoice::Iso,
    };
    let report = match method {
        Method::Boussinesq => {
            let (cells, width) = grid(contact, load, cells, width)?;
            contact.boussinesq(load, cells.0, cells.1, width, BoussinesqOptions::default())
        }
        Method::Slices => contact.slices(load, law),
        Method::Hertz => Ok(contact.hertz(load)),
    };
    report.map_err(|e| Failure::Run(e.to_string()))
}

/// The contact analysis.
pub struct Contact;

impl Analysis for Contact {
    const NAME: &'static str = "contact";
    type Request = ContactRequest;
    type Result = ContactResult;

    /// Solves the contact and writes the outputs; a solution that did not converge is
    /// returned too (see [`ContactResult::convergence`]).
    fn run(request: &ContactRequest, context: &Context<'_>) -> Result<ContactResult, Failure> {
        let model = context.model.load()?.bearing;
        let tilt = request.tilt.si() + model.misalignment().inner_ring_tilt;
        let contact =
            RollerRacewayContact::from_model(&model, request.raceway == Raceway::Inner, tilt)
                .map_err(|e| Failure::Input(e.to_string()))?;
        let report = solve(
            &contact,
            request.method,
            request.load.si(),
            request.cells,
            request.width.map(|w| w.si()),
            request.slice_law,
        )?;
        let result = ContactResult::new(model.name(), report);
        if let Some(dir) = &request.out {
            write_outputs(&out_dir(dir)?, &result)?;
        }
        Ok(result)
    }
}

/// Writes `central_line.csv`, `central_line.svg` and, for Boussinesq, `pressure_map.csv` and
/// `pressure_map.svg` (like seed 004 Figs 5–6).
fn write_outputs(dir: &Path, r: &ContactResult) -> Result<(), Failure> {
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
                r.load_n, r.method
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
        write_csv(
            &dir.join("pressure_map.csv"),
            &["x_m", "y_m", "pressure_pa"],
            map_cells(map).map(Vec::from),
        )?;
        plot_pressure_map(&dir.join("pressure_map.svg"), "Contact pressure, MPa", map)?;
    }
    Ok(())
}

/// SVG heat map of a pressure field in MPa over mm axes.
pub fn plot_pressure_map(path: &Path, title: &str, map: &PressureMap) -> Result<(), Failure> {
    let (x0, x1, y0, y1) = map.extent;
    let mpa: Vec<f64> = map.pressure.iter().map(|p| p * 1e-6).collect();
    map_plot(
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
        &MapLabels {
            value: "pressure, MPa",
            outline: &[],
        },
    )?;
    Ok(())
}
