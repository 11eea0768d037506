//! The journal-bearing state at a given journal position and velocity: builds the dimensionless
//! film fields, solves the Reynolds equation (with the coupled viscosity, liner deflection and
//! temperature iteration of seed 002 (4.31)) and integrates forces, torques and flows.

use super::{FilmStart, JournalBearing, JournalOperating, JournalOptions};
use crate::error::{Result, ReynoldsError, finite, positive};
use crate::grid::{Axis, EdgeBc, Grid2d};
use crate::reynolds2d::{self, Fields2d, ReynoldsOptions, Solution2d};
use crate::thermal::ThermalModel;
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

/// [`solve_state`] with an optional frozen temperature field (the thermal model is then off):
/// discretise, apply the supply line, run the coupled iteration, integrate the surface loads.
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
    let pb = Problem::new(b, visc, op, e, edot, opt)?;
    let prescribed = pb.supply_line(e)?;
    let coupling = Coupling::new(b, visc, pb.grid.nx, frozen_temperature.is_some())?;
    let warm = warm.filter(|w| w.pressure.len() == pb.grid.len());
    let mut it = pb.start(&coupling, op, warm, frozen_temperature, prescribed);
    let counts = pb.coupled_solve(&coupling, &mut it, warm.is_some())?;
    let sol = it
        .sol
        .take()
        .ok_or(ReynoldsError::Singular("journal solve"))?;
    let converged = counts.coupling_ok && sol.converged;
    let loads = pb.surface_loads(&sol, &it);
    let side_flow = pb.side_flow(&sol, &it);
    let max_pressure = it.p_new.iter().fold(f64::MIN, |a, &v| a.max(v));
    let min_film = it.film.iter().fold(f64::MAX, |a, &v| a.min(v));
    Ok(JournalState {
        grid: pb.grid,
        symmetric: opt.axial_symmetry,
        n_axial_full: pb.n_axial_full,
        pressure: it.p_new,
        film: it.film,
        fill: sol.fill.clone(),
        cavitated: sol.cavitated.clone(),
        temperature: it.temp,
        deflection: it.defl,
        viscosity: it.mu,
        force: loads.force,
        journal_torque: loads.journal_torque,
        bearing_torque: loads.bearing_torque,
        side_flow,
        max_pressure,
        min_film,
        power_loss: loads.power,
        iterations: counts.iterations,
        coupling_iterations: counts.coupling_iterations,
        converged,
        reynolds: sol,
    })
}

/// The discretised problem at one journal position and velocity: scales of the dimensionless
/// form (module documentation), the grid and the rigid film.
struct Problem<'a> {
    b: &'a JournalBearing,
    visc: &'a dyn Viscosity,
    opt: &'a JournalOptions,
    /// Eccentricity ratio ε.
    eps: f64,
    grid: Grid2d,
    n_axial_full: usize,
    /// Axial step Δζ = Δz/R.
    dzeta: f64,
    /// Condition on the last axial row: symmetry plane (node or face) or ambient pressure.
    top: EdgeBc,
    /// Bush and journal surface speeds, m/s.
    ub: f64,
    uj: f64,
    /// Reference speed V, m/s.
    vref: f64,
    /// Reference viscosity μ₀ = μ(0, T), Pa·s.
    mu0: f64,
    /// Pressure scale μ₀ V R / c², Pa.
    p_ref: f64,
    /// Rigid film h(θᵢ) = c − e_x cos θ − e_y sin θ + w(θ) per column, m.
    rigid_film: Vec<f64>,
    /// Squeeze ∂h/∂t per column (journal velocity and moving waviness), m/s.
    dhdt: Vec<f64>,
}

/// Iteration counts of the coupled solve.
struct Counts {
    iterations: usize,
    coupling_iterations: usize,
    coupling_ok: bool,
}

/// The couplings of seed 002 (4.31) that make the Reynolds equation nonlinear.
struct Coupling {
    /// Circulant weights of the liner kernel (elastic liner), if any.
    liner: Option<Vec<f64>>,
    /// Thermal model and its bore response, unless absent or the temperature is frozen.
    thermal: Option<(ThermalModel, Vec<f64>)>,
    /// Whether anything couples back into the film (liner, thermal model or μ(p)).
    coupled: bool,
}

/// Fields of the coupled iteration.
struct Iterate {
    /// Relaxed pressure used for μ(p, T), deflection and heat, Pa.
    pc: Vec<f64>,
    /// Film temperature, K.
    temp: Vec<f64>,
    /// Liner deflection, m.
    defl: Vec<f64>,
    /// Film thickness, m.
    film: Vec<f64>,
    /// Viscosity, Pa·s.
    mu: Vec<f64>,
    /// Dimensionless coefficients of the Reynolds equation.
    fields: Fields2d,
    /// Last Reynolds solution (dimensionless).
    sol: Option<Solution2d>,
    /// Pressure of the last Reynolds solution, Pa.
    p_new: Vec<f64>,
}

/// Surface integrals of the film tractions.
struct SurfaceLoads {
    force: [f64; 2],
    journal_torque: f64,
    bearing_torque: f64,
    power: f64,
}

/// Axial nodes solved for `n_axial` nodes over the full length, and the condition on the last
/// row: half the length up to the symmetry plane (through a node or a face), or the far end.
fn axial_rows(n_axial: usize, axial_symmetry: bool) -> (usize, EdgeBc) {
    if axial_symmetry {
        if n_axial % 2 == 1 {
            (n_axial.div_ceil(2), EdgeBc::SymmetryNode)
        } else {
            (n_axial / 2, EdgeBc::SymmetryFace)
        }
    } else {
        (n_axial, EdgeBc::Pressure(0.0))
    }
}

/// Rigid film h(θ) = c − e_x cos θ − e_y sin θ + w(θ) and squeeze ∂h/∂t per grid column;
/// errors where the film closes.
fn rigid_film(
    b: &JournalBearing,
    op: &JournalOperating,
    e: [f64; 2],
    edot: [f64; 2],
    nt: usize,
    dth: f64,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let c = b.clearance;
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
    Ok((hg, dhdt))
}

/// Liner deflection δ(θᵢ, z_j) = Σₖ wᵢ₋ₖ p⁺(θₖ, z_j) of the circulant kernel weights `w`
/// (only positive pressure loads the liner).
fn liner_deflection(w: &[f64], nt: usize, ny: usize, p: &[f64], out: &mut [f64]) {
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

/// Largest nodal change between two pressure fields relative to the largest |p|; infinite
/// without a previous field.
fn relative_change(prev: Option<&[f64]>, new: &[f64]) -> f64 {
    let pmax = new.iter().fold(0.0f64, |a, v| a.max(v.abs())).max(1e-300);
    match prev {
        Some(pp) => {
            pp.iter()
                .zip(new)
                .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()))
                / pmax
        }
        None => f64::INFINITY,
    }
}

impl Coupling {
    /// Liner kernel weights on `nt` columns and the thermal response at the bore (no thermal
    /// model when the temperature field is frozen).
    fn new(
        b: &JournalBearing,
        visc: &dyn Viscosity,
        nt: usize,
        frozen_temperature: bool,
    ) -> Result<Self> {
        let liner = match &b.liner {
            Some(k) => Some(k.circulant(nt)?),
            None => None,
        };
        let thermal = if frozen_temperature { None } else { b.thermal };
        let thermal = thermal.map(|t| (t, t.response(b.radius + b.clearance)));
        let coupled = liner.is_some() || thermal.is_some() || !visc.pressure_independent();
        Ok(Self {
            liner,
            thermal,
            coupled,
        })
    }
}

impl<'a> Problem<'a> {
    /// Validates the input and discretises the bearing at position `e`, velocity `edot`.
    fn new(
        b: &'a JournalBearing,
        visc: &'a dyn Viscosity,
        op: &JournalOperating,
        e: [f64; 2],
        edot: [f64; 2],
        opt: &'a JournalOptions,
    ) -> Result<Self> {
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
        let nt = opt.n_circumferential;
        let n_axial_full = opt.n_axial;
        let dzeta = b.length / r / (n_axial_full - 1) as f64;
        let (ny, top) = axial_rows(n_axial_full, opt.axial_symmetry);
        let grid = Grid2d {
            nx: nt,
            ny,
            dx: std::f64::consts::TAU / nt as f64,
            dy: dzeta,
            x_axis: Axis::Periodic,
            y_axis: Axis::Ends(EdgeBc::Pressure(0.0), top),
        };
        let (rigid_film, dhdt) = rigid_film(b, op, e, edot, nt, grid.dx)?;
        Ok(Self {
            b,
            visc,
            opt,
            eps,
            grid,
            n_axial_full,
            dzeta,
            top,
            ub: op.bearing_speed * r,
            uj: op.journal_speed * r,
            vref,
            mu0,
            p_ref,
            rigid_film,
            dhdt,
        })
    }

    /// Prescribed dimensionless pressure (NaN = unknown) on the supply line: the feed groove,
    /// or ambient pressure on the maximum-gap line; empty without a supply line.
    fn supply_line(&self, e: [f64; 2]) -> Result<Vec<f64>> {
        let supply = match (&self.b.feed, self.opt.film_start) {
            (Some(f), _) => {
                finite("feed pressure", f.pressure)?;
                Some((f.angle, f.pressure))
            }
            (None, FilmStart::MaxGap) if self.eps > 0.0 => {
                Some((e[1].atan2(e[0]) + std::f64::consts::PI, 0.0))
            }
            _ => None,
        };
        let mut prescribed = Vec::new();
        if let Some((angle, pressure)) = supply {
            let (grid, nt) = (&self.grid, self.grid.nx);
            prescribed = vec![f64::NAN; grid.len()];
            let i = ((angle.rem_euclid(std::f64::consts::TAU) / grid.dx).round() as usize) % nt;
            for j in 1..grid.ny {
                prescribed[grid.idx(i, j)] = pressure / self.p_ref;
            }
        }
        Ok(prescribed)
    }

    /// Initial fields: pressure, temperature and deflection of the warm start (or the frozen
    /// temperature), otherwise zero pressure at the ambient (or operating) temperature.
    fn start(
        &self,
        coupling: &Coupling,
        op: &JournalOperating,
        warm: Option<&JournalState>,
        frozen_temperature: Option<&[f64]>,
        prescribed: Vec<f64>,
    ) -> Iterate {
        let n = self.grid.len();
        let pc: Vec<f64> = warm
            .map(|w| w.pressure.clone())
            .unwrap_or_else(|| vec![0.0; n]);
        let temp: Vec<f64> = match (frozen_temperature, warm) {
            (Some(t), _) if t.len() == n => t.to_vec(),
            (_, Some(w)) => w.temperature.clone(),
            _ => vec![
                coupling
                    .thermal
                    .as_ref()
                    .map(|(t, _)| t.ambient_temperature)
                    .unwrap_or(op.temperature);
                n
            ],
        };
        let mut defl = vec![0.0; n];
        if warm.is_some()
            && let Some(w) = &coupling.liner
        {
            liner_deflection(w, self.grid.nx, self.grid.ny, &pc, &mut defl);
        }
        Iterate {
            pc,
            temp,
            defl,
            film: vec![0.0; n],
            mu: vec![0.0; n],
            fields: Fields2d {
                flow_x: vec![0.0; n],
                flow_y: vec![0.0; n],
                couette_x: vec![0.0; n],
                couette_y: Vec::new(),
                squeeze: vec![0.0; n],
                prescribed,
            },
            sol: warm.map(|w| w.reynolds.clone()),
            p_new: vec![0.0; n],
        }
    }

    /// The coupled iteration of seed 002 (4.31): Reynolds solves with μ(p, T), the liner
    /// deflection and the bore temperature updated from the under-relaxed pressure until the
    /// pressure field settles.
    fn coupled_solve(
        &self,
        coupling: &Coupling,
        it: &mut Iterate,
        warm_start: bool,
    ) -> Result<Counts> {
        let opt = self.opt;
        let ropt = ReynoldsOptions {
            cavitation: opt.cavitation,
            cavitation_pressure: opt.cavitation_pressure / self.p_ref,
            max_iterations: opt.max_active_set_iterations,
        };
        let mut counts = Counts {
            iterations: 0,
            coupling_iterations: 0,
            coupling_ok: !coupling.coupled,
        };
        let mut p_prev: Option<Vec<f64>> = None;
        let omega = opt.coupling_relaxation;
        for step in 0..opt.max_coupling_iterations.max(1) {
            counts.coupling_iterations = step + 1;
            self.assemble(it)?;
            counts.iterations += self.solve_reynolds(&ropt, it)?;
            if !coupling.coupled {
                break;
            }
            if relative_change(p_prev.as_deref(), &it.p_new) < opt.coupling_tolerance {
                counts.coupling_ok = true;
                break;
            }
            p_prev = Some(it.p_new.clone());
            // relaxed coupling pressure
            if step == 0 && !warm_start {
                it.pc.copy_from_slice(&it.p_new);
            } else {
                for (pc, p) in it.pc.iter_mut().zip(&it.p_new) {
                    *pc += omega * (p - *pc);
                }
            }
            if let Some(w) = &coupling.liner {
                liner_deflection(w, self.grid.nx, self.grid.ny, &it.pc, &mut it.defl);
            }
            if let Some((tm, resp)) = &coupling.thermal {
                self.update_temperature(tm, resp, it);
            }
        }
        Ok(counts)
    }

    /// Film thickness (rigid film plus liner deflection), viscosity μ(p, T) and the
    /// dimensionless Poiseuille, Couette and squeeze coefficients at every node.
    fn assemble(&self, it: &mut Iterate) -> Result<()> {
        let (b, r, c) = (self.b, self.b.radius, self.b.clearance);
        let (nt, ny) = (self.grid.nx, self.grid.ny);
        let c3 = c * c * c;
        for i in 0..nt {
            for j in 0..ny {
                let k = i * ny + j;
                let h = self.rigid_film[i] + it.defl[k];
                if h.is_nan() || h <= 0.0 {
                    return Err(ReynoldsError::InvalidInput {
                        what: "film thickness",
                        reason: "deflection closes the film".into(),
                    });
                }
                it.film[k] = h;
                let m = self.visc.viscosity(it.pc[k].max(0.0), it.temp[k]);
                if !(m > 0.0 && m.is_finite()) {
                    return Err(ReynoldsError::NoSolution(format!(
                        "viscosity law gives {m} Pa·s at p = {:.3e} Pa, T = {:.1} K",
                        it.pc[k], it.temp[k]
                    )));
                }
                it.mu[k] = m;
                let s = b.slip.poiseuille(h) / c3 * (self.mu0 / m);
                it.fields.flow_x[k] = s;
                it.fields.flow_y[k] = s;
                it.fields.couette_x[k] = b.slip.couette(h, self.ub, self.uj) / (c * self.vref);
                it.fields.squeeze[k] = self.dhdt[i] * r / (c * self.vref);
            }
        }
        Ok(())
    }

    /// One direct Reynolds solve (warm-started from the last one); returns its iterations.
    fn solve_reynolds(&self, ropt: &ReynoldsOptions, it: &mut Iterate) -> Result<usize> {
        let s = reynolds2d::solve(&self.grid, &it.fields, ropt, it.sol.as_ref())?;
        let iterations = s.iterations;
        for (p, ps) in it.p_new.iter_mut().zip(&s.pressure) {
            *p = ps * self.p_ref;
        }
        it.sol = Some(s);
        Ok(iterations)
    }

    /// Relaxes the film temperature towards the bore temperature of the thermal model under
    /// the heat flux of the relaxed pressure, column by column in z.
    fn update_temperature(&self, tm: &ThermalModel, resp: &[f64], it: &mut Iterate) {
        let (nt, ny) = (self.grid.nx, self.grid.ny);
        let omega = self.opt.coupling_relaxation;
        let q = self.heat_flux(it);
        let mut tnew = vec![0.0; nt];
        let mut col = vec![0.0; nt];
        for j in 0..ny {
            for i in 0..nt {
                col[i] = q[i * ny + j];
            }
            tm.bore_temperature(resp, &col, &mut tnew);
            for i in 0..nt {
                let k = i * ny + j;
                it.temp[k] += omega * (tnew[i] - it.temp[k]);
            }
        }
    }

    /// Heat flux into the bush per unit area (seed 002 (4.16), dimensional, flag F-76):
    /// Q = S|∇p|² + μV²/Γ(h), V the sliding speed; ruptured zones carry the Couette part scaled
    /// as the shear. Evaluated with the relaxed pressure of the iteration.
    fn heat_flux(&self, it: &Iterate) -> Vec<f64> {
        let (p, h, mu) = (&it.pc, &it.film, &it.mu);
        let (fill, cav): (&[f64], &[bool]) = match &it.sol {
            Some(s) => (&s.fill, &s.cavitated),
            None => (&[], &[]),
        };
        let (b, g) = (self.b, &self.grid);
        let (nt, ny) = (g.nx, g.ny);
        let r = b.radius;
        let v = self.uj - self.ub;
        let mut q = vec![0.0; nt * ny];
        for i in 0..nt {
            let ip = (i + 1) % nt;
            let im = (i + nt - 1) % nt;
            for j in 0..ny {
                let k = i * ny + j;
                let couette = mu[k] * v * v / b.slip.gamma(h[k]);
                if !cav.is_empty() && cav[k] {
                    q[k] = couette * self.opt.cavitated_shear.factor(fill[k]);
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

    /// Axial integration weight of row j (trapezoidal in ζ, doubled for the mirrored half).
    fn axial_weights(&self) -> Vec<f64> {
        let (ny, dzeta) = (self.grid.ny, self.dzeta);
        let sym = self.opt.axial_symmetry;
        (0..ny)
            .map(|j| {
                let half_cell = j == 0
                    || (j == ny - 1
                        && matches!(self.top, EdgeBc::SymmetryNode | EdgeBc::Pressure(_)));
                let w = if half_cell { 0.5 * dzeta } else { dzeta };
                w * if sym { 2.0 } else { 1.0 }
            })
            .collect()
    }

    /// Force on the journal, torques on journal and bush and the dissipated power from the
    /// pressure and the wall tractions (cavitated nodes carry the Couette shear scaled by the
    /// cavitated-shear option).
    fn surface_loads(&self, sol: &Solution2d, it: &Iterate) -> SurfaceLoads {
        let (b, r) = (self.b, self.b.radius);
        let (nt, ny, dth) = (self.grid.nx, self.grid.ny, self.grid.dx);
        let (ub, uj) = (self.ub, self.uj);
        let (p_new, film, mu) = (&it.p_new, &it.film, &it.mu);
        let wz = self.axial_weights();
        let area = r * r * dth; // per unit dζ weight
        let (mut fx, mut fy, mut tj, mut tb, mut power) = (0.0, 0.0, 0.0, 0.0, 0.0);
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
                    let f = self.opt.cavitated_shear.factor(sol.fill[k]);
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
        SurfaceLoads {
            force: [fx, fy],
            journal_torque: tj,
            bearing_torque: tb,
            power,
        }
    }

    /// Net outflow through the end(s), m³/s.
    fn side_flow(&self, sol: &Solution2d, it: &Iterate) -> f64 {
        let (b, r, dzeta) = (self.b, self.b.radius, self.dzeta);
        let (nt, ny, dth) = (self.grid.nx, self.grid.ny, self.grid.dx);
        let (p_new, film, mu) = (&it.p_new, &it.film, &it.mu);
        let sym = self.opt.axial_symmetry;
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
            let qc = |ii: usize| b.slip.couette(film[ii * ny + jb], self.ub, self.uj);
            let div = (qc(ip) - qc(im)) / (2.0 * r * dth);
            face - (div + self.dhdt[i]) * r * dth * 0.5 * r * dzeta
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
        q_side
    }
}
