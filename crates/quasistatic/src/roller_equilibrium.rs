//! Equilibrium of one roller in the cage frame (SPEC §5.4, seed 001).
//!
//! Forces along e_θ on the roller (positive in the bearing's positive sense): the raceway
//! friction forces F_fв = μ_i Q_i and F_fн = μ_o Q_o (μ from `rolldyn_lubrication::traction`,
//! sign of the sliding speed ring − roller, see [`crate::kinematics`]), the rib friction
//! 2F_fб of the two roller-end films and the cage-bar force. The tangential balance gives the
//! roller ↔ bar normal force (seed 001 F_S(i) = ±F_fв ± F_fн ± 2F_fб):
//!
//! P = F_fв + F_fн + 2F_fб + F_D  (the force the roller exerts on the cage, along e_θ),
//! Q_bar = |P|, with F_D the drag of the air–oil mixture on the orbiting roller (acting at its
//! centre: no moment about its axis; Harris & Kotzalas, `rolldyn_lubrication::mixture::roller_drag_factor`).
//!
//! Moment about the roller axis (seed 001 ΣT(ε_w), derived here with vectors so that it holds
//! for either sense of rotation):
//!
//! ΣT = R_w (F_fн − F_fв) + d_б·2F_fб − μ_s Q_bar R_w − f_к(Q_i + Q_o) sgn ω_w − c_sc ω_w = 0,
//!
//! * d_б = signed radial offset of the rib contact (mid-height of the rib) from the roller
//!   centre: seed 001's lever D_wp/2 − (D_нр − D_б1)/4 for ribs on the outer ring;
//! * μ_s = bar friction coefficient at the bar sliding speed ω_w R_w (it always opposes the
//!   spin); its radial force on the cage gives the cage the moment +μ_s Q_bar R_w;
//! * rolling resistance T_к = f_к F per raceway contact (seed 001), opposing the spin;
//! * roller-end ↔ pocket films T_sc = c_sc ω_w, c_sc = 2 · π μ r_e⁴/(2h) (SPEC §4.9 proposal:
//!   Newtonian disc shear, h = half the pocket end clearance, viscosity at the mean bearing
//!   temperature).
//!
//! Rib film (seed 001): h_б = Δ_бр/2, τ = μ₀ V_sб/h_б with V_sб the sliding speed rib − roller
//! end at the middle of the contact patch and the viscosity at the rib ring's temperature; the
//! area is the overlap of the roller end face with the rib face (⚠ F-43 proposal), a circular
//! segment of the end face.
//!
//! The unknown is the roller spin ω_w (equivalently ε_w); ΣT(ω_w) decreases with ω_w, and is
//! solved by the safeguarded Newton of [`rolldyn_numerics::root1d`] (secant slope). The unloaded zone (Q_i = 0,
//! Q_o = F_c) uses the same equations (SPEC §5.4 proposal).

use crate::conditions::QuasiStaticContactTemperatures;
use crate::error::QsError;
use crate::friction::BarLaw;
use crate::kinematics::Kinematics;
use rolldyn_lubrication::traction::regularisation;
use rolldyn_lubrication::{ContactGeometry, ContactState, Traction, TractionModel, traction};
use rolldyn_numerics::{Bracket, Derivative, Point, Root1dOptions, find_root};
use std::convert::Infallible;

/// Geometry and surface data of one contact type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSetup {
    /// Reduced radius R' in the rolling direction, m.
    pub reduced_radius: f64,
    /// Reduced modulus E' (1.13), Pa.
    pub reduced_modulus: f64,
    /// R_a of (ring or cage, roller), m.
    pub roughness: [f64; 2],
    /// Contact length used when the load distribution gives none, m.
    pub default_length: f64,
}

/// Rib (flange) film of the two roller ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RibFilm {
    /// The ribs belong to the outer ring.
    pub outer_ring: bool,
    /// Radius of the middle of the contact patch from the bearing axis, m.
    pub radius_m: f64,
    /// Signed radial offset of that point from the roller centre d_б, m.
    pub lever_m: f64,
    /// μ A / h of one end film times 2 (both ends), N·s/m.
    pub coefficient: f64,
}

/// Everything a roller equation needs besides its loads.
#[derive(Debug, Clone)]
pub struct RollerEnv<'a> {
    /// Raceway traction model.
    pub traction: &'a TractionModel,
    /// Bar friction law.
    pub bar: &'a BarLaw,
    /// Kinematics at the current cage speed.
    pub kin: Kinematics,
    /// Inner raceway contact data.
    pub inner: ContactSetup,
    /// Outer raceway contact data.
    pub outer: ContactSetup,
    /// Roller ↔ bar contact data.
    pub bar_contact: ContactSetup,
    /// Oil temperatures of the contacts, K.
    pub temperatures: QuasiStaticContactTemperatures,
    /// Rib film (`None`: no guiding ribs or switched off).
    pub rib: Option<RibFilm>,
    /// c_sc of T_sc = c_sc ω_w (both ends), N·m·s.
    pub pocket_coefficient: f64,
    /// f_к, m.
    pub rolling_friction_m: f64,
    /// Drag of the air–oil mixture on the orbiting roller along e_θ, −k v|v| with
    /// v = ω₀ d_m/2 ([`crate::conditions::DragInputs::roller_drag_kg_m`]), N.
    pub orbital_drag_n: f64,
}

/// Normal loads of one roller from the load distribution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerLoads {
    /// Q_i (F_в), N.
    pub inner_n: f64,
    /// Q_o (F_н), N.
    pub outer_n: f64,
    /// Effective inner contact length, m.
    pub inner_length_m: f64,
    /// Effective outer contact length, m.
    pub outer_length_m: f64,
}

/// State of one roller at a given spin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerEval {
    /// ω_w, rad/s.
    pub spin: f64,
    /// Inner contact traction (`None` when unloaded).
    pub inner: Option<Traction>,
    /// Outer contact traction (`None` when unloaded).
    pub outer: Option<Traction>,
    /// Inner contact state (for the scuffing search).
    pub inner_state: ContactState,
    /// Outer contact state.
    pub outer_state: ContactState,
    /// F_fв on the roller along e_θ, N.
    pub inner_force: f64,
    /// F_fн on the roller along e_θ, N.
    pub outer_force: f64,
    /// 2F_fб on the roller along e_θ, N.
    pub rib_force: f64,
    /// Sliding speed rib − roller end at the patch middle, m/s.
    pub rib_sliding: f64,
    /// Force on the cage along e_θ, P, N.
    pub push: f64,
    /// Bar friction coefficient (signed with ω_w).
    pub bar_mu: f64,
    /// Bar traction details (traction-model bar law).
    pub bar: Option<Traction>,
    /// T_sc on the roller, N·m.
    pub pocket_moment: f64,
    /// Rolling-resistance moment on the roller, N·m.
    pub rolling_moment: f64,
    /// ΣT, N·m.
    pub moment: f64,
}

impl RollerEnv<'_> {
    fn state(
        &self,
        c: &ContactSetup,
        q: f64,
        length: f64,
        rolling: f64,
        sliding: f64,
        t: f64,
    ) -> ContactState {
        ContactState {
            normal_force_n: q,
            geometry: ContactGeometry::Line {
                length_m: if length > 0.0 {
                    length
                } else {
                    c.default_length
                },
            },
            reduced_radius_m: c.reduced_radius,
            reduced_modulus_pa: c.reduced_modulus,
            rolling_speed_m_s: rolling,
            sliding_speed_m_s: sliding,
            temperature_k: t,
            roughness_ra_m: c.roughness,
            film_thickness_m: None,
        }
    }

    /// Evaluates the roller at spin `spin`.
    pub fn evaluate(&self, loads: &RollerLoads, spin: f64) -> RollerEval {
        let k = &self.kin;
        let rw = k.roller_radius;
        let si = self.state(
            &self.inner,
            loads.inner_n,
            loads.inner_length_m,
            k.inner_rolling(spin),
            k.inner_sliding(spin),
            self.temperatures.inner,
        );
        let so = self.state(
            &self.outer,
            loads.outer_n,
            loads.outer_length_m,
            k.outer_rolling(spin),
            k.outer_sliding(spin),
            self.temperatures.outer,
        );
        let ti = (loads.inner_n > 0.0).then(|| traction(&si, self.traction));
        let to = (loads.outer_n > 0.0).then(|| traction(&so, self.traction));
        let fi = ti.map_or(0.0, |t| t.coefficient * loads.inner_n);
        let fo = to.map_or(0.0, |t| t.coefficient * loads.outer_n);
        let (rib_force, rib_sliding, rib_moment) = match &self.rib {
            Some(r) => {
                let ring = if r.outer_ring {
                    k.outer_speed
                } else {
                    k.inner_speed
                };
                let v = (ring - k.cage_speed) * r.radius_m - spin * r.lever_m;
                let f = r.coefficient * v;
                (f, v, r.lever_m * f)
            }
            None => (0.0, 0.0, 0.0),
        };
        let push = fi + fo + rib_force + self.orbital_drag_n;
        let q_bar = push.abs();
        let v_bar = spin * rw;
        let sb = self.state(
            &self.bar_contact,
            q_bar,
            0.0,
            0.5 * v_bar,
            v_bar,
            self.temperatures.cage_bar,
        );
        let (bar_mu, bar) = if q_bar > 0.0 {
            self.bar.eval(&sb)
        } else {
            (0.0, None)
        };
        let pocket_moment = -self.pocket_coefficient * spin;
        let rolling_moment = -self.rolling_friction_m
            * (loads.inner_n + loads.outer_n)
            * regularisation(v_bar, 1e-3);
        let moment =
            rw * (fo - fi) + rib_moment - bar_mu * q_bar * rw + pocket_moment + rolling_moment;
        RollerEval {
            spin,
            inner: ti,
            outer: to,
            inner_state: si,
            outer_state: so,
            inner_force: fi,
            outer_force: fo,
            rib_force,
            rib_sliding,
            push,
            bar_mu,
            bar,
            pocket_moment,
            rolling_moment,
            moment,
        }
    }

    /// Solves ΣT(ω_w) = 0 from the guess `guess` (warm start) or the no-slip spin on the more
    /// loaded raceway. `tol` is the relative moment tolerance, `fd_rel`/`fd_min` the
    /// finite-difference step, `max_evals` the budget.
    pub fn solve(
        &self,
        loads: &RollerLoads,
        guess: Option<f64>,
        tol: f64,
        fd_rel: f64,
        fd_min: f64,
        max_evals: usize,
    ) -> Result<(RollerEval, usize), QsError> {
        let k = &self.kin;
        let so = k.no_slip_spin_outer();
        let si = k.no_slip_spin_inner();
        let w = so.abs().max(si.abs());
        let lo = so.min(si).min(0.0) - 0.5 * w - 1.0;
        let hi = so.max(si).max(0.0) + 0.5 * w + 1.0;
        let x0 = guess.unwrap_or(if loads.inner_n > loads.outer_n {
            si
        } else {
            so
        });
        let scale = k.roller_radius * (loads.inner_n + loads.outer_n) + 1e-9;
        let opts = Root1dOptions {
            bracket: Bracket::Search {
                limits: (lo, hi),
                fd_step: (fd_rel * w).max(fd_min),
                max_first_step: 0.05 * (w + 1.0),
            },
            derivative: Derivative::Secant,
            x_tol: 1e-12 * (w + 1.0),
            max_evaluations: max_evals,
            ..Root1dOptions::default()
        };
        let Ok(root) = find_root(
            |x| {
                let moment = self.evaluate(loads, x).moment / scale;
                Ok::<_, Infallible>(Point::residual(moment, tol))
            },
            x0,
            &opts,
        );
        if !root.converged() {
            return Err(QsError::not_converged(
                "roller moment equation",
                root.evaluations,
                &[
                    ("roller moment / (R_w ΣQ)", root.value),
                    ("roller spin / (rad/s)", root.x),
                ],
            ));
        }
        Ok((self.evaluate(loads, root.x), root.evaluations))
    }
}

/// Area of the part of a disc of radius `r` lying farther than `r − h` from its centre on one
/// side (circular segment of height `h`), m².
pub fn circular_segment_area(r: f64, h: f64) -> f64 {
    let h = h.clamp(0.0, 2.0 * r);
    let a = r - h;
    r * r * (a / r).clamp(-1.0, 1.0).acos() - a * (r * r - a * a).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_area_limits() {
        let r = 0.007;
        assert!(circular_segment_area(r, 0.0).abs() < 1e-18);
        let half = circular_segment_area(r, r);
        assert!((half - 0.5 * std::f64::consts::PI * r * r).abs() < 1e-15);
        let full = circular_segment_area(r, 2.0 * r);
        assert!((full - std::f64::consts::PI * r * r).abs() < 1e-15);
    }
}
