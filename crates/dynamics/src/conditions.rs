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
            SpeedLaw::Schedule(p) => {
                let Some(first) = p.first() else { return 0.0 };
                if t <= first.0 {
                    return first.1;
                }
                for w in p.windows(2) {
                    if t <= w[1].0 {
                        return w[0].1 + (w[1].1 - w[0].1) * (t - w[0].0) / (w[1].0 - w[0].0);
                    }
                }
                p[p.len() - 1].1
            }
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
    /// Misalignment of the inner-ring axis: tilt angle, rad (prescribed, constant).
    pub misalignment_rad: f64,
    /// Direction of the misalignment: the inner-ring axis tilts toward this azimuth, rad from
    /// +x (default 0).
    pub misalignment_azimuth_rad: f64,
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
            misalignment_rad: 0.0,
            misalignment_azimuth_rad: 0.0,
        }
    }

    /// Total external force on the inner ring at time `t`, N.
    pub fn inner_ring_force(&self, t: f64) -> V3 {
        let mut f = [0.0; 3];
        for l in &self.loads {
            match *l {
                InnerRingLoad::Fixed { force_n } => {
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
        if !(self.misalignment_rad.abs() < 0.02 && self.misalignment_azimuth_rad.is_finite()) {
            return Err(DynError::InvalidInput(
                "misalignment must be finite and below 0.02 rad (69′)".into(),
            ));
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
}
