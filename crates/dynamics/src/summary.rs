//! Accumulators of the per-revolution and run summaries (time-weighted means and maxima over
//! accepted steps, so that short impacts between output samples are not missed).

use crate::checkpoint::{Reader, Writer};
use crate::error::DynError;
use rolldyn_lubrication::{ContactGeometry, ContactState};

/// Values of one accepted step.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StepValues {
    pub cage_speed: f64,
    pub slip: f64,
    pub power: f64,
    pub max_fi: f64,
    pub max_fo: f64,
    pub max_bar: f64,
    pub land: f64,
    pub max_vs: f64,
    pub max_srr: f64,
    pub max_rib: f64,
    pub max_pocket: f64,
    /// inner-raceway sliding split along the roller, magnitudes: the largest over the loaded
    /// rollers and those of the most loaded roller, m/s
    pub sliding: SlidingMaxima,
    /// z-component of r × v of the cage centre (r in the radial plane), m²/s
    pub orbit_moment: f64,
    /// |r|² of the cage centre in the radial plane, m²
    pub orbit_r2: f64,
    /// inner contact state with the largest slip among loaded rollers
    pub worst: Option<ContactState>,
}

/// Largest magnitudes of the rolling-direction and axial components of the inner-raceway
/// sliding velocity ([`crate::kinematics::split_sliding`]): over all loaded rollers, and of the
/// roller carrying the largest inner-raceway normal force, m/s.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct SlidingMaxima {
    pub rolling: f64,
    pub axial: f64,
    pub rolling_most_loaded: f64,
    pub axial_most_loaded: f64,
}

impl SlidingMaxima {
    /// Of one evaluation's raceway `table`: over the rollers loaded above `threshold` N (the
    /// rollers of the sliding-speed maximum) and of the most loaded roller.
    pub fn of(table: &crate::rhs::ContactTable, threshold: f64) -> Self {
        let mut m = Self::default();
        let mut most = 0.0;
        for (j, &q) in table.force.iter().enumerate() {
            let (rolling, axial) = (table.sliding_rolling[j].abs(), table.sliding_axial[j].abs());
            if q > threshold && q > 0.0 {
                m.rolling = m.rolling.max(rolling);
                m.axial = m.axial.max(axial);
            }
            if q > most {
                most = q;
                (m.rolling_most_loaded, m.axial_most_loaded) = (rolling, axial);
            }
        }
        m
    }

    /// The larger of each component.
    pub fn max(self, o: Self) -> Self {
        Self {
            rolling: self.rolling.max(o.rolling),
            axial: self.axial.max(o.axial),
            rolling_most_loaded: self.rolling_most_loaded.max(o.rolling_most_loaded),
            axial_most_loaded: self.axial_most_loaded.max(o.axial_most_loaded),
        }
    }

    fn to_array(self) -> [f64; 4] {
        [
            self.rolling,
            self.axial,
            self.rolling_most_loaded,
            self.axial_most_loaded,
        ]
    }

    fn from_array(v: [f64; 4]) -> Self {
        Self {
            rolling: v[0],
            axial: v[1],
            rolling_most_loaded: v[2],
            axial_most_loaded: v[3],
        }
    }
}

/// Packs a line-contact state into 9 numbers (checkpoints).
pub(crate) fn pack(s: &Option<ContactState>) -> [f64; 10] {
    match s {
        None => [0.0; 10],
        Some(s) => {
            let l = match s.geometry {
                ContactGeometry::Line { length_m } => length_m,
                _ => 0.0,
            };
            [
                1.0,
                s.normal_force_n,
                l,
                s.reduced_radius_m,
                s.reduced_modulus_pa,
                s.rolling_speed_m_s,
                s.sliding_speed_m_s,
                s.temperature_k,
                s.roughness_ra_m[0],
                s.roughness_ra_m[1],
            ]
        }
    }
}

pub(crate) fn unpack(p: &[f64; 10]) -> Option<ContactState> {
    if p[0] == 0.0 {
        return None;
    }
    Some(ContactState {
        normal_force_n: p[1],
        geometry: ContactGeometry::Line { length_m: p[2] },
        reduced_radius_m: p[3],
        reduced_modulus_pa: p[4],
        rolling_speed_m_s: p[5],
        sliding_speed_m_s: p[6],
        temperature_k: p[7],
        roughness_ra_m: [p[8], p[9]],
        film_thickness_m: None,
    })
}

/// Statistics over a time window.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Window {
    pub t0: f64,
    pub dur: f64,
    pub speed_int: f64,
    pub slip_int: f64,
    pub power_int: f64,
    pub max_fi: f64,
    pub max_fo: f64,
    pub max_bar: f64,
    pub max_land: f64,
    pub max_vs: f64,
    pub max_srr: f64,
    pub cage_angle0: f64,
    pub worst: Option<ContactState>,
    pub worst_srr: f64,
    pub min_margin: f64,
    pub max_rib: f64,
    pub max_pocket: f64,
    pub orbit_moment_int: f64,
    pub orbit_r2_int: f64,
    pub sliding: SlidingMaxima,
}

impl Window {
    pub fn start(t: f64, cage_angle: f64) -> Self {
        Self {
            t0: t,
            dur: 0.0,
            speed_int: 0.0,
            slip_int: 0.0,
            power_int: 0.0,
            max_fi: 0.0,
            max_fo: 0.0,
            max_bar: 0.0,
            max_land: 0.0,
            max_vs: 0.0,
            max_srr: 0.0,
            cage_angle0: cage_angle,
            worst: None,
            worst_srr: 0.0,
            min_margin: f64::INFINITY,
            max_rib: 0.0,
            max_pocket: 0.0,
            orbit_moment_int: 0.0,
            orbit_r2_int: 0.0,
            sliding: SlidingMaxima::default(),
        }
    }

    pub fn add(&mut self, h: f64, v: &StepValues) {
        self.dur += h;
        self.orbit_moment_int += h * v.orbit_moment;
        self.orbit_r2_int += h * v.orbit_r2;
        self.speed_int += h * v.cage_speed;
        self.slip_int += h * v.slip;
        self.power_int += h * v.power;
        self.max_fi = self.max_fi.max(v.max_fi);
        self.max_fo = self.max_fo.max(v.max_fo);
        self.max_bar = self.max_bar.max(v.max_bar);
        self.max_land = self.max_land.max(v.land);
        self.max_vs = self.max_vs.max(v.max_vs);
        self.max_rib = self.max_rib.max(v.max_rib);
        self.max_pocket = self.max_pocket.max(v.max_pocket);
        self.sliding = self.sliding.max(v.sliding);
        if v.max_srr > self.max_srr {
            self.max_srr = v.max_srr;
        }
        if v.worst.is_some() && v.max_srr >= self.worst_srr {
            self.worst_srr = v.max_srr;
            self.worst = v.worst;
        }
    }

    pub fn mean_speed(&self) -> f64 {
        if self.dur > 0.0 {
            self.speed_int / self.dur
        } else {
            f64::NAN
        }
    }

    pub fn mean_slip(&self) -> f64 {
        if self.dur > 0.0 {
            self.slip_int / self.dur
        } else {
            f64::NAN
        }
    }

    pub fn mean_power(&self) -> f64 {
        if self.dur > 0.0 {
            self.power_int / self.dur
        } else {
            f64::NAN
        }
    }

    /// Whirl ratio = mean cage spin / orbital speed of the cage centre over the window. The
    /// orbital speed is the |r|²-weighted mean ∫(r × v)_z dt / ∫|r|² dt, so that jitter of a
    /// nearly centred cage (small |r|) does not dominate, as the unwrapped angle of the centre
    /// would. NaN unless the centre orbits: its mean orbital speed must sweep at least half a
    /// turn over the window — a cage centre that sits in one place (pressed against the land or
    /// located by the rollers) has no defined whirl, and the ratio of its jitter would be noise.
    pub fn whirl(&self, cage_angle: f64) -> f64 {
        if !(self.dur > 0.0 && self.orbit_r2_int > 0.0) {
            return f64::NAN;
        }
        let orbital = self.orbit_moment_int / self.orbit_r2_int;
        let spin = (cage_angle - self.cage_angle0) / self.dur;
        if (orbital * self.dur).abs() >= std::f64::consts::PI {
            spin / orbital
        } else {
            f64::NAN
        }
    }

    /// RMS distance of the cage centre from the bearing axis over the window, m.
    pub fn orbit_radius_rms(&self) -> f64 {
        if self.dur > 0.0 {
            (self.orbit_r2_int / self.dur).sqrt()
        } else {
            f64::NAN
        }
    }

    pub fn save(&self, w: &mut Writer) {
        for x in [
            self.t0,
            self.dur,
            self.speed_int,
            self.slip_int,
            self.power_int,
            self.max_fi,
            self.max_fo,
            self.max_bar,
            self.max_land,
            self.max_vs,
            self.max_srr,
            self.cage_angle0,
            self.worst_srr,
            self.min_margin,
            self.max_rib,
            self.max_pocket,
            self.orbit_moment_int,
            self.orbit_r2_int,
        ] {
            w.f64(x);
        }
        for x in pack(&self.worst) {
            w.f64(x);
        }
        for x in self.sliding.to_array() {
            w.f64(x);
        }
    }

    pub fn load(r: &mut Reader) -> Result<Self, DynError> {
        let mut v = [0.0; 18];
        for x in v.iter_mut() {
            *x = r.f64()?;
        }
        let mut p = [0.0; 10];
        for x in p.iter_mut() {
            *x = r.f64()?;
        }
        let mut sliding = [0.0; 4];
        for x in sliding.iter_mut() {
            *x = r.f64()?;
        }
        Ok(Self {
            t0: v[0],
            dur: v[1],
            speed_int: v[2],
            slip_int: v[3],
            power_int: v[4],
            max_fi: v[5],
            max_fo: v[6],
            max_bar: v[7],
            max_land: v[8],
            max_vs: v[9],
            max_srr: v[10],
            cage_angle0: v[11],
            worst_srr: v[12],
            min_margin: v[13],
            max_rib: v[14],
            max_pocket: v[15],
            orbit_moment_int: v[16],
            orbit_r2_int: v[17],
            worst: unpack(&p),
            sliding: SlidingMaxima::from_array(sliding),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cage spinning at `spin` whose centre circles at radius `r` with angular speed
    /// `orbital` (plus a fixed offset `offset` along x), sampled over `dur`.
    fn window(spin: f64, orbital: f64, r: f64, offset: f64, dur: f64) -> (Window, f64) {
        let mut w = Window::start(0.0, 0.0);
        let n = 20_000;
        let h = dur / n as f64;
        for i in 0..n {
            let t = (i as f64 + 0.5) * h;
            let (s, c) = (orbital * t).sin_cos();
            let (x, y) = (offset + r * c, r * s);
            let (vx, vy) = (-r * orbital * s, r * orbital * c);
            let v = StepValues {
                orbit_moment: x * vy - y * vx,
                orbit_r2: x * x + y * y,
                ..Default::default()
            };
            w.add(h, &v);
        }
        (w, spin * dur)
    }

    #[test]
    fn synchronous_orbit_is_precession() {
        let settings = crate::DynamicsSettings::default();
        let (w, angle) = window(300.0, 300.0, 50e-6, 0.0, 2.0 * std::f64::consts::PI / 300.0);
        let ratio = w.whirl(angle);
        assert!((ratio - 1.0).abs() < 1e-6, "{ratio}");
        assert!(settings.is_precession(ratio));
        assert!((w.orbit_radius_rms() - 50e-6).abs() < 1e-9);
        // a slower orbit: whirl ratio 2 (half a turn per cage revolution) is still defined
        let (w, angle) = window(300.0, 150.0, 50e-6, 0.0, 2.0 * std::f64::consts::PI / 300.0);
        let ratio = w.whirl(angle);
        assert!((ratio - 2.0).abs() < 1e-3, "{ratio}");
        assert!(!settings.is_precession(ratio));
    }

    #[test]
    fn a_parked_cage_centre_has_no_whirl() {
        // centre pressed 120 µm off the axis, jittering by 1 µm at 20 kHz
        let (w, angle) = window(
            300.0,
            2.0 * std::f64::consts::PI * 2e4,
            1e-6,
            120e-6,
            2.0 * std::f64::consts::PI / 300.0,
        );
        assert!(w.whirl(angle).is_nan());
        assert!(!crate::DynamicsSettings::default().is_precession(w.whirl(angle)));
    }
}
