//! Lubricant and solid property models (SPEC §4.1, §4.2).
//!
//! A [`Lubricant`] is a set of temperature laws ([`TempLaw`]) in SI units, with the provenance of
//! each property ([`PropertySource`]: measured or estimated, and from where). Every optional
//! property that a source does not give is `None`, and models that need it refuse to build
//! ([`crate::LubError::MissingProperty`]). User oil files (TOML with units) are read by
//! `rolldyn_model::oil_file` into this type.

use crate::error::LubError;
use crate::provenance::{Basis, OilProperty, PropertySource};

/// 0 °C in kelvin.
pub const CELSIUS_ZERO: f64 = 273.15;

/// A scalar property as a function of temperature. Output in SI units of the property.
#[derive(Debug, Clone, PartialEq)]
pub enum TempLaw {
    /// Temperature-independent value.
    Constant {
        /// value (SI)
        value: f64,
    },
    /// Σ cₖ θᵏ with θ = T − 273.15 in **°C** (form of the PAO1 and NVI 65 fits of seed 000).
    PolynomialCelsius {
        /// c₀, c₁, … (SI units of the property per °Cᵏ)
        coeffs: Vec<f64>,
    },
    /// a·θᵇ with θ in **°C** (PAO1 kinematic viscosity of seed 000 §2.2); requires θ > 0.
    PowerCelsius {
        /// a (SI units · °C^−b)
        a: f64,
        /// b
        b: f64,
    },
    /// a·Tᵇ with T in kelvin (e.g. the seed 000 VNII law ᾱ = a Tᵇ once its constants are confirmed, F-27).
    PowerKelvin {
        /// a
        a: f64,
        /// b
        b: f64,
    },
    /// v_ref · exp(−β (T − T_ref)) (Reynolds exponential law; NVI 65 η = 0.1432 e^{−0.04θ}).
    Exponential {
        /// value at `t_ref_k`
        value_ref: f64,
        /// reference temperature, K
        t_ref_k: f64,
        /// β, 1/K
        beta_per_k: f64,
    },
    /// Walther / ASTM D341 kinematic viscosity: log₁₀ log₁₀(ν + 0.7) = a − b log₁₀ T (ν in mm²/s,
    /// T in K); **output converted to m²/s**. Standard form, not in the seeds (SPEC §4.2.5).
    Walther {
        /// A
        a: f64,
        /// B
        b: f64,
    },
}

impl TempLaw {
    /// Evaluate at temperature `t_k` (kelvin).
    #[inline]
    pub fn eval(&self, t_k: f64) -> f64 {
        match self {
            TempLaw::Constant { value } => *value,
            TempLaw::PolynomialCelsius { coeffs } => {
                let th = t_k - CELSIUS_ZERO;
                coeffs.iter().rev().fold(0.0, |acc, c| acc * th + c)
            }
            TempLaw::PowerCelsius { a, b } => a * (t_k - CELSIUS_ZERO).powf(*b),
            TempLaw::PowerKelvin { a, b } => a * t_k.powf(*b),
            TempLaw::Exponential {
                value_ref,
                t_ref_k,
                beta_per_k,
            } => value_ref * (-beta_per_k * (t_k - t_ref_k)).exp(),
            TempLaw::Walther { a, b } => {
                let ll = a - b * t_k.log10();
                (10f64.powf(10f64.powf(ll)) - 0.7) * 1e-6
            }
        }
    }
}

/// Atmospheric-pressure viscosity law.
#[derive(Debug, Clone, PartialEq)]
pub enum ViscosityLaw {
    /// Kinematic viscosity ν(T) in m²/s; dynamic viscosity η = ρ(T)·ν(T) (needs `density`).
    Kinematic {
        /// ν(T), m²/s
        law: TempLaw,
    },
    /// Dynamic viscosity η(T) in Pa·s.
    Dynamic {
        /// η(T), Pa·s
        law: TempLaw,
    },
}

/// Film-parameter limits Λ_bd, Λ_hd of the mixed-friction blend (1.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MixedLimitsData {
    /// Λ below which friction is boundary
    pub lambda_bd: f64,
    /// Λ above which friction is hydrodynamic
    pub lambda_hd: f64,
}

/// A lubricant: temperature laws of every property the LUB models may need. All SI.
///
/// Properties that a data set does not define are `None`; [`Lubricant::missing`] documents what
/// the source lacks. Use the accessor methods (they take kelvin).
#[derive(Debug, Clone, PartialEq)]
pub struct Lubricant {
    /// Name (library key or user name).
    pub name: String,
    /// Where the data come from (seed, table/equation), free text.
    pub source: String,
    /// Oil class and grade, e.g. `ISO VG 68 mineral (VI 95)`; empty when the source gives none.
    pub class: String,
    /// Valid temperature range [T_min, T_max] in K of the fits. The traction model clamps the
    /// property temperature to this range (and flags it).
    pub temperature_range_k: [f64; 2],
    /// Density ρ(T), kg/m³.
    pub density: Option<TempLaw>,
    /// Atmospheric viscosity η_N0(T) / ν(T).
    pub viscosity: Option<ViscosityLaw>,
    /// Barus pressure–viscosity coefficient ᾱ(T), 1/Pa ((1.5), (002-3.8)).
    pub pressure_viscosity: Option<TempLaw>,
    /// Roelands pressure–viscosity index Z; if `None` it is derived from ᾱ (α = 5.1e-9 (ln η0 + 9.67) Z).
    pub roelands_z: Option<f64>,
    /// Oil shear modulus Γ(T) (G in seed 000), Pa ((1.4)).
    pub shear_modulus: Option<TempLaw>,
    /// Eyring characteristic stress τ0(T), Pa ((1.4)).
    pub eyring_stress: Option<TempLaw>,
    /// Temperature–viscosity coefficient β0 of (1.5)/(1.9), 1/K. If `None`, derived from the
    /// viscosity law as −d ln η0/dT.
    pub beta0_per_k: Option<f64>,
    /// Combined temperature–pressure coefficient κ (printed γ in (1.9) and for VNII; F-24), 1/(K·Pa).
    pub kappa_per_k_pa: Option<f64>,
    /// Oil thermal conductivity K_f(T) (λ_c of seed 001), W/(m·K).
    pub thermal_conductivity: Option<TempLaw>,
    /// Λ_bd / Λ_hd recommended with this oil for (1.3).
    pub mixed_friction: Option<MixedLimitsData>,
    /// What the source does not give (documentation only).
    pub missing: Vec<String>,
    /// Where each given property comes from (measured or estimated); a property without an
    /// entry has no stated provenance (user oil files may omit it).
    pub provenance: Vec<PropertySource>,
}

/// Properties of an oil evaluated at one temperature (SI). Missing items are `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OilProperties {
    /// temperature at which the properties were evaluated, K
    pub temperature_k: f64,
    /// ρ, kg/m³
    pub density: Option<f64>,
    /// η_N0, Pa·s
    pub dynamic_viscosity: Option<f64>,
    /// ᾱ, 1/Pa
    pub pressure_viscosity: Option<f64>,
    /// Γ, Pa
    pub shear_modulus: Option<f64>,
    /// τ0, Pa
    pub eyring_stress: Option<f64>,
    /// β0, 1/K
    pub beta0: Option<f64>,
    /// κ, 1/(K·Pa)
    pub kappa: Option<f64>,
    /// K_f, W/(m·K)
    pub thermal_conductivity: Option<f64>,
}

impl Lubricant {
    fn missing_err(&self, property: &'static str) -> LubError {
        LubError::MissingProperty {
            oil: self.name.clone(),
            property,
        }
    }

    /// Checks that the data are physical and plausible: an ordered temperature range above 0 K,
    /// every defined property finite and within its [`crate::plausible`] bound at every kelvin
    /// of the range (κ and β0 may be zero), Z within its bound and 0 ≤ Λ_bd < Λ_hd ≤ 10. The
    /// error names the property ([`LubError::Property`]). User oils are checked on load; the
    /// built-in library passes.
    pub fn validate(&self) -> Result<(), LubError> {
        use crate::plausible::{self as bound, OilBound};
        let bad = |key: &'static str, reason: String| {
            Err(LubError::Property {
                oil: self.name.clone(),
                key,
                reason,
            })
        };
        let [lo, hi] = self.temperature_range_k;
        if !(lo > 0.0 && hi >= lo && hi.is_finite()) {
            return bad(
                "temperature_range",
                format!("[{lo}, {hi}] K must be ordered kelvin values above 0"),
            );
        }
        // β0 derived by a central difference and κ may be zero up to rounding
        let rounded = |v: f64| if v > -1e-12 { v.max(0.0) } else { v };
        for t in bound::check_temperatures(lo, hi) {
            let p = self.properties(t);
            let at = format!(" at {:.1} °C", t - 273.15);
            let checked: [(&OilBound, Option<f64>); 8] = [
                (&bound::DENSITY, p.density),
                (&bound::VISCOSITY, p.dynamic_viscosity),
                (&bound::PRESSURE_VISCOSITY, p.pressure_viscosity),
                (&bound::SHEAR_MODULUS, p.shear_modulus),
                (&bound::EYRING_STRESS, p.eyring_stress),
                (&bound::THERMAL_CONDUCTIVITY, p.thermal_conductivity),
                (&bound::BETA0, p.beta0.map(rounded)),
                (&bound::KAPPA, p.kappa.map(rounded)),
            ];
            for (limits, value) in checked {
                if let Some(reason) = value.and_then(|v| limits.violation(v, &at)) {
                    return bad(limits.key, reason);
                }
            }
        }
        if let Some(reason) = self
            .roelands_z
            .and_then(|z| bound::ROELANDS_Z.violation(z, ""))
        {
            return bad(bound::ROELANDS_Z.key, reason);
        }
        if let Some(m) = self.mixed_friction {
            let limits = &bound::LAMBDA;
            if !(m.lambda_bd >= 0.0 && m.lambda_hd > m.lambda_bd) {
                return bad(
                    limits.key,
                    format!(
                        "needs 0 ≤ lambda_bd < lambda_hd, got {} and {}",
                        m.lambda_bd, m.lambda_hd
                    ),
                );
            }
            if let Some(reason) = limits.violation(m.lambda_hd, " (lambda_hd)") {
                return bad(limits.key, reason);
            }
        }
        Ok(())
    }

    /// The properties whose provenance is `basis`, in [`OilProperty::ALL`] order.
    pub fn properties_with(&self, basis: Basis) -> Vec<OilProperty> {
        OilProperty::ALL
            .into_iter()
            .filter(|p| {
                self.provenance
                    .iter()
                    .any(|s| s.property == *p && s.basis == basis)
            })
            .collect()
    }

    /// Is `t_k` inside the documented temperature range?
    pub fn in_range(&self, t_k: f64) -> bool {
        t_k >= self.temperature_range_k[0] && t_k <= self.temperature_range_k[1]
    }

    /// Clamp a temperature to the documented range.
    #[inline]
    pub fn clamp_temperature(&self, t_k: f64) -> f64 {
        t_k.clamp(self.temperature_range_k[0], self.temperature_range_k[1])
    }

    /// Density ρ(T), kg/m³.
    pub fn density(&self, t_k: f64) -> Result<f64, LubError> {
        self.density
            .as_ref()
            .map(|l| l.eval(t_k))
            .ok_or_else(|| self.missing_err("density"))
    }

    /// Dynamic viscosity at atmospheric pressure η_N0(T), Pa·s.
    pub fn dynamic_viscosity(&self, t_k: f64) -> Result<f64, LubError> {
        match &self.viscosity {
            None => Err(self.missing_err("viscosity law")),
            Some(ViscosityLaw::Dynamic { law }) => Ok(law.eval(t_k)),
            Some(ViscosityLaw::Kinematic { law }) => Ok(law.eval(t_k) * self.density(t_k)?),
        }
    }

    /// Kinematic viscosity ν(T), m²/s.
    pub fn kinematic_viscosity(&self, t_k: f64) -> Result<f64, LubError> {
        match &self.viscosity {
            None => Err(self.missing_err("viscosity law")),
            Some(ViscosityLaw::Kinematic { law }) => Ok(law.eval(t_k)),
            Some(ViscosityLaw::Dynamic { law }) => Ok(law.eval(t_k) / self.density(t_k)?),
        }
    }

    /// Barus pressure–viscosity coefficient ᾱ(T), 1/Pa.
    pub fn pressure_viscosity(&self, t_k: f64) -> Result<f64, LubError> {
        self.pressure_viscosity
            .as_ref()
            .map(|l| l.eval(t_k))
            .ok_or_else(|| self.missing_err("pressure-viscosity coefficient (alpha)"))
    }

    /// Oil shear modulus Γ(T), Pa.
    pub fn shear_modulus(&self, t_k: f64) -> Result<f64, LubError> {
        self.shear_modulus
            .as_ref()
            .map(|l| l.eval(t_k))
            .ok_or_else(|| self.missing_err("shear modulus (Gamma)"))
    }

    /// Eyring stress τ0(T), Pa.
    pub fn eyring_stress(&self, t_k: f64) -> Result<f64, LubError> {
        self.eyring_stress
            .as_ref()
            .map(|l| l.eval(t_k))
            .ok_or_else(|| self.missing_err("Eyring stress (tau0)"))
    }

    /// Oil thermal conductivity K_f(T), W/(m·K).
    pub fn thermal_conductivity(&self, t_k: f64) -> Result<f64, LubError> {
        self.thermal_conductivity
            .as_ref()
            .map(|l| l.eval(t_k))
            .ok_or_else(|| self.missing_err("thermal conductivity (K_f)"))
    }

    /// κ (γ of (1.9)), 1/(K·Pa).
    pub fn kappa(&self) -> Result<f64, LubError> {
        self.kappa_per_k_pa
            .ok_or_else(|| self.missing_err("temperature-pressure coefficient (kappa)"))
    }

    /// Temperature–viscosity coefficient β0, 1/K: the given constant, or −d ln η0/dT of the
    /// viscosity law (central difference, ±0.5 K) when none is given.
    pub fn beta0(&self, t_k: f64) -> Result<f64, LubError> {
        if let Some(b) = self.beta0_per_k {
            return Ok(b);
        }
        let h = 0.5;
        let lo = self.dynamic_viscosity(t_k - h)?;
        let hi = self.dynamic_viscosity(t_k + h)?;
        Ok(-(hi.ln() - lo.ln()) / (2.0 * h))
    }

    /// All properties at `t_k` (missing ones `None`).
    pub fn properties(&self, t_k: f64) -> OilProperties {
        OilProperties {
            temperature_k: t_k,
            density: self.density(t_k).ok(),
            dynamic_viscosity: self.dynamic_viscosity(t_k).ok(),
            pressure_viscosity: self.pressure_viscosity(t_k).ok(),
            shear_modulus: self.shear_modulus(t_k).ok(),
            eyring_stress: self.eyring_stress(t_k).ok(),
            beta0: self.beta0(t_k).ok(),
            kappa: self.kappa_per_k_pa,
            thermal_conductivity: self.thermal_conductivity(t_k).ok(),
        }
    }

    /// Check that the properties named by `needs` exist; returns the first missing one.
    pub(crate) fn require(&self, needs: &[Property]) -> Result<(), LubError> {
        let t = 0.5 * (self.temperature_range_k[0] + self.temperature_range_k[1]);
        for p in needs {
            match p {
                Property::Viscosity => self.dynamic_viscosity(t).map(|_| ())?,
                Property::Alpha => self.pressure_viscosity(t).map(|_| ())?,
                Property::Gamma => self.shear_modulus(t).map(|_| ())?,
                Property::Tau0 => self.eyring_stress(t).map(|_| ())?,
                Property::Beta0 => self.beta0(t).map(|_| ())?,
                Property::Kappa => self.kappa().map(|_| ())?,
                Property::Kf => self.thermal_conductivity(t).map(|_| ())?,
            }
        }
        if !(self.temperature_range_k[0] > 0.0
            && self.temperature_range_k[1] >= self.temperature_range_k[0])
        {
            return Err(LubError::InvalidInput(format!(
                "lubricant '{}': temperature_range_k must be increasing and positive (kelvin)",
                self.name
            )));
        }
        Ok(())
    }
}

/// Property tags used by [`Lubricant::require`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Property {
    Viscosity,
    Alpha,
    Gamma,
    Tau0,
    Beta0,
    Kappa,
    Kf,
}

/// Thermal properties of the contacting solids (K_m, ρ_m, c_m of (1.9); λ, γ, c of the seed 001
/// Blok formula).
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolidThermal {
    /// thermal conductivity, W/(m·K)
    pub conductivity_w_mk: f64,
    /// density, kg/m³
    pub density_kg_m3: f64,
    /// specific heat, J/(kg·K)
    pub specific_heat_j_kgk: f64,
}

impl SolidThermal {
    /// Bearing steel with the seed 000 §2.2 values K_m = 45.4 W/(m·K), c_m = 520 J/(kg·K) and the
    /// SPEC F-25 proposal ρ_m = 7830 kg/m³ (AISI 52100). **Default.**
    pub const STEEL: SolidThermal = SolidThermal {
        conductivity_w_mk: 45.4,
        density_kg_m3: 7830.0,
        specific_heat_j_kgk: 520.0,
    };
    /// The literal seed 000 §2.2 / §3.1.2 set with ρ_m = 830 kg/m³ (an oil density misprinted as the
    /// steel density, F-25). Selectable for reproducing the seed literally.
    pub const SEED_000_LITERAL: SolidThermal = SolidThermal {
        conductivity_w_mk: 45.4,
        density_kg_m3: 830.0,
        specific_heat_j_kgk: 520.0,
    };

    /// Thermal effusivity product K·ρ·c, W²·s/(m⁴·K²).
    #[inline]
    pub fn krc(&self) -> f64 {
        self.conductivity_w_mk * self.density_kg_m3 * self.specific_heat_j_kgk
    }
}

impl Default for SolidThermal {
    fn default() -> Self {
        SolidThermal::STEEL
    }
}
