//! Built-in oil library: every oil the seeds define (SPEC §4.2), each with its source and the
//! list of what the seeds do not give.
//!
//! | name | source | complete for | missing (must be supplied by the user) |
//! |---|---|---|---|
//! | `pao1-vg320` | seed 000 §2.2 (ν, ᾱ, Γ, τ0 fits in °C; K_f, κ, β0) | Muraki traction, films | oil density (SPEC F-25 default 850 kg/m³ assumed), Λ_bd/Λ_hd (literature 0.01/1.5 used if asked) |
//! | `nvi65` | seed 000 Table 2.3 and its fits (η(θ), ᾱ(θ) with F-26 MPa⁻¹), Γ = 3 GPa, Λ 1.35/3.05 | elastic-only traction (the seed's use), films | τ0, κ, K_f, density |
//! | `vnii-np-50-1-4u` | seed 000 §3.1.2 (β0, γ≡κ, Γ, τ0, Λ 0.2/1.5) | nothing alone | viscosity law, ᾱ (printed law unusable, F-27), K_f, density |
//! | `vg220-mineral` | seed 000 §3.2.1 (ν 220 / 19 mm²/s at 40 / 100 °C → Walther) | viscosity only | density, ᾱ, Γ, τ0, κ, K_f |
//! | `mn-7.5u` | seed 000 Fig. 2.12 (name only; data in the cited Balyakin 2007) | nothing | everything |
//! | `ipm-10` | seed 001 (name only) | nothing | everything (μ0(t), α(t), λ(t), β) |
//! | `seed002-test-oil` | seed 002 roller–plate oil μ = 0.024 Pa·s, α = 0.75e-8 1/Pa | isothermal films | temperature dependence, density, rheology |
//! | `irp-150` | seed 002 gearbox oil IRP-150 μ = 0.14 Pa·s, α = 1.4e-8 1/Pa | isothermal films | temperature dependence, density, rheology |
//!
//! | `iso-vg-<N>-mineral`, `iso-vg-<N>-pao` | ISO 3448 grades N = 10 … 680 ([`crate::grades`]) | everything | Λ_bd/Λ_hd |
//! | `mil-prf-23699`, `mil-prf-7808`, `vg220-gear` | aero-engine and gear oils ([`crate::grades`]) | everything | Λ_bd/Λ_hd |
//!
//! Each oil lists in [`Lubricant::provenance`] which property is measured and which estimated.
//!
//! Temperature laws that the seeds write in °C are stored as `*_celsius` [`TempLaw`]s: the API
//! still takes kelvin and converts internally (θ = T − 273.15).

use crate::error::LubError;
use crate::grades::{BaseOil, iso_vg, mil_prf_7808, mil_prf_23699, vg220_gear};
use crate::lubricant::{CELSIUS_ZERO, Lubricant, MixedLimitsData, TempLaw, ViscosityLaw};
use crate::provenance::{OilProperty, PropertySource};
use crate::seed_rheology::{
    NVI65_SHEAR_MODULUS_PA, VNII_EYRING_STRESS_PA, VNII_SHEAR_MODULUS_PA, pao1_eyring_stress,
    pao1_shear_modulus,
};
use crate::viscosity::walther_from_two_points;

/// Names of the built-in oils (CLI keys): the seeds' oils, the ISO VG grades, the aero-engine
/// and gear oils.
pub const KNOWN_OILS: [&str; 35] = [
    "pao1-vg320",
    "nvi65",
    "vnii-np-50-1-4u",
    "vg220-mineral",
    "mn-7.5u",
    "ipm-10",
    "seed002-test-oil",
    "irp-150",
    "iso-vg-10-mineral",
    "iso-vg-15-mineral",
    "iso-vg-22-mineral",
    "iso-vg-32-mineral",
    "iso-vg-46-mineral",
    "iso-vg-68-mineral",
    "iso-vg-100-mineral",
    "iso-vg-150-mineral",
    "iso-vg-220-mineral",
    "iso-vg-320-mineral",
    "iso-vg-460-mineral",
    "iso-vg-680-mineral",
    "iso-vg-10-pao",
    "iso-vg-15-pao",
    "iso-vg-22-pao",
    "iso-vg-32-pao",
    "iso-vg-46-pao",
    "iso-vg-68-pao",
    "iso-vg-100-pao",
    "iso-vg-150-pao",
    "iso-vg-220-pao",
    "iso-vg-320-pao",
    "iso-vg-460-pao",
    "iso-vg-680-pao",
    "mil-prf-23699",
    "mil-prf-7808",
    "vg220-gear",
];

/// Look up a built-in oil by name (case-insensitive; `_` and ` ` are accepted for `-`).
/// An unknown name gives [`LubError::UnknownOil`] listing the known names.
pub fn lubricant_by_name(name: &str) -> Result<Lubricant, LubError> {
    let key = name.trim().to_ascii_lowercase().replace(['_', ' '], "-");
    match key.as_str() {
        "pao1-vg320" | "pao1" => Ok(pao1_vg320()),
        "nvi65" | "nvi-65" => Ok(nvi65()),
        "vnii-np-50-1-4u" => Ok(vnii_np_50_1_4u()),
        "vg220-mineral" | "vg220" => Ok(vg220_mineral()),
        "mn-7.5u" => Ok(mn_7_5u()),
        "ipm-10" => Ok(ipm_10()),
        "seed002-test-oil" => Ok(seed002_test_oil()),
        "irp-150" => Ok(irp_150()),
        "mil-prf-23699" => Ok(mil_prf_23699()),
        "mil-prf-7808" => Ok(mil_prf_7808()),
        "vg220-gear" => Ok(vg220_gear()),
        _ => iso_vg_by_name(&key).unwrap_or_else(|| {
            Err(LubError::UnknownOil {
                name: name.to_string(),
                known: KNOWN_OILS.to_vec(),
            })
        }),
    }
}

/// `iso-vg-<N>-mineral` / `iso-vg-<N>-pao` of a listed grade, or `None`.
fn iso_vg_by_name(key: &str) -> Option<Result<Lubricant, LubError>> {
    let rest = key.strip_prefix("iso-vg-")?;
    let (grade, base) = rest.split_once('-')?;
    let base = match base {
        "mineral" => BaseOil::Mineral,
        "pao" => BaseOil::Pao,
        _ => return None,
    };
    let grade: u32 = grade.parse().ok()?;
    crate::grades::ISO_VG_GRADES
        .contains(&grade)
        .then(|| iso_vg(grade, base))
}

/// κ of PAO1 (seed 000 §2.2), 1/(K·Pa).
const PAO1_KAPPA_PER_K_PA: f64 = 1.2e-10;
/// κ (γ) of VNII NP 50-1-4u (seed 000 §3.1.2), 1/(K·Pa).
const VNII_KAPPA_PER_K_PA: f64 = 1e-11;

/// `properties` given by the seed `source`, each as measured.
fn given_by(source: &str, properties: &[OilProperty]) -> Vec<PropertySource> {
    properties
        .iter()
        .map(|p| PropertySource::measured(*p, source))
        .collect()
}

fn c(t_c: f64) -> f64 {
    t_c + CELSIUS_ZERO
}

/// PAO1, polyalphaolefin ISO VG 320 — seed 000 §2.2 (traction data of Vengudusamy et al., cited).
///
/// * ν = 2 367 473·θ^−2.4151 mm²/s (θ in °C) → `power_celsius` a = 2.367473 m²/s;
/// * ᾱ = 15.666 − 0.0666 θ GPa⁻¹; Γ = 7.444 + 0.0163θ − 0.002083θ² + 0.0000121θ³ GPa;
///   τ0 = 8.46 − 0.054θ MPa (all θ in °C, stored in SI);
/// * K_f = 0.1304 W/(m·K), κ = 1.2×10⁻¹⁰ 1/(K·Pa), β0 = 0.023 1/K.
/// * Valid 40…100 °C (range of the fitted curves, Fig. 2.8).
///
/// Missing: the oil density (needed for η = ρν): SPEC F-25 proposal 850 kg/m³ (assumed, constant).
/// The steel data of the same paragraph (K_m, ρ_m, c_m) are in [`crate::SolidThermal`].
pub fn pao1_vg320() -> Lubricant {
    Lubricant {
        name: "pao1-vg320".into(),
        class: "PAO, ISO VG 320".into(),
        source: "seed 000 §2.2 (PAO1 ISO VG 320 temperature laws, K_f, kappa, beta0); density: flag F-25 assumption (docs/theory.md appendix A)".into(),
        temperature_range_k: [c(40.0), c(100.0)],
        density: Some(TempLaw::Constant { value: 850.0 }),
        viscosity: Some(ViscosityLaw::Kinematic {
            law: TempLaw::PowerCelsius {
                a: 2_367_473.0e-6,
                b: -2.4151,
            },
        }),
        pressure_viscosity: Some(TempLaw::PolynomialCelsius {
            coeffs: vec![15.666e-9, -0.0666e-9],
        }),
        roelands_z: None,
        shear_modulus: Some(pao1_shear_modulus()),
        eyring_stress: Some(pao1_eyring_stress()),
        beta0_per_k: Some(0.023),
        kappa_per_k_pa: Some(PAO1_KAPPA_PER_K_PA),
        thermal_conductivity: Some(TempLaw::Constant { value: 0.1304 }),
        mixed_friction: None,
        missing: vec![
            "oil density (850 kg/m^3 assumed, flag F-25)".into(),
            "Lambda_bd / Lambda_hd".into(),
        ],
        provenance: [
            given_by(
                "seed 000 §2.2",
                &[
                    OilProperty::Viscosity,
                    OilProperty::PressureViscosity,
                    OilProperty::ShearModulus,
                    OilProperty::EyringStress,
                    OilProperty::Beta0,
                    OilProperty::Kappa,
                    OilProperty::ThermalConductivity,
                ],
            ),
            vec![PropertySource::estimated(
                OilProperty::Density,
                "850 kg/m3 assumed (SPEC flag F-25)",
            )],
        ]
        .concat(),
    }
}

/// NVI 65, medium-viscosity mineral oil (O'Brien & Taylor tests) — seed 000 Table 2.3 and fits:
/// η = 0.1432·e^{−0.04θ} Pa·s (β0 = 0.04 1/K), ᾱ = (0.0259 − 0.0001θ) MPa⁻¹ (printed "Pa⁻¹", F-26),
/// θ in °C; Γ = 3 GPa, used with the elastic (linear) term of (1.4) only; Λ_bd = 1.35, Λ_hd = 3.05.
/// Valid 19…60 °C (Table 2.3).
///
/// Missing: τ0, κ, K_f, density.
pub fn nvi65() -> Lubricant {
    Lubricant {
        name: "nvi65".into(),
        class: "mineral (NVI 65)".into(),
        source: "seed 000 Table 2.3 and fits of §2.3 (eta(theta), alpha(theta) in MPa^-1 per F-26), Gamma = 3 GPa, Lambda 1.35/3.05".into(),
        temperature_range_k: [c(19.0), c(60.0)],
        density: None,
        viscosity: Some(ViscosityLaw::Dynamic {
            law: TempLaw::Exponential {
                value_ref: 0.1432,
                t_ref_k: CELSIUS_ZERO,
                beta_per_k: 0.04,
            },
        }),
        pressure_viscosity: Some(TempLaw::PolynomialCelsius {
            coeffs: vec![0.0259e-6, -0.0001e-6],
        }),
        roelands_z: None,
        shear_modulus: Some(TempLaw::Constant {
            value: NVI65_SHEAR_MODULUS_PA,
        }),
        eyring_stress: None,
        beta0_per_k: Some(0.04),
        kappa_per_k_pa: None,
        thermal_conductivity: None,
        mixed_friction: Some(MixedLimitsData {
            lambda_bd: 1.35,
            lambda_hd: 3.05,
        }),
        missing: vec![
            "Eyring stress tau0".into(),
            "kappa".into(),
            "thermal conductivity K_f".into(),
            "density".into(),
        ],
        provenance: given_by(
            "seed 000 Table 2.3 and §2.3",
            &[
                OilProperty::Viscosity,
                OilProperty::PressureViscosity,
                OilProperty::ShearModulus,
                OilProperty::Beta0,
                OilProperty::MixedFriction,
            ],
        ),
    }
}

/// VNII NP 50-1-4u aviation oil — seed 000 §3.1.2 (also 2002834): β0 = 0.025 1/K, γ ≡ κ = 1×10⁻¹¹
/// 1/(K·Pa), Γ = 5×10⁷ Pa, τ0 = 3×10⁵ Pa, Λ_bd = 0.2, Λ_hd = 1.5. Range of use in the seed: 50…100 °C.
///
/// Missing: the viscosity–temperature law ("from the data sheet"), ᾱ (the printed ᾱ = 0.3·T^−4.167
/// MPa⁻¹ is implausible for T in °C or K — F-27: supply a, b of a `power_kelvin` law yourself), K_f,
/// oil density. The seed's "ρ_m = 830 kg/m³" is a steel-density misprint (F-25), see
/// [`crate::SolidThermal::SEED_000_LITERAL`].
pub fn vnii_np_50_1_4u() -> Lubricant {
    Lubricant {
        name: "vnii-np-50-1-4u".into(),
        class: "synthetic aviation turbine oil".into(),
        source: "seed 000 §3.1.2 (beta0, gamma=kappa, Gamma, tau0, Lambda 0.2/1.5)".into(),
        temperature_range_k: [c(50.0), c(100.0)],
        density: None,
        viscosity: None,
        pressure_viscosity: None,
        roelands_z: None,
        shear_modulus: Some(TempLaw::Constant {
            value: VNII_SHEAR_MODULUS_PA,
        }),
        eyring_stress: Some(TempLaw::Constant {
            value: VNII_EYRING_STRESS_PA,
        }),
        beta0_per_k: Some(0.025),
        kappa_per_k_pa: Some(VNII_KAPPA_PER_K_PA),
        thermal_conductivity: None,
        mixed_friction: Some(MixedLimitsData {
            lambda_bd: 0.2,
            lambda_hd: 1.5,
        }),
        missing: vec![
            "viscosity-temperature law (seed: 'from the data sheet')".into(),
            "pressure-viscosity coefficient (printed 0.3 T^-4.167 MPa^-1 unusable, F-27)".into(),
            "thermal conductivity K_f".into(),
            "density".into(),
        ],
        provenance: given_by(
            "seed 000 §3.1.2",
            &[
                OilProperty::ShearModulus,
                OilProperty::EyringStress,
                OilProperty::Beta0,
                OilProperty::Kappa,
                OilProperty::MixedFriction,
            ],
        ),
    }
}

/// VG 220 mineral base oil of the tapered-bearing grease — seed 000 §3.2.1: ν = 220 mm²/s at 40 °C and
/// 19 mm²/s at 100 °C, interpolated by Walther/ASTM D341 (standard form, not in the seeds; A = 8.8222,
/// B = 3.3867, ν(60 °C) ≈ 78.8 mm²/s). Valid 40…100 °C. Grease starvation: use
/// [`crate::film::GREASE_STARVATION_FACTOR`] (−30 %, seed 000 citing Larsson).
///
/// Missing: density (so no dynamic viscosity without a user value), ᾱ, Γ, τ0, κ, K_f.
pub fn vg220_mineral() -> Lubricant {
    Lubricant {
        name: "vg220-mineral".into(),
        class: "mineral, ISO VG 220 (grease base oil)".into(),
        source: "seed 000 §3.2.1 (nu 220 / 19 mm^2/s at 40 / 100 C); Walther/ASTM D341 interpolation (standard form)".into(),
        temperature_range_k: [c(40.0), c(100.0)],
        density: None,
        viscosity: Some(ViscosityLaw::Kinematic {
            law: walther_from_two_points(c(40.0), 220e-6, c(100.0), 19e-6),
        }),
        pressure_viscosity: None,
        roelands_z: None,
        shear_modulus: None,
        eyring_stress: None,
        beta0_per_k: None,
        kappa_per_k_pa: None,
        thermal_conductivity: None,
        mixed_friction: None,
        missing: vec![
            "density".into(),
            "pressure-viscosity coefficient".into(),
            "shear modulus Gamma".into(),
            "Eyring stress tau0".into(),
            "kappa".into(),
            "thermal conductivity K_f".into(),
        ],
        provenance: given_by("seed 000 §3.2.1", &[OilProperty::Viscosity]),
    }
}

fn name_only(name: &str, source: &str, range_c: [f64; 2], missing: &[&str]) -> Lubricant {
    Lubricant {
        name: name.into(),
        source: source.into(),
        class: String::new(),
        temperature_range_k: [c(range_c[0]), c(range_c[1])],
        density: None,
        viscosity: None,
        pressure_viscosity: None,
        roelands_z: None,
        shear_modulus: None,
        eyring_stress: None,
        beta0_per_k: None,
        kappa_per_k_pa: None,
        thermal_conductivity: None,
        mixed_friction: None,
        missing: missing.iter().map(|s| s.to_string()).collect(),
        provenance: Vec::new(),
    }
}

/// MN-7.5u — seed 000 Fig. 2.12 (critical-slip curves at 60/100/140 °C). The seed names the oil only;
/// its parameters are in the cited Balyakin (2007). Range: the seed's 60…140 °C.
///
/// Missing: everything.
pub fn mn_7_5u() -> Lubricant {
    name_only(
        "mn-7.5u",
        "seed 000 Fig. 2.12 (name only; data in Balyakin 2007, not in the seeds)",
        [60.0, 140.0],
        &["all properties (viscosity, alpha, Gamma, tau0, beta0, kappa, K_f, density)"],
    )
}

/// IPM-10 — seed 001 test oil, name only. seed 001 requires μ0(t), α(t), λ(t), β.
/// Range: not given by the seed; the entry accepts 0…200 °C (nothing in it depends on temperature).
///
/// Missing: everything.
pub fn ipm_10() -> Lubricant {
    name_only(
        "ipm-10",
        "seed 001 (name only)",
        [0.0, 200.0],
        &[
            "all properties (mu0(t), alpha(t), lambda(t), beta, density)",
            "temperature range",
        ],
    )
}

/// seed 002 roller–plate test oil: μ = 0.024 Pa·s, α = 0.75×10⁻⁸ 1/Pa (temperature not given: the
/// laws are constants, so the entry accepts 0…200 °C).
pub fn seed002_test_oil() -> Lubricant {
    Lubricant {
        viscosity: Some(ViscosityLaw::Dynamic {
            law: TempLaw::Constant { value: 0.024 },
        }),
        pressure_viscosity: Some(TempLaw::Constant { value: 0.75e-8 }),
        provenance: given_by(
            "seed 002",
            &[OilProperty::Viscosity, OilProperty::PressureViscosity],
        ),
        ..name_only(
            "seed002-test-oil",
            "seed 002 roller-plate oil (mu = 0.024 Pa s, alpha = 0.75e-8 1/Pa)",
            [0.0, 200.0],
            &[
                "temperature dependence",
                "density",
                "Gamma, tau0, beta0, kappa, K_f",
            ],
        )
    }
}

/// seed 002 gearbox oil IRP-150: μ = 0.14 Pa·s, α = 1.4×10⁻⁸ 1/Pa (temperature not given; constants).
pub fn irp_150() -> Lubricant {
    Lubricant {
        viscosity: Some(ViscosityLaw::Dynamic {
            law: TempLaw::Constant { value: 0.14 },
        }),
        pressure_viscosity: Some(TempLaw::Constant { value: 1.4e-8 }),
        provenance: given_by(
            "seed 002 ch. 5",
            &[OilProperty::Viscosity, OilProperty::PressureViscosity],
        ),
        ..name_only(
            "irp-150",
            "seed 002 ch. 5 gearbox oil IRP-150 (mu = 0.14 Pa s, alpha = 1.4e-8 1/Pa)",
            [0.0, 200.0],
            &[
                "temperature dependence",
                "density",
                "Gamma, tau0, beta0, kappa, K_f",
            ],
        )
    }
}
