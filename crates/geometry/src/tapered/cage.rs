//! The roller-guided polyamide cage of a tapered row (seed 000 §3.2).

use super::roller::TaperedRoller;
use crate::cage::windowed_ring;
use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;

/// One cage per row, centred by its rollers (no land).
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedCage {
    /// Circumferential play of a roller in its pocket at mid-length: pocket width − D_w [m].
    pub pocket_clearance: f64,
    /// Axial play of a roller in its pocket: pocket length − roller length [m].
    pub end_clearance: f64,
    /// Diameter at which the roller touches the pocket bars, at the roller mid-length [m].
    pub bar_contact_diameter: f64,
    /// Cage body approximated as a ring of these diameters and width [m].
    pub inner_diameter: f64,
    pub outer_diameter: f64,
    pub width: f64,
    /// Mass [kg] and inertias about the cage axis and a transverse axis [kg·m²].
    pub mass: f64,
    pub inertia_axial: f64,
    pub inertia_transverse: f64,
    pub material: Material,
    /// Roller–cage friction coefficient (seed 000 §3.2: 0.06 for polyamide).
    pub roller_friction: f64,
}

impl TaperedCage {
    /// Mass properties of the ring with `pockets` windows of (D_w + pocket clearance) ×
    /// (L + end clearance) cut through its wall.
    pub fn computed_mass_properties(
        &self,
        roller: &TaperedRoller,
        pockets: usize,
    ) -> MassProperties {
        let wall = 0.5 * (self.outer_diameter - self.inner_diameter);
        let window = (roller.mean_diameter + self.pocket_clearance)
            * (roller.length + self.end_clearance)
            * wall;
        windowed_ring(
            self.inner_diameter,
            self.outer_diameter,
            self.width,
            self.material.density,
            pockets as f64 * window,
        )
    }

    /// The cage with mass and inertias set from [`Self::computed_mass_properties`].
    pub fn with_computed_mass(mut self, roller: &TaperedRoller, pockets: usize) -> Self {
        let m = self.computed_mass_properties(roller, pockets);
        self.mass = m.mass;
        self.inertia_axial = m.axial_inertia;
        self.inertia_transverse = m.transverse_inertia;
        self
    }

    pub fn validate(&self, roller: &TaperedRoller) -> Result<(), GeometryError> {
        require_positive("cage.pocket_clearance", self.pocket_clearance)?;
        require_positive("cage.end_clearance", self.end_clearance)?;
        require_positive("cage.inner_diameter", self.inner_diameter)?;
        require_positive("cage.width", self.width)?;
        require_positive("cage.mass", self.mass)?;
        require_positive("cage.inertia_axial", self.inertia_axial)?;
        require_positive("cage.inertia_transverse", self.inertia_transverse)?;
        if self.outer_diameter <= self.inner_diameter {
            return Err(GeometryError::new(
                "cage.outer_diameter",
                "must be larger than cage.inner_diameter",
            ));
        }
        if !(self.bar_contact_diameter > self.inner_diameter
            && self.bar_contact_diameter < self.outer_diameter)
        {
            return Err(GeometryError::new(
                "cage.bar_contact_diameter",
                "must lie between the cage inner and outer diameters",
            ));
        }
        if self.width <= roller.length + self.end_clearance {
            return Err(GeometryError::new(
                "cage.width",
                "the cage is not wider than its pockets",
            ));
        }
        if !(0.0..=1.0).contains(&self.roller_friction) {
            return Err(GeometryError::new(
                "cage.roller_friction",
                "must lie in 0…1",
            ));
        }
        Ok(())
    }
}
