//! Running the tapered model: the seated start, the integration with samples at a fixed
//! interval, and the run's summary (seed 000 §3.2.1 observables).

use super::columns::{SAMPLE_COLUMNS, sample_from_row, sample_row};
use super::contacts::ContactRecorder;
use super::layout::TaperedLayout;
use super::model::TaperedModel;
use super::rhs::{RollerReport, TaperedSystem};
use super::sample::TaperedSample;
use super::summary::{TaperedSummary, summarise};
use crate::checkpoint::{Reader, Writer, fnv1a};
use crate::error::DynError;
use crate::integrator::{Dopri5, StepError};
use crate::layout::{CAGE_DOF, INNER_DOF, ROLLER_DOF, cage, inner_ring, read3, roller, write3};
use crate::rhs::axisymmetric_omega;
use crate::rosenbrock::{JacobianBlock, JacobianBorder, RosenbrockW};
use crate::settings::IntegratorMethod;
use crate::settings::IntegratorSettings;
use crate::simulation::{ERROR_LENGTH_SCALE_M, contact_frequency, roller_velocity_scales};
use crate::stepper::Stepper;
use crate::vec3::{add, axpy, dot, scale};
use std::ops::ControlFlow;

/// Settings of a tapered run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedRunSettings {
    /// simulated time, s
    pub duration_s: f64,
    /// interval of the recorded samples, s (default 50 µs: 20 kHz, far above the roller-pass
    /// frequencies of ≈ 100–150 Hz and their harmonics)
    pub sample_interval_s: f64,
    /// initial angular offset of row 1's rollers and cage against row 0's, as a fraction of
    /// the pocket pitch (default 0: "at the initial moment the windows of the cages were
    /// opposite each other", seed 000 §3.2.1)
    pub row1_offset_pitch: f64,
    /// start of the window the summary is taken over, s (default `None`: the last 60 % of the
    /// run, [`super::summary::steady_window`])
    pub steady_from_s: Option<f64>,
    /// the integrator: the Rosenbrock-W method (a block per roller) at τ = 10⁻⁵. Measured on
    /// `examples/tapered-cassette.toml` (VG 220 base oil at 60 °C, case 1, from the seated
    /// start, 2026-11-28): 47 451 steps and 39 s wall for 30 ms against 252 258 steps and 177 s
    /// for 20 ms with Dormand–Prince 5(4) — the mineral oil's steep traction at small slip makes
    /// the rollers' spin stiff, and the explicit method is held to ≈ 80 ns steps by stability
    /// (on the PAO1 oil, whose traction rises more gently, Dormand–Prince needs fewer steps:
    /// 2 855 against ≈ 11 000 for 5 ms).
    pub integrator: IntegratorSettings,
}

impl Default for TaperedRunSettings {
    fn default() -> Self {
        Self {
            duration_s: 0.2,
            sample_interval_s: 5e-5,
            row1_offset_pitch: 0.0,
            steady_from_s: None,
            integrator: IntegratorSettings {
                tolerance: 1e-5,
                method: IntegratorMethod::RosenbrockW,
                ..IntegratorSettings::default()
            },
        }
    }
}

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedRun {
    pub samples: Vec<TaperedSample>,
    pub summary: TaperedSummary,
    /// accepted and rejected steps, right-hand-side evaluations
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evaluations: u64,
    /// the state component that limited the step most often
    pub most_limiting: Option<String>,
}

/// The seated start: rollers on the cone and the large rib at their pocket azimuths, cages and
/// rollers at the epicyclic speeds (pure rolling; the apex condition makes it pure along the
/// whole line), the inner ring at the origin; row 1 turned by `row1_offset_pitch` pitches.
pub fn initial_state(model: &TaperedModel, row1_offset_pitch: f64) -> Vec<f64> {
    let pitch = std::f64::consts::TAU / model.z as f64;
    let lay = TaperedLayout { z: model.z };
    let mut y = vec![0.0; lay.len()];
    let w_i = model.conditions.inner_speed.speed(0.0);
    let w_c = model.epicyclic_cage_speed;
    // pure rolling on the cone: the roller's spin relative to the cage carries its surface at
    // the contact (distance ℓ cos β sin β from its axis) with the cone (ℓ cos β sin α_i from the
    // bearing axis)
    let spin_ratio = model.cone_angle.sin() / model.half_angle.sin();
    for j in 0..2 * model.z {
        let geo = &model.rows[j / model.z];
        let offset = if j < model.z { 0.0 } else { row1_offset_pitch };
        let psi = pitch * ((j % model.z) as f64 + offset);
        let b = lay.roller(j);
        let (rho, z) = (
            geo.mid.0 + model.x_cm * geo.u.0,
            geo.mid.1 + model.x_cm * geo.u.1,
        );
        let e_rho = [psi.cos(), psi.sin(), 0.0];
        let u = add(scale(e_rho, geo.u.0), [0.0, 0.0, geo.u.1]);
        let spin = -geo.sigma * (w_i - w_c) * spin_ratio;
        let omega = axpy([0.0, 0.0, w_c], spin, u);
        let momentum = add(
            scale(omega, model.it_r),
            scale(u, (model.ia_r - model.it_r) * dot(u, omega)),
        );
        y[b + roller::AZIMUTH] = psi;
        y[b + roller::RADIUS] = rho;
        y[b + roller::AXIAL] = z;
        write3(&mut y, b + roller::AXIS, scale(u, geo.sigma));
        y[b + roller::ORBITAL_SPEED] = w_c;
        write3(&mut y, b + roller::MOMENTUM, momentum);
    }
    for k in 0..2 {
        let ci = lay.cage(k);
        write3(&mut y, ci + cage::CENTRE, [0.0, 0.0, model.rows[k].mid.1]);
        y[ci + cage::ANGLE] = if k == 0 {
            0.0
        } else {
            row1_offset_pitch * pitch
        };
        write3(&mut y, ci + cage::AXIS, [0.0, 0.0, 1.0]);
        write3(&mut y, ci + cage::MOMENTUM, [0.0, 0.0, model.ia_c * w_c]);
    }
    y
}

/// Error scales of the state (crate docs, "Error control"): lengths 1 mm, velocities the
/// rolling speed; the rollers' radial and axial velocities and transverse angular momenta by
/// `set.velocity_scale` ([`roller_velocity_scales`], `ω_c` of the cone and cup line contacts).
fn error_scales(model: &TaperedModel, set: &IntegratorSettings) -> (Vec<f64>, Vec<f64>) {
    let lay = TaperedLayout { z: model.z };
    let r_m = 0.5 * model.bearing.pitch_diameter;
    let v_ref = (model.conditions.inner_speed.speed(0.0).abs() * r_m).max(1.0);
    let len = ERROR_LENGTH_SCALE_M;
    let half_l = 0.5 * model.bearing.roller.length;
    let rw = 0.5 * model.bearing.roller.mean_diameter;
    let spin = model.ia_r * v_ref / rw;
    let (v_roller, l_transverse) =
        roller_velocity_scales(set, v_ref, spin, model.it_r, half_l, || {
            let [cone, cup] = &model.slices.k;
            let lines = [
                (&cone[..], model.slices.n[0]),
                (&cup[..], model.slices.n[1]),
            ];
            contact_frequency(lines, model.m_r, set.contact_frequency_load_n)
        });
    let (mut s, mut rel) = (vec![len; lay.len()], vec![0.0; lay.len()]);
    for j in 0..2 * model.z {
        let b = lay.roller(j);
        let vals = [
            (roller::AZIMUTH, len / r_m, 0.0),
            (roller::AXIS, len / half_l, 0.0),
            (roller::AXIS + 1, len / half_l, 0.0),
            (roller::AXIS + 2, len / half_l, 0.0),
            (roller::ORBITAL_SPEED, v_ref / r_m, 1.0),
            (roller::RADIAL_VELOCITY, v_roller, 1.0),
            (roller::AXIAL_VELOCITY, v_roller, 1.0),
            // global x, y: transverse (plus the axis's small radial share of the spin, held by
            // the relative part); z: the spin about the nearly axial roller axis
            (roller::MOMENTUM, l_transverse, 1.0),
            (roller::MOMENTUM + 1, l_transverse, 1.0),
            (roller::MOMENTUM + 2, spin, 1.0),
        ];
        for (k, sc, r) in vals {
            s[b + k] = sc;
            rel[b + k] = r;
        }
    }
    let lc = model.ia_c * v_ref / r_m;
    for k in 0..2 {
        let ci = lay.cage(k);
        s[ci + cage::ANGLE] = len / r_m;
        for i in 0..3 {
            s[ci + cage::AXIS + i] = len / r_m;
            (s[ci + cage::VELOCITY + i], rel[ci + cage::VELOCITY + i]) = (v_ref, 1.0);
            (s[ci + cage::MOMENTUM + i], rel[ci + cage::MOMENTUM + i]) = (lc, 1.0);
        }
    }
    let ii = lay.inner();
    for i in 0..3 {
        (
            s[ii + inner_ring::VELOCITY + i],
            rel[ii + inner_ring::VELOCITY + i],
        ) = (v_ref, 1.0);
    }
    (s, rel)
}

/// Runs `model` for `settings.duration_s`, calling `progress(t)` after every sample.
pub fn run(
    model: &TaperedModel,
    settings: &TaperedRunSettings,
    mut progress: impl FnMut(f64),
) -> Result<TaperedRun, DynError> {
    run_recorded(model, settings, None, |t| {
        progress(t);
        ControlFlow::Continue(())
    })
}

/// [`run`], handing every sample with its contact record to `recorder` (the record is only
/// computed when a recorder is given); `progress(t)` may stop the run
/// ([`DynError::Interrupted`]).
pub fn run_recorded(
    model: &TaperedModel,
    settings: &TaperedRunSettings,
    recorder: Option<&mut dyn ContactRecorder>,
    mut progress: impl FnMut(f64) -> ControlFlow<()>,
) -> Result<TaperedRun, DynError> {
    let mut sim = TaperedSimulation::new(model, settings, recorder.is_some());
    sim.run_until(settings.duration_s, recorder, &mut progress)?;
    Ok(sim.finish())
}

/// A tapered run that can be taken in pieces, checkpointed and restored: a run split at any
/// sample, or restored from a [`TaperedSimulation::checkpoint_with`] of one, is the same run
/// bit for bit.
pub struct TaperedSimulation<'m> {
    model: &'m TaperedModel,
    settings: TaperedRunSettings,
    dp: Stepper,
    sys: TaperedSystem<'m>,
    samples: Vec<TaperedSample>,
    /// the time of the next sample, s
    next: f64,
    fingerprint: u64,
}

impl<'m> TaperedSimulation<'m> {
    /// The run of `model` from the seated start; `record_contacts` computes the contact record
    /// a [`ContactRecorder`] needs.
    pub fn new(
        model: &'m TaperedModel,
        settings: &TaperedRunSettings,
        record_contacts: bool,
    ) -> Self {
        let y0 = initial_state(model, settings.row1_offset_pitch);
        let (scale_v, rel) = error_scales(model, &settings.integrator);
        let mut sys = TaperedSystem::new(model);
        if record_contacts {
            sys.record_contacts();
        }
        // the length of the run is not part of its set-up: a resumed run may go further
        let setup = TaperedRunSettings {
            duration_s: 0.0,
            ..*settings
        };
        Self {
            model,
            settings: *settings,
            dp: stepper(model, y0, scale_v, rel, &settings.integrator),
            sys,
            samples: Vec::new(),
            next: 0.0,
            fingerprint: fnv1a(format!("tapered {model:?}{setup:?}").as_bytes()),
        }
    }

    /// The time of the last sample taken, s (`None` before the first).
    pub fn time(&self) -> Option<f64> {
        self.samples.last().map(|s| s.time_s)
    }

    /// Integrates and samples every `sample_interval_s` up to `t_end`, handing each sample
    /// with its contact record to `recorder`; `progress(t)` after every sample may stop the
    /// run ([`DynError::Interrupted`]).
    pub fn run_until(
        &mut self,
        t_end: f64,
        mut recorder: Option<&mut dyn ContactRecorder>,
        progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
    ) -> Result<(), DynError> {
        let (model, set) = (self.model, self.settings.integrator);
        let lay = self.sys.layout;
        let mut ybuf = vec![0.0; lay.len()];
        while self.next <= t_end {
            let next = self.next;
            let dp = &mut self.dp;
            while dp.t() < next {
                dp.step(&mut self.sys, &set)
                    .map_err(|e| step_error(e, dp.t(), &lay))?;
                if dp.stats().accepted >= set.max_steps {
                    return Err(DynError::StepBudgetExhausted {
                        time_s: dp.t(),
                        steps: dp.stats().accepted,
                    });
                }
            }
            if dp.stats().accepted == 0 {
                ybuf.copy_from_slice(dp.y());
                let mut dy = vec![0.0; lay.len()];
                crate::integrator::OdeSystem::rhs_reported(&mut self.sys, 0.0, &ybuf, &mut dy);
            } else {
                dp.interpolate(next, &mut ybuf);
            }
            let current = sample(model, &lay, next, &ybuf, &self.sys.rollers);
            if let (Some(r), Some(contacts)) = (recorder.as_deref_mut(), &self.sys.contacts) {
                r.record(&current, contacts);
            }
            self.samples.push(current);
            self.next += self.settings.sample_interval_s;
            if progress(next).is_break() {
                return Err(DynError::Interrupted { time_s: next });
            }
        }
        Ok(())
    }

    /// The run state (integrator, samples so far) with a `note` of the caller's own, given
    /// back by [`TaperedSimulation::restore`] and covered by the checksum.
    pub fn checkpoint_with(&self, note: &[u8]) -> Vec<u8> {
        let mut w = Writer::new();
        w.u64(self.fingerprint);
        self.dp.save(&mut w);
        w.f64(self.next);
        w.u64(self.samples.len() as u64);
        for s in &self.samples {
            for v in sample_row(s) {
                w.f64(v);
            }
        }
        w.bytes(note);
        w.seal()
    }

    /// Restores a checkpoint of a run of the same model and settings (its length aside) and
    /// returns its note; a damaged checkpoint or one of another run is refused.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<Vec<u8>, DynError> {
        let mut r = Reader::open(bytes)?;
        if r.u64()? != self.fingerprint {
            return Err(DynError::Checkpoint(
                "the checkpoint belongs to a different set-up (bearing model, operating conditions, sample interval or integrator settings)".into(),
            ));
        }
        let dp = self.dp.load(&mut r)?;
        let next = r.f64()?;
        let count =
            usize::try_from(r.u64()?).map_err(|_| DynError::Checkpoint("truncated data".into()))?;
        let mut samples = Vec::new();
        let mut row = [0.0; SAMPLE_COLUMNS.len()];
        for _ in 0..count {
            for v in row.iter_mut() {
                *v = r.f64()?;
            }
            samples.push(sample_from_row(&row));
        }
        let note = r.bytes()?;
        if !r.at_end() {
            return Err(DynError::Checkpoint("trailing data".into()));
        }
        (self.dp, self.next, self.samples) = (dp, next, samples);
        // the contact report of the last accepted step: its last evaluation, at the state
        if self.dp.stats().accepted > 0 {
            let (t, y) = (self.dp.t(), self.dp.y().to_vec());
            let mut dy = vec![0.0; y.len()];
            crate::integrator::OdeSystem::rhs_reported(&mut self.sys, t, &y, &mut dy);
        }
        Ok(note)
    }

    /// At the current state: the Rosenbrock-W Jacobian approximation evaluated afresh
    /// ([`RosenbrockW::jacobian_approximation`]) and its test oracle, the dense
    /// column-by-column difference Jacobian ([`RosenbrockW::dense_difference_jacobian`]), both
    /// dense and row-major; `None` for Dormand–Prince. For diagnostics and tests: the run
    /// continues with this Jacobian.
    pub fn jacobian_against_oracle(&mut self) -> Option<(Vec<f64>, Vec<f64>)> {
        match &mut self.dp {
            Stepper::RosenbrockW(ig) => {
                let a = ig.jacobian_approximation(&mut self.sys);
                Some((a, ig.dense_difference_jacobian(&mut self.sys)))
            }
            Stepper::Dopri5(_) => None,
        }
    }

    /// The run: its samples, summary and step statistics.
    pub fn finish(self) -> TaperedRun {
        let stats = self.dp.stats();
        let lay = self.sys.layout;
        TaperedRun {
            summary: summarise(self.model, &self.samples, self.settings.steady_from_s),
            steps: stats.accepted,
            rejected_steps: stats.rejected,
            rhs_evaluations: stats.rhs_evaluations,
            most_limiting: stats.most_limiting().map(|c| component_name(c, &lay)),
            samples: self.samples,
        }
    }
}

/// The integrator of `settings.method` at the start state; for Rosenbrock-W the Jacobian
/// blocks are the rollers (one colour group: no roller's rates depend on another roller), the
/// two cages (one group) and the inner ring, and with [`IntegratorSettings::bordered_jacobian`]
/// each roller's couplings with its cage and the inner ring (the border).
fn stepper(
    model: &TaperedModel,
    y: Vec<f64>,
    scale: Vec<f64>,
    relative: Vec<f64>,
    set: &IntegratorSettings,
) -> Stepper {
    match set.method {
        IntegratorMethod::Dopri5 => {
            Stepper::Dopri5(Dopri5::new(0.0, y, scale, relative, set.initial_step_s))
        }
        IntegratorMethod::RosenbrockW => {
            let lay = TaperedLayout { z: model.z };
            let block = |start, n| JacobianBlock { start, n };
            let groups = [
                (0..2 * model.z)
                    .map(|j| block(lay.roller(j), ROLLER_DOF))
                    .collect(),
                vec![block(lay.cage(0), CAGE_DOF), block(lay.cage(1), CAGE_DOF)],
                vec![block(lay.inner(), INNER_DOF)],
            ];
            let integrator = RosenbrockW::new(0.0, y, scale, relative, set.initial_step_s, &groups);
            Stepper::RosenbrockW(if set.bordered_jacobian {
                integrator.with_border(&JacobianBorder {
                    group: 0,
                    support: (0..2 * model.z)
                        .map(|j| TaperedSystem::border_support(&lay, j))
                        .collect(),
                })
            } else {
                integrator
            })
        }
    }
}

/// Body and component of state index `c`.
fn component_name(c: usize, lay: &TaperedLayout) -> String {
    if c < lay.cage(0) {
        format!("roller {} component {}", c / ROLLER_DOF, c % ROLLER_DOF)
    } else if c < lay.inner() {
        let k = c - lay.cage(0);
        format!("cage {} component {}", k / CAGE_DOF, k % CAGE_DOF)
    } else {
        format!("inner ring component {}", c - lay.inner())
    }
}

/// The diagnosis of a failed step: the body and component that limited it.
fn step_error(e: StepError, t: f64, lay: &TaperedLayout) -> DynError {
    let name = |c: usize| component_name(c, lay);
    match e {
        StepError::Collapse { h, component } => DynError::StepSizeCollapse {
            time_s: t,
            step_s: h,
            component: name(component),
        },
        StepError::NonFinite { h, component } => DynError::NonFinite {
            time_s: t,
            component: name(component),
            step_s: h,
        },
    }
}

/// A sample from the interpolated state `y` at `t` and the contact report of the last accepted
/// step.
fn sample(
    model: &TaperedModel,
    lay: &TaperedLayout,
    t: f64,
    y: &[f64],
    rollers: &[RollerReport],
) -> TaperedSample {
    let z = model.z;
    let mut s = TaperedSample {
        time_s: t,
        inner_ring: read3(y, lay.inner() + inner_ring::CENTRE),
        cage_angle: [0.0; 2],
        cage_speed: [0.0; 2],
        max_cone_load: [0.0; 2],
        rollers_near_max: [0; 2],
        max_rib_force: [0.0; 2],
        total_rib_force: [0.0; 2],
        cone_sliding: [0.0; 2],
        cup_sliding: [0.0; 2],
        max_slip: 0.0,
        tracked_large_rib: [0.0; 2],
        tracked_small_rib: [0.0; 2],
        rib_ehl_share: 0.0,
    };
    let (mut ribs_loaded, mut ribs_ehl) = (0usize, 0usize);
    for k in 0..2 {
        let ci = lay.cage(k);
        s.cage_angle[k] = y[ci + cage::ANGLE];
        let axis = read3(y, ci + cage::AXIS);
        let w = axisymmetric_omega(read3(y, ci + cage::MOMENTUM), axis, model.ia_c, model.it_c);
        s.cage_speed[k] = dot(w, axis);
        let row = &rollers[k * z..(k + 1) * z];
        let max = row.iter().fold(0.0_f64, |m, r| m.max(r.cone));
        s.max_cone_load[k] = max;
        s.rollers_near_max[k] = row
            .iter()
            .filter(|r| max > 0.0 && r.cone >= 0.9 * max)
            .count();
        let (mut load, mut cone_v, mut cup_load, mut cup_v) = (0.0, 0.0, 0.0, 0.0);
        for r in row {
            s.max_rib_force[k] = s.max_rib_force[k].max(r.large_rib);
            s.total_rib_force[k] += r.large_rib;
            load += r.cone;
            cone_v += r.cone * r.cone_sliding;
            cup_load += r.cup;
            cup_v += r.cup * r.cup_sliding;
            s.max_slip = s.max_slip.max(r.slip);
            if r.large_rib > 0.0 {
                ribs_loaded += 1;
                ribs_ehl += usize::from(r.rib_ehl);
            }
        }
        s.cone_sliding[k] = if load > 0.0 { cone_v / load } else { 0.0 };
        s.cup_sliding[k] = if cup_load > 0.0 {
            cup_v / cup_load
        } else {
            0.0
        };
    }
    for k in 0..2 {
        s.tracked_large_rib[k] = rollers[k * z].large_rib;
        s.tracked_small_rib[k] = rollers[k * z].small_rib;
    }
    s.rib_ehl_share = if ribs_loaded > 0 {
        ribs_ehl as f64 / ribs_loaded as f64
    } else {
        0.0
    };
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::tests::scales_of_both_velocity_scales;
    use crate::tapered::cassette;

    /// The cassette's roller (m_r = π/4·d²·L·ρ ≈ 0.14 kg) between its cone and cup line
    /// contacts at 100 N: Palmgren's δ = 3.84·10⁻⁵ Q^0.9/L^0.8 (mm, N) ≈ 0.11 µm over the
    /// 47.9 mm working length, k = n Q/δ ≈ 1.0·10⁹ N/m each, ω_c = √(2k/m_r) ≈ 1.2·10⁵ rad/s
    /// (the model's slice laws give 1.29·10⁵).
    #[test]
    fn contact_frequency_of_the_cassette_is_of_the_hand_estimate() {
        let model = cassette();
        let set = IntegratorSettings::default();
        let [cone, cup] = &model.slices.k;
        let lines = [
            (&cone[..], model.slices.n[0]),
            (&cup[..], model.slices.n[1]),
        ];
        let w = contact_frequency(lines, model.m_r, set.contact_frequency_load_n);
        println!("ω_c = {w:.4e} rad/s, m_r = {} kg", model.m_r);
        assert!((1.0e5..1.5e5).contains(&w), "{w}");
    }

    /// `velocity_scale` applies to the tapered rollers as to the cylindrical ones: the
    /// energy-consistent scales loosen only the rollers' radial/axial velocities and their
    /// transverse (global x, y) momenta, and never tighten anything.
    #[test]
    fn contact_frequency_scales_loosen_only_roller_contact_velocities() {
        let model = cassette();
        let (old, new) = scales_of_both_velocity_scales(|set| error_scales(&model, set).0);
        let lay = TaperedLayout { z: model.z };
        let transverse = [
            roller::RADIAL_VELOCITY,
            roller::AXIAL_VELOCITY,
            roller::MOMENTUM,
            roller::MOMENTUM + 1,
        ];
        for j in 0..2 * model.z {
            let b = lay.roller(j);
            for k in 0..ROLLER_DOF {
                if transverse.contains(&k) {
                    assert!(new[b + k] > 3.0 * old[b + k], "roller {j} component {k}");
                } else {
                    assert_eq!(new[b + k], old[b + k], "roller {j} component {k}");
                }
            }
        }
        assert_eq!(new[lay.cage(0)..], old[lay.cage(0)..]);
    }
}
