//! Linearised stiffness and damping coefficients by central-difference perturbation of the
//! journal position and velocity (what rotordynamics codes expect, SPEC §8.6 / issue item 4):
//! K_ij = −∂F_i/∂e_j, C_ij = −∂F_i/∂ė_j, each column from two perturbed solves warm-started from
//! the static state. A thermal solution keeps its temperature field frozen during the
//! perturbations (thermal time constants are long compared with vibration periods); viscosity,
//! deflection and cavitation respond.

use super::solver::{JournalState, reference_speed, solve_state_impl};
use super::{JournalBearing, JournalOperating, JournalOptions};
use crate::error::Result;
use crate::viscosity::Viscosity;

/// Stiffness K, damping C (bearing frame), direct solves used and convergence of all solves.
pub(crate) type Coefficients = ([[f64; 2]; 2], [[f64; 2]; 2], usize, bool);

/// Stiffness and damping in the bearing frame, with the number of direct solves used.
pub(crate) fn coefficients(
    b: &JournalBearing,
    visc: &dyn Viscosity,
    op: &JournalOperating,
    e: [f64; 2],
    base: &JournalState,
    opt: &JournalOptions,
) -> Result<Coefficients> {
    let c = b.clearance;
    let de = opt.perturbation * c;
    let vref = reference_speed(b, op, [0.0, 0.0]).unwrap_or(c);
    let dv = opt.perturbation * c * vref / b.radius;
    let frozen = b.thermal.map(|_| base.temperature.as_slice());
    let mut k = [[0.0; 2]; 2];
    let mut d = [[0.0; 2]; 2];
    let mut solves = 0;
    let mut ok = true;
    for j in 0..2 {
        let mut fpm = [[0.0; 2]; 2];
        for (s, sign) in [(0usize, 1.0), (1usize, -1.0)] {
            let mut ep = e;
            ep[j] += sign * de;
            let st = solve_state_impl(b, visc, op, ep, [0.0, 0.0], opt, Some(base), frozen)?;
            solves += st.iterations;
            ok &= st.converged;
            fpm[s] = st.force;
        }
        for i in 0..2 {
            k[i][j] = -(fpm[0][i] - fpm[1][i]) / (2.0 * de);
        }
        for (s, sign) in [(0usize, 1.0), (1usize, -1.0)] {
            let mut v = [0.0; 2];
            v[j] = sign * dv;
            let st = solve_state_impl(b, visc, op, e, v, opt, Some(base), frozen)?;
            solves += st.iterations;
            ok &= st.converged;
            fpm[s] = st.force;
        }
        for i in 0..2 {
            d[i][j] = -(fpm[0][i] - fpm[1][i]) / (2.0 * dv);
        }
    }
    Ok((k, d, solves, ok))
}

/// Q M Qᵀ with Q the rotation by −β (bearing frame → load frame).
pub(crate) fn rotate(m: [[f64; 2]; 2], beta: f64) -> [[f64; 2]; 2] {
    let (s, c) = beta.sin_cos();
    let q = [[c, s], [-s, c]];
    let mut t = [[0.0; 2]; 2];
    for i in 0..2 {
        for j in 0..2 {
            let mut v = 0.0;
            for a in 0..2 {
                for bb in 0..2 {
                    v += q[i][a] * m[a][bb] * q[j][bb];
                }
            }
            t[i][j] = v;
        }
    }
    t
}
