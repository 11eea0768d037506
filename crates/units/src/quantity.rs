//! [`Quantity`]: an SI value whose dimension is checked when it is parsed.

use crate::dimension::{Dim, Dimension};
use crate::unit_table;
use serde::de::{self, Deserialize, Deserializer, Visitor};
use std::fmt;
use std::marker::PhantomData;
use std::str::FromStr;

/// A value in SI units with a compile-time dimension `D`.
#[derive(Clone, Copy, PartialEq, PartialOrd)]
pub struct Quantity<D: Dim> {
    si: f64,
    dimension: PhantomData<D>,
}

/// Why a quantity could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UnitError {
    #[error("empty value; expected {expected} such as '{example}'")]
    Empty {
        expected: Dimension,
        example: String,
    },
    #[error("'{text}' does not start with a number")]
    BadNumber { text: String },
    #[error("'{value}' is not a finite number")]
    NotFinite { value: String },
    #[error("unknown unit '{unit}' for {expected} (accepted: {accepted})")]
    UnknownUnit {
        unit: String,
        expected: Dimension,
        accepted: &'static str,
    },
    #[error(
        "'{text}' has no unit: give {expected} with its unit, e.g. '{text} {example}' \
         (accepted units: {accepted}; a bare number is only SI in a file or from Python)"
    )]
    MissingUnit {
        text: String,
        expected: Dimension,
        example: &'static str,
        accepted: &'static str,
    },
    #[error("'{text}' is below absolute zero (0 K = -273.15 °C)")]
    BelowAbsoluteZero { text: String },
    #[error("'{text}': {reason}")]
    BadRange { text: String, reason: &'static str },
    #[error("'{text}' is {got}, but {expected} is expected (accepted units: {accepted})")]
    WrongDimension {
        text: String,
        got: Dimension,
        expected: Dimension,
        accepted: &'static str,
    },
}

impl<D: Dim> Quantity<D> {
    /// Wraps a value that is already in SI units.
    pub const fn from_si(si: f64) -> Self {
        Self {
            si,
            dimension: PhantomData,
        }
    }

    /// The value in SI units (m, N, Pa, rad, rad/s, K, …).
    pub const fn si(self) -> f64 {
        self.si
    }

    /// The dimension of this quantity type.
    pub fn dimension() -> Dimension {
        D::DIMENSION
    }

    /// Parses `"<number> <unit>"`. A text must carry its unit (only a dimensionless value or a
    /// zero other than a temperature may be bare): a bare number is SI only as a number (TOML,
    /// JSON, Python float), never as text.
    pub fn parse(text: &str) -> Result<Self, UnitError> {
        parse_si(text, D::DIMENSION).map(Self::from_si)
    }
}

/// Parses `text` as a value of dimension `expected` and returns it in SI units.
pub fn parse_si(text: &str, expected: Dimension) -> Result<f64, UnitError> {
    let (scaled, offset) = parse_scaled(text, expected)?;
    let si = scaled + offset;
    if expected == Dimension::Temperature && si < 0.0 {
        return Err(UnitError::BelowAbsoluteZero {
            text: text.trim().to_string(),
        });
    }
    Ok(si)
}

/// Parses `text` as a difference of two values of dimension `expected` (a step of a range:
/// `10C` is 10 K) and returns it in SI units.
pub(crate) fn parse_difference_si(text: &str, expected: Dimension) -> Result<f64, UnitError> {
    parse_scaled(text, expected).map(|(scaled, _)| scaled)
}

/// The number of `text` times the scale of its unit, and the offset of that unit (°C), both SI.
fn parse_scaled(text: &str, expected: Dimension) -> Result<(f64, f64), UnitError> {
    let text = text.trim();
    if text.is_empty() {
        return Err(UnitError::Empty {
            expected,
            example: format!("1 {}", expected.si_symbol()),
        });
    }
    let split = number_prefix_len(text);
    let (number, unit) = text.split_at(split);
    let value: f64 = number.parse().map_err(|_| UnitError::BadNumber {
        text: text.to_string(),
    })?;
    if !value.is_finite() {
        return Err(UnitError::NotFinite {
            value: text.to_string(),
        });
    }
    let unit = unit.trim();
    if unit.is_empty() {
        // Zero is zero in every unit but a temperature's.
        if expected == Dimension::Dimensionless
            || (value == 0.0 && expected != Dimension::Temperature)
        {
            return Ok((value, 0.0));
        }
        return Err(UnitError::MissingUnit {
            text: text.to_string(),
            expected,
            example: expected.example_unit(),
            accepted: expected.examples(),
        });
    }
    let found = unit_table::lookup(unit, expected).ok_or_else(|| UnitError::UnknownUnit {
        unit: unit.to_string(),
        expected,
        accepted: expected.examples(),
    })?;
    if found.dimension != expected {
        return Err(UnitError::WrongDimension {
            text: text.to_string(),
            got: found.dimension,
            expected,
            accepted: expected.examples(),
        });
    }
    Ok((value * found.scale, found.offset))
}

/// Length of the leading decimal number (sign, digits, point, exponent) in `text`.
fn number_prefix_len(text: &str) -> usize {
    let bytes = text.as_bytes();
    let mut i = 0;
    if i < bytes.len() && (bytes[i] == b'+' || bytes[i] == b'-') {
        i += 1;
    }
    while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.') {
        i += 1;
    }
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        let mut j = i + 1;
        if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
            j += 1;
        }
        if j < bytes.len() && bytes[j].is_ascii_digit() {
            while j < bytes.len() && bytes[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    i
}

impl<D: Dim> FromStr for Quantity<D> {
    type Err = UnitError;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Self::parse(text)
    }
}

impl<D: Dim> fmt::Debug for Quantity<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.si, D::DIMENSION.si_symbol())
    }
}

impl<D: Dim> fmt::Display for Quantity<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.si, D::DIMENSION.si_symbol())
    }
}

impl<D: Dim> serde::Serialize for Quantity<D> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_f64(self.si)
    }
}

impl<'de, D: Dim> Deserialize<'de> for Quantity<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        struct QuantityVisitor<D>(PhantomData<D>);
        impl<D: Dim> Visitor<'_> for QuantityVisitor<D> {
            type Value = Quantity<D>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(
                    f,
                    "{} as a number in {} or a string with unit ({})",
                    D::DIMENSION.name(),
                    D::DIMENSION.si_symbol(),
                    D::DIMENSION.examples()
                )
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                if v.is_finite() {
                    Ok(Quantity::from_si(v))
                } else {
                    Err(E::custom(UnitError::NotFinite {
                        value: v.to_string(),
                    }))
                }
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(Quantity::from_si(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(Quantity::from_si(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Quantity::parse(v).map_err(E::custom)
            }
        }
        deserializer.deserialize_any(QuantityVisitor(PhantomData))
    }
}
