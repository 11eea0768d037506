//! Cage ↔ guiding-land force models behind a small trait, so that the hydrodynamic cage-land
//! model of the Reynolds crate can replace the default two-level-friction contact (SPEC §3.3
//! pair 14; next issue: hydrodynamic land).

use crate::parameters::PairParameters;
use crate::vec3::{V3, add, cross, dot, norm, perp, scale, sub};
use rolldyn_contact::damping::SliceDamping;

/// Kinematics of the cage at one axial station of its guiding land (all inertial frame, SI).
/// The force model is called once per station per right-hand-side evaluation (two stations,
/// at the land edges, so that cage tilt meets a restoring moment).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LandKinematics {
    /// Unit vector of the land (ring) axis.
    pub land_axis: V3,
    /// Point on the land axis in the station plane, m.
    pub land_center: V3,
    /// Velocity of `land_center`, m/s.
    pub land_velocity: V3,
    /// Angular velocity of the land (ring), rad/s.
    pub land_omega: V3,
    /// Point on the cage axis in the station plane, m.
    pub cage_center: V3,
    /// Velocity of `cage_center`, m/s.
    pub cage_velocity: V3,
    /// Angular velocity of the cage, rad/s.
    pub cage_omega: V3,
    /// Land radius, m.
    pub land_radius_m: f64,
    /// Nominal radial clearance (half the diametral floating clearance), m.
    pub radial_gap_m: f64,
    /// True when the cage bore runs on an inner-ring land; false for an outer land.
    pub inner_land: bool,
    /// Axial width represented by this station, m.
    pub width_m: f64,
    /// Number of stations the land is split into (the elastic coefficient is shared).
    pub stations: usize,
    /// Oil temperature, K.
    pub temperature_k: f64,
}

/// Result of a land-force evaluation at one station.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LandForce {
    /// Force on the cage, N (the ring gets the opposite).
    pub force_on_cage_n: V3,
    /// Point of application, m.
    pub point_m: V3,
    /// Normal force magnitude, N.
    pub normal_force_n: f64,
    /// Frictional (dissipated) power, W.
    pub power_w: f64,
    /// Penetration beyond the nominal clearance, m (≤ 0: no contact).
    pub penetration_m: f64,
}

/// A cage ↔ guiding-land force law. Implementations must be deterministic, allocation-free and
/// never return NaN for finite input.
pub trait CageLandModel: std::fmt::Debug + Send + Sync {
    /// Force at one land station.
    fn force(&self, k: &LandKinematics) -> LandForce;
}

/// Default land model: compliant contact `K_p δⁿ + STEP(δ,0,0,d,C_h)·δ̇` beyond the floating
/// clearance with the two-level friction law (SPEC §3.3 pair 14, §3.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoLevelLand {
    /// Pair parameters (K_p is the coefficient of the whole land; split over the stations).
    pub parameters: PairParameters,
}

impl CageLandModel for TwoLevelLand {
    #[inline]
    fn force(&self, k: &LandKinematics) -> LandForce {
        let p = &self.parameters;
        let e = perp(sub(k.cage_center, k.land_center), k.land_axis);
        let ecc = norm(e);
        let delta = ecc - k.radial_gap_m;
        if delta <= 0.0 || ecc == 0.0 {
            return LandForce {
                penetration_m: delta,
                ..LandForce::default()
            };
        }
        let n = scale(e, 1.0 / ecc);
        let share = 1.0 / k.stations.max(1) as f64;
        let elastic = share * p.k_p * delta.powf(p.exponent);
        let delta_dot = dot(sub(k.cage_velocity, k.land_velocity), n);
        let damping = SliceDamping::new(share * p.c_h, p.d);
        let fn_ = damping.normal_force(elastic, delta, delta_dot);
        let side = if k.inner_land { -1.0 } else { 1.0 };
        let point = add(k.land_center, scale(n, side * k.land_radius_m));
        let vc = add(
            k.cage_velocity,
            cross(k.cage_omega, sub(point, k.cage_center)),
        );
        let vl = add(
            k.land_velocity,
            cross(k.land_omega, sub(point, k.land_center)),
        );
        let vt = perp(sub(vc, vl), n);
        let vs = norm(vt);
        let mu = p.friction.coefficient(vs);
        let mut f = scale(n, -fn_);
        if vs > 0.0 {
            f = add(f, scale(vt, -mu * fn_ / vs));
        }
        LandForce {
            force_on_cage_n: f,
            point_m: point,
            normal_force_n: fn_,
            power_w: mu * fn_ * vs,
            penetration_m: delta,
        }
    }
}
