//! One recorded output step of a tapered run (seed 000 §3.2.1 observables): what the run
//! returns, the summary reduces, the sample columns print and a contact recorder receives.

use crate::vec3::V3;

/// One recorded sample.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedSample {
    pub time_s: f64,
    /// inner-ring centre, m
    pub inner_ring: V3,
    /// cage angle (unwrapped) and spin per row, rad and rad/s
    pub cage_angle: [f64; 2],
    pub cage_speed: [f64; 2],
    /// per row: largest roller load on the cone, N; rollers within 10 % of it
    pub max_cone_load: [f64; 2],
    pub rollers_near_max: [usize; 2],
    /// per row: largest large-end ↔ rib force, N; sum over the row, N
    pub max_rib_force: [f64; 2],
    pub total_rib_force: [f64; 2],
    /// per row: load-weighted sliding speed on cone and cup, m/s
    pub cone_sliding: [f64; 2],
    pub cup_sliding: [f64; 2],
    /// largest relative slip of a loaded slice, both rows
    pub max_slip: f64,
    /// roller 0 of each row: large-end and small-end rib forces, N
    pub tracked_large_rib: [f64; 2],
    pub tracked_small_rib: [f64; 2],
    /// share of loaded large-rib contacts running in EHL (patch inside the overlap)
    pub rib_ehl_share: f64,
}
