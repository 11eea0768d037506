//! Streaming outputs: [`OutputSink`] receives a [`Snapshot`] at every fixed output step and a
//! [`RevolutionSummary`] at the end of every cage revolution; nothing is kept in memory beyond
//! the current values. [`RunSummary`] is the final summary of a run.

use crate::ends::EndContactRegime;
use crate::vec3::V3;

/// Per-roller quantities of one raceway contact (struct of arrays, index = roller). Speeds,
/// film, Λ and μ are load-weighted means over the roller's loaded slices; force and power are
/// sums. Unloaded rollers have force 0, film and Λ NaN.
#[derive(Debug, Clone, Copy)]
pub struct ContactSnapshot<'a> {
    /// normal force Q, N
    pub force_n: &'a [f64],
    /// sliding speed |v₁ − v₂|, m/s
    pub sliding_speed_m_s: &'a [f64],
    /// rolling (entrainment) speed u in the roller's orbital frame, m/s
    pub rolling_speed_m_s: &'a [f64],
    /// slide-to-roll ratio s = v/u
    pub slide_to_roll: &'a [f64],
    /// minimum film thickness, m
    pub film_thickness_m: &'a [f64],
    /// film parameter Λ
    pub lambda: &'a [f64],
    /// traction coefficient μ
    pub traction_coefficient: &'a [f64],
    /// friction power μ Q v, W
    pub friction_power_w: &'a [f64],
    /// normal force of every slice, roller-major (`[j * slices + i]`, slices in the order of
    /// the roller's slice stack along its axis; 0 where unloaded), N — the axial load
    /// distribution the raceway wear lines need
    pub slice_force_n: &'a [f64],
}

/// Per-roller kinematics and forces (struct of arrays, index = roller).
#[derive(Debug, Clone, Copy)]
pub struct RollerSnapshot<'a> {
    /// azimuth θ of the roller centre, rad (unwrapped)
    pub azimuth_rad: &'a [f64],
    /// radius r of the roller centre, m
    pub radius_m: &'a [f64],
    /// axial position z of the roller centre, m
    pub axial_m: &'a [f64],
    /// orbital speed θ̇, rad/s
    pub orbital_speed_rad_s: &'a [f64],
    /// spin speed about the roller axis (inertial), rad/s — negative for ω_i > 0
    pub spin_speed_rad_s: &'a [f64],
    /// yaw (skew): angle of the axis toward +θ in the tangential plane, rad
    pub yaw_rad: &'a [f64],
    /// pitch (tilt): angle of the axis toward +r in the axial–radial plane, rad
    pub pitch_rad: &'a [f64],
    /// inner raceway contact
    pub inner: ContactSnapshot<'a>,
    /// outer raceway contact
    pub outer: ContactSnapshot<'a>,
    /// roller ↔ cage bar normal force, N
    pub cage_bar_force_n: &'a [f64],
    /// roller ↔ cage bar friction power, W
    pub cage_bar_power_w: &'a [f64],
    /// roller ↔ cage bar sliding speed (force-weighted over the bar contacts; the speed of the
    /// friction law), m/s — 0 without contact
    pub cage_bar_sliding_speed_m_s: &'a [f64],
    /// roller ends ↔ ribs normal force (both ends, all ribs), N (pair 56)
    pub rib_force_n: &'a [f64],
    /// roller ends ↔ ribs sliding speed (force-weighted), m/s — the wear-relevant speed
    pub rib_sliding_speed_m_s: &'a [f64],
    /// distance of the rib contact point from the rib edge (rim minus edge break), m
    /// (force-weighted; NaN without contact) — seed §3.1.1.7 convex vs flat rib
    pub rib_edge_distance_m: &'a [f64],
    /// reduced radius of the end/rib pair of the rib contacts, m (+∞ for a pair without
    /// curvature, NaN without contact)
    pub rib_reduced_radius_m: &'a [f64],
    /// distance of the rib contact point from the roller axis, m (force-weighted; NaN without
    /// contact) — the wear line on the roller end
    pub rib_contact_radius_m: &'a [f64],
    /// distance of the rib contact point from the ring axis, m (force-weighted; NaN without
    /// contact) — the wear line on the rib
    pub rib_contact_ring_radius_m: &'a [f64],
    /// roller ends ↔ ribs friction coefficient (force-weighted)
    pub rib_friction_coefficient: &'a [f64],
    /// roller ends ↔ ribs friction power, W
    pub rib_power_w: &'a [f64],
    /// friction regime of the most loaded rib contact (SPEC §6.7)
    pub rib_regime: &'a [EndContactRegime],
    /// roller ends ↔ cage pocket faces normal force, N (pair 54)
    pub pocket_face_force_n: &'a [f64],
    /// roller ends ↔ cage pocket faces friction power, W
    pub pocket_face_power_w: &'a [f64],
}

/// A contact force on the cage and its point of application (inertial frame).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PointForce {
    /// force on the cage, N (zero without contact)
    pub force_n: V3,
    /// point of application, m
    pub point_m: V3,
}

/// The contact forces one roller puts on its pocket (the cage-load export, SPEC §7.2).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PocketLoads {
    /// roller ↔ bar at the evaluation points `[side −, end 0; side −, end 1; side +, end 0;
    /// side +, end 1]` (side −: the bar at lower cage angle; ends at the two ends of the roller's
    /// straight part)
    pub bar: [PointForce; 4],
    /// roller ends ↔ pocket faces, in the order of the model's pocket faces
    pub end: [PointForce; 2],
}

/// The cage's loads and rigid-body motion at one output time (inertial frame).
#[derive(Debug, Clone, Copy)]
pub struct CageLoads<'a> {
    /// unit axis of the cage
    pub axis: V3,
    /// acceleration of the cage centre, m/s²
    pub acceleration_m_s2: V3,
    /// angular velocity, rad/s
    pub angular_velocity_rad_s: V3,
    /// angular acceleration `I⁻¹(L̇ − ω × L)`, rad/s²
    pub angular_acceleration_rad_s2: V3,
    /// per pocket (index = roller)
    pub pockets: &'a [PocketLoads],
    /// cage ↔ guiding land at its two stations
    pub land: [PointForce; 2],
}

/// State of the bearing at one output time.
#[derive(Debug, Clone, Copy)]
pub struct Snapshot<'a> {
    /// time, s
    pub time_s: f64,
    /// prescribed inner-ring speed, rad/s
    pub inner_ring_speed_rad_s: f64,
    /// prescribed outer-ring speed, rad/s
    pub outer_ring_speed_rad_s: f64,
    /// inner-ring rotation angle ∫ω dt, rad (a point at angle ψ in the ring's frame is at
    /// azimuth ψ + this angle)
    pub inner_ring_angle_rad: f64,
    /// outer-ring rotation angle ∫ω dt, rad
    pub outer_ring_angle_rad: f64,
    /// inner-ring centre, m
    pub inner_ring_center_m: V3,
    /// cage centre, m
    pub cage_center_m: V3,
    /// cage rotation angle, rad (unwrapped)
    pub cage_angle_rad: f64,
    /// cage spin speed, rad/s
    pub cage_speed_rad_s: f64,
    /// epicyclic cage speed, rad/s
    pub epicyclic_cage_speed_rad_s: f64,
    /// cage slip 1 − ω_c/ω_c0 (SPEC §3.5)
    pub cage_slip: f64,
    /// cage ↔ land normal force, N
    pub cage_land_force_n: f64,
    /// cage ↔ land friction power, W
    pub cage_land_power_w: f64,
    /// rollers
    pub rollers: RollerSnapshot<'a>,
    /// contact forces on the cage and its motion
    pub cage_loads: CageLoads<'a>,
}

/// Summary of one cage revolution (seed 000 Table 3.2 columns that this issue covers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RevolutionSummary {
    /// revolution number (1 = first completed)
    pub revolution: u64,
    /// start and end time, s
    pub start_s: f64,
    /// end time, s
    pub end_s: f64,
    /// mean cage speed, rad/s
    pub cage_speed_mean_rad_s: f64,
    /// mean cage slip
    pub cage_slip_mean: f64,
    /// largest roller ↔ inner-raceway force, N
    pub max_inner_contact_force_n: f64,
    /// largest roller ↔ outer-raceway force, N
    pub max_outer_contact_force_n: f64,
    /// largest roller ↔ cage-bar force, N
    pub max_roller_cage_force_n: f64,
    /// largest cage ↔ land force, N
    pub max_cage_land_force_n: f64,
    /// largest sliding speed on the inner raceway (loaded rollers), m/s
    pub max_inner_sliding_speed_m_s: f64,
    /// largest relative slip v/u on the inner raceway (loaded rollers)
    pub max_relative_slip: f64,
    /// scuffing margin s_cr/s at the contact with the largest relative slip (∞ when the
    /// friction curve has no maximum in range or the check is off)
    pub scuffing_margin: f64,
    /// whirl ratio: cage spin / orbital speed of the cage centre (NaN when the centre does not
    /// orbit — it sweeps less than half a turn in the revolution)
    pub whirl_ratio: f64,
    /// precession (seed 000 §3.1.1): the cage centre orbits with the cage speed, |whirl ratio −
    /// 1| ≤ `DynamicsSettings::precession_band`
    pub precession: bool,
    /// RMS distance of the cage centre from the bearing axis, m
    pub cage_orbit_radius_m: f64,
    /// mean total friction power of all contacts, W
    pub friction_power_mean_w: f64,
    /// largest roller-end ↔ rib force (one roller, both ends), N (seed 000 Table 3.2)
    pub max_roller_end_rib_force_n: f64,
    /// largest roller-end ↔ cage pocket-face force (one roller, both ends), N (Table 3.2)
    pub max_roller_end_cage_force_n: f64,
    /// the mean cage speed changed by less than the steady-state tolerance since the previous
    /// revolution
    pub steady: bool,
    /// largest rolling-direction and axial components of the inner-raceway sliding velocity
    /// over the loaded rollers, and of the most loaded roller, m/s ([`RunSummary`] has the same
    /// four figures over the run)
    pub max_inner_sliding_rolling_direction_m_s: f64,
    pub max_inner_sliding_axial_m_s: f64,
    pub max_inner_sliding_rolling_direction_most_loaded_m_s: f64,
    pub max_inner_sliding_axial_most_loaded_m_s: f64,
}

/// Final summary of a run (the `rolldyn simulate --json` fields).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSummary {
    /// time-mean cage slip over the summary window
    pub cage_slip_mean: f64,
    /// time-mean cage speed, rad/s
    pub cage_speed_mean_rad_s: f64,
    /// epicyclic cage speed at the end of the run, rad/s
    pub epicyclic_cage_speed_rad_s: f64,
    /// N
    pub max_inner_contact_force_n: f64,
    /// N
    pub max_outer_contact_force_n: f64,
    /// N
    pub max_roller_cage_force_n: f64,
    /// N
    pub max_cage_land_force_n: f64,
    /// largest inner-raceway sliding speed of a loaded roller (load-weighted mean of |v| over
    /// its slices), m/s
    pub max_inner_sliding_speed_m_s: f64,
    /// largest v/u on the inner raceway
    pub max_relative_slip: f64,
    /// smallest s_cr/s (∞ if no check gave a value)
    pub min_scuffing_margin: f64,
    /// cage spin / cage-centre orbital speed over the window (NaN when the centre does not orbit)
    pub whirl_ratio: f64,
    /// the cage precesses: |whirl ratio − 1| ≤ `DynamicsSettings::precession_band`
    pub precession: bool,
    /// RMS distance of the cage centre from the bearing axis over the window, m
    pub cage_orbit_radius_m: f64,
    /// simulated time at the end, s
    pub simulated_time_s: f64,
    /// wall-clock time of all `run_until` calls, s
    pub wall_time_s: f64,
    /// accepted steps
    pub steps: u64,
    /// rejected steps
    pub rejected_steps: u64,
    /// right-hand-side evaluations of the integrator
    pub rhs_evaluations: u64,
    /// largest roller-end ↔ rib force, N (seed 000 Table 3.2)
    pub max_roller_end_rib_force_n: f64,
    /// largest roller-end ↔ cage pocket-face force, N (seed 000 Table 3.2)
    pub max_roller_end_cage_force_n: f64,
    /// largest rolling-direction (circumferential) component of the inner-raceway sliding
    /// velocity at a loaded roller's centre of pressure, m/s (docs/outputs.md)
    pub max_inner_sliding_rolling_direction_m_s: f64,
    /// largest axial component (from skew) of that sliding velocity, m/s
    pub max_inner_sliding_axial_m_s: f64,
    /// largest rolling-direction component of the roller carrying the largest inner-raceway
    /// normal force at the time, m/s
    pub max_inner_sliding_rolling_direction_most_loaded_m_s: f64,
    /// largest axial component of the most loaded roller, m/s
    pub max_inner_sliding_axial_most_loaded_m_s: f64,
}

/// Receiver of the streaming outputs.
pub trait OutputSink {
    /// Called at every output time `t` (multiples of `DynamicsSettings::output_step_s`).
    fn sample(&mut self, t: f64, snapshot: &Snapshot);
    /// Called at the end of every cage revolution.
    fn revolution(&mut self, _summary: &RevolutionSummary) {}
}

/// A sink that ignores everything.
#[derive(Debug, Clone, Copy, Default)]
pub struct NullSink;

impl OutputSink for NullSink {
    fn sample(&mut self, _t: f64, _snapshot: &Snapshot) {}
}

/// Owned buffers behind a [`Snapshot`].
#[derive(Debug, Clone, Default)]
pub(crate) struct SnapshotBuffers {
    pub azimuth: Vec<f64>,
    pub radius: Vec<f64>,
    pub axial: Vec<f64>,
    pub orbital: Vec<f64>,
    pub spin: Vec<f64>,
    pub yaw: Vec<f64>,
    pub pitch: Vec<f64>,
    pub srr_inner: Vec<f64>,
    pub srr_outer: Vec<f64>,
    /// reduced radius of the end/rib pair per roller (NaN without rib contact)
    pub rib_reduced_radius: Vec<f64>,
}

impl SnapshotBuffers {
    pub fn new(z: usize) -> Self {
        let v = || vec![0.0; z];
        Self {
            azimuth: v(),
            radius: v(),
            axial: v(),
            orbital: v(),
            spin: v(),
            yaw: v(),
            pitch: v(),
            srr_inner: v(),
            srr_outer: v(),
            rib_reduced_radius: v(),
        }
    }
}
