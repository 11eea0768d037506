//! Lubricated roller–plate line contact (SPEC §8.4–8.5, seed 002 ch. 3 and 5).
//!
//! * [`analytic`] — closed-form rigid solutions (Martin/Kapitsa, squeeze term, Barus);
//! * [`solve`] — numerical steady solution for a given rigid approach, minimum film or load per
//!   length: rigid or elastic (any [`Compliance`]), isoviscous or piezoviscous, optionally
//!   compressible, with squeeze velocity; full EHL by a coupled Newton method (below);
//! * [`load_damping`] — W₀(h_m) and λ(h_m) = −∂W/∂ḣ tables with interpolation (3.16)–(3.20);
//! * [`transient`] — M ḧ + λ(h) ḣ − W₀(h) = −F after load steps, stiff integration, and the
//!   matched-asymptotic solution of (3.25) for verification;
//! * [`load_step`] — a load step from a steady state: table, integration and summary.
//!
//! **EHL method.** Unknowns are the nodal pressures and film thicknesses. The Reynolds equation
//! (finite volumes, Poiseuille faces by arithmetic means, Couette flux by second-order upwinding)
//! and the elastic film equation written in *differential-deflection* form (the second
//! difference of h − x²/2R − Dp, whose influence coefficients decay like 1/(i−j)², as in Hughes,
//! Elcoate & Evans 2000) are solved together by Newton's method: influence coefficients within
//! `near_band` nodes enter the banded Jacobian, which preconditions a GMRES solve of the exact
//! Newton system (the far field applied by FFT products), so Newton converges quadratically. The
//! two end values of h (dense in p) and the load / film constraint form a 3×3 Schur border.
//! Cavitation (Reynolds exit) is a complementarity condition handled by a semismooth active set.
//! Heavy loads fall back to load continuation.

pub mod analytic;
mod ehl;
pub mod load_damping;
pub mod load_step;
pub mod study;
pub mod transient;

pub use ehl::solve;

use crate::compliance::LineKernel;
use crate::compliance::fourier::FourierKernel;
use crate::compliance::half_space::HalfSpace;
use crate::compliance::layer::ElasticLayer;
use crate::slip::SlipLengths;
use crate::viscosity::Density;
use crate::waviness::Waviness;
use std::sync::Arc;

/// Elastic compliance of the contacting bodies (sum of the plate's and the roller's kernels).
#[derive(Debug, Clone)]
pub enum Compliance {
    /// Rigid surfaces.
    Rigid,
    /// Elastic half-space(s), seed (3.3).
    HalfSpace(HalfSpace),
    /// Finite-thickness plate bonded to a rigid base.
    Layer(Arc<ElasticLayer>),
    /// Kernel identified from FE data (seed (3.77)).
    Fourier(FourierKernel),
    /// Sum of several kernels (e.g. plate + roller).
    Sum(Vec<Compliance>),
}

impl Compliance {
    /// True for rigid surfaces.
    pub fn is_rigid(&self) -> bool {
        match self {
            Compliance::Rigid => true,
            Compliance::Sum(v) => v.iter().all(|c| c.is_rigid()),
            _ => false,
        }
    }

    /// Effective modulus E′ (Pa) used only for the Hertz estimates behind the automatic domain and
    /// the initial guess; None if rigid. An identified Fourier kernel carries no modulus: steel
    /// (2.3×10¹¹ Pa) is assumed for these estimates.
    pub fn e_prime(&self) -> Option<f64> {
        match self {
            Compliance::Rigid => None,
            Compliance::HalfSpace(h) => Some(h.e_prime()),
            Compliance::Layer(l) => Some(l.e / (1.0 - l.nu * l.nu)),
            Compliance::Fourier(_) => Some(2.3e11),
            Compliance::Sum(v) => {
                let s: f64 = v.iter().filter_map(|c| c.e_prime()).map(|e| 1.0 / e).sum();
                (s > 0.0).then(|| 1.0 / s)
            }
        }
    }
}

impl LineKernel for Compliance {
    fn value(&self, u: f64) -> f64 {
        match self {
            Compliance::Rigid => 0.0,
            Compliance::HalfSpace(h) => h.value(u),
            Compliance::Layer(l) => l.value(u),
            Compliance::Fourier(f) => f.value(u),
            Compliance::Sum(v) => v.iter().map(|c| c.value(u)).sum(),
        }
    }
    fn integral(&self, u0: f64, u1: f64) -> f64 {
        match self {
            Compliance::Rigid => 0.0,
            Compliance::HalfSpace(h) => h.integral(u0, u1),
            Compliance::Layer(l) => l.integral(u0, u1),
            Compliance::Fourier(f) => f.integral(u0, u1),
            Compliance::Sum(v) => v.iter().map(|c| c.integral(u0, u1)).sum(),
        }
    }
}

/// The lubricated problem: a cylinder of (reduced) radius R on a plate, per unit length, with
/// its surface speeds, lubricant, compliance and wall slip (the dry Hertz line contact is
/// `rolldyn_contact::hertz::LineContact`).
#[derive(Debug, Clone)]
pub struct LubricatedLineContact {
    /// Reduced radius R, m.
    pub radius: f64,
    /// Surface speeds along x of the plate (u₁) and the roller (u₂), m/s; the seed's V = u₁ + u₂.
    pub surface_speeds: [f64; 2],
    /// Lubricant temperature for the viscosity law, K.
    pub temperature: f64,
    /// Density law. Default incompressible (the seed).
    pub density: Density,
    /// Elastic compliance. Default rigid.
    pub compliance: Compliance,
    /// Wall slip lengths (k₁ plate, k₂ roller), m.
    pub slip: SlipLengths,
    /// Waviness along x (m), added to the geometric gap as a stationary snapshot (its travelling
    /// squeeze term is not included in the line contact).
    pub waviness: Waviness,
}

impl LubricatedLineContact {
    /// Rigid, incompressible contact with sum speed V shared equally by both surfaces.
    pub fn new(radius: f64, sum_speed: f64) -> Self {
        Self {
            radius,
            surface_speeds: [0.5 * sum_speed, 0.5 * sum_speed],
            temperature: 313.15,
            density: Density::Incompressible,
            compliance: Compliance::Rigid,
            slip: SlipLengths::NONE,
            waviness: Waviness::none(),
        }
    }

    /// V = u₁ + u₂.
    pub fn sum_speed(&self) -> f64 {
        self.surface_speeds[0] + self.surface_speeds[1]
    }
}

/// What fixes the solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Constraint {
    /// Rigid approach h₀: h = h₀ + x²/2R + δ(x) with δ from the (absolute) compliance kernel —
    /// the seed's h_m of (3.74)–(3.75) (its tables give h_m this way).
    RigidApproach(f64),
    /// Minimum film thickness, m.
    MinFilm(f64),
    /// Load per unit length, N/m (inverse mode).
    LoadPerLength(f64),
}

/// Grid choice.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LineGrid {
    /// Uniform for elastic problems (Toeplitz influence matrix), clustered near the contact for
    /// rigid ones. Default.
    #[default]
    Auto,
    /// Uniform spacing.
    Uniform,
    /// Clustered at x = 0 with the given central spacing, m.
    Clustered(f64),
}

/// Every knob of the line-contact solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineContactOptions {
    /// Number of nodes. Default 1000.
    pub nodes: usize,
    /// Inlet coordinate (negative), m; None = automatic: −max(4.5 b, 30√(Rh)) elastic,
    /// −100√(Rh) rigid (b Hertz half-width, h the film scale).
    pub inlet: Option<f64>,
    /// Outlet coordinate, m; None = automatic: max(1.5 b, 5√(Rh)).
    pub outlet: Option<f64>,
    /// Grid type.
    pub grid: LineGrid,
    /// Influence coefficients kept in the banded Newton Jacobian (each side), nodes; the rest enters through GMRES matrix–vector products (FFT). Default 8.
    pub near_band: usize,
    /// Convergence tolerance on the scaled residuals. Default 1e-8.
    pub tolerance: f64,
    /// Maximum Newton iterations per solve. Default 80.
    pub max_iterations: usize,
    /// Normal approach speed V_y = dh/dt (squeeze, positive = separating), m/s. Default 0.
    pub squeeze_velocity: f64,
    /// Compute the damping λ = −∂W/∂V_y by ±ΔV_y at fixed rigid approach. Default true.
    pub damping: bool,
    /// Squeeze perturbation Δν = ΔV_y/V·√(R/h) for λ (central difference). Default 1e-2.
    pub damping_perturbation: f64,
    /// Load-continuation steps allowed when Newton fails (halving the load). Default 8.
    pub continuation_steps: usize,
    /// Cavitation pressure (gauge), Pa. Default 0.
    pub cavitation_pressure: f64,
}

impl Default for LineContactOptions {
    fn default() -> Self {
        Self {
            nodes: 1000,
            inlet: None,
            outlet: None,
            grid: LineGrid::Auto,
            near_band: 8,
            tolerance: 1e-8,
            max_iterations: 80,
            squeeze_velocity: 0.0,
            damping: true,
            damping_perturbation: 1e-2,
            continuation_steps: 8,
            cavitation_pressure: 0.0,
        }
    }
}

/// Results (fields named as printed by the CLI).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LineContactResult {
    /// Load per unit length, N/m.
    pub load_per_length_n_per_m: f64,
    /// Maximum pressure, Pa.
    pub max_pressure_pa: f64,
    /// Minimum film thickness, m.
    pub min_film_m: f64,
    /// Film at the contact centre x = 0, m.
    pub central_film_m: f64,
    /// Exit (cavitation) coordinate, m, interpolated with p ∝ (x_c − x)².
    pub outlet_position_m: f64,
    /// Rigid approach h₀ (film = h₀ + x²/2R + δ), m.
    pub rigid_approach_m: f64,
    /// Damping per unit length λ = −∂W/∂V_y, N·s/m² (0 when not computed).
    pub damping_ns_per_m2: f64,
    /// Hertz half-width for this load (0 when rigid), m.
    pub hertz_half_width_m: f64,
    /// Hertz maximum pressure for this load (0 when rigid), Pa.
    pub hertz_pressure_pa: f64,
    /// Pressure profile (x, p), m and Pa.
    pub pressure: Vec<(f64, f64)>,
    /// Film profile (x, h), m.
    pub film: Vec<(f64, f64)>,
    /// Newton iterations (all solves, including continuation and damping perturbations).
    pub iterations: usize,
    /// Whether the final solve met its tolerance.
    pub converged: bool,
    /// Wall time, s.
    pub solve_time_s: f64,
}
