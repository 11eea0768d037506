//! Physical quantities with engineering units at the boundary, SI inside.
//!
//! Model files and command-line flags accept values such as `"165 mm"`, `"15 µm"`, `"6371 rpm"`,
//! `"4 arcmin"`, `"100 °C"`, `"1167 N"`, `"1 GPa"`, `"2.5 m/s"`, `"0.024 Pa s"`. A plain number
//! (TOML number or a string without unit) is taken as SI (m, N, Pa, rad, rad/s, K, …).
//! The value is converted once, on parsing, and the rest of rolldyn works with `f64` in SI.
//!
//! ```
//! use rolldyn_units::{Quantity, Length, Temperature};
//! let d: Quantity<Length> = "165 mm".parse().unwrap();
//! assert!((d.si() - 0.165).abs() < 1e-15);
//! let t: Quantity<Temperature> = "100 C".parse().unwrap();
//! assert!((t.si() - 373.15).abs() < 1e-12);
//! assert!("1167 N".parse::<Quantity<Length>>().is_err());
//! ```

mod dimension;
mod quantity;
mod range;
mod unit_table;

pub use dimension::markers::*;
pub use dimension::{Dim, Dimension};
pub use quantity::{Quantity, UnitError};
pub use range::QuantityRange;

/// A number for a message, short whatever its size: plain with up to 6 significant digits
/// from 10⁻³ to 10⁶ (`1167`, `0.0125`), scientific beyond (`1.0000e300`), `NaN`/`inf` as is.
pub fn format_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return v.to_string();
    }
    if (1e-3..1e6).contains(&v.abs()) {
        let text = format!(
            "{:.*}",
            (5 - v.abs().log10().floor() as i32).max(0) as usize,
            v
        );
        if text.contains('.') {
            return text.trim_end_matches('0').trim_end_matches('.').to_string();
        }
        return text;
    }
    format!("{v:.4e}")
}

/// rpm → rad/s.
pub const RPM: f64 = std::f64::consts::PI / 30.0;
/// One arc-minute in rad.
pub const ARCMIN: f64 = std::f64::consts::PI / 10_800.0;
/// 0 °C in kelvin.
pub const CELSIUS_ZERO: f64 = 273.15;

#[cfg(test)]
mod tests {
    use super::format_number;

    #[test]
    fn numbers_in_messages_stay_short() {
        assert_eq!(format_number(1167.0), "1167");
        assert_eq!(format_number(0.0125), "0.0125");
        assert_eq!(format_number(2.5), "2.5");
        assert_eq!(format_number(1e300), "1.0000e300");
        assert_eq!(format_number(-3.2e-9), "-3.2000e-9");
        assert_eq!(format_number(0.0), "0");
    }
}
