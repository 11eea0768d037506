//! Equilibrium of the inner-ring assembly (Jones' five degrees of freedom, Harris & Kotzalas,
//! Advanced Concepts, ch. 1): the applied loads plus the cone and rib forces of all 2Z rollers
//! vanish. Each roller is solved in its axial plane for the ring's in-plane motion
//! ([`super::plane::PlaneMotion`]); the ring unknowns by damped Newton steps on a
//! forward-difference Jacobian.

use super::case::{TaperedLoadCase, TiltCondition};
use super::plane::{Line, PlaneMotion, cross, rotated};
use super::roller::{CONE, CUP, RollerLoading, RollerPose, RollerState, RowRoller};
use super::settings::TaperedLoadSettings;
use crate::QsError;
use rolldyn_geometry::{DoubleRowTaperedBearing, Rz};
use rolldyn_numerics::dense_lu::DenseLu;
use std::f64::consts::TAU;

/// Unit of the scaled displacement unknowns [m] (tilts times ℓ).
const DISPLACEMENT_UNIT: f64 = 1e-6;

/// Everything the ring iteration needs.
pub(crate) struct RingProblem<'a> {
    pub rows: &'a [RowRoller; 2],
    pub z: usize,
    /// azimuth of roller 0 of each row [rad]
    pub phase: [f64; 2],
    /// epicyclic cage speed [rad/s] and each roller's centrifugal force [N]
    pub cage_speed: f64,
    pub centrifugal: f64,
    /// applied (F_x, F_y, F_z, M_x, M_y); the moments are ignored with an imposed tilt
    pub applied: [f64; 5],
    /// indices of the unknowns (3 with an imposed tilt, else 5)
    pub free: Vec<usize>,
    /// ℓ: half the row spacing, the moment arm of the residual scaling [m]
    pub arm: f64,
    pub force_scale: f64,
    /// half the axial clearance: the fallback step when nothing touches [m]
    free_play: f64,
    pub settings: TaperedLoadSettings,
}

/// One evaluation: the inner-ring residual and the roller states.
#[derive(Clone)]
pub(crate) struct RingState {
    pub x: [f64; 5],
    pub residual: [f64; 5],
    pub rollers: Vec<RollerState>,
}

impl<'a> RingProblem<'a> {
    pub fn new(
        b: &DoubleRowTaperedBearing,
        rows: &'a [RowRoller; 2],
        case: &TaperedLoadCase,
        settings: TaperedLoadSettings,
    ) -> Self {
        let z = b.rollers_per_row;
        let cage = b.epicyclic_cage_speed(case.inner_speed_rad_s);
        let centrifugal = rows[0].mass * cage * cage * rows[0].centre_of_mass_radius();
        let arm = 0.5 * b.row_spacing;
        let (moment, free) = match case.tilt {
            TiltCondition::Moment(m) => (m, vec![0, 1, 2, 3, 4]),
            TiltCondition::Imposed(_) => ([0.0; 2], vec![0, 1, 2]),
        };
        let applied = [
            case.radial_load_n,
            0.0,
            case.axial_load_n,
            moment[0],
            moment[1],
        ];
        let force_scale = [
            applied[0],
            applied[2],
            moment[0] / arm,
            moment[1] / arm,
            1.0,
        ]
        .iter()
        .fold(0.0_f64, |a, v| a.max(v.abs()));
        Self {
            rows,
            z,
            phase: [0.0, settings.row1_offset_pitch * TAU / z as f64],
            cage_speed: cage,
            centrifugal,
            applied,
            free,
            arm,
            force_scale,
            free_play: (0.5 * b.axial_clearance).max(DISPLACEMENT_UNIT),
            settings,
        }
    }

    /// Azimuth of roller `j` of row `k` [rad].
    pub fn azimuth(&self, k: usize, j: usize) -> f64 {
        self.phase[k] + TAU * j as f64 / self.z as f64
    }

    /// The cup line and centrifugal force of roller `j` of row `k` in its cone's frame.
    pub fn loading(&self, x: &[f64; 5], k: usize, j: usize) -> (PlaneMotion, RollerLoading) {
        let motion = PlaneMotion::at(x, self.azimuth(k, j));
        let loading = RollerLoading {
            cup: motion.line_to_ring(&self.rows[k].cup),
            centrifugal: rotated(Rz::new(self.centrifugal, 0.0), -motion.angle),
        };
        (motion, loading)
    }

    /// Residual (applied + roller forces on the inner ring) at `x`, starting every roller
    /// from its pose in `warm`.
    pub fn evaluate(&self, x: [f64; 5], warm: &[RollerState]) -> Result<RingState, QsError> {
        let floor = self.force_scale / (2 * self.z) as f64;
        let mut residual = self.applied;
        let mut rollers = Vec::with_capacity(2 * self.z);
        for k in 0..2 {
            for j in 0..self.z {
                let (motion, loading) = self.loading(&x, k, j);
                let start = warm
                    .get(k * self.z + j)
                    .map_or(RollerPose::default(), |s| s.pose);
                let st = self.rows[k].solve(
                    &loading,
                    start,
                    floor,
                    self.settings.roller_tolerance,
                    self.settings.max_roller_iterations,
                )?;
                let (force, moment) = self.inner_ring_wrench(k, &st, &motion);
                add_wrench(&mut residual, self.azimuth(k, j), force, moment);
                rollers.push(st);
            }
        }
        Ok(RingState {
            x,
            residual,
            rollers,
        })
    }

    /// Force and moment of one roller on the inner ring (cone and rib contacts), bearing frame.
    fn inner_ring_wrench(&self, k: usize, st: &RollerState, motion: &PlaneMotion) -> (Rz, f64) {
        let row = &self.rows[k];
        let rib = st.rib * row.rib_normal;
        let force = -(st.q[CONE] * row.cone.normal + rib);
        let moment = -(st.moment[CONE] - cross(st.sphere_centre, rib));
        motion.wrench_to_bearing(force, moment)
    }

    /// Force and moment on the roller from the cup plus its centrifugal force, bearing frame.
    pub fn cup_side_wrench(
        &self,
        st: &RollerState,
        loading: &RollerLoading,
        motion: &PlaneMotion,
    ) -> (Rz, f64) {
        let cup: &Line = &loading.cup;
        let force = st.q[CUP] * cup.normal + loading.centrifugal;
        let moment = st.moment[CUP] - cross(st.centre_of_mass, loading.centrifugal);
        motion.wrench_to_bearing(force, moment)
    }

    /// Scaled residual: forces over the force scale, moments over force scale × ℓ.
    pub fn scaled(&self, r: &[f64; 5]) -> [f64; 5] {
        std::array::from_fn(|i| r[i] / self.force_scale / if i < 3 { 1.0 } else { self.arm })
    }

    fn error(&self, s: &RingState) -> f64 {
        let r = self.scaled(&s.residual);
        self.free.iter().fold(0.0_f64, |a, &i| a.max(r[i].abs()))
    }

    /// Unknown `i` in units of [`DISPLACEMENT_UNIT`] (tilts times ℓ).
    fn unit(&self, i: usize) -> f64 {
        if i < 3 {
            DISPLACEMENT_UNIT
        } else {
            DISPLACEMENT_UNIT / self.arm
        }
    }

    /// Forward-difference Jacobian of the scaled residual by the scaled unknowns.
    fn jacobian(&self, s: &RingState) -> Result<Vec<f64>, QsError> {
        let n = self.free.len();
        let r0 = self.scaled(&s.residual);
        let size = self
            .free
            .iter()
            .fold(1.0_f64, |a, &i| a.max((s.x[i] / self.unit(i)).abs()));
        let h = self.settings.jacobian_step * size;
        let mut jac = vec![0.0; n * n];
        for (col, &i) in self.free.iter().enumerate() {
            let mut x = s.x;
            x[i] += h * self.unit(i);
            let r = self.scaled(&self.evaluate(x, &s.rollers)?.residual);
            for (row, &m) in self.free.iter().enumerate() {
                jac[row * n + col] = (r[m] - r0[m]) / h;
            }
        }
        Ok(jac)
    }

    /// Solves the ring equilibrium from `x0`.
    pub fn solve(&self, x0: [f64; 5]) -> Result<(RingState, usize), QsError> {
        let tol = self.settings.tolerance;
        let mut s = self.evaluate(x0, &[])?;
        for it in 0..self.settings.max_iterations {
            if self.error(&s) <= tol {
                return Ok((s, it));
            }
            s = self.step(s)?;
        }
        if self.error(&s) <= tol {
            return Ok((s, self.settings.max_iterations));
        }
        let r = self.scaled(&s.residual);
        let names = [
            "F_x / F",
            "F_y / F",
            "F_z / F",
            "M_x / (F ℓ)",
            "M_y / (F ℓ)",
        ];
        let residuals: Vec<(&str, f64)> = self.free.iter().map(|&i| (names[i], r[i])).collect();
        Err(QsError::not_converged(
            "tapered load distribution",
            self.settings.max_iterations,
            &residuals,
        ))
    }

    /// One Newton step (Levenberg–Marquardt damped when the plain step does not lower the
    /// residual), halved until the largest scaled residual falls.
    fn step(&self, s: RingState) -> Result<RingState, QsError> {
        let n = self.free.len();
        let jac = self.jacobian(&s)?;
        let r = self.scaled(&s.residual);
        let rf: Vec<f64> = self.free.iter().map(|&i| r[i]).collect();
        let e0 = self.error(&s);
        for lambda in [0.0, 1e-6, 1e-3, 1e-1, 1.0, 10.0] {
            let Some(d) = damped_step(&jac, &rf, n, lambda) else {
                continue;
            };
            let mut t = 1.0;
            for _ in 0..30 {
                let mut x = s.x;
                for (c, &i) in self.free.iter().enumerate() {
                    x[i] += t * d[c] * self.unit(i);
                }
                let next = self.evaluate(x, &s.rollers)?;
                if self.error(&next) < e0 {
                    return Ok(next);
                }
                t *= 0.5;
            }
        }
        // nothing touches or no step helps: move along the residual by half the free play
        let mut x = s.x;
        let step = self.free_play / DISPLACEMENT_UNIT;
        for &i in &self.free {
            x[i] += step * r[i] / e0.max(1e-300) * self.unit(i);
        }
        self.evaluate(x, &s.rollers)
    }
}

/// `(JᵀJ + λ diag JᵀJ) d = −Jᵀ r` (λ = 0: the Newton step `J d = −r`).
fn damped_step(jac: &[f64], r: &[f64], n: usize, lambda: f64) -> Option<Vec<f64>> {
    let (a, mut b) = if lambda == 0.0 {
        (jac.to_vec(), r.iter().map(|v| -v).collect::<Vec<_>>())
    } else {
        let mut a = vec![0.0; n * n];
        let mut b = vec![0.0; n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = (0..n).map(|k| jac[k * n + i] * jac[k * n + j]).sum();
            }
            b[i] = -(0..n).map(|k| jac[k * n + i] * r[k]).sum::<f64>();
        }
        for i in 0..n {
            a[i * n + i] *= 1.0 + lambda;
        }
        (a, b)
    };
    let lu = DenseLu::new(n, a).ok()?;
    lu.solve(&mut b);
    b.iter().all(|v| v.is_finite()).then_some(b)
}

/// Adds an in-plane force `(F_r, F_z)` and moment `m` (vector along e_t) at azimuth `psi` to
/// the 3-D wrench (F_x, F_y, F_z, M_x, M_y).
pub(crate) fn add_wrench(w: &mut [f64; 5], psi: f64, force: Rz, moment: f64) {
    let (s, c) = psi.sin_cos();
    w[0] += force.r * c;
    w[1] += force.r * s;
    w[2] += force.z;
    w[3] -= moment * s;
    w[4] += moment * c;
}
