//! One roller in its axial plane, in the frame of the cone (Harris & Kotzalas, Advanced
//! Concepts of Bearing Technology, ch. 1 "tapered roller bearings": the roller loaded by the
//! cone, the cup, the large rib and its centrifugal force).
//!
//! The large rib is rigid (Harris): the roller's end sphere stays on the rib face and slides
//! along it, so the roller has two free coordinates, the lift `v` of its mid-point normal to
//! its axis (away from the cone) and its tilt `φ` about that point; the shift along the axis
//! that keeps the sphere on the face follows from both. The rib force is the constraint force
//! and drops out of the two equilibrium equations; it follows afterwards from the force
//! balance along the face normal. The raceway contacts are slice sums (SPEC §2.1): a slice at
//! `x` from the mid-point penetrates a raceway line by `δ = reach − dist(c(x), line)` and
//! carries `Q = k δ^n`, so that a tilt between the raceways loads the roller's edge.
//!
//! The two equations are the gradient of the potential energy
//! `E(v, φ) = Σ k δ^{n+1}/(n+1) − F_c · c_cm(v, φ)`, minimised by Gauss–Newton steps with a
//! backtracking line search on `E`.

use super::plane::{Line, cross, rotated};
use crate::QsError;
use rolldyn_contact::slices::SliceLaw;
use rolldyn_geometry::{DoubleRowTaperedBearing, Rz};

/// Raceway index: cone (inner) and cup (outer).
pub(crate) const CONE: usize = 0;
pub(crate) const CUP: usize = 1;

/// Approaches up to this are taken as no contact [m]: a seated roller touches its cone with
/// an approach of zero up to the rounding of its ≈ 0.1 m coordinates (≈ 1e-17 m), and a
/// contact with a vanishing stiffness k n δ^(n−1) would stall the Newton steps.
const ROUNDING_APPROACH: f64 = 1e-13;

/// Largest Newton step of the lift and of the tilt times L/2 [m]: 5 µm, a fraction of the
/// elastic approaches of a loaded roller, keeps a step on a barely loaded roller bounded.
const MAX_STEP: f64 = 5e-6;

/// A roller of one row, seated on the cone and the large rib, in the cone's frame.
#[derive(Debug, Clone)]
pub(crate) struct RowRoller {
    /// roller mid-point and unit axis (toward the large end) when seated
    mid: Rz,
    axis: Rz,
    /// unit normal to the axis, away from the cone
    lift: Rz,
    /// end-sphere centre's position on the axis from the mid-point
    sphere: f64,
    /// unit normal of the large-rib face toward the roller (rigid rib)
    pub rib_normal: Rz,
    pub cone: Line,
    /// the cup raceway in the bearing frame
    pub cup: Line,
    /// slice positions from the mid-point, reaches, law coefficients and exponents
    x: Vec<f64>,
    reach: Vec<f64>,
    k: [Vec<f64>; 2],
    n: [f64; 2],
    /// centre of mass on the axis from the mid-point; roller mass
    x_cm: f64,
    pub mass: f64,
    /// half the working length: the length that turns the tilt into a displacement
    pub half_length: f64,
}

/// The roller's free coordinates: lift `v` [m] and tilt `φ` [rad] relative to the cone.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct RollerPose {
    pub v: f64,
    pub phi: f64,
}

/// The environment of one roller: the cup line and the centrifugal force, in the cone frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RollerLoading {
    pub cup: Line,
    pub centrifugal: Rz,
}

/// Contact forces and equilibrium terms of one roller at one pose.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct RollerState {
    pub pose: RollerPose,
    /// total normal force on cone and cup [N]
    pub q: [f64; 2],
    /// largest slice force on cone and cup [N]
    pub slice_max: [f64; 2],
    /// moment of the raceway forces about the cone-frame origin, `z F_r − r F_z` [N·m]
    pub moment: [f64; 2],
    /// rib force along the rib normal [N] and the end-sphere centre (on its line of action)
    pub rib: f64,
    pub sphere_centre: Rz,
    /// centre of mass (where the centrifugal force acts)
    pub centre_of_mass: Rz,
    /// generalised forces −∂E/∂(v, φ) [N, N·m], Gauss–Newton Hessian, energy [J]
    gradient: [f64; 2],
    hessian: [[f64; 2]; 2],
    energy: f64,
    /// loaded slices
    loaded: usize,
}

/// Where the roller's points are for a pose, with their derivatives by (v, φ).
struct Placement {
    mid: Rz,
    axis: Rz,
    d_mid: [Rz; 2],
    d_axis: [Rz; 2],
}

impl RowRoller {
    /// Roller of row `k` of `b` with the cone and cup slice laws `laws`.
    pub fn new(
        b: &DoubleRowTaperedBearing,
        k: usize,
        laws: &[SliceLaw; 2],
    ) -> Result<Self, QsError> {
        let row = b.row(k);
        let roller = &b.roller;
        let stack = roller.slices();
        let mut coefficients = [Vec::new(), Vec::new()];
        let mut exponents = [0.0; 2];
        for (race, law) in laws.iter().enumerate() {
            for &l in &stack.length {
                let form = law
                    .power_form(l)
                    .map_err(|e| QsError::Contact(e.to_string()))?;
                coefficients[race].push(form.coefficient);
                exponents[race] = form.exponent;
            }
        }
        let line = |l: &rolldyn_geometry::RacewayLine| Line {
            point: l.point,
            normal: l.normal,
        };
        let axis = row.roller_axis;
        let mut lift = axis.perpendicular();
        if lift.dot(row.cone.normal) < 0.0 {
            lift = -lift;
        }
        Ok(Self {
            mid: row.roller_mid,
            axis,
            lift,
            sphere: roller.sphere_centre(),
            rib_normal: row.large_rib.normal,
            cone: line(&row.cone),
            cup: line(&row.cup),
            reach: roller.generatrix_reach(&stack),
            x: stack.position,
            k: coefficients,
            n: exponents,
            x_cm: roller.centre_of_mass_offset(),
            mass: roller.mass_properties().mass,
            half_length: roller.working_half_length(),
        })
    }

    /// Approach of cone plus cup of the seated roller carrying `q` evenly on all slices [m]
    /// (a start value of the ring iteration).
    pub fn approach_for_load(&self, q: f64) -> f64 {
        let per_slice = q / self.x.len() as f64;
        let middle = self.x.len() / 2;
        (0..2)
            .map(|race| (per_slice / self.k[race][middle]).powf(1.0 / self.n[race]))
            .sum()
    }

    /// Largest interference of the seated roller (on cone and rib) with the cup [m]: the
    /// rigid-body approach that the contacts share.
    #[cfg(test)]
    pub fn seated_cup_interference(&self, loading: &RollerLoading) -> f64 {
        let p = self.place(RollerPose::default());
        (0..self.x.len())
            .map(|i| self.reach[i] - loading.cup.distance(p.mid + self.x[i] * p.axis))
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Distance of the seated roller's centre of mass from the bearing axis [m].
    pub fn centre_of_mass_radius(&self) -> f64 {
        (self.mid + self.x_cm * self.axis).r
    }

    /// The rib constraint: the end-sphere centre moves along the rib face, so the mid-point
    /// shifts along the axis by `s` with `n_f · (v e_v + s e_u + x_s (u(φ) − u₀)) = 0`.
    fn place(&self, pose: RollerPose) -> Placement {
        let nf = self.rib_normal;
        let along = nf.dot(self.axis);
        let axis = rotated(self.axis, pose.phi);
        let d_axis_phi = rotated(self.axis.perpendicular(), pose.phi);
        let shift = -(pose.v * nf.dot(self.lift) + self.sphere * nf.dot(axis - self.axis)) / along;
        let d_shift = [
            -nf.dot(self.lift) / along,
            -self.sphere * nf.dot(d_axis_phi) / along,
        ];
        Placement {
            mid: self.mid + pose.v * self.lift + shift * self.axis,
            axis,
            d_mid: [self.lift + d_shift[0] * self.axis, d_shift[1] * self.axis],
            d_axis: [Rz::default(), d_axis_phi],
        }
    }

    /// Approach of slice `i` to the raceway `line` in `placement`: its reach less the distance
    /// of its centre from the line [m].
    fn slice_approach(&self, i: usize, placement: &Placement, line: &Line) -> f64 {
        self.reach[i] - line.distance(placement.mid + self.x[i] * placement.axis)
    }

    /// Slice forces on the cone and on the cup at `pose` [N], in the order of the slices.
    pub fn slice_loads(&self, pose: RollerPose, loading: &RollerLoading) -> [Vec<f64>; 2] {
        let p = self.place(pose);
        [(CONE, &self.cone), (CUP, &loading.cup)].map(|(race, line)| {
            (0..self.x.len())
                .map(|i| {
                    let delta = self.slice_approach(i, &p, line);
                    if delta <= ROUNDING_APPROACH {
                        0.0
                    } else {
                        self.k[race][i] * delta.powf(self.n[race])
                    }
                })
                .collect()
        })
    }

    /// Contact forces, generalised forces and energy at `pose`.
    pub fn evaluate(&self, pose: RollerPose, loading: &RollerLoading) -> RollerState {
        let p = self.place(pose);
        let mut st = RollerState {
            pose,
            ..RollerState::default()
        };
        for (race, line) in [(CONE, &self.cone), (CUP, &loading.cup)] {
            let n = self.n[race];
            for i in 0..self.x.len() {
                let centre = p.mid + self.x[i] * p.axis;
                let delta = self.slice_approach(i, &p, line);
                if delta <= ROUNDING_APPROACH {
                    continue;
                }
                let q = self.k[race][i] * delta.powf(n);
                let stiffness = n * q / delta;
                // ∂δ/∂q = −n_line · ∂c/∂q
                let g = [0, 1].map(|j| -line.normal.dot(p.d_mid[j] + self.x[i] * p.d_axis[j]));
                for a in 0..2 {
                    st.gradient[a] -= q * g[a];
                    for b in 0..2 {
                        st.hessian[a][b] += stiffness * g[a] * g[b];
                    }
                }
                st.energy += q * delta / (n + 1.0);
                st.q[race] += q;
                st.slice_max[race] = st.slice_max[race].max(q);
                let contact = centre - self.reach[i] * line.normal;
                st.moment[race] -= cross(contact, q * line.normal);
                st.loaded += 1;
            }
        }
        // potential of the centrifugal force, from the seated position (keeps E small)
        let cm = p.mid + self.x_cm * p.axis;
        st.centre_of_mass = cm;
        st.energy -= loading
            .centrifugal
            .dot(cm - (self.mid + self.x_cm * self.axis));
        for j in 0..2 {
            st.gradient[j] += loading
                .centrifugal
                .dot(p.d_mid[j] + self.x_cm * p.d_axis[j]);
        }
        st.sphere_centre = p.mid + self.sphere * p.axis;
        // rib force from the balance along the face normal (Harris: the flange load)
        let others =
            st.q[CONE] * self.cone.normal + st.q[CUP] * loading.cup.normal + loading.centrifugal;
        st.rib = -self.rib_normal.dot(others);
        st
    }

    /// Force scale of a roller's convergence test: its loads, at least `floor` [N].
    fn scale(&self, st: &RollerState, loading: &RollerLoading, floor: f64) -> f64 {
        (st.q[CONE] + st.q[CUP] + loading.centrifugal.norm()).max(floor)
    }

    fn converged(&self, st: &RollerState, loading: &RollerLoading, floor: f64, tol: f64) -> bool {
        let s = self.scale(st, loading, floor) * tol;
        st.gradient[0].abs() <= s && st.gradient[1].abs() <= s * self.half_length
    }

    /// Lift that brings the roller to its first touch of the cup (no slice loaded, the
    /// centrifugal force pushing it out) from `pose`.
    fn lift_to_cup(&self, pose: RollerPose, loading: &RollerLoading) -> f64 {
        let p = self.place(pose);
        let mut step = f64::INFINITY;
        for i in 0..self.x.len() {
            let centre = p.mid + self.x[i] * p.axis;
            let gap = loading.cup.distance(centre) - self.reach[i];
            let rate = -loading.cup.normal.dot(p.d_mid[0]);
            if rate > 0.0 {
                step = step.min(gap / rate);
            }
        }
        step
    }

    /// The roller's equilibrium from `start`: Gauss–Newton on E with a backtracking line
    /// search; `floor` is the least force scale of the residual test [N].
    pub fn solve(
        &self,
        loading: &RollerLoading,
        start: RollerPose,
        floor: f64,
        tol: f64,
        max_iterations: usize,
    ) -> Result<RollerState, QsError> {
        let mut st = self.evaluate(start, loading);
        for _ in 0..max_iterations {
            if self.converged(&st, loading, floor, tol) {
                return Ok(st);
            }
            if st.loaded == 0 {
                if loading.centrifugal.norm() == 0.0 {
                    // free between the raceways: by convention seated on cone and rib,
                    // unloaded (the seated cone approach is zero up to rounding)
                    let seated = self.evaluate(RollerPose::default(), loading);
                    return Ok(RollerState {
                        sphere_centre: seated.sphere_centre,
                        centre_of_mass: seated.centre_of_mass,
                        ..RollerState::default()
                    });
                }
                let lift = self.lift_to_cup(st.pose, loading);
                if !lift.is_finite() {
                    break;
                }
                let pose = RollerPose {
                    v: st.pose.v + lift + 100.0 * ROUNDING_APPROACH,
                    phi: st.pose.phi,
                };
                st = self.evaluate(pose, loading);
                continue;
            }
            st = self.line_search(&st, loading)?;
        }
        if self.converged(&st, loading, floor, tol) {
            return Ok(st);
        }
        let s = self.scale(&st, loading, floor);
        Err(QsError::not_converged(
            "tapered roller equilibrium",
            max_iterations,
            &[
                ("lift force / load", st.gradient[0] / s),
                (
                    "tilt moment / (load · L/2)",
                    st.gradient[1] / (s * self.half_length),
                ),
            ],
        ))
    }

    /// Size of the generalised forces with the tilt moment over L/2 [N].
    fn gradient_norm(&self, st: &RollerState) -> f64 {
        st.gradient[0].hypot(st.gradient[1] / self.half_length)
    }

    /// One damped Gauss–Newton step: `(H + λ diag H) d = −∇E`, halved until E decreases.
    fn line_search(
        &self,
        st: &RollerState,
        loading: &RollerLoading,
    ) -> Result<RollerState, QsError> {
        let h = st.hessian;
        let g = st.gradient;
        let mut lambda = 1e-10;
        for _ in 0..12 {
            let a = h[0][0] * (1.0 + lambda) + 1e-300;
            let d = h[1][1] * (1.0 + lambda) + 1e-300;
            let det = a * d - h[0][1] * h[1][0];
            let mut step = [
                (d * g[0] - h[0][1] * g[1]) / det,
                (a * g[1] - h[1][0] * g[0]) / det,
            ];
            let size = step[0].abs().max(step[1].abs() * self.half_length);
            if size > MAX_STEP {
                step = step.map(|v| v * MAX_STEP / size);
            }
            let mut t = 1.0;
            for _ in 0..40 {
                let pose = RollerPose {
                    v: st.pose.v + t * step[0],
                    phi: st.pose.phi + t * step[1],
                };
                let next = self.evaluate(pose, loading);
                let decrease = t * (g[0] * step[0] + g[1] * step[1]);
                // near the solution E is flat to rounding: a smaller gradient then decides
                if next.energy <= st.energy - 1e-4 * decrease
                    || self.gradient_norm(&next) < 0.5 * self.gradient_norm(st)
                {
                    return Ok(next);
                }
                t *= 0.5;
            }
            lambda = (lambda * 100.0).max(1e-6);
        }
        // no decrease representable: E is flat to rounding here, keep the point
        Ok(*st)
    }
}
