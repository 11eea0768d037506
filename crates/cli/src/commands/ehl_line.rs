//! `rolldyn ehl-line`: lubricated roller–plate line contact by the Reynolds equation (SPEC
//! §8.4–8.5, seed 002 ch. 3 and 5) — rigid or elastic, isoviscous or piezoviscous, for a given
//! minimum film or load per unit length, with the squeeze damping λ = −∂W/∂ḣ; and a transient
//! load step M ḧ + λ(h) ḣ − W₀(h) = −F (`--step-to`).

use super::journal::{check_finite, library_failure};
use crate::failure::Failure;
use crate::output::{out_dir, print_json, write_csv};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_reynolds::compliance::half_space::HalfSpace;
use rolldyn_reynolds::compliance::layer::ElasticLayer;
use rolldyn_reynolds::line_contact::load_damping::LoadDampingTable;
use rolldyn_reynolds::line_contact::transient::{
    Tabulated, TransientOptions, TransientSample, simulate,
};
use rolldyn_reynolds::line_contact::{
    Compliance, Constraint, LineContactOptions, LineContactResult, LubricatedLineContact, solve,
};
use rolldyn_reynolds::{Barus, Density, Isoviscous, Roelands, Viscosity as ViscosityLaw};
use rolldyn_units::{DynamicViscosity, Length, Mass, Pressure, Quantity, Speed, Time};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::sync::Arc;

#[derive(Clone, Copy, clap::ValueEnum, PartialEq, Eq)]
pub enum LawName {
    /// μ = μ₀ exp(αp) (the seed's law).
    Barus,
    /// Roelands with the same initial slope α (for comparisons with film formulas).
    Roelands,
}

#[derive(Clone, Copy, clap::ValueEnum, PartialEq, Eq)]
pub enum DensityName {
    /// Constant density (the seed).
    Incompressible,
    /// Dowson–Higginson compressibility.
    DowsonHigginson,
}

#[derive(clap::Args)]
pub struct Args {
    /// (Reduced) roller radius R.
    #[arg(long)]
    pub radius: Quantity<Length>,
    /// Dynamic viscosity μ₀ at ambient pressure.
    #[arg(long)]
    pub viscosity: Quantity<DynamicViscosity>,
    /// Rolling (entrainment) speed u_m = (u₁ + u₂)/2; the seed's V = u₁ + u₂ = 2u_m.
    #[arg(long)]
    pub rolling_speed: Quantity<Speed>,
    /// Minimum film thickness h_m (given-film mode).
    #[arg(long, conflicts_with = "load_per_length")]
    pub min_film: Option<Quantity<Length>>,
    /// Load per unit length (inverse mode): N/m, kN/m, MN/m, N/mm, kN/mm (e.g. 300kN/m).
    #[arg(long)]
    pub load_per_length: Option<String>,
    /// Pressure–viscosity coefficient α: 1/Pa, /Pa, 1/GPa (e.g. 7.5e-9/Pa); 0 = isoviscous.
    #[arg(long, default_value = "0")]
    pub piezo: String,
    /// Pressure–viscosity law used with --piezo.
    #[arg(long, value_enum, default_value = "barus")]
    pub law: LawName,
    /// Density law.
    #[arg(long, value_enum, default_value = "incompressible")]
    pub density: DensityName,
    /// Elastic bodies: none | half-space (roller and plate half-spaces) | plate:THICKNESS
    /// (bonded plate of that thickness + roller compressed about its axis).
    #[arg(long, default_value = "none")]
    pub elastic: String,
    /// Young's modulus of both bodies.
    #[arg(long, default_value = "210GPa")]
    pub modulus: Quantity<Pressure>,
    /// Poisson ratio of both bodies.
    #[arg(long, default_value = "0.3")]
    pub poisson: f64,
    /// Normal approach speed dh/dt (positive = separating).
    #[arg(long, default_value = "0m/s", allow_hyphen_values = true)]
    pub squeeze_velocity: Quantity<Speed>,
    /// Grid nodes.
    #[arg(long, default_value = "1000")]
    pub nodes: usize,
    /// Transient: step the load per length to this value at t = 0 (e.g. 600kN/m).
    #[arg(long)]
    pub step_to: Option<String>,
    /// Transient: simulated time after the step.
    #[arg(long, default_value = "1ms")]
    pub duration: Quantity<Time>,
    /// Transient: roller length carrying the load.
    #[arg(long, default_value = "10mm")]
    pub contact_length: Quantity<Length>,
    /// Transient: roller mass [default: steel cylinder π R² × contact length × 7850 kg/m³].
    #[arg(long)]
    pub mass: Option<Quantity<Mass>>,
    #[arg(long)]
    pub json: bool,
    /// Write pressure/film profiles (CSV + SVG), and the transient history, here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Splits `text` into a number and a unit from `units` (suffix, scale), longest first.
fn parse_with(text: &str, units: &[(&str, f64)], what: &str) -> Result<f64, Failure> {
    let t = text.trim();
    let accepted: Vec<&str> = units.iter().map(|u| u.0).collect();
    let bad = || {
        Failure::Input(format!(
            "{what} '{text}': expected a number with unit ({})",
            accepted.join(", ")
        ))
    };
    let (number, scale) = units
        .iter()
        .find_map(|(u, s)| t.strip_suffix(u).map(|n| (n.trim(), *s)))
        .unwrap_or((t, 1.0));
    let v: f64 = number.parse().map_err(|_| bad())?;
    if !v.is_finite() {
        return Err(bad());
    }
    Ok(v * scale)
}

/// Load per unit length, N/m.
pub(crate) fn parse_load_per_length(text: &str, what: &str) -> Result<f64, Failure> {
    Quantity::<rolldyn_units::LoadPerLength>::parse(text)
        .map(|w| w.si())
        .map_err(|e| Failure::Input(format!("{what} '{text}': {e}")))
}

/// Pressure–viscosity coefficient, 1/Pa: accepts `7.5e-9/Pa`, `7.5e-9 1/Pa`, `20/GPa`, `20 1/GPa`.
pub(crate) fn parse_piezo(text: &str) -> Result<f64, Failure> {
    parse_with(
        text,
        &[
            ("1/GPa", 1e-9),
            ("/GPa", 1e-9),
            ("1/MPa", 1e-6),
            ("/MPa", 1e-6),
            ("1/Pa", 1.0),
            ("/Pa", 1.0),
        ],
        "--piezo",
    )
}

fn compliance(args: &Args, r: f64) -> Result<Compliance, Failure> {
    let e = args.modulus.si();
    let nu = args.poisson;
    if !(e.is_finite() && e > 0.0) {
        return Err(Failure::Input("--modulus must be > 0".into()));
    }
    if !(nu > -1.0 && nu < 0.5) {
        return Err(Failure::Input("--poisson must lie in (−1, 0.5)".into()));
    }
    let spec = args.elastic.trim();
    Ok(match spec {
        "none" | "rigid" => Compliance::Rigid,
        // reference length of the log kernel: the roller diameter (only shifts the rigid
        // approach, not the film or the pressure)
        "half-space" => Compliance::HalfSpace(HalfSpace::pair(e, nu, e, nu, 2.0 * r)),
        _ => {
            let Some(t) = spec.strip_prefix("plate:") else {
                return Err(Failure::Input(format!(
                    "--elastic '{spec}': expected none, half-space or plate:THICKNESS (e.g. plate:50mm)"
                )));
            };
            let t = Quantity::<Length>::parse(t)
                .map_err(|err| Failure::Input(format!("--elastic plate thickness: {err}")))?
                .si();
            if !(t.is_finite() && t > 0.0) {
                return Err(Failure::Input(
                    "--elastic plate thickness must be > 0".into(),
                ));
            }
            Compliance::Sum(vec![
                Compliance::Layer(Arc::new(ElasticLayer::bonded(t, e, nu))),
                Compliance::HalfSpace(HalfSpace::roller_on_axis(r, e, nu)),
            ])
        }
    })
}

#[derive(Serialize)]
struct Limits {
    nodes: usize,
    max_newton_iterations: usize,
    continuation_steps: usize,
    tolerance: f64,
}

#[derive(Serialize, Clone, Copy)]
struct TransientSummary {
    initial_load_per_length_n_per_m: f64,
    step_to_n_per_m: f64,
    duration_s: f64,
    mass_kg: f64,
    contact_length_m: f64,
    /// Film variable of the transient: the rigid approach h₀ (equal to h_m for rigid bodies).
    initial_film_m: f64,
    final_film_m: f64,
    static_film_at_new_load_m: f64,
    min_film_m: f64,
    peak_pressure_pa: f64,
    final_pressure_pa: f64,
    table_points: usize,
    samples: usize,
}

#[derive(Serialize)]
struct Answer {
    load_per_length_n_per_m: f64,
    max_pressure_pa: f64,
    min_film_m: f64,
    central_film_m: f64,
    outlet_position_m: f64,
    damping_ns_per_m2: f64,
    rigid_approach_m: f64,
    hertz_half_width_m: f64,
    hertz_pressure_pa: f64,
    iterations: usize,
    converged: bool,
    solve_time_s: f64,
    limits: Limits,
    elastic: String,
    piezo_per_pa: f64,
    sum_speed_m_s: f64,
    squeeze_velocity_m_s: f64,
    transient: Option<TransientSummary>,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let r = args.radius.si();
    if !(r.is_finite() && r > 0.0) {
        return Err(Failure::Input("--radius must be > 0".into()));
    }
    let mu = args.viscosity.si();
    if !(mu.is_finite() && mu > 0.0) {
        return Err(Failure::Input("--viscosity must be > 0".into()));
    }
    let um = args.rolling_speed.si();
    let vy = args.squeeze_velocity.si();
    if um == 0.0 && vy == 0.0 {
        return Err(Failure::Input(
            "zero rolling speed with zero squeeze velocity: no hydrodynamic film (give --rolling-speed or --squeeze-velocity)".into(),
        ));
    }
    if !(10..=200_000).contains(&args.nodes) {
        return Err(Failure::Input("--nodes must lie in 10…200000".into()));
    }
    let alpha = parse_piezo(&args.piezo)?;
    if alpha < 0.0 {
        return Err(Failure::Input("--piezo must be ≥ 0".into()));
    }
    let constraint = match (&args.min_film, &args.load_per_length) {
        (Some(h), None) => {
            let h = h.si();
            if !(h.is_finite() && h > 0.0) {
                return Err(Failure::Input(format!(
                    "--min-film must be > 0 (got {h} m)"
                )));
            }
            Constraint::MinFilm(h)
        }
        (None, Some(w)) => {
            let w = parse_load_per_length(w, "--load-per-length")?;
            if !(w.is_finite() && w > 0.0) {
                return Err(Failure::Input(format!(
                    "--load-per-length must be > 0 (got {w} N/m)"
                )));
            }
            Constraint::LoadPerLength(w)
        }
        _ => {
            return Err(Failure::Input(
                "give exactly one of --min-film or --load-per-length".into(),
            ));
        }
    };
    let mut contact = LubricatedLineContact::new(r, 2.0 * um);
    contact.compliance = compliance(&args, r)?;
    contact.density = match args.density {
        DensityName::Incompressible => Density::Incompressible,
        DensityName::DowsonHigginson => Density::DowsonHigginson,
    };
    let visc: Box<dyn ViscosityLaw> = if alpha == 0.0 {
        Box::new(Isoviscous { mu })
    } else {
        match args.law {
            LawName::Barus => Box::new(Barus { mu0: mu, alpha }),
            LawName::Roelands => Box::new(Roelands::from_alpha(mu, alpha)),
        }
    };
    let options = LineContactOptions {
        nodes: args.nodes,
        squeeze_velocity: vy,
        ..LineContactOptions::default()
    };
    let res = solve(&contact, visc.as_ref(), constraint, &options).map_err(library_failure)?;

    let transient = match &args.step_to {
        None => None,
        Some(text) => Some(run_transient(
            &args,
            &contact,
            visc.as_ref(),
            &options,
            &res,
            parse_load_per_length(text, "--step-to")?,
        )?),
    };
    let answer = Answer {
        load_per_length_n_per_m: res.load_per_length_n_per_m,
        max_pressure_pa: res.max_pressure_pa,
        min_film_m: res.min_film_m,
        central_film_m: res.central_film_m,
        outlet_position_m: res.outlet_position_m,
        damping_ns_per_m2: res.damping_ns_per_m2,
        rigid_approach_m: res.rigid_approach_m,
        hertz_half_width_m: res.hertz_half_width_m,
        hertz_pressure_pa: res.hertz_pressure_pa,
        iterations: res.iterations,
        converged: res.converged,
        solve_time_s: res.solve_time_s,
        limits: Limits {
            nodes: options.nodes,
            max_newton_iterations: options.max_iterations,
            continuation_steps: options.continuation_steps,
            tolerance: options.tolerance,
        },
        elastic: args.elastic.trim().to_string(),
        piezo_per_pa: alpha,
        sum_speed_m_s: 2.0 * um,
        squeeze_velocity_m_s: vy,
        transient: transient.as_ref().map(|t| t.0),
    };
    check_finite(&answer, &["transient"])?;
    if let Some(dir) = &args.out {
        let dir = out_dir(dir)?;
        write_profiles(&dir, &res)?;
        if let Some((_, samples)) = &transient {
            write_transient(&dir, samples)?;
        }
    }
    if args.json {
        print_json(&answer)?;
    } else {
        print_text(&answer);
    }
    if !res.converged {
        return Err(Failure::Run(format!(
            "the line contact did not converge ({} Newton iterations, limit {} per solve)",
            res.iterations, options.max_iterations
        )));
    }
    Ok(())
}

fn run_transient(
    args: &Args,
    contact: &LubricatedLineContact,
    visc: &dyn ViscosityLaw,
    options: &LineContactOptions,
    start: &LineContactResult,
    w2: f64,
) -> Result<(TransientSummary, Vec<TransientSample>), Failure> {
    if !(w2.is_finite() && w2 > 0.0) {
        return Err(Failure::Input(format!(
            "--step-to must be > 0 (got {w2} N/m)"
        )));
    }
    if options.squeeze_velocity != 0.0 {
        return Err(Failure::Input(
            "--step-to starts from a steady state: do not combine it with --squeeze-velocity"
                .into(),
        ));
    }
    let duration = args.duration.si();
    if !(duration > 0.0 && duration.is_finite()) {
        return Err(Failure::Input("--duration must be > 0".into()));
    }
    let ell = args.contact_length.si();
    if !(ell > 0.0 && ell.is_finite()) {
        return Err(Failure::Input("--contact-length must be > 0".into()));
    }
    let r = contact.radius;
    let mass = args
        .mass
        .map_or(7850.0 * std::f64::consts::PI * r * r * ell, Quantity::si);
    if !(mass > 0.0 && mass.is_finite()) {
        return Err(Failure::Input("--mass must be > 0".into()));
    }
    let w1 = start.load_per_length_n_per_m;
    let h1 = start.rigid_approach_m;
    let quiet = LineContactOptions {
        damping: false,
        ..*options
    };
    let end =
        solve(contact, visc, Constraint::LoadPerLength(w2), &quiet).map_err(library_failure)?;
    let h2 = end.rigid_approach_m;
    if !(h1 > 0.0 && h2 > 0.0) {
        return Err(Failure::Input(format!(
            "the transient mode tabulates W₀, λ over the rigid approach h₀, which must stay > 0 \
             (got {h1:.3e} m → {h2:.3e} m with --elastic {}); use --elastic none or a lighter load",
            args.elastic
        )));
    }
    let (lo, hi) = (0.7 * h1.min(h2), 1.3 * h1.max(h2));
    let n = 11;
    let hs: Vec<f64> = (0..n)
        .map(|k| lo * (hi / lo).powf(k as f64 / (n - 1) as f64))
        .collect();
    let table = LoadDampingTable::build(contact, visc, &hs, options).map_err(library_failure)?;
    let film = Tabulated {
        table: &table,
        length: ell,
        v: contact.sum_speed(),
        r,
    };
    let force = |_: f64| w2 * ell;
    let mut samples = simulate(
        &film,
        mass,
        &force,
        h1,
        0.0,
        duration,
        &TransientOptions::default(),
    )
    .map_err(library_failure)?;
    if samples.iter().any(|s| s.h <= lo || s.h >= hi) {
        return Err(Failure::Run(format!(
            "the film left the tabulated range {lo:.3e}…{hi:.3e} m during the transient \
             (inertia overshoot); shorten --duration or reduce the step"
        )));
    }
    // thin to ≤ 2000 samples for output
    if samples.len() > 2000 {
        let step = samples.len().div_ceil(2000);
        let last = *samples.last().expect("non-empty");
        samples = samples.into_iter().step_by(step).collect();
        if samples.last() != Some(&last) {
            samples.push(last);
        }
    }
    let last = *samples
        .last()
        .ok_or_else(|| Failure::Run("the transient returned no samples".into()))?;
    let summary = TransientSummary {
        initial_load_per_length_n_per_m: w1,
        step_to_n_per_m: w2,
        duration_s: duration,
        mass_kg: mass,
        contact_length_m: ell,
        initial_film_m: h1,
        final_film_m: last.h,
        static_film_at_new_load_m: h2,
        min_film_m: samples.iter().map(|s| s.h).fold(f64::INFINITY, f64::min),
        peak_pressure_pa: samples.iter().map(|s| s.p_max).fold(0.0, f64::max),
        final_pressure_pa: last.p_max,
        table_points: n,
        samples: samples.len(),
    };
    Ok((summary, samples))
}

fn print_text(a: &Answer) {
    println!(
        "line contact ({}; α = {:.3e} 1/Pa; V = u₁ + u₂ = {:.4} m/s)",
        a.elastic, a.piezo_per_pa, a.sum_speed_m_s
    );
    println!(
        "  load per length   {:>12.4e} N/m",
        a.load_per_length_n_per_m
    );
    println!("  max pressure      {:>12.4e} Pa", a.max_pressure_pa);
    println!("  min film          {:>12.4e} m", a.min_film_m);
    println!("  central film      {:>12.4e} m", a.central_film_m);
    println!("  outlet position   {:>12.4e} m", a.outlet_position_m);
    println!("  damping λ         {:>12.4e} N·s/m²", a.damping_ns_per_m2);
    if a.hertz_pressure_pa > 0.0 {
        println!(
            "  Hertz b, p_h      {:.4e} m, {:.4e} Pa",
            a.hertz_half_width_m, a.hertz_pressure_pa
        );
    }
    println!(
        "  {} Newton iterations; converged: {}; {:.3} s",
        a.iterations, a.converged, a.solve_time_s
    );
    if let Some(t) = &a.transient {
        println!(
            "  load step {:.4e} → {:.4e} N/m over {:.3e} s: h₀ {:.4e} → {:.4e} m (static {:.4e}), peak p_max {:.4e} Pa",
            t.initial_load_per_length_n_per_m,
            t.step_to_n_per_m,
            t.duration_s,
            t.initial_film_m,
            t.final_film_m,
            t.static_film_at_new_load_m,
            t.peak_pressure_pa
        );
    }
}

fn write_profiles(dir: &Path, res: &LineContactResult) -> Result<(), Failure> {
    let n = res.pressure.len().min(res.film.len());
    write_csv(
        &dir.join("profile.csv"),
        &["x_m", "pressure_pa", "film_m"],
        (0..n).map(|i| vec![res.pressure[i].0, res.pressure[i].1, res.film[i].1]),
    )?;
    let p: Vec<(f64, f64)> = res
        .pressure
        .iter()
        .map(|&(x, p)| (x * 1e3, p * 1e-6))
        .collect();
    let h: Vec<(f64, f64)> = res.film.iter().map(|&(x, h)| (x * 1e3, h * 1e6)).collect();
    let pc = vec![("pressure".to_string(), p)];
    line_plot(
        &dir.join("pressure.svg"),
        &Labels {
            title: "Film pressure",
            x: "x, mm",
            y: "pressure, MPa",
        },
        &Series::from_pairs(&pc),
    )?;
    let hc = vec![("film".to_string(), h)];
    line_plot(
        &dir.join("film.svg"),
        &Labels {
            title: "Film thickness",
            x: "x, mm",
            y: "film, µm",
        },
        &Series::from_pairs(&hc),
    )?;
    Ok(())
}

fn write_transient(dir: &Path, samples: &[TransientSample]) -> Result<(), Failure> {
    write_csv(
        &dir.join("transient.csv"),
        &[
            "t_s",
            "film_m",
            "film_rate_m_s",
            "reaction_n",
            "max_pressure_pa",
        ],
        samples
            .iter()
            .map(|s| vec![s.t, s.h, s.hdot, s.reaction, s.p_max]),
    )?;
    let h = vec![(
        "h_m(t)".to_string(),
        samples.iter().map(|s| (s.t * 1e3, s.h * 1e6)).collect(),
    )];
    line_plot(
        &dir.join("transient_film.svg"),
        &Labels {
            title: "Film after the load step",
            x: "time, ms",
            y: "film h, µm",
        },
        &Series::from_pairs(&h),
    )?;
    let p = vec![(
        "p_max(t)".to_string(),
        samples
            .iter()
            .map(|s| (s.t * 1e3, s.p_max * 1e-6))
            .collect(),
    )];
    line_plot(
        &dir.join("transient_pressure.svg"),
        &Labels {
            title: "Maximum pressure after the load step",
            x: "time, ms",
            y: "p_max, MPa",
        },
        &Series::from_pairs(&p),
    )?;
    Ok(())
}
