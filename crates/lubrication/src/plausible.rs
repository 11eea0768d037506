//! Plausibility bounds of oil properties (issue 39 N12): values that are finite and positive
//! but describe no liquid lubricant (a density of 9·10¹¹ kg/m³) are refused with the property
//! at fault, not run into a silently wrong skid or film. The bounds are generous: they exclude
//! absurd input, not unusual oils (docs/lubricants.md, "Plausibility bounds").

/// One property's plausible range (SI) and the reason for it.
#[derive(Debug, Clone, Copy)]
pub struct OilBound {
    /// The property's key (as in [`crate::OilProperty::key`]).
    pub key: &'static str,
    /// Plausible range, SI.
    pub range: (f64, f64),
    /// The unit shown in messages.
    pub unit: &'static str,
    /// The factor from SI to `unit`.
    pub shown: f64,
    /// Why the range holds every liquid lubricant.
    pub reason: &'static str,
}

/// Density ρ, kg/m³.
pub const DENSITY: OilBound = OilBound {
    key: "density",
    range: (500.0, 2500.0),
    unit: "kg/m³",
    shown: 1.0,
    reason: "liquid lubricants lie between light mineral oils (≈ 800) and perfluoropolyethers (≈ 1900)",
};
/// Dynamic viscosity η at atmospheric pressure, Pa·s.
pub const VISCOSITY: OilBound = OilBound {
    key: "viscosity",
    range: (1e-5, 1e5),
    unit: "Pa·s",
    shown: 1.0,
    reason: "from below hot water (0.28 mPa·s) to above a cold gear oil; 10⁵ Pa·s does not flow",
};
/// Barus pressure–viscosity coefficient ᾱ, 1/Pa.
pub const PRESSURE_VISCOSITY: OilBound = OilBound {
    key: "pressure_viscosity",
    range: (1e-11, 1e-7),
    unit: "1/GPa",
    shown: 1e9,
    reason: "water-based fluids ≈ 0.1, mineral and synthetic oils 8–35, traction fluids ≈ 40 1/GPa",
};
/// Limiting elastic shear modulus Γ, Pa.
pub const SHEAR_MODULUS: OilBound = OilBound {
    key: "shear_modulus",
    range: (1e5, 1e11),
    unit: "GPa",
    shown: 1e-9,
    reason: "EHL films show 0.1–3 GPa; 100 GPa is a metal's",
};
/// Eyring stress τ0, Pa.
pub const EYRING_STRESS: OilBound = OilBound {
    key: "eyring_stress",
    range: (1e2, 1e9),
    unit: "MPa",
    shown: 1e-6,
    reason: "oils show 1–20 MPa; 1 GPa exceeds the shear strength of bearing steel",
};
/// Thermal conductivity K_f, W/(m·K).
pub const THERMAL_CONDUCTIVITY: OilBound = OilBound {
    key: "thermal_conductivity",
    range: (0.01, 2.0),
    unit: "W/(m·K)",
    shown: 1.0,
    reason: "oils ≈ 0.1–0.15, water ≈ 0.6 W/(m·K)",
};
/// Temperature–viscosity coefficient β0, 1/K (given or derived from the viscosity law).
pub const BETA0: OilBound = OilBound {
    key: "beta0",
    range: (0.0, 0.5),
    unit: "1/K",
    shown: 1.0,
    reason: "oils show 0.01–0.1 1/K: the viscosity falls with temperature, by less than 40 % per kelvin",
};
/// Temperature–pressure coefficient κ, 1/(K·Pa).
pub const KAPPA: OilBound = OilBound {
    key: "kappa",
    range: (0.0, 1e-9),
    unit: "1/(K·GPa)",
    shown: 1e9,
    reason: "seed oils show ≈ 0.01–0.1 1/(K·GPa)",
};
/// Roelands pressure–viscosity index Z.
pub const ROELANDS_Z: OilBound = OilBound {
    key: "roelands_z",
    range: (0.1, 1.5),
    unit: "",
    shown: 1.0,
    reason: "oils show Z ≈ 0.4–0.8",
};
/// Film parameter Λ of the mixed-friction limits.
pub const LAMBDA: OilBound = OilBound {
    key: "mixed_friction",
    range: (0.0, 10.0),
    unit: "",
    shown: 1.0,
    reason: "a film parameter above ≈ 3 is full film already",
};

/// The temperatures at which the laws are checked over `[lo, hi]` (K): the ends and every
/// kelvin in between (at most 2000 points), so that a law turning negative or implausible
/// inside the range is found on load, not at the temperature of a run.
pub fn check_temperatures(lo: f64, hi: f64) -> impl Iterator<Item = f64> {
    let steps = ((hi - lo).ceil() as usize).clamp(1, 2000);
    (0..=steps).map(move |k| lo + (hi - lo) * k as f64 / steps as f64)
}

impl OilBound {
    /// `None` when `value` is within the bound, else the reason (value, range and why) for a
    /// message naming the property; `at` says where the value was evaluated (e.g. "at 40 °C").
    pub fn violation(&self, value: f64, at: &str) -> Option<String> {
        let (lo, hi) = self.range;
        if (lo..=hi).contains(&value) {
            return None;
        }
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        Some(format!(
            "{:.4e}{unit}{at} is implausible (expected {:.4e}…{:.4e}{unit}: {})",
            value * self.shown,
            lo * self.shown,
            hi * self.shown,
            self.reason
        ))
    }
}

#[cfg(test)]
mod tests {
    use crate::{LubError, TempLaw, lubricant_by_name};

    #[test]
    fn n12_an_implausible_or_dipping_law_names_its_property() {
        let seed = lubricant_by_name("seed002-test-oil").unwrap();
        let dense = crate::Lubricant {
            density: Some(TempLaw::Constant { value: 9e11 }),
            ..seed.clone()
        };
        match dense.validate() {
            Err(LubError::Property { key, .. }) => assert_eq!(key, "density"),
            other => panic!("{other:?}"),
        }
        // within bounds at both ends and the middle of the range, negative in between:
        // c ((θ − a)² − b²) with its roots inside the first half of the range
        let [lo, hi] = seed.temperature_range_k;
        let span = hi - lo;
        let (a, b) = (lo - 273.15 + 0.25 * span, 0.1 * span);
        let c = 1.0 / (0.5525 * span * span);
        let dipping = crate::Lubricant {
            thermal_conductivity: Some(TempLaw::PolynomialCelsius {
                coeffs: vec![c * (a * a - b * b), -2.0 * a * c, c],
            }),
            ..seed
        };
        match dipping.validate() {
            Err(LubError::Property { key, .. }) => assert_eq!(key, "thermal_conductivity"),
            other => panic!("{other:?}"),
        }
    }
}
