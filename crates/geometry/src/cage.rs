//! The cage (SPEC §1.5).

use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;

/// What centres the cage.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CageGuidance {
    /// Cage bore runs on a land of the inner ring (2002834).
    InnerLand,
    /// Cage outside diameter runs in a land of the outer ring (seed 001).
    OuterLand,
    /// Cage centred by the rollers (polyamide cage of the tapered bearing).
    Rollers,
}

/// A machined window cage.
#[derive(Debug, Clone, PartialEq)]
pub struct Cage {
    pub guidance: CageGuidance,
    /// Diametral clearance between cage centring surface and guiding land ("зазор плавания").
    pub floating_clearance: f64,
    /// Circumferential pocket (window) size, measured at the bar contact diameter [m].
    pub pocket_circumferential: f64,
    /// Axial pocket size [m].
    pub pocket_axial: f64,
    /// Diameter at which the rollers touch the cage bars [m] (2002834: 192.5 mm).
    pub bar_contact_diameter: f64,
    pub inner_diameter: f64,
    pub outer_diameter: f64,
    pub width: f64,
    pub material: Material,
    pub roughness_ra: f64,
    pub mass_properties: MassProperties,
}

/// Mass properties of a ring (diameters `inner` < `outer`, `width`, density `rho`) from which
/// `window_volume` of pocket material is removed uniformly (its effect on the ratio of inertia to
/// mass is below 1 % for bar-type cages).
pub(crate) fn windowed_ring(
    inner: f64,
    outer: f64,
    width: f64,
    rho: f64,
    window_volume: f64,
) -> MassProperties {
    let (ri, ro) = (0.5 * inner, 0.5 * outer);
    let ring = MassProperties::hollow_cylinder(ri, ro, width, rho);
    let ring_volume = std::f64::consts::PI * (ro * ro - ri * ri) * width;
    ring.scaled((1.0 - window_volume / ring_volume).max(0.0))
}

impl Cage {
    /// Mass properties of the cage ring with `pockets` windows of the pocket size cut through
    /// its radial wall: [`windowed_ring`].
    pub fn computed_mass_properties(&self, pockets: usize) -> MassProperties {
        let wall = 0.5 * (self.outer_diameter - self.inner_diameter);
        windowed_ring(
            self.inner_diameter,
            self.outer_diameter,
            self.width,
            self.material.density,
            pockets as f64 * self.pocket_circumferential * self.pocket_axial * wall,
        )
    }

    /// Diameter of the guiding land the cage runs on, from the cage and its floating clearance.
    pub fn land_diameter(&self) -> Option<f64> {
        match self.guidance {
            CageGuidance::InnerLand => Some(self.inner_diameter - self.floating_clearance),
            CageGuidance::OuterLand => Some(self.outer_diameter + self.floating_clearance),
            CageGuidance::Rollers => None,
        }
    }

    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("cage.pocket_circumferential", self.pocket_circumferential)?;
        require_positive("cage.pocket_axial", self.pocket_axial)?;
        require_positive("cage.bar_contact_diameter", self.bar_contact_diameter)?;
        require_positive("cage.inner_diameter", self.inner_diameter)?;
        require_positive("cage.width", self.width)?;
        if self.outer_diameter <= self.inner_diameter {
            return Err(GeometryError::new(
                "cage.outer_diameter",
                "must be larger than cage.inner_diameter",
            ));
        }
        if self.floating_clearance < 0.0 || !self.floating_clearance.is_finite() {
            return Err(GeometryError::new(
                "cage.floating_clearance",
                "must not be negative",
            ));
        }
        if self.guidance != CageGuidance::Rollers && self.floating_clearance == 0.0 {
            return Err(GeometryError::new(
                "cage.floating_clearance",
                "a land-guided cage needs a positive floating clearance",
            ));
        }
        if self.roughness_ra < 0.0 {
            return Err(GeometryError::new(
                "cage.roughness_ra",
                "must not be negative",
            ));
        }
        Ok(())
    }
}
