//! Built-in oils of commercial classes: the ISO 3448 viscosity grades as mineral and PAO oils,
//! two aero-engine turbine oils and an industrial gear oil. Each is two kinematic viscosities
//! (40 and 100 °C) joined by ASTM D341 (Walther), and class values for everything a data sheet
//! does not give, each entry of [`Lubricant::provenance`] saying which is which.
//!
//! | property | how |
//! |---|---|
//! | ν40 | ISO 3448:1992 Table 1 midpoint (VG oils); data sheet or specification (others) |
//! | ν100 | from the class viscosity index by ASTM D2270 ([`nu100_from_viscosity_index`]) or data sheet |
//! | ρ(θ) | 15 °C value (class or data sheet) and [`density_from_15c`] |
//! | ᾱ(θ) | Wooster correlation at 40 and 100 °C, linear in θ between ([`wooster_pressure_viscosity`]) |
//! | K_f(θ) | Cragoe correlation from the 15 °C density ([`cragoe_thermal_conductivity`]) |
//! | β0 | −d ln η0/dT of the viscosity law (`beta0_per_k = None`) |
//! | Γ, τ0 | transferred from the seed oil of the same class (ESTIMATED) |
//! | κ | −dᾱ/dθ of the ᾱ law: in seed 000 eq. (1.9), ln η carries ᾱp − (β0 + κp)ΔT, so ∂²ln η/∂p∂T = −κ |

use crate::correlations::{
    cragoe_thermal_conductivity, density_from_15c, wooster_pressure_viscosity,
};
use crate::error::LubError;
use crate::lubricant::{CELSIUS_ZERO, Lubricant, TempLaw, ViscosityLaw};
use crate::provenance::{OilProperty, PropertySource};
use crate::seed_rheology::{
    NVI65_SHEAR_MODULUS_PA, VNII_EYRING_STRESS_PA, VNII_SHEAR_MODULUS_PA, pao1_eyring_stress,
    pao1_shear_modulus,
};
use crate::viscosity::walther_from_two_points;
use crate::viscosity_index::nu100_from_viscosity_index;

/// ISO 3448:1992 Table 1 viscosity grades built into the library: the midpoint kinematic
/// viscosity at 40 °C in mm²/s (the grade's limits are ±10 %).
pub const ISO_VG_GRADES: [u32; 12] = [10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680];

/// Temperature range of the mineral oils, °C: the two viscosity points at 40 and 100 °C with a
/// 20 K margin on each side.
const RANGE_C: [f64; 2] = [20.0, 120.0];

/// Temperature range of the PAO oils, °C: 20 K below the 40 °C point, but not above 100 °C,
/// where the transferred PAO1 fit of Γ(θ) ends (its cubic has a spurious minimum at 111 °C).
const PAO_RANGE_C: [f64; 2] = [20.0, 100.0];

/// Temperature range of the aero-engine oils, °C (bearing chambers run hotter; same margin
/// below, 50 K above the 100 °C viscosity point).
const AERO_RANGE_C: [f64; 2] = [20.0, 150.0];

/// Base-oil class: fixes the class values used where no data sheet gives a property.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BaseOil {
    /// Paraffinic mineral oil.
    Mineral,
    /// Polyalphaolefin.
    Pao,
    /// Polyol or diester (aero-engine turbine oils).
    Ester,
}

impl BaseOil {
    /// Name used in oil names (`mineral`, `pao`, `ester`).
    pub fn name(self) -> &'static str {
        match self {
            BaseOil::Mineral => "mineral",
            BaseOil::Pao => "pao",
            BaseOil::Ester => "ester",
        }
    }

    /// Class viscosity index of the VG oils (ESTIMATED) and its source.
    fn typical_viscosity_index(self) -> Option<(f64, &'static str)> {
        match self {
            BaseOil::Mineral => Some((
                95.0,
                "VI 95, the value of SKF's viscosity-temperature diagram of ISO VG mineral \
                 oils (SKF Rolling bearings catalogue, 2018, 'Lubrication'); industrial mineral \
                 oils have VI 95-105",
            )),
            BaseOil::Pao => Some((
                140.0,
                "VI 140, middle of the VI 135-150 of PAO oils of 6-40 mm2/s at 100 C (Rudnick \
                 & Shubkin, 'Poly(alpha-olefins)', ch. 1 of Synthetic Lubricants and \
                 High-Performance Functional Fluids, 2nd ed., 1999)",
            )),
            BaseOil::Ester => None,
        }
    }

    /// Class density at 15 °C, kg/m³ (ESTIMATED), and its source.
    fn typical_density_15c(self) -> (f64, &'static str) {
        match self {
            BaseOil::Mineral => (
                880.0,
                "880 kg/m3 at 15 C, class value of paraffinic mineral oils ISO VG 32-220 \
                 (0.86-0.90 g/ml)",
            ),
            BaseOil::Pao => (
                850.0,
                "850 kg/m3 at 15 C, class value of PAO oils (0.82-0.86 g/ml)",
            ),
            BaseOil::Ester => (
                1000.0,
                "1000 kg/m3 at 15 C, class value of polyol-ester turbine oils (about 1.00 g/ml)",
            ),
        }
    }

    /// Γ, τ0 of the class: the seed oil of the same class, transferred (ESTIMATED).
    fn traction(self) -> ClassTraction {
        match self {
            BaseOil::Mineral => ClassTraction {
                shear_modulus: TempLaw::Constant {
                    value: NVI65_SHEAR_MODULUS_PA,
                },
                eyring_stress: TempLaw::Constant { value: 5.0e6 },
                shear_modulus_source: "Gamma = 3 GPa of the mineral oil NVI 65 (seed 000 §2.3), \
                                       transferred to the class",
                eyring_stress_source: "tau0 = 5 MPa, middle of the 2-10 MPa of mineral oils at \
                                       40-80 C (Evans & Johnson, Proc. IMechE C 200 (1986) 313)",
            },
            BaseOil::Pao => ClassTraction {
                shear_modulus: pao1_shear_modulus(),
                eyring_stress: pao1_eyring_stress(),
                shear_modulus_source: "Gamma(theta) of PAO1 VG 320 (seed 000 §2.2), transferred \
                                       to the class",
                eyring_stress_source: "tau0(theta) of PAO1 VG 320 (seed 000 §2.2), transferred \
                                       to the class",
            },
            BaseOil::Ester => ClassTraction {
                shear_modulus: TempLaw::Constant {
                    value: VNII_SHEAR_MODULUS_PA,
                },
                eyring_stress: TempLaw::Constant {
                    value: VNII_EYRING_STRESS_PA,
                },
                shear_modulus_source: "Gamma of the synthetic aviation turbine oil VNII NP \
                                       50-1-4u (seed 000 §3.1.2), transferred to the class",
                eyring_stress_source: "tau0 of the synthetic aviation turbine oil VNII NP \
                                       50-1-4u (seed 000 §3.1.2), transferred to the class",
            },
        }
    }
}

/// The traction parameters of a class and where they come from.
struct ClassTraction {
    shear_modulus: TempLaw,
    eyring_stress: TempLaw,
    shear_modulus_source: &'static str,
    eyring_stress_source: &'static str,
}

/// What distinguishes one class oil: its name, two viscosity points and density.
struct Recipe {
    name: String,
    class: String,
    base: BaseOil,
    range_c: [f64; 2],
    nu40_m2_s: f64,
    nu100_m2_s: f64,
    viscosity: PropertySource,
    density_15c_kg_m3: f64,
    density: PropertySource,
}

/// ISO VG `grade` (one of [`ISO_VG_GRADES`]) of a mineral or PAO base oil: ν40 the grade
/// midpoint, ν100 from the class viscosity index by ASTM D2270.
pub fn iso_vg(grade: u32, base: BaseOil) -> Result<Lubricant, LubError> {
    let class_vi = base.typical_viscosity_index();
    let Some((vi, vi_source)) = class_vi.filter(|_| ISO_VG_GRADES.contains(&grade)) else {
        return Err(LubError::InvalidInput(format!(
            "no built-in ISO VG {grade} {} oil (grades {ISO_VG_GRADES:?}, mineral or pao)",
            base.name()
        )));
    };
    let nu40 = f64::from(grade) * 1e-6;
    let nu100 = nu100_from_viscosity_index(nu40, vi)?;
    let (rho15, rho_source) = base.typical_density_15c();
    Ok(build(Recipe {
        name: format!("iso-vg-{grade}-{}", base.name()),
        class: format!("ISO VG {grade} {} (VI {vi:.0})", base.name()),
        base,
        range_c: match base {
            BaseOil::Pao => PAO_RANGE_C,
            _ => RANGE_C,
        },
        nu40_m2_s: nu40,
        nu100_m2_s: nu100,
        viscosity: PropertySource::estimated(
            OilProperty::Viscosity,
            format!(
                "nu40 = {grade} mm2/s (ISO 3448:1992 Table 1 midpoint); nu100 = {:.2} mm2/s \
                 from {vi_source} by ASTM D2270; ASTM D341 through both",
                nu100 * 1e6
            ),
        ),
        density_15c_kg_m3: rho15,
        density: class_density(rho_source),
    }))
}

/// MIL-PRF-23699 standard class, 5 mm²/s polyol-ester aero-engine oil: the typical values of
/// Mobil Jet Oil II, a qualified product (ν40 = 27.6, ν100 = 5.1 mm²/s; the specification asks
/// ν100 4.90–5.40 and ν40 ≥ 23 mm²/s).
pub fn mil_prf_23699() -> Lubricant {
    build(Recipe {
        name: "mil-prf-23699".into(),
        class: "MIL-PRF-23699 STD, polyol ester, 5 mm2/s".into(),
        base: BaseOil::Ester,
        range_c: AERO_RANGE_C,
        nu40_m2_s: 27.6e-6,
        nu100_m2_s: 5.1e-6,
        viscosity: PropertySource::measured(
            OilProperty::Viscosity,
            "Mobil Jet Oil II (qualified to MIL-PRF-23699 STD) product data sheet: 27.6 / 5.1 \
             mm2/s at 40 / 100 C; ASTM D341 through both",
        ),
        density_15c_kg_m3: BaseOil::Ester.typical_density_15c().0,
        density: class_density(BaseOil::Ester.typical_density_15c().1),
    })
}

/// MIL-PRF-7808 grade 3, 3 mm²/s diester aero-engine oil: an oil at the specification's grade 3
/// minima ν100 = 3.0 mm²/s and ν40 = 11.5 mm²/s (ESTIMATED as representative: no product data
/// sheet at hand; products lie at or slightly above these limits).
pub fn mil_prf_7808() -> Lubricant {
    build(Recipe {
        name: "mil-prf-7808".into(),
        class: "MIL-PRF-7808 grade 3, diester, 3 mm2/s".into(),
        base: BaseOil::Ester,
        range_c: AERO_RANGE_C,
        nu40_m2_s: 11.5e-6,
        nu100_m2_s: 3.0e-6,
        viscosity: PropertySource::estimated(
            OilProperty::Viscosity,
            "MIL-PRF-7808 grade 3 minima nu100 = 3.0, nu40 = 11.5 mm2/s (Table I), taken as \
             representative; ASTM D341 through both",
        ),
        density_15c_kg_m3: 950.0,
        density: class_density(
            "950 kg/m3 at 15 C, class value of diester turbine oils (about 0.95 g/ml)",
        ),
    })
}

/// ISO VG 220 mineral EP industrial gear oil: the typical values of Mobilgear 600 XP 220
/// (ν40 = 220, ν100 = 19.0 mm²/s, density 0.89 g/ml at 15 °C).
pub fn vg220_gear() -> Lubricant {
    build(Recipe {
        name: "vg220-gear".into(),
        class: "ISO VG 220 mineral EP gear oil".into(),
        base: BaseOil::Mineral,
        range_c: RANGE_C,
        nu40_m2_s: 220e-6,
        nu100_m2_s: 19.0e-6,
        viscosity: PropertySource::measured(
            OilProperty::Viscosity,
            "Mobilgear 600 XP 220 product data sheet: 220 / 19.0 mm2/s at 40 / 100 C; ASTM \
             D341 through both",
        ),
        density_15c_kg_m3: 890.0,
        density: PropertySource::measured(
            OilProperty::Density,
            "Mobilgear 600 XP 220 product data sheet: 0.89 g/ml at 15 C; thermal expansion \
             6.5e-4 1/K (ESTIMATED class value)",
        ),
    })
}

fn class_density(rho15_source: &str) -> PropertySource {
    PropertySource::estimated(
        OilProperty::Density,
        format!("{rho15_source}; thermal expansion 6.5e-4 1/K (class value)"),
    )
}

/// The oil of `recipe`: Walther law through its two points, class correlations and traction.
fn build(recipe: Recipe) -> Lubricant {
    let c = |t_c: f64| t_c + CELSIUS_ZERO;
    let density = density_from_15c(recipe.density_15c_kg_m3);
    let viscosity = walther_from_two_points(c(40.0), recipe.nu40_m2_s, c(100.0), recipe.nu100_m2_s);
    let alpha_at =
        |t_c: f64| wooster_pressure_viscosity(viscosity.eval(c(t_c)) * density.eval(c(t_c)));
    let (alpha40, alpha100) = (alpha_at(40.0), alpha_at(100.0));
    let alpha_slope = (alpha100 - alpha40) / 60.0;
    let traction = recipe.base.traction();
    let transferred = match recipe.base {
        BaseOil::Mineral => "",
        BaseOil::Pao | BaseOil::Ester => ", a mineral-oil correlation applied to this class",
    };
    let mut provenance = vec![
        recipe.viscosity,
        recipe.density,
        PropertySource::estimated(
            OilProperty::PressureViscosity,
            format!(
                "Wooster correlation (Stachowiak & Batchelor, Engineering Tribology §2.6) at \
                 40 and 100 C ({:.1} / {:.1} 1/GPa), linear in theta between{transferred}",
                alpha40 * 1e9,
                alpha100 * 1e9
            ),
        ),
        PropertySource::estimated(OilProperty::Beta0, "-d ln eta0/dT of the viscosity law"),
        PropertySource::estimated(
            OilProperty::ThermalConductivity,
            format!(
                "Cragoe (1929) petroleum-oil correlation from the 15 C density{}",
                if transferred.is_empty() {
                    ""
                } else {
                    ", applied to this class"
                }
            ),
        ),
        PropertySource::estimated(OilProperty::ShearModulus, traction.shear_modulus_source),
        PropertySource::estimated(OilProperty::EyringStress, traction.eyring_stress_source),
    ];
    provenance.push(PropertySource::estimated(
        OilProperty::Kappa,
        "-d alpha/d theta of the alpha law (seed 000 eq. 1.9: d2 ln eta/dp dT = -kappa)",
    ));
    Lubricant {
        source: format!(
            "{}; class values where no data is given (see measured / estimated)",
            recipe.class
        ),
        name: recipe.name,
        class: recipe.class,
        temperature_range_k: recipe.range_c.map(c),
        density: Some(density),
        viscosity: Some(ViscosityLaw::Kinematic { law: viscosity }),
        pressure_viscosity: Some(TempLaw::PolynomialCelsius {
            coeffs: vec![alpha40 - 40.0 * alpha_slope, alpha_slope],
        }),
        roelands_z: None,
        shear_modulus: Some(traction.shear_modulus),
        eyring_stress: Some(traction.eyring_stress),
        beta0_per_k: None,
        kappa_per_k_pa: Some(-alpha_slope),
        thermal_conductivity: Some(cragoe_thermal_conductivity(recipe.density_15c_kg_m3)),
        mixed_friction: None,
        missing: vec!["Lambda_bd / Lambda_hd".to_string()],
        provenance,
    }
}
