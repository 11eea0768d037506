//! Schema (engineering units) → geometry (SI), with defaults and key-naming errors.

use crate::schema::*;
use rolldyn_contact::hertz::Conformity;
use rolldyn_geometry::*;
use std::collections::BTreeMap;

/// Default number of slices per roller (seed 000 Fig. 2.4 uses 9 for display; 30 resolves a
/// crown of a few µm to better than 1 % in load, SPEC §1.3).
pub const DEFAULT_SLICES: usize = 30;

type Result<T> = std::result::Result<T, GeometryError>;

/// The materials a model's parts may name: the built-in ones
/// ([`rolldyn_geometry::material_database`]) and the file's `[materials]` tables, which take
/// precedence.
pub(crate) struct Materials(BTreeMap<String, Material>);

impl Materials {
    pub(crate) fn new(sections: &BTreeMap<String, MaterialSection>) -> Result<Self> {
        let mut map: BTreeMap<String, Material> = material_database::all()
            .iter()
            .flat_map(|r| {
                let material = r.material();
                std::iter::once(r.name)
                    .chain(r.aliases.iter().copied())
                    .map(move |name| (name.to_string(), material.clone()))
            })
            .collect();
        for (name, m) in sections {
            let key = |field: &str| format!("materials.{name}.{field}");
            let material = Material {
                name: name.clone(),
                youngs_modulus: m.youngs_modulus.si(),
                poisson_ratio: m.poisson_ratio.si(),
                density: m.density.si(),
                meyer_hardness: m.meyer_hardness.map(|h| h.si()),
                fatigue: fatigue_strength(m, &key)?,
            };
            require_positive(&key("youngs_modulus"), material.youngs_modulus)?;
            require_positive(&key("density"), material.density)?;
            if !(0.0..0.5).contains(&material.poisson_ratio) {
                return Err(GeometryError::new(
                    key("poisson_ratio"),
                    "must lie in [0, 0.5)",
                ));
            }
            rolldyn_geometry::plausible::check_material(&format!("materials.{name}"), &material)?;
            if let Some(h) = material.meyer_hardness {
                require_positive(&key("meyer_hardness"), h)?;
            }
            map.insert(name.clone(), material);
        }
        Ok(Self(map))
    }

    pub(crate) fn get(&self, name: Option<&str>, key: &str) -> Result<Material> {
        let name = name.unwrap_or("bearing-steel");
        self.0.get(name).cloned().ok_or_else(|| {
            let known: Vec<_> = self.0.keys().map(String::as_str).collect();
            GeometryError::new(
                key,
                format!("unknown material '{name}' (known: {})", known.join(", ")),
            )
        })
    }
}

/// The S–N curve and σ_u of a `[materials]` table: its own `sn_curve` with `ultimate_strength`,
/// those of the built-in material it names in `fatigue_like`, or none.
fn fatigue_strength(
    m: &MaterialSection,
    key: &dyn Fn(&str) -> String,
) -> Result<Option<FatigueStrength>> {
    match (&m.fatigue_like, &m.sn_curve, m.ultimate_strength) {
        (None, None, None) => Ok(None),
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => Err(GeometryError::new(
            key("fatigue_like"),
            "give either fatigue_like or sn_curve with ultimate_strength, not both",
        )),
        (Some(like), None, None) => {
            let record = material_database::find(like).ok_or_else(|| {
                GeometryError::new(
                    key("fatigue_like"),
                    format!(
                        "unknown built-in material '{like}' (known: {})",
                        material_database::names().join(", ")
                    ),
                )
            })?;
            Ok(record.material().fatigue)
        }
        (None, Some(_), None) => Err(GeometryError::new(
            key("ultimate_strength"),
            "needed with sn_curve (the Goodman and Gerber corrections use it)",
        )),
        (None, None, Some(_)) => Err(GeometryError::new(
            key("sn_curve"),
            "needed with ultimate_strength (σ_u alone gives no fatigue strength)",
        )),
        (None, Some(curve), Some(ultimate)) => {
            let sn_key = key("sn_curve");
            if curve.cycles.len() != curve.amplitude.len() {
                return Err(GeometryError::new(
                    sn_key,
                    format!(
                        "{} cycles but {} amplitudes: give one amplitude per cycle count",
                        curve.cycles.len(),
                        curve.amplitude.len()
                    ),
                ));
            }
            let points: Vec<(f64, f64)> = curve
                .cycles
                .iter()
                .zip(&curve.amplitude)
                .map(|(&n, s)| (n, s.si()))
                .collect();
            if points.len() < 2 {
                return Err(GeometryError::new(
                    sn_key,
                    format!(
                        "an S–N curve needs at least two points, got {}",
                        points.len()
                    ),
                ));
            }
            if let Some((index, reason)) = first_invalid_sn_point(&points) {
                return Err(GeometryError::new(
                    sn_key,
                    format!("point {index}: {reason}"),
                ));
            }
            if curve.source.trim().is_empty() {
                return Err(GeometryError::new(
                    format!("{sn_key}.source"),
                    "say where the points come from",
                ));
            }
            require_positive(&key("ultimate_strength"), ultimate.si())?;
            Ok(Some(FatigueStrength {
                ultimate_strength: ultimate.si(),
                sn_curve: points,
                source: format!("{sn_key}: {}", curve.source.trim()),
            }))
        }
    }
}

pub(crate) fn mass_properties(
    computed: MassProperties,
    given: &MassOverride,
    key: &str,
) -> Result<MassProperties> {
    let Some(mass) = given.mass.map(|m| m.si()) else {
        if given.axial_inertia.is_some() || given.transverse_inertia.is_some() {
            return Err(GeometryError::new(
                format!("{key}.mass"),
                "give the mass together with the inertias",
            ));
        }
        return Ok(computed);
    };
    require_positive(&format!("{key}.mass"), mass)?;
    rolldyn_geometry::plausible::check_mass(&format!("{key}.mass"), mass, computed.mass)?;
    let scaled = computed.scaled(mass / computed.mass);
    Ok(MassProperties {
        mass,
        axial_inertia: given.axial_inertia.map_or(scaled.axial_inertia, |i| i.si()),
        transverse_inertia: given
            .transverse_inertia
            .map_or(scaled.transverse_inertia, |i| i.si()),
    })
}

fn chamfer(section: &Option<ChamferSection>) -> Option<Chamfer> {
    section.as_ref().map(|c| Chamfer {
        axial_length: c.axial.si(),
        radial_height: c.radial.si(),
        radius: c.radius.si(),
    })
}

/// Inputs the Johns–Gohar profile needs from the rest of the model.
pub(crate) struct DesignContact {
    pub reduced_modulus: f64,
    pub reduced_radius: f64,
}

pub(crate) fn profile(
    section: &ProfileSection,
    half_length: f64,
    key: &str,
    design: &DesignContact,
) -> Result<Profile> {
    let (shape, chamfer_section) = match section {
        ProfileSection::Straight { chamfer } => (ProfileShape::Straight, chamfer),
        ProfileSection::Crowned {
            straight_length,
            drop,
            crown_radius,
            chamfer,
        } => (
            ProfileShape::Crowned {
                straight_length: straight_length.si(),
                drop: drop.si(),
                crown_radius: crown_radius.map(|r| r.si()),
            },
            chamfer,
        ),
        ProfileSection::Logarithmic { k, c, chamfer } => (
            ProfileShape::Logarithmic {
                k: k.si(),
                c: c.si(),
            },
            chamfer,
        ),
        ProfileSection::JohnsGohar {
            design_load,
            chamfer,
        } => {
            let load = design_load.si();
            require_positive(&format!("{key}.design_load"), load)?;
            let effective_length =
                2.0 * (half_length - chamfer.as_ref().map_or(0.0, |c| c.axial.si()));
            let hertz = rolldyn_contact::hertz::LineContact {
                reduced_radius: design.reduced_radius,
                reduced_modulus: design.reduced_modulus,
                length: effective_length,
            };
            (
                ProfileShape::JohnsGohar {
                    design_load: load,
                    effective_length,
                    reduced_modulus: design.reduced_modulus,
                    hertz_half_width: hertz.half_width(load),
                },
                chamfer,
            )
        }
        ProfileSection::Polyline { x, drop, chamfer } => {
            if x.len() != drop.len() {
                return Err(GeometryError::new(
                    format!("{key}.drop"),
                    format!("has {} values but {key}.x has {}", drop.len(), x.len()),
                ));
            }
            let points = x.iter().zip(drop).map(|(x, z)| (x.si(), z.si())).collect();
            (ProfileShape::Polyline { points }, chamfer)
        }
    };
    Ok(Profile {
        shape,
        chamfer: chamfer(chamfer_section),
        half_length,
    })
}

fn ring(
    section: &RingSection,
    key: &str,
    inner: bool,
    materials: &Materials,
    design: &DesignContact,
) -> Result<Ring> {
    let (wanted, unwanted) = if inner {
        (section.bore_diameter, section.outside_diameter)
    } else {
        (section.outside_diameter, section.bore_diameter)
    };
    let (wanted_key, unwanted_key) = if inner {
        ("bore_diameter", "outside_diameter")
    } else {
        ("outside_diameter", "bore_diameter")
    };
    if unwanted.is_some() {
        return Err(GeometryError::new(
            format!("{key}.{unwanted_key}"),
            format!("does not apply to this ring; use {key}.{wanted_key}"),
        ));
    }
    let body_diameter = wanted
        .ok_or_else(|| GeometryError::new(format!("{key}.{wanted_key}"), "missing key"))?
        .si();
    let ribs = section
        .ribs
        .iter()
        .map(|r| Rib {
            side: match r.side {
                RibSideName::Left => RibSide::Left,
                RibSideName::Right => RibSide::Right,
            },
            diameter: r.diameter.si(),
            face: match &r.face {
                RibFaceSection::Flat => RibFace::Flat,
                RibFaceSection::Cone { angle } => RibFace::Cone { angle: angle.si() },
                RibFaceSection::ConvexTorus {
                    radius,
                    crest_offset,
                } => RibFace::ConvexTorus {
                    radius: radius.si(),
                    crest_offset: crest_offset.map_or(0.0, |c| c.si()),
                },
                RibFaceSection::ConcaveTorus { radius } => RibFace::ConcaveTorus {
                    radius: radius.si(),
                },
            },
            edge_break: r.edge_break.map_or(0.0, |e| e.si()),
        })
        .collect();
    let width = section.width.si();
    let raceway_profile = section
        .raceway_profile
        .as_ref()
        .map(|p| profile(p, 0.5 * width, &format!("{key}.raceway_profile"), design))
        .transpose()?;
    let mut ring = Ring {
        raceway_diameter: section.raceway_diameter.si(),
        body_diameter,
        width,
        ribs,
        rib_spacing: section.rib_spacing.map(|s| s.si()),
        raceway_profile,
        raceway_wear: None,
        guiding_land: None,
        material: materials.get(section.material.as_deref(), &format!("{key}.material"))?,
        roughness_ra: section.roughness_ra.map_or(0.0, |r| r.si()),
        mass_properties: MassProperties::default(),
    };
    ring.mass_properties = mass_properties(
        ring.computed_mass_properties(),
        &section.mass_properties,
        &format!("{key}.mass_properties"),
    )?;
    Ok(ring)
}

fn roller(
    section: &RollerSection,
    materials: &Materials,
    design: &DesignContact,
) -> Result<Roller> {
    let length = section.length.si();
    let half = 0.5 * length;
    let profile = match &section.profile {
        Some(p) => profile(p, half, "roller.profile", design)?,
        None => Profile::straight(half),
    };
    let mut roller = Roller {
        diameter: section.diameter.si(),
        length,
        profile,
        end_face: match section.end_face {
            None | Some(EndFaceSection::Flat) => EndFace::Flat,
            Some(EndFaceSection::Sphere { radius }) => EndFace::Sphere {
                radius: radius.si(),
            },
        },
        edge_break: section.edge_break.map_or(0.0, |e| e.si()),
        slice_count: section.slices.unwrap_or(DEFAULT_SLICES),
        material: materials.get(section.material.as_deref(), "roller.material")?,
        roughness_ra: section.roughness_ra.map_or(0.0, |r| r.si()),
        mass_properties: MassProperties::default(),
    };
    require_positive("roller.diameter", roller.diameter)?;
    require_positive("roller.length", roller.length)?;
    roller.mass_properties = mass_properties(
        roller.computed_mass_properties(),
        &section.mass_properties,
        "roller.mass_properties",
    )?;
    Ok(roller)
}

fn pocket(section: &CageSection) -> CagePocket {
    let p = &section.pocket;
    let lip = |l: &LipSection| RetainingLip {
        diameter: l.diameter.si(),
        window: l.window.si(),
        tip_radius: l.tip_radius.map_or(0.0, |r| r.si()),
    };
    CagePocket {
        faces: match p.faces {
            None | Some(PocketFacesName::Flat) => PocketFaces::Flat,
            Some(PocketFacesName::Concave) => PocketFaces::Concave,
        },
        face_clearance: p.face_clearance.si(),
        outer_lip: p.outer_lip.as_ref().map(lip),
        inner_lip: p.inner_lip.as_ref().map(lip),
        axial: section.pocket_axial.si(),
        fillet_radius: p.fillet_radius.map_or(0.0, |r| r.si()),
    }
}

/// The cage of a bearing whose pocket sits on the pitch radius `pitch_radius` around rollers of
/// radius `roller_radius`: its mass follows from the pocket profile.
fn cage(
    section: &CageSection,
    materials: &Materials,
    (pockets, roller_radius, pitch_radius): (usize, f64, f64),
) -> Result<Cage> {
    let mut cage = Cage {
        guidance: match section.guidance {
            GuidanceName::InnerLand => CageGuidance::InnerLand,
            GuidanceName::OuterLand => CageGuidance::OuterLand,
            GuidanceName::Rollers => CageGuidance::Rollers,
        },
        floating_clearance: section.floating_clearance.map_or(0.0, |c| c.si()),
        pocket: pocket(section),
        inner_diameter: section.inner_diameter.si(),
        outer_diameter: section.outer_diameter.si(),
        width: section.width.si(),
        material: materials.get(section.material.as_deref(), "cage.material")?,
        plating: section.plating,
        roughness_ra: section.roughness_ra.map_or(0.0, |r| r.si()),
        mass_properties: MassProperties::default(),
    };
    cage.validate()?;
    let ctx = cage.pocket_context(roller_radius, pitch_radius, pockets);
    cage.mass_properties = mass_properties(
        cage.computed_mass_properties(&ctx)?,
        &section.mass_properties,
        "cage.mass_properties",
    )?;
    Ok(cage)
}

/// The contact of the roller with the first given raceway decides the Johns–Gohar profile.
fn design_contact(file: &ModelFile, materials: &Materials) -> Result<DesignContact> {
    let (section, inner) = match (&file.inner_ring, &file.outer_ring) {
        (Some(r), _) => (r, true),
        (None, Some(r)) => (r, false),
        (None, None) => {
            return Err(GeometryError::new(
                "inner_ring",
                "missing: give inner_ring and/or outer_ring",
            ));
        }
    };
    let ring = if inner { "inner_ring" } else { "outer_ring" };
    let ring_material = materials.get(section.material.as_deref(), &format!("{ring}.material"))?;
    let roller_material = materials.get(file.roller.material.as_deref(), "roller.material")?;
    let raceway_key = format!("{ring}.raceway_diameter");
    // each diameter checked on its own, so that the error blames the value that is wrong
    require_positive("roller.diameter", file.roller.diameter.si())?;
    require_positive(&raceway_key, section.raceway_diameter.si())?;
    let conformity = if inner {
        Conformity::ConvexConvex
    } else {
        Conformity::ConvexConcave
    };
    Ok(DesignContact {
        reduced_modulus: rolldyn_contact::hertz::reduced_modulus(
            roller_material.youngs_modulus,
            roller_material.poisson_ratio,
            ring_material.youngs_modulus,
            ring_material.poisson_ratio,
        ),
        reduced_radius: rolldyn_contact::hertz::reduced_radius(
            0.5 * file.roller.diameter.si(),
            0.5 * section.raceway_diameter.si(),
            conformity,
        )
        .map_err(|e| GeometryError::new(raceway_key, e.to_string()))?,
    })
}

/// Builds the geometry a model file describes.
pub(crate) fn build(file: &ModelFile) -> Result<BearingModel> {
    let materials = Materials::new(&file.materials)?;
    let design = design_contact(file, &materials)?;
    let roller = roller(&file.roller, &materials, &design)?;
    let misalignment = Misalignment {
        inner_ring_tilt: file
            .misalignment
            .as_ref()
            .map_or(0.0, |m| m.inner_ring.si()),
    };
    let name = file.bearing.name.clone();
    match file.bearing.kind {
        ModelKind::DoubleRowTapered => Err(GeometryError::new(
            "bearing.kind",
            "a double-row tapered bearing is read by its own schema (docs/model-format.md)",
        )),
        ModelKind::RollerRaceway => {
            for (present, key) in [
                (file.cage.is_some(), "cage"),
                (file.clearance.is_some(), "clearance"),
                (file.roller.count.is_some(), "roller.count"),
            ] {
                if present {
                    return Err(GeometryError::new(
                        key,
                        "does not apply to a roller-raceway model",
                    ));
                }
            }
            let (section, inner, key) = match (&file.inner_ring, &file.outer_ring) {
                (Some(r), None) => (r, true, "inner_ring"),
                (None, Some(r)) => (r, false, "outer_ring"),
                _ => {
                    return Err(GeometryError::new(
                        "outer_ring",
                        "a roller-raceway model has exactly one ring (inner_ring or outer_ring)",
                    ));
                }
            };
            Ok(BearingModel::RollerRaceway(RollerRacewayPair {
                name,
                roller,
                raceway: ring(section, key, inner, &materials, &design)?,
                raceway_is_inner: inner,
                misalignment,
            }))
        }
        ModelKind::Cylindrical => {
            let inner = file
                .inner_ring
                .as_ref()
                .ok_or_else(|| GeometryError::new("inner_ring", "missing table [inner_ring]"))?;
            let outer = file
                .outer_ring
                .as_ref()
                .ok_or_else(|| GeometryError::new("outer_ring", "missing table [outer_ring]"))?;
            let roller_count = file
                .roller
                .count
                .ok_or_else(|| GeometryError::new("roller.count", "missing key"))?;
            let mut inner_ring = ring(inner, "inner_ring", true, &materials, &design)?;
            let mut outer_ring = ring(outer, "outer_ring", false, &materials, &design)?;
            let cage = file
                .cage
                .as_ref()
                .map(|c| {
                    let pitch_radius =
                        0.25 * (inner_ring.raceway_diameter + outer_ring.raceway_diameter);
                    cage(
                        c,
                        &materials,
                        (roller_count, 0.5 * roller.diameter, pitch_radius),
                    )
                })
                .transpose()?;
            attach_guiding_land(
                cage.as_ref(),
                (inner, &mut inner_ring),
                (outer, &mut outer_ring),
            )?;
            let clearance = file.clearance.as_ref();
            let geometric =
                outer_ring.raceway_diameter - inner_ring.raceway_diameter - 2.0 * roller.diameter;
            Ok(BearingModel::Cylindrical(CylindricalRollerBearing {
                name,
                inner_ring,
                outer_ring,
                roller,
                roller_count,
                cage,
                clearance: Clearance {
                    radial: clearance
                        .and_then(|c| c.radial)
                        .map_or(geometric, |r| r.si()),
                    roller_rib_axial: clearance.and_then(|c| c.roller_rib_axial).map(|r| r.si()),
                    allow_preload: clearance.is_some_and(|c| c.preload),
                    radial_is_operating: clearance.is_some_and(|c| c.operating),
                },
                misalignment,
            }))
        }
    }
}

/// Puts the land the cage runs on onto the guiding ring: its diameter follows from the cage
/// and its floating clearance, its width from `<ring>.guiding_land.width` (default: cage width).
fn attach_guiding_land(
    cage: Option<&Cage>,
    inner: (&RingSection, &mut Ring),
    outer: (&RingSection, &mut Ring),
) -> Result<()> {
    let guidance = cage.map(|c| c.guidance);
    for ((section, ring), key, guided) in [
        (
            inner,
            "inner_ring",
            guidance == Some(CageGuidance::InnerLand),
        ),
        (
            outer,
            "outer_ring",
            guidance == Some(CageGuidance::OuterLand),
        ),
    ] {
        match (guided, &section.guiding_land, cage) {
            (true, land, Some(cage)) => {
                ring.guiding_land = cage.land_diameter().map(|diameter| GuidingLand {
                    diameter,
                    width: land.as_ref().map_or(cage.width, |l| l.width.si()),
                });
            }
            (false, Some(_), _) => {
                return Err(GeometryError::new(
                    format!("{key}.guiding_land"),
                    "this ring does not guide the cage (see cage.guidance)",
                ));
            }
            _ => {}
        }
    }
    Ok(())
}
