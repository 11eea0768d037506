//! Operating conditions of one quasi-static point ([`QuasiStaticConditions`], SPEC §5.6 "input").
//!
//! All SI: speeds in rad/s, forces in N, lengths in m, temperatures in **kelvin**. Values the
//! seeds do not give have documented defaults (marked "standard form" or "assumed").

use rolldyn_lubrication::{
    FilmFormula, Lubricant, MixedLimits, MurakiSettings, Rheology, Seed001Settings,
    traction::TractionConfig,
};

/// 20 °C in kelvin: default assembly (reference) temperature of the fits and clearances.
pub const ASSEMBLY_TEMPERATURE_K: f64 = 293.15;

/// Linear thermal expansion coefficient of through-hardened bearing steel, 1/K (AISI 52100:
/// 11.9e-6 between 20 and 100 °C; standard value, not in the seeds).
pub const STEEL_EXPANSION_PER_K: f64 = 11.9e-6;

/// Temperatures of the bearing parts, K (SPEC §5.2: "temperature per part").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartTemperatures {
    /// Inner ring t_в.
    pub inner_ring: f64,
    /// Outer ring t_н.
    pub outer_ring: f64,
    /// Rollers.
    pub rollers: f64,
    /// Cage.
    pub cage: f64,
    /// Shaft under the inner ring.
    pub shaft: f64,
    /// Housing (or outer shaft of an intershaft bearing) around the outer ring.
    pub housing: f64,
    /// Temperature at which the mounting clearance, fits and diameters are given (default 20 °C).
    pub assembly: f64,
}

impl PartTemperatures {
    /// Every part at `t_k`, assembled at 20 °C.
    pub fn uniform(t_k: f64) -> Self {
        Self {
            inner_ring: t_k,
            outer_ring: t_k,
            rollers: t_k,
            cage: t_k,
            shaft: t_k,
            housing: t_k,
            assembly: ASSEMBLY_TEMPERATURE_K,
        }
    }

    /// Inner ring (and shaft) at `inner_k`, outer ring (and housing) at `outer_k`, rollers and
    /// cage at the mean (seed 001: "mean bearing temperature").
    pub fn rings(inner_k: f64, outer_k: f64) -> Self {
        let mean = 0.5 * (inner_k + outer_k);
        Self {
            inner_ring: inner_k,
            outer_ring: outer_k,
            rollers: mean,
            cage: mean,
            shaft: inner_k,
            housing: outer_k,
            assembly: ASSEMBLY_TEMPERATURE_K,
        }
    }

    /// Mean of the ring temperatures, seed 001 t_вм = (t_в + t_н)/2 (SPEC §4.10).
    pub fn mean_rings(&self) -> f64 {
        0.5 * (self.inner_ring + self.outer_ring)
    }
}

/// Oil (inlet) temperatures of the contacts, K. Seed 001 starts the flash-temperature iteration
/// of a raceway contact from the temperature of its ring; seed 000 uses one oil temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuasiStaticContactTemperatures {
    /// Roller ↔ inner raceway.
    pub inner: f64,
    /// Roller ↔ outer raceway.
    pub outer: f64,
    /// Roller ↔ cage bar (seed 001: at the outer-ring temperature).
    pub cage_bar: f64,
}

/// Elastic, mass and thermal data of a shaft or housing (not part of the bearing model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartMaterial {
    /// Young's modulus, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Density, kg/m³ (centrifugal growth).
    pub density: f64,
    /// Linear thermal expansion coefficient, 1/K.
    pub thermal_expansion: f64,
}

impl PartMaterial {
    /// Steel: E = 208 GPa, ν = 0.3, ρ = 7830 kg/m³, α = 11.9e-6 1/K.
    pub const STEEL: PartMaterial = PartMaterial {
        youngs_modulus: 208e9,
        poisson_ratio: 0.3,
        density: 7830.0,
        thermal_expansion: STEEL_EXPANSION_PER_K,
    };
}

impl Default for PartMaterial {
    fn default() -> Self {
        Self::STEEL
    }
}

/// Mounting of the rings (SPEC §5.2): interference fits on the shaft and in the housing.
/// Interference is diametral and given at the assembly temperature; negative = loose fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mounting {
    /// Diametral interference of the inner ring on the shaft, m. Default 0.
    pub shaft_interference_m: f64,
    /// Bore of a hollow shaft, m (0 = solid). Default 0.
    pub shaft_bore_diameter_m: f64,
    /// Diametral interference of the outer ring in the housing, m. Default 0.
    pub housing_interference_m: f64,
    /// Outside diameter of the housing (or of the outer shaft of an intershaft bearing), m;
    /// `None` = a housing much stiffer than the ring (Lamé limit D_h → ∞). Default `None`.
    pub housing_outside_diameter_m: Option<f64>,
    /// Shaft material. Default steel.
    pub shaft_material: PartMaterial,
    /// Housing material. Default steel.
    pub housing_material: PartMaterial,
}

impl Default for Mounting {
    fn default() -> Self {
        Self {
            shaft_interference_m: 0.0,
            shaft_bore_diameter_m: 0.0,
            housing_interference_m: 0.0,
            housing_outside_diameter_m: None,
            shaft_material: PartMaterial::STEEL,
            housing_material: PartMaterial::STEEL,
        }
    }
}

/// Thermal expansion coefficients of the bearing parts, 1/K (the geometry's materials carry no
/// expansion coefficient). Default steel 11.9e-6 for all.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalExpansion {
    /// Inner ring.
    pub inner_ring: f64,
    /// Outer ring.
    pub outer_ring: f64,
    /// Rollers.
    pub rollers: f64,
    /// Cage (brass ≈ 19e-6, polyamide ≈ 80e-6 if applicable).
    pub cage: f64,
}

impl Default for ThermalExpansion {
    fn default() -> Self {
        Self {
            inner_ring: STEEL_EXPANSION_PER_K,
            outer_ring: STEEL_EXPANSION_PER_K,
            rollers: STEEL_EXPANSION_PER_K,
            cage: STEEL_EXPANSION_PER_K,
        }
    }
}

/// Raceway friction model (SPEC §5.4 "friction from the lubrication crate — selectable").
#[derive(Debug, Clone, PartialEq)]
pub enum FrictionModel {
    /// Seed 001 (SPEC §4.9): asperity-contact fraction η = 0.25 − Φ(Λ)/2, Newtonian film shear
    /// with Barus viscosity, Blok flash-temperature iteration; film by the seed 001 formula,
    /// Λ after Tallian (F-44). Needs η0(T), ᾱ(T), β0 and K_f of the oil.
    Seed001(Seed001Settings),
    /// Seed 000 (SPEC §4.4–4.5): Muraki hydrodynamic traction, Kragelsky boundary friction
    /// (2.10), film-parameter blend (1.3) with `mixed` limits (`None` → the oil's Λ_bd/Λ_hd, or
    /// pure hydrodynamic friction if the oil has none), film formula `film` (Auto = (2.17)).
    Muraki {
        /// Muraki rheology switches.
        settings: MurakiSettings,
        /// Λ_bd, Λ_hd of (1.3).
        mixed: Option<MixedLimits>,
        /// Film formula.
        film: FilmFormula,
    },
    /// Any configuration of the lubrication crate; its `oil` is replaced by the conditions'
    /// lubricant.
    Custom(Box<TractionConfig>),
}

impl FrictionModel {
    /// Seed 000 settings for NVI 65 in the O'Brien–Taylor study (SPEC V-06, §4.2.2): elastic
    /// (first) term of (1.4) only with Γ = 3 GPa (from the oil), capped at 0.1; Λ_bd = 1.35,
    /// Λ_hd = 3.05; Kragelsky boundary friction; film (2.17).
    pub fn seed000_nvi65() -> Self {
        FrictionModel::Muraki {
            settings: MurakiSettings {
                rheology: Rheology::LinearElastic { cap: 0.1 },
                ..MurakiSettings::default()
            },
            mixed: Some(MixedLimits::NVI65),
            film: FilmFormula::Auto,
        }
    }

    /// Seed 001 model with its default settings (SPEC §4.9 proposals).
    pub fn seed001() -> Self {
        FrictionModel::Seed001(Seed001Settings::default())
    }
}

/// Friction of the roller ↔ cage-bar contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum BarFriction {
    /// `SameAsRaceways` with the seed 001 raceway model (seed 001: "the film and friction of the
    /// bar contact are computed as for a ring contact", flash temperature with the bar surface
    /// stationary), otherwise `Constant(0.01)` — the middle of the 0.00075…0.02 range SPEC §3.3
    /// quotes for the hydrodynamic cage contacts of seed 000 (the elastic-only NVI 65 law would
    /// saturate at its cap at the slide-to-roll ratio 2 of a bar contact). Default.
    #[default]
    Auto,
    /// The raceway friction model evaluated at the bar contact (line contact roller ↔ flat bar).
    SameAsRaceways,
    /// Constant coefficient, smoothed to zero over |v| < 1 mm/s (odd in the sliding speed).
    Constant(f64),
}

/// Resistance coefficient C_n(Re) of the cage in the air–oil medium (SPEC §5.5, ⚠ F-43: not
/// given by seed 001).
#[derive(Debug, Clone, PartialEq)]
pub enum DragCoefficient {
    /// Free rotating disc (standard form, not in the seeds): seed 001's moment
    /// T = C_n ρ ω² [R⁵ − r⁵ + 2.5 B (R⁴ + r⁴)] is the integral of a wall shear
    /// τ = ½ c_f ρ (ωr)² over both side faces and both cylinders with C_n = (2π/5) c_f; for a
    /// bare disc (r = B = 0) it equals the classical ½ C_M ρ ω² R⁵, hence C_n = C_M/2 with
    /// C_M = 3.87 Re^−½ (laminar, Cochran) and C_M = 0.146 Re^−⅕ (turbulent, von Kármán),
    /// blended smoothly (cubic STEP in ln Re over [Re_c/2, 2 Re_c]) around `critical_reynolds`
    /// (default 3×10⁵). Cross-check: with the seed 000 §3.6 mixture (linear density, χ = 0.05)
    /// it gives 0.221 N·m for the 2002834 cage at 391.8 rad/s against the seed's CFD 0.259 N·m
    /// (F-22). Default.
    Disc {
        /// Transition Reynolds number R²ω/ν.
        critical_reynolds: f64,
    },
    /// Constant C_n.
    Constant(f64),
    /// Table (Re, C_n), interpolated linearly in ln Re, end values held (the seed's "input
    /// table", F-43).
    Table(Vec<(f64, f64)>),
}

impl Default for DragCoefficient {
    fn default() -> Self {
        DragCoefficient::Disc {
            critical_reynolds: 3e5,
        }
    }
}

/// Density of the air–oil medium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MixtureDensity {
    /// Seed 001: γ_ср = γ_см O²/(0.4 + 0.6 O) (SPEC §4.10). Default.
    #[default]
    Seed001,
    /// Seed 000 §3.6: ρ = ρ_oil χ + ρ_air (1 − χ) (the rule of the seed 000 CFD).
    Linear,
}

/// Air–oil drag of the cage (SPEC §4.10, §5.5).
#[derive(Debug, Clone, PartialEq)]
pub struct DragInputs {
    /// Volume fraction of oil in the bearing cavity O_дсм (0…1). Default 0.05 (the oil volume
    /// concentration of the seed 000 CFD, SPEC §3.6).
    pub oil_volume_fraction: f64,
    /// Mixture density rule. Default seed 001.
    pub density_rule: MixtureDensity,
    /// Oil density, kg/m³, used when the lubricant has no density law. Default 870 kg/m³
    /// (assumed: mineral oil at 40…60 °C).
    pub oil_density_kg_m3: f64,
    /// Air density, kg/m³ (mixture viscosity rule of SPEC §3.6). Default 1.2.
    pub air_density_kg_m3: f64,
    /// Air dynamic viscosity, Pa·s. Default 1.85e-5.
    pub air_viscosity_pa_s: f64,
    /// C_n(Re).
    pub coefficient: DragCoefficient,
    /// Switch the drag off (pure-rolling checks). Default true (on).
    pub enabled: bool,
    /// A linear viscous drag `M = −c ω` given per model (SPEC §3.6, seed 000 §3.1.1's CFD value;
    /// the dynamics' `[dynamics] cage_drag`), N·m·s/rad, replacing the mixture formula. Default
    /// `None` (the formula). The dynamics' quasi-static start sets it so that both models see
    /// the same drag.
    pub viscous_coefficient_n_m_s: Option<f64>,
    /// Roller drag factor k = ½ ρ_eff C_D D l, kg/m: each roller feels F = k (ω₀ d_m/2)²
    /// against its orbital motion, the mixture at rest
    /// (`rolldyn_lubrication::mixture::roller_drag_factor`). Default 0 (seed 000 §3.6 neglects
    /// roller drag); `rolldyn skid` and the dynamics' start set it from `[dynamics]
    /// roller_drag_coefficient`.
    pub roller_drag_kg_m: f64,
}

impl Default for DragInputs {
    fn default() -> Self {
        Self {
            oil_volume_fraction: 0.05,
            density_rule: MixtureDensity::Seed001,
            oil_density_kg_m3: 870.0,
            air_density_kg_m3: 1.2,
            air_viscosity_pa_s: 1.85e-5,
            coefficient: DragCoefficient::default(),
            enabled: true,
            viscous_coefficient_n_m_s: None,
            roller_drag_kg_m: 0.0,
        }
    }
}

/// Roller-end friction (SPEC §4.9): Newtonian shear in the roller-end ↔ rib films and the
/// roller-end ↔ cage-pocket films.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndFriction {
    /// Roller end ↔ guiding ribs F_fб (seed 001). Default true.
    pub ribs: bool,
    /// Roller end ↔ cage pocket moment T_sc (seed 001; disc-shear form, F-43). Default true.
    pub pocket: bool,
}

impl Default for EndFriction {
    fn default() -> Self {
        Self {
            ribs: true,
            pocket: true,
        }
    }
}

/// Cage–land (narrow journal bearing) inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageLandInputs {
    /// Axial width of one guiding rail of the cage, m; `None` → the ring's guiding-land width if
    /// given, else half of (cage width − pocket axial length) (the two side rims of a window
    /// cage).
    pub rail_width_m: Option<f64>,
    /// Number of rails (separate short bearings). Default 2.
    pub rails: u32,
    /// Switch the land friction off. Default true (on).
    pub enabled: bool,
    /// Press the cage on its land with the centrifugal force of its own displacement,
    /// F_cs = m_c e ω₀² (SPEC §5.5 proposal: the displaced centre orbits with the cage, a
    /// synchronous whirl). Default true. Off: the centre stays where the roller forces put it
    /// (no whirl; issue 23 compares it with the dynamics).
    pub centrifugal_pressing: bool,
}

impl Default for CageLandInputs {
    fn default() -> Self {
        Self {
            rail_width_m: None,
            rails: 2,
            enabled: true,
            centrifugal_pressing: true,
        }
    }
}

/// Everything that defines one operating point (SPEC §5.6 "input").
#[derive(Debug, Clone, PartialEq)]
pub struct QuasiStaticConditions {
    /// Inner-ring angular speed ω_в, rad/s (positive = the bearing's positive sense).
    pub inner_speed_rad_s: f64,
    /// Outer-ring angular speed ω_н, rad/s (intershaft bearings: both non-zero).
    pub outer_speed_rad_s: f64,
    /// Radial load F_r on the inner ring, N (≥ 0); its direction is the reference of the roller
    /// angles.
    pub radial_load_n: f64,
    /// Angular speed of the radial-load direction, rad/s: 0 for a load fixed in space (default),
    /// the inner-ring speed for a load rotating with the inner ring (unbalance, seed 000
    /// §3.1.1.5). The roller pushes on the cage follow the load zone, so the cage–land film sees
    /// a load of this speed (theory §6.5).
    pub load_speed_rad_s: f64,
    /// Tilt of the inner ring relative to the outer ring, rad; `None` → the bearing model's.
    pub misalignment_rad: Option<f64>,
    /// Azimuth of the tilt plane measured from the load direction, rad. Default 0 (tilt in the
    /// plane containing the axis and the load).
    pub misalignment_azimuth_rad: f64,
    /// Part temperatures.
    pub temperatures: PartTemperatures,
    /// Contact oil temperatures; `None` → raceway contacts at their ring's temperature, the bar
    /// contact at the cage temperature.
    pub contact_temperatures: Option<QuasiStaticContactTemperatures>,
    /// Oil.
    pub lubricant: Lubricant,
    /// Raceway friction model.
    pub friction: FrictionModel,
    /// Roller ↔ cage-bar friction.
    pub bar_friction: BarFriction,
    /// Roller-end friction switches.
    pub end_friction: EndFriction,
    /// Rolling-friction coefficient f_к of T_к = f_к F (a length), m. Default 5e-6 m
    /// (hardened steel on hardened steel, 0.005…0.01 mm: standard reference value, not in the
    /// seeds).
    pub rolling_friction_m: f64,
    /// Air–oil drag of the cage.
    pub drag: DragInputs,
    /// Cage land.
    pub cage_land: CageLandInputs,
    /// Fits.
    pub mounting: Mounting,
    /// Thermal expansion coefficients of the bearing parts.
    pub thermal_expansion: ThermalExpansion,
}

impl QuasiStaticConditions {
    /// A point with every part at `temperature_k`, default friction (Muraki, oil's Λ limits)
    /// and all documented defaults.
    pub fn new(
        inner_speed_rad_s: f64,
        outer_speed_rad_s: f64,
        radial_load_n: f64,
        lubricant: Lubricant,
        temperature_k: f64,
    ) -> Self {
        Self {
            inner_speed_rad_s,
            outer_speed_rad_s,
            radial_load_n,
            load_speed_rad_s: 0.0,
            misalignment_rad: None,
            misalignment_azimuth_rad: 0.0,
            temperatures: PartTemperatures::uniform(temperature_k),
            contact_temperatures: None,
            lubricant,
            friction: FrictionModel::Muraki {
                settings: MurakiSettings::default(),
                mixed: None,
                film: FilmFormula::Auto,
            },
            bar_friction: BarFriction::Auto,
            end_friction: EndFriction::default(),
            rolling_friction_m: 5e-6,
            drag: DragInputs::default(),
            cage_land: CageLandInputs::default(),
            mounting: Mounting::default(),
            thermal_expansion: ThermalExpansion::default(),
        }
    }

    /// Contact temperatures in use (explicit or from the part temperatures).
    pub fn resolved_contact_temperatures(&self) -> QuasiStaticContactTemperatures {
        self.contact_temperatures
            .unwrap_or(QuasiStaticContactTemperatures {
                inner: self.temperatures.inner_ring,
                outer: self.temperatures.outer_ring,
                cage_bar: self.temperatures.cage,
            })
    }
}

/// Converts rpm to rad/s.
pub fn rpm(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

/// Converts °C to K.
pub fn celsius(t: f64) -> f64 {
    t + 273.15
}
