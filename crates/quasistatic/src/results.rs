//! Results of one quasi-static point ([`SkidResult`], SPEC §5.6 "output"). All SI; every
//! value is finite (quantities that do not exist, e.g. the film of an unloaded contact or the
//! scuffing margin of a friction curve without maximum, are `None`).

use crate::cage_equilibrium::CageBalance;
use crate::kinematics::KinematicCase;
use crate::load_distribution::LoadDistribution;
use crate::operating_geometry::OperatingGeometry;
use serde::Serialize;

/// Zone of a roller (SPEC §5.4: loaded and unloaded zones treated separately).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Zone {
    /// The roller carries load on the inner raceway.
    Loaded,
    /// Only the centrifugal force presses the roller on the outer raceway.
    Unloaded,
}

/// One roller ↔ raceway contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactResult {
    /// Normal load, N.
    pub normal_force_n: f64,
    /// Effective contact length (Hertz pressure of the most loaded slice), m.
    pub effective_length_m: f64,
    /// Maximum Hertz pressure, Pa.
    pub max_pressure_pa: f64,
    /// Hertz half-width, m.
    pub half_width_m: f64,
    /// Rolling (entrainment) speed (v₁ + v₂)/2 in the cage frame, signed, m/s.
    pub rolling_speed_m_s: f64,
    /// Sliding speed ring − roller, signed, m/s.
    pub sliding_speed_m_s: f64,
    /// Slide-to-roll ratio s = v/|u| (2.11) (|u| floored at the options' minimum rolling speed).
    pub slide_roll_ratio: f64,
    /// Friction coefficient (sign of the sliding speed).
    pub friction_coefficient: f64,
    /// Friction force on the roller along e_θ, N.
    pub friction_force_n: f64,
    /// Central film thickness, m (`None` when unloaded).
    pub film_central_m: Option<f64>,
    /// Minimum film thickness (for Λ), m.
    pub film_minimum_m: Option<f64>,
    /// Film parameter Λ of the friction model (seed 000 (1.2) or Tallian, F-44).
    pub lambda: Option<f64>,
    /// Contact oil temperature (after the seed 001 flash iteration), K.
    pub temperature_k: f64,
    /// Friction power |μ| Q |v| (2.21), W.
    pub power_w: f64,
    /// Friction regime ("boundary", "mixed", "hydrodynamic", "unloaded").
    pub regime: &'static str,
    /// Critical slip s_cr of the friction curve at this contact (SPEC §4.8).
    pub critical_slip: Option<f64>,
    /// Scuffing margin s_cr/|s| (`None` without an interior maximum of the friction curve or
    /// without rolling).
    pub scuffing_margin: Option<f64>,
    /// Warnings of the traction model (SPEC §9.2 flags).
    pub warnings: Vec<&'static str>,
}

/// Roller ↔ cage-bar contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BarResult {
    /// Normal force F_S, N (signed push P on the cage along e_θ in `push_n`).
    pub normal_force_n: f64,
    /// Force the roller exerts on the cage along e_θ, N (> 0: the roller drives the cage).
    pub push_n: f64,
    /// Friction coefficient (sign of the roller spin).
    pub friction_coefficient: f64,
    /// Sliding speed ω_w R_w, m/s.
    pub sliding_speed_m_s: f64,
    /// Friction power, W.
    pub power_w: f64,
}

/// One roller.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RollerResult {
    /// Index (roller 0 at the options' phase angle).
    pub index: usize,
    /// Angle from the load direction, rad.
    pub azimuth_rad: f64,
    /// Loaded / unloaded zone.
    pub zone: Zone,
    /// Roller spin ω_w about its axis in the cage frame, rad/s.
    pub spin_rad_s: f64,
    /// Roller slip ε_w relative to the reference ring (SPEC §5.3).
    pub slip: f64,
    /// Centrifugal force F_c, N.
    pub centrifugal_force_n: f64,
    /// Roller tilt between the raceways, rad.
    pub tilt_rad: f64,
    /// Inner raceway contact.
    pub inner: ContactResult,
    /// Outer raceway contact.
    pub outer: ContactResult,
    /// Cage-bar contact.
    pub bar: BarResult,
    /// Rib friction 2F_fб on the roller, N.
    pub rib_force_n: f64,
    /// Rib film power, W.
    pub rib_power_w: f64,
    /// Pocket-film moment T_sc on the roller, N·m.
    pub pocket_moment_n_m: f64,
    /// Pocket-film power, W.
    pub pocket_power_w: f64,
    /// Rolling-resistance moment on the roller, N·m.
    pub rolling_resistance_moment_n_m: f64,
    /// Rolling-resistance power f_к(Q_i + Q_o)|ω_w|, W.
    pub rolling_resistance_power_w: f64,
    /// Total friction power of this roller's contacts, W.
    pub power_w: f64,
    /// Final moment residual ΣT, N·m.
    pub moment_residual_n_m: f64,
}

/// Power losses by source, W.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PowerBreakdown {
    /// Inner raceway contacts.
    pub inner_raceways_w: f64,
    /// Outer raceway contacts.
    pub outer_raceways_w: f64,
    /// Cage bars.
    pub cage_bars_w: f64,
    /// Roller ends ↔ ribs.
    pub ribs_w: f64,
    /// Roller ends ↔ cage pockets.
    pub pockets_w: f64,
    /// Rolling resistance.
    pub rolling_resistance_w: f64,
    /// Cage land.
    pub cage_land_w: f64,
    /// Air–oil drag of the cage.
    pub drag_w: f64,
    /// Air–oil drag of the orbiting rollers.
    pub roller_drag_w: f64,
}

impl PowerBreakdown {
    /// Sum, W.
    pub fn total(&self) -> f64 {
        self.inner_raceways_w
            + self.outer_raceways_w
            + self.cage_bars_w
            + self.ribs_w
            + self.pockets_w
            + self.rolling_resistance_w
            + self.cage_land_w
            + self.drag_w
            + self.roller_drag_w
    }
}

/// Final residuals of the nested iterations.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Residuals {
    /// Cage moment Φ / (sum of the moment magnitudes at the first iterate): the residual the
    /// cage iteration tests against `cage_tolerance`.
    pub cage_moment_relative: f64,
    /// Largest roller moment residual / (R_w ΣQ).
    pub roller_moment_relative: f64,
    /// Ring force balance |ΣQ_i e_r − F_r| / F_r (absolute N when F_r = 0).
    pub force_balance_relative: f64,
    /// Largest roller radial balance |Q_o − Q_i − F_c|, N.
    pub roller_radial_balance_n: f64,
}

/// Iteration counts.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Iterations {
    /// Evaluations of the cage equation Φ(ε₀).
    pub cage_evaluations: usize,
    /// Evaluations of roller equations, summed.
    pub roller_evaluations: usize,
    /// Ring Newton iterations of the load distribution, summed.
    pub load_iterations: usize,
}

/// Result of [`crate::solve`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SkidResult {
    /// Which rings rotate.
    pub kinematic_case: KinematicCase,
    /// ω_в, rad/s.
    pub inner_speed_rad_s: f64,
    /// ω_н, rad/s.
    pub outer_speed_rad_s: f64,
    /// F_r, N.
    pub radial_load_n: f64,
    /// Ring tilt used, rad.
    pub misalignment_rad: f64,
    /// Cage speed ω₀, rad/s.
    pub cage_speed_rad_s: f64,
    /// Epicyclic cage speed ω₀₀, rad/s.
    pub epicyclic_cage_speed_rad_s: f64,
    /// Cage slip ε₀ = 1 − ω₀/ω₀₀ (negative: cage faster than epicyclic).
    pub cage_slip: f64,
    /// Reference ring of the roller slips ("inner" or "outer").
    pub roller_slip_reference: &'static str,
    /// Per roller.
    pub rollers: Vec<RollerResult>,
    /// Largest raceway normal load (inner or outer), N.
    pub max_roller_load_n: f64,
    /// Largest Hertz pressure of the raceway contacts, Pa.
    pub max_contact_pressure_pa: f64,
    /// Rollers carrying inner-raceway load.
    pub loaded_rollers: usize,
    /// Load-zone half angle, rad.
    pub load_zone_half_angle_rad: f64,
    /// Inner-ring displacement (x, y), m.
    pub ring_displacement_m: [f64; 2],
    /// Operating diametral radial clearance, m.
    pub operating_clearance_m: f64,
    /// Operating geometry with every contribution.
    pub operating_geometry: OperatingGeometry,
    /// Moments and forces on the cage.
    pub cage: CageBalance,
    /// Total friction power, W.
    pub power_loss_w: f64,
    /// Power delivered by the rings (Σ ring torques × speeds); equals `power_loss_w` in
    /// equilibrium when the rolling resistance is off (its ring reaction is not modelled).
    pub power_input_w: f64,
    /// Power by source.
    pub power: PowerBreakdown,
    /// Smallest scuffing margin s_cr/s over the loaded raceway contacts.
    pub min_scuffing_margin: Option<f64>,
    /// Basic static radial load rating C₀r of ISO 76 (standard form, not in the seeds), N.
    pub static_load_rating_n: f64,
    /// Wall-clock solve time, s.
    pub solve_time_s: f64,
    /// Iteration counts.
    pub iterations: Iterations,
    /// Every residual test passed: the cage moment `|Φ|/scale ≤ cage_residual_slack ×
    /// cage_tolerance` (1e-5 by default, [`Residuals::cage_moment_relative`]), each
    /// roller moment to `roller_tolerance` and the load distribution to `load_tolerance`
    /// ([`crate::QuasiStaticOptions`]). A point failing one is returned as an error, so this is
    /// true for a returned result.
    pub converged: bool,
    /// Final residuals.
    pub residuals: Residuals,
    /// Name of the raceway friction model.
    pub friction_model: &'static str,
    /// Name of the cage–land model.
    pub cage_land_model: &'static str,
    /// The drag laws used (cage: the model's linear coefficient or the seed 001 formula;
    /// rollers).
    pub cage_drag_law: String,
    /// Warnings (static capacity exceeded, fits lost, film collapse on the land, …).
    pub warnings: Vec<String>,
    /// The frictionless load distribution at the solution.
    #[serde(skip)]
    pub load_distribution: LoadDistribution,
}
