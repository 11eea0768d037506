//! Sizes of outputs: a byte count given on the command line (`2GB`, `500 MB`, `64KiB`) and the
//! estimate of how much disk a table of a number of values takes, so that a run can refuse an
//! output that would fill the disk before writing any of it.

use std::fmt;
use std::str::FromStr;

/// Disk taken by one value of a table written as CSV and Parquet: at most 24 characters in the
/// CSV (`-1.2345678901234567e-15,`) and 8 bytes plus its definition level in the Parquet file.
/// Real tables take less (short numbers, compression): the estimate errs on the large side.
pub const BYTES_PER_VALUE: f64 = 33.0;

/// Estimated disk taken by tables of `values` values in all ([`BYTES_PER_VALUE`]).
pub fn estimated_table_bytes(values: f64) -> ByteSize {
    ByteSize(values * BYTES_PER_VALUE)
}

/// A number of bytes.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct ByteSize(pub f64);

/// Decimal (`kB` … `TB`) and binary (`KiB` … `TiB`) multiples.
const UNITS: [(&str, f64); 10] = [
    ("B", 1.0),
    ("kB", 1e3),
    ("KB", 1e3),
    ("MB", 1e6),
    ("GB", 1e9),
    ("TB", 1e12),
    ("KiB", 1024.0),
    ("MiB", 1048576.0),
    ("GiB", 1073741824.0),
    ("TiB", 1099511627776.0),
];

impl FromStr for ByteSize {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let text = text.trim();
        let split = text
            .find(|c: char| c.is_ascii_alphabetic() && c != 'e')
            .unwrap_or(text.len());
        let (number, unit) = (text[..split].trim(), text[split..].trim());
        let scale = match unit {
            "" => 1.0,
            _ => UNITS
                .iter()
                .find(|(name, _)| *name == unit)
                .map(|(_, scale)| *scale)
                .ok_or_else(|| {
                    format!(
                        "'{text}': unknown unit '{unit}' (B, kB, MB, GB, TB, KiB, MiB, GiB, TiB)"
                    )
                })?,
        };
        match number.parse::<f64>() {
            Ok(n) if n >= 0.0 && n.is_finite() => Ok(ByteSize(n * scale)),
            _ => Err(format!("'{text}': expected a size such as 500MB or 20GB")),
        }
    }
}

impl fmt::Display for ByteSize {
    /// Three significant digits in the largest decimal unit that keeps the number ≥ 1 (whole
    /// bytes below 1 kB).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (unit, scale) = ["TB", "GB", "MB", "kB"]
            .iter()
            .zip([1e12, 1e9, 1e6, 1e3])
            .find(|(_, scale)| self.0 >= *scale)
            .map_or(("B", 1.0), |(unit, scale)| (*unit, scale));
        let n = self.0 / scale;
        let decimals = if n >= 100.0 || scale == 1.0 {
            0
        } else if n >= 10.0 {
            1
        } else {
            2
        };
        write!(f, "{n:.decimals$} {unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_and_print() {
        let parse = |t: &str| t.parse::<ByteSize>().unwrap().0;
        assert_eq!(parse("2GB"), 2e9);
        assert_eq!(parse("500 MB"), 5e8);
        assert_eq!(parse("1.5kB"), 1500.0);
        assert_eq!(parse("64KiB"), 65536.0);
        assert_eq!(parse("1e6"), 1e6);
        assert!("12 parsecs".parse::<ByteSize>().is_err());
        assert!("-1GB".parse::<ByteSize>().is_err());
        assert!("GB".parse::<ByteSize>().is_err());
        assert_eq!(ByteSize(2e9).to_string(), "2.00 GB");
        assert_eq!(ByteSize(123456.0).to_string(), "123 kB");
        assert_eq!(ByteSize(4.2e13).to_string(), "42.0 TB");
        assert_eq!(ByteSize(12.0).to_string(), "12 B");
        assert_eq!(estimated_table_bytes(1e6).0, 3.3e7);
    }
}
