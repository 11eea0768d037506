//! What one evaluation of the right-hand side reports besides `ẏ`: the per-roller contact
//! tables, the contact forces and powers, the first divergence, and the scratch of the stages.

use super::Scratch;
use crate::ends::EndContactRegime;
use crate::output::{PocketLoads, PointForce};
use rolldyn_lubrication::ContactState;

/// Per-roller contact quantities of one raceway (struct of arrays). Speeds, film, Λ and μ are
/// load-weighted means over the loaded slices; force and power are sums.
#[derive(Debug, Clone, Default)]
pub(crate) struct ContactTable {
    pub force: Vec<f64>,
    pub sliding: Vec<f64>,
    /// the load-weighted mean sliding velocity split along the roller
    /// ([`crate::kinematics::split_sliding`]): the sliding velocity at the contact's centre of
    /// pressure (it is linear along the roller), signed, m/s
    pub sliding_rolling: Vec<f64>,
    pub sliding_axial: Vec<f64>,
    pub rolling: Vec<f64>,
    pub film: Vec<f64>,
    pub lambda: Vec<f64>,
    pub mu: Vec<f64>,
    pub power: Vec<f64>,
    /// normal force of every slice, roller-major (`slice_force[j * slices + i]`; 0 where
    /// unloaded), N
    pub slice_force: Vec<f64>,
    /// contact state of the most loaded slice (scuffing check)
    pub worst: Vec<Option<ContactState>>,
    pub(super) worst_q: Vec<f64>,
}

impl ContactTable {
    fn new(z: usize, slices: usize) -> Self {
        Self {
            force: vec![0.0; z],
            sliding: vec![0.0; z],
            sliding_rolling: vec![0.0; z],
            sliding_axial: vec![0.0; z],
            rolling: vec![0.0; z],
            film: vec![0.0; z],
            lambda: vec![0.0; z],
            mu: vec![0.0; z],
            power: vec![0.0; z],
            slice_force: vec![0.0; z * slices],
            worst: vec![None; z],
            worst_q: vec![0.0; z],
        }
    }

    /// Zeroes roller `j`'s normal force and, with [`Tables::Fill`], the rest of its row.
    #[inline]
    pub(super) fn reset(&mut self, j: usize, tables: Tables) {
        self.force[j] = 0.0;
        if tables == Tables::Skip {
            return;
        }
        self.sliding[j] = 0.0;
        self.sliding_rolling[j] = 0.0;
        self.sliding_axial[j] = 0.0;
        self.rolling[j] = 0.0;
        self.film[j] = 0.0;
        self.lambda[j] = 0.0;
        self.mu[j] = 0.0;
        self.power[j] = 0.0;
        let slices = self.slice_force.len() / self.force.len();
        self.slice_force[j * slices..(j + 1) * slices].fill(0.0);
        self.worst[j] = None;
        self.worst_q[j] = 0.0;
    }

    /// Turns roller `j`'s load-weighted sums into means (film and Λ NaN without load).
    #[inline]
    pub(super) fn finish(&mut self, j: usize) {
        let q = self.force[j];
        if q > 0.0 {
            let w = 1.0 / q;
            self.sliding[j] *= w;
            self.sliding_rolling[j] *= w;
            self.sliding_axial[j] *= w;
            self.rolling[j] *= w;
            self.film[j] *= w;
            self.lambda[j] *= w;
            self.mu[j] *= w;
        } else {
            self.film[j] = f64::NAN;
            self.lambda[j] = f64::NAN;
        }
    }
}

/// Whether an evaluation fills the per-roller contact tables of [`Diagnostics`] (sliding and
/// rolling speeds, film, Λ, μ, friction power, worst slice). The forces, the divergence check
/// and the per-roller normal forces are always computed; the tables are needed only at states
/// that are reported (accepted steps, output samples), not at the integrator's inner stages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Tables {
    Fill,
    Skip,
}

/// Which body pierced what (divergence diagnosis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Violation {
    pub what: &'static str,
    pub index: usize,
    pub penetration: f64,
}

/// Records the first penetration deeper than `limit` (divergence check).
#[inline]
pub(super) fn note(
    violation: &mut Option<Violation>,
    what: &'static str,
    index: usize,
    penetration: f64,
    limit: f64,
) {
    if penetration > limit && violation.is_none() {
        *violation = Some(Violation {
            what,
            index,
            penetration,
        });
    }
}

/// Scratch and per-evaluation results of the right-hand side.
#[derive(Debug, Clone)]
pub(crate) struct Diagnostics {
    pub inner: ContactTable,
    pub outer: ContactTable,
    /// roller–cage bar normal force per roller (sum of the evaluation points), N
    pub bar: Vec<f64>,
    pub bar_power: Vec<f64>,
    /// force-weighted sliding speed of the roller–cage bar contacts per roller, m/s (0: none)
    pub bar_sliding: Vec<f64>,
    /// roller end ↔ rib normal force per roller (sum of both ends and all ribs), N
    pub rib: Vec<f64>,
    /// force-weighted sliding speed of the rib contacts per roller, m/s
    pub rib_sliding: Vec<f64>,
    /// force-weighted distance of the rib contact point from the rib edge (rim), m (NaN: none)
    pub rib_edge: Vec<f64>,
    /// force-weighted distance of the rib contact point from the roller axis and from the ring
    /// axis, m (NaN: none)
    pub rib_end_radius: Vec<f64>,
    pub rib_ring_radius: Vec<f64>,
    /// force-weighted friction coefficient of the rib contacts per roller
    pub rib_mu: Vec<f64>,
    /// friction power of the rib contacts per roller, W
    pub rib_power: Vec<f64>,
    /// regime of the most loaded rib contact per roller
    pub rib_regime: Vec<EndContactRegime>,
    /// roller end ↔ cage pocket face normal force per roller, N
    pub pocket: Vec<f64>,
    /// friction power of the pocket-face contacts per roller, W
    pub pocket_power: Vec<f64>,
    /// contact forces on the cage per pocket (index = roller)
    pub pocket_loads: Vec<PocketLoads>,
    /// cage–land force at each station
    pub land_loads: [PointForce; 2],
    /// cage–land normal force (sum of stations), N
    pub land_force: f64,
    pub land_power: f64,
    /// prescribed ring speeds at the evaluation time
    pub inner_speed: f64,
    pub outer_speed: f64,
    pub violation: Option<Violation>,
    /// the stages' working arrays, allocated once
    pub(super) scratch: Scratch,
}

impl Diagnostics {
    pub fn new(z: usize, slices: usize) -> Self {
        Self {
            inner: ContactTable::new(z, slices),
            outer: ContactTable::new(z, slices),
            bar: vec![0.0; z],
            bar_power: vec![0.0; z],
            bar_sliding: vec![0.0; z],
            rib: vec![0.0; z],
            rib_sliding: vec![0.0; z],
            rib_edge: vec![f64::NAN; z],
            rib_end_radius: vec![f64::NAN; z],
            rib_ring_radius: vec![f64::NAN; z],
            rib_mu: vec![0.0; z],
            rib_power: vec![0.0; z],
            rib_regime: vec![EndContactRegime::None; z],
            pocket: vec![0.0; z],
            pocket_power: vec![0.0; z],
            pocket_loads: vec![PocketLoads::default(); z],
            land_loads: [PointForce::default(); 2],
            land_force: 0.0,
            land_power: 0.0,
            inner_speed: 0.0,
            outer_speed: 0.0,
            violation: None,
            scratch: Scratch::new(z, slices),
        }
    }
}
