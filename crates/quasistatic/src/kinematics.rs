//! Kinematics in the inverted motion, cage stopped (SPEC §5.3, seed 001).
//!
//! Sign convention: every speed is a component along the positive circumferential direction
//! e_θ (the sense of positive ring speeds). In the frame rotating with the cage (ω₀):
//!
//! * ring surface speeds `U_i = (ω_в − ω₀) d_вр/2`, `U_o = (ω_н − ω₀) D_нр/2`; seed 001's
//!   V_в = d_вр(ω₀ − ω_в)/2 = −U_i and V_н = D_нр(ω_н − ω₀)/2 = U_o;
//! * the roller spins at ω_w about its own axis (positive in the bearing's positive sense);
//!   its surface moves at `+ω_w R_w` at the outer contact and `−ω_w R_w` at the inner one;
//! * sliding speeds (ring minus roller, the lubrication crate's v = v₁ − v₂ with surface 1 the
//!   ring): inner `v_i = U_i + ω_w R_w`, outer `v_o = U_o − ω_w R_w` (seed 001:
//!   V_sв = V_w − V_в = v_i, V_sн = V_н − V_w = v_o with V_w = ω_w R_w);
//! * rolling (entrainment) speeds `u_i = (U_i − ω_w R_w)/2`, `u_o = (U_o + ω_w R_w)/2`.
//!
//! Epicyclic (no-slip) cage speed ω₀₀ = (d_вр ω_в + D_нр ω_н)/(d_вр + D_нр)
//! ([`rolldyn_geometry::epicyclic_cage_speed`], on the operating raceway diameters): both
//! contacts roll without sliding, d_вр(ω₀₀ − ω_в) = D_нр(ω_н − ω₀₀). This is seed 001's
//! (d_вр ω_в + D_нр ω_н)/(2(D_нр − D_wp)) with the roller touching both raceways (they differ
//! by G/(2 d_m) ≈ 10⁻⁴ with clearance G; the exact form makes ε₀ = 0 the pure rolling state).
//! Cage slip: ω₀ = ω₀₀(1 − ε₀) (SPEC §5.3), negative when the cage runs faster than epicyclic.

use crate::options::SlipReference;
/// Cage slip ε₀ (SPEC §5.3): the geometry crate's definition.
pub use rolldyn_geometry::cage_slip;
use serde::Serialize;

/// Which ring rotates (reported).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum KinematicCase {
    /// Both rings at rest.
    Stationary,
    /// Inner ring rotating, outer ring at rest (ordinary support bearing).
    InnerRotating,
    /// Outer ring rotating, inner ring at rest.
    OuterRotating,
    /// Both rings rotating (intershaft bearing), in the same or opposite senses.
    BothRotating,
}

impl KinematicCase {
    /// Classifies ring speeds.
    pub fn of(inner: f64, outer: f64) -> Self {
        match (inner != 0.0, outer != 0.0) {
            (false, false) => KinematicCase::Stationary,
            (true, false) => KinematicCase::InnerRotating,
            (false, true) => KinematicCase::OuterRotating,
            (true, true) => KinematicCase::BothRotating,
        }
    }
}

/// Speeds and radii of one kinematic state (cage speed given).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics {
    /// ω_в, rad/s.
    pub inner_speed: f64,
    /// ω_н, rad/s.
    pub outer_speed: f64,
    /// ω₀, rad/s.
    pub cage_speed: f64,
    /// d_вр/2, m.
    pub inner_radius: f64,
    /// D_нр/2, m.
    pub outer_radius: f64,
    /// D_wp/2, m.
    pub roller_radius: f64,
}

impl Kinematics {
    /// Inner-ring surface speed in the cage frame U_i = (ω_в − ω₀) r_i (= −V_в), m/s.
    pub fn inner_surface_speed(&self) -> f64 {
        (self.inner_speed - self.cage_speed) * self.inner_radius
    }

    /// Outer-ring surface speed in the cage frame U_o = (ω_н − ω₀) r_o (= V_н), m/s.
    pub fn outer_surface_speed(&self) -> f64 {
        (self.outer_speed - self.cage_speed) * self.outer_radius
    }

    /// Roller spin without sliding on the outer raceway, U_o/R_w, rad/s.
    pub fn no_slip_spin_outer(&self) -> f64 {
        self.outer_surface_speed() / self.roller_radius
    }

    /// Roller spin without sliding on the inner raceway, −U_i/R_w, rad/s.
    pub fn no_slip_spin_inner(&self) -> f64 {
        -self.inner_surface_speed() / self.roller_radius
    }

    /// Sliding speed ring − roller at the inner contact, v_i = U_i + ω_w R_w, m/s.
    pub fn inner_sliding(&self, spin: f64) -> f64 {
        self.inner_surface_speed() + spin * self.roller_radius
    }

    /// Sliding speed ring − roller at the outer contact, v_o = U_o − ω_w R_w, m/s.
    pub fn outer_sliding(&self, spin: f64) -> f64 {
        self.outer_surface_speed() - spin * self.roller_radius
    }

    /// Rolling speed (U_i − ω_w R_w)/2 at the inner contact, m/s.
    pub fn inner_rolling(&self, spin: f64) -> f64 {
        0.5 * (self.inner_surface_speed() - spin * self.roller_radius)
    }

    /// Rolling speed (U_o + ω_w R_w)/2 at the outer contact, m/s.
    pub fn outer_rolling(&self, spin: f64) -> f64 {
        0.5 * (self.outer_surface_speed() + spin * self.roller_radius)
    }

    /// The reference ring of the per-roller slip: `true` = outer.
    pub fn reference_is_outer(&self, reference: SlipReference) -> bool {
        match reference {
            SlipReference::Outer => true,
            SlipReference::Inner => false,
            SlipReference::FasterRing => self.outer_speed.abs() > self.inner_speed.abs(),
        }
    }

    /// Roller slip ε_w relative to the reference ring: V_w = V_ref (1 − ε_w) (seed 001 with the
    /// outer ring as reference); 0 when the reference ring does not move relative to the cage.
    pub fn roller_slip(&self, spin: f64, reference: SlipReference) -> f64 {
        let vw = spin * self.roller_radius;
        if self.reference_is_outer(reference) {
            let v = self.outer_surface_speed();
            if v.abs() > 0.0 { 1.0 - vw / v } else { 0.0 }
        } else {
            let v = -self.inner_surface_speed();
            if v.abs() > 0.0 { 1.0 - vw / v } else { 0.0 }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rolldyn_geometry::epicyclic_cage_speed;

    #[test]
    fn epicyclic_state_has_no_sliding() {
        let (di, do_) = (0.065, 0.095);
        for (wi, wo) in [(300.0, 0.0), (0.0, 250.0), (850.0, 1370.0), (500.0, -200.0)] {
            let w0 = epicyclic_cage_speed(di, do_, wi, wo);
            let k = Kinematics {
                inner_speed: wi,
                outer_speed: wo,
                cage_speed: w0,
                inner_radius: 0.5 * di,
                outer_radius: 0.5 * do_,
                roller_radius: 0.0075,
            };
            let spin = k.no_slip_spin_outer();
            assert!((k.no_slip_spin_inner() - spin).abs() < 1e-12 * spin.abs().max(1.0));
            assert!(k.inner_sliding(spin).abs() < 1e-12);
            assert!(k.outer_sliding(spin).abs() < 1e-12);
            assert!(k.roller_slip(spin, SlipReference::FasterRing).abs() < 1e-12);
        }
    }

    #[test]
    fn seed001_epicyclic_formula_at_zero_clearance() {
        // d_i + D_o = 2(D_o − D_w) when D_o = d_i + 2 D_w
        let (di, dw) = (0.11, 0.011);
        let do_ = di + 2.0 * dw;
        let (wi, wo) = (853.7, 1368.4);
        let seed = (di * wi + do_ * wo) / (2.0 * (do_ - dw));
        assert!((epicyclic_cage_speed(di, do_, wi, wo) - seed).abs() < 1e-12 * seed);
    }
}
