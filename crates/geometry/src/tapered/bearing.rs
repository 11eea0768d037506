//! The double-row tapered roller bearing (seed 000 §3.2) and its derived dimensions.

use super::cage::TaperedCage;
use super::rib::LargeRib;
use super::roller::TaperedRoller;
use super::wear::TaperedWear;
use crate::bearing::Misalignment;
use crate::material::Material;

/// How the two rows face each other.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arrangement {
    /// Back-to-back (TDO: double cup, two cones): the roller large ends and the cone large ribs
    /// face outward, the load lines spread apart outside the bearing.
    O,
    /// Face-to-face: the large ends face the bearing mid-plane.
    X,
}

impl Arrangement {
    /// +1 if the large ends of row `k` (0: z < 0, 1: z > 0) point to +z, −1 otherwise.
    pub fn large_end_sign(self, k: usize) -> f64 {
        let outward = if k == 0 { -1.0 } else { 1.0 };
        match self {
            Self::O => outward,
            Self::X => -outward,
        }
    }
}

/// A double-row tapered roller bearing: one double cup (fixed), two cones joined by a spacer.
#[derive(Debug, Clone, PartialEq)]
pub struct DoubleRowTaperedBearing {
    pub name: String,
    /// Bore d of the cones [m].
    pub bore: f64,
    /// Outside diameter D of the cup [m].
    pub outside_diameter: f64,
    /// Pitch diameter d_m: diameter of the circle of roller mid-points [m].
    pub pitch_diameter: f64,
    pub roller: TaperedRoller,
    pub rollers_per_row: usize,
    pub arrangement: Arrangement,
    /// Axial distance between the two rows' roller mid-point circles [m].
    pub row_spacing: f64,
    /// Total axial play of the inner assembly (cones + spacer) against the cup [m].
    pub axial_clearance: f64,
    pub large_rib: LargeRib,
    /// Axial gap between a seated roller's small end face and the small (retaining) rib [m].
    pub small_rib_gap: f64,
    pub cage: TaperedCage,
    pub inner_material: Material,
    pub outer_material: Material,
    pub misalignment: Misalignment,
    /// Wear accumulated so far (unworn: the default), seed 000 §3.2.2–3.2.4.
    pub wear: TaperedWear,
}

impl DoubleRowTaperedBearing {
    /// Roller-axis angle θ_r to the bearing axis from the apex condition (the roller apex lies on
    /// the bearing axis): sin θ_r = d_m tan β / D_w.
    pub fn roller_axis_angle(&self) -> f64 {
        (self.pitch_diameter * self.roller.half_angle.tan() / self.roller.mean_diameter).asin()
    }

    /// Cone (inner raceway) half-angle α_i = θ_r − β.
    pub fn cone_angle(&self) -> f64 {
        self.roller_axis_angle() - self.roller.half_angle
    }

    /// Cup (outer raceway) half-angle α_o = θ_r + β: the contact angle of the bearing.
    pub fn cup_angle(&self) -> f64 {
        self.roller_axis_angle() + self.roller.half_angle
    }

    /// Roller mid-point → apex along the roller axis, D_w / (2 tan β) [m].
    pub fn apex_distance(&self) -> f64 {
        self.roller.apex_distance()
    }

    /// Normal gap between roller and cup per row with the inner assembly centred in its axial
    /// play and the rollers seated on cone and rib: ½ c_a sin α_o [m].
    pub fn normal_gap(&self) -> f64 {
        0.5 * self.axial_clearance * self.cup_angle().sin()
    }

    /// Radii of the cone and cup contacts in the roller mid-length section of a seated roller
    /// with zero gap [m]. Both lie at ℓ cos β from the apex, so their ratio is
    /// sin α_i : sin α_o.
    pub fn contact_radii(&self) -> (f64, f64) {
        let s = self.apex_distance() * self.roller.half_angle.cos();
        (s * self.cone_angle().sin(), s * self.cup_angle().sin())
    }

    /// Epicyclic cage speed [rad/s] for a fixed cup: pure rolling along the whole contact
    /// lines (all through the apex) gives (ω_i − ω_c) sin α_i = ω_c sin α_o, the
    /// [`crate::epicyclic_cage_speed`] of the contact radii.
    pub fn epicyclic_cage_speed(&self, inner_speed: f64) -> f64 {
        let (ri, ro) = self.contact_radii();
        crate::epicyclic_cage_speed(ri, ro, inner_speed, 0.0)
    }

    /// Roller-pass frequencies (outer, inner) [Hz] of one row for a fixed cup:
    /// Z ω_c / 2π and Z (ω_i − ω_c) / 2π at the epicyclic cage speed.
    pub fn pass_frequencies(&self, inner_speed: f64) -> (f64, f64) {
        let wc = self.epicyclic_cage_speed(inner_speed);
        let z = self.rollers_per_row as f64 / std::f64::consts::TAU;
        (z * wc.abs(), z * (inner_speed - wc).abs())
    }
}
