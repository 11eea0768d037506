//! The oil and the test contact that the lubrication analyses (`oils`, `traction`, `film`)
//! evaluate: a built-in oil or a user oil file, with the temperature-range policy; a ball on a
//! disc (the PAO1 traction rig of seed 000 §2.2) or a line contact, with its elastic data.

use crate::analysis::Context;
use crate::failure::Failure;
use rolldyn_contact::hertz::{MAX_CREDIBLE_PRESSURE_PA, reduced_modulus};
use rolldyn_lubrication::contact_state::{
    circular_load_for_max_pressure, line_load_for_max_pressure,
};
use rolldyn_lubrication::{ContactGeometry, Lubricant, lubricant_by_name};
use rolldyn_units::{Dimensionless, Length, Pressure, Quantity, format_number};
use serde::Deserialize;
use std::path::PathBuf;

/// Which oil: a built-in one (`rolldyn oils`) or a user oil file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OilChoice {
    /// Built-in oil, e.g. `pao1-vg320`.
    pub oil: String,
    /// User oil file (TOML with the keys of the built-in library; docs/lubricants.md); it
    /// replaces `oil`.
    pub oil_file: Option<PathBuf>,
    /// A temperature outside the oil's documented range is an error instead of a warning.
    pub strict: bool,
}

impl Default for OilChoice {
    fn default() -> Self {
        Self {
            oil: "pao1-vg320".into(),
            oil_file: None,
            strict: false,
        }
    }
}

impl OilChoice {
    /// The selected lubricant.
    pub fn load(&self) -> Result<Lubricant, Failure> {
        let Some(path) = &self.oil_file else {
            return lubricant_by_name(&self.oil).map_err(|e| Failure::Input(e.to_string()));
        };
        rolldyn_model::load_oil_file(path).map_err(|e| Failure::Input(e.to_string()))
    }

    /// Warns (or fails when `strict`) when `temperature_k` is outside the oil's range.
    pub fn check_temperature(
        &self,
        oil: &Lubricant,
        temperature_k: f64,
        context: &Context<'_>,
    ) -> Result<(), Failure> {
        if oil.in_range(temperature_k) {
            return Ok(());
        }
        let [lo, hi] = oil.temperature_range_k;
        let outside = format!(
            "{:.1} °C is outside the documented range of {} ({:.0}…{:.0} °C)",
            temperature_k - 273.15,
            oil.name,
            lo - 273.15,
            hi - 273.15
        );
        if self.strict {
            return Err(Failure::Input(outside));
        }
        context
            .observer
            .warning(&format!("{outside}; properties are clamped to the range"));
        Ok(())
    }
}

/// The kind of test contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum ContactKind {
    /// Ball on a flat disc (circular point contact; `radius` is the ball radius).
    BallOnDisc,
    /// Line contact of length `length`; `radius` is the reduced radius R′ (seed 000 eq. 1.12).
    Line,
}

/// The test contact and its elastic data.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Rig {
    pub contact: ContactKind,
    /// Ball radius (ball-on-disc) or reduced radius R′ (line); default the Ø19 mm ball of the
    /// seed's PAO1 tests.
    pub radius: Quantity<Length>,
    /// Contact length of a line contact.
    pub length: Quantity<Length>,
    /// Young's modulus of both bodies (AISI 52100).
    pub youngs_modulus: Quantity<Pressure>,
    /// Poisson's ratio of both bodies.
    pub poisson_ratio: Quantity<Dimensionless>,
}

impl Default for Rig {
    fn default() -> Self {
        Self {
            contact: ContactKind::BallOnDisc,
            radius: Quantity::from_si(9.5e-3),
            length: Quantity::from_si(10e-3),
            youngs_modulus: Quantity::from_si(210e9),
            poisson_ratio: Quantity::from_si(0.3),
        }
    }
}

impl Rig {
    /// Validated geometry: (contact geometry, reduced radius R′, reduced modulus E′).
    pub fn geometry(&self) -> Result<(ContactGeometry, f64, f64), Failure> {
        let (r, l) = (self.radius.si(), self.length.si());
        let (e, nu) = (self.youngs_modulus.si(), self.poisson_ratio.si());
        if !(r > 0.0) || !(l > 0.0) || !(e > 0.0) || !(0.0..0.5).contains(&nu) {
            return Err(Failure::Input(
                "--radius, --length and --youngs-modulus must be positive, 0 ≤ --poisson-ratio < 0.5".into(),
            ));
        }
        let geometry = match self.contact {
            ContactKind::BallOnDisc => ContactGeometry::Circular,
            ContactKind::Line => ContactGeometry::Line { length_m: l },
        };
        Ok((geometry, r, reduced_modulus(e, nu, e, nu)))
    }

    /// Refuses a normal load (given at `flag`) whose Hertz pressure on this contact is beyond
    /// any bearing material ([`MAX_CREDIBLE_PRESSURE_PA`]).
    pub fn check_load(&self, flag: &str, load: f64) -> Result<(), Failure> {
        let limit = self.load_for_max_pressure(MAX_CREDIBLE_PRESSURE_PA)?;
        if load <= limit {
            return Ok(());
        }
        Err(Failure::Input(format!(
            "{flag} {} N is implausible: above {} N, the load of a Hertz pressure of {} GPa on \
             this contact, beyond any bearing material (the elastic contact does not apply)",
            format_number(load),
            format_number(limit),
            MAX_CREDIBLE_PRESSURE_PA * 1e-9
        )))
    }

    /// Normal load giving the maximum Hertz pressure `p_max` on this contact.
    pub fn load_for_max_pressure(&self, p_max: f64) -> Result<f64, Failure> {
        let (geometry, r, e) = self.geometry()?;
        Ok(match geometry {
            ContactGeometry::Line { length_m } => line_load_for_max_pressure(p_max, length_m, e, r),
            _ => circular_load_for_max_pressure(p_max, r, e),
        })
    }
}
