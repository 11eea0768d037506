//! The cage (SPEC §1.5).

use crate::cage_pocket::{CagePocket, PocketContext};
use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;
use serde::{Deserialize, Serialize};

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

/// A plating of the cage (`cage.plating`); its effect on fatigue is the fatigue crate's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Plating {
    /// Silver plating (the seed bearings' cages, seed 000 §3.1.1.8).
    Silver,
}

/// A machined window cage.
#[derive(Debug, Clone, PartialEq)]
pub struct Cage {
    pub guidance: CageGuidance,
    /// Diametral clearance between cage centring surface and guiding land ("зазор плавания").
    pub floating_clearance: f64,
    /// The pocket as it is built: faces, lips, axial size, fillet (docs/theory.md §1.6). Contact,
    /// bar stiffness, mass and both stress models read it.
    pub pocket: CagePocket,
    pub inner_diameter: f64,
    pub outer_diameter: f64,
    pub width: f64,
    pub material: Material,
    /// `None`: unplated.
    pub plating: Option<Plating>,
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
    /// Resolves the pocket against its bearing: roller radius, pitch radius, pocket count.
    pub fn pocket_context(
        &self,
        roller_radius: f64,
        pitch_radius: f64,
        pockets: usize,
    ) -> PocketContext {
        PocketContext {
            roller_radius,
            pitch_radius,
            cage_inner_radius: 0.5 * self.inner_diameter,
            cage_outer_radius: 0.5 * self.outer_diameter,
            pockets,
        }
    }

    /// Mass properties of the cage ring with its windows cut ([`CagePocket::cage_mass`]).
    pub fn computed_mass_properties(
        &self,
        ctx: &PocketContext,
    ) -> Result<MassProperties, GeometryError> {
        self.pocket
            .cage_mass(ctx, self.width, self.material.density)
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
        require_positive("cage.pocket_axial", self.pocket.axial)?;
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
