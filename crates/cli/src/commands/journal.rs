//! `rolldyn journal`: finite journal bearing by the Reynolds equation (SPEC §8.6, seed 002 ch. 4)
//! — pressure field, load, attitude, Sommerfeld number, friction, side flow and the 2×2
//! stiffness and damping coefficients, for a given eccentricity ratio or a given load. The model
//! file form (`--file`) adds the elastic liner + housing and the Fourier thermal model.

use crate::failure::Failure;
use crate::output::{out_dir, print_json, write_csv};
use rolldyn_plot::{Field, Labels, Series, heat_map, line_plot};
use rolldyn_reynolds::compliance::liner::{AnalyticLinerKernel, LinerKernel, Material, two_layer};
use rolldyn_reynolds::journal::{
    FilmStart, JournalBearing, JournalOperating, JournalOptions, JournalResult, solve_eccentricity,
    solve_load,
};
use rolldyn_reynolds::thermal::ThermalModel;
use rolldyn_reynolds::{
    Barus, Cavitation, Isoviscous, Petrusevich, ReynoldsError, Viscosity as ViscosityLaw,
};
use rolldyn_units::{
    AngularSpeed, DynamicViscosity, Force, Length, PerPressure, Pressure, Quantity, Temperature,
    ThermalConductivity,
};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, clap::ValueEnum, Deserialize, PartialEq, Eq, Debug)]
#[serde(rename_all = "kebab-case")]
pub enum CavitationName {
    /// Reynolds / Swift–Stieber (p ≥ 0 by complementarity).
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson (Elrod).
    Jfo,
    /// Full Sommerfeld: sub-ambient pressures allowed.
    None,
}

#[derive(Clone, Copy, clap::ValueEnum, Deserialize, PartialEq, Eq, Debug)]
#[serde(rename_all = "kebab-case")]
pub enum FilmStartName {
    /// Ambient pressure on the line of maximum gap (Raimondi–Boyd convention).
    MaxGap,
    /// No supply line: the film starts where the complementarity problem puts it (seed scheme).
    Free,
}

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with geometry, operating point, viscosity law, liner and thermal model
    /// (see examples/journal/seed002-ch4.toml); replaces the geometry/operating flags.
    #[arg(long, conflicts_with_all = ["radius", "length", "clearance", "viscosity", "speed", "eccentricity", "load"])]
    pub file: Option<PathBuf>,
    /// Journal radius R.
    #[arg(long)]
    pub radius: Option<Quantity<Length>>,
    /// Bearing length L.
    #[arg(long)]
    pub length: Option<Quantity<Length>>,
    /// Radial clearance c.
    #[arg(long)]
    pub clearance: Option<Quantity<Length>>,
    /// Dynamic viscosity μ (isoviscous).
    #[arg(long)]
    pub viscosity: Option<Quantity<DynamicViscosity>>,
    /// Journal speed (bush fixed).
    #[arg(long)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Eccentricity ratio ε = e/c, 0 < ε < 1.
    #[arg(long, conflicts_with = "load", allow_hyphen_values = true)]
    pub eccentricity: Option<f64>,
    /// Static load W: solve for the equilibrium eccentricity and attitude.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Option<Quantity<Force>>,
    /// Lubricant temperature (isothermal model).
    #[arg(long, default_value = "40C")]
    pub temperature: Quantity<Temperature>,
    /// Cavitation model [default: reynolds].
    #[arg(long, value_enum)]
    pub cavitation: Option<CavitationName>,
    /// Grid: circumferential × axial nodes (full length) [default: 120x40].
    #[arg(long)]
    pub grid: Option<String>,
    /// Where the film starts without a feed groove [default: max-gap].
    #[arg(long, value_enum)]
    pub film_start: Option<FilmStartName>,
    /// Skip the 2×2 stiffness and damping coefficients (8 extra solves).
    #[arg(long)]
    pub no_coefficients: bool,
    #[arg(long)]
    pub json: bool,
    /// Write the pressure field (CSV), a heat map and the mid-plane profile (SVG) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

// ---------------------------------------------------------------- model file

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ModelFile {
    geometry: GeometryFile,
    operating: OperatingFile,
    viscosity: ViscosityFile,
    liner: Option<LinerFile>,
    thermal: Option<ThermalFile>,
    solver: Option<SolverFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GeometryFile {
    /// Journal radius R (bush bore R₁ = R + c).
    radius: Quantity<Length>,
    length: Quantity<Length>,
    clearance: Quantity<Length>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct OperatingFile {
    speed: Quantity<AngularSpeed>,
    eccentricity: Option<f64>,
    load: Option<Quantity<Force>>,
    temperature: Option<Quantity<Temperature>>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum LawName {
    Isoviscous,
    Barus,
    Petrusevich,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ViscosityFile {
    law: LawName,
    mu0: Quantity<DynamicViscosity>,
    alpha: Option<Quantity<PerPressure>>,
    /// Viscosity–temperature slope Ω₀, 1/K (plain number).
    omega0_per_k: Option<f64>,
    /// Reference temperature of μ₀ (default: the operating temperature).
    t_ref: Option<Quantity<Temperature>>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum KernelName {
    Analytic,
    Winkler,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinerFile {
    thickness: Quantity<Length>,
    modulus: Quantity<Pressure>,
    poisson: f64,
    kernel: Option<KernelName>,
    housing: Option<HousingFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct HousingFile {
    outer_radius: Quantity<Length>,
    modulus: Quantity<Pressure>,
    poisson: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ThermalFile {
    conductivity: Quantity<ThermalConductivity>,
    ambient_temperature: Quantity<Temperature>,
    outer_radius: Quantity<Length>,
    harmonics: Option<usize>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SolverFile {
    cavitation: Option<CavitationName>,
    grid: Option<String>,
    film_start: Option<FilmStartName>,
}

enum Mode {
    Eccentricity(f64),
    Load(f64),
}

struct Problem {
    bearing: JournalBearing,
    viscosity: Box<dyn ViscosityLaw>,
    law: &'static str,
    op: JournalOperating,
    mode: Mode,
    cavitation: CavitationName,
    grid: (usize, usize),
    film_start: FilmStartName,
}

fn parse_grid(text: &str) -> Result<(usize, usize), Failure> {
    let bad = || {
        Failure::Input(format!(
            "--grid '{text}': expected NxM (circumferential × axial nodes), e.g. 120x40, with N ≥ 8 and M ≥ 3"
        ))
    };
    let (a, b) = text.split_once(['x', 'X', '×']).ok_or_else(bad)?;
    let n: usize = a.trim().parse().map_err(|_| bad())?;
    let m: usize = b.trim().parse().map_err(|_| bad())?;
    if n < 8 || m < 3 || n > 4000 || m > 2000 {
        return Err(bad());
    }
    Ok((n, m))
}

fn mode(eps: Option<f64>, load: Option<f64>, ctx: &str, key: &str) -> Result<Mode, Failure> {
    match (eps, load) {
        (Some(e), None) => {
            if !(e.is_finite() && e > 0.0 && e < 1.0) {
                return Err(Failure::Input(format!(
                    "{ctx}{key}eccentricity {e}: must satisfy 0 < ε < 1 (ε ≥ 1 is metal contact; at ε = 0 the load and Sommerfeld number are undefined)"
                )));
            }
            Ok(Mode::Eccentricity(e))
        }
        (None, Some(w)) => {
            if !(w.is_finite() && w > 0.0) {
                return Err(Failure::Input(format!("{ctx}{key}load {w} N: must be > 0")));
            }
            Ok(Mode::Load(w))
        }
        (Some(_), Some(_)) => Err(Failure::Input(format!(
            "{ctx}give either {key}eccentricity or {key}load, not both"
        ))),
        (None, None) => Err(Failure::Input(format!(
            "{ctx}give {key}eccentricity or {key}load"
        ))),
    }
}

fn positive(what: &str, v: f64) -> Result<f64, Failure> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Failure::Input(format!("{what} must be > 0 (got {v})")))
    }
}

fn from_flags(args: &Args) -> Result<Problem, Failure> {
    let need = |name: &str, v: Option<f64>| {
        v.ok_or_else(|| Failure::Input(format!("--{name} is required (or use --file)")))
    };
    let r = positive("--radius", need("radius", args.radius.map(Quantity::si))?)?;
    let l = positive("--length", need("length", args.length.map(Quantity::si))?)?;
    let c = need("clearance", args.clearance.map(Quantity::si))?;
    if !(c.is_finite() && c > 0.0) {
        return Err(Failure::Input(format!(
            "--clearance must be > 0 (got {c} m): a zero clearance leaves no film"
        )));
    }
    let mu = positive(
        "--viscosity",
        need("viscosity", args.viscosity.map(Quantity::si))?,
    )?;
    let w = need("speed", args.speed.map(Quantity::si))?;
    if !w.is_finite() {
        return Err(Failure::Input("--speed must be finite".into()));
    }
    Ok(Problem {
        bearing: JournalBearing::new(r, l, c),
        viscosity: Box::new(Isoviscous { mu }),
        law: "isoviscous",
        op: JournalOperating {
            journal_speed: w,
            bearing_speed: 0.0,
            temperature: args.temperature.si(),
        },
        mode: mode(args.eccentricity, args.load.map(Quantity::si), "", "--")?,
        cavitation: args.cavitation.unwrap_or(CavitationName::Reynolds),
        grid: parse_grid(args.grid.as_deref().unwrap_or("120x40"))?,
        film_start: args.film_start.unwrap_or(FilmStartName::MaxGap),
    })
}

fn from_file(path: &Path, args: &Args) -> Result<Problem, Failure> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Input(format!("{file}: cannot read the file: {e}")))?;
    let m: ModelFile = toml::from_str(&text).map_err(|e| {
        let at = e
            .span()
            .map(|s| toml_location(&text, s.start))
            .unwrap_or_default();
        Failure::Input(format!(
            "{file}{at}: {}",
            e.message().trim().replace('\n', " ")
        ))
    })?;
    let key = |k: &str, msg: String| Failure::Input(format!("{file}: {k}: {msg}"));
    let pos = |k: &str, v: f64| -> Result<f64, Failure> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(key(k, format!("must be > 0 (got {v})")))
        }
    };
    let r = pos("geometry.radius", m.geometry.radius.si())?;
    let l = pos("geometry.length", m.geometry.length.si())?;
    let c = pos("geometry.clearance", m.geometry.clearance.si())?;
    let t_op = m
        .operating
        .temperature
        .map_or(args.temperature.si(), Quantity::si);
    pos("operating.temperature", t_op)?;
    let mut bearing = JournalBearing::new(r, l, c);
    let v = &m.viscosity;
    let mu0 = pos("viscosity.mu0", v.mu0.si())?;
    let alpha = v.alpha.map_or(0.0, Quantity::si);
    if !(alpha.is_finite() && alpha >= 0.0) {
        return Err(key("viscosity.alpha", format!("must be ≥ 0 (got {alpha})")));
    }
    let (viscosity, law): (Box<dyn ViscosityLaw>, &'static str) = match v.law {
        LawName::Isoviscous => (Box::new(Isoviscous { mu: mu0 }), "isoviscous"),
        LawName::Barus => (Box::new(Barus { mu0, alpha }), "barus"),
        LawName::Petrusevich => {
            let omega0 = v.omega0_per_k.ok_or_else(|| {
                key(
                    "viscosity.omega0_per_k",
                    "required by the Petrusevich law".into(),
                )
            })?;
            if !(omega0.is_finite() && omega0 >= 0.0) {
                return Err(key(
                    "viscosity.omega0_per_k",
                    format!("must be ≥ 0 (got {omega0})"),
                ));
            }
            let t_ref_k = v.t_ref.map_or(t_op, Quantity::si);
            (
                Box::new(Petrusevich {
                    mu0,
                    alpha,
                    omega0,
                    t_ref_k,
                }),
                "petrusevich",
            )
        }
    };
    if let Some(liner) = &m.liner {
        let r1 = r + c;
        let t = pos("liner.thickness", liner.thickness.si())?;
        let e = pos("liner.modulus", liner.modulus.si())?;
        if !(liner.poisson > -1.0 && liner.poisson < 0.5) {
            return Err(key("liner.poisson", "must lie in (−1, 0.5)".into()));
        }
        let lin = Material {
            e,
            nu: liner.poisson,
        };
        let k0 = match &liner.housing {
            Some(h) => {
                let r3 = h.outer_radius.si();
                if !(r3.is_finite() && r3 > r1 + t) {
                    return Err(key(
                        "liner.housing.outer_radius",
                        format!("must exceed the liner outer radius {:.6} m", r1 + t),
                    ));
                }
                let eh = pos("liner.housing.modulus", h.modulus.si())?;
                if !(h.poisson > -1.0 && h.poisson < 0.5) {
                    return Err(key("liner.housing.poisson", "must lie in (−1, 0.5)".into()));
                }
                two_layer(
                    r1,
                    r1 + t,
                    r3,
                    lin,
                    Material {
                        e: eh,
                        nu: h.poisson,
                    },
                )
            }
            None => rolldyn_reynolds::compliance::liner::winkler(t, e, liner.poisson),
        };
        bearing.liner = Some(match liner.kernel.unwrap_or(KernelName::Analytic) {
            KernelName::Analytic => LinerKernel::Analytic(AnalyticLinerKernel::seed(k0)),
            KernelName::Winkler => LinerKernel::Winkler { k0 },
        });
    }
    if let Some(th) = &m.thermal {
        bearing.thermal = Some(ThermalModel {
            conductivity: pos("thermal.conductivity", th.conductivity.si())?,
            ambient_temperature: pos("thermal.ambient_temperature", th.ambient_temperature.si())?,
            outer_radius: pos("thermal.outer_radius", th.outer_radius.si())?,
            harmonics: th.harmonics.unwrap_or(10),
        });
    }
    let s = m.solver.as_ref();
    let grid_text = args
        .grid
        .clone()
        .or_else(|| s.and_then(|s| s.grid.clone()))
        .unwrap_or_else(|| "120x40".into());
    Ok(Problem {
        bearing,
        viscosity,
        law,
        op: JournalOperating {
            journal_speed: m.operating.speed.si(),
            bearing_speed: 0.0,
            temperature: t_op,
        },
        mode: mode(
            m.operating.eccentricity,
            m.operating.load.map(Quantity::si),
            &format!("{file}: "),
            "operating.",
        )?,
        cavitation: args
            .cavitation
            .or(s.and_then(|s| s.cavitation))
            .unwrap_or(CavitationName::Reynolds),
        grid: parse_grid(&grid_text)?,
        film_start: args
            .film_start
            .or(s.and_then(|s| s.film_start))
            .unwrap_or(FilmStartName::MaxGap),
    })
}

/// ":LINE (section.key)" of a byte offset in a TOML text, for error messages.
fn toml_location(text: &str, offset: usize) -> String {
    let before = &text[..offset.min(text.len())];
    let line_no = before.matches('\n').count() + 1;
    let line = text.lines().nth(line_no - 1).unwrap_or("").trim();
    let section = before
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim().to_string());
    let key = line
        .split_once('=')
        .map(|(k, _)| k.trim().to_string())
        .filter(|k| !k.starts_with('['));
    match (section, key) {
        (Some(s), Some(k)) => format!(":{line_no} ({s}.{k})"),
        (None, Some(k)) => format!(":{line_no} ({k})"),
        (Some(s), None) => format!(":{line_no} ([{s}])"),
        (None, None) => format!(":{line_no}"),
    }
}

// ---------------------------------------------------------------- output

#[derive(Serialize)]
struct Limits {
    max_active_set_iterations: usize,
    max_coupling_iterations: usize,
    max_load_iterations: usize,
    max_eccentricity: f64,
}

#[derive(Serialize)]
struct Answer {
    eccentricity: f64,
    attitude_deg: f64,
    sommerfeld: f64,
    load_n: f64,
    max_pressure_pa: f64,
    friction_torque_nm: f64,
    friction_variable: f64,
    side_flow_m3_s: f64,
    /// Load frame: x′ along the load, y′ 90° counter-clockwise (direction of rotation).
    stiffness_n_per_m: Option<[[f64; 2]; 2]>,
    damping_ns_per_m: Option<[[f64; 2]; 2]>,
    min_film_m: f64,
    power_loss_w: f64,
    max_temperature_k: f64,
    mean_temperature_k: f64,
    max_deflection_m: f64,
    iterations: usize,
    coupling_iterations: usize,
    load_iterations: usize,
    converged: bool,
    solve_time_s: f64,
    limits: Limits,
    grid: [usize; 2],
    cavitation: &'static str,
    film_start: &'static str,
    viscosity_law: &'static str,
    elastic_liner: bool,
    thermal: bool,
}

pub(crate) fn library_failure(e: ReynoldsError) -> Failure {
    match e {
        ReynoldsError::InvalidInput { .. } | ReynoldsError::NoSolution(_) => {
            Failure::Input(e.to_string())
        }
        ReynoldsError::NotConverged { .. } | ReynoldsError::Singular(_) => {
            Failure::Run(e.to_string())
        }
    }
}

pub fn run(args: Args) -> Result<(), Failure> {
    let p = match &args.file {
        Some(path) => from_file(path, &args)?,
        None => from_flags(&args)?,
    };
    let options = JournalOptions {
        n_circumferential: p.grid.0,
        n_axial: p.grid.1,
        cavitation: match p.cavitation {
            CavitationName::Reynolds => Cavitation::Reynolds,
            CavitationName::Jfo => Cavitation::Jfo,
            CavitationName::None => Cavitation::None,
        },
        film_start: match p.film_start {
            FilmStartName::MaxGap => FilmStart::MaxGap,
            FilmStartName::Free => FilmStart::Free,
        },
        coefficients: !args.no_coefficients,
        ..JournalOptions::default()
    };
    let visc: &dyn ViscosityLaw = p.viscosity.as_ref();
    let res = match p.mode {
        Mode::Eccentricity(e) => solve_eccentricity(&p.bearing, visc, &p.op, e, &options),
        Mode::Load(w) => solve_load(&p.bearing, visc, &p.op, w, &options),
    }
    .map_err(library_failure)?;
    let answer = Answer {
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
        cavitation: match p.cavitation {
            CavitationName::Reynolds => "reynolds",
            CavitationName::Jfo => "jfo",
            CavitationName::None => "none",
        },
        film_start: match p.film_start {
            FilmStartName::MaxGap => "max-gap",
            FilmStartName::Free => "free",
        },
        viscosity_law: p.law,
        elastic_liner: p.bearing.liner.is_some(),
        thermal: p.bearing.thermal.is_some(),
    };
    check_finite(&answer, &["stiffness_n_per_m", "damping_ns_per_m"])?;
    if let Some(dir) = &args.out {
        write_outputs(&out_dir(dir)?, &res)?;
    }
    if args.json {
        print_json(&answer)?;
    } else {
        print_text(&answer);
    }
    if !res.converged {
        return Err(Failure::Run(format!(
            "the solution did not meet its tolerances within the iteration limits \
             ({} Reynolds solves, {} coupling iterations of at most {}, {} load iterations of at most {}); \
             try a finer grid, a smaller eccentricity or load",
            res.iterations,
            res.coupling_iterations,
            options.max_coupling_iterations,
            res.load_iterations,
            options.max_load_iterations
        )));
    }
    Ok(())
}

/// Never print NaN: serde_json writes non-finite numbers as `null`, so any `null` other than
/// the listed optional fields means the solver produced a non-finite value.
pub(crate) fn check_finite<T: Serialize>(answer: &T, optional: &[&str]) -> Result<(), Failure> {
    fn bad(v: &serde_json::Value, optional: &[&str]) -> bool {
        match v {
            serde_json::Value::Null => true,
            serde_json::Value::Array(a) => a.iter().any(|x| bad(x, optional)),
            serde_json::Value::Object(o) => o
                .iter()
                .any(|(k, x)| !(x.is_null() && optional.contains(&k.as_str())) && bad(x, optional)),
            _ => false,
        }
    }
    let value = serde_json::to_value(answer).map_err(|e| Failure::Run(e.to_string()))?;
    if bad(&value, optional) {
        return Err(Failure::Run(
            "the solver returned a non-finite value (NaN or infinity); nothing printed".into(),
        ));
    }
    Ok(())
}

fn print_text(a: &Answer) {
    println!(
        "journal bearing: ε = {:.4}, attitude {:.2}°, S = {:.4}",
        a.eccentricity, a.attitude_deg, a.sommerfeld
    );
    println!("  load                {:>12.4e} N", a.load_n);
    println!("  max pressure        {:>12.4e} Pa", a.max_pressure_pa);
    println!("  min film            {:>12.4e} m", a.min_film_m);
    println!(
        "  friction torque     {:>12.4e} N·m   (R/c)f = {:.4}",
        a.friction_torque_nm, a.friction_variable
    );
    println!("  side flow           {:>12.4e} m³/s", a.side_flow_m3_s);
    println!("  power loss          {:>12.4e} W", a.power_loss_w);
    if let (Some(k), Some(c)) = (a.stiffness_n_per_m, a.damping_ns_per_m) {
        println!(
            "  stiffness N/m (load frame)   [{:.4e} {:.4e}; {:.4e} {:.4e}]",
            k[0][0], k[0][1], k[1][0], k[1][1]
        );
        println!(
            "  damping N·s/m (load frame)   [{:.4e} {:.4e}; {:.4e} {:.4e}]",
            c[0][0], c[0][1], c[1][0], c[1][1]
        );
    }
    if a.thermal {
        println!(
            "  temperature max/mean {:.2} / {:.2} °C",
            a.max_temperature_k - 273.15,
            a.mean_temperature_k - 273.15
        );
    }
    if a.elastic_liner {
        println!("  max liner deflection {:.4e} m", a.max_deflection_m);
    }
    println!(
        "  {} Reynolds solves, {} coupling, {} load iterations; converged: {}; {:.3} s",
        a.iterations, a.coupling_iterations, a.load_iterations, a.converged, a.solve_time_s
    );
}

fn write_outputs(dir: &Path, res: &JournalResult) -> Result<(), Failure> {
    let p = &res.pressure;
    let nt = p.theta.len();
    let nz = p.z.len();
    if nt == 0 || nz == 0 || p.values.len() != nt * nz {
        return Err(Failure::Run("the solver returned no pressure field".into()));
    }
    // angles from the load line in [0, 360)°, sorted
    let deg: Vec<f64> = p
        .theta
        .iter()
        .map(|t| t.to_degrees().rem_euclid(360.0))
        .collect();
    let mut order: Vec<usize> = (0..nt).collect();
    order.sort_by(|&a, &b| deg[a].total_cmp(&deg[b]));
    let film_ok = res.film.values.len() == nt * nz;
    let temp_ok = res.temperature.values.len() == nt * nz;
    let degr = &deg;
    write_csv(
        &dir.join("pressure.csv"),
        &["theta_deg", "z_m", "pressure_pa", "film_m", "temperature_k"],
        order.iter().flat_map(|&i| {
            (0..nz).map(move |j| {
                let k = i * nz + j;
                vec![
                    degr[i],
                    p.z[j],
                    p.values[k],
                    if film_ok {
                        res.film.values[k]
                    } else {
                        f64::NAN
                    },
                    if temp_ok {
                        res.temperature.values[k]
                    } else {
                        f64::NAN
                    },
                ]
            })
        }),
    )?;
    // heat map, x (θ) fastest, MPa
    let mut values = Vec::with_capacity(nt * nz);
    for j in 0..nz {
        for &i in &order {
            values.push(p.values[i * nz + j] * 1e-6);
        }
    }
    let (z0, z1) = (p.z[0].min(p.z[nz - 1]), p.z[0].max(p.z[nz - 1]));
    heat_map(
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
            extent: (deg[order[0]], deg[order[nt - 1]], z0, z1),
        },
    )?;
    // mid-plane profile: the axial node nearest z = 0
    let jm = (0..nz)
        .min_by(|&a, &b| p.z[a].abs().total_cmp(&p.z[b].abs()))
        .unwrap_or(0);
    let mid: Vec<(f64, f64)> = order
        .iter()
        .map(|&i| (deg[i], p.values[i * nz + jm] * 1e-6))
        .collect();
    let curves = vec![(format!("z = {:.3e} m", p.z[jm]), mid)];
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
