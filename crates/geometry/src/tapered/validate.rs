//! Validation of a double-row tapered bearing: every part, their fit together, the apex
//! condition and the seated rows inside the rings.

use super::bearing::DoubleRowTaperedBearing;
use super::rib::end_contact_angle;
use crate::error::{GeometryError, require_positive};

/// Largest accepted apex mismatch [m]: the derived geometry closes to round-off (≈ 1e-15 m), so
/// anything above this is a construction error.
const MAX_APEX_MISMATCH: f64 = 1e-9;

impl DoubleRowTaperedBearing {
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

    /// Checks every part and their fit together.
    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("bearing.bore", self.bore)?;
        require_positive("bearing.outside_diameter", self.outside_diameter)?;
        crate::plausible::check_outside_diameter(
            "bearing.outside_diameter",
            self.outside_diameter,
        )?;
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
