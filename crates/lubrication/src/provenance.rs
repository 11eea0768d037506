//! Where each property of an oil comes from: measured (a standard, a data sheet, a test) or
//! estimated (a correlation, a value typical of the oil class, a value transferred from another
//! oil), with the source named.

use std::fmt;

/// How a property value was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Basis {
    /// From a measurement: a standard's defined value, a product data sheet, a test report.
    Measured,
    /// From a correlation, a class-typical value or a value of another oil (ESTIMATED).
    Estimated,
}

impl Basis {
    /// `measured` or `estimated`.
    pub fn name(self) -> &'static str {
        match self {
            Basis::Measured => "measured",
            Basis::Estimated => "estimated",
        }
    }
}

/// The properties of a [`crate::Lubricant`] that carry a provenance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum OilProperty {
    /// The viscosity–temperature law (ν or η at atmospheric pressure).
    Viscosity,
    /// ρ(T).
    Density,
    /// Barus ᾱ(T).
    PressureViscosity,
    /// Γ(T).
    ShearModulus,
    /// τ0(T).
    EyringStress,
    /// β0.
    Beta0,
    /// κ.
    Kappa,
    /// K_f(T).
    ThermalConductivity,
    /// Λ_bd / Λ_hd.
    MixedFriction,
}

impl OilProperty {
    /// Every property, in listing order.
    pub const ALL: [OilProperty; 9] = [
        OilProperty::Viscosity,
        OilProperty::Density,
        OilProperty::PressureViscosity,
        OilProperty::ShearModulus,
        OilProperty::EyringStress,
        OilProperty::Beta0,
        OilProperty::Kappa,
        OilProperty::ThermalConductivity,
        OilProperty::MixedFriction,
    ];

    /// The key of the property in oil files and listings (`viscosity`, `density`, …).
    pub fn key(self) -> &'static str {
        match self {
            OilProperty::Viscosity => "viscosity",
            OilProperty::Density => "density",
            OilProperty::PressureViscosity => "pressure_viscosity",
            OilProperty::ShearModulus => "shear_modulus",
            OilProperty::EyringStress => "eyring_stress",
            OilProperty::Beta0 => "beta0",
            OilProperty::Kappa => "kappa",
            OilProperty::ThermalConductivity => "thermal_conductivity",
            OilProperty::MixedFriction => "mixed_friction",
        }
    }

    /// The property named by `key` (as [`OilProperty::key`]).
    pub fn from_key(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.key() == key)
    }
}

impl fmt::Display for OilProperty {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// The origin of one property of an oil.
#[derive(Debug, Clone, PartialEq)]
pub struct PropertySource {
    /// Which property.
    pub property: OilProperty,
    /// Measured or estimated.
    pub basis: Basis,
    /// The standard clause, data sheet, correlation or transferred oil, with the reasoning of an
    /// estimate.
    pub source: String,
}

impl PropertySource {
    /// A measured property and its source.
    pub fn measured(property: OilProperty, source: impl Into<String>) -> Self {
        Self {
            property,
            basis: Basis::Measured,
            source: source.into(),
        }
    }

    /// An estimated property and the rule or class value behind it.
    pub fn estimated(property: OilProperty, source: impl Into<String>) -> Self {
        Self {
            property,
            basis: Basis::Estimated,
            source: source.into(),
        }
    }
}
