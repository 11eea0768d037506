//! One row of a double-row tapered bearing in the (r, z) half-plane: raceway lines, seated
//! roller, large-rib contact and small rib (seed 000 §3.2; apex condition).
//!
//! Everything is built once in the row's own frame (large ends toward +z, roller mid-points at
//! z = 0) and then placed by [`RowFrame`]: the O/X mirror lives there and nowhere else.

use super::bearing::DoubleRowTaperedBearing;
use super::plane::{Rz, axis_crossing};
use super::rib::{TaperedRibFace, end_contact_angle};

/// A raceway generatrix in the (r, z) half-plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewayLine {
    /// The point of the line in the mid-length section of the seated roller [m].
    pub point: Rz,
    /// Unit direction along the raceway toward the roller large end.
    pub direction: Rz,
    /// Unit normal out of the ring surface, toward the roller.
    pub normal: Rz,
}

/// The large-rib face at the initial contact with the roller end sphere (roller seated on the
/// cone raceway).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LargeRibContact {
    pub face: TaperedRibFace,
    /// Initial contact point, at mid rib height [m].
    pub point: Rz,
    /// Unit face normal at the contact, out of the rib toward the roller.
    pub normal: Rz,
    /// Unit face tangent at the contact, away from the raceway (up the rib).
    pub tangent: Rz,
    /// Centre of the face's profile arc for toroidal faces [m].
    pub face_centre: Option<Rz>,
    /// Face band along `tangent` from `point`: (undercut end, rib top), signed distances [m].
    pub band: (f64, f64),
    /// Where the face tangent at the contact meets the cone raceway line (the rib's foot) [m].
    pub face_base: Rz,
    /// Centre of the roller's end sphere when seated [m].
    pub end_sphere_centre: Rz,
}

impl LargeRibContact {
    /// Normal curvature of the rib face along its parallel circle at the contact, by Meusnier's
    /// theorem `κ = n_r / r` (the face is a surface of revolution about the bearing axis),
    /// signed convex > 0 toward the roller as in the contact crate's curvatures, 1/m. For the
    /// example's cone rib −1.38 m⁻¹: the rib wraps the end sphere around the circumference
    /// (seed 000 §3.2.2 gives only the axial-section curvatures).
    pub fn circumferential_curvature(&self) -> f64 {
        self.normal.r / self.point.r
    }
}

/// The small (retaining) rib face: a plane normal to the roller axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SmallRibFace {
    /// Where the face meets the cone raceway line [m].
    pub point: Rz,
    /// Unit face normal toward the roller (along the roller axis, toward the large end).
    pub normal: Rz,
    /// Axial gap between the seated roller's small end face and this face [m].
    pub gap: f64,
}

/// One row in bearing coordinates (z = bearing axis, origin at the bearing mid-plane).
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedRow {
    pub index: usize,
    /// Axial position of the roller mid-points' circle [m].
    pub mid_z: f64,
    /// +1 if the large ends point to +z, −1 otherwise.
    pub large_end_sign: f64,
    /// Apex of the roller and the cone raceway on the bearing axis [m].
    pub apex_z: f64,
    /// Axis crossing of the cup raceway line, moved from `apex_z` by the normal gap [m].
    pub cup_apex_z: f64,
    /// Roller mid-point of a seated roller (r = d_m/2) [m].
    pub roller_mid: Rz,
    /// Unit roller-axis direction, small end → large end.
    pub roller_axis: Rz,
    pub cone: RacewayLine,
    /// Cup line placed at the per-row normal gap from the roller.
    pub cup: RacewayLine,
    pub large_rib: LargeRibContact,
    pub small_rib: SmallRibFace,
}

/// Placement of a row's own frame in the bearing: z ↦ mid_z + sign·z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowFrame {
    pub mid_z: f64,
    pub sign: f64,
}

impl RowFrame {
    pub fn of(bearing: &DoubleRowTaperedBearing, k: usize) -> Self {
        let side = if k == 0 { -1.0 } else { 1.0 };
        Self {
            mid_z: side * 0.5 * bearing.row_spacing,
            sign: bearing.arrangement.large_end_sign(k),
        }
    }

    pub fn point(&self, p: Rz) -> Rz {
        Rz::new(p.r, self.mid_z + self.sign * p.z)
    }

    pub fn direction(&self, v: Rz) -> Rz {
        Rz::new(v.r, self.sign * v.z)
    }

    fn line(&self, l: RacewayLine) -> RacewayLine {
        RacewayLine {
            point: self.point(l.point),
            direction: self.direction(l.direction),
            normal: self.direction(l.normal),
        }
    }
}

/// The roller's own section coordinates (x along the axis from mid-length, y away from the
/// cone) mapped into the row frame.
struct RollerSection {
    mid: Rz,
    axis: Rz,
    outward: Rz,
}

impl RollerSection {
    fn at(&self, x: f64, y: f64) -> Rz {
        self.mid + x * self.axis + y * self.outward
    }

    fn vector(&self, x: f64, y: f64) -> Rz {
        x * self.axis + y * self.outward
    }
}

impl DoubleRowTaperedBearing {
    /// Row `k` (0: z < 0, 1: z > 0) in bearing coordinates.
    pub fn row(&self, k: usize) -> TaperedRow {
        TaperedRow::new(self, k)
    }
}

impl TaperedRow {
    pub fn new(bearing: &DoubleRowTaperedBearing, k: usize) -> Self {
        let frame = RowFrame::of(bearing, k);
        let roller = &bearing.roller;
        let axis = Rz::at_angle_from_axis(bearing.roller_axis_angle());
        let section = RollerSection {
            mid: Rz::new(0.5 * bearing.pitch_diameter, 0.0),
            axis,
            outward: axis.perpendicular(),
        };
        let half_dw = 0.5 * roller.mean_diameter;
        let cone_direction = Rz::at_angle_from_axis(bearing.cone_angle());
        let cone = RacewayLine {
            point: section.at(0.0, -half_dw),
            direction: cone_direction,
            normal: cone_direction.perpendicular(),
        };
        let cup_direction = Rz::at_angle_from_axis(bearing.cup_angle());
        let cup_normal = -cup_direction.perpendicular();
        let cup = RacewayLine {
            point: section.at(0.0, half_dw) - bearing.normal_gap() * cup_normal,
            direction: cup_direction,
            normal: cup_normal,
        };
        let apex = axis_crossing(cone.point, cone.direction).unwrap_or(f64::NAN);
        let cup_apex = axis_crossing(cup.point, cup.direction).unwrap_or(f64::NAN);
        Self {
            index: k,
            mid_z: frame.mid_z,
            large_end_sign: frame.sign,
            apex_z: frame.point(Rz::new(0.0, apex)).z,
            cup_apex_z: frame.point(Rz::new(0.0, cup_apex)).z,
            roller_mid: frame.point(section.mid),
            roller_axis: frame.direction(axis),
            cone: frame.line(cone),
            cup: frame.line(cup),
            large_rib: large_rib_contact(bearing, &section, &frame),
            small_rib: small_rib_face(bearing, &section, &frame),
        }
    }
}

/// The large-rib face placed so that the end sphere touches it at mid rib height.
fn large_rib_contact(
    bearing: &DoubleRowTaperedBearing,
    section: &RollerSection,
    frame: &RowFrame,
) -> LargeRibContact {
    let roller = &bearing.roller;
    let rib = &bearing.large_rib;
    let phi = end_contact_angle(roller, rib.contact_height()).unwrap_or(f64::NAN);
    let radius = roller.large_end_sphere_radius;
    let centre = section.at(roller.sphere_centre(), 0.0);
    let towards_rib = section.vector(phi.cos(), -phi.sin());
    let point = centre + radius * towards_rib;
    let face_centre = match rib.face {
        TaperedRibFace::Conical => None,
        TaperedRibFace::ConcaveTorus { radius } => Some(point - radius * towards_rib),
        TaperedRibFace::ConvexTorus { radius } => Some(point + radius * towards_rib),
    };
    let h = rib.contact_height();
    LargeRibContact {
        face: rib.face,
        point: frame.point(point),
        normal: frame.direction(-towards_rib),
        tangent: frame.direction(section.vector(phi.sin(), phi.cos())),
        face_centre: face_centre.map(|c| frame.point(c)),
        band: (rib.undercut - h, rib.height - h),
        face_base: frame.point(point - h * section.vector(phi.sin(), phi.cos())),
        end_sphere_centre: frame.point(centre),
    }
}

/// The small rib: a plane normal to the roller axis, `small_rib_gap` beyond the small end.
fn small_rib_face(
    bearing: &DoubleRowTaperedBearing,
    section: &RollerSection,
    frame: &RowFrame,
) -> SmallRibFace {
    let roller = &bearing.roller;
    let x = -0.5 * roller.length - bearing.small_rib_gap;
    let y = -(x + roller.apex_distance()) * roller.half_angle.tan();
    SmallRibFace {
        point: frame.point(section.at(x, y)),
        normal: frame.direction(section.axis),
        gap: bearing.small_rib_gap,
    }
}
