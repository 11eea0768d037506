//! Solver knobs of the quasi-static model ([`QuasiStaticOptions`]) and the switches of the
//! seed proposals (SPEC §0.4: every adopted proposal is switchable, default = the proposal).

use rolldyn_contact::roller_raceway::SliceLawChoice;
use serde::Serialize;

/// Which ring the per-roller slip ε_w is measured against (SPEC §5.3: seed 001 measures it
/// against the driving outer ring of an intershaft bearing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SlipReference {
    /// The ring with the larger absolute speed |ω| (the inner ring of an ordinary bearing, the
    /// outer ring of a seed 001 intershaft bearing whose outer ring is faster). Default.
    #[default]
    FasterRing,
    /// Always the inner ring.
    Inner,
    /// Always the outer ring.
    Outer,
}

/// Lever arm of the cage–land friction moment (⚠ F-41).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LandMomentArm {
    /// The land radius D_s1/2 (SPEC F-41 proposal). Default.
    #[default]
    Radius,
    /// The seed's literal T_sб = f F_RS D_s1 (diameter as lever arm).
    SeedDiameter,
}

/// Solver tolerances and iteration budgets. Every field has a documented default
/// ([`QuasiStaticOptions::default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct QuasiStaticOptions {
    /// Relative tolerance of the cage moment equation Φ(ε₀) = 0: |Φ| ≤ tol·(sum of the
    /// magnitudes of all moments on the cage). Default 1e-6 (SPEC §5.6). A point is returned
    /// only if its final residual is within `cage_residual_slack` × this.
    pub cage_tolerance: f64,
    /// Factor on `cage_tolerance` that a returned point's final cage residual may reach. A root
    /// bracketed to the speed tolerance can keep a residual slightly above `cage_tolerance`
    /// (Φ is not resolved below the f64 resolution of the cage speed); a larger final residual
    /// is a convergence failure. Default 10 (intershaft and equal-speed points end at
    /// 1.0–1.4e-6 with the default tolerance).
    pub cage_residual_slack: f64,
    /// Relative tolerance of each roller moment equation ΣT(ε_w) = 0, scaled by the moments of
    /// the raceway normal loads at the roller radius (R_w·(Q_i + Q_o + Q_bar)). Default 1e-10.
    pub roller_tolerance: f64,
    /// Relative tolerance of the ring force balance and of each roller's radial balance in the
    /// load distribution. Default 1e-12.
    pub load_tolerance: f64,
    /// Relative finite-difference step of the first Newton derivative (SPEC §5.6: 1e-6
    /// relative, at least `fd_min_step_rad_s` absolute). Default 1e-6.
    pub fd_relative_step: f64,
    /// Smallest (absolute) finite-difference step in angular speed, rad/s. Default 1e-9.
    pub fd_min_step_rad_s: f64,
    /// Function-evaluation budget of the cage equation. Default 60.
    pub max_cage_evaluations: usize,
    /// Function-evaluation budget of each roller equation. Default 80.
    pub max_roller_evaluations: usize,
    /// Iteration budget of the ring load-distribution Newton solve. Default 100.
    pub max_load_iterations: usize,
    /// Slice law of the roller–raceway contacts (SPEC §2.1): seed eqs (2.3)/(2.4) (default) or
    /// the ISO/TS 16281 lamina law.
    pub slice_law: SliceLawChoice,
    /// Angular position of roller 0 measured from the radial-load direction, rad. Default 0
    /// (a roller under the load, the symmetric case of the classical closed forms).
    pub roller_phase_rad: f64,
    /// Initial guess of the cage slip ε₀ (e.g. the previous point of a sweep). Default 0.
    pub initial_cage_slip: f64,
    /// Per-roller slip reference ring (reporting only).
    pub slip_reference: SlipReference,
    /// Lever arm of the cage–land friction moment (⚠ F-41).
    pub land_moment_arm: LandMomentArm,
    /// Evaluate the scuffing margin s_cr/s of every loaded raceway contact (critical-slip
    /// search of the lubrication crate, ≈ 30 traction evaluations per distinct contact).
    /// Default true.
    pub scuffing: bool,
    /// Rolling-speed magnitude below which a contact is treated as not rolling (no scuffing
    /// margin, slide-to-roll ratio reported with the floored speed), m/s. Default 1e-3.
    pub min_rolling_speed_m_s: f64,
}

impl Default for QuasiStaticOptions {
    fn default() -> Self {
        Self {
            cage_tolerance: 1e-6,
            cage_residual_slack: 10.0,
            roller_tolerance: 1e-10,
            load_tolerance: 1e-12,
            fd_relative_step: 1e-6,
            fd_min_step_rad_s: 1e-9,
            max_cage_evaluations: 60,
            max_roller_evaluations: 80,
            max_load_iterations: 100,
            slice_law: SliceLawChoice::Seed,
            roller_phase_rad: 0.0,
            initial_cage_slip: 0.0,
            slip_reference: SlipReference::FasterRing,
            land_moment_arm: LandMomentArm::Radius,
            scuffing: true,
            min_rolling_speed_m_s: 1e-3,
        }
    }
}
