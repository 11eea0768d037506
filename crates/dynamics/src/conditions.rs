//! Operating conditions: speeds, loads, temperatures, inner-ring support, gravity, cage drag
//! (SPEC §3.7, §3.6).

use crate::error::DynError;
use crate::vec3::V3;

/// Prescribed angular speed of a ring about its axis, rad/s (positive counter-clockwise about
/// +z).
#[derive(Debug, Clone, PartialEq)]
pub enum SpeedLaw {
    /// ω(t) = ω.
    Constant(f64),
    /// Linear ramp from `from` at `t0` to `to` at `t1`, constant outside.
    Ramp {
        /// speed before `t0_s`, rad/s
        from: f64,
        /// speed after `t1_s`, rad/s
        to: f64,
        /// ramp start, s
        t0_s: f64,
        /// ramp end, s (> t0_s)
        t1_s: f64,
    },
    /// Piecewise-linear schedule `(t, ω)` with strictly increasing times, constant beyond the
    /// ends (speed schedules of SPEC §3.7).
    Schedule(Vec<(f64, f64)>),
}

impl SpeedLaw {
    /// ω(t).
    pub fn speed(&self, t: f64) -> f64 {
        match self {
            SpeedLaw::Constant(w) => *w,
            SpeedLaw::Ramp {
                from,
                to,
                t0_s,
                t1_s,
            } => {
                if t <= *t0_s {
                    *from
                } else if t >= *t1_s {
                    *to
                } else {
                    from + (to - from) * (t - t0_s) / (t1_s - t0_s)
                }
            }
            SpeedLaw::Schedule(p) => piecewise_linear(p, t),
        }
    }

    /// Rotation angle ∫₀ᵗ ω dt, rad (exact for every law; negative t integrates backwards).
    pub fn angle(&self, t: f64) -> f64 {
        match self {
            SpeedLaw::Constant(w) => w * t,
            SpeedLaw::Ramp {
                from,
                to,
                t0_s,
                t1_s,
            } => piecewise_linear_integral(&[(*t0_s, *from), (*t1_s, *to)], t),
            SpeedLaw::Schedule(p) => piecewise_linear_integral(p, t),
        }
    }

    fn validate(&self, what: &str) -> Result<(), DynError> {
        let bad = |m: &str| Err(DynError::InvalidInput(format!("{what}: {m}")));
        match self {
            SpeedLaw::Constant(w) if !w.is_finite() => bad("speed must be finite"),
            SpeedLaw::Ramp {
                from,
                to,
                t0_s,
                t1_s,
            } if !(from.is_finite() && to.is_finite() && t0_s.is_finite() && t1_s > t0_s) => {
                bad("ramp needs finite speeds and t1 > t0")
            }
            SpeedLaw::Schedule(p)
                if p.is_empty()
                    || p.iter().any(|(t, w)| !t.is_finite() || !w.is_finite())
                    || p.windows(2).any(|w| w[1].0 <= w[0].0) =>
            {
                bad("schedule needs finite points with strictly increasing times")
            }
            _ => Ok(()),
        }
    }
}

/// Value at `t` of the piecewise-linear function through `pts` (constant beyond the ends; 0
/// for no points).
pub fn piecewise_linear(pts: &[(f64, f64)], t: f64) -> f64 {
    rolldyn_numerics::table::interpolate_held(pts, t)
}

/// ∫₀ᵗ of the piecewise-linear function through `pts` (constant beyond the ends).
fn piecewise_linear_integral(pts: &[(f64, f64)], t: f64) -> f64 {
    // antiderivative F(x) with F(pts[0].0) = 0, then F(t) − F(0)
    let f = |x: f64| -> f64 {
        let (t0, w0) = pts[0];
        if x <= t0 {
            return w0 * (x - t0);
        }
        let mut acc = 0.0;
        for w in pts.windows(2) {
            let ((ta, wa), (tb, wb)) = (w[0], w[1]);
            if x <= tb {
                let wx = wa + (wb - wa) * (x - ta) / (tb - ta);
                return acc + 0.5 * (wa + wx) * (x - ta);
            }
            acc += 0.5 * (wa + wb) * (tb - ta);
        }
        let (tl, wl) = pts[pts.len() - 1];
        acc + wl * (x - tl)
    };
    f(t) - f(0.0)
}

/// A force on the inner ring (applied at its centre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InnerRingLoad {
    /// Constant force fixed in space, N (x, y radial; z axial).
    Fixed {
        /// force vector, N
        force_n: V3,
    },
    /// Radial force of constant magnitude rotating with the shaft: direction angle
    /// `phase_rad + φ_i(t)` in the x–y plane (2002834: "the radial load rotates with the inner
    /// ring").
    Rotating {
        /// magnitude, N
        magnitude_n: f64,
        /// direction at t = 0, rad from +x
        phase_rad: f64,
    },
    /// Rotating unbalance `F = U ω_i²` (SPEC §3.7), rotating with the shaft.
    Unbalance {
        /// unbalance U, kg·m
        unbalance_kg_m: f64,
        /// direction at t = 0, rad from +x
        phase_rad: f64,
    },
    /// Force fixed in space with one step: `before_n` for t ≤ `at_s`, `after_n` for t > `at_s`
    /// (SPEC §3.7: 1032930 gearbox load 3708.8 N before, 406.5 N after starter cut-off). At the
    /// instant of the step the force still has its `before_n` value.
    FixedStep {
        /// force vector up to and including `at_s`, N
        before_n: V3,
        /// force vector after `at_s`, N
        after_n: V3,
        /// time of the step, s
        at_s: f64,
    },
}

impl InnerRingLoad {
    /// The fixed-in-space part of this load at `t`, N (zero for rotating loads).
    fn fixed_force(&self, t: f64) -> V3 {
        match *self {
            InnerRingLoad::Fixed { force_n } => force_n,
            InnerRingLoad::FixedStep {
                before_n,
                after_n,
                at_s,
            } => {
                if t <= at_s {
                    before_n
                } else {
                    after_n
                }
            }
            InnerRingLoad::Rotating { .. } | InnerRingLoad::Unbalance { .. } => [0.0; 3],
        }
    }
}

/// How the inner ring may move (its spin is always prescribed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InnerRingSupport {
    /// Radial (x, y) translation free (default true: the centre trajectory is an output).
    pub radial_free: bool,
    /// Axial translation free (default false). With the roller-end ↔ rib contacts (pair 56)
    /// the ribs carry the axial load path between inner ring and rollers, so `true` is usable;
    /// without ribs on the inner ring (or with them switched off) nothing holds the ring axially.
    pub axial_free: bool,
    /// Mass moved with the inner ring, kg (`None` → the ring's own mass; set the rotor share
    /// for a shaft-mounted ring).
    pub mass_kg: Option<f64>,
}

impl Default for InnerRingSupport {
    fn default() -> Self {
        Self {
            radial_free: true,
            axial_free: false,
            mass_kg: None,
        }
    }
}

/// Oil temperatures per contact, K (SPEC §3.7: inputs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactTemperatures {
    /// inner raceway contacts
    pub inner_raceway_k: f64,
    /// outer raceway contacts
    pub outer_raceway_k: f64,
    /// cage contacts (bars, land)
    pub cage_k: f64,
}

impl ContactTemperatures {
    /// The same temperature everywhere.
    pub fn uniform(t_k: f64) -> Self {
        Self {
            inner_raceway_k: t_k,
            outer_raceway_k: t_k,
            cage_k: t_k,
        }
    }
}

/// Operating conditions of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct OperatingConditions {
    /// Inner-ring speed law, rad/s.
    pub inner_speed: SpeedLaw,
    /// Outer-ring speed law, rad/s (0 for a fixed outer ring; intershaft bearings rotate it).
    pub outer_speed: SpeedLaw,
    /// Forces on the inner ring.
    pub loads: Vec<InnerRingLoad>,
    /// Inner-ring support.
    pub support: InnerRingSupport,
    /// Gravity acceleration vector, m/s² (default (0, −9.81, 0): y up).
    pub gravity_m_s2: V3,
    /// Oil temperatures per contact.
    pub temperatures: ContactTemperatures,
    /// Cage viscous drag coefficient c, N·m·s/rad: `M = −c ω_cage` (SPEC §3.6, ⚠ F-22; 2002834
    /// at 100 °C: 6.62·10⁻⁴, [`CAGE_DRAG_2002834_100C`]).
    pub cage_drag_n_m_s: f64,
    /// Roller drag factor k = ½ ρ_eff C_D D l of the air–oil mixture, kg/m: every roller feels
    /// F = −k |v| v with v its centre's velocity across its axis, the mixture at rest
    /// (`rolldyn_lubrication::mixture::roller_drag_factor`; 0 = none, as seed 000 §3.6).
    pub roller_drag_kg_m: f64,
    /// Misalignment of the inner-ring axis: tilt angle, rad (prescribed, constant).
    pub misalignment_rad: f64,
    /// Direction of the misalignment: the inner-ring axis tilts toward this azimuth, rad from
    /// +x (default 0).
    pub misalignment_azimuth_rad: f64,
    /// Operating radial (diametral) clearance over time, `(t s, G_r m)` piecewise linear and
    /// constant beyond the ends (SPEC §3.7 "operating clearance as a function of time"); `None`
    /// keeps the bearing's clearance. The change against the bearing's clearance moves the outer
    /// raceway radially by half of it.
    pub clearance_schedule: Option<Vec<(f64, f64)>>,
}

/// Cage drag coefficient of 2002834 at 100 °C from seed 000 §3.1.1 (M = −662 ω in N·mm and
/// rad/ms, SPEC ⚠ F-22), N·m·s/rad.
pub const CAGE_DRAG_2002834_100C: f64 = 6.62e-4;

impl OperatingConditions {
    /// Constant inner-ring speed `inner_rad_s`, fixed outer ring, a radial load `radial_n`
    /// fixed in space pointing in −y (load zone at the bottom), 100 °C everywhere, gravity on,
    /// no cage drag, no misalignment.
    pub fn new(inner_rad_s: f64, radial_n: f64) -> Self {
        Self {
            inner_speed: SpeedLaw::Constant(inner_rad_s),
            outer_speed: SpeedLaw::Constant(0.0),
            loads: vec![InnerRingLoad::Fixed {
                force_n: [0.0, -radial_n, 0.0],
            }],
            support: InnerRingSupport::default(),
            gravity_m_s2: [0.0, -9.81, 0.0],
            temperatures: ContactTemperatures::uniform(373.15),
            cage_drag_n_m_s: 0.0,
            roller_drag_kg_m: 0.0,
            misalignment_rad: 0.0,
            misalignment_azimuth_rad: 0.0,
            clearance_schedule: None,
        }
    }

    /// Operating radial clearance at `t` from the schedule, m (`None` without a schedule).
    pub fn clearance_at(&self, t: f64) -> Option<f64> {
        self.clearance_schedule
            .as_ref()
            .map(|p| piecewise_linear(p, t))
    }

    /// Total external force on the inner ring at time `t`, N.
    pub fn inner_ring_force(&self, t: f64) -> V3 {
        let mut f = [0.0; 3];
        for l in &self.loads {
            match *l {
                InnerRingLoad::Fixed { .. } | InnerRingLoad::FixedStep { .. } => {
                    let force_n = l.fixed_force(t);
                    for k in 0..3 {
                        f[k] += force_n[k];
                    }
                }
                InnerRingLoad::Rotating {
                    magnitude_n,
                    phase_rad,
                } => {
                    let a = phase_rad + self.inner_speed.angle(t);
                    f[0] += magnitude_n * a.cos();
                    f[1] += magnitude_n * a.sin();
                }
                InnerRingLoad::Unbalance {
                    unbalance_kg_m,
                    phase_rad,
                } => {
                    let w = self.inner_speed.speed(t);
                    let a = phase_rad + self.inner_speed.angle(t);
                    let m = unbalance_kg_m * w * w;
                    f[0] += m * a.cos();
                    f[1] += m * a.sin();
                }
            }
        }
        f
    }

    /// Sum of the loads fixed in space at `t` (fixed loads and load steps), N.
    pub fn fixed_force(&self, t: f64) -> V3 {
        let mut f = [0.0; 3];
        for l in &self.loads {
            let g = l.fixed_force(t);
            for k in 0..3 {
                f[k] += g[k];
            }
        }
        f
    }

    /// Magnitude of the sum of the loads rotating with the shaft at `t` (rotating loads and
    /// the unbalance force `U ω²`), N. They all turn with the inner ring, so the magnitude of
    /// their sum does not depend on the shaft angle.
    pub fn rotating_force_magnitude(&self, t: f64) -> f64 {
        let w = self.inner_speed.speed(t);
        let (mut x, mut y) = (0.0, 0.0);
        for l in &self.loads {
            let (m, phase) = match *l {
                InnerRingLoad::Rotating {
                    magnitude_n,
                    phase_rad,
                } => (magnitude_n, phase_rad),
                InnerRingLoad::Unbalance {
                    unbalance_kg_m,
                    phase_rad,
                } => (unbalance_kg_m * w * w, phase_rad),
                InnerRingLoad::Fixed { .. } | InnerRingLoad::FixedStep { .. } => continue,
            };
            x += m * phase.cos();
            y += m * phase.sin();
        }
        x.hypot(y)
    }

    /// The conditions frozen at time `t` (seed 000 §3.1.2, SPEC §3.1: quasi-steady runs at
    /// frozen points of a start-up): speeds become constants `ω(t)`, load steps the fixed force
    /// they have at `t` (the value before the step when `t` is the step time), rotating loads
    /// and the unbalance keep turning with the shaft from the direction they have at `t`, and a
    /// clearance schedule becomes its value at `t`. Temperatures, drag and misalignment are
    /// already constant.
    pub fn frozen_at(&self, t: f64) -> OperatingConditions {
        let angle = self.inner_speed.angle(t);
        let loads = self
            .loads
            .iter()
            .map(|l| match *l {
                InnerRingLoad::Fixed { .. } | InnerRingLoad::FixedStep { .. } => {
                    InnerRingLoad::Fixed {
                        force_n: l.fixed_force(t),
                    }
                }
                InnerRingLoad::Rotating {
                    magnitude_n,
                    phase_rad,
                } => InnerRingLoad::Rotating {
                    magnitude_n,
                    phase_rad: (phase_rad + angle).rem_euclid(std::f64::consts::TAU),
                },
                InnerRingLoad::Unbalance {
                    unbalance_kg_m,
                    phase_rad,
                } => InnerRingLoad::Unbalance {
                    unbalance_kg_m,
                    phase_rad: (phase_rad + angle).rem_euclid(std::f64::consts::TAU),
                },
            })
            .collect();
        OperatingConditions {
            inner_speed: SpeedLaw::Constant(self.inner_speed.speed(t)),
            outer_speed: SpeedLaw::Constant(self.outer_speed.speed(t)),
            loads,
            clearance_schedule: self.clearance_at(t).map(|g| vec![(0.0, g)]),
            ..self.clone()
        }
    }

    pub(crate) fn validate(&self) -> Result<(), DynError> {
        self.inner_speed.validate("inner_speed")?;
        self.outer_speed.validate("outer_speed")?;
        let t = &self.temperatures;
        if ![t.inner_raceway_k, t.outer_raceway_k, t.cage_k]
            .iter()
            .all(|&x| x > 0.0 && x.is_finite())
        {
            return Err(DynError::InvalidInput(
                "temperatures must be finite and > 0 K".into(),
            ));
        }
        if !(self.cage_drag_n_m_s >= 0.0 && self.cage_drag_n_m_s.is_finite()) {
            return Err(DynError::InvalidInput(
                "cage drag coefficient must be finite and ≥ 0".into(),
            ));
        }
        if !(self.roller_drag_kg_m >= 0.0 && self.roller_drag_kg_m.is_finite()) {
            return Err(DynError::InvalidInput(
                "roller drag factor must be finite and ≥ 0".into(),
            ));
        }
        if !(self.misalignment_rad.abs() < 0.02 && self.misalignment_azimuth_rad.is_finite()) {
            return Err(DynError::InvalidInput(
                "misalignment must be finite and below 0.02 rad (69′)".into(),
            ));
        }
        if let Some(p) = &self.clearance_schedule {
            SpeedLaw::Schedule(p.clone()).validate("clearance_schedule")?;
        }
        if !self.gravity_m_s2.iter().all(|g| g.is_finite()) {
            return Err(DynError::InvalidInput("gravity must be finite".into()));
        }
        for l in &self.loads {
            let ok = match *l {
                InnerRingLoad::Fixed { force_n } => force_n.iter().all(|x| x.is_finite()),
                InnerRingLoad::Rotating {
                    magnitude_n,
                    phase_rad,
                } => magnitude_n.is_finite() && phase_rad.is_finite(),
                InnerRingLoad::Unbalance {
                    unbalance_kg_m,
                    phase_rad,
                } => unbalance_kg_m.is_finite() && phase_rad.is_finite(),
                InnerRingLoad::FixedStep {
                    before_n,
                    after_n,
                    at_s,
                } => before_n.iter().chain(&after_n).all(|x| x.is_finite()) && at_s.is_finite(),
            };
            if !ok {
                return Err(DynError::InvalidInput("loads must be finite".into()));
            }
        }
        if let Some(m) = self.support.mass_kg
            && !(m > 0.0 && m.is_finite())
        {
            return Err(DynError::InvalidInput("inner-ring mass must be > 0".into()));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ramp_angle_is_integral_of_speed() {
        let law = SpeedLaw::Ramp {
            from: 10.0,
            to: 30.0,
            t0_s: 1.0,
            t1_s: 2.0,
        };
        // 10·1 + (10+30)/2·1 + 30·1 = 60 at t = 3
        assert!((law.angle(3.0) - 60.0).abs() < 1e-12);
        assert!((law.speed(1.5) - 20.0).abs() < 1e-12);
        assert!((SpeedLaw::Constant(5.0).angle(2.0) - 10.0).abs() < 1e-12);
    }

    const RPM: f64 = std::f64::consts::PI / 30.0;

    /// SPEC §3.7: F = U ω² rotating with the shaft equals a rotating load of that magnitude
    /// (1032930: 3.1625e-3 kg·m gives 1376 N at 6300 rpm, 2919 N at 9175 rpm).
    #[test]
    fn unbalance_force_is_u_omega_squared() {
        for (rpm, expected) in [(6300.0, 1376.0), (9175.0, 2919.0)] {
            let w = rpm * RPM;
            let mut unbalance = OperatingConditions::new(w, 0.0);
            unbalance.loads = vec![InnerRingLoad::Unbalance {
                unbalance_kg_m: 3.1625e-3,
                phase_rad: 0.3,
            }];
            let mut rotating = unbalance.clone();
            rotating.loads = vec![InnerRingLoad::Rotating {
                magnitude_n: 3.1625e-3 * w * w,
                phase_rad: 0.3,
            }];
            for t in [0.0, 1.3e-3, 0.25] {
                let (a, b) = (unbalance.inner_ring_force(t), rotating.inner_ring_force(t));
                for k in 0..3 {
                    assert!((a[k] - b[k]).abs() < 1e-9 * expected, "{rpm} rpm, t = {t}");
                }
                assert!((a[0].hypot(a[1]) - expected).abs() < 0.5, "{rpm} rpm");
            }
            assert!((unbalance.rotating_force_magnitude(0.0) - expected).abs() < 0.5);
        }
    }

    /// SPEC §3.7: the gearbox load steps from 3708.8 N to 406.5 N at starter cut-off; the
    /// value at the step time itself is the one before.
    #[test]
    fn load_step_switches_after_its_time() {
        let mut c = OperatingConditions::new(600.0, 0.0);
        c.loads = vec![
            InnerRingLoad::Fixed {
                force_n: [0.0, -578.8, 0.0],
            },
            InnerRingLoad::FixedStep {
                before_n: [0.0, -3708.8, 0.0],
                after_n: [0.0, -406.5, 0.0],
                at_s: 82.0988,
            },
        ];
        assert!(c.validate().is_ok());
        assert_eq!(c.inner_ring_force(0.0), [0.0, -578.8 - 3708.8, 0.0]);
        assert_eq!(c.inner_ring_force(82.0988), [0.0, -578.8 - 3708.8, 0.0]);
        assert_eq!(c.inner_ring_force(82.0989), [0.0, -578.8 - 406.5, 0.0]);
        assert_eq!(c.fixed_force(270.0), [0.0, -578.8 - 406.5, 0.0]);
        assert_eq!(c.rotating_force_magnitude(10.0), 0.0);
        c.loads.push(InnerRingLoad::FixedStep {
            before_n: [f64::NAN, 0.0, 0.0],
            after_n: [0.0; 3],
            at_s: 1.0,
        });
        assert!(c.validate().is_err());
    }

    /// Seed 000 §3.1.2: the frozen conditions at t carry the schedules' values at t as
    /// constants.
    #[test]
    fn frozen_conditions_take_the_schedule_values() {
        let mut c = OperatingConditions::new(0.0, 0.0);
        c.inner_speed = SpeedLaw::Schedule(vec![
            (0.0, 0.0),
            (82.0988, 6300.0 * RPM),
            (270.4988, 9175.0 * RPM),
        ]);
        c.loads = vec![
            InnerRingLoad::FixedStep {
                before_n: [0.0, -3708.8, 0.0],
                after_n: [0.0, -406.5, 0.0],
                at_s: 82.0988,
            },
            InnerRingLoad::Unbalance {
                unbalance_kg_m: 3.1625e-3,
                phase_rad: 0.0,
            },
        ];
        c.clearance_schedule = Some(vec![(0.0, 20e-6), (270.4988, -4e-6)]);
        let at_cut_off = c.frozen_at(82.0988);
        assert_eq!(at_cut_off.inner_speed, SpeedLaw::Constant(6300.0 * RPM));
        assert_eq!(at_cut_off.fixed_force(1.0), [0.0, -3708.8, 0.0]);
        assert!((at_cut_off.rotating_force_magnitude(0.0) - 1376.0).abs() < 0.5);
        let after = c.frozen_at(85.2988);
        assert_eq!(after.fixed_force(0.0), [0.0, -406.5, 0.0]);
        let end = c.frozen_at(270.4988);
        assert!((end.inner_speed.speed(0.0) - 9175.0 * RPM).abs() < 1e-9);
        let g = end.clearance_at(0.0).unwrap_or(f64::NAN);
        assert!((g + 4e-6).abs() < 1e-15);
        assert_eq!(end.clearance_at(5.0), Some(g));
        assert!(end.validate().is_ok());
        // the unbalance keeps the direction it has at the frozen time
        let f_sched = c.inner_ring_force(270.4988);
        let f_frozen = end.inner_ring_force(0.0);
        for k in 0..2 {
            assert!((f_sched[k] - f_frozen[k]).abs() < 1e-6 * 2919.0);
        }
    }
}
