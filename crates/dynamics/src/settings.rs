//! Every solver knob in one place (rapier-style): [`DynamicsSettings`] with
//! [`IntegratorSettings`]. All defaults are documented and justified.

/// Time-integration method (measured comparison in `docs/dynamics-integrator.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum IntegratorMethod {
    /// Explicit Dormand–Prince 5(4) with FSAL and 4th-order dense output
    /// ([`crate::Dopri5`]).
    #[default]
    Dopri5,
    /// Linearly implicit Rosenbrock-W method ROS34PW2, order 3(2), with a block-diagonal
    /// finite-difference Jacobian per body reused over many steps ([`crate::RosenbrockW`]).
    RosenbrockW,
}

/// Characteristic scale of the roller velocities and transverse angular momenta in the error
/// test (crate docs, "Error control"; measured in `docs/dynamics-integrator.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum VelocityErrorScale {
    /// Every velocity to `τ·v_ref`, the largest raceway surface speed (the only choice before
    /// the fourth session).
    SurfaceSpeed,
    /// Energy-consistent with the positions: a roller's radial and axial velocity to
    /// `τ·ω_c·s_x` and its transverse angular momentum to `τ·I_t·ω_c·s_φ`, where `s_x` and
    /// `s_φ` are the position and tilt scales and `ω_c` is the roller–raceway contact frequency
    /// (`√(k_i + k_o)/m_r`, the linearised stiffness of both line contacts at 100 N). A
    /// velocity error `ε_v` in a mode of frequency `ω_c` becomes a position error `ε_v/ω_c`
    /// within a period, so both then carry the same elastic energy. The surface speed stays a
    /// floor, and the orbital speed, the spin and the cage and ring velocities keep `v_ref`
    /// (they set the sliding speeds directly). 2002834: `ω_c ≈ 2.8·10⁵ rad/s`, 5–6× looser on
    /// the roller radial velocity than [`Self::SurfaceSpeed`]. The tapered bearing takes `ω_c`
    /// of its cone and cup line contacts (the cassette: 1.29·10⁵ rad/s, 19× looser on the
    /// radial and axial velocities, 33× on the transverse momenta; 1.7× fewer steps,
    /// `docs/dynamics-integrator.md` §5.7).
    #[default]
    ContactFrequency,
}

/// Settings of the variable-step integrator: explicit Dormand–Prince 5(4) or the linearly
/// implicit Rosenbrock-W method (see `docs/dynamics-integrator.md` for the measured choice).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IntegratorSettings {
    /// Method (default [`IntegratorMethod::Dopri5`], see `docs/dynamics-integrator.md`).
    pub method: IntegratorMethod,
    /// Rosenbrock-W only: accepted steps between evaluations of the block Jacobian (default
    /// 20 ≈ 1.5 extra RHS per step for the 31-RHS coloured Jacobian of 2002834). A W-method
    /// keeps its order with a stale Jacobian, only its damping of the stiff modes degrades.
    pub jacobian_interval: u32,
    /// Rosenbrock-W only: re-evaluate a non-fresh Jacobian after a rejected step (default
    /// false: on 2002834 it doubled the RHS count without fewer rejections, see
    /// `docs/dynamics-integrator.md`).
    pub refresh_jacobian_on_reject: bool,
    /// Rosenbrock-W only: keep the LU (and Schur complement) factors of `I/(γh_f) − A` while
    /// the step size `h` stays within `|h/h_f − 1| ≤ refactor_step_ratio` of the step size
    /// `h_f` they were factored at. A W-method keeps its order for any matrix in place of the
    /// Jacobian (Hairer & Wanner II, §IV.7): the factors then stand for the matrix
    /// `A' = A + (1/(γh) − 1/(γh_f)) I`; only the damping of the stiff modes changes slightly.
    /// 0 refactors on every change of `h`. Default 0.05: on the tapered cassette 5 % less CPU
    /// time than 0 with the same RHS count; 0.2 took 24 % more RHS (more rejections), see
    /// `docs/dynamics-integrator.md` §5.7.
    pub refactor_step_ratio: f64,
    /// Rosenbrock-W only: couple each roller's block with its cage and the inner ring in the
    /// Jacobian and solve the stages as one bordered block system (Schur complement on the
    /// cages and ring), where the model declares the coupling (the tapered bearing; default
    /// true: the roller ↔ inner-ring traction coupling is stiff, `docs/dynamics-integrator.md`
    /// §2). The cylindrical model keeps the block-diagonal Jacobian.
    pub bordered_jacobian: bool,
    /// Dimensionless error tolerance τ. A step is accepted when, for every state component,
    /// `|error_i| ≤ τ·(s_i + ρ_i |y_i|)` where `s_i` is the component's characteristic scale
    /// (see the crate docs, "Error control") and `ρ_i` is 1 for velocities/momenta and 0 for
    /// positions and angles. Default 1e-6: positions to 1 nm (0.1–1 % of a raceway approach).
    /// Halving it changes the mean cage speed and slip by well under 1 % (test
    /// `tests/convergence.rs`). Averaged over 15 revolutions of 2002834, all per-revolution
    /// figures are then within their revolution-to-revolution scatter of a τ = 1e-8 reference,
    /// except the mean friction power (+0.9 %). At 1e-5 that bias is +2.6 %, at 3e-5 +4.3 %;
    /// at 1e-4 the raceway force maxima are 20–28 % high (`docs/dynamics-integrator.md`).
    pub tolerance: f64,
    /// Scale of the roller velocities in the error test, cylindrical and tapered (default
    /// [`VelocityErrorScale::ContactFrequency`]).
    pub velocity_scale: VelocityErrorScale,
    /// First trial step, s (default 1e-7; the controller adapts within a few steps).
    pub initial_step_s: f64,
    /// Largest step, s (default 5e-5: keeps roller–cage impacts from being stepped over when a
    /// roller is free in its pocket — an impact lasts ≳ 50 µs at the default bar stiffness).
    pub max_step_s: f64,
    /// Smallest step before the run stops with [`crate::DynError::StepSizeCollapse`], s
    /// (default 1e-12).
    pub min_step_s: f64,
    /// Safety factor of the step controller (default 0.9, Hairer–Wanner).
    pub safety: f64,
    /// PI controller exponent β on the previous error (default 0.04, Hairer's DOPRI5; 0 gives
    /// the classical I controller).
    pub pi_beta: f64,
    /// Rosenbrock-W only: bound the next step also by Gustafsson's predictive controller
    /// `h·safety·(h/h_prev)·(err_prev/err²)^{1/3}` (RODAS, Hairer & Wanner II §IV.8), which
    /// shrinks the step before an error growth rather than after a rejection. Default true: on
    /// the tapered cassette it halved the rejected steps and took 11–17 % fewer RHS evaluations
    /// than the PI controller alone (`docs/dynamics-integrator.md` §5.7).
    pub predictive_step: bool,
    /// Rosenbrock-W only: keep the step size (and so the factors of the stage matrix) when the
    /// controller proposes a growth by less than this ratio (RADAU5's `quot2 − 1`; default
    /// 0.2; 0 never holds).
    pub hold_step_ratio: f64,
    /// Reference load of the roller–raceway contact frequency `ω_c` of
    /// [`VelocityErrorScale::ContactFrequency`], N (default 100 N). The linearised stiffness
    /// `k = n Q/δ` of a line contact grows as `Q^{1/10}` (n = 10/9), so a tenfold load moves
    /// `ω_c` by 12 %: a scale, not a load-dependent quantity.
    pub contact_frequency_load_n: f64,
    /// Largest step growth per step (default 5) and smallest shrink (default 0.2).
    pub max_growth: f64,
    /// See `max_growth`.
    pub min_shrink: f64,
    /// Step budget of one `run_until` call (default 2e8 — effectively unlimited; guards
    /// against endless runs with absurd inputs).
    pub max_steps: u64,
}

impl Default for IntegratorSettings {
    fn default() -> Self {
        Self {
            method: IntegratorMethod::default(),
            jacobian_interval: 20,
            refresh_jacobian_on_reject: false,
            refactor_step_ratio: 0.05,
            bordered_jacobian: true,
            tolerance: 1e-6,
            velocity_scale: VelocityErrorScale::default(),
            initial_step_s: 1e-7,
            max_step_s: 5e-5,
            min_step_s: 1e-12,
            safety: 0.9,
            pi_beta: 0.04,
            predictive_step: true,
            hold_step_ratio: 0.2,
            contact_frequency_load_n: 100.0,
            max_growth: 5.0,
            min_shrink: 0.2,
            max_steps: 200_000_000,
        }
    }
}

/// Settings of a dynamics run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicsSettings {
    /// Integrator settings.
    pub integrator: IntegratorSettings,
    /// Interval of the fixed-step output samples passed to the sink, s (default 5e-5 s =
    /// 0.05 ms; seed 000 used 0.002 ms for wear runs — set it smaller when needed). 0 disables
    /// sampling.
    pub output_step_s: f64,
    /// Number of cage revolutions at the start of a run excluded from the run summary (default
    /// 1: the start transient). When the run completes fewer, the whole run is summarised.
    pub discard_revolutions: u32,
    /// Steady state: the mean cage speed of two consecutive cage revolutions differs by less
    /// than this fraction (default 1e-3).
    pub steady_state_tolerance: f64,
    /// Evaluate the scuffing margin s_cr/s once per cage revolution at the inner-raceway
    /// contact with the largest relative slip (default true; ≈ 100 traction evaluations per
    /// revolution).
    pub scuffing_check: bool,
    /// Rollers whose inner contact force is below this fraction of the largest one are left out
    /// of the sliding-speed and relative-slip maxima (default 0.05: rollers entering or leaving
    /// the load zone carry a few newtons and slide freely, which is not the seed's "sliding
    /// speed on the inner ring").
    pub slip_load_fraction: f64,
    /// A roller or cage penetrating a raceway, bar or land deeper than this is reported as a
    /// divergence, m (default 0.1 mm — a hundred times a working approach).
    pub divergence_penetration_m: f64,
    /// A roller axis tilted (yaw and pitch combined) by more than this from the bearing axis is
    /// reported as a divergence, rad (default 0.1 rad ≈ 5.7°). With the roller-end ↔ rib and
    /// pocket-face contacts switched off only the cage bars bound roller skew: a roller whose
    /// bar-contact points sit at `±h` along its axis in a pocket with play `p` per side can skew
    /// by at most `ψ = p/h` before both ends touch opposite bars — 2002834 with the Ø190.2 mm
    /// bar contact: `p = (11.25 − 11.00)/2 = 0.125 mm`, `h = 2.5 mm` → 0.05 rad (0.08/0.11/0.16
    /// rad for the wider Table 3.1 windows). Pitch is held by the raceways to ≈ `G_r/L`. The
    /// default is twice the 2002834 bar bound: a tilt beyond it means a roller passed through a
    /// bar, i.e. a real divergence, not rattling inside the pocket.
    pub divergence_tilt_rad: f64,
    /// Precession (seed 000 §3.1.1: "whirl ratio ≈ 1", variants 6, 36, 37 with 1.00–1.02) is
    /// reported when |whirl ratio − 1| is at most this band (default 0.05: the seed's
    /// non-precessing variants lie at ≤ 0.80 or ≥ 1.10, its precessing ones within 0.02, and
    /// variant 35 at 0.97 counts as precessing too).
    pub precession_band: f64,
}

impl DynamicsSettings {
    /// Whether a whirl ratio means precession (see [`Self::precession_band`]).
    pub fn is_precession(&self, whirl_ratio: f64) -> bool {
        (whirl_ratio - 1.0).abs() <= self.precession_band
    }
}

impl Default for DynamicsSettings {
    fn default() -> Self {
        Self {
            integrator: IntegratorSettings::default(),
            output_step_s: 5e-5,
            discard_revolutions: 1,
            steady_state_tolerance: 1e-3,
            scuffing_check: true,
            slip_load_fraction: 0.05,
            divergence_penetration_m: 1e-4,
            divergence_tilt_rad: 0.1,
            precession_band: 0.05,
        }
    }
}
