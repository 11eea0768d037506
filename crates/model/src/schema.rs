//! The model-file schema (TOML), in engineering units. Documented in `docs/model-format.md`;
//! every struct rejects unknown keys. Converted once into `rolldyn_geometry` types (SI).

use rolldyn_units::{
    Angle, AngularSpeed, Damping, Density, Dimensionless, Force, Inertia, KinematicViscosity,
    Length, Mass, PerArea, PerPressure, Pressure, Quantity, RotationalDamping, Speed, Temperature,
    ThermalConductivity, Time, Unbalance,
};
use serde::Deserialize;
use std::collections::BTreeMap;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelFile {
    pub bearing: BearingSection,
    #[serde(default)]
    pub materials: BTreeMap<String, MaterialSection>,
    pub inner_ring: Option<RingSection>,
    pub outer_ring: Option<RingSection>,
    pub roller: RollerSection,
    pub cage: Option<CageSection>,
    pub clearance: Option<ClearanceSection>,
    pub misalignment: Option<MisalignmentSection>,
    pub lubricant: Option<LubricantSection>,
    pub operating: Option<OperatingSection>,
    pub startup: Option<StartupSection>,
    pub dynamics: Option<DynamicsSection>,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum ModelKind {
    /// A complete single-row cylindrical roller bearing.
    Cylindrical,
    /// One roller on one raceway (contact studies).
    RollerRaceway,
    /// A double-row tapered roller bearing: the tables of [`crate::tapered::TaperedModelFile`].
    DoubleRowTapered,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BearingSection {
    pub name: String,
    pub kind: ModelKind,
    pub description: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSection {
    pub youngs_modulus: Quantity<Pressure>,
    pub poisson_ratio: Quantity<Dimensionless>,
    pub density: Quantity<Density>,
    pub meyer_hardness: Option<Quantity<Pressure>>,
    /// σ_u, given together with `sn_curve`
    pub ultimate_strength: Option<Quantity<Pressure>>,
    /// the fully reversed S–N curve of the material (cage fatigue)
    pub sn_curve: Option<SnCurveSection>,
    /// the name of a built-in material whose S–N curve and σ_u this material takes
    pub fatigue_like: Option<String>,
}

/// `sn_curve = { cycles = [...], amplitude = ["480 MPa", ...], source = "..." }`: the points
/// (N, σ_a) of a fully reversed S–N curve, N increasing, the last point the knee.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SnCurveSection {
    pub cycles: Vec<f64>,
    pub amplitude: Vec<Quantity<Pressure>>,
    /// where the points come from
    pub source: String,
}

/// Mass properties given instead of computed from geometry.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MassOverride {
    pub mass: Option<Quantity<Mass>>,
    pub axial_inertia: Option<Quantity<Inertia>>,
    pub transverse_inertia: Option<Quantity<Inertia>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RingSection {
    pub raceway_diameter: Quantity<Length>,
    /// Inner ring only.
    pub bore_diameter: Option<Quantity<Length>>,
    /// Outer ring only.
    pub outside_diameter: Option<Quantity<Length>>,
    pub width: Quantity<Length>,
    pub material: Option<String>,
    pub roughness_ra: Option<Quantity<Length>>,
    pub rib_spacing: Option<Quantity<Length>>,
    #[serde(default)]
    pub ribs: Vec<RibSection>,
    pub guiding_land: Option<GuidingLandSection>,
    pub raceway_profile: Option<ProfileSection>,
    /// Raceway wear map (`file = "wear.csv"`, relative to the model file).
    pub raceway_wear: Option<RacewayWearSection>,
    #[serde(default)]
    pub mass_properties: MassOverride,
}

/// `[inner_ring.raceway_wear]` / `[outer_ring.raceway_wear]`: the CSV file of a raceway wear
/// map (axial position × ring angle, docs/model-format.md).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RacewayWearSection {
    pub file: String,
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum RibSideName {
    Left,
    Right,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RibSection {
    pub side: RibSideName,
    pub diameter: Quantity<Length>,
    #[serde(default)]
    pub face: RibFaceSection,
    pub edge_break: Option<Quantity<Length>>,
}

#[derive(Debug, Deserialize, Default)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum RibFaceSection {
    #[default]
    Flat,
    Cone {
        angle: Quantity<Angle>,
    },
    ConvexTorus {
        radius: Quantity<Length>,
        crest_offset: Option<Quantity<Length>>,
    },
    ConcaveTorus {
        radius: Quantity<Length>,
    },
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GuidingLandSection {
    pub width: Quantity<Length>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChamferSection {
    pub axial: Quantity<Length>,
    pub radial: Quantity<Length>,
    pub radius: Quantity<Length>,
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum ProfileSection {
    Straight {
        chamfer: Option<ChamferSection>,
    },
    Crowned {
        straight_length: Quantity<Length>,
        drop: Quantity<Length>,
        crown_radius: Option<Quantity<Length>>,
        chamfer: Option<ChamferSection>,
    },
    Logarithmic {
        k: Quantity<Length>,
        c: Quantity<PerArea>,
        chamfer: Option<ChamferSection>,
    },
    JohnsGohar {
        design_load: Quantity<Force>,
        chamfer: Option<ChamferSection>,
    },
    Polyline {
        x: Vec<Quantity<Length>>,
        drop: Vec<Quantity<Length>>,
        chamfer: Option<ChamferSection>,
    },
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum EndFaceSection {
    Flat,
    Sphere { radius: Quantity<Length> },
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RollerSection {
    pub count: Option<usize>,
    pub diameter: Quantity<Length>,
    pub length: Quantity<Length>,
    pub slices: Option<usize>,
    pub material: Option<String>,
    pub roughness_ra: Option<Quantity<Length>>,
    pub edge_break: Option<Quantity<Length>>,
    pub end_face: Option<EndFaceSection>,
    pub profile: Option<ProfileSection>,
    #[serde(default)]
    pub mass_properties: MassOverride,
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum GuidanceName {
    InnerLand,
    OuterLand,
    Rollers,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CageSection {
    pub guidance: GuidanceName,
    pub floating_clearance: Option<Quantity<Length>>,
    pub pocket_axial: Quantity<Length>,
    /// the pocket's profile in the cage's transverse plane (docs/model-format.md, `[cage.pocket]`)
    pub pocket: PocketSection,
    pub inner_diameter: Quantity<Length>,
    pub outer_diameter: Quantity<Length>,
    pub width: Quantity<Length>,
    pub material: Option<String>,
    /// "silver"; none: unplated
    pub plating: Option<rolldyn_geometry::Plating>,
    pub roughness_ra: Option<Quantity<Length>>,
    #[serde(default)]
    pub mass_properties: MassOverride,
}

/// `[cage.pocket]`: faces, retaining lips and window-corner fillet of a window cage.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PocketSection {
    /// "flat" (default) or "concave"
    pub faces: Option<PocketFacesName>,
    /// pocket width at the pitch circle − roller diameter
    pub face_clearance: Quantity<Length>,
    pub outer_lip: Option<LipSection>,
    pub inner_lip: Option<LipSection>,
    /// window-corner fillet between bar and rim (stress models)
    pub fillet_radius: Option<Quantity<Length>>,
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum PocketFacesName {
    Flat,
    Concave,
}

/// A retaining lip: its edge circle, the window between the two edges, the edge radius.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LipSection {
    pub diameter: Quantity<Length>,
    pub window: Quantity<Length>,
    /// default 0 (a sharp edge)
    pub tip_radius: Option<Quantity<Length>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClearanceSection {
    pub radial: Option<Quantity<Length>>,
    pub roller_rib_axial: Option<Quantity<Length>>,
    #[serde(default)]
    pub preload: bool,
    #[serde(default)]
    pub operating: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MisalignmentSection {
    pub inner_ring: Quantity<Angle>,
}

/// `[lubricant]`: the oil, and values the seeds do not give (SPEC F-27) as overrides.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LubricantSection {
    /// Built-in oil name (see `rolldyn oils`).
    pub oil: Option<String>,
    /// User oil file (TOML, docs/lubricants.md), relative to the model file.
    pub file: Option<String>,
    /// Kinematic viscosity at two temperatures → Walther/ASTM D341 law.
    pub kinematic_viscosity: Option<ViscosityPoints>,
    pub density: Option<Quantity<Density>>,
    pub pressure_viscosity: Option<Quantity<PerPressure>>,
    pub shear_modulus: Option<Quantity<Pressure>>,
    pub eyring_stress: Option<Quantity<Pressure>>,
    pub thermal_conductivity: Option<Quantity<ThermalConductivity>>,
    pub lambda_boundary: Option<f64>,
    pub lambda_hydrodynamic: Option<f64>,
    pub rheology: Option<RheologyName>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViscosityPoints {
    pub temperatures: [Quantity<Temperature>; 2],
    pub values: [Quantity<KinematicViscosity>; 2],
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum RheologyName {
    ViscoElastic,
    Isothermal,
    LinearElastic,
}

/// `[operating]`: speeds, loads and temperatures of one operating point.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OperatingSection {
    pub inner_speed: Option<Quantity<AngularSpeed>>,
    pub outer_speed: Option<Quantity<AngularSpeed>>,
    pub radial_load: Option<Quantity<Force>>,
    pub axial_load: Option<Quantity<Force>>,
    /// `fixed` (in space) or `rotating` (with the inner ring, e.g. unbalance; 2002834).
    pub load_direction: Option<LoadDirection>,
    #[serde(default)]
    pub temperatures: TemperatureSection,
    /// Rotating unbalance U of the shaft, F = U ω² (SPEC §3.7).
    pub unbalance: Option<Quantity<Unbalance>>,
    /// Direction of the unbalance force at t = 0, from +x (default 0).
    pub unbalance_phase: Option<Quantity<Angle>>,
    /// `[[operating.loads]]`: further radial forces fixed in space, optionally with one step.
    #[serde(default)]
    pub loads: Vec<LoadEntry>,
    /// Inner-ring speed over time (piecewise linear), instead of `inner_speed`.
    pub speed_schedule: Option<SpeedSchedule>,
    /// Operating radial clearance over time (piecewise linear), SPEC §3.7.
    pub clearance_schedule: Option<ClearanceSchedule>,
    /// Oil temperature over time (piecewise linear), instead of `temperatures.oil`.
    pub oil_temperature_schedule: Option<TemperatureSchedule>,
}

/// `[[operating.loads]]`: a radial force on the inner ring fixed in space (gravity share,
/// gearbox load; SPEC §3.7), optionally stepping to `after` once `at` has passed.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadEntry {
    /// Label for outputs.
    pub name: Option<String>,
    pub magnitude: Quantity<Force>,
    /// Direction of the force in the x–y plane from +x (default 270° = −y, downwards).
    pub direction: Option<Quantity<Angle>>,
    /// Magnitude after the step at `at`.
    pub after: Option<Quantity<Force>>,
    /// Time of the step; `magnitude` holds up to and including it.
    pub at: Option<Quantity<Time>>,
}

/// `[operating.speed_schedule]`: `time = [...]`, `speed = [...]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpeedSchedule {
    pub time: Vec<Quantity<Time>>,
    pub speed: Vec<Quantity<AngularSpeed>>,
}

/// `[operating.clearance_schedule]`: `time = [...]`, `radial = [...]` (diametral, negative =
/// preload).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClearanceSchedule {
    pub time: Vec<Quantity<Time>>,
    pub radial: Vec<Quantity<Length>>,
}

/// `[operating.oil_temperature_schedule]`: `time = [...]`, `oil = [...]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TemperatureSchedule {
    pub time: Vec<Quantity<Time>>,
    pub oil: Vec<Quantity<Temperature>>,
}

/// `[startup]`: frozen time points of a start-up (seed 000 §3.1.2, Table 3.4), each run as a
/// constant-condition simulation to steady state.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StartupSection {
    pub frozen_points: Vec<Quantity<Time>>,
    /// One label per frozen point (default "1", "2", …).
    pub labels: Option<Vec<String>>,
    /// Cage revolutions simulated per point (default 10).
    pub revolutions: Option<f64>,
    /// Last revolutions averaged for the reported slip (default: the last half).
    pub average_revolutions: Option<f64>,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum LoadDirection {
    Fixed,
    Rotating,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct TemperatureSection {
    pub oil: Option<Quantity<Temperature>>,
    pub inner_ring: Option<Quantity<Temperature>>,
    pub outer_ring: Option<Quantity<Temperature>>,
    pub rollers: Option<Quantity<Temperature>>,
    pub cage: Option<Quantity<Temperature>>,
    pub shaft: Option<Quantity<Temperature>>,
    pub housing: Option<Quantity<Temperature>>,
}

/// `[dynamics]`: contact parameters of SPEC Table 2.1 and the cage drag (SPEC §3.3–3.6).
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct DynamicsSection {
    /// c of `M = −c ω_cage`, e.g. "662 Nmm/(rad/ms)" or "6.62e-4 Nms"
    pub cage_drag: Option<Quantity<RotationalDamping>>,
    /// force law of the cage on its guiding land: "hydrodynamic" or "contact"
    pub cage_land_law: Option<CageLandLawName>,
    /// fill fraction of the land clearance (oil volume / clearance volume) of the hydrodynamic
    /// land, 0 < f ≤ 1
    pub cage_land_fill: Option<Quantity<Dimensionless>>,
    /// drag coefficient C_D of a roller in cross flow (roller drag in the air–oil mixture)
    pub roller_drag_coefficient: Option<Quantity<Dimensionless>>,
    /// volume fraction of oil in the bearing cavity (air–oil mixture density)
    pub oil_volume_fraction: Option<Quantity<Dimensionless>>,
    /// pairs 13, 23
    pub raceways: Option<RacewayPairSection>,
    /// pair 34
    pub roller_cage: Option<RollerCageSection>,
    /// pair 14
    pub cage_land: Option<PairSection>,
    /// pair 56
    pub roller_end_rib: Option<EndPairSection>,
    /// pair 54
    pub roller_end_cage: Option<EndPairSection>,
}

/// Force law names of the cage ↔ guiding land.
#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum CageLandLawName {
    Hydrodynamic,
    Contact,
}

/// Roller slices ↔ raceways (the slice law is built from the geometry).
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RacewayPairSection {
    pub damping: Option<Quantity<Damping>>,
    pub damping_ramp: Option<Quantity<Length>>,
}

/// Two-level friction law (SPEC §3.4).
#[derive(Debug, Deserialize, Default, Clone, Copy)]
#[serde(deny_unknown_fields)]
pub struct FrictionSection {
    pub r#static: Option<Quantity<Dimensionless>>,
    pub dynamic: Option<Quantity<Dimensionless>>,
    pub static_speed: Option<Quantity<Speed>>,
    pub dynamic_speed: Option<Quantity<Speed>>,
}

/// A power-law contact pair.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct PairSection {
    /// K_p in SI, N/mⁿ (a plain number: its unit depends on n)
    pub stiffness: Option<f64>,
    pub exponent: Option<f64>,
    pub damping: Option<Quantity<Damping>>,
    pub damping_ramp: Option<Quantity<Length>>,
    pub friction: Option<FrictionSection>,
}

/// Force law names of the roller ↔ cage bar contact (pair 34).
#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum BarLawName {
    Elastic,
    Lubricated,
}

/// The roller ↔ cage bar pair: a power-law pair with its force law.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RollerCageSection {
    /// "elastic" (default) or "lubricated" (the oil film between roller and bar, then the
    /// elastic law)
    pub law: Option<BarLawName>,
    pub stiffness: Option<f64>,
    pub exponent: Option<f64>,
    pub damping: Option<Quantity<Damping>>,
    pub damping_ramp: Option<Quantity<Length>>,
    pub friction: Option<FrictionSection>,
}

/// Friction law names of the roller-end contacts.
#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum EndFrictionName {
    Boundary,
    Kragelsky,
    Ehl,
}

/// A roller-end contact pair.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct EndPairSection {
    pub enabled: Option<bool>,
    pub friction_law: Option<EndFrictionName>,
    pub stiffness: Option<f64>,
    pub exponent: Option<f64>,
    pub damping: Option<Quantity<Damping>>,
    pub damping_ramp: Option<Quantity<Length>>,
    pub friction: Option<FrictionSection>,
}
