//! # rolldyn-dynamics — 6-DOF multibody dynamics of cylindrical roller bearings (SPEC §3)
//!
//! Every roller and the cage move with six degrees of freedom, the inner ring translates freely
//! under its loads with a prescribed spin (and prescribed misalignment), the outer ring is fixed
//! or spins at a prescribed speed. Contacts are compliant force laws (no impulses, seed 000
//! §2.1): roller slices ↔ both raceways with the slice laws of `rolldyn_contact::slices`, the
//! STEP damping ramp (SPEC §2.2) and EHL traction per slice from
//! [`rolldyn_lubrication::traction()`]; roller ↔ cage bars; cage ↔ guiding land
//! ([`CageLandModel`], default two-level friction); cage viscous drag (SPEC §3.6).
//!
//! ## Entry point
//! [`Simulation::new`] → [`Simulation::run_until`] with an [`OutputSink`] (streaming samples
//! and per-revolution summaries) → [`RunSummary`]. [`Simulation::checkpoint`] /
//! [`Simulation::restore`] continue a run bit-for-bit. [`study::measure_cage_slip`] measures the
//! cage slip over whole revolutions for the cage-slip studies.
//!
//! ## Coordinates (inertial frame = outer-ring frame)
//! `z` is the bearing axis, `x`, `y` span the radial plane (gravity default −y). The state
//! vector is described in [`Layout`]:
//!
//! * **Roller centre in cylindrical coordinates** `(θ, r, z)` with rates `(θ̇, ṙ, ż)`: the
//!   radius — the quantity the raceway contacts are most sensitive to — is a state component of
//!   its own, so the error control holds it to nanometres while the azimuth, which only matters
//!   against the ≈ 1 mm pocket clearance, has a correspondingly looser absolute tolerance.
//!   Translational equations `m(r̈ − rθ̇²) = F_r`, `m(rθ̈ + 2ṙθ̇) = F_θ`, `m z̈ = F_z`
//!   (seed 000 eq. (2.1)).
//! * **Roller attitude by its axis unit vector `a`** (inertial components; `a_x, a_y` are small,
//!   so they are well conditioned) and its **angular momentum `L`** (inertial): for an
//!   axisymmetric body `L = I_t ω + (I_a − I_t)(a·ω) a`, so `ω(L, a)` is explicit,
//!   `ȧ = ω × a` and `L̇ = M` — the full Newton–Euler equations (seed 000 eq. (2.2)) with the
//!   gyroscopic term `ω × Iω` contained exactly. The **spin angle is not a state**: an
//!   axisymmetric roller's contact geometry does not depend on it, so it can never limit the
//!   step; spin enters through `a·L` (the surface velocities) only. Yaw (skew) and pitch (tilt)
//!   are reported as `atan2(a·e_θ, a_z)` and `atan2(a·e_r, a_z)`.
//! * **Cage**: centre `(x, y, z)` Cartesian (it moves within the floating clearance), rotation
//!   angle `φ` (the pocket positions depend on it; `φ̇ = ω·a`), axis `a` and angular momentum
//!   `L` as for the rollers (the cage is treated as axisymmetric in inertia; its pockets enter
//!   through the contact geometry only).
//! * **Inner ring**: centre `(x, y, z)` and velocity, free or fixed per direction
//!   ([`InnerRingSupport`]); spin and tilt are prescribed ([`OperatingConditions`]).
//!
//! ## Contacts
//! * *Raceways*: slice `s` of roller `j` sits at `p = c + x_s a`. Its approach on the inner ring
//!   is `δ = R_i + R_w − ρ − z_s − z_race(ζ)` with `ρ` the distance of `p` from the (misaligned)
//!   inner-ring axis, on the outer ring `δ = ρ + R_w − R_o` with `R_o = R_i + D_w + G_r/2` (the
//!   operating radial clearance of the model). Pitch enters through `x_s a`, yaw through the
//!   contact-point velocity (axial sliding component). Normal force: slice law + STEP damping,
//!   clamped ≥ 0 (`rolldyn_contact::damping::SliceDamping`); tangential force `−μ Q v̂` with μ
//!   from `traction()` at the slice's `Q`, `u` (orbital-frame rolling speed, SPEC §3.5), `|v|`.
//! * *Cage bars*: the bar edges of pocket `j` are lines parallel to the cage axis at the bar
//!   contact radius, `±½` pocket width from the pocket centre; each is tested against the roller
//!   axis at both ends of the straight part of the roller (alternating yaw, "bone-shaped" scar,
//!   SPEC §1.5). `K_p δⁿ + STEP(δ,0,0,d,C_h)δ̇` with two-level friction (SPEC §3.3, §3.4).
//! * *Guiding land*: two stations at the quarter points of the land width (cage tilt meets a
//!   restoring moment), model behind [`CageLandModel`].
//!
//! ## Error control
//! Component `i` of the state is accepted with `|e_i| ≤ τ (s_i + ρ_i |y_i|)`: lengths
//! `s = 1 mm` (1 nm at τ = 10⁻⁶), angles `1 mm/R` (roller axis: `1 mm/(L/2)`), velocities
//! `s = v_ref = max(|ω_i| R_i, |ω_o| R_o, 1 m/s)` with `ρ = 1`, angular momenta
//! `I_a v_ref/R`. By default ([`VelocityErrorScale::ContactFrequency`]) a roller's radial and
//! axial velocities and its transverse angular momenta use the energy-consistent scales
//! `ω_c·1 mm` and `I_t ω_c·1 mm/(L/2)` instead (floored by the above), `ω_c` the roller–raceway
//! contact frequency. See `docs/dynamics-integrator.md` for the integrator choice and the
//! measured accuracy.
//!
//! * *Roller ends*: each end disc against the rib faces of both rings (pair 56: flat, conical,
//!   convex/concave toroidal faces, rim edge break, spherical or flat roller ends) and against
//!   the axial faces of its cage pocket (pair 54): deepest point of the end disc inside the face
//!   band, `K_p δⁿ + STEP(δ,0,0,d,C_h)δ̇`, boundary friction 0.065 / Kragelsky / EHL with the
//!   SPEC §6.7 regime (module `ends`, [`RollerEndParameters`]). The ribs bound roller skew to
//!   the rib clearance (2002834: ≈ 0.0046 rad instead of the cage-bar bound ≈ 0.05 rad).
//!
//! ## Not modelled
//! The inner ring's tilt is prescribed, not a degree of freedom; end–rib compliance is the power
//! law `K_p δⁿ` (tabulated FE force–approach curves are not read).

mod checkpoint;
pub mod conditions;
mod ends;
mod error;
mod initial;
pub mod integrator;
mod kinematics;
pub mod land;
mod layout;
mod model;
pub mod output;
pub mod output_columns;
pub mod parameters;
mod rhs;
pub mod rosenbrock;
pub mod settings;
mod simulation;
mod slice_kernel;
mod stepper;
pub mod study;
mod summary;
mod summary_columns;
pub mod tapered;
mod vec3;

pub use conditions::{
    CAGE_DRAG_2002834_100C, ContactTemperatures, InnerRingLoad, InnerRingSupport,
    OperatingConditions, SpeedLaw,
};
pub use ends::EndContactRegime;
pub use error::DynError;
pub use initial::{InitialState, RollerStart, StaticRoller, StaticSolution, pure_rolling_spin};
pub use integrator::{Dopri5, OdeSystem, StepStats};
pub use land::{CageLandModel, HydrodynamicLand, LandForce, LandKinematics, TwoLevelLand};
pub use layout::{Layout, cage, inner_ring, roller};
pub use model::RacewayTraction;
pub use output::{
    ContactSnapshot, NullSink, OutputSink, RevolutionSummary, RollerSnapshot, RunSummary, Snapshot,
};
pub use parameters::{
    ContactParameters, EndFriction, PairParameters, RacewayParameters, RollerEndParameters,
};
pub use rhs::axisymmetric_omega;
pub use rosenbrock::{JacobianBlock, JacobianBorder, RosenbrockW};
pub use settings::{DynamicsSettings, IntegratorMethod, IntegratorSettings, VelocityErrorScale};
pub use simulation::Simulation;
pub use summary_columns::SummaryValue;
pub use vec3::V3;
