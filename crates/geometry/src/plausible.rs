//! Plausibility bounds of a bearing (issue 22 item 5): values that pass the consistency checks
//! but describe no bearing (a cage wider than a room, roughness comparable to the roller) are
//! rejected with the key at fault. The bounds are generous: they exclude absurd input, not
//! unusual designs (docs/model-format.md, "Plausibility bounds").

use crate::bearing::CylindricalRollerBearing;
use crate::error::GeometryError;
use crate::material::Material;
use crate::ring::Ring;

/// A ring may be at most this many times as wide as the bearing's outside diameter.
pub const MAX_WIDTH_PER_OUTSIDE_DIAMETER: f64 = 2.0;
/// The cage may be at most this many times as wide as the wider ring.
pub const MAX_CAGE_WIDTH_PER_RING_WIDTH: f64 = 2.0;
/// A roughness R_a may be at most this fraction of the roller diameter.
pub const MAX_ROUGHNESS_PER_ROLLER_DIAMETER: f64 = 0.01;
/// Densities of engineering solids, kg/m³ (foamed polymer … tungsten carbide).
pub const DENSITY_RANGE_KG_M3: (f64, f64) = (100.0, 25_000.0);
/// Young's moduli of engineering solids, Pa (soft polymer … diamond).
pub const YOUNGS_MODULUS_RANGE_PA: (f64, f64) = (1e7, 1.2e12);
/// Largest outside diameter, m: the largest rolling bearings (tunnel-boring machines, wind
/// turbines) are ≈ 8 m across.
pub const MAX_OUTSIDE_DIAMETER_M: f64 = 10.0;
/// A ring wall (raceway to bore or outside) may be at most this many roller diameters thick:
/// catalogue rings are ≈ 0.3–1.5 D_w; a thicker wall is a housing, not a ring.
pub const MAX_WALL_PER_ROLLER_DIAMETER: f64 = 10.0;
/// The radial clearance may be at most this fraction of the pitch diameter: the largest
/// ISO 5753 group (C5) stays below ≈ 0.2 % of the bore.
pub const MAX_CLEARANCE_PER_PITCH_DIAMETER: f64 = 0.01;
/// A given mass may differ from the mass computed from the dimensions by at most this factor.
pub const MAX_MASS_FACTOR: f64 = 10.0;

/// Checks that the physical constants of a material are those of a solid; `key` is its
/// `materials.<name>` path.
pub fn check_material(key: &str, m: &Material) -> Result<(), GeometryError> {
    within(
        &format!("{key}.density"),
        m.density,
        DENSITY_RANGE_KG_M3,
        "kg/m³",
        1.0,
    )?;
    within(
        &format!("{key}.youngs_modulus"),
        m.youngs_modulus,
        YOUNGS_MODULUS_RANGE_PA,
        "GPa",
        1e-9,
    )
}

/// Checks that a given mass is within [`MAX_MASS_FACTOR`] of the `computed` one.
pub fn check_mass(key: &str, given: f64, computed: f64) -> Result<(), GeometryError> {
    let range = (computed / MAX_MASS_FACTOR, computed * MAX_MASS_FACTOR);
    within(key, given, range, "kg", 1.0).map_err(|e| {
        GeometryError::new(
            e.key,
            format!("{} (the dimensions give {computed:.4} kg)", e.reason),
        )
    })
}

/// Checks an outside diameter [m] at `key` against [`MAX_OUTSIDE_DIAMETER_M`].
pub(crate) fn check_outside_diameter(key: &str, diameter: f64) -> Result<(), GeometryError> {
    at_most(
        key,
        diameter,
        MAX_OUTSIDE_DIAMETER_M,
        "10 m (the largest rolling bearings are ≈ 8 m)",
    )
}

fn within(
    key: &str,
    value: f64,
    (lo, hi): (f64, f64),
    unit: &str,
    shown: f64,
) -> Result<(), GeometryError> {
    if (lo..=hi).contains(&value) {
        return Ok(());
    }
    Err(GeometryError::new(
        key,
        format!(
            "{:.4e} {unit} is implausible (expected {:.4e}…{:.4e} {unit})",
            value * shown,
            lo * shown,
            hi * shown
        ),
    ))
}

fn at_most(key: &str, value: f64, limit: f64, what: &str) -> Result<(), GeometryError> {
    if value <= limit {
        return Ok(());
    }
    Err(GeometryError::new(
        key,
        format!(
            "{:.4e} mm is implausible: more than {what} ({:.4} mm)",
            value * 1e3,
            limit * 1e3
        ),
    ))
}

impl CylindricalRollerBearing {
    /// The plausibility bounds of a bearing that passed its consistency checks.
    pub(crate) fn validate_plausibility(&self) -> Result<(), GeometryError> {
        let outside = self.outer_ring.body_diameter;
        check_outside_diameter("outer_ring.outside_diameter", outside)?;
        let wall = MAX_WALL_PER_ROLLER_DIAMETER * self.roller.diameter;
        at_most(
            "outer_ring.outside_diameter",
            self.outer_ring.wall_thickness(),
            wall,
            "a ring wall of 10 roller diameters",
        )?;
        at_most(
            "inner_ring.bore_diameter",
            self.inner_ring.wall_thickness(),
            wall,
            "a ring wall of 10 roller diameters",
        )?;
        at_most(
            "clearance.radial",
            self.clearance.radial.abs(),
            MAX_CLEARANCE_PER_PITCH_DIAMETER * self.pitch_diameter(),
            "1 % of the pitch diameter (ISO 5753's largest group C5 is below 0.2 % of the bore)",
        )?;
        at_most(
            "roller.edge_break",
            self.roller.edge_break,
            0.5 * self.roller.diameter,
            "the roller's radius",
        )?;
        if let Some(chamfer) = self.roller.profile.chamfer {
            at_most(
                "roller.profile.chamfer.radius",
                chamfer.radius,
                self.roller.length,
                "the roller's length",
            )?;
        }
        let ring_width = self.inner_ring.width.max(self.outer_ring.width);
        for (key, ring, inner) in [
            ("inner_ring", &self.inner_ring, true),
            ("outer_ring", &self.outer_ring, false),
        ] {
            at_most(
                &format!("{key}.width"),
                ring.width,
                MAX_WIDTH_PER_OUTSIDE_DIAMETER * outside,
                "twice the outside diameter",
            )?;
            if let Some(land) = ring.guiding_land {
                at_most(
                    &format!("{key}.guiding_land.width"),
                    land.width,
                    ring.width,
                    "the ring's width",
                )?;
            }
            if let Some(chamfer) = ring.raceway_profile.as_ref().and_then(|p| p.chamfer) {
                at_most(
                    &format!("{key}.raceway_profile.chamfer.radius"),
                    chamfer.radius,
                    ring.width,
                    "the ring's width",
                )?;
            }
            self.check_ribs(key, ring, inner)?;
        }
        at_most(
            "roller.length",
            self.roller.length,
            ring_width,
            "the wider ring",
        )?;
        let roughness = MAX_ROUGHNESS_PER_ROLLER_DIAMETER * self.roller.diameter;
        let mut surfaces = vec![
            ("inner_ring.roughness_ra", self.inner_ring.roughness_ra),
            ("outer_ring.roughness_ra", self.outer_ring.roughness_ra),
            ("roller.roughness_ra", self.roller.roughness_ra),
        ];
        if let Some(cage) = &self.cage {
            at_most(
                "cage.width",
                cage.width,
                MAX_CAGE_WIDTH_PER_RING_WIDTH * ring_width,
                "twice the wider ring",
            )?;
            at_most(
                "cage.outer_diameter",
                cage.outer_diameter,
                outside,
                "the bearing's outside diameter",
            )?;
            at_most(
                "cage.pocket.fillet_radius",
                cage.pocket.fillet_radius,
                0.5 * self.roller.diameter,
                "the roller's radius (the fillet would fill the window)",
            )?;
            surfaces.push(("cage.roughness_ra", cage.roughness_ra));
        }
        for (key, ra) in surfaces {
            at_most(key, ra, roughness, "1 % of the roller diameter")?;
        }
        Ok(())
    }

    /// At most one rib per side, and each rim inside the other ring's raceway.
    fn check_ribs(&self, key: &str, ring: &Ring, inner: bool) -> Result<(), GeometryError> {
        for (i, rib) in ring.ribs.iter().enumerate() {
            let rib_key = format!("{key}.ribs[{i}]");
            if ring.ribs[..i].iter().any(|r| r.side == rib.side) {
                return Err(GeometryError::new(
                    format!("{rib_key}.side"),
                    "a ring has at most one rib on each side",
                ));
            }
            let crosses = if inner {
                rib.diameter >= self.outer_ring.raceway_diameter
            } else {
                rib.diameter <= self.inner_ring.raceway_diameter
            };
            let height = 0.5 * (rib.diameter - ring.raceway_diameter).abs();
            at_most(
                &format!("{rib_key}.edge_break"),
                rib.edge_break,
                height,
                "the rib's height above the raceway",
            )?;
            if crosses {
                return Err(GeometryError::new(
                    format!("{rib_key}.diameter"),
                    format!(
                        "rib rim Ø{:.3} mm reaches the opposite raceway",
                        rib.diameter * 1e3
                    ),
                ));
            }
        }
        Ok(())
    }
}
