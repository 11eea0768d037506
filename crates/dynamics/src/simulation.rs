//! The public entry point: [`Simulation`].

use crate::checkpoint::{Reader, Writer, fnv1a};
use crate::conditions::OperatingConditions;
use crate::error::DynError;
use crate::initial::{
    InitialState, RollerStart, StaticSolution, pure_rolling_spin, static_equilibrium,
};
use crate::integrator::{Dopri5, OdeSystem, StepError, StepStats};
use crate::land::CageLandModel;
use crate::layout::{
    CAGE_DOF, INNER_DOF, Layout, ROLLER_DOF, cage, inner_ring, read3, roller, write3,
};
use crate::model::{Model, RacewayTraction};
use crate::output::{
    CageLoads, ContactSnapshot, OutputSink, RevolutionSummary, RollerSnapshot, RunSummary,
    Snapshot, SnapshotBuffers,
};
use crate::parameters::ContactParameters;
use crate::rhs::{Diagnostics, Tables, axisymmetric_omega, rhs};
use crate::rosenbrock::{JacobianBlock, RosenbrockW};
use crate::settings::{DynamicsSettings, IntegratorMethod, IntegratorSettings, VelocityErrorScale};
use crate::stepper::Stepper;
use crate::summary::{SlidingMaxima, StepValues, Window};
use crate::vec3::{V3, cross, dot, sub, unit_or};
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_lubrication::{SlipSearch, scuffing::scuffing_check};
use std::f64::consts::TAU;
use std::ops::ControlFlow;
use std::time::Instant;

struct Sys<'a> {
    model: &'a Model,
    diag: &'a mut Diagnostics,
}

impl OdeSystem for Sys<'_> {
    #[inline]
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        rhs(self.model, t, y, dy, self.diag, Tables::Skip);
    }

    #[inline]
    fn rhs_reported(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        rhs(self.model, t, y, dy, self.diag, Tables::Fill);
    }
}

/// Bookkeeping of cage revolutions, summary windows and the cage-centre orbit.
#[derive(Debug, Clone, Copy)]
struct Tracker {
    /// completed cage revolutions
    revolutions: u64,
    /// cage angle at the start of the current revolution
    rev_angle0: f64,
    rev: Window,
    run: Window,
    /// the run window has been restarted after the discarded revolutions
    run_started: bool,
    prev_rev_speed: f64,
    steady_at: f64,
    next_sample: u64,
    wall: f64,
}

/// A dynamics run of one cylindrical roller bearing.
///
/// ```no_run
/// use rolldyn_dynamics::*;
/// # fn demo(bearing: &rolldyn_geometry::CylindricalRollerBearing,
/// #         traction: rolldyn_lubrication::TractionModel) -> Result<(), DynError> {
/// let cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 500.0);
/// let params = ContactParameters::for_bearing(bearing);
/// let mut sim = Simulation::new(bearing, cond, params, DynamicsSettings::default(),
///                               RacewayTraction::same(traction))?;
/// let summary = sim.run_until(0.05, &mut NullSink, &mut |_t| {})?;
/// println!("cage slip {:.4}", summary.cage_slip_mean);
/// # Ok(()) }
/// ```
#[derive(Debug)]
pub struct Simulation {
    model: Model,
    settings: DynamicsSettings,
    ig: Stepper,
    diag: Diagnostics,
    snap: SnapshotBuffers,
    scratch_y: Vec<f64>,
    scratch_dy: Vec<f64>,
    tr: Tracker,
    fingerprint: u64,
}

impl Simulation {
    /// Builds a run from the default start ([`Simulation::default_initial_state`]).
    pub fn new(
        bearing: &CylindricalRollerBearing,
        conditions: OperatingConditions,
        parameters: ContactParameters,
        settings: DynamicsSettings,
        traction: RacewayTraction,
    ) -> Result<Self, DynError> {
        let mut model = Model::new(bearing, conditions, parameters, traction)?;
        model.apply(&settings);
        let init = default_initial_state(&model)?;
        Self::from_model(model, settings, &init)
    }

    /// Builds a run from an explicit initial state (e.g. from the quasi-static model).
    pub fn with_initial_state(
        bearing: &CylindricalRollerBearing,
        conditions: OperatingConditions,
        parameters: ContactParameters,
        settings: DynamicsSettings,
        traction: RacewayTraction,
        initial: &InitialState,
    ) -> Result<Self, DynError> {
        let mut model = Model::new(bearing, conditions, parameters, traction)?;
        model.apply(&settings);
        Self::from_model(model, settings, initial)
    }

    /// The default start of a bearing: pure-rolling kinematics at the epicyclic cage speed,
    /// rollers centred in their pockets at their static equilibrium radius under the ring load.
    pub fn default_initial_state(
        bearing: &CylindricalRollerBearing,
        conditions: OperatingConditions,
        parameters: ContactParameters,
        traction: RacewayTraction,
    ) -> Result<InitialState, DynError> {
        let model = Model::new(bearing, conditions, parameters, traction)?;
        default_initial_state(&model)
    }

    /// Static load distribution of the bearing under its load at the start (rollers at the
    /// pocket centres, centrifugal force at the epicyclic cage speed).
    pub fn static_solution(&self) -> Result<StaticSolution, DynError> {
        static_solution(&self.model)
    }

    /// Replaces the cage ↔ land force model (e.g. the hydrodynamic model of the Reynolds
    /// crate). The default is [`crate::TwoLevelLand`] with `ContactParameters::cage_land`.
    pub fn set_cage_land_model(&mut self, model: Box<dyn CageLandModel>) {
        self.model.land_model = model;
        self.fingerprint = fingerprint(&self.model, &self.settings);
        self.ig.invalidate();
    }

    /// Sets [`crate::DynamicsSettings::discard_revolutions`], the cage revolutions left out of the
    /// run summary (the approach to steady state). Call it before running.
    pub fn set_discard_revolutions(&mut self, revolutions: u32) {
        self.settings.discard_revolutions = revolutions;
        self.tr.run_started = revolutions == 0;
        self.fingerprint = fingerprint(&self.model, &self.settings);
    }

    /// Switches the integration method ([`crate::IntegratorSettings::method`], e.g. the CLI's
    /// `--integrator`) at the current state: the new stepper starts from the current `(t, y)`
    /// with the initial step size and keeps the step statistics. Call it before running (and
    /// before [`Simulation::restore`] of a checkpoint written with `method`).
    pub fn set_integrator_method(&mut self, method: IntegratorMethod) {
        if self.settings.integrator.method == method {
            return;
        }
        self.settings.integrator.method = method;
        let set = &self.settings.integrator;
        let (scale, relative) = error_scales(&self.model, set);
        let (t, y) = (self.ig.t(), self.ig.y().to_vec());
        let mut ig = new_stepper(&self.model, set, t, y, scale, relative);
        *ig.stats_mut() = self.ig.stats().clone();
        self.ig = ig;
    }

    fn from_model(
        model: Model,
        settings: DynamicsSettings,
        init: &InitialState,
    ) -> Result<Self, DynError> {
        let set = &settings.integrator;
        if !(set.tolerance > 0.0
            && set.tolerance < 1.0
            && set.initial_step_s > 0.0
            && set.max_step_s >= set.initial_step_s
            && set.min_step_s > 0.0
            && set.min_step_s < set.initial_step_s
            && set.safety > 0.0
            && set.safety <= 1.0
            && set.max_growth > 1.0
            && set.min_shrink > 0.0
            && set.min_shrink < 1.0)
        {
            return Err(DynError::InvalidInput(
                "integrator settings out of range (0 < tolerance < 1, 0 < min_step < initial_step ≤ max_step, 0 < safety ≤ 1, min_shrink < 1 < max_growth)".into(),
            ));
        }
        if !(settings.output_step_s >= 0.0 && settings.output_step_s.is_finite()) {
            return Err(DynError::InvalidInput("output step must be ≥ 0".into()));
        }
        let lay = model.layout;
        if init.rollers.len() != model.z {
            return Err(DynError::InvalidInput(format!(
                "initial state has {} rollers, the bearing {}",
                init.rollers.len(),
                model.z
            )));
        }
        let y = pack_state(&model, init)?;
        let (scale, relative) = error_scales(&model, set);
        let ig = new_stepper(&model, set, 0.0, y, scale, relative);
        let z = model.z;
        let fingerprint = fingerprint(&model, &settings);
        let mut sim = Self {
            scratch_y: vec![0.0; lay.len()],
            scratch_dy: vec![0.0; lay.len()],
            diag: Diagnostics::new(z, model.slice_x.len()),
            snap: SnapshotBuffers::new(z),
            ig,
            settings,
            tr: Tracker {
                revolutions: 0,
                rev_angle0: 0.0,
                rev: Window::start(0.0, 0.0),
                run: Window::start(0.0, 0.0),
                run_started: false,
                prev_rev_speed: f64::NAN,
                steady_at: f64::NAN,
                next_sample: 0,
                wall: 0.0,
            },
            model,
            fingerprint,
        };
        let ci = lay.cage();
        let phi = sim.ig.y()[ci + cage::ANGLE];
        sim.tr.rev_angle0 = phi;
        sim.tr.rev = Window::start(0.0, phi);
        sim.tr.run = sim.tr.rev;
        sim.tr.run_started = settings.discard_revolutions == 0;
        Ok(sim)
    }

    /// Current simulated time, s.
    pub fn time(&self) -> f64 {
        self.ig.t()
    }

    /// Current state vector (layout in [`Layout`]).
    pub fn state(&self) -> &[f64] {
        self.ig.y()
    }

    /// State-vector layout.
    pub fn layout(&self) -> Layout {
        self.model.layout
    }

    /// Step statistics so far.
    pub fn stats(&self) -> &StepStats {
        self.ig.stats()
    }

    /// Name of the state component that limited the step most often, if any.
    pub fn most_limiting_component(&self) -> Option<String> {
        self.ig
            .stats()
            .most_limiting()
            .map(|i| self.model.layout.describe(i))
    }

    /// How often each kind of state component limited the step (every roller's radius r
    /// counted together as "roller radius r", and so on), most frequent first; kinds that never
    /// limited it are left out.
    pub fn step_limits(&self) -> Vec<(String, u64)> {
        let layout = self.model.layout;
        let mut by_kind: Vec<(String, u64)> = Vec::new();
        for (i, &count) in self.ig.stats().limiting.iter().enumerate() {
            if count == 0 {
                continue;
            }
            let (kind, _) = layout.kind(i);
            match by_kind.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, c)) => *c += count,
                None => by_kind.push((kind, count)),
            }
        }
        // stable: equal counts keep the layout order
        by_kind.sort_by_key(|(_, c)| std::cmp::Reverse(*c));
        by_kind
    }

    /// Completed cage revolutions (each one sent to the output sink).
    pub fn revolutions(&self) -> u64 {
        self.tr.revolutions
    }

    /// Number of rollers.
    pub fn roller_count(&self) -> usize {
        self.model.z
    }

    /// Time at which steady state was first detected (cage-speed change per revolution below
    /// `DynamicsSettings::steady_state_tolerance`), s.
    pub fn steady_state_time(&self) -> Option<f64> {
        self.tr.steady_at.is_finite().then_some(self.tr.steady_at)
    }

    /// Total mechanical energy, J: kinetic energy of rollers, cage and inner ring, elastic energy
    /// of the raceway, bar and (default-model) land contacts, potential of the fixed loads and
    /// gravity. Conserved by a frictionless, undamped run with fixed loads.
    pub fn mechanical_energy(&mut self) -> f64 {
        energy(&self.model, self.ig.t(), self.ig.y())
    }

    /// Current cage speed, rad/s.
    pub fn cage_speed(&self) -> f64 {
        cage_speed(&self.model, self.ig.y())
    }

    /// Epicyclic cage speed at the current time, rad/s.
    pub fn epicyclic_cage_speed(&self) -> f64 {
        let t = self.ig.t();
        let c = &self.model.conditions;
        self.model
            .epicyclic(c.inner_speed.speed(t), c.outer_speed.speed(t))
    }

    /// Integrates until `t_end` (the last step may end slightly beyond it: steps are never
    /// shortened to hit `t_end`, so that a run split into pieces — or resumed from a checkpoint —
    /// is bit-for-bit identical to an uninterrupted one). Samples are written at every multiple
    /// of the output step up to `t_end`; `progress` receives the time after every step.
    pub fn run_until(
        &mut self,
        t_end: f64,
        sink: &mut dyn OutputSink,
        progress: &mut dyn FnMut(f64),
    ) -> Result<RunSummary, DynError> {
        self.run_until_interruptible(t_end, sink, &mut |t| {
            progress(t);
            ControlFlow::Continue(())
        })
    }

    /// [`Simulation::run_until`] whose `progress(t)`, called after every accepted step, may stop
    /// the run: `ControlFlow::Break` ends it with [`DynError::Interrupted`] at the last accepted
    /// state (the same steps as an uninterrupted run up to there).
    pub fn run_until_interruptible(
        &mut self,
        t_end: f64,
        sink: &mut dyn OutputSink,
        progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
    ) -> Result<RunSummary, DynError> {
        if !t_end.is_finite() {
            return Err(DynError::InvalidInput("end time must be finite".into()));
        }
        let wall0 = Instant::now();
        let result = self.run_inner(t_end, sink, progress);
        self.tr.wall += wall0.elapsed().as_secs_f64();
        result?;
        Ok(self.summary())
    }

    fn run_inner(
        &mut self,
        t_end: f64,
        sink: &mut dyn OutputSink,
        progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
    ) -> Result<(), DynError> {
        let mut steps: u64 = 0;
        // samples still inside the last accepted step (after a resume or a previous call)
        self.emit_samples(t_end, sink);
        while self.ig.t() < t_end {
            if steps >= self.settings.integrator.max_steps {
                return Err(DynError::StepBudgetExhausted {
                    time_s: self.ig.t(),
                    steps,
                });
            }
            let t_before = self.ig.t();
            {
                let mut sys = Sys {
                    model: &self.model,
                    diag: &mut self.diag,
                };
                self.ig
                    .step(&mut sys, &self.settings.integrator)
                    .map_err(|e| match e {
                        StepError::Collapse { h, component } => DynError::StepSizeCollapse {
                            time_s: t_before,
                            step_s: h,
                            component: self.model.layout.describe(component),
                        },
                        StepError::NonFinite { h, component } => DynError::NonFinite {
                            time_s: t_before,
                            component: self.model.layout.describe(component),
                            step_s: h,
                        },
                    })?;
            }
            steps += 1;
            if let Some(v) = self.diag.violation {
                return Err(DynError::Divergence {
                    time_s: self.ig.t(),
                    body: format!("roller {} / {}", v.index, v.what),
                    detail: format!(
                        "penetration {:.3} mm exceeds the divergence limit",
                        v.penetration * 1e3
                    ),
                    step_s: self.ig.t() - t_before,
                });
            }
            let lay = self.model.layout;
            for j in 0..self.model.z {
                let b = lay.roller(j);
                let y = self.ig.y();
                let tilt = {
                    let a = read3(y, b + roller::AXIS);
                    (a[0] * a[0] + a[1] * a[1]).sqrt().atan2(a[2])
                };
                if tilt > self.settings.divergence_tilt_rad {
                    return Err(DynError::Divergence {
                        time_s: self.ig.t(),
                        body: format!("roller {j} attitude"),
                        detail: format!("axis tilted (skew + pitch) by {:.4} rad", tilt),
                        step_s: self.ig.t() - t_before,
                    });
                }
            }
            self.after_step(self.ig.t() - t_before, sink);
            self.emit_samples(t_end, sink);
            if progress(self.ig.t()).is_break() {
                return Err(DynError::Interrupted {
                    time_s: self.ig.t(),
                });
            }
        }
        Ok(())
    }

    /// Statistics of an accepted step from the diagnostics at the new state.
    fn step_values(&self) -> StepValues {
        let d = &self.diag;
        let m = &self.model;
        let w = cage_speed(m, self.ig.y());
        let w0 = m.epicyclic(d.inner_speed, d.outer_speed);
        let max_fi = d.inner.force.iter().fold(0.0_f64, |a, &b| a.max(b));
        let thresh = self.settings.slip_load_fraction * max_fi;
        let mut v = StepValues {
            cage_speed: w,
            slip: rolldyn_geometry::cage_slip(w, w0),
            max_fi,
            max_fo: d.outer.force.iter().fold(0.0_f64, |a, &b| a.max(b)),
            max_bar: d.bar.iter().fold(0.0_f64, |a, &b| a.max(b)),
            land: d.land_force,
            max_rib: d.rib.iter().fold(0.0_f64, |a, &b| a.max(b)),
            max_pocket: d.pocket.iter().fold(0.0_f64, |a, &b| a.max(b)),
            ..StepValues::default()
        };
        let ci = m.layout.cage();
        let (x, yc, vx, vy) = (
            self.ig.y()[ci + cage::CENTRE],
            self.ig.y()[ci + cage::CENTRE + 1],
            self.ig.y()[ci + cage::VELOCITY],
            self.ig.y()[ci + cage::VELOCITY + 1],
        );
        v.orbit_moment = x * vy - yc * vx;
        v.orbit_r2 = x * x + yc * yc;
        v.sliding = SlidingMaxima::of(&d.inner, thresh);
        let mut power = d.land_power;
        for j in 0..m.z {
            power += d.inner.power[j]
                + d.outer.power[j]
                + d.bar_power[j]
                + d.rib_power[j]
                + d.pocket_power[j];
            if d.inner.force[j] > thresh && d.inner.force[j] > 0.0 {
                let vs = d.inner.sliding[j];
                let u = d.inner.rolling[j].max(1e-6);
                v.max_vs = v.max_vs.max(vs);
                let s = vs / u;
                if s >= v.max_srr {
                    v.max_srr = s;
                    v.worst = d.inner.worst[j];
                }
            }
        }
        v.power = power;
        v
    }

    fn after_step(&mut self, h: f64, sink: &mut dyn OutputSink) {
        let v = self.step_values();
        let lay = self.model.layout;
        let ci = lay.cage();
        let y = self.ig.y();
        let phi = y[ci + cage::ANGLE];
        self.tr.rev.add(h, &v);
        self.tr.run.add(h, &v);
        if (phi - self.tr.rev_angle0).abs() >= TAU {
            self.finish_revolution(phi, sink);
        }
    }

    fn scuffing_margin(&self, w: &Window) -> f64 {
        if !self.settings.scuffing_check {
            return f64::INFINITY;
        }
        let Some(state) = w.worst else {
            return f64::INFINITY;
        };
        if state.rolling_speed_m_s.abs() <= 0.0 {
            return f64::INFINITY;
        }
        match scuffing_check(&state, &self.model.traction.inner, &SlipSearch::default()) {
            Ok(c) => c.margin.unwrap_or(f64::INFINITY),
            Err(_) => f64::INFINITY,
        }
    }

    fn finish_revolution(&mut self, phi: f64, sink: &mut dyn OutputSink) {
        let t = self.ig.t();
        self.tr.revolutions += 1;
        let w = self.tr.rev;
        let margin = self.scuffing_margin(&w);
        let speed = w.mean_speed();
        let steady = self.tr.prev_rev_speed.is_finite()
            && ((speed - self.tr.prev_rev_speed) / speed).abs()
                < self.settings.steady_state_tolerance;
        if steady && !self.tr.steady_at.is_finite() {
            self.tr.steady_at = t;
        }
        let whirl = w.whirl(phi);
        let summary = RevolutionSummary {
            revolution: self.tr.revolutions,
            start_s: w.t0,
            end_s: t,
            cage_speed_mean_rad_s: speed,
            cage_slip_mean: w.mean_slip(),
            max_inner_contact_force_n: w.max_fi,
            max_outer_contact_force_n: w.max_fo,
            max_roller_cage_force_n: w.max_bar,
            max_cage_land_force_n: w.max_land,
            max_inner_sliding_speed_m_s: w.max_vs,
            max_relative_slip: w.max_srr,
            scuffing_margin: margin,
            whirl_ratio: whirl,
            precession: self.settings.is_precession(whirl),
            cage_orbit_radius_m: w.orbit_radius_rms(),
            friction_power_mean_w: w.mean_power(),
            max_roller_end_rib_force_n: w.max_rib,
            max_roller_end_cage_force_n: w.max_pocket,
            steady,
            max_inner_sliding_rolling_direction_m_s: w.sliding.rolling,
            max_inner_sliding_axial_m_s: w.sliding.axial,
            max_inner_sliding_rolling_direction_most_loaded_m_s: w.sliding.rolling_most_loaded,
            max_inner_sliding_axial_most_loaded_m_s: w.sliding.axial_most_loaded,
        };
        self.tr.prev_rev_speed = speed;
        if self.tr.run_started {
            self.tr.run.min_margin = self.tr.run.min_margin.min(margin);
        }
        if !self.tr.run_started
            && self.tr.revolutions >= u64::from(self.settings.discard_revolutions)
        {
            self.tr.run = Window::start(t, phi);
            self.tr.run_started = true;
        }
        self.tr.rev_angle0 = phi;
        self.tr.rev = Window::start(t, phi);
        sink.revolution(&summary);
    }

    fn emit_samples(&mut self, t_end: f64, sink: &mut dyn OutputSink) {
        let dt = self.settings.output_step_s;
        if dt <= 0.0 {
            return;
        }
        loop {
            let ts = self.tr.next_sample as f64 * dt;
            if ts > self.ig.t() || ts > t_end || ts < self.ig.dense_start() - 1e-15 {
                if ts < self.ig.dense_start() - 1e-15 {
                    // sample time before the available dense output (cannot happen in a
                    // continuous run); skip it
                    self.tr.next_sample += 1;
                    continue;
                }
                return;
            }
            if self.ig.has_dense() {
                self.ig.interpolate(ts, &mut self.scratch_y);
            } else {
                self.scratch_y.copy_from_slice(self.ig.y());
            }
            rhs(
                &self.model,
                ts,
                &self.scratch_y,
                &mut self.scratch_dy,
                &mut self.diag,
                Tables::Fill,
            );
            self.write_sample(ts, sink);
            self.tr.next_sample += 1;
        }
    }

    fn write_sample(&mut self, t: f64, sink: &mut dyn OutputSink) {
        let m = &self.model;
        let y = &self.scratch_y;
        let lay = m.layout;
        for j in 0..m.z {
            let b = lay.roller(j);
            let th = y[b + roller::AZIMUTH];
            let a = unit_or(read3(y, b + roller::AXIS), [0.0, 0.0, 1.0]);
            let (s, c) = th.sin_cos();
            let ar = a[0] * c + a[1] * s;
            let at = -a[0] * s + a[1] * c;
            let l = read3(y, b + roller::MOMENTUM);
            let w = axisymmetric_omega(l, a, m.ia_r, m.it_r);
            let sb = &mut self.snap;
            sb.azimuth[j] = th;
            sb.radius[j] = y[b + roller::RADIUS];
            sb.axial[j] = y[b + roller::AXIAL];
            sb.orbital[j] = y[b + roller::ORBITAL_SPEED];
            sb.spin[j] = dot(w, a);
            sb.yaw[j] = at.atan2(a[2]);
            sb.pitch[j] = ar.atan2(a[2]);
            let d = &self.diag;
            sb.srr_inner[j] = d.inner.sliding[j] / d.inner.rolling[j].max(1e-9);
            sb.srr_outer[j] = d.outer.sliding[j] / d.outer.rolling[j].max(1e-9);
            sb.rib_reduced_radius[j] = if d.rib[j] > 0.0 {
                m.ends.rib_reduced_radius
            } else {
                f64::NAN
            };
        }
        let ci = lay.cage();
        let ii = lay.inner();
        let wc = cage_speed(m, y);
        let d = &self.diag;
        let w0 = m.epicyclic(d.inner_speed, d.outer_speed);
        let sb = &self.snap;
        let snapshot = Snapshot {
            time_s: t,
            inner_ring_speed_rad_s: d.inner_speed,
            outer_ring_speed_rad_s: d.outer_speed,
            inner_ring_angle_rad: m.conditions.inner_speed.angle(t),
            outer_ring_angle_rad: m.conditions.outer_speed.angle(t),
            inner_ring_center_m: read3(y, ii + inner_ring::CENTRE),
            cage_center_m: read3(y, ci + cage::CENTRE),
            cage_angle_rad: y[ci + cage::ANGLE],
            cage_speed_rad_s: wc,
            epicyclic_cage_speed_rad_s: w0,
            cage_slip: rolldyn_geometry::cage_slip(wc, w0),
            cage_land_force_n: d.land_force,
            cage_land_power_w: d.land_power,
            rollers: RollerSnapshot {
                azimuth_rad: &sb.azimuth,
                radius_m: &sb.radius,
                axial_m: &sb.axial,
                orbital_speed_rad_s: &sb.orbital,
                spin_speed_rad_s: &sb.spin,
                yaw_rad: &sb.yaw,
                pitch_rad: &sb.pitch,
                inner: contact_snapshot(&d.inner, &sb.srr_inner),
                outer: contact_snapshot(&d.outer, &sb.srr_outer),
                cage_bar_force_n: &d.bar,
                cage_bar_power_w: &d.bar_power,
                cage_bar_sliding_speed_m_s: &d.bar_sliding,
                rib_force_n: &d.rib,
                rib_sliding_speed_m_s: &d.rib_sliding,
                rib_edge_distance_m: &d.rib_edge,
                rib_reduced_radius_m: &sb.rib_reduced_radius,
                rib_contact_radius_m: &d.rib_end_radius,
                rib_contact_ring_radius_m: &d.rib_ring_radius,
                rib_friction_coefficient: &d.rib_mu,
                rib_power_w: &d.rib_power,
                rib_regime: &d.rib_regime,
                pocket_face_force_n: &d.pocket,
                pocket_face_power_w: &d.pocket_power,
            },
            cage_loads: cage_loads(m, y, &self.scratch_dy, d),
        };
        sink.sample(t, &snapshot);
    }

    /// Evaluates the right-hand side `f(t, y)` at the current state into `dy` (benchmarks and
    /// diagnostics; `dy.len()` must equal the state length).
    pub fn evaluate_derivative(&mut self, dy: &mut [f64]) {
        if dy.len() == self.ig.y().len() {
            rhs(
                &self.model,
                self.ig.t(),
                self.ig.y(),
                dy,
                &mut self.diag,
                Tables::Fill,
            );
        }
    }

    /// Sends a sample of the current state to `sink` (outside the fixed output grid).
    pub fn sample_now(&mut self, sink: &mut dyn OutputSink) {
        let t = self.ig.t();
        self.scratch_y.copy_from_slice(self.ig.y());
        rhs(
            &self.model,
            t,
            &self.scratch_y,
            &mut self.scratch_dy,
            &mut self.diag,
            Tables::Fill,
        );
        self.write_sample(t, sink);
    }

    /// The run summary so far (window after the discarded start revolutions, or the whole run
    /// if fewer were completed).
    pub fn summary(&self) -> RunSummary {
        let w = &self.tr.run;
        let ci = self.model.layout.cage();
        let phi = self.ig.y()[ci + cage::ANGLE];
        let mut margin = w.min_margin;
        if !margin.is_finite() && self.tr.revolutions == 0 {
            margin = self.scuffing_margin(w);
        }
        let st = &self.ig.stats();
        let whirl = w.whirl(phi);
        RunSummary {
            cage_slip_mean: w.mean_slip(),
            cage_speed_mean_rad_s: w.mean_speed(),
            epicyclic_cage_speed_rad_s: self.epicyclic_cage_speed(),
            max_inner_contact_force_n: w.max_fi,
            max_outer_contact_force_n: w.max_fo,
            max_roller_cage_force_n: w.max_bar,
            max_cage_land_force_n: w.max_land,
            max_inner_sliding_speed_m_s: w.max_vs,
            max_relative_slip: w.max_srr,
            min_scuffing_margin: margin,
            whirl_ratio: whirl,
            precession: self.settings.is_precession(whirl),
            cage_orbit_radius_m: w.orbit_radius_rms(),
            simulated_time_s: self.ig.t(),
            wall_time_s: self.tr.wall,
            steps: st.accepted,
            rejected_steps: st.rejected,
            rhs_evaluations: st.rhs_evaluations,
            max_roller_end_rib_force_n: w.max_rib,
            max_roller_end_cage_force_n: w.max_pocket,
            max_inner_sliding_rolling_direction_m_s: w.sliding.rolling,
            max_inner_sliding_axial_m_s: w.sliding.axial,
            max_inner_sliding_rolling_direction_most_loaded_m_s: w.sliding.rolling_most_loaded,
            max_inner_sliding_axial_most_loaded_m_s: w.sliding.axial_most_loaded,
        }
    }

    /// Serialises the complete run state (state vector, integrator memory incl. the dense
    /// output of the last step, statistics, summary accumulators, output position) to bytes.
    pub fn checkpoint(&self) -> Vec<u8> {
        self.checkpoint_with(&[])
    }

    /// [`Simulation::checkpoint`] with a `note` of the caller's own (e.g. what it knows of its
    /// outputs at this point), given back by [`Simulation::restore`] and covered by the
    /// checksum.
    pub fn checkpoint_with(&self, note: &[u8]) -> Vec<u8> {
        let mut w = Writer::new();
        w.u64(self.fingerprint);
        self.ig.save(&mut w);
        let tr = &self.tr;
        w.u64(tr.revolutions);
        w.f64(tr.rev_angle0);
        tr.rev.save(&mut w);
        tr.run.save(&mut w);
        w.u64(u64::from(tr.run_started));
        w.f64(tr.prev_rev_speed);
        w.f64(tr.steady_at);
        w.u64(tr.next_sample);
        w.f64(self.settings.output_step_s);
        w.f64(tr.wall);
        w.bytes(note);
        w.seal()
    }

    /// Restores a checkpoint written by [`Simulation::checkpoint`] of a simulation built from
    /// the same inputs; the run then continues bit-for-bit. A damaged checkpoint (checksum),
    /// one of another format version or bearing, and one written with another non-zero output
    /// step (the samples would change their spacing) are refused. Returns the note of
    /// [`Simulation::checkpoint_with`] (empty for [`Simulation::checkpoint`]).
    pub fn restore(&mut self, bytes: &[u8]) -> Result<Vec<u8>, DynError> {
        let mut r = Reader::open(bytes)?;
        if r.u64()? != self.fingerprint {
            return Err(DynError::Checkpoint(
                "the checkpoint belongs to a different set-up (bearing model, operating conditions, contact or integrator settings)".into(),
            ));
        }
        let ig = self.ig.load(&mut r)?;
        let mut tr = self.tr;
        tr.revolutions = r.u64()?;
        tr.rev_angle0 = r.f64()?;
        tr.rev = Window::load(&mut r)?;
        tr.run = Window::load(&mut r)?;
        tr.run_started = r.u64()? != 0;
        tr.prev_rev_speed = r.f64()?;
        tr.steady_at = r.f64()?;
        tr.next_sample = r.u64()?;
        let output_step = r.f64()?;
        tr.wall = r.f64()?;
        let note = r.bytes()?;
        if !r.at_end() {
            return Err(DynError::Checkpoint("trailing data".into()));
        }
        let step = self.settings.output_step_s;
        if output_step != step {
            if output_step > 0.0 && step > 0.0 {
                return Err(DynError::Checkpoint(format!(
                    "written with an output step of {output_step:e} s, this run has {step:e} s"
                )));
            }
            // samples start (again) at the first output time of the resumed run
            tr.next_sample = 0;
        }
        self.ig = ig;
        self.tr = tr;
        Ok(note)
    }
}
/// The cage's contact forces and rigid-body motion at the state `y` with derivative `dy`
/// (the cage-load export, SPEC §7.2): `v̇` from `dy`, `ω` from `L`, and `α = I⁻¹(L̇ − ω × L)`
/// (Euler's equation of the axisymmetric body in the inertial frame).
fn cage_loads<'a>(m: &Model, y: &[f64], dy: &[f64], d: &'a Diagnostics) -> CageLoads<'a> {
    let ci = m.layout.cage();
    let axis = unit_or(read3(y, ci + cage::AXIS), [0.0, 0.0, 1.0]);
    let l = read3(y, ci + cage::MOMENTUM);
    let omega = axisymmetric_omega(l, axis, m.ia_c, m.it_c);
    let l_dot = read3(dy, ci + cage::MOMENTUM);
    let alpha = axisymmetric_omega(sub(l_dot, cross(omega, l)), axis, m.ia_c, m.it_c);
    CageLoads {
        axis,
        acceleration_m_s2: read3(dy, ci + cage::VELOCITY),
        angular_velocity_rad_s: omega,
        angular_acceleration_rad_s2: alpha,
        pockets: &d.pocket_loads,
        land: d.land_loads,
    }
}

fn contact_snapshot<'a>(t: &'a crate::rhs::ContactTable, srr: &'a [f64]) -> ContactSnapshot<'a> {
    ContactSnapshot {
        force_n: &t.force,
        sliding_speed_m_s: &t.sliding,
        rolling_speed_m_s: &t.rolling,
        slide_to_roll: srr,
        film_thickness_m: &t.film,
        lambda: &t.lambda,
        traction_coefficient: &t.mu,
        friction_power_w: &t.power,
        slice_force_n: &t.slice_force,
    }
}

fn cage_speed(model: &Model, y: &[f64]) -> f64 {
    let ci = model.layout.cage();
    let a = unit_or(read3(y, ci + cage::AXIS), [0.0, 0.0, 1.0]);
    let l = read3(y, ci + cage::MOMENTUM);
    dot(axisymmetric_omega(l, a, model.ia_c, model.it_c), a)
}

fn static_solution(model: &Model) -> Result<StaticSolution, DynError> {
    let c = &model.conditions;
    let wc = model.epicyclic(c.inner_speed.speed(0.0), c.outer_speed.speed(0.0));
    let az: Vec<f64> = (0..model.z)
        .map(|j| TAU * j as f64 / model.z as f64)
        .collect();
    let f = c.inner_ring_force(0.0);
    let g = c.gravity_m_s2;
    let force = [f[0] + model.m_i * g[0], f[1] + model.m_i * g[1], 0.0];
    static_equilibrium(model, &az, wc, force, c.support.radial_free)
}

fn default_initial_state(model: &Model) -> Result<InitialState, DynError> {
    let c = &model.conditions;
    let wo = c.outer_speed.speed(0.0);
    let wc = model.epicyclic(c.inner_speed.speed(0.0), wo);
    let st = static_solution(model)?;
    let e = st.ring_displacement_m;
    let a = model.axis_i;
    // With a misaligned inner ring the roller starts on the ring's mid-plane (between its ribs):
    // the plane through the ring centre normal to its axis, z = z_c − ((x−x_c)a_x + (y−y_c)a_y)/a_z.
    let mid_plane_z = |r: f64, psi: f64| {
        e[2] - ((r * psi.cos() - e[0]) * a[0] + (r * psi.sin() - e[1]) * a[1]) / a[2]
    };
    let rollers = st
        .rollers
        .iter()
        .map(|r| RollerStart {
            azimuth_rad: r.azimuth_rad,
            radius_m: r.radius_m,
            axial_m: mid_plane_z(r.radius_m, r.azimuth_rad),
            orbital_speed_rad_s: wc,
            spin_speed_rad_s: pure_rolling_spin(wc, wo, r.radius_m, model.rw),
            yaw_rad: 0.0,
            pitch_rad: 0.0,
        })
        .collect();
    let cage_center = match model.land {
        Some(l) if l.inner => e,
        _ => [0.0; 3],
    };
    Ok(InitialState {
        rollers,
        cage_angle_rad: 0.0,
        cage_speed_rad_s: wc,
        cage_center_m: cage_center,
        inner_ring_center_m: e,
    })
}

fn pack_state(model: &Model, init: &InitialState) -> Result<Vec<f64>, DynError> {
    let lay = model.layout;
    let mut y = vec![0.0; lay.len()];
    for (j, r) in init.rollers.iter().enumerate() {
        let vals = [
            r.azimuth_rad,
            r.radius_m,
            r.axial_m,
            r.orbital_speed_rad_s,
            r.spin_speed_rad_s,
            r.yaw_rad,
            r.pitch_rad,
        ];
        if !vals.iter().all(|v| v.is_finite()) || r.radius_m <= 0.0 {
            return Err(DynError::InvalidInput(format!(
                "initial state of roller {j} is not finite or has a non-positive radius"
            )));
        }
        let b = lay.roller(j);
        let (s, c) = r.azimuth_rad.sin_cos();
        let er = [c, s, 0.0];
        let et = [-s, c, 0.0];
        let a = unit_or(
            [
                r.pitch_rad.tan() * er[0] + r.yaw_rad.tan() * et[0],
                r.pitch_rad.tan() * er[1] + r.yaw_rad.tan() * et[1],
                1.0,
            ],
            [0.0, 0.0, 1.0],
        );
        y[b + roller::AZIMUTH] = r.azimuth_rad;
        y[b + roller::RADIUS] = r.radius_m;
        y[b + roller::AXIAL] = r.axial_m;
        write3(&mut y, b + roller::AXIS, a);
        y[b + roller::ORBITAL_SPEED] = r.orbital_speed_rad_s;
        // angular velocity: spin about the axis (transverse part zero)
        let l: V3 = [
            model.ia_r * r.spin_speed_rad_s * a[0],
            model.ia_r * r.spin_speed_rad_s * a[1],
            model.ia_r * r.spin_speed_rad_s * a[2],
        ];
        write3(&mut y, b + roller::MOMENTUM, l);
    }
    let ci = lay.cage();
    write3(&mut y, ci + cage::CENTRE, init.cage_center_m);
    y[ci + cage::ANGLE] = init.cage_angle_rad;
    // A cage centred on an inner-ring land starts aligned with that (possibly misaligned) ring,
    // so that its pockets hold the rollers on the ring's mid-plane.
    let cage_axis = match model.land {
        Some(l) if l.inner => model.axis_i,
        _ => [0.0, 0.0, 1.0],
    };
    write3(&mut y, ci + cage::AXIS, cage_axis);
    for k in 0..3 {
        y[ci + cage::MOMENTUM + k] = model.ia_c * init.cage_speed_rad_s * cage_axis[k];
    }
    let ii = lay.inner();
    write3(&mut y, ii + inner_ring::CENTRE, init.inner_ring_center_m);
    if !y.iter().all(|v| v.is_finite()) {
        return Err(DynError::InvalidInput("initial state is not finite".into()));
    }
    Ok(y)
}

/// Roller–raceway contact frequency `ω_c = √((k_i + k_o)/m_r)` of 2002834-type models,
/// [`contact_frequency`] of the inner and outer line contacts, rad/s.
pub(crate) fn roller_contact_frequency(model: &Model, reference_load_n: f64) -> f64 {
    contact_frequency(
        [
            (&model.inner.k, model.inner.n),
            (&model.outer.k, model.outer.n),
        ],
        model.m_r,
        reference_load_n,
    )
}

/// Contact frequency `ω_c = √((k_1 + k_2)/m_r)` of a roller of mass `m_r` between two line
/// contacts, rad/s: each line contact's slice law `Q_s = k_s δⁿ` (`(k_s per slice, n)`)
/// linearised as `k = n Q/δ` with all slices at one approach δ, at the reference load `Q`
/// ([`IntegratorSettings::contact_frequency_load_n`]).
pub(crate) fn contact_frequency(lines: [(&[f64], f64); 2], roller_mass: f64, load_n: f64) -> f64 {
    let stiffness = |(k, n): (&[f64], f64)| {
        let k_sum: f64 = k.iter().sum();
        let delta = (load_n / k_sum).powf(1.0 / n);
        n * load_n / delta
    };
    let [a, b] = lines;
    ((stiffness(a) + stiffness(b)) / roller_mass).sqrt()
}

/// Error scales `(roller radial and axial velocity, roller transverse angular momentum)` of
/// [`IntegratorSettings::velocity_scale`] (crate docs, "Error control"): `v_ref` and the spin
/// momentum `I_a v_ref/r`, or with [`VelocityErrorScale::ContactFrequency`] the
/// energy-consistent `ω_c·s_x` and `I_t ω_c·s_x/(L/2)` floored by them (`s_x` the 1 mm
/// length scale, `L/2` the roller's half-length, `ω_c` from `contact_frequency`).
pub(crate) fn roller_velocity_scales(
    set: &IntegratorSettings,
    v_ref: f64,
    spin_momentum: f64,
    transverse_inertia: f64,
    half_length: f64,
    contact_frequency: impl FnOnce() -> f64,
) -> (f64, f64) {
    match set.velocity_scale {
        VelocityErrorScale::SurfaceSpeed => (v_ref, spin_momentum),
        VelocityErrorScale::ContactFrequency => {
            let w_c = contact_frequency();
            (
                v_ref.max(w_c * ERROR_LENGTH_SCALE_M),
                spin_momentum.max(transverse_inertia * w_c * ERROR_LENGTH_SCALE_M / half_length),
            )
        }
    }
}

/// Length scale `s_x` of the error test (crate docs, "Error control"): 1 nm at τ = 10⁻⁶, m.
pub(crate) const ERROR_LENGTH_SCALE_M: f64 = 1e-3;

/// The stepper of `set.method` at `(t, y)` with the error scales of [`error_scales`].
fn new_stepper(
    model: &Model,
    set: &IntegratorSettings,
    t: f64,
    y: Vec<f64>,
    scale: Vec<f64>,
    relative: Vec<f64>,
) -> Stepper {
    let lay = model.layout;
    match set.method {
        IntegratorMethod::Dopri5 => {
            Stepper::Dopri5(Dopri5::new(t, y, scale, relative, set.initial_step_s))
        }
        IntegratorMethod::RosenbrockW => {
            // one block per body; rollers form one colour group (a roller's derivative
            // depends on no other roller's state), cage and inner ring one group each
            let rollers = (0..model.z)
                .map(|j| JacobianBlock {
                    start: lay.roller(j),
                    n: ROLLER_DOF,
                })
                .collect();
            let groups = [
                rollers,
                vec![JacobianBlock {
                    start: lay.cage(),
                    n: CAGE_DOF,
                }],
                vec![JacobianBlock {
                    start: lay.inner(),
                    n: INNER_DOF,
                }],
            ];
            Stepper::RosenbrockW(RosenbrockW::new(
                t,
                y,
                scale,
                relative,
                set.initial_step_s,
                &groups,
            ))
        }
    }
}

/// Characteristic scales of the state components (crate docs, "Error control").
fn error_scales(model: &Model, set: &IntegratorSettings) -> (Vec<f64>, Vec<f64>) {
    let lay = model.layout;
    let c = &model.conditions;
    let v_ref = (c.inner_speed.speed(0.0).abs() * model.ri)
        .max(c.outer_speed.speed(0.0).abs() * model.ro)
        .max(1.0);
    let len = ERROR_LENGTH_SCALE_M;
    let half_l = model
        .slice_x
        .iter()
        .fold(0.0_f64, |a, &x| a.max(x.abs()))
        .max(1e-3);
    let spin_momentum = model.ia_r * v_ref / model.rw;
    let (v_roller, l_transverse) =
        roller_velocity_scales(set, v_ref, spin_momentum, model.it_r, half_l, || {
            roller_contact_frequency(model, set.contact_frequency_load_n)
        });
    let mut s = vec![0.0; lay.len()];
    let mut rel = vec![0.0; lay.len()];
    for j in 0..model.z {
        let b = lay.roller(j);
        // (offset, scale, relative weight) of every component
        let vals = [
            (roller::AZIMUTH, len / model.rm, 0.0),
            (roller::RADIUS, len, 0.0),
            (roller::AXIAL, len, 0.0),
            (roller::AXIS, len / half_l, 0.0),
            (roller::AXIS + 1, len / half_l, 0.0),
            (roller::AXIS + 2, len / half_l, 0.0),
            (roller::ORBITAL_SPEED, v_ref / model.rm, 1.0),
            (roller::RADIAL_VELOCITY, v_roller, 1.0),
            (roller::AXIAL_VELOCITY, v_roller, 1.0),
            (roller::MOMENTUM, l_transverse, 1.0),
            (roller::MOMENTUM + 1, l_transverse, 1.0),
            (roller::MOMENTUM + 2, spin_momentum, 1.0),
        ];
        for (k, sc, r) in vals {
            s[b + k] = sc;
            rel[b + k] = r;
        }
    }
    let ci = lay.cage();
    let cw = model
        .land
        .map(|l| l.width)
        .unwrap_or(2.0 * half_l)
        .max(1e-3);
    let lc = model.ia_c * v_ref / model.rm;
    let vals = [
        (cage::CENTRE, len, 0.0),
        (cage::CENTRE + 1, len, 0.0),
        (cage::CENTRE + 2, len, 0.0),
        (cage::ANGLE, len / model.rm, 0.0),
        (cage::AXIS, len / cw, 0.0),
        (cage::AXIS + 1, len / cw, 0.0),
        (cage::AXIS + 2, len / cw, 0.0),
        (cage::VELOCITY, v_ref, 1.0),
        (cage::VELOCITY + 1, v_ref, 1.0),
        (cage::VELOCITY + 2, v_ref, 1.0),
        (cage::MOMENTUM, lc, 1.0),
        (cage::MOMENTUM + 1, lc, 1.0),
        (cage::MOMENTUM + 2, lc, 1.0),
    ];
    for (k, sc, r) in vals {
        s[ci + k] = sc;
        rel[ci + k] = r;
    }
    let ii = lay.inner();
    for k in 0..3 {
        s[ii + inner_ring::CENTRE + k] = len;
        s[ii + inner_ring::VELOCITY + k] = v_ref;
        rel[ii + inner_ring::VELOCITY + k] = 1.0;
    }
    (s, rel)
}

/// Fingerprint of everything that defines the dynamics of a run — the model (bearing,
/// contacts, traction, operating conditions, cage land) and the settings except the output step
/// and the integrator method (both checked apart) — so that a checkpoint is not resumed into
/// another set-up. FNV-1a of their exact `Debug` text (floats print as round-trip values).
fn fingerprint(model: &Model, settings: &DynamicsSettings) -> u64 {
    let mut settings = *settings;
    settings.output_step_s = 0.0;
    settings.integrator.method = IntegratorMethod::Dopri5;
    fnv1a(format!("{model:?}{settings:?}").as_bytes())
}

/// Total mechanical energy (see [`Simulation::mechanical_energy`]).
fn energy(model: &Model, t: f64, y: &[f64]) -> f64 {
    use crate::vec3::{axpy, norm, perp, sub};
    let lay = model.layout;
    let cond = &model.conditions;
    let g = cond.gravity_m_s2;
    let mut e = 0.0;
    let ii = lay.inner();
    let oi = read3(y, ii + inner_ring::CENTRE);
    let vi = read3(y, ii + inner_ring::VELOCITY);
    e += 0.5 * model.m_i * dot(vi, vi) - model.m_i * dot(g, oi);
    // fixed loads only (rotating loads are not conservative)
    for l in &cond.loads {
        if let crate::conditions::InnerRingLoad::Fixed { force_n } = l {
            e -= dot(*force_n, oi);
        }
    }
    let _ = t;
    let ci = lay.cage();
    let cc = read3(y, ci + cage::CENTRE);
    let ac = unit_or(read3(y, ci + cage::AXIS), [0.0, 0.0, 1.0]);
    let vc = read3(y, ci + cage::VELOCITY);
    let lc = read3(y, ci + cage::MOMENTUM);
    let wc = axisymmetric_omega(lc, ac, model.ia_c, model.it_c);
    e += 0.5 * model.m_c * dot(vc, vc) + 0.5 * dot(wc, lc) - model.m_c * dot(g, cc);
    let bar = &model.params.roller_cage;
    let pitch = TAU / model.z as f64;
    for j in 0..model.z {
        let b = lay.roller(j);
        let (th, r, z) = (
            y[b + roller::AZIMUTH],
            y[b + roller::RADIUS],
            y[b + roller::AXIAL],
        );
        let a = unit_or(read3(y, b + roller::AXIS), [0.0, 0.0, 1.0]);
        let (thd, rd, zd) = (
            y[b + roller::ORBITAL_SPEED],
            y[b + roller::RADIAL_VELOCITY],
            y[b + roller::AXIAL_VELOCITY],
        );
        let l = read3(y, b + roller::MOMENTUM);
        let w = axisymmetric_omega(l, a, model.ia_r, model.it_r);
        let (s, c) = th.sin_cos();
        let centre = [r * c, r * s, z];
        let v2 = rd * rd + r * r * thd * thd + zd * zd;
        e += 0.5 * model.m_r * v2 + 0.5 * dot(w, l) - model.m_r * dot(g, centre);
        for sl in 0..model.slice_x.len() {
            let p = axpy(centre, model.slice_x[sl], a);
            let d = sub(p, oi);
            let dp = perp(d, model.axis_i);
            let di = model.ri + model.rw - norm(dp) - model.slice_drop[sl];
            if di > 0.0 {
                e += model.inner.k[sl] * di.powf(model.inner.n + 1.0) / (model.inner.n + 1.0);
            }
            let dout =
                (p[0] * p[0] + p[1] * p[1]).sqrt() + model.rw - model.ro - model.slice_drop[sl];
            if dout > 0.0 {
                e += model.outer.k[sl] * dout.powf(model.outer.n + 1.0) / (model.outer.n + 1.0);
            }
        }
        let php = y[ci + cage::ANGLE] + pitch * j as f64;
        let (sp, cp) = php.sin_cos();
        let ep = unit_or(perp([cp, sp, 0.0], ac), [cp, sp, 0.0]);
        let tp = crate::vec3::cross(ac, ep);
        for side in [-1.0, 1.0] {
            for (sl, &x) in model.slice_x.iter().enumerate() {
                let q = axpy(centre, x, a);
                let radius = model.rw - model.slice_drop[sl];
                let (delta, _) = crate::rhs::wall_overlap(model, cc, (ep, tp), side, q, radius);
                if delta > 0.0 {
                    let share = model.slice_length[sl] / model.bar_law.reference_length();
                    e += share * bar.k_p * delta.powf(bar.exponent + 1.0) / (bar.exponent + 1.0);
                }
            }
        }
    }
    if let Some(land) = model.land {
        let p = &model.params.cage_land;
        let (o, axis) = if land.inner {
            (oi, model.axis_i)
        } else {
            ([0.0; 3], [0.0, 0.0, 1.0])
        };
        for zeta in [-0.25 * land.width, 0.25 * land.width] {
            let ecc = norm(perp(sub(axpy(cc, zeta, ac), axpy(o, zeta, axis)), axis));
            let delta = ecc - land.gap;
            if delta > 0.0 {
                e += 0.5 * p.k_p * delta.powf(p.exponent + 1.0) / (p.exponent + 1.0);
            }
        }
    }
    e
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::model::RacewayTraction;
    use crate::output::NullSink;

    fn model_2002834() -> Model {
        let b = rolldyn_model::default_cylindrical_bearing();
        let cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 500.0);
        Model::new(
            &b,
            cond,
            ContactParameters::for_bearing(&b),
            RacewayTraction::same(
                rolldyn_lubrication::TractionModel::muraki(
                    rolldyn_lubrication::lubricant_by_name("pao1-vg320").expect("built-in oil"),
                )
                .expect("valid oil"),
            ),
        )
        .expect("valid model")
    }

    /// The model's pair-34 law on a slice (`share` of the bar contact length) is the seed law
    /// `share·K_p δⁿ + STEP(δ,0,0,d,share·C_h)·δ̇` (to round-off: the share passes through a
    /// length); with a film it adds the film force above touch.
    #[test]
    fn bar_law_at_a_bar_point_is_the_seed_law() {
        use rolldyn_contact::bar_force::{BarFilm, BarFilmSettings};
        use rolldyn_contact::damping::SliceDamping;
        let m = model_2002834();
        let p = m.params.roller_cage;
        let length = m.slice_length[0];
        let share = length / m.bar_law.reference_length();
        let damping = SliceDamping::new(share * p.c_h, p.d);
        for (delta, rate) in [(1e-7_f64, 0.1), (5e-7, -0.02), (2e-6, 0.0)] {
            let seed = damping.normal_force(share * p.k_p * delta.powf(p.exponent), delta, rate);
            let law = m.bar_law.normal_force(-delta, -rate, 20.0, length);
            assert!((law / seed - 1.0).abs() < 1e-14, "{law} vs {seed}");
        }
        assert_eq!(m.bar_law.reach(), 0.0);
        let b = rolldyn_model::default_cylindrical_bearing();
        assert_eq!(m.bar_law.reference_length(), b.roller.bar_contact_length());
        let mut params = ContactParameters::for_bearing(&b);
        params.roller_cage_film = BarFilm::of_bearing(&b, 3e-3, &BarFilmSettings::default());
        let law = params.roller_cage_law(b.roller.bar_contact_length());
        assert!(law.reach() > 0.0);
        assert!(law.normal_force(5e-6, 0.0, 20.0, length) > 0.0);
    }

    /// Every roller of 2002834 yawed by 2 mrad under 2 kN at 6371 rpm: on the loaded inner
    /// contacts the sliding gets an axial component of about u·sin(yaw) (the raceway surface
    /// crossing the skewed roller), the two components add up in squares to the sliding speed
    /// (uniform along a yawed roller), and the step values report the split of the most loaded
    /// roller and the maxima; a short run carries them into the summary.
    #[test]
    fn a_yawed_roller_slides_axially_and_the_split_adds_up() {
        let b = rolldyn_model::default_cylindrical_bearing();
        let cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 2000.0);
        let params = ContactParameters::for_bearing(&b);
        let traction = model_2002834().traction;
        let yaw = 2e-3;
        let mut init =
            Simulation::default_initial_state(&b, cond.clone(), params, traction.clone()).unwrap();
        for r in &mut init.rollers {
            r.yaw_rad = yaw;
        }
        let settings = DynamicsSettings::default();
        let mut sim =
            Simulation::with_initial_state(&b, cond, params, settings, traction, &init).unwrap();
        let mut dy = vec![0.0; sim.state().len()];
        sim.evaluate_derivative(&mut dy);
        let t = &sim.diag.inner;
        let loaded: Vec<usize> = (0..t.force.len()).filter(|&j| t.force[j] > 0.0).collect();
        assert!(!loaded.is_empty());
        for &j in &loaded {
            let (roll, axial, v) = (t.sliding_rolling[j], t.sliding_axial[j], t.sliding[j]);
            let expected = t.rolling[j] * yaw.sin();
            assert!(
                (axial.abs() - expected).abs() < 0.1 * expected,
                "{j}: {axial} vs {expected}"
            );
            assert!(
                (roll.hypot(axial) - v).abs() < 1e-3 * v,
                "{j}: {roll}, {axial}, {v}"
            );
        }
        let most = loaded
            .iter()
            .copied()
            .max_by(|&a, &b| t.force[a].total_cmp(&t.force[b]));
        let most = most.unwrap();
        let v = sim.step_values();
        assert_eq!(v.sliding.axial_most_loaded, t.sliding_axial[most].abs());
        assert!(v.sliding.axial >= v.sliding.axial_most_loaded);
        let summary = sim.run_until(2e-5, &mut NullSink, &mut |_| {}).unwrap();
        assert!(summary.max_inner_sliding_axial_m_s > 0.0, "{summary:?}");
        assert!(
            summary.max_inner_sliding_axial_m_s >= summary.max_inner_sliding_axial_most_loaded_m_s
        );
        assert!(
            summary.max_inner_sliding_rolling_direction_m_s
                >= summary.max_inner_sliding_rolling_direction_most_loaded_m_s
        );
    }

    /// ω_c of 2002834 against a hand estimate: seed 000 (2.3)/(2.4) line contacts at 100 N
    /// are ≈ 5·10⁸ N/m each, the roller 0.015–0.02 kg → √(10⁹/0.0175) ≈ 2.4·10⁵ rad/s.
    #[test]
    fn contact_frequency_of_2002834_is_of_the_hand_estimate() {
        let load = IntegratorSettings::default().contact_frequency_load_n;
        let w = roller_contact_frequency(&model_2002834(), load);
        assert!((1.5e5..4.0e5).contains(&w), "{w}");
    }

    /// Error scales `(SurfaceSpeed, ContactFrequency)` of a model's `error_scales`.
    pub(crate) fn scales_of_both_velocity_scales(
        error_scales: impl Fn(&IntegratorSettings) -> Vec<f64>,
    ) -> (Vec<f64>, Vec<f64>) {
        let with = |velocity_scale| IntegratorSettings {
            velocity_scale,
            ..IntegratorSettings::default()
        };
        (
            error_scales(&with(VelocityErrorScale::SurfaceSpeed)),
            error_scales(&with(VelocityErrorScale::ContactFrequency)),
        )
    }

    /// The energy-consistent scales loosen only the roller's radial/axial velocities and
    /// transverse momenta, by ω_c·1 mm / v_ref, and never tighten anything.
    #[test]
    fn contact_frequency_scales_loosen_only_roller_contact_velocities() {
        let model = model_2002834();
        let (old, new) = scales_of_both_velocity_scales(|set| error_scales(&model, set).0);
        for (i, (a, b)) in old.iter().zip(&new).enumerate() {
            assert!(b >= a, "component {i}");
        }
        let b = model.layout.roller(0);
        let transverse = [
            roller::RADIAL_VELOCITY,
            roller::AXIAL_VELOCITY,
            roller::MOMENTUM,
            roller::MOMENTUM + 1,
        ];
        for k in transverse {
            assert!(new[b + k] > 3.0 * old[b + k], "roller component {k}");
        }
        for k in (0..ROLLER_DOF).filter(|k| !transverse.contains(k)) {
            assert_eq!(new[b + k], old[b + k], "roller component {k}");
        }
        let c = model.layout.cage();
        assert_eq!(new[c..], old[c..]);
    }
}
