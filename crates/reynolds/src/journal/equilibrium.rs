//! Journal-bearing solutions for a given eccentricity ratio or a given load (equilibrium
//! eccentricity and attitude by a bracketed secant/bisection search on ln|F|(ε)).

use super::coefficients::{coefficients, rotate};
use super::solver::{JournalState, solve_state_impl, validate};
use super::{JournalBearing, JournalOperating, JournalOptions, JournalResult, SurfaceField};
use crate::error::{Result, ReynoldsError};
use crate::viscosity::Viscosity;
use std::time::Instant;

/// Solves at a given eccentricity ratio ε ∈ (0, 1) (journal displaced along the bearing +x axis;
/// the results are rotated into the load frame).
pub fn solve_eccentricity(
    bearing: &JournalBearing,
    viscosity: &dyn Viscosity,
    op: &JournalOperating,
    eccentricity: f64,
    options: &JournalOptions,
) -> Result<JournalResult> {
    let t0 = Instant::now();
    validate(bearing, op, options)?;
    check_eps(eccentricity)?;
    let a = working_angle(options);
    let e = [
        eccentricity * bearing.clearance * a.cos(),
        eccentricity * bearing.clearance * a.sin(),
    ];
    let st = solve_state_impl(bearing, viscosity, op, e, [0.0, 0.0], options, None, None)?;
    finish(bearing, viscosity, op, e, st, options, 0, true, t0)
}

/// Direction of the journal displacement in the bearing frame used for the solve: the maximum
/// gap (θ = angle + π) falls exactly on a grid column, so that the Raimondi–Boyd supply line
/// ([`super::FilmStart::MaxGap`]) sits at the maximum gap also for odd circumferential counts.
/// Results are reported in the load frame and do not depend on this choice otherwise.
fn working_angle(options: &JournalOptions) -> f64 {
    let n = options.n_circumferential.max(1);
    let dth = std::f64::consts::TAU / n as f64;
    (n / 2) as f64 * dth - std::f64::consts::PI
}

fn check_eps(eps: f64) -> Result<()> {
    if !(eps.is_finite() && eps > 0.0 && eps < 1.0) {
        return Err(ReynoldsError::InvalidInput {
            what: "eccentricity",
            reason: format!(
                "ε = {eps}: must satisfy 0 < ε < 1 (ε ≥ 1 is contact; at ε = 0 the load and the \
                 Sommerfeld number are undefined)"
            ),
        });
    }
    Ok(())
}

/// Solves for the equilibrium under a static load of magnitude `load_n` (N). The load direction
/// defines the load frame of the results.
pub fn solve_load(
    bearing: &JournalBearing,
    viscosity: &dyn Viscosity,
    op: &JournalOperating,
    load_n: f64,
    options: &JournalOptions,
) -> Result<JournalResult> {
    let t0 = Instant::now();
    validate(bearing, op, options)?;
    if !(load_n.is_finite() && load_n > 0.0) {
        return Err(ReynoldsError::InvalidInput {
            what: "load",
            reason: format!("{load_n} N: must be finite and > 0"),
        });
    }
    let a = working_angle(options);
    let mut search = LoadSearch {
        bearing,
        viscosity,
        op,
        options,
        dir: (a.cos(), a.sin()),
        load_n,
        target: load_n.ln(),
        evals: 0,
        solves: 0,
        last: None,
    };
    let (eps, converged) = search.equilibrium()?;
    let e = search.position(eps);
    let st = search
        .last
        .ok_or(ReynoldsError::Singular("equilibrium search"))?;
    let mut res = finish(
        bearing,
        viscosity,
        op,
        e,
        st,
        options,
        search.evals,
        converged,
        t0,
    )?;
    res.iterations = search.solves;
    Ok(res)
}

/// The equilibrium search of [`solve_load`]: ln|F|(ε) − ln W bracketed, then its root by Brent.
struct LoadSearch<'a> {
    bearing: &'a JournalBearing,
    viscosity: &'a dyn Viscosity,
    op: &'a JournalOperating,
    options: &'a JournalOptions,
    /// Direction of the journal displacement in the bearing frame (cos, sin).
    dir: (f64, f64),
    /// Load W, N.
    load_n: f64,
    /// ln W.
    target: f64,
    /// States evaluated.
    evals: usize,
    /// Direct Reynolds solves of those states.
    solves: usize,
    /// Last state evaluated (the warm start of the next).
    last: Option<JournalState>,
}

impl LoadSearch<'_> {
    /// Journal position at eccentricity ratio `eps`, m.
    fn position(&self, eps: f64) -> [f64; 2] {
        let c = self.bearing.clearance;
        [eps * c * self.dir.0, eps * c * self.dir.1]
    }

    /// ln|F(ε)| − ln W, warm-started from the last state.
    fn eval(&mut self, eps: f64) -> Result<f64> {
        let st = solve_state_impl(
            self.bearing,
            self.viscosity,
            self.op,
            self.position(eps),
            [0.0, 0.0],
            self.options,
            self.last.as_ref(),
            None,
        )?;
        self.evals += 1;
        self.solves += st.iterations;
        let f = st.force[0].hypot(st.force[1]).max(1e-300).ln() - self.target;
        self.last = Some(st);
        Ok(f)
    }

    /// Equilibrium eccentricity ratio and whether the search converged (otherwise the middle of
    /// the bracket); `last` holds the state there.
    fn equilibrium(&mut self) -> Result<(f64, bool)> {
        let (a, b, fa, fb) = self.bracket()?;
        let options = self.options;
        // Brent in u = −ln(1 − ε) (ln W is close to linear in u at large ε)
        let u = |e: f64| -(1.0 - e).ln();
        let inv = |u: f64| 1.0 - (-u).exp();
        let (root, _, _) = match crate::roots::brent(
            |uu| self.eval(inv(uu)),
            u(a),
            u(b),
            fa,
            fb,
            1e-13,
            options.load_tolerance,
            options.max_load_iterations,
        ) {
            Ok(v) => v,
            Err(ReynoldsError::NotConverged { .. }) => (f64::NAN, 0.0, 0),
            Err(e) => return Err(e),
        };
        let converged = root.is_finite();
        // re-evaluate at the root so that the returned state is the one at ε (Brent's last
        // evaluation is not always the best point)
        let eps = if converged { inv(root) } else { 0.5 * (a + b) };
        if converged
            && self
                .last
                .as_ref()
                .map(|s| ((s.force[0].hypot(s.force[1])).ln() - self.target).abs())
                > Some(options.load_tolerance)
        {
            self.eval(eps)?;
        }
        Ok((eps, converged))
    }

    /// Bracket [a, b] of the equilibrium with the function values (f(a) ≤ 0 ≤ f(b)): b at the
    /// largest eccentricity allowed, a lowered tenfold from 0.05 until the load exceeds the
    /// capacity there.
    fn bracket(&mut self) -> Result<(f64, f64, f64, f64)> {
        let load_n = self.load_n;
        let emax = self.options.max_eccentricity.min(0.9999);
        let (mut a, mut b) = (0.05f64, emax);
        let mut fb = self.eval(b)?;
        if fb < 0.0 {
            return Err(ReynoldsError::NoSolution(format!(
                "load {load_n} N exceeds the capacity {:.4e} N at ε = {emax}",
                (fb + self.target).exp()
            )));
        }
        let mut fa = self.eval(a)?;
        while fa > 0.0 {
            b = a;
            fb = fa;
            a *= 0.1;
            if a < 1e-9 {
                return Err(ReynoldsError::NoSolution(format!(
                    "load {load_n} N is below the capacity at ε = 1e-9"
                )));
            }
            fa = self.eval(a)?;
        }
        Ok((a, b, fa, fb))
    }
}

#[allow(clippy::too_many_arguments)]
fn finish(
    b: &JournalBearing,
    visc: &dyn Viscosity,
    op: &JournalOperating,
    e: [f64; 2],
    st: JournalState,
    opt: &JournalOptions,
    load_iterations: usize,
    load_converged: bool,
    t0: Instant,
) -> Result<JournalResult> {
    let (r, c, l) = (b.radius, b.clearance, b.length);
    let w = [-st.force[0], -st.force[1]];
    let load = w[0].hypot(w[1]);
    if load.is_nan() || load <= 0.0 {
        return Err(ReynoldsError::NoSolution("the film carries no load".into()));
    }
    let beta = w[1].atan2(w[0]);
    let (sb, cb) = beta.sin_cos();
    let ev = [cb * e[0] + sb * e[1], -sb * e[0] + cb * e[1]];
    let spin = op.journal_speed + op.bearing_speed;
    let mut psi = ev[1].atan2(ev[0]).to_degrees();
    if spin < 0.0 {
        psi = -psi;
    }
    let mu0 = visc.viscosity(0.0, op.temperature);
    let nrev = spin.abs() / std::f64::consts::TAU;
    let pm = load / (2.0 * r * l);
    let sommerfeld = (r / c).powi(2) * mu0 * nrev / pm;
    let friction = -st.journal_torque;
    let (mut kk, mut dd) = ([[0.0; 2]; 2], [[0.0; 2]; 2]);
    let mut coeff_ok = true;
    if opt.coefficients {
        let (k, d, _, ok) = coefficients(b, visc, op, e, &st, opt)?;
        kk = rotate(k, beta);
        dd = rotate(d, beta);
        coeff_ok = ok;
    }
    let eps = e[0].hypot(e[1]) / c;
    let field = |v: &[f64]| expand(&st, v, beta, l);
    let isothermal = b.thermal.is_none();
    let tmax = st.temperature.iter().fold(f64::MIN, |a, &v| a.max(v));
    let tmean = st.temperature.iter().sum::<f64>() / st.temperature.len() as f64;
    Ok(JournalResult {
        eccentricity: eps,
        attitude_deg: psi,
        sommerfeld,
        load_n: load,
        max_pressure_pa: st.max_pressure,
        friction_torque_nm: friction,
        bearing_torque_nm: st.bearing_torque,
        friction_variable: friction / (load * c),
        side_flow_m3_s: st.side_flow,
        power_loss_w: st.power_loss,
        min_film_m: st.min_film,
        eccentricity_vector_m: ev,
        stiffness_n_per_m: kk,
        damping_ns_per_m: dd,
        max_temperature_k: if isothermal { op.temperature } else { tmax },
        mean_temperature_k: if isothermal { op.temperature } else { tmean },
        max_deflection_m: st.deflection.iter().fold(0.0f64, |a, &v| a.max(v)),
        iterations: st.iterations,
        coupling_iterations: st.coupling_iterations,
        load_iterations,
        converged: st.converged && load_converged && coeff_ok,
        solve_time_s: t0.elapsed().as_secs_f64(),
        pressure: field(&st.pressure),
        film: field(&st.film),
        temperature: if isothermal {
            SurfaceField::default()
        } else {
            field(&st.temperature)
        },
    })
}

/// Expands a (half-length) nodal field to the full surface in load-frame angles.
fn expand(st: &JournalState, v: &[f64], beta: f64, length: f64) -> SurfaceField {
    let g = &st.grid;
    let nfull = st.n_axial_full;
    let dz = length / (nfull - 1) as f64;
    let z: Vec<f64> = (0..nfull).map(|j| -0.5 * length + j as f64 * dz).collect();
    let theta: Vec<f64> = (0..g.nx)
        .map(|i| (i as f64 * g.dx - beta).rem_euclid(std::f64::consts::TAU))
        .collect();
    let mut values = vec![0.0; g.nx * nfull];
    for i in 0..g.nx {
        for j in 0..nfull {
            let js = if st.symmetric && j >= g.ny {
                nfull - 1 - j
            } else {
                j
            };
            values[i * nfull + j] = v[i * g.ny + js.min(g.ny - 1)];
        }
    }
    SurfaceField { theta, z, values }
}
