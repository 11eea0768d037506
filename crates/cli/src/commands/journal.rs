//! `rolldyn journal`: finite journal bearing by the Reynolds equation (SPEC §8.6, seed 002 ch. 4)
//! — pressure field, load, attitude, Sommerfeld number, friction, side flow and the 2×2
//! stiffness and damping coefficients, for a given eccentricity ratio or a given load. The model
//! file form (`--file`) adds the elastic liner + housing and the Fourier thermal model.

use crate::failure::Failure;
use crate::output::print_json;
use rolldyn::output::{out_dir, write_csv};
use rolldyn_model::journal::{JournalTarget, journal_target, load_journal, parse_grid};
use rolldyn_output::{default_reason, mark_non_finite};
use rolldyn_plot::{Field, Labels, Series, heat_map, line_plot};
use rolldyn_reynolds::journal::{
    FilmStart, JournalBearing, JournalOperating, JournalOptions, JournalResult, solve_eccentricity,
    solve_load,
};
use rolldyn_reynolds::{Cavitation, Isoviscous, Viscosity as ViscosityLaw};
use rolldyn_units::{AngularSpeed, DynamicViscosity, Force, Length, Quantity, Temperature};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, clap::ValueEnum, PartialEq, Eq, Debug)]
pub enum CavitationName {
    /// Reynolds / Swift–Stieber (p ≥ 0 by complementarity).
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson (Elrod).
    Jfo,
    /// Full Sommerfeld: sub-ambient pressures allowed.
    None,
}

#[derive(Clone, Copy, clap::ValueEnum, PartialEq, Eq, Debug)]
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

/// The flag spelling of a cavitation model (JSON `cavitation`).
fn cavitation_name(c: Cavitation) -> &'static str {
    match c {
        Cavitation::Reynolds => "reynolds",
        Cavitation::Jfo => "jfo",
        Cavitation::None => "none",
    }
}

/// The flag spelling of a film start (JSON `film_start`).
fn film_start_name(f: FilmStart) -> &'static str {
    match f {
        FilmStart::MaxGap => "max-gap",
        FilmStart::Free => "free",
    }
}

/// Grid when neither the flags nor the model file give one.
const DEFAULT_GRID: &str = "120x40";

#[derive(clap::Args)]
pub struct Args {
    /// Model file (TOML) with geometry, operating point, viscosity law, liner and thermal model
    /// (see examples/journal/seed002-ch4.toml); replaces the geometry/operating flags.
    #[arg(long, conflicts_with_all = ["radius", "length", "clearance", "viscosity", "speed", "eccentricity", "load"])]
    pub file: Option<PathBuf>,
    /// Journal radius R.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<Quantity<Length>>,
    /// Bearing length L.
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<Quantity<Length>>,
    /// Radial clearance c.
    #[arg(long, allow_hyphen_values = true)]
    pub clearance: Option<Quantity<Length>>,
    /// Dynamic viscosity μ (isoviscous).
    #[arg(long, allow_hyphen_values = true)]
    pub viscosity: Option<Quantity<DynamicViscosity>>,
    /// Journal speed (bush fixed).
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Eccentricity ratio ε = e/c, 0 < ε < 1.
    #[arg(long, conflicts_with = "load", allow_hyphen_values = true)]
    pub eccentricity: Option<f64>,
    /// Static load W: solve for the equilibrium eccentricity and attitude.
    #[arg(long, allow_hyphen_values = true)]
    pub load: Option<Quantity<Force>>,
    /// Lubricant temperature (isothermal model).
    #[arg(long, allow_hyphen_values = true, default_value = "40C")]
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
    let target = journal_target(args.eccentricity, args.load.map(Quantity::si), "--")
        .map_err(|e| Failure::Input(format!("{}: {}", e.key, e.reason)))?;
    Ok(Problem {
        bearing: JournalBearing::new(r, l, c),
        viscosity: Box::new(Isoviscous { mu }),
        law: "isoviscous",
        op: JournalOperating {
            journal_speed: w,
            bearing_speed: 0.0,
            temperature: args.temperature.si(),
        },
        target,
        cavitation: args
            .cavitation
            .map_or(Cavitation::Reynolds, CavitationName::model),
        grid: grid(args.grid.as_deref().unwrap_or(DEFAULT_GRID))?,
        film_start: args
            .film_start
            .map_or(FilmStart::MaxGap, FilmStartName::model),
    })
}

/// The model file, with the solver flags overriding its `[solver]` table.
fn from_file(path: &Path, args: &Args) -> Result<Problem, Failure> {
    let m = load_journal(path, args.temperature.si())?;
    let grid = match &args.grid {
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
        cavitation: args
            .cavitation
            .map(CavitationName::model)
            .or(m.solver.cavitation)
            .unwrap_or(Cavitation::Reynolds),
        grid,
        film_start: args
            .film_start
            .map(FilmStartName::model)
            .or(m.solver.film_start)
            .unwrap_or(FilmStart::MaxGap),
    })
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

pub fn run(args: Args) -> Result<(), Failure> {
    let p = match &args.file {
        Some(path) => from_file(path, &args)?,
        None => from_flags(&args)?,
    };
    let options = JournalOptions {
        n_circumferential: p.grid.0,
        n_axial: p.grid.1,
        cavitation: p.cavitation,
        film_start: p.film_start,
        coefficients: !args.no_coefficients,
        ..JournalOptions::default()
    };
    let visc: &dyn ViscosityLaw = p.viscosity.as_ref();
    let res = match p.target {
        JournalTarget::Eccentricity(e) => solve_eccentricity(&p.bearing, visc, &p.op, e, &options),
        JournalTarget::Load(w) => solve_load(&p.bearing, visc, &p.op, w, &options),
    }?;
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
        cavitation: cavitation_name(p.cavitation),
        film_start: film_start_name(p.film_start),
        viscosity_law: p.law,
        elastic_liner: p.bearing.liner.is_some(),
        thermal: p.bearing.thermal.is_some(),
    };
    if let Some(dir) = &args.out {
        write_outputs(&out_dir(dir)?, &res)?;
    }
    if args.json {
        print_json(&answer.to_json())?;
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

impl Answer {
    /// The answer as JSON under the non-finite policy of docs/outputs.md (a 2×2 matrix with a
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
