//! The tapered roller: a truncated cone with a spherical large end (seed 000 §3.2).

use crate::error::{GeometryError, require_positive};
use crate::mass::MassProperties;
use crate::material::Material;
use crate::profile::Profile;
use crate::roller::validate_profile;

/// Default number of slices of a tapered roller (seed 000 §3.2: "short cylinders of equal
/// thickness"; 10 slices of ≈ 5 mm resolve the load along the 50 mm roller of the cassette
/// bearing and the 9 wear lines of seed 000 §3.2.3).
pub const DEFAULT_TAPERED_SLICES: usize = 10;

/// Simpson intervals of the mass integral: the end sphere cap (≈ 0.07 mm high) and the chamfers
/// are resolved to better than 1e-6 of the mass.
const MASS_INTERVALS: usize = 4000;

/// One tapered roller (all rollers of both rows are identical).
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedRoller {
    /// Mean diameter D_w at mid-length [m].
    pub mean_diameter: f64,
    /// Overall length L along the roller axis, from the small end face to the vertex of the
    /// large end sphere [m].
    pub length: f64,
    /// Half-angle β between the generatrix and the roller axis [rad] (seed: 53′).
    pub half_angle: f64,
    /// Radius of the spherical large end face [m] (seed: 640 mm); `f64::INFINITY` = flat.
    pub large_end_sphere_radius: f64,
    /// 45° edge chamfer at both ends, measured along the axis and radially [m].
    pub end_chamfer: f64,
    pub slice_count: usize,
    pub material: Material,
    /// Drop along the generatrix over the working length (`None` = straight generatrix).
    pub profile: Option<Profile>,
}

/// Equal-length slices of the working length (between the end chamfers) as struct-of-arrays.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TaperedSliceStack {
    /// Axial position of each slice centre from the roller mid-length, + toward the large end [m].
    pub position: Vec<f64>,
    /// Nominal cone radius at the slice centre [m] (before the profile drop).
    pub radius: Vec<f64>,
    /// Slice length along the roller axis [m].
    pub length: Vec<f64>,
    /// Profile drop at the slice centre, normal to the generatrix [m].
    pub drop: Vec<f64>,
}

impl TaperedRoller {
    /// Large-end diameter D_w + L tan β [m].
    pub fn large_diameter(&self) -> f64 {
        2.0 * self.radius_at(0.5 * self.length)
    }

    /// Small-end diameter D_w − L tan β [m].
    pub fn small_diameter(&self) -> f64 {
        2.0 * self.radius_at(-0.5 * self.length)
    }

    /// Nominal cone radius D_w/2 + x tan β at axial position x from mid-length, + toward the
    /// large end [m].
    pub fn radius_at(&self, x: f64) -> f64 {
        0.5 * self.mean_diameter + x * self.half_angle.tan()
    }

    /// Distance from the mid-length point to the roller apex along the axis,
    /// D_w / (2 tan β) [m]: the cone radius vanishes there.
    pub fn apex_distance(&self) -> f64 {
        0.5 * self.mean_diameter / self.half_angle.tan()
    }

    /// Half of the working length (between the end chamfers) [m].
    pub fn working_half_length(&self) -> f64 {
        0.5 * self.length - self.end_chamfer
    }

    /// Profile drop at x (0 for a straight generatrix) [m].
    pub fn drop_at(&self, x: f64) -> f64 {
        self.profile.as_ref().map_or(0.0, |p| p.drop(x))
    }

    /// Position of the end-sphere centre on the roller axis from mid-length [m]
    /// (L/2 − R: the sphere's vertex is the large end of the roller).
    pub fn sphere_centre(&self) -> f64 {
        0.5 * self.length - self.large_end_sphere_radius
    }

    /// Radius of the flat or spherical large end face where it meets the chamfer [m].
    pub fn large_end_face_radius(&self) -> f64 {
        0.5 * self.large_diameter() - self.end_chamfer
    }

    /// Radius of the roller body at x: cone minus profile drop, cut by the 45° chamfers and the
    /// end sphere [m].
    pub fn body_radius(&self, x: f64) -> f64 {
        let to_end = 0.5 * self.length - x.abs();
        let chamfer_cut = (self.end_chamfer - to_end).max(0.0);
        let cone = self.radius_at(x) - self.drop_at(x) - chamfer_cut;
        if self.large_end_sphere_radius.is_finite() {
            let r = self.large_end_sphere_radius;
            let dx = x - self.sphere_centre();
            cone.min((r * r - dx * dx).max(0.0).sqrt())
        } else {
            cone
        }
    }

    /// Slices of equal length over the working length (seed 000 §3.2).
    pub fn slices(&self) -> TaperedSliceStack {
        let n = self.slice_count.max(1);
        let half = self.working_half_length();
        let width = 2.0 * half / n as f64;
        let mut stack = TaperedSliceStack::default();
        for k in 0..n {
            let x = -half + (k as f64 + 0.5) * width;
            stack.position.push(x);
            stack.radius.push(self.radius_at(x));
            stack.length.push(width);
            stack.drop.push(self.drop_at(x));
        }
        stack
    }

    /// Per slice of `stack`, the perpendicular distance from the slice's axis point to the
    /// generatrix, `r cos β` less the profile drop [m]: a raceway line at a smaller distance
    /// from that axis point than this penetrates the slice by the difference.
    pub fn generatrix_reach(&self, stack: &TaperedSliceStack) -> Vec<f64> {
        let cos_beta = self.half_angle.cos();
        stack
            .radius
            .iter()
            .zip(&stack.drop)
            .map(|(r, d)| r * cos_beta - d)
            .collect()
    }

    /// Mass and inertias about the centre of mass of the body incl. the end cap and chamfers.
    pub fn mass_properties(&self) -> MassProperties {
        self.mass_and_centroid().0
    }

    /// Centre of mass from mid-length, + toward the large end [m].
    pub fn centre_of_mass_offset(&self) -> f64 {
        self.mass_and_centroid().1
    }

    fn mass_and_centroid(&self) -> (MassProperties, f64) {
        MassProperties::solid_of_revolution_with_centroid(
            |x| self.body_radius(x),
            0.5 * self.length,
            self.material.density,
            MASS_INTERVALS,
        )
    }

    pub fn validate(&self) -> Result<(), GeometryError> {
        require_positive("roller.mean_diameter", self.mean_diameter)?;
        require_positive("roller.length", self.length)?;
        require_positive("roller.half_angle", self.half_angle)?;
        if self.half_angle >= 10f64.to_radians() {
            return Err(GeometryError::new(
                "roller.half_angle",
                format!(
                    "{:.1}′ is not a roller taper (below 10°)",
                    self.half_angle.to_degrees() * 60.0
                ),
            ));
        }
        if self.slice_count == 0 || self.slice_count > 1000 {
            return Err(GeometryError::new(
                "roller.slices",
                format!("must be between 1 and 1000, got {}", self.slice_count),
            ));
        }
        let small_radius = 0.5 * self.small_diameter();
        if !(small_radius > 0.0) {
            return Err(GeometryError::new(
                "roller.length",
                "the roller is longer than its cone: the small end would pass the apex",
            ));
        }
        if !(self.end_chamfer >= 0.0) || self.end_chamfer >= small_radius.min(0.25 * self.length) {
            return Err(GeometryError::new(
                "roller.end_chamfer",
                format!(
                    "{:.3} mm must be ≥ 0 and smaller than the small-end radius and a quarter of the length",
                    self.end_chamfer * 1e3
                ),
            ));
        }
        if !(self.large_end_sphere_radius > 0.5 * self.large_diameter()) {
            return Err(GeometryError::new(
                "roller.large_end_sphere_radius",
                format!(
                    "{:.3} mm must exceed the large-end radius {:.3} mm (infinite = flat end)",
                    self.large_end_sphere_radius * 1e3,
                    0.5e3 * self.large_diameter()
                ),
            ));
        }
        if let Some(p) = &self.profile {
            validate_profile(p, self.small_diameter(), "roller.profile")?;
        }
        Ok(())
    }
}
