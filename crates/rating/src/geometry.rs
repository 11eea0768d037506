//! The internal dimensions of a radial roller bearing that its ratings take.

use crate::RatingError;

/// Internal geometry of a radial roller bearing in the terms of ISO 281:2007 §3 (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerBearingGeometry {
    /// Roller diameter D_we (the mean diameter of a tapered roller) [m].
    pub roller_diameter_m: f64,
    /// Effective roller length L_we: the longest contact length less chamfers [m].
    pub effective_length_m: f64,
    /// Nominal contact angle α (0 for cylindrical, the cup angle of a tapered bearing) [rad].
    pub contact_angle_rad: f64,
    /// Pitch diameter of the roller set D_pw [m].
    pub pitch_diameter_m: f64,
    /// Rollers per row Z.
    pub rollers_per_row: usize,
    /// Rows i.
    pub rows: usize,
}

impl RollerBearingGeometry {
    /// The bearing of issue 38 (NU 2215 style): 16 rollers 15 × 22 mm on D_pw = (75 + 130)/2 mm,
    /// the worked case of the tests.
    #[cfg(test)]
    pub(crate) fn issue_38_bearing() -> Self {
        Self {
            roller_diameter_m: 0.015,
            effective_length_m: 0.022,
            contact_angle_rad: 0.0,
            pitch_diameter_m: 0.1025,
            rollers_per_row: 16,
            rows: 1,
        }
    }

    /// γ = D_we cos α / D_pw (ISO 281:2007 Table 7's argument).
    pub fn gamma(&self) -> f64 {
        self.roller_diameter_m * self.contact_angle_rad.cos() / self.pitch_diameter_m
    }

    /// Checks that every dimension is positive and the contact angle lies in [0, 45°] (a radial
    /// bearing, ISO 281:2007 §7.1).
    pub fn validate(&self) -> Result<(), RatingError> {
        let positive = [
            ("roller diameter", self.roller_diameter_m),
            ("effective roller length", self.effective_length_m),
            ("pitch diameter", self.pitch_diameter_m),
        ];
        for (name, v) in positive {
            if !(v > 0.0 && v.is_finite()) {
                return Err(RatingError::OutOfRange(format!(
                    "{name} must be positive, got {v} m"
                )));
            }
        }
        if self.rollers_per_row == 0 || self.rows == 0 {
            return Err(RatingError::OutOfRange(
                "a bearing needs at least one row of rollers".into(),
            ));
        }
        if !(0.0..=std::f64::consts::FRAC_PI_4).contains(&self.contact_angle_rad) {
            return Err(RatingError::OutOfRange(format!(
                "contact angle {:.2}° outside 0…45°: not a radial roller bearing (ISO 281 §7.1)",
                self.contact_angle_rad.to_degrees()
            )));
        }
        Ok(())
    }
}
