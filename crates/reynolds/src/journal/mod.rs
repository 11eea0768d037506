//! Finite journal bearing (SPEC §8.6, seed 002 ch. 4): pressure field, load capacity, attitude
//! angle, Sommerfeld number, friction torque and friction variable, side flow, maximum pressure,
//! the 2×2 stiffness and damping coefficients, elastic liner + housing deformation and the
//! Fourier thermal model coupled through μ(p, T).
//!
//! Conventions (SPEC §8.6 with flag F-72 resolved by a fixed frame):
//! * bearing frame x, y; journal centre at e = (e_x, e_y) from the bush centre;
//! * θ = angle of a point of the bush measured counter-clockwise from +x; film
//!   h(θ, z) = c − e_x cos θ − e_y sin θ + w(θ) + δ(θ, z);
//! * positive speeds are counter-clockwise; the bush is surface 1 (slip length k₁), the journal
//!   surface 2 (k₂);
//! * forces are on the journal; the external load W balances them, W = −F;
//! * results are reported in the *load frame*: x′ along W, y′ 90° counter-clockwise from it, so a
//!   journal rotating counter-clockwise sits at attitude ψ > 0 ahead of the load line.
//!
//! Internally the Reynolds equation is solved in dimensionless form (θ, ζ = z/R, H = h/c,
//! P̃ = p c²/(μ₀ V R) with V a reference speed), by the direct complementarity solver of
//! [`crate::reynolds2d`] on half the length (axial symmetry) by default.

mod coefficients;
mod equilibrium;
pub mod limits;
mod solver;
pub mod study;

pub use equilibrium::{solve_eccentricity, solve_load};
pub use solver::{JournalState, solve_state};

use crate::cavitation::Cavitation;
use crate::compliance::liner::LinerKernel;
use crate::slip::SlipLengths;
use crate::thermal::ThermalModel;
use crate::waviness::Waviness;

/// Geometry and optional physics of a journal bearing.
#[derive(Debug, Clone, PartialEq)]
pub struct JournalBearing {
    /// Journal radius R, m.
    pub radius: f64,
    /// Bearing length L, m.
    pub length: f64,
    /// Radial clearance c, m.
    pub clearance: f64,
    /// Wall slip lengths (k₁ bush, k₂ journal), m; seed 002 (1.15).
    pub slip: SlipLengths,
    /// Surface waviness along θ (rad), seed 002 input "small-scale waviness parameters".
    pub waviness: Waviness,
    /// Axial feed groove (full length) at a prescribed pressure, if any.
    pub feed: Option<FeedGroove>,
    /// Elastic liner (and housing) deformation, if any.
    pub liner: Option<LinerKernel>,
    /// Fourier thermal model, if any (otherwise isothermal at the operating temperature).
    pub thermal: Option<ThermalModel>,
}

impl JournalBearing {
    /// Rigid, isothermal, no-slip bearing.
    pub fn new(radius: f64, length: f64, clearance: f64) -> Self {
        Self {
            radius,
            length,
            clearance,
            slip: SlipLengths::NONE,
            waviness: Waviness::none(),
            feed: None,
            liner: None,
            thermal: None,
        }
    }
}

/// A full-length axial feed groove: the grid column nearest to `angle` is held at `pressure`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeedGroove {
    /// Angle of the groove in the bearing frame, rad.
    pub angle: f64,
    /// Supply pressure (gauge), Pa.
    pub pressure: f64,
}

/// Operating condition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalOperating {
    /// Journal angular speed, rad/s (counter-clockwise positive).
    pub journal_speed: f64,
    /// Bush angular speed, rad/s (0 for a fixed bush).
    pub bearing_speed: f64,
    /// Lubricant temperature for an isothermal solution (and the reference for the viscosity
    /// law's μ₀ in the Sommerfeld number), K.
    pub temperature: f64,
}

impl JournalOperating {
    /// Fixed bush, journal at `rpm`, temperature `t_k`.
    pub fn rpm(rpm: f64, t_k: f64) -> Self {
        Self {
            journal_speed: rpm * std::f64::consts::TAU / 60.0,
            bearing_speed: 0.0,
            temperature: t_k,
        }
    }
}

/// Shear in cavitated (ruptured) film regions, for friction torque and heat generation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CavitatedShear {
    /// Couette shear scaled by the fill fraction θ (striated film; for the Reynolds model θ is
    /// estimated from the film content at rupture).
    FillFraction,
    /// Full-film Couette shear everywhere (flooded; Petroff-type; the Raimondi–Boyd charts'
    /// friction variable). Default.
    #[default]
    FullFilm,
    /// No shear in cavitated regions.
    None,
}

impl CavitatedShear {
    /// Fraction of the full-film Couette shear carried by a cavitated node of fill fraction
    /// `fill`.
    pub(crate) fn factor(self, fill: f64) -> f64 {
        match self {
            CavitatedShear::FillFraction => fill,
            CavitatedShear::FullFilm => 1.0,
            CavitatedShear::None => 0.0,
        }
    }
}

/// Where the pressure film may start when no feed groove is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FilmStart {
    /// Ambient pressure on the line of maximum film thickness (lubricant supplied there; the
    /// Raimondi–Boyd convention for full 360° bearings). Default.
    #[default]
    MaxGap,
    /// No supply line: the film starts wherever the complementarity problem puts it (the seed's
    /// ADI + projection scheme, SPEC §8.6).
    Free,
}

/// Every knob of the journal-bearing solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalOptions {
    /// Nodes around the circumference (periodic). Default 120.
    pub n_circumferential: usize,
    /// Nodes along the full length including both ends. Default 40.
    pub n_axial: usize,
    /// Solve half the length with a symmetry plane (exact for this model, which has no axial
    /// asymmetry). Default true.
    pub axial_symmetry: bool,
    /// Cavitation model. Default Reynolds (Swift–Stieber).
    pub cavitation: Cavitation,
    /// Cavitation pressure (gauge), Pa. Default 0.
    pub cavitation_pressure: f64,
    /// Maximum active-set iterations per Reynolds solve. Default 60.
    pub max_active_set_iterations: usize,
    /// Relative tolerance of the coupled viscosity/deflection/temperature iteration on the
    /// pressure field. Default 1e-7.
    pub coupling_tolerance: f64,
    /// Maximum coupled iterations (the seed needs ≈ 200 with its ADI). Default 200.
    pub max_coupling_iterations: usize,
    /// Under-relaxation of the pressure used for μ(p, T), deflection and heat. Default 0.7.
    pub coupling_relaxation: f64,
    /// Relative tolerance on the load in the equilibrium search. Default 1e-8.
    pub load_tolerance: f64,
    /// Maximum equilibrium-search evaluations. Default 60.
    pub max_load_iterations: usize,
    /// Largest eccentricity ratio the equilibrium search may reach. Default 0.995.
    pub max_eccentricity: f64,
    /// Compute the 2×2 stiffness and damping coefficients. Default true.
    pub coefficients: bool,
    /// Relative perturbation for the coefficients: Δe = δ·c, Δė = δ·c·V/R. Default 1e-4.
    pub perturbation: f64,
    /// Shear in cavitated zones. Default full film (Raimondi–Boyd).
    pub cavitated_shear: CavitatedShear,
    /// Film start without a feed groove. Default: ambient at the maximum gap (Raimondi–Boyd).
    pub film_start: FilmStart,
}

impl Default for JournalOptions {
    fn default() -> Self {
        Self {
            n_circumferential: 120,
            n_axial: 40,
            axial_symmetry: true,
            cavitation: Cavitation::Reynolds,
            cavitation_pressure: 0.0,
            max_active_set_iterations: 60,
            coupling_tolerance: 1e-7,
            max_coupling_iterations: 200,
            coupling_relaxation: 0.7,
            load_tolerance: 1e-8,
            max_load_iterations: 60,
            max_eccentricity: 0.995,
            coefficients: true,
            perturbation: 1e-4,
            cavitated_shear: CavitatedShear::FullFilm,
            film_start: FilmStart::MaxGap,
        }
    }
}

/// A nodal field on the full bearing surface (θ fastest-varying last: index i·n_axial + j).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SurfaceField {
    /// Angles θᵢ in the *load frame* (from the load direction, counter-clockwise), rad.
    pub theta: Vec<f64>,
    /// Axial positions z_j from the bearing centre, m.
    pub z: Vec<f64>,
    /// Values, index i·z.len() + j.
    pub values: Vec<f64>,
}

/// Results of a journal-bearing solution (fields named as printed by the CLI).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct JournalResult {
    /// Eccentricity ratio ε = e/c.
    pub eccentricity: f64,
    /// Attitude angle between the load line and the line of centres, measured in the direction
    /// of rotation, degrees.
    pub attitude_deg: f64,
    /// Sommerfeld number S = (R/c)² μ₀ N / P, N = (ω_journal + ω_bush)/2π in rev/s, P = W/(2RL).
    pub sommerfeld: f64,
    /// Load capacity |W|, N.
    pub load_n: f64,
    /// Maximum film pressure, Pa.
    pub max_pressure_pa: f64,
    /// Friction torque on the journal (positive = resisting a positive journal speed), N·m.
    pub friction_torque_nm: f64,
    /// Friction torque on the bush (positive = dragging it counter-clockwise), N·m.
    pub bearing_torque_nm: f64,
    /// Friction variable (R/c)·f with f = friction torque/(W R).
    pub friction_variable: f64,
    /// Net side leakage through both ends, m³/s.
    pub side_flow_m3_s: f64,
    /// Power dissipated in the film, W.
    pub power_loss_w: f64,
    /// Minimum film thickness, m.
    pub min_film_m: f64,
    /// Journal-centre position in the load frame, m.
    pub eccentricity_vector_m: [f64; 2],
    /// Stiffness K_ij = −∂F_i/∂e_j in the load frame, N/m.
    pub stiffness_n_per_m: [[f64; 2]; 2],
    /// Damping C_ij = −∂F_i/∂ė_j in the load frame, N·s/m.
    pub damping_ns_per_m: [[f64; 2]; 2],
    /// Maximum and mean film (bore) temperature, K (operating temperature when isothermal).
    pub max_temperature_k: f64,
    /// Mean film temperature, K.
    pub mean_temperature_k: f64,
    /// Maximum liner deflection, m (0 when rigid).
    pub max_deflection_m: f64,
    /// Direct Reynolds solves (active-set iterations on the full grid) of the static solution,
    /// including the equilibrium search and the coupling iterations (coefficient perturbations
    /// and the coarse-grid start are not counted).
    pub iterations: usize,
    /// Coupled (viscosity/deflection/thermal) iterations of the final state.
    pub coupling_iterations: usize,
    /// Equilibrium-search evaluations (0 for a given eccentricity).
    pub load_iterations: usize,
    /// All iterations met their tolerances.
    pub converged: bool,
    /// Wall-clock time of the whole solution, s.
    pub solve_time_s: f64,
    /// Pressure field, Pa.
    pub pressure: SurfaceField,
    /// Film thickness field, m.
    pub film: SurfaceField,
    /// Temperature field, K (empty when isothermal).
    pub temperature: SurfaceField,
}
