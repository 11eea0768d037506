//! The cone's large rib: face shape, height band and the initial contact with the roller end.

use super::roller::TaperedRoller;
use crate::error::{GeometryError, require_positive};

/// Shape of the large-rib face in the axial section (seed 000 §3.2.2: conical; concave torus
/// R 800…1300 mm; convex torus R 1100 mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TaperedRibFace {
    Conical,
    ConcaveTorus { radius: f64 },
    ConvexTorus { radius: f64 },
}

impl TaperedRibFace {
    /// Signed curvature of the face profile [1/m]: + concave (wrapping the roller end),
    /// − convex, 0 conical. The end–rib reduced curvature is 1/R_end − this.
    pub fn curvature(&self) -> f64 {
        match *self {
            Self::Conical => 0.0,
            Self::ConcaveTorus { radius } => 1.0 / radius,
            Self::ConvexTorus { radius } => -1.0 / radius,
        }
    }
}

/// The large rib of each cone (it carries the roller's axial force component).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LargeRib {
    pub face: TaperedRibFace,
    /// Rib top: height of the face above the cone raceway line, measured along the face [m].
    pub height: f64,
    /// Undercut (grinding relief) at the raceway–rib corner: the face starts this far above the
    /// raceway line, measured along the face [m].
    pub undercut: f64,
}

impl LargeRib {
    /// Height of the initial contact above the raceway line: the middle of the face band
    /// between undercut and top (seed 000 §3.2.2: "the initial contact point lies at mid rib
    /// height") [m].
    pub fn contact_height(&self) -> f64 {
        0.5 * (self.undercut + self.height)
    }

    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("large_rib.height", self.height)?;
        if !(self.undercut >= 0.0) || self.undercut >= self.height {
            return Err(GeometryError::new(
                "large_rib.undercut",
                format!(
                    "{:.3} mm must be ≥ 0 and below the rib height {:.3} mm",
                    self.undercut * 1e3,
                    self.height * 1e3
                ),
            ));
        }
        if let TaperedRibFace::ConcaveTorus { radius } | TaperedRibFace::ConvexTorus { radius } =
            self.face
        {
            require_positive("large_rib.face_radius", radius)?;
        }
        Ok(())
    }
}

/// Angle φ [rad] on the roller's end sphere (from the roller axis toward the cone, about the
/// sphere centre) of the initial end–rib contact, for a roller seated on the cone raceway, such
/// that the face tangent at the contact meets the raceway line `height` below it (along the
/// face). In roller coordinates (x along the axis from mid-length, y away from the cone) the
/// raceway is y = −(x + ℓ) tan β and the contact P = (x_C + R cos φ, −R sin φ); the distance
/// along the tangent (sin φ, cos φ) from the raceway to P equals h when
/// R sin(φ − β) + h cos(φ − β) = (x_C + ℓ) sin β. The root near the roller axis is returned;
/// `None` if there is none.
pub fn end_contact_angle(roller: &TaperedRoller, height: f64) -> Option<f64> {
    let (r, beta) = (roller.large_end_sphere_radius, roller.half_angle);
    let b = (roller.sphere_centre() + roller.apex_distance()) * beta.sin();
    let psi = (b / r.hypot(height)).asin() - height.atan2(r);
    let phi = psi + beta;
    phi.is_finite().then_some(phi)
}
