//! The journal-bearing state at a given journal position and velocity: builds the dimensionless
//! film fields, solves the Reynolds equation (with the coupled viscosity, liner deflection and
//! temperature iteration of seed 002 (4.31)) and integrates forces, torques and flows.

use super::{CavitatedShear, FilmStart, JournalBearing, JournalOperating, JournalOptions};
use crate::error::{Result, ReynoldsError, finite, positive};
use crate::grid::{Axis, EdgeBc, Grid2d};
use crate::reynolds2d::{self, Fields2d, ReynoldsOptions, Solution2d};
use crate::viscosity::Viscosity;
use crate::waviness::WavySurface;

/// Solution of the journal bearing at one journal position/velocity (bearing frame, SI).
#[derive(Debug, Clone)]
pub struct JournalState {
    /// Grid actually solved (half length when symmetric).
    pub grid: Grid2d,
    /// True when only half the length was solved (z ≤ 0 side).
    pub symmetric: bool,
    /// Axial node count of the full length.
    pub n_axial_full: usize,
    /// Pressure, Pa (index i·ny + j of `grid`).
    pub pressure: Vec<f64>,
    /// Film thickness, m.
    pub film: Vec<f64>,
    /// Fill fraction θ.
    pub fill: Vec<f64>,
    /// True at cavitated nodes.
    pub cavitated: Vec<bool>,
    /// Film temperature, K.
    pub temperature: Vec<f64>,
    /// Liner deflection, m.
    pub deflection: Vec<f64>,
    /// Viscosity, Pa·s.
    pub viscosity: Vec<f64>,
    /// Fluid force on the journal in the bearing frame, N.
    pub force: [f64; 2],
    /// Torque of the fluid on the journal (counter-clockwise positive), N·m.
    pub journal_torque: f64,
    /// Torque of the fluid on the bush (counter-clockwise positive), N·m.
    pub bearing_torque: f64,
    /// Net outflow through both ends, m³/s.
    pub side_flow: f64,
    /// Maximum pressure, Pa.
    pub max_pressure: f64,
    /// Minimum film, m.
    pub min_film: f64,
    /// Dissipated power, W.
    pub power_loss: f64,
    /// Direct Reynolds solves.
    pub iterations: usize,
    /// Coupled iterations.
    pub coupling_iterations: usize,
    /// All iterations converged.
    pub converged: bool,
    pub(crate) reynolds: Solution2d,
}

/// Reference speed for scaling, m/s (errors when nothing drives the film).
pub(crate) fn reference_speed(
    b: &JournalBearing,
    op: &JournalOperating,
    edot: [f64; 2],
) -> Result<f64> {
    let (ub, uj) = (op.bearing_speed * b.radius, op.journal_speed * b.radius);
    let sq = (edot[0].hypot(edot[1])) * b.radius / b.clearance;
    let v = (ub + uj).abs().max((uj - ub).abs()).max(sq);
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(ReynoldsError::InvalidInput {
            what: "speed",
            reason: "zero journal and bush speed with zero squeeze velocity: no hydrodynamic film"
                .into(),
        })
    }
}

pub(crate) fn validate(
    b: &JournalBearing,
    op: &JournalOperating,
    opt: &JournalOptions,
) -> Result<()> {
    positive("radius", b.radius)?;
    positive("length", b.length)?;
    positive("clearance", b.clearance)?;
    finite("journal speed", op.journal_speed)?;
    finite("bearing speed", op.bearing_speed)?;
    positive("temperature", op.temperature)?;
    if b.slip.k1 < 0.0 || b.slip.k2 < 0.0 {
        return Err(ReynoldsError::InvalidInput {
            what: "slip length",
            reason: "must be ≥ 0".into(),
        });
    }
    if opt.n_circumferential < 8 || opt.n_axial < 3 {
        return Err(ReynoldsError::InvalidInput {
            what: "grid",
            reason: format!(
                "{}×{} is too coarse (≥ 8×3)",
                opt.n_circumferential, opt.n_axial
            ),
        });
    }
    if !(opt.coupling_relaxation > 0.0 && opt.coupling_relaxation <= 1.0) {
        return Err(ReynoldsError::InvalidInput {
            what: "coupling relaxation",
            reason: "must be in (0, 1]".into(),
        });
    }
    if let Some(t) = &b.thermal {
        t.validate(b.radius + b.clearance)?;
    }
    Ok(())
}

/// Solves the bearing at journal position `e` (m) and velocity `edot` (m/s), bearing frame.
pub fn solve_state(
    bearing: &JournalBearing,
    viscosity: &dyn Viscosity,
    op: &JournalOperating,
    e: [f64; 2],
    edot: [f64; 2],
    options: &JournalOptions,
    warm: Option<&JournalState>,
) -> Result<JournalState> {
    solve_state_impl(bearing, viscosity, op, e, edot, options, warm, None)
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_state_impl(
    b: &JournalBearing,
    visc: &dyn Viscosity,
    op: &JournalOperating,
    e: [f64; 2],
    edot: [f64; 2],
    opt: &JournalOptions,
    warm: Option<&JournalState>,
    frozen_temperature: Option<&[f64]>,
) -> Result<JournalState> {
    validate(b, op, opt)?;
    finite("eccentricity", e[0])?;
    finite("eccentricity", e[1])?;
    finite("squeeze velocity", edot[0])?;
    finite("squeeze velocity", edot[1])?;
    let (r, c) = (b.radius, b.clearance);
    let eps = e[0].hypot(e[1]) / c;
    if eps >= 1.0 {
        return Err(ReynoldsError::InvalidInput {
            what: "eccentricity",
            reason: format!("ε = {eps} ≥ 1: the journal touches the bush"),
        });
    }
    let vref = reference_speed(b, op, edot)?;
    let mu0 = visc.viscosity(0.0, op.temperature);
    positive("viscosity μ(0, T)", mu0)?;
    let p_ref = mu0 * vref * r / (c * c);
    // grid
    let nt = opt.n_circumferential;
    let nfull = opt.n_axial;
    let dzeta = b.length / r / (nfull - 1) as f64;
    let (ny, top) = if opt.axial_symmetry {
        if nfull % 2 == 1 {
            (nfull.div_ceil(2), EdgeBc::SymmetryNode)
        } else {
            (nfull / 2, EdgeBc::SymmetryFace)
        }
    } else {
        (nfull, EdgeBc::Pressure(0.0))
    };
    let grid = Grid2d {
        nx: nt,
        ny,
        dx: std::f64::consts::TAU / nt as f64,
        dy: dzeta,
        x_axis: Axis::Periodic,
        y_axis: Axis::Ends(EdgeBc::Pressure(0.0), top),
    };
    let n = grid.len();
    let dth = grid.dx;
    // geometric film and squeeze (per θ column)
    let (ub, uj) = (op.bearing_speed * r, op.journal_speed * r);
    let wave_speed = match b.waviness.surface {
        WavySurface::First => op.bearing_speed,
        WavySurface::Second => op.journal_speed,
    };
    let mut hg = vec![0.0; nt];
    let mut dhdt = vec![0.0; nt];
    for i in 0..nt {
        let th = i as f64 * dth;
        let (s, co) = th.sin_cos();
        hg[i] = c - e[0] * co - e[1] * s + b.waviness.value(th);
        dhdt[i] = -edot[0] * co - edot[1] * s + b.waviness.squeeze(th, wave_speed);
        if hg[i] <= 0.0 {
            return Err(ReynoldsError::InvalidInput {
                what: "film thickness",
                reason: format!(
                    "h ≤ 0 at θ = {th:.3} rad (eccentricity plus waviness ≥ clearance)"
                ),
            });
        }
    }
    // feed groove, or ambient pressure on the maximum-gap line
    let supply = match (&b.feed, opt.film_start) {
        (Some(f), _) => {
            finite("feed pressure", f.pressure)?;
            Some((f.angle, f.pressure))
        }
        (None, FilmStart::MaxGap) if eps > 0.0 => {
            Some((e[1].atan2(e[0]) + std::f64::consts::PI, 0.0))
        }
        _ => None,
    };
    let mut prescribed = Vec::new();
    if let Some((angle, pressure)) = supply {
        prescribed = vec![f64::NAN; n];
        let i = ((angle.rem_euclid(std::f64::consts::TAU) / dth).round() as usize) % nt;
        for j in 1..ny {
            prescribed[grid.idx(i, j)] = pressure / p_ref;
        }
    }
    // liner kernel weights
    let liner_w = match &b.liner {
        Some(k) => Some(k.circulant(nt)?),
        None => None,
    };
    let thermal = if frozen_temperature.is_some() {
        None
    } else {
        b.thermal
    };
    let t_resp = thermal.map(|t| t.response(r + c));
    let coupled = liner_w.is_some() || thermal.is_some() || !visc.pressure_independent();
    // state
    let warm = warm.filter(|w| w.pressure.len() == n);
    let mut pc: Vec<f64> = warm
        .map(|w| w.pressure.clone())
        .unwrap_or_else(|| vec![0.0; n]);
    let mut temp: Vec<f64> = match (frozen_temperature, warm) {
        (Some(t), _) if t.len() == n => t.to_vec(),
        (_, Some(w)) => w.temperature.clone(),
        _ => vec![
            thermal
                .map(|t| t.ambient_temperature)
                .unwrap_or(op.temperature);
            n
        ],
    };
    let mut defl = vec![0.0; n];
    let update_defl = |p: &[f64], out: &mut Vec<f64>| {
        if let Some(w) = &liner_w {
            for j in 0..ny {
                for i in 0..nt {
                    let mut s = 0.0;
                    for k in 0..nt {
                        let pk = p[k * ny + j];
                        if pk > 0.0 {
                            s += w[(i + nt - k) % nt] * pk;
                        }
                    }
                    out[i * ny + j] = s;
                }
            }
        }
    };
    if warm.is_some() {
        update_defl(&pc, &mut defl);
    }
    let ropt = ReynoldsOptions {
        cavitation: opt.cavitation,
        cavitation_pressure: opt.cavitation_pressure / p_ref,
        max_iterations: opt.max_active_set_iterations,
    };
    let mut film = vec![0.0; n];
    let mut mu = vec![0.0; n];
    let mut fields = Fields2d {
        flow_x: vec![0.0; n],
        flow_y: vec![0.0; n],
        couette_x: vec![0.0; n],
        couette_y: Vec::new(),
        squeeze: vec![0.0; n],
        prescribed,
    };
    let mut sol: Option<Solution2d> = warm.map(|w| w.reynolds.clone());
    let mut p_new = vec![0.0; n];
    let mut p_prev: Option<Vec<f64>> = None;
    let mut iterations = 0;
    let mut coupling_iterations = 0;
    let mut coupling_ok = !coupled;
    let c3 = c * c * c;
    let omega = opt.coupling_relaxation;
    for it in 0..opt.max_coupling_iterations.max(1) {
        coupling_iterations = it + 1;
        for i in 0..nt {
            for j in 0..ny {
                let k = i * ny + j;
                let h = hg[i] + defl[k];
                if h.is_nan() || h <= 0.0 {
                    return Err(ReynoldsError::InvalidInput {
                        what: "film thickness",
                        reason: "deflection closes the film".into(),
                    });
                }
                film[k] = h;
                let m = visc.viscosity(pc[k].max(0.0), temp[k]);
                if !(m > 0.0 && m.is_finite()) {
                    return Err(ReynoldsError::NoSolution(format!(
                        "viscosity law gives {m} Pa·s at p = {:.3e} Pa, T = {:.1} K",
                        pc[k], temp[k]
                    )));
                }
                mu[k] = m;
                let s = b.slip.poiseuille(h) / c3 * (mu0 / m);
                fields.flow_x[k] = s;
                fields.flow_y[k] = s;
                fields.couette_x[k] = b.slip.couette(h, ub, uj) / (c * vref);
                fields.squeeze[k] = dhdt[i] * r / (c * vref);
            }
        }
        let s = reynolds2d::solve(&grid, &fields, &ropt, sol.as_ref())?;
        iterations += s.iterations;
        for k in 0..n {
            p_new[k] = s.pressure[k] * p_ref;
        }
        sol = Some(s);
        if !coupled {
            break;
        }
        let pmax = p_new.iter().fold(0.0f64, |a, v| a.max(v.abs())).max(1e-300);
        let change = match &p_prev {
            Some(pp) => {
                pp.iter()
                    .zip(&p_new)
                    .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()))
                    / pmax
            }
            None => f64::INFINITY,
        };
        if change < opt.coupling_tolerance {
            coupling_ok = true;
            break;
        }
        p_prev = Some(p_new.clone());
        // relaxed coupling pressure
        if it == 0 && warm.is_none() {
            pc.copy_from_slice(&p_new);
        } else {
            for k in 0..n {
                pc[k] += omega * (p_new[k] - pc[k]);
            }
        }
        update_defl(&pc, &mut defl);
        if let (Some(tm), Some(resp)) = (thermal, &t_resp) {
            let fill = &sol.as_ref().map(|s| s.fill.clone()).unwrap_or_default();
            let cav = &sol
                .as_ref()
                .map(|s| s.cavitated.clone())
                .unwrap_or_default();
            let q = heat_flux(
                b,
                &grid,
                &pc,
                &film,
                &mu,
                fill,
                cav,
                ub,
                uj,
                opt.cavitated_shear,
            );
            let mut tnew = vec![0.0; nt];
            let mut col = vec![0.0; nt];
            for j in 0..ny {
                for i in 0..nt {
                    col[i] = q[i * ny + j];
                }
                tm.bore_temperature(resp, &col, &mut tnew);
                for i in 0..nt {
                    let k = i * ny + j;
                    temp[k] += omega * (tnew[i] - temp[k]);
                }
            }
        }
    }
    let sol = sol.ok_or(ReynoldsError::Singular("journal solve"))?;
    let converged = coupling_ok && sol.converged;
    // post-processing
    let sym = opt.axial_symmetry;
    let wz: Vec<f64> = (0..ny)
        .map(|j| {
            let half_cell = j == 0
                || (j == ny - 1 && matches!(top, EdgeBc::SymmetryNode | EdgeBc::Pressure(_)));
            let w = if half_cell { 0.5 * dzeta } else { dzeta };
            w * if sym { 2.0 } else { 1.0 }
        })
        .collect();
    let area = r * r * dth; // per unit dζ weight
    let (mut fx, mut fy, mut tj, mut tb, mut power) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let shear_factor = |k: usize| -> f64 {
        if !sol.cavitated[k] {
            1.0
        } else {
            match opt.cavitated_shear {
                CavitatedShear::FillFraction => sol.fill[k],
                CavitatedShear::FullFilm => 1.0,
                CavitatedShear::None => 0.0,
            }
        }
    };
    for i in 0..nt {
        let th = i as f64 * dth;
        let (s, co) = th.sin_cos();
        let ip = (i + 1) % nt;
        let im = (i + nt - 1) % nt;
        for j in 0..ny {
            let k = i * ny + j;
            let da = area * wz[j];
            let p = p_new[k];
            fx -= p * co * da;
            fy -= p * s * da;
            let (t1, t2) = if sol.cavitated[k] {
                let (a, bb) = b.slip.wall_tractions(film[k], mu[k], 0.0, ub, uj);
                let f = shear_factor(k);
                (a * f, bb * f)
            } else {
                let g = (p_new[ip * ny + j] - p_new[im * ny + j]) / (2.0 * r * dth);
                b.slip.wall_tractions(film[k], mu[k], g, ub, uj)
            };
            tj += r * t2 * da;
            tb += r * t1 * da;
            power -= (t1 * ub + t2 * uj) * da;
        }
    }
    // side flow through the end(s): face flux into the boundary half cell minus what the half
    // cell itself consumes (Couette divergence and squeeze), which makes the boundary flux
    // second-order accurate; ruptured columns do not leak
    let mut q_side = 0.0;
    let end_flux = |k0: usize, k1: usize, i: usize, jb: usize| -> f64 {
        if sol.cavitated[k1] {
            return 0.0;
        }
        let s0 = b.slip.poiseuille(film[k0]) / mu[k0];
        let s1 = b.slip.poiseuille(film[k1]) / mu[k1];
        let face = 0.5 * (s0 + s1) * (p_new[k1] - p_new[k0]) / (r * dzeta) * r * dth;
        let (ip, im) = ((i + 1) % nt, (i + nt - 1) % nt);
        let qc = |ii: usize| b.slip.couette(film[ii * ny + jb], ub, uj);
        let div = (qc(ip) - qc(im)) / (2.0 * r * dth);
        face - (div + dhdt[i]) * r * dth * 0.5 * r * dzeta
    };
    for i in 0..nt {
        if ny > 1 {
            q_side += end_flux(i * ny, i * ny + 1, i, 0);
        }
        if !sym && ny > 2 {
            q_side += end_flux(i * ny + ny - 1, i * ny + ny - 2, i, ny - 1);
        }
    }
    if sym {
        q_side *= 2.0;
    }
    let max_pressure = p_new.iter().fold(f64::MIN, |a, &v| a.max(v));
    let min_film = film.iter().fold(f64::MAX, |a, &v| a.min(v));
    Ok(JournalState {
        grid,
        symmetric: sym,
        n_axial_full: nfull,
        pressure: p_new,
        film,
        fill: sol.fill.clone(),
        cavitated: sol.cavitated.clone(),
        temperature: temp,
        deflection: defl,
        viscosity: mu,
        force: [fx, fy],
        journal_torque: tj,
        bearing_torque: tb,
        side_flow: q_side,
        max_pressure,
        min_film,
        power_loss: power,
        iterations,
        coupling_iterations,
        converged,
        reynolds: sol,
    })
}

/// Heat flux into the bush per unit area (seed 002 (4.16), dimensional, flag F-76):
/// Q = S|∇p|² + μV²/Γ(h), V the sliding speed; ruptured zones carry the Couette part scaled as
/// the shear.
#[allow(clippy::too_many_arguments)]
pub(crate) fn heat_flux(
    b: &JournalBearing,
    g: &Grid2d,
    p: &[f64],
    h: &[f64],
    mu: &[f64],
    fill: &[f64],
    cav: &[bool],
    ub: f64,
    uj: f64,
    shear: CavitatedShear,
) -> Vec<f64> {
    let (nt, ny) = (g.nx, g.ny);
    let r = b.radius;
    let v = uj - ub;
    let mut q = vec![0.0; nt * ny];
    for i in 0..nt {
        let ip = (i + 1) % nt;
        let im = (i + nt - 1) % nt;
        for j in 0..ny {
            let k = i * ny + j;
            let couette = mu[k] * v * v / b.slip.gamma(h[k]);
            if !cav.is_empty() && cav[k] {
                let f = match shear {
                    CavitatedShear::FillFraction => fill[k],
                    CavitatedShear::FullFilm => 1.0,
                    CavitatedShear::None => 0.0,
                };
                q[k] = couette * f;
                continue;
            }
            let gx = (p[ip * ny + j] - p[im * ny + j]) / (2.0 * r * g.dx);
            let gz = if j == 0 {
                (p[k + 1] - p[k]) / (r * g.dy)
            } else if j + 1 < ny {
                (p[k + 1] - p[k - 1]) / (2.0 * r * g.dy)
            } else {
                0.0
            };
            q[k] = b.slip.poiseuille(h[k]) / mu[k] * (gx * gx + gz * gz) + couette;
        }
    }
    q
}
