//! EHL line: lubricated roller–plate line contact by the Reynolds equation (SPEC §8.4–8.5,
//! seed 002 ch. 3 and 5) — rigid or elastic, isoviscous or piezoviscous, for a given minimum
//! film or load per unit length, with the squeeze damping λ = −∂W/∂ḣ; and a transient load step
//! M ḧ + λ(h) ḣ − W₀(h) = −F (`step_to`).

use crate::analysis::{Analysis, Context};
use crate::failure::Failure;
use crate::output::{out_dir, write_csv};
use crate::table::{Table, Tables};
use rolldyn_output::{default_reason, mark_non_finite};
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_reynolds::compliance::half_space::HalfSpace;
use rolldyn_reynolds::compliance::layer::ElasticLayer;
use rolldyn_reynolds::line_contact::load_step::{LoadStep, LoadStepResult, load_step};
use rolldyn_reynolds::line_contact::transient::TransientSample;
use rolldyn_reynolds::line_contact::{
    Compliance, Constraint, LineContactOptions, LineContactResult, LubricatedLineContact, solve,
};
use rolldyn_reynolds::{Barus, Density, Isoviscous, Roelands, Viscosity as ViscosityLaw};
use rolldyn_units::{
    DynamicViscosity, Length, LoadPerLength, Mass, PerPressure, Pressure, Quantity, Speed, Time,
};
use serde::{Deserialize, Serialize, Serializer};
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The pressure–viscosity law used with a piezo coefficient.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum LawName {
    /// μ = μ₀ exp(αp) (the seed's law).
    #[default]
    Barus,
    /// Roelands with the same initial slope α (for comparisons with film formulas).
    Roelands,
}

/// The density law.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum DensityName {
    /// Constant density (the seed).
    #[default]
    Incompressible,
    /// Dowson–Higginson compressibility.
    DowsonHigginson,
}

/// A line-contact analysis: the contact, its lubricant, the mode (given minimum film or given
/// load per length) and an optional load step.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EhlLineRequest {
    /// (Reduced) roller radius R.
    pub radius: Quantity<Length>,
    /// Dynamic viscosity μ₀ at ambient pressure.
    pub viscosity: Quantity<DynamicViscosity>,
    /// Rolling (entrainment) speed u_m = (u₁ + u₂)/2; the seed's V = u₁ + u₂ = 2u_m.
    pub rolling_speed: Quantity<Speed>,
    /// Minimum film thickness h_m (given-film mode).
    #[serde(default)]
    pub min_film: Option<Quantity<Length>>,
    /// Load per unit length (inverse mode).
    #[serde(default)]
    pub load_per_length: Option<Quantity<LoadPerLength>>,
    /// Pressure–viscosity coefficient α; 0 = isoviscous.
    #[serde(default = "zero")]
    pub piezo: Quantity<PerPressure>,
    #[serde(default)]
    pub law: LawName,
    #[serde(default)]
    pub density: DensityName,
    /// Elastic bodies: `none` | `half-space` (roller and plate half-spaces) | `plate:THICKNESS`
    /// (bonded plate of that thickness + roller compressed about its axis).
    #[serde(default = "rigid")]
    pub elastic: String,
    /// Young's modulus of both bodies.
    #[serde(default = "steel_modulus")]
    pub modulus: Quantity<Pressure>,
    /// Poisson ratio of both bodies.
    #[serde(default = "steel_poisson")]
    pub poisson: f64,
    /// Normal approach speed dh/dt (positive = separating).
    #[serde(default = "zero")]
    pub squeeze_velocity: Quantity<Speed>,
    /// Grid nodes.
    #[serde(default = "thousand")]
    pub nodes: usize,
    /// Transient: step the load per length to this value at t = 0.
    #[serde(default)]
    pub step_to: Option<Quantity<LoadPerLength>>,
    /// Transient: simulated time after the step.
    #[serde(default = "one_ms")]
    pub duration: Quantity<Time>,
    /// Transient: roller length carrying the load.
    #[serde(default = "ten_mm")]
    pub contact_length: Quantity<Length>,
    /// Transient: roller mass (default: steel cylinder π R² × contact length × 7850 kg/m³).
    #[serde(default)]
    pub mass: Option<Quantity<Mass>>,
    /// Write pressure/film profiles (CSV + SVG), and the transient history, here.
    #[serde(default)]
    pub out: Option<PathBuf>,
}

fn zero<D: rolldyn_units::Dim>() -> Quantity<D> {
    Quantity::from_si(0.0)
}
fn rigid() -> String {
    "none".into()
}
fn steel_modulus() -> Quantity<Pressure> {
    Quantity::from_si(210e9)
}
fn steel_poisson() -> f64 {
    0.3
}
fn thousand() -> usize {
    1000
}
fn one_ms() -> Quantity<Time> {
    Quantity::from_si(1e-3)
}
fn ten_mm() -> Quantity<Length> {
    Quantity::from_si(10e-3)
}

fn compliance(request: &EhlLineRequest, r: f64) -> Result<Compliance, Failure> {
    let e = request.modulus.si();
    let nu = request.poisson;
    if !(e.is_finite() && e > 0.0) {
        return Err(Failure::Input("--modulus must be > 0".into()));
    }
    if !(nu > -1.0 && nu < 0.5) {
        return Err(Failure::Input("--poisson must lie in (−1, 0.5)".into()));
    }
    let spec = request.elastic.trim();
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

/// The solver's limits.
#[derive(Clone, Debug, Serialize)]
pub struct Limits {
    pub nodes: usize,
    pub max_newton_iterations: usize,
    pub continuation_steps: usize,
    pub tolerance: f64,
}

/// The summary of a load step.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TransientSummary {
    pub initial_load_per_length_n_per_m: f64,
    pub step_to_n_per_m: f64,
    pub duration_s: f64,
    pub mass_kg: f64,
    pub contact_length_m: f64,
    /// Film variable of the transient: the rigid approach h₀ (equal to h_m for rigid bodies).
    pub initial_film_m: f64,
    pub final_film_m: f64,
    pub static_film_at_new_load_m: f64,
    pub min_film_m: f64,
    pub peak_pressure_pa: f64,
    pub final_pressure_pa: f64,
    pub table_points: usize,
    pub samples: usize,
}

/// Samples of the load-step history kept for `transient.csv` and the plots.
const MAX_TRANSIENT_SAMPLES: usize = 2000;

impl TransientSummary {
    fn new(step: &LoadStep, r: &LoadStepResult) -> Self {
        Self {
            initial_load_per_length_n_per_m: r.initial_load_per_length_n_per_m,
            step_to_n_per_m: step.to,
            duration_s: step.duration,
            mass_kg: r.mass_kg,
            contact_length_m: step.contact_length,
            initial_film_m: r.initial_film_m,
            final_film_m: r.final_film_m,
            static_film_at_new_load_m: r.static_film_at_new_load_m,
            min_film_m: r.min_film_m,
            peak_pressure_pa: r.peak_pressure_pa,
            final_pressure_pa: r.final_pressure_pa,
            table_points: r.table_points,
            samples: r.samples.len(),
        }
    }

    /// The real-valued fields by their JSON keys.
    fn numbers(&self) -> [(&'static str, f64); 11] {
        [
            (
                "initial_load_per_length_n_per_m",
                self.initial_load_per_length_n_per_m,
            ),
            ("step_to_n_per_m", self.step_to_n_per_m),
            ("duration_s", self.duration_s),
            ("mass_kg", self.mass_kg),
            ("contact_length_m", self.contact_length_m),
            ("initial_film_m", self.initial_film_m),
            ("final_film_m", self.final_film_m),
            ("static_film_at_new_load_m", self.static_film_at_new_load_m),
            ("min_film_m", self.min_film_m),
            ("peak_pressure_pa", self.peak_pressure_pa),
            ("final_pressure_pa", self.final_pressure_pa),
        ]
    }
}

/// The summary of a line-contact solution (the `--json` answer).
#[derive(Clone, Debug, Serialize)]
pub struct EhlLineSummary {
    pub load_per_length_n_per_m: f64,
    pub max_pressure_pa: f64,
    pub min_film_m: f64,
    pub central_film_m: f64,
    pub outlet_position_m: f64,
    pub damping_ns_per_m2: f64,
    pub rigid_approach_m: f64,
    pub hertz_half_width_m: f64,
    pub hertz_pressure_pa: f64,
    pub iterations: usize,
    pub converged: bool,
    pub solve_time_s: f64,
    pub limits: Limits,
    pub elastic: String,
    pub piezo_per_pa: f64,
    pub sum_speed_m_s: f64,
    pub squeeze_velocity_m_s: f64,
    pub transient: Option<TransientSummary>,
}

impl EhlLineSummary {
    /// The summary as JSON under the non-finite policy of docs/outputs.md (the `transient`
    /// object carries its own `non_finite`).
    fn to_json(&self) -> serde_json::Value {
        let mut value = serde_json::to_value(self).unwrap_or_default();
        let reason = |_: &str, v: f64| default_reason(v).to_string();
        if let Some(object) = value.as_object_mut() {
            mark_non_finite(object, &self.numbers(), reason);
            if let (Some(t), Some(nested)) = (
                &self.transient,
                object.get_mut("transient").and_then(|v| v.as_object_mut()),
            ) {
                mark_non_finite(nested, &t.numbers(), reason);
            }
        }
        value
    }

    /// The real-valued top-level fields by their JSON keys.
    fn numbers(&self) -> [(&'static str, f64); 13] {
        [
            ("load_per_length_n_per_m", self.load_per_length_n_per_m),
            ("max_pressure_pa", self.max_pressure_pa),
            ("min_film_m", self.min_film_m),
            ("central_film_m", self.central_film_m),
            ("outlet_position_m", self.outlet_position_m),
            ("damping_ns_per_m2", self.damping_ns_per_m2),
            ("rigid_approach_m", self.rigid_approach_m),
            ("hertz_half_width_m", self.hertz_half_width_m),
            ("hertz_pressure_pa", self.hertz_pressure_pa),
            ("solve_time_s", self.solve_time_s),
            ("piezo_per_pa", self.piezo_per_pa),
            ("sum_speed_m_s", self.sum_speed_m_s),
            ("squeeze_velocity_m_s", self.squeeze_velocity_m_s),
        ]
    }
}

/// A line-contact solution: its summary (serialised as the `--json` answer, non-finite values
/// as `null` with their reason) and its tables.
#[derive(Clone, Debug)]
pub struct EhlLineResult {
    pub summary: EhlLineSummary,
    /// `profile`: x, pressure and film along the contact.
    pub profile: Table,
    /// `transient`: the load-step history (time, film, film rate, reaction, peak pressure).
    pub transient: Option<Table>,
}

impl EhlLineResult {
    /// The failure to report after the result when the contact did not converge (the result
    /// is still shown and its files written).
    pub fn convergence_failure(&self) -> Option<Failure> {
        let s = &self.summary;
        (!s.converged).then(|| {
            Failure::Run(format!(
                "the line contact did not converge ({} Newton iterations, limit {} per solve)",
                s.iterations, s.limits.max_newton_iterations
            ))
        })
    }
}

impl Serialize for EhlLineResult {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.summary.to_json().serialize(serializer)
    }
}

impl Tables for EhlLineResult {
    fn tables(&self) -> Vec<Table> {
        std::iter::once(self.profile.clone())
            .chain(self.transient.clone())
            .collect()
    }
}

impl fmt::Display for EhlLineResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = &self.summary;
        writeln!(
            f,
            "line contact ({}; α = {:.3e} 1/Pa; V = u₁ + u₂ = {:.4} m/s)",
            a.elastic, a.piezo_per_pa, a.sum_speed_m_s
        )?;
        writeln!(
            f,
            "  load per length   {:>12.4e} N/m",
            a.load_per_length_n_per_m
        )?;
        writeln!(f, "  max pressure      {:>12.4e} Pa", a.max_pressure_pa)?;
        writeln!(f, "  min film          {:>12.4e} m", a.min_film_m)?;
        writeln!(f, "  central film      {:>12.4e} m", a.central_film_m)?;
        writeln!(f, "  outlet position   {:>12.4e} m", a.outlet_position_m)?;
        writeln!(
            f,
            "  damping λ         {:>12.4e} N·s/m²",
            a.damping_ns_per_m2
        )?;
        if a.hertz_pressure_pa > 0.0 {
            writeln!(
                f,
                "  Hertz b, p_h      {:.4e} m, {:.4e} Pa",
                a.hertz_half_width_m, a.hertz_pressure_pa
            )?;
        }
        write!(
            f,
            "  {} Newton iterations; converged: {}; {:.3} s",
            a.iterations, a.converged, a.solve_time_s
        )?;
        if let Some(t) = &a.transient {
            write!(
                f,
                "\n  load step {:.4e} → {:.4e} N/m over {:.3e} s: h₀ {:.4e} → {:.4e} m (static {:.4e}), peak p_max {:.4e} Pa",
                t.initial_load_per_length_n_per_m,
                t.step_to_n_per_m,
                t.duration_s,
                t.initial_film_m,
                t.final_film_m,
                t.static_film_at_new_load_m,
                t.peak_pressure_pa
            )?;
        }
        Ok(())
    }
}

/// The line-contact analysis.
pub struct EhlLine;

impl Analysis for EhlLine {
    const NAME: &'static str = "ehl-line";
    type Request = EhlLineRequest;
    type Result = EhlLineResult;

    /// Solves the contact (and the load step); with `out`, writes the profiles and the
    /// history. A solution that did not converge is returned (see
    /// [`EhlLineResult::convergence_failure`]).
    fn run(request: &EhlLineRequest, _context: &Context<'_>) -> Result<EhlLineResult, Failure> {
        let r = request.radius.si();
        if !(r.is_finite() && r > 0.0) {
            return Err(Failure::Input("--radius must be > 0".into()));
        }
        let mu = request.viscosity.si();
        if !(mu.is_finite() && mu > 0.0) {
            return Err(Failure::Input("--viscosity must be > 0".into()));
        }
        let um = request.rolling_speed.si();
        rolldyn_model::bounds::check_rolling_speed("--rolling-speed", um)
            .map_err(|e| Failure::Input(e.to_string()))?;
        let vy = request.squeeze_velocity.si();
        if um == 0.0 && vy == 0.0 {
            return Err(Failure::Input(
                "zero rolling speed with zero squeeze velocity: no hydrodynamic film (give --rolling-speed or --squeeze-velocity)".into(),
            ));
        }
        if !(10..=200_000).contains(&request.nodes) {
            return Err(Failure::Input("--nodes must lie in 10…200000".into()));
        }
        let alpha = request.piezo.si();
        if alpha < 0.0 {
            return Err(Failure::Input("--piezo must be ≥ 0".into()));
        }
        let constraint = match (&request.min_film, &request.load_per_length) {
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
                let w = w.si();
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
        contact.compliance = compliance(request, r)?;
        contact.density = match request.density {
            DensityName::Incompressible => Density::Incompressible,
            DensityName::DowsonHigginson => Density::DowsonHigginson,
        };
        let visc: Box<dyn ViscosityLaw> = if alpha == 0.0 {
            Box::new(Isoviscous { mu })
        } else {
            match request.law {
                LawName::Barus => Box::new(Barus { mu0: mu, alpha }),
                LawName::Roelands => Box::new(Roelands::from_alpha(mu, alpha)),
            }
        };
        let options = LineContactOptions {
            nodes: request.nodes,
            squeeze_velocity: vy,
            ..LineContactOptions::default()
        };
        let res = solve(&contact, visc.as_ref(), constraint, &options)?;
        let transient = match request.step_to {
            None => None,
            Some(to) => {
                let step = LoadStep {
                    to: to.si(),
                    duration: request.duration.si(),
                    contact_length: request.contact_length.si(),
                    mass: request.mass.map(Quantity::si),
                    max_samples: MAX_TRANSIENT_SAMPLES,
                };
                let result = load_step(&contact, visc.as_ref(), &options, &res, &step)?;
                Some((TransientSummary::new(&step, &result), result))
            }
        };
        let summary = EhlLineSummary {
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
            elastic: request.elastic.trim().to_string(),
            piezo_per_pa: alpha,
            sum_speed_m_s: 2.0 * um,
            squeeze_velocity_m_s: vy,
            transient: transient.as_ref().map(|t| t.0),
        };
        let samples = transient.as_ref().map(|t| t.1.samples.as_slice());
        if let Some(dir) = &request.out {
            let dir = out_dir(dir)?;
            write_profiles(&dir, &res)?;
            if let Some(samples) = samples {
                write_transient(&dir, samples)?;
            }
        }
        Ok(EhlLineResult {
            summary,
            profile: profile_table(&res),
            transient: samples.map(transient_table),
        })
    }
}

const PROFILE_COLUMNS: [&str; 3] = ["x_m", "pressure_pa", "film_m"];

/// Row-major values of [`PROFILE_COLUMNS`].
fn profile_rows(res: &LineContactResult) -> Vec<f64> {
    let n = res.pressure.len().min(res.film.len());
    (0..n)
        .flat_map(|i| [res.pressure[i].0, res.pressure[i].1, res.film[i].1])
        .collect()
}

fn profile_table(res: &LineContactResult) -> Table {
    Table::from_rows(
        "profile",
        &PROFILE_COLUMNS.map(String::from),
        &profile_rows(res),
    )
}

const TRANSIENT_COLUMNS: [&str; 5] = [
    "t_s",
    "film_m",
    "film_rate_m_s",
    "reaction_n",
    "max_pressure_pa",
];

/// Row-major values of [`TRANSIENT_COLUMNS`].
fn transient_rows(samples: &[TransientSample]) -> Vec<f64> {
    samples
        .iter()
        .flat_map(|s| [s.t, s.h, s.hdot, s.reaction, s.p_max])
        .collect()
}

fn transient_table(samples: &[TransientSample]) -> Table {
    Table::from_rows(
        "transient",
        &TRANSIENT_COLUMNS.map(String::from),
        &transient_rows(samples),
    )
}

fn write_profiles(dir: &Path, res: &LineContactResult) -> Result<(), Failure> {
    write_csv(
        &dir.join("profile.csv"),
        &PROFILE_COLUMNS,
        profile_rows(res)
            .chunks(PROFILE_COLUMNS.len())
            .map(<[f64]>::to_vec),
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
        &TRANSIENT_COLUMNS,
        transient_rows(samples)
            .chunks(TRANSIENT_COLUMNS.len())
            .map(<[f64]>::to_vec),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/outputs.md: a non-finite value prints as `null` with its reason, also inside the
    /// nested `transient` object; finite values are untouched.
    #[test]
    fn non_finite_values_print_as_null_with_a_reason() {
        let transient = TransientSummary {
            initial_load_per_length_n_per_m: 1e5,
            step_to_n_per_m: 2e5,
            duration_s: 1e-3,
            mass_kg: 0.1,
            contact_length_m: 0.01,
            initial_film_m: 1e-6,
            final_film_m: f64::NAN,
            static_film_at_new_load_m: 8e-7,
            min_film_m: 7e-7,
            peak_pressure_pa: 1e9,
            final_pressure_pa: 9e8,
            table_points: 10,
            samples: 100,
        };
        let summary = EhlLineSummary {
            load_per_length_n_per_m: 1e5,
            max_pressure_pa: f64::INFINITY,
            min_film_m: 1e-6,
            central_film_m: 1.2e-6,
            outlet_position_m: 1e-4,
            damping_ns_per_m2: 1e3,
            rigid_approach_m: 1e-6,
            hertz_half_width_m: 0.0,
            hertz_pressure_pa: 0.0,
            iterations: 5,
            converged: true,
            solve_time_s: 0.01,
            limits: Limits {
                nodes: 100,
                max_newton_iterations: 50,
                continuation_steps: 1,
                tolerance: 1e-9,
            },
            elastic: "none".into(),
            piezo_per_pa: 0.0,
            sum_speed_m_s: 2.0,
            squeeze_velocity_m_s: 0.0,
            transient: Some(transient),
        };
        let result = EhlLineResult {
            summary,
            profile: Table::new("profile"),
            transient: None,
        };
        let v = serde_json::to_value(&result).unwrap();
        assert!(v["max_pressure_pa"].is_null());
        assert_eq!(v["non_finite"]["max_pressure_pa"], "diverged");
        assert_eq!(v["min_film_m"], 1e-6);
        assert!(v["transient"]["final_film_m"].is_null());
        assert_eq!(
            v["transient"]["non_finite"]["final_film_m"],
            "not defined for this run"
        );
        assert!(v["transient"]["non_finite"].get("min_film_m").is_none());
    }
}
