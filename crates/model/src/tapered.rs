//! The model file of a double-row tapered roller bearing (`[bearing] kind =
//! "double-row-tapered"`, docs/model-format.md "Double-row tapered bearing"): schema in
//! engineering units and its conversion to [`DoubleRowTaperedBearing`] (SI).

use crate::convert::{DesignContact, Materials, mass_properties, profile};
use crate::schema::{
    DynamicsSection, LubricantSection, MassOverride, MaterialSection, MisalignmentSection,
    ModelKind, OperatingSection, ProfileSection,
};
use rolldyn_contact::hertz::{Conformity, reduced_modulus, reduced_radius};
use rolldyn_geometry::tapered::DEFAULT_TAPERED_SLICES;
use rolldyn_geometry::*;
use rolldyn_units::{Angle, Dimensionless, Length, Quantity};
use serde::Deserialize;
use std::collections::BTreeMap;

/// Roller–cage friction of the polyamide cage (seed 000 §3.2: 0.06).
pub const DEFAULT_POLYAMIDE_CAGE_FRICTION: f64 = 0.06;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaperedModelFile {
    pub bearing: TaperedBearingSection,
    #[serde(default)]
    pub materials: BTreeMap<String, MaterialSection>,
    pub roller: TaperedRollerSection,
    pub large_rib: LargeRibSection,
    pub small_rib: SmallRibSection,
    pub cage: TaperedCageSection,
    pub misalignment: Option<MisalignmentSection>,
    pub lubricant: Option<LubricantSection>,
    pub operating: Option<OperatingSection>,
    pub dynamics: Option<DynamicsSection>,
}

#[derive(Debug, Deserialize, Clone, Copy)]
pub enum ArrangementName {
    O,
    X,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaperedBearingSection {
    pub name: String,
    pub kind: ModelKind,
    pub description: Option<String>,
    pub bore: Quantity<Length>,
    pub outside_diameter: Quantity<Length>,
    pub pitch_diameter: Quantity<Length>,
    pub rollers_per_row: usize,
    pub arrangement: ArrangementName,
    pub row_spacing: Quantity<Length>,
    pub axial_clearance: Quantity<Length>,
    pub inner_ring_material: Option<String>,
    pub outer_ring_material: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaperedRollerSection {
    pub mean_diameter: Quantity<Length>,
    pub length: Quantity<Length>,
    pub half_angle: Quantity<Angle>,
    pub large_end_sphere_radius: Quantity<Length>,
    pub end_chamfer: Quantity<Length>,
    pub slices: Option<usize>,
    pub material: Option<String>,
    pub profile: Option<ProfileSection>,
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum RibFaceName {
    Conical,
    Concave,
    Convex,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LargeRibSection {
    pub face: RibFaceName,
    pub face_radius: Option<Quantity<Length>>,
    pub height: Quantity<Length>,
    pub undercut: Quantity<Length>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SmallRibSection {
    pub gap: Quantity<Length>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaperedCageSection {
    pub pocket_clearance: Quantity<Length>,
    pub end_clearance: Quantity<Length>,
    pub bar_contact_diameter: Quantity<Length>,
    pub inner_diameter: Quantity<Length>,
    pub outer_diameter: Quantity<Length>,
    pub width: Quantity<Length>,
    pub material: Option<String>,
    pub roller_friction: Option<Quantity<Dimensionless>>,
    #[serde(default)]
    pub mass_properties: MassOverride,
}

type Result<T> = std::result::Result<T, GeometryError>;

/// Refuses the keys of the shared tables that the tapered dynamics does not read (it runs with
/// the cup fixed, its contact parameters fixed, docs/theory.md §12.2), so that none is
/// silently ignored.
pub(crate) fn refuse_unread_keys(file: &TaperedModelFile) -> Result<()> {
    let unread = |key: &str, reason: &str| Err(GeometryError::new(key, reason.to_string()));
    if file.dynamics.is_some() {
        return unread(
            "dynamics",
            "a double-row tapered model takes no [dynamics] table: its contact parameters are fixed (docs/theory.md §12.2)",
        );
    }
    let Some(op) = &file.operating else {
        return Ok(());
    };
    if op.outer_speed.is_some_and(|w| w.si() != 0.0) {
        return unread(
            "operating.outer_speed",
            "the tapered dynamics runs with the cup fixed: give 0 rpm or leave it out",
        );
    }
    if op.clearance_schedule.is_some() {
        return unread(
            "operating.clearance_schedule",
            "a double-row tapered bearing has an axial clearance (bearing.axial_clearance), not a radial clearance schedule",
        );
    }
    Ok(())
}

/// Builds the bearing a tapered model file describes.
pub(crate) fn build(file: &TaperedModelFile) -> Result<DoubleRowTaperedBearing> {
    let materials = Materials::new(&file.materials)?;
    let b = &file.bearing;
    let mut bearing = DoubleRowTaperedBearing {
        name: b.name.clone(),
        bore: b.bore.si(),
        outside_diameter: b.outside_diameter.si(),
        pitch_diameter: b.pitch_diameter.si(),
        roller: roller(&file.roller, &materials)?,
        rollers_per_row: b.rollers_per_row,
        arrangement: match b.arrangement {
            ArrangementName::O => Arrangement::O,
            ArrangementName::X => Arrangement::X,
        },
        row_spacing: b.row_spacing.si(),
        axial_clearance: b.axial_clearance.si(),
        large_rib: large_rib(&file.large_rib)?,
        small_rib_gap: file.small_rib.gap.si(),
        cage: cage(&file.cage, &materials)?,
        inner_material: materials.get(
            b.inner_ring_material.as_deref(),
            "bearing.inner_ring_material",
        )?,
        outer_material: materials.get(
            b.outer_ring_material.as_deref(),
            "bearing.outer_ring_material",
        )?,
        misalignment: Misalignment {
            inner_ring_tilt: file
                .misalignment
                .as_ref()
                .map_or(0.0, |m| m.inner_ring.si()),
        },
        wear: Default::default(),
    };
    bearing.roller.validate()?;
    if let Some(section) = &file.roller.profile {
        let design = design_contact(&bearing)?;
        let half = bearing.roller.working_half_length();
        bearing.roller.profile = Some(profile(section, half, "roller.profile", &design)?);
    }
    let computed = bearing
        .cage
        .computed_mass_properties(&bearing.roller, bearing.rollers_per_row);
    let m = mass_properties(computed, &file.cage.mass_properties, "cage.mass_properties")?;
    bearing.cage.mass = m.mass;
    bearing.cage.inertia_axial = m.axial_inertia;
    bearing.cage.inertia_transverse = m.transverse_inertia;
    Ok(bearing)
}

fn roller(section: &TaperedRollerSection, materials: &Materials) -> Result<TaperedRoller> {
    Ok(TaperedRoller {
        mean_diameter: section.mean_diameter.si(),
        length: section.length.si(),
        half_angle: section.half_angle.si(),
        large_end_sphere_radius: section.large_end_sphere_radius.si(),
        end_chamfer: section.end_chamfer.si(),
        slice_count: section.slices.unwrap_or(DEFAULT_TAPERED_SLICES),
        material: materials.get(section.material.as_deref(), "roller.material")?,
        profile: None,
    })
}

fn large_rib(section: &LargeRibSection) -> Result<LargeRib> {
    let radius = || {
        section.face_radius.map(|r| r.si()).ok_or_else(|| {
            GeometryError::new(
                "large_rib.face_radius",
                "missing key: a toroidal face needs its radius",
            )
        })
    };
    let face = match section.face {
        RibFaceName::Conical if section.face_radius.is_some() => {
            return Err(GeometryError::new(
                "large_rib.face_radius",
                "does not apply to a conical face",
            ));
        }
        RibFaceName::Conical => TaperedRibFace::Conical,
        RibFaceName::Concave => TaperedRibFace::ConcaveTorus { radius: radius()? },
        RibFaceName::Convex => TaperedRibFace::ConvexTorus { radius: radius()? },
    };
    Ok(LargeRib {
        face,
        height: section.height.si(),
        undercut: section.undercut.si(),
    })
}

fn cage(section: &TaperedCageSection, materials: &Materials) -> Result<TaperedCage> {
    Ok(TaperedCage {
        pocket_clearance: section.pocket_clearance.si(),
        end_clearance: section.end_clearance.si(),
        bar_contact_diameter: section.bar_contact_diameter.si(),
        inner_diameter: section.inner_diameter.si(),
        outer_diameter: section.outer_diameter.si(),
        width: section.width.si(),
        mass: 0.0,
        inertia_axial: 0.0,
        inertia_transverse: 0.0,
        material: materials.get(section.material.as_deref(), "cage.material")?,
        roller_friction: section
            .roller_friction
            .map_or(DEFAULT_POLYAMIDE_CAGE_FRICTION, |f| f.si()),
    })
}

/// The roller on the cone raceway in the mid-length section, for a Johns–Gohar profile: the
/// normal-section radii of the roller (D_w / (2 cos β)) and of the cone (r_i / cos α_i).
fn design_contact(bearing: &DoubleRowTaperedBearing) -> Result<DesignContact> {
    let (roller, inner) = (&bearing.roller.material, &bearing.inner_material);
    let (cone_radius, _) = bearing.contact_radii();
    Ok(DesignContact {
        reduced_modulus: reduced_modulus(
            roller.youngs_modulus,
            roller.poisson_ratio,
            inner.youngs_modulus,
            inner.poisson_ratio,
        ),
        reduced_radius: reduced_radius(
            0.5 * bearing.roller.mean_diameter / bearing.roller.half_angle.cos(),
            cone_radius / bearing.cone_angle().cos(),
            Conformity::ConvexConvex,
        )
        .map_err(|e| GeometryError::new("bearing.pitch_diameter", e.to_string()))?,
    })
}
