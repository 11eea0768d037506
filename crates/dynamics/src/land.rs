//! Cage ↔ guiding-land force models behind a small trait (SPEC §3.3 pair 14): the two-level
//! friction contact [`TwoLevelLand`] and the hydrodynamic land [`HydrodynamicLand`] of the
//! Reynolds crate, whose film force acts together with that contact.

use crate::parameters::PairParameters;
use crate::vec3::{V3, add, cross, dot, norm, perp, power, scale, sub};
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
    /// Couple on the cage in addition to the moment of the force about its centre, N·m
    /// (e.g. the friction torque of a fluid film).
    pub moment_on_cage_n_m: V3,
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
        let elastic = share * p.k_p * power(delta, p.exponent);
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
            moment_on_cage_n_m: [0.0; 3],
        }
    }
}

/// Hydrodynamic cage land (issue 7; SPEC §8.6, seed 001 "narrow journal bearing"): the film
/// force and friction torque of the Reynolds crate's [`rolldyn_reynolds::cage_land::CageLand`]
/// (short-bearing theory corrected by a table of the finite Reynolds solver) at every station,
/// plus the compliant metal contact of [`TwoLevelLand`] once the film is squeezed out (the
/// cage touching the land beyond its floating clearance).
#[derive(Debug, Clone)]
pub struct HydrodynamicLand {
    film: rolldyn_reynolds::cage_land::CageLand,
    /// Oil viscosity in the land film, Pa·s (constant during a run).
    pub viscosity_pa_s: f64,
    contact: TwoLevelLand,
}

impl HydrodynamicLand {
    /// Land of radius `radius_m`, total width `width_m` split over `stations` stations, radial
    /// clearance `gap_m`, on the inner (`inner_land`) or outer ring, its clearance filled with
    /// oil to the fraction `fill_fraction` (1: flooded; below 1 a starved film on the wetted arc
    /// around the minimum gap, [`rolldyn_reynolds::cage_land`] module doc); `contact` is the
    /// metal contact beyond the clearance. Builds the correction table (≈ 0.3 s).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        radius_m: f64,
        width_m: f64,
        stations: usize,
        gap_m: f64,
        inner_land: bool,
        viscosity_pa_s: f64,
        fill_fraction: f64,
        contact: TwoLevelLand,
    ) -> Result<Self, crate::DynError> {
        use rolldyn_reynolds::cage_land::{
            CageLand, CageLandGeometry, CageLandOptions, LandPosition,
        };
        if !(viscosity_pa_s > 0.0 && viscosity_pa_s.is_finite()) {
            return Err(crate::DynError::InvalidInput(format!(
                "land film viscosity {viscosity_pa_s} Pa s must be positive"
            )));
        }
        let geometry = CageLandGeometry {
            radius: radius_m,
            width: width_m / stations.max(1) as f64,
            clearance: gap_m,
            position: if inner_land {
                LandPosition::InnerRing
            } else {
                LandPosition::OuterRing
            },
        };
        let options = CageLandOptions {
            fill_fraction,
            ..CageLandOptions::default()
        };
        let film = CageLand::new(geometry, &options)
            .map_err(|e| crate::DynError::InvalidInput(format!("hydrodynamic cage land: {e}")))?;
        Ok(Self {
            film,
            viscosity_pa_s,
            contact,
        })
    }
}

impl CageLandModel for HydrodynamicLand {
    fn force(&self, k: &LandKinematics) -> LandForce {
        let metal = self.contact.force(k);
        // Orthonormal basis (u, v) of the station plane, u along the projection of x.
        let mut u = perp([1.0, 0.0, 0.0], k.land_axis);
        if norm(u) < 1e-6 {
            u = perp([0.0, 1.0, 0.0], k.land_axis);
        }
        let u = scale(u, 1.0 / norm(u));
        let v = cross(k.land_axis, u);
        let e = perp(sub(k.cage_center, k.land_center), k.land_axis);
        let edot = perp(sub(k.cage_velocity, k.land_velocity), k.land_axis);
        let film = self.film.evaluate(
            [dot(e, u), dot(e, v)],
            [dot(edot, u), dot(edot, v)],
            dot(k.cage_omega, k.land_axis),
            dot(k.land_omega, k.land_axis),
            self.viscosity_pa_s,
        );
        // The film force acts through the cage axis at this station; its friction torque is a
        // couple about the land axis.
        let radial = add(scale(u, film.force_n[0]), scale(v, film.force_n[1]));
        let slip = dot(sub(k.cage_omega, k.land_omega), k.land_axis);
        let film_power = (film.torque_nm * slip).abs();
        let couple = scale(k.land_axis, film.torque_nm);
        if metal.normal_force_n <= 0.0 {
            return LandForce {
                force_on_cage_n: radial,
                point_m: k.cage_center,
                normal_force_n: norm(radial),
                power_w: film_power,
                penetration_m: metal.penetration_m,
                moment_on_cage_n_m: couple,
            };
        }
        // Film and metal contact together: one resultant at the metal contact point, with the
        // couple that moves the film force back to the cage axis.
        let shift = cross(sub(k.cage_center, metal.point_m), radial);
        LandForce {
            force_on_cage_n: add(metal.force_on_cage_n, radial),
            point_m: metal.point_m,
            normal_force_n: metal.normal_force_n + norm(radial),
            power_w: metal.power_w + film_power,
            penetration_m: metal.penetration_m,
            moment_on_cage_n_m: add(add(metal.moment_on_cage_n_m, couple), shift),
        }
    }
}
