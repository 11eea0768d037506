//! The double-row tapered roller bearing (seed 000 §3.2) and its derived dimensions.

use super::cage::TaperedCage;
use super::rib::{LargeRib, end_contact_angle};
use super::roller::TaperedRoller;
use super::row::TaperedRow;
use super::wear::TaperedWear;
use crate::bearing::Misalignment;
use crate::error::{GeometryError, require_positive};
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

/// Largest accepted apex mismatch [m]: the derived geometry closes to round-off (≈ 1e-15 m), so
/// anything above this is a construction error.
const MAX_APEX_MISMATCH: f64 = 1e-9;

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

    /// Largest distance between the roller apex (where the roller's two generatrices meet) and
    /// the cone and cup raceway apices on the bearing axis [m] (row 0, zero gap); 0 up to
    /// round-off when the data satisfy the apex condition.
    pub fn apex_mismatch(&self) -> f64 {
        let row = self.row(0);
        let apex = row.roller_mid - self.apex_distance() * row.roller_axis;
        let zero_gap_cup = row.cup.point + self.normal_gap() * row.cup.normal;
        [
            apex.r.abs(),
            (apex.z - row.apex_z).abs(),
            apex.distance_to_line(row.cone.point, row.cone.direction),
            apex.distance_to_line(zero_gap_cup, row.cup.direction),
        ]
        .into_iter()
        .fold(0.0, f64::max)
    }

    /// Row `k` (0: z < 0, 1: z > 0) in bearing coordinates.
    pub fn row(&self, k: usize) -> TaperedRow {
        TaperedRow::new(self, k)
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

    /// Checks every part and their fit together.
    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("bearing.bore", self.bore)?;
        require_positive("bearing.outside_diameter", self.outside_diameter)?;
        require_positive("bearing.pitch_diameter", self.pitch_diameter)?;
        self.roller.validate()?;
        self.large_rib.validate()?;
        self.cage.validate(&self.roller)?;
        if !(self.bore < self.pitch_diameter && self.pitch_diameter < self.outside_diameter) {
            return Err(GeometryError::new(
                "bearing.pitch_diameter",
                "must lie between the bore and the outside diameter",
            ));
        }
        if !self.roller.large_end_sphere_radius.is_finite() {
            return Err(GeometryError::new(
                "roller.large_end_sphere_radius",
                "the large end must be spherical: it guides the roller on the rib",
            ));
        }
        self.validate_apex()?;
        self.validate_fit()?;
        self.validate_rows()?;
        let tilt = self.misalignment.inner_ring_tilt;
        if !tilt.is_finite() || tilt.abs() > 1f64.to_radians() {
            return Err(GeometryError::new(
                "misalignment.inner_ring",
                format!(
                    "{:.1}′ is beyond the 1° a roller bearing can run with",
                    tilt.to_degrees() * 60.0
                ),
            ));
        }
        Ok(())
    }

    fn validate_apex(&self) -> Result<(), GeometryError> {
        let sin_theta =
            self.pitch_diameter * self.roller.half_angle.tan() / self.roller.mean_diameter;
        if !(sin_theta < 1.0) {
            return Err(GeometryError::new(
                "bearing.pitch_diameter",
                format!(
                    "no roller-axis angle puts the apex of a {:.2}′ roller of Ø{:.3} mm on the \
                     axis at d_m = {:.3} mm (sin θ_r = {sin_theta:.3})",
                    self.roller.half_angle.to_degrees() * 60.0,
                    self.roller.mean_diameter * 1e3,
                    self.pitch_diameter * 1e3
                ),
            ));
        }
        let mismatch = self.apex_mismatch();
        if !(mismatch < MAX_APEX_MISMATCH) {
            return Err(GeometryError::new(
                "bearing.pitch_diameter",
                format!(
                    "roller and raceway apices miss each other by {:.3e} mm",
                    mismatch * 1e3
                ),
            ));
        }
        Ok(())
    }

    fn validate_fit(&self) -> Result<(), GeometryError> {
        let z = self.rollers_per_row;
        if z < 3 {
            return Err(GeometryError::new(
                "bearing.rollers_per_row",
                "a row needs at least 3 rollers",
            ));
        }
        // Roller diameter and pitch diameter both grow in proportion to the distance from the
        // apex, so the mid-length section decides whether the rollers fit.
        let chord = self.pitch_diameter * (std::f64::consts::PI / z as f64).sin();
        let dw = self.roller.mean_diameter;
        if chord <= dw {
            let max = (std::f64::consts::PI / (dw / self.pitch_diameter).asin()).floor();
            return Err(GeometryError::new(
                "bearing.rollers_per_row",
                format!(
                    "{z} rollers Ø{:.3} mm overlap on the pitch circle Ø{:.3} mm (at most {max} fit)",
                    dw * 1e3,
                    self.pitch_diameter * 1e3
                ),
            ));
        }
        if !(self.axial_clearance >= 0.0) {
            return Err(GeometryError::new(
                "bearing.axial_clearance",
                "must not be negative",
            ));
        }
        if !(self.small_rib_gap > 0.0) {
            return Err(GeometryError::new("small_rib.gap", "must be positive"));
        }
        if end_contact_angle(&self.roller, self.large_rib.contact_height()).is_none() {
            return Err(GeometryError::new(
                "large_rib.height",
                "the roller end sphere cannot touch a rib face at mid rib height",
            ));
        }
        Ok(())
    }

    fn validate_rows(&self) -> Result<(), GeometryError> {
        let row = self.row(1);
        let lowest_raceway =
            row.cone.point.r - 0.5 * self.roller.length * row.cone.direction.r.abs();
        if !(0.5 * self.bore < lowest_raceway) {
            return Err(GeometryError::new(
                "bearing.bore",
                format!(
                    "Ø{:.3} mm cuts through the cone raceway (smallest raceway Ø{:.3} mm)",
                    self.bore * 1e3,
                    2e3 * lowest_raceway
                ),
            ));
        }
        let highest_raceway =
            row.cup.point.r + 0.5 * self.roller.length * row.cup.direction.r.abs();
        if !(0.5 * self.outside_diameter > highest_raceway) {
            return Err(GeometryError::new(
                "bearing.outside_diameter",
                format!(
                    "Ø{:.3} mm cuts through the cup raceway (largest raceway Ø{:.3} mm)",
                    self.outside_diameter * 1e3,
                    2e3 * highest_raceway
                ),
            ));
        }
        let contact = row.large_rib.point - row.cone.point;
        let above_raceway = contact.dot(row.cone.normal);
        let face_radius = self.roller.large_end_face_radius();
        let across = row.roller_axis.perpendicular();
        let away_from_cone = if across.dot(row.cone.normal) > 0.0 {
            across
        } else {
            -across
        };
        let below_axis = -(row.large_rib.point - row.roller_mid).dot(away_from_cone);
        if !(above_raceway > 0.0 && below_axis > 0.0 && below_axis < face_radius) {
            return Err(GeometryError::new(
                "large_rib.height",
                format!(
                    "the end–rib contact {:.3} mm above the raceway is not on the cone-side half \
                     of the roller end face (face radius {:.3} mm)",
                    above_raceway * 1e3,
                    face_radius * 1e3
                ),
            ));
        }
        let axial_extent = self.roller.length * self.roller_axis_angle().cos();
        if !(self.row_spacing > axial_extent) {
            return Err(GeometryError::new(
                "bearing.row_spacing",
                format!(
                    "{:.3} mm makes the two rows overlap (a roller spans {:.3} mm axially)",
                    self.row_spacing * 1e3,
                    axial_extent * 1e3
                ),
            ));
        }
        Ok(())
    }
}
