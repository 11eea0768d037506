//! Initial conditions: a plain [`InitialState`] (what a quasi-static solution provides: roller
//! positions and speeds, cage speed) and the default start from pure-rolling kinematics with
//! rollers at their static equilibrium radius under the ring load ([`StaticSolution`]).

use crate::error::DynError;
use crate::model::{Model, RacewaySlices};
use crate::vec3::V3;

/// Initial state of one roller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerStart {
    /// azimuth θ of the centre, rad
    pub azimuth_rad: f64,
    /// radius r of the centre, m
    pub radius_m: f64,
    /// axial position z of the centre, m
    pub axial_m: f64,
    /// orbital speed θ̇, rad/s
    pub orbital_speed_rad_s: f64,
    /// spin speed about the roller axis in the inertial frame, rad/s (pure rolling on a fixed
    /// outer ring: −θ̇ (R_o)/R_w … see [`pure_rolling_spin`])
    pub spin_speed_rad_s: f64,
    /// yaw (skew) angle, rad
    pub yaw_rad: f64,
    /// pitch (tilt) angle, rad
    pub pitch_rad: f64,
}

/// Initial state of the bearing (the quasi-static model can fill it).
#[derive(Debug, Clone, PartialEq)]
pub struct InitialState {
    /// one entry per roller; roller `j` sits in cage pocket `j`
    pub rollers: Vec<RollerStart>,
    /// cage rotation angle (pocket 0 at this azimuth), rad
    pub cage_angle_rad: f64,
    /// cage spin speed, rad/s
    pub cage_speed_rad_s: f64,
    /// cage centre, m
    pub cage_center_m: V3,
    /// inner-ring centre, m
    pub inner_ring_center_m: V3,
}

/// Spin speed about the roller axis (inertial) for pure rolling on the outer raceway:
/// `ω = (ω_o (r + R_w) − θ̇ r)/R_w` (roller centre at radius `r`).
pub fn pure_rolling_spin(orbital: f64, outer_speed: f64, radius: f64, roller_radius: f64) -> f64 {
    (outer_speed * (radius + roller_radius) - orbital * radius) / roller_radius
}

/// One roller of a static solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticRoller {
    /// azimuth, rad
    pub azimuth_rad: f64,
    /// centre radius, m
    pub radius_m: f64,
    /// inner contact force, N
    pub inner_load_n: f64,
    /// outer contact force, N
    pub outer_load_n: f64,
}

/// Static load distribution: inner-ring displacement and roller loads (rollers without tilt,
/// centrifugal force `m r θ̇²` included; the classical load distribution with the slice laws).
#[derive(Debug, Clone, PartialEq)]
pub struct StaticSolution {
    /// inner-ring centre, m
    pub ring_displacement_m: V3,
    /// rollers
    pub rollers: Vec<StaticRoller>,
}

/// Force of a roller on a raceway at approach `delta` of the roller centre section (no tilt):
/// `Σ_s k_s (δ − z_s)ⁿ`.
pub(crate) fn roller_force(rs: &RacewaySlices, drops: &[f64], delta: f64) -> f64 {
    let mut q = 0.0;
    for (k, z) in rs.k.iter().zip(drops) {
        let d = delta - z;
        if d > 0.0 {
            q += k * d.powf(rs.n);
        }
    }
    q
}

/// Radius of a roller in equilibrium between the raceways with the inner ring displaced by
/// `e_along` (component of the ring displacement along the roller's radial direction) and an
/// outward external force `f_out` (centrifugal + gravity component).
fn roller_radius(model: &Model, e_along: f64, f_out: f64) -> (f64, f64, f64) {
    let g = |r: f64| {
        let di = model.ri + model.rw - (r - e_along);
        let dout = r + model.rw - model.ro;
        let qi = roller_force(&model.inner, &model.slice_drop, di);
        let qo = roller_force(&model.outer, &model.slice_drop, dout);
        (qo - qi - f_out, qi, qo)
    };
    let mut lo = model.ri + model.rw + e_along - 2e-4;
    let mut hi = model.ro - model.rw + 2e-4;
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if g(mid).0 > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo < 1e-13 {
            break;
        }
    }
    let r = 0.5 * (lo + hi);
    let (_, qi, qo) = g(r);
    (r, qi, qo)
}

/// Static equilibrium of the rollers at `azimuths` orbiting at `orbital` rad/s under the
/// external force `force` (N, x–y components used) on the inner ring: bisection on the ring
/// displacement along the force, then the roller radii.
pub(crate) fn static_equilibrium(
    model: &Model,
    azimuths: &[f64],
    orbital: f64,
    force: V3,
    ring_free: bool,
) -> Result<StaticSolution, DynError> {
    let g = model.conditions.gravity_m_s2;
    let fmag = (force[0] * force[0] + force[1] * force[1]).sqrt();
    let dir = if fmag > 0.0 {
        [force[0] / fmag, force[1] / fmag]
    } else {
        [0.0, -1.0]
    };
    let solve_at = |s: f64| -> (f64, Vec<StaticRoller>) {
        let mut along = 0.0;
        let mut rollers = Vec::with_capacity(azimuths.len());
        for &th in azimuths {
            let (sn, cs) = th.sin_cos();
            let e_along = s * (dir[0] * cs + dir[1] * sn);
            let f_out = model.m_r * (model.rm * orbital * orbital + g[0] * cs + g[1] * sn);
            let (r, qi, qo) = roller_radius(model, e_along, f_out);
            // force of the roller on the ring along −e_r, projected on the load direction
            along -= qi * (dir[0] * cs + dir[1] * sn);
            rollers.push(StaticRoller {
                azimuth_rad: th,
                radius_m: r,
                inner_load_n: qi,
                outer_load_n: qo,
            });
        }
        (fmag + along, rollers)
    };
    let s = if ring_free && fmag > 0.0 {
        let mut lo = 0.0;
        let mut hi = (model.ro - model.ri - 2.0 * model.rw).abs() + 2e-4;
        if solve_at(hi).0 > 0.0 {
            return Err(DynError::InvalidInput(format!(
                "no static equilibrium: the bearing cannot carry {fmag:.1} N within 0.2 mm of ring displacement"
            )));
        }
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if solve_at(mid).0 > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo < 1e-13 {
                break;
            }
        }
        0.5 * (lo + hi)
    } else {
        0.0
    };
    let (_, rollers) = solve_at(s);
    Ok(StaticSolution {
        ring_displacement_m: [s * dir[0], s * dir[1], 0.0],
        rollers,
    })
}
