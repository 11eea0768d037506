//! The load case of the tapered load distribution: loads on the inner-ring assembly, its tilt
//! condition and the speed.

/// How the tilt of the inner-ring assembly is set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TiltCondition {
    /// The tilting moment (M_x, M_y) on the inner-ring assembly is given [N·m]; both tilts are
    /// unknowns (Jones' five degrees of freedom).
    Moment([f64; 2]),
    /// The tilt of the inner-ring axis is imposed (misalignment, e.g. by shaft bending) [rad],
    /// here as a rotation about the y axis, i.e. in the plane of the bearing axis and the radial
    /// load (seed 000 §3.2.1 case 3); the moment the bearing then carries is an output.
    Imposed(f64),
}

/// Loads on the inner-ring assembly (both cones and the spacer, one rigid body) in the bearing
/// frame: z along the bearing axis, x along the radial load, the cup fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedLoadCase {
    /// Radial load F_r along +x [N].
    pub radial_load_n: f64,
    /// Axial load F_a along +z [N].
    pub axial_load_n: f64,
    /// Tilting moment or imposed misalignment.
    pub tilt: TiltCondition,
    /// Inner-ring speed [rad/s]: the rollers orbit at the epicyclic cage speed and press on the
    /// cup with their centrifugal force.
    pub inner_speed_rad_s: f64,
}

impl TaperedLoadCase {
    /// Checks that every value is finite.
    pub(crate) fn validate(&self) -> Result<(), crate::QsError> {
        let tilt = match self.tilt {
            TiltCondition::Moment([mx, my]) => [mx, my],
            TiltCondition::Imposed(t) => [t, 0.0],
        };
        let values = [
            ("radial load", self.radial_load_n),
            ("axial load", self.axial_load_n),
            ("moment or misalignment", tilt[0]),
            ("moment", tilt[1]),
            ("inner-ring speed", self.inner_speed_rad_s),
        ];
        for (name, v) in values {
            if !v.is_finite() {
                return Err(crate::QsError::InvalidInput(format!(
                    "{name} must be finite, got {v}"
                )));
            }
        }
        Ok(())
    }
}
