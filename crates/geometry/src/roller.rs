//! Rollers: body, end faces, profile, slices and mass properties (SPEC §1.3).

use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;
use crate::profile::Profile;

/// Shape of a roller end face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndFace {
    Flat,
    /// Spherical end face of radius R (double-row tapered bearing: 640 mm).
    Sphere {
        radius: f64,
    },
}

/// One roller (all rollers of a row are identical).
#[derive(Debug, Clone, PartialEq)]
pub struct Roller {
    /// Nominal (largest) diameter D_w [m].
    pub diameter: f64,
    /// Overall length L_w [m].
    pub length: f64,
    /// Generatrix profile over the length.
    pub profile: Profile,
    pub end_face: EndFace,
    /// Edge break (corner radius) between end face and chamfer [m].
    pub edge_break: f64,
    /// Number of slices for the slice contact model (SPEC §1.3).
    pub slice_count: usize,
    pub material: Material,
    /// Arithmetic mean roughness Ra of the rolling surface [m].
    pub roughness_ra: f64,
    /// Mass properties; computed from the geometry unless given.
    pub mass_properties: MassProperties,
}

/// Slices of a roller as struct-of-arrays: mid positions, lengths and profile drops.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SliceStack {
    /// Axial mid-position of each slice, from the roller centre [m].
    pub position: Vec<f64>,
    /// Axial length of each slice [m].
    pub length: Vec<f64>,
    /// Profile drop at each slice mid-point [m].
    pub drop: Vec<f64>,
}

impl Roller {
    /// Distance from the roller's mid-plane of the two points where the dynamics evaluates the
    /// roller ↔ cage-bar contact: the ends of the straight part (SPEC §1.5 "bone-shaped" scar), m.
    pub fn bar_contact_half_span(&self) -> f64 {
        self.profile.chamfer_start().min(0.5 * self.length)
    }

    /// Length of the roller's line contact on a flat cage bar at light load: the straight part
    /// of a crowned roller, else the effective length [m] (the length of the bar contact law,
    /// docs/theory.md §2.3.1).
    pub fn bar_contact_length(&self) -> f64 {
        match self.profile.shape {
            crate::ProfileShape::Crowned {
                straight_length, ..
            } => straight_length,
            _ => self.profile.effective_length(),
        }
    }

    /// Mass properties of the roller body from its profile and density (Simpson rule, 400
    /// intervals: the chamfers are resolved to < 0.1 % of the mass).
    pub fn computed_mass_properties(&self) -> MassProperties {
        let r = 0.5 * self.diameter;
        MassProperties::solid_of_revolution(
            |x| r - self.profile.drop(x).min(self.chamfer_height()),
            0.5 * self.length,
            self.material.density,
            400,
        )
    }

    /// Radial height of the chamfer (drop is capped there for the mass computation).
    fn chamfer_height(&self) -> f64 {
        self.profile.chamfer.map_or(0.5 * self.diameter, |c| {
            c.radial_height.min(0.5 * self.diameter)
        })
    }

    /// Cuts the full roller length into `slice_count` equal slices (SPEC §1.3: "short cylinders
    /// of equal thickness"); slices on the chamfers carry their (large) drop and so stay unloaded.
    pub fn slices(&self) -> SliceStack {
        let n = self.slice_count.max(1);
        let width = self.length / n as f64;
        let mut stack = SliceStack::default();
        for k in 0..n {
            let x = -0.5 * self.length + (k as f64 + 0.5) * width;
            stack.position.push(x);
            stack.length.push(width);
            stack.drop.push(self.profile.drop(x));
        }
        stack
    }

    /// Validates sizes and the profile; `key` prefixes are model-file paths.
    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("roller.diameter", self.diameter)?;
        require_positive("roller.length", self.length)?;
        if self.slice_count == 0 || self.slice_count > 1000 {
            return Err(GeometryError::new(
                "roller.slices",
                format!("must be between 1 and 1000, got {}", self.slice_count),
            ));
        }
        if self.roughness_ra < 0.0 {
            return Err(GeometryError::new(
                "roller.roughness_ra",
                "must not be negative",
            ));
        }
        validate_profile(&self.profile, self.diameter, "roller.profile")?;
        if let EndFace::Sphere { radius } = self.end_face
            && radius < 0.5 * self.diameter
        {
            return Err(GeometryError::new(
                "roller.end_face.radius",
                format!(
                    "spherical end radius {:.3} mm is smaller than the roller radius {:.3} mm",
                    radius * 1e3,
                    0.5e3 * self.diameter
                ),
            ));
        }
        Ok(())
    }
}

/// Checks a profile against the body it belongs to (`diameter` of the roller).
pub(crate) fn validate_profile(
    profile: &Profile,
    diameter: f64,
    key: &str,
) -> Result<(), GeometryError> {
    use crate::profile::ProfileShape::*;
    let half = profile.half_length;
    if let Some(c) = profile.chamfer {
        require_positive(&format!("{key}.chamfer.axial"), c.axial_length)?;
        require_positive(&format!("{key}.chamfer.radius"), c.radius)?;
        if c.radial_height < 0.0 || !c.radial_height.is_finite() {
            return Err(GeometryError::new(
                format!("{key}.chamfer.radial"),
                "must not be negative",
            ));
        }
        if c.axial_length >= half {
            return Err(GeometryError::new(
                format!("{key}.chamfer.axial"),
                format!(
                    "chamfers of {:.3} mm leave no working length on a {:.3} mm body",
                    c.axial_length * 1e3,
                    2e3 * half
                ),
            ));
        }
        if c.radial_height >= 0.5 * diameter {
            return Err(GeometryError::new(
                format!("{key}.chamfer.radial"),
                "chamfer height is not smaller than the roller radius",
            ));
        }
    }
    let xe = profile.chamfer_start();
    match &profile.shape {
        Straight => {}
        Crowned {
            straight_length,
            drop,
            crown_radius,
        } => {
            if !(*straight_length >= 0.0) || *straight_length > 2.0 * xe {
                return Err(GeometryError::new(
                    format!("{key}.straight_length"),
                    format!(
                        "straight part {:.3} mm must lie within the working length {:.3} mm",
                        straight_length * 1e3,
                        2e3 * xe
                    ),
                ));
            }
            require_positive(&format!("{key}.drop"), *drop)?;
            if *drop >= 0.5 * diameter {
                return Err(GeometryError::new(
                    format!("{key}.drop"),
                    format!(
                        "crown drop {:.4} mm is larger than the roller radius {:.3} mm",
                        drop * 1e3,
                        0.5e3 * diameter
                    ),
                ));
            }
            if let Some(r) = crown_radius {
                require_positive(&format!("{key}.crown_radius"), *r)?;
            }
        }
        Logarithmic { k, c } => {
            require_positive(&format!("{key}.k"), *k)?;
            require_positive(&format!("{key}.c"), *c)?;
            if c * xe * xe >= 1.0 {
                return Err(GeometryError::new(
                    format!("{key}.c"),
                    format!(
                        "the logarithm is singular at |x| = {:.4} mm, inside the working half-length {:.4} mm",
                        1e3 / c.sqrt(),
                        xe * 1e3
                    ),
                ));
            }
            if profile.drop(xe) >= 0.5 * diameter {
                return Err(GeometryError::new(
                    format!("{key}.k"),
                    "crown drop exceeds the roller radius",
                ));
            }
        }
        JohnsGohar {
            design_load,
            effective_length,
            reduced_modulus,
            hertz_half_width,
        } => {
            require_positive(&format!("{key}.design_load"), *design_load)?;
            require_positive(&format!("{key}.effective_length"), *effective_length)?;
            require_positive(&format!("{key}.reduced_modulus"), *reduced_modulus)?;
            require_positive(&format!("{key}.hertz_half_width"), *hertz_half_width)?;
        }
        Polyline { points } => {
            if points.len() < 2 {
                return Err(GeometryError::new(
                    format!("{key}.x"),
                    "needs at least two points",
                ));
            }
            for (i, w) in points.windows(2).enumerate() {
                if !(w[1].0 > w[0].0) {
                    return Err(GeometryError::new(
                        format!("{key}.x[{}]", i + 1),
                        "axial positions must increase strictly",
                    ));
                }
            }
            if let Some((i, _)) = points
                .iter()
                .enumerate()
                .find(|(_, p)| !p.1.is_finite() || p.1 < 0.0 || p.1 >= 0.5 * diameter)
            {
                return Err(GeometryError::new(
                    format!("{key}.drop[{i}]"),
                    "drop must be ≥ 0 and smaller than the roller radius",
                ));
            }
        }
    }
    Ok(())
}
