//! Journal: finite journal bearing by the Reynolds equation (SPEC §8.6, seed 002 ch. 4) —
//! pressure field, load, attitude, Sommerfeld number, friction, side flow and the 2×2 stiffness
//! and damping coefficients, for a given eccentricity ratio or a given load. The journal file
//! form (`file`) adds the elastic liner + housing and the Fourier thermal model.

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::output::{out_dir, write_csv};
use crate::table::{Table, Tables};
use rolldyn_model::journal::{JournalTarget, journal_target, load_journal, parse_grid};
use rolldyn_output::{default_reason, mark_non_finite};
use rolldyn_plot::{Field, Labels, MapLabels, Series, line_plot, map_plot};
use rolldyn_reynolds::journal::{
    FilmStart, JournalBearing, JournalOperating, JournalOptions, JournalResult as Solution,
    solve_eccentricity, solve_load,
};
use rolldyn_reynolds::{Cavitation, Isoviscous, Viscosity as ViscosityLaw};
use rolldyn_units::{AngularSpeed, DynamicViscosity, Force, Length, Quantity, Temperature};
use serde::{Deserialize, Serialize, Serializer};
use std::fmt;
use std::path::{Path, PathBuf};

/// The cavitation model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum CavitationName {
    /// Reynolds / Swift–Stieber (p ≥ 0 by complementarity).
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson (Elrod).
    Jfo,
    /// Full Sommerfeld: sub-ambient pressures allowed.
    None,
}

/// Where the film starts without a feed groove.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum FilmStartName {
    /// Ambient pressure on the line of maximum gap (Raimondi–Boyd convention).
    MaxGap,
    /// No supply line: the film starts where the complementarity problem puts it (seed scheme).
    Free,
}

impl CavitationName {
    fn model(self) -> Cavitation {
        match self {
            Self::Reynolds => Cavitation::Reynolds,
            Self::Jfo => Cavitation::Jfo,
            Self::None => Cavitation::None,
        }
    }
}

impl FilmStartName {
    fn model(self) -> FilmStart {
        match self {
            Self::MaxGap => FilmStart::MaxGap,
            Self::Free => FilmStart::Free,
        }
    }
}

/// The spelling of a cavitation model (JSON `cavitation`).
fn cavitation_name(c: Cavitation) -> &'static str {
    match c {
        Cavitation::Reynolds => "reynolds",
        Cavitation::Jfo => "jfo",
        Cavitation::None => "none",
    }
}

/// The spelling of a film start (JSON `film_start`).
fn film_start_name(f: FilmStart) -> &'static str {
    match f {
        FilmStart::MaxGap => "max-gap",
        FilmStart::Free => "free",
    }
}

/// Grid when neither the request nor the journal file gives one.
const DEFAULT_GRID: &str = "120x40";

/// A journal-bearing analysis: the bearing and its operating point given field by field, or a
/// journal file; the solver options override the file's `[solver]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JournalRequest {
    /// Journal file (TOML) with geometry, operating point, viscosity law, liner and thermal
    /// model (examples/journal/seed002-ch4.toml); replaces the geometry and operating fields.
    #[serde(default)]
    pub file: Option<PathBuf>,
    /// Journal radius R.
    #[serde(default)]
    pub radius: Option<Quantity<Length>>,
    /// Bearing length L.
    #[serde(default)]
    pub length: Option<Quantity<Length>>,
    /// Radial clearance c.
    #[serde(default)]
    pub clearance: Option<Quantity<Length>>,
    /// Dynamic viscosity μ (isoviscous).
    #[serde(default)]
    pub viscosity: Option<Quantity<DynamicViscosity>>,
    /// Journal speed (bush fixed).
    #[serde(default)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Eccentricity ratio ε = e/c, 0 < ε < 1.
    #[serde(default)]
    pub eccentricity: Option<f64>,
    /// Static load W: solve for the equilibrium eccentricity and attitude.
    #[serde(default)]
    pub load: Option<Quantity<Force>>,
    /// Lubricant temperature (isothermal model).
    #[serde(default = "forty_celsius")]
    pub temperature: Quantity<Temperature>,
    /// Cavitation model (default: the file's, else Reynolds).
    #[serde(default)]
    pub cavitation: Option<CavitationName>,
    /// Grid: circumferential × axial nodes (full length), e.g. `120x40`.
    #[serde(default)]
    pub grid: Option<String>,
    /// Where the film starts without a feed groove (default: the file's, else max-gap).
    #[serde(default)]
    pub film_start: Option<FilmStartName>,
    /// Skip the 2×2 stiffness and damping coefficients (8 extra solves).
    #[serde(default)]
    pub no_coefficients: bool,
    /// Write the pressure field (CSV), a heat map and the mid-plane profile (SVG) here.
    #[serde(default)]
    pub out: Option<PathBuf>,
}

fn forty_celsius() -> Quantity<Temperature> {
    Quantity::from_si(313.15)
}

impl Default for JournalRequest {
    fn default() -> Self {
        Self {
            file: None,
            radius: None,
            length: None,
            clearance: None,
            viscosity: None,
            speed: None,
            eccentricity: None,
            load: None,
            temperature: forty_celsius(),
            cavitation: None,
            grid: None,
            film_start: None,
            no_coefficients: false,
            out: None,
        }
    }
}

struct Problem {
    bearing: JournalBearing,
    viscosity: Box<dyn ViscosityLaw>,
    law: &'static str,
    op: JournalOperating,
    target: JournalTarget,
    cavitation: Cavitation,
    grid: (usize, usize),
    film_start: FilmStart,
}

fn grid(text: &str) -> Result<(usize, usize), Failure> {
    parse_grid(text).map_err(|why| Failure::Input(format!("--grid {why}")))
}

fn positive(what: &str, v: f64) -> Result<f64, Failure> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Failure::Input(format!("{what} must be > 0 (got {v})")))
    }
}

fn from_fields(request: &JournalRequest) -> Result<Problem, Failure> {
    let need = |name: &str, v: Option<f64>| {
        v.ok_or_else(|| Failure::Input(format!("--{name} is required (or use --file)")))
    };
    let r = positive(
        "--radius",
        need("radius", request.radius.map(Quantity::si))?,
    )?;
    let l = positive(
        "--length",
        need("length", request.length.map(Quantity::si))?,
    )?;
    let c = need("clearance", request.clearance.map(Quantity::si))?;
    if !(c.is_finite() && c > 0.0) {
        return Err(Failure::Input(format!(
            "--clearance must be > 0 (got {c} m): a zero clearance leaves no film"
        )));
    }
    let mu = positive(
        "--viscosity",
        need("viscosity", request.viscosity.map(Quantity::si))?,
    )?;
    let w = need("speed", request.speed.map(Quantity::si))?;
    if !w.is_finite() {
        return Err(Failure::Input("--speed must be finite".into()));
    }
    let target = journal_target(request.eccentricity, request.load.map(Quantity::si), "--")
        .map_err(|e| Failure::Input(format!("{}: {}", e.key, e.reason)))?;
    Ok(Problem {
        bearing: JournalBearing::new(r, l, c),
        viscosity: Box::new(Isoviscous { mu }),
        law: "isoviscous",
        op: JournalOperating {
            journal_speed: w,
            bearing_speed: 0.0,
            temperature: request.temperature.si(),
        },
        target,
        cavitation: request
            .cavitation
            .map_or(Cavitation::Reynolds, CavitationName::model),
        grid: grid(request.grid.as_deref().unwrap_or(DEFAULT_GRID))?,
        film_start: request
            .film_start
            .map_or(FilmStart::MaxGap, FilmStartName::model),
    })
}

/// The journal file, with the solver options overriding its `[solver]` table.
fn from_file(path: &Path, request: &JournalRequest) -> Result<Problem, Failure> {
    let replaced = [
        ("radius", request.radius.is_some()),
        ("length", request.length.is_some()),
        ("clearance", request.clearance.is_some()),
        ("viscosity", request.viscosity.is_some()),
        ("speed", request.speed.is_some()),
        ("eccentricity", request.eccentricity.is_some()),
        ("load", request.load.is_some()),
    ];
    if let Some((name, _)) = replaced.iter().find(|(_, given)| *given) {
        return Err(Failure::Input(format!(
            "--{name}: the journal file gives it (--file replaces the geometry and operating options)"
        )));
    }
    let m = load_journal(path, request.temperature.si())?;
    let grid = match &request.grid {
        Some(text) => grid(text)?,
        None => match m.solver.grid {
            Some(g) => g,
            None => grid(DEFAULT_GRID)?,
        },
    };
    Ok(Problem {
        bearing: m.bearing,
        viscosity: m.viscosity,
        law: m.viscosity_law,
        op: m.operating,
        target: m.target,
        cavitation: request
            .cavitation
            .map(CavitationName::model)
            .or(m.solver.cavitation)
            .unwrap_or(Cavitation::Reynolds),
        grid,
        film_start: request
            .film_start
            .map(FilmStartName::model)
            .or(m.solver.film_start)
            .unwrap_or(FilmStart::MaxGap),
    })
}

/// The solver's iteration limits.
#[derive(Clone, Debug, Serialize)]
pub struct Limits {
    pub max_active_set_iterations: usize,
    pub max_coupling_iterations: usize,
    pub max_load_iterations: usize,
    pub max_eccentricity: f64,
}

/// The summary of a journal solution (the `--json` answer).
#[derive(Clone, Debug, Serialize)]
pub struct JournalSummary {
    pub eccentricity: f64,
    pub attitude_deg: f64,
    pub sommerfeld: f64,
    pub load_n: f64,
    pub max_pressure_pa: f64,
    pub friction_torque_nm: f64,
    pub friction_variable: f64,
    pub side_flow_m3_s: f64,
    /// Load frame: x′ along the load, y′ 90° counter-clockwise (direction of rotation).
    pub stiffness_n_per_m: Option<[[f64; 2]; 2]>,
    pub damping_ns_per_m: Option<[[f64; 2]; 2]>,
    pub min_film_m: f64,
    pub power_loss_w: f64,
    pub max_temperature_k: f64,
    pub mean_temperature_k: f64,
    pub max_deflection_m: f64,
    pub iterations: usize,
    pub coupling_iterations: usize,
    pub load_iterations: usize,
    pub converged: bool,
    pub solve_time_s: f64,
    pub limits: Limits,
    pub grid: [usize; 2],
    pub cavitation: &'static str,
    pub film_start: &'static str,
    pub viscosity_law: &'static str,
    pub elastic_liner: bool,
    pub thermal: bool,
}

/// A journal solution: its summary (serialised as the `--json` answer, non-finite values as
/// `null` with their reason) and its tables.
#[derive(Clone, Debug)]
pub struct JournalResult {
    pub summary: JournalSummary,
    /// `pressure`: θ from the load line (°, sorted), z, pressure, film and temperature at every
    /// node; empty when the solver returned no field.
    pub pressure: Table,
    /// `midplane`: the pressure on the axial node nearest z = 0.
    pub midplane: Table,
}

impl JournalResult {
    /// The failure to report after the result when the solution did not meet its tolerances
    /// (the result is still shown and its files written).
    pub fn convergence_failure(&self) -> Option<Failure> {
        let s = &self.summary;
        (!s.converged).then(|| {
            Failure::Run(format!(
                "the solution did not meet its tolerances within the iteration limits \
                 ({} Reynolds solves, {} coupling iterations of at most {}, {} load iterations of at most {}); \
                 try a finer grid, a smaller eccentricity or load",
                s.iterations,
                s.coupling_iterations,
                s.limits.max_coupling_iterations,
                s.load_iterations,
                s.limits.max_load_iterations
            ))
        })
    }
}

impl JournalSummary {
    /// The summary as JSON under the non-finite policy of docs/outputs.md (a 2×2 matrix with a
    /// non-finite entry is `null` as a whole).
    fn to_json(&self) -> serde_json::Value {
        let mut value = serde_json::to_value(self).unwrap_or_default();
        if let Some(object) = value.as_object_mut() {
            mark_non_finite(object, &self.numbers(), |_, v| {
                default_reason(v).to_string()
            });
        }
        value
    }

    /// The real-valued fields by their JSON keys (a matrix by its first non-finite entry).
    fn numbers(&self) -> Vec<(&'static str, f64)> {
        let mut numbers = vec![
            ("eccentricity", self.eccentricity),
            ("attitude_deg", self.attitude_deg),
            ("sommerfeld", self.sommerfeld),
            ("load_n", self.load_n),
            ("max_pressure_pa", self.max_pressure_pa),
            ("friction_torque_nm", self.friction_torque_nm),
            ("friction_variable", self.friction_variable),
            ("side_flow_m3_s", self.side_flow_m3_s),
            ("min_film_m", self.min_film_m),
            ("power_loss_w", self.power_loss_w),
            ("max_temperature_k", self.max_temperature_k),
            ("mean_temperature_k", self.mean_temperature_k),
            ("max_deflection_m", self.max_deflection_m),
            ("solve_time_s", self.solve_time_s),
        ];
        for (key, matrix) in [
            ("stiffness_n_per_m", self.stiffness_n_per_m),
            ("damping_ns_per_m", self.damping_ns_per_m),
        ] {
            if let Some(m) = matrix {
                let entries = m.as_flattened();
                let worst = entries
                    .iter()
                    .find(|v| !v.is_finite())
                    .unwrap_or(&entries[0]);
                numbers.push((key, *worst));
            }
        }
        numbers
    }
}

impl Serialize for JournalResult {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.summary.to_json().serialize(serializer)
    }
}

impl Tables for JournalResult {
    fn tables(&self) -> Vec<Table> {
        vec![self.pressure.clone(), self.midplane.clone()]
    }
}

impl fmt::Display for JournalResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = &self.summary;
        writeln!(
            f,
            "journal bearing: ε = {:.4}, attitude {:.2}°, S = {:.4}",
            a.eccentricity, a.attitude_deg, a.sommerfeld
        )?;
        writeln!(f, "  load                {:>12.4e} N", a.load_n)?;
        writeln!(f, "  max pressure        {:>12.4e} Pa", a.max_pressure_pa)?;
        writeln!(f, "  min film            {:>12.4e} m", a.min_film_m)?;
        writeln!(
            f,
            "  friction torque     {:>12.4e} N·m   (R/c)f = {:.4}",
            a.friction_torque_nm, a.friction_variable
        )?;
        writeln!(f, "  side flow           {:>12.4e} m³/s", a.side_flow_m3_s)?;
        writeln!(f, "  power loss          {:>12.4e} W", a.power_loss_w)?;
        if let (Some(k), Some(c)) = (a.stiffness_n_per_m, a.damping_ns_per_m) {
            writeln!(
                f,
                "  stiffness N/m (load frame)   [{:.4e} {:.4e}; {:.4e} {:.4e}]",
                k[0][0], k[0][1], k[1][0], k[1][1]
            )?;
            writeln!(
                f,
                "  damping N·s/m (load frame)   [{:.4e} {:.4e}; {:.4e} {:.4e}]",
                c[0][0], c[0][1], c[1][0], c[1][1]
            )?;
        }
        if a.thermal {
            writeln!(
                f,
                "  temperature max/mean {:.2} / {:.2} °C",
                a.max_temperature_k - 273.15,
                a.mean_temperature_k - 273.15
            )?;
        }
        if a.elastic_liner {
            writeln!(f, "  max liner deflection {:.4e} m", a.max_deflection_m)?;
        }
        write!(
            f,
            "  {} Reynolds solves, {} coupling, {} load iterations; converged: {}; {:.3} s",
            a.iterations, a.coupling_iterations, a.load_iterations, a.converged, a.solve_time_s
        )
    }
}

/// The journal-bearing analysis.
pub struct Journal;

impl Analysis for Journal {
    const NAME: &'static str = "journal";
    type Request = JournalRequest;
    type Result = JournalResult;

    /// Solves the bearing; with `out`, writes the pressure field and its plots. A solution
    /// that did not converge is returned (see [`JournalResult::convergence_failure`]).
    fn run(request: &JournalRequest, _context: &Context<'_>) -> Result<JournalResult, Failure> {
        let p = match &request.file {
            Some(path) => from_file(path, request)?,
            None => from_fields(request)?,
        };
        let options = JournalOptions {
            n_circumferential: p.grid.0,
            n_axial: p.grid.1,
            cavitation: p.cavitation,
            film_start: p.film_start,
            coefficients: !request.no_coefficients,
            ..JournalOptions::default()
        };
        let visc: &dyn ViscosityLaw = p.viscosity.as_ref();
        let res = match p.target {
            JournalTarget::Eccentricity(e) => {
                solve_eccentricity(&p.bearing, visc, &p.op, e, &options)
            }
            JournalTarget::Load(w) => solve_load(&p.bearing, visc, &p.op, w, &options),
        }?;
        let summary = JournalSummary {
            eccentricity: res.eccentricity,
            attitude_deg: res.attitude_deg,
            sommerfeld: res.sommerfeld,
            load_n: res.load_n,
            max_pressure_pa: res.max_pressure_pa,
            friction_torque_nm: res.friction_torque_nm,
            friction_variable: res.friction_variable,
            side_flow_m3_s: res.side_flow_m3_s,
            stiffness_n_per_m: options.coefficients.then_some(res.stiffness_n_per_m),
            damping_ns_per_m: options.coefficients.then_some(res.damping_ns_per_m),
            min_film_m: res.min_film_m,
            power_loss_w: res.power_loss_w,
            max_temperature_k: res.max_temperature_k,
            mean_temperature_k: res.mean_temperature_k,
            max_deflection_m: res.max_deflection_m,
            iterations: res.iterations,
            coupling_iterations: res.coupling_iterations,
            load_iterations: res.load_iterations,
            converged: res.converged,
            solve_time_s: res.solve_time_s,
            limits: Limits {
                max_active_set_iterations: options.max_active_set_iterations,
                max_coupling_iterations: options.max_coupling_iterations,
                max_load_iterations: options.max_load_iterations,
                max_eccentricity: options.max_eccentricity,
            },
            grid: [options.n_circumferential, options.n_axial],
            cavitation: cavitation_name(p.cavitation),
            film_start: film_start_name(p.film_start),
            viscosity_law: p.law,
            elastic_liner: p.bearing.liner.is_some(),
            thermal: p.bearing.thermal.is_some(),
        };
        let field = PressureField::new(&res);
        if let Some(dir) = &request.out {
            let Some(field) = &field else {
                return Err(Failure::Run("the solver returned no pressure field".into()));
            };
            field.write(&out_dir(dir)?)?;
        }
        let (pressure, midplane) = match &field {
            Some(field) => (field.table(), field.midplane_table()),
            None => (Table::new("pressure"), Table::new("midplane")),
        };
        Ok(JournalResult {
            summary,
            pressure,
            midplane,
        })
    }
}

/// Names of the pressure field's columns.
const PRESSURE_COLUMNS: [&str; 5] = ["theta_deg", "z_m", "pressure_pa", "film_m", "temperature_k"];

/// The solution's pressure field on the nodes, θ sorted from the load line.
struct PressureField<'a> {
    res: &'a Solution,
    /// θ′ from the load line in [0, 360)°, by node.
    deg: Vec<f64>,
    /// Node indices in ascending θ′.
    order: Vec<usize>,
    nz: usize,
    /// The axial node nearest z = 0.
    mid: usize,
}

impl<'a> PressureField<'a> {
    /// `None` when the solver returned no pressure field.
    fn new(res: &'a Solution) -> Option<Self> {
        let p = &res.pressure;
        let (nt, nz) = (p.theta.len(), p.z.len());
        if nt == 0 || nz == 0 || p.values.len() != nt * nz {
            return None;
        }
        let deg: Vec<f64> = p
            .theta
            .iter()
            .map(|t| t.to_degrees().rem_euclid(360.0))
            .collect();
        let mut order: Vec<usize> = (0..nt).collect();
        order.sort_by(|&a, &b| deg[a].total_cmp(&deg[b]));
        let mid = (0..nz)
            .min_by(|&a, &b| p.z[a].abs().total_cmp(&p.z[b].abs()))
            .unwrap_or(0);
        Some(Self {
            res,
            deg,
            order,
            nz,
            mid,
        })
    }

    /// Row-major values of [`PRESSURE_COLUMNS`], θ′ slowest (NaN for a film or temperature
    /// field the solver did not return).
    fn rows(&self) -> Vec<f64> {
        let (p, nz) = (&self.res.pressure, self.nz);
        let n = p.values.len();
        let film_ok = self.res.film.values.len() == n;
        let temp_ok = self.res.temperature.values.len() == n;
        let mut values = Vec::with_capacity(n * PRESSURE_COLUMNS.len());
        for &i in &self.order {
            for j in 0..nz {
                let k = i * nz + j;
                values.extend([
                    self.deg[i],
                    p.z[j],
                    p.values[k],
                    if film_ok {
                        self.res.film.values[k]
                    } else {
                        f64::NAN
                    },
                    if temp_ok {
                        self.res.temperature.values[k]
                    } else {
                        f64::NAN
                    },
                ]);
            }
        }
        values
    }

    fn table(&self) -> Table {
        let names = PRESSURE_COLUMNS.map(String::from);
        Table::from_rows("pressure", &names, &self.rows())
    }

    /// The mid-plane profile: (θ′ in °, pressure in Pa).
    fn midplane(&self) -> Vec<(f64, f64)> {
        let p = &self.res.pressure;
        self.order
            .iter()
            .map(|&i| (self.deg[i], p.values[i * self.nz + self.mid]))
            .collect()
    }

    fn midplane_table(&self) -> Table {
        let mid = self.midplane();
        Table::new("midplane")
            .real("theta_deg", mid.iter().map(|m| m.0).collect())
            .real("pressure_pa", mid.iter().map(|m| m.1).collect())
    }

    /// `pressure.csv`, `pressure_map.svg` and `pressure_midplane.svg` in `dir`.
    fn write(&self, dir: &Path) -> Result<(), Failure> {
        let (p, nz) = (&self.res.pressure, self.nz);
        let nt = self.order.len();
        write_csv(
            &dir.join("pressure.csv"),
            &PRESSURE_COLUMNS,
            self.rows()
                .chunks(PRESSURE_COLUMNS.len())
                .map(<[f64]>::to_vec),
        )?;
        // heat map, x (θ) fastest, MPa
        let mut values = Vec::with_capacity(nt * nz);
        for j in 0..nz {
            for &i in &self.order {
                values.push(p.values[i * nz + j] * 1e-6);
            }
        }
        let (z0, z1) = (p.z[0].min(p.z[nz - 1]), p.z[0].max(p.z[nz - 1]));
        map_plot(
            &dir.join("pressure_map.svg"),
            &Labels {
                title: "Film pressure, MPa",
                x: "angle from the load line θ′, deg (direction of rotation)",
                y: "axial position z, m",
            },
            &Field {
                values: &values,
                nx: nt,
                ny: nz,
                extent: (
                    self.deg[self.order[0]],
                    self.deg[self.order[nt - 1]],
                    z0,
                    z1,
                ),
            },
            &MapLabels {
                value: "film pressure, MPa",
                outline: &[],
            },
        )?;
        let mid: Vec<(f64, f64)> = self
            .midplane()
            .into_iter()
            .map(|(t, v)| (t, v * 1e-6))
            .collect();
        let curves = vec![(format!("z = {:.3e} m", p.z[self.mid]), mid)];
        line_plot(
            &dir.join("pressure_midplane.svg"),
            &Labels {
                title: "Mid-plane film pressure",
                x: "angle from the load line θ′, deg (direction of rotation)",
                y: "pressure, MPa",
            },
            &Series::from_pairs(&curves),
        )?;
        Ok(())
    }
}
