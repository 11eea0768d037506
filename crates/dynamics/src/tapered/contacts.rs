//! The opt-in contact record of the tapered run: what a wear calculation needs per roller and
//! output step (seed 000 §2.4.1 step 1, §3.2.2–3.2.4). Filled only when a [`ContactRecorder`]
//! is given to [`super::run_recorded`], so a plain run pays nothing for it.

use super::sample::TaperedSample;

/// One raceway contact of one roller, slice by slice (0 on unloaded slices).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SliceContacts {
    /// normal force, N
    pub force_n: Vec<f64>,
    /// magnitude of the sliding velocity, m/s
    pub sliding_m_s: Vec<f64>,
    /// film parameter Λ of the traction model (minimum film over the composite roughness)
    pub lambda: Vec<f64>,
    /// Hertz half-width of the slice's line contact, m
    pub half_width_m: Vec<f64>,
    /// reduced radius of roller slice and raceway across the contact line, m
    pub reduced_radius_m: Vec<f64>,
    /// distance of the contact point from the ring's axis, m
    pub ring_radius_m: Vec<f64>,
}

impl SliceContacts {
    fn zeroed(slices: usize) -> Self {
        let zero = || vec![0.0; slices];
        Self {
            force_n: zero(),
            sliding_m_s: zero(),
            lambda: zero(),
            half_width_m: zero(),
            reduced_radius_m: zero(),
            ring_radius_m: zero(),
        }
    }

    pub(crate) fn clear(&mut self) {
        for v in [
            &mut self.force_n,
            &mut self.sliding_m_s,
            &mut self.lambda,
            &mut self.half_width_m,
            &mut self.reduced_radius_m,
            &mut self.ring_radius_m,
        ] {
            v.fill(0.0);
        }
    }
}

/// The large end of one roller on its large rib.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RibContact {
    /// normal force, N (0 without contact)
    pub force_n: f64,
    /// magnitude of the sliding velocity, m/s
    pub sliding_m_s: f64,
    /// film parameter Λ (NaN in boundary friction)
    pub lambda: f64,
    /// radius √(R δ) of the contact spot, m
    pub spot_radius_m: f64,
    /// whether the contact ran in EHL (spot inside the faces' overlap, SPEC §6.7)
    pub elastohydrodynamic: bool,
    /// distance of the contact point from the roller axis and from the cone's axis, m
    pub end_radius_m: f64,
    pub rib_radius_m: f64,
}

/// Everything recorded for one roller.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RollerContacts {
    pub cone: SliceContacts,
    pub cup: SliceContacts,
    pub large_rib: RibContact,
    /// yaw (skew: roller axis out of its axial plane) and pitch (tilt in the axial plane
    /// against the seated axis) of the roller, rad
    pub yaw_rad: f64,
    pub pitch_rad: f64,
}

impl RollerContacts {
    pub(crate) fn zeroed(slices: usize) -> Self {
        Self {
            cone: SliceContacts::zeroed(slices),
            cup: SliceContacts::zeroed(slices),
            ..Self::default()
        }
    }
}

/// A sink of the run's output steps with their contact record (rollers of row 0, then row 1).
pub trait ContactRecorder {
    fn record(&mut self, sample: &TaperedSample, rollers: &[RollerContacts]);
}
