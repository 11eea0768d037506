//! Bearing rings: raceway, ribs (flanges) and guiding lands (SPEC §1.2).

use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;
use crate::profile::Profile;
use crate::wear_map::RacewayWearMap;

/// Which side of the raceway a rib stands on (axial −/+).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RibSide {
    Left,
    Right,
}

/// Shape of the rib face that the roller end touches (SPEC §1.2 "Ribs").
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RibFace {
    Flat,
    /// Conical face inclined by `angle` from the radial plane (tapered bearings).
    Cone {
        angle: f64,
    },
    /// Convex toroidal face of profile radius `radius` (patent RU 2815566: 430 or 37.5 mm),
    /// most protruding at the rib mid-height shifted by `crest_offset` toward the raceway.
    ConvexTorus {
        radius: f64,
        crest_offset: f64,
    },
    /// Concave toroidal face of profile radius `radius` (tapered study: 800…1300 mm).
    ConcaveTorus {
        radius: f64,
    },
}

/// A rib (flange) on a ring.
#[derive(Debug, Clone, PartialEq)]
pub struct Rib {
    pub side: RibSide,
    /// Rim diameter: outside diameter of an inner-ring rib, bore of an outer-ring rib [m].
    pub diameter: f64,
    pub face: RibFace,
    /// Edge break ("притупление") at the rim [m].
    pub edge_break: f64,
}

/// A cylindrical guiding land for the cage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuidingLand {
    pub diameter: f64,
    pub width: f64,
}

/// A bearing ring (inner or outer).
#[derive(Debug, Clone, PartialEq)]
pub struct Ring {
    /// Raceway diameter d_i (inner) or D_o (outer) [m].
    pub raceway_diameter: f64,
    /// Bore of the inner ring, outside diameter D of the outer ring [m].
    pub body_diameter: f64,
    pub width: f64,
    pub ribs: Vec<Rib>,
    /// Axial distance between the two rib faces [m] when the ring has two ribs.
    pub rib_spacing: Option<f64>,
    /// Raceway generatrix (straight if absent).
    pub raceway_profile: Option<Profile>,
    /// Raceway wear over axial position × ring angle (none when unworn).
    pub raceway_wear: Option<RacewayWearMap>,
    pub guiding_land: Option<GuidingLand>,
    pub material: Material,
    pub roughness_ra: f64,
    pub mass_properties: MassProperties,
}

impl Ring {
    /// Mass properties of the ring body as a hollow cylinder between raceway and body diameter
    /// (ribs neglected: their mass is a few per cent and does not enter the dynamics of a
    /// ring whose motion is prescribed or stiffly supported).
    pub fn computed_mass_properties(&self) -> MassProperties {
        let (a, b) = (0.5 * self.raceway_diameter, 0.5 * self.body_diameter);
        MassProperties::hollow_cylinder(a.min(b), a.max(b), self.width, self.material.density)
    }

    /// Radial wall thickness t_b between raceway and the outer surface (seed 000 eq. 2.4).
    pub fn wall_thickness(&self) -> f64 {
        0.5 * (self.body_diameter - self.raceway_diameter).abs()
    }

    /// Raceway drop at axial position `x`: the profile's drop (0 for a straight raceway) plus
    /// the circumferential mean wear depth (the axisymmetric reading of the worn raceway).
    pub fn raceway_drop(&self, x: f64) -> f64 {
        self.profile_drop(x) + self.raceway_wear.as_ref().map_or(0.0, |w| w.mean_depth(x))
    }

    /// Raceway drop at axial position `x` and ring-frame angle `angle_rad`: the profile's drop
    /// plus the wear depth there.
    pub fn raceway_drop_at(&self, x: f64, angle_rad: f64) -> f64 {
        self.profile_drop(x)
            + self
                .raceway_wear
                .as_ref()
                .map_or(0.0, |w| w.depth(x, angle_rad))
    }

    fn profile_drop(&self, x: f64) -> f64 {
        self.raceway_profile.as_ref().map_or(0.0, |p| p.drop(x))
    }

    /// Validates the ring; `key` is `inner_ring` or `outer_ring`, `inner` tells which.
    pub fn validate(&self, key: &str, inner: bool) -> Result<(), GeometryError> {
        require_positive(&format!("{key}.raceway_diameter"), self.raceway_diameter)?;
        require_positive(&format!("{key}.width"), self.width)?;
        let body_key = if inner {
            "bore_diameter"
        } else {
            "outside_diameter"
        };
        require_positive(&format!("{key}.{body_key}"), self.body_diameter)?;
        let body_ok = if inner {
            self.body_diameter < self.raceway_diameter
        } else {
            self.body_diameter > self.raceway_diameter
        };
        if !body_ok {
            return Err(GeometryError::new(
                format!("{key}.{body_key}"),
                format!(
                    "{} {:.3} mm leaves no ring wall below the raceway Ø{:.3} mm",
                    body_key.replace('_', " "),
                    self.body_diameter * 1e3,
                    self.raceway_diameter * 1e3
                ),
            ));
        }
        for (i, rib) in self.ribs.iter().enumerate() {
            let rib_key = format!("{key}.ribs[{i}]");
            require_positive(&format!("{rib_key}.diameter"), rib.diameter)?;
            let stands_proud = if inner {
                rib.diameter > self.raceway_diameter
            } else {
                rib.diameter < self.raceway_diameter
            };
            if !stands_proud {
                return Err(GeometryError::new(
                    format!("{rib_key}.diameter"),
                    "a rib must stand proud of the raceway",
                ));
            }
            if rib.edge_break < 0.0 {
                return Err(GeometryError::new(
                    format!("{rib_key}.edge_break"),
                    "must not be negative",
                ));
            }
            match rib.face {
                RibFace::ConvexTorus { radius, .. } | RibFace::ConcaveTorus { radius } => {
                    require_positive(&format!("{rib_key}.face.radius"), radius)?
                }
                RibFace::Cone { angle } if angle.abs() >= std::f64::consts::FRAC_PI_4 => {
                    return Err(GeometryError::new(
                        format!("{rib_key}.face.angle"),
                        "must be below 45°",
                    ));
                }
                _ => {}
            }
        }
        if let Some(spacing) = self.rib_spacing {
            require_positive(&format!("{key}.rib_spacing"), spacing)?;
            if spacing > self.width {
                return Err(GeometryError::new(
                    format!("{key}.rib_spacing"),
                    "rib spacing is larger than the ring width",
                ));
            }
        }
        if let Some(land) = self.guiding_land {
            require_positive(&format!("{key}.guiding_land.width"), land.width)?;
        }
        if self.roughness_ra < 0.0 {
            return Err(GeometryError::new(
                format!("{key}.roughness_ra"),
                "must not be negative",
            ));
        }
        Ok(())
    }
}
