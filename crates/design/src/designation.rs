//! ISO designations of single-row cylindrical roller bearings (ISO 15 dimension series, the
//! type letters of the catalogues): `NU2215`, `NU 215`, `NJ 310`, `N 1012`, `NUP2310`.

use crate::iso15::{self, BoundaryRow, DimensionSeries};

/// Which ring carries which ribs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RibArrangement {
    /// Two ribs on the outer ring, none on the inner ring.
    #[default]
    Nu,
    /// Two ribs on the outer ring, one on the inner ring.
    Nj,
    /// Two ribs on the outer ring, two on the inner ring (one a loose rib washer).
    Nup,
    /// Two ribs on the inner ring, none on the outer ring.
    N,
}

impl RibArrangement {
    pub fn letters(self) -> &'static str {
        match self {
            Self::Nu => "NU",
            Self::Nj => "NJ",
            Self::Nup => "NUP",
            Self::N => "N",
        }
    }

    /// The ring whose two ribs guide the rollers axially and whose rib rims guide the cage.
    pub fn outer_ribs(self) -> bool {
        self != Self::N
    }

    /// Ribs on the ring that does not guide: (left, right).
    pub fn other_ring_ribs(self) -> (bool, bool) {
        match self {
            Self::Nu | Self::N => (false, false),
            Self::Nj => (true, false),
            Self::Nup => (true, true),
        }
    }
}

/// A designation read: type letters, dimension series, bore code and the ISO 15 row.
#[derive(Clone, Debug, PartialEq)]
pub struct Designation {
    pub text: String,
    pub ribs: RibArrangement,
    pub series: DimensionSeries,
    pub bore_code: u32,
    pub row: BoundaryRow,
}

/// The tapered series that `rolldyn new` recognises in order to refuse them clearly.
const TAPERED_SERIES: [&str; 5] = ["302", "303", "320", "322", "323"];

/// Reads a designation; the reason it is none, saying what is understood, otherwise.
pub fn parse(text: &str) -> Result<Designation, String> {
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let compact = compact.to_ascii_uppercase();
    let letters: String = compact
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect();
    let rest = &compact[letters.len()..];
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    let suffix = &rest[digits.len()..];
    if letters.is_empty() && digits.len() == 5 && TAPERED_SERIES.contains(&&digits[..3]) {
        return Err(format!(
            "'{text}' is a tapered roller bearing (ISO 355 series {}): `rolldyn new` writes \
             single-row cylindrical bearings (kind \"cylindrical\"); the tapered model is the \
             double-row kind \"double-row-tapered\" (docs/model-format.md, \
             examples/tapered-cassette.toml), written by hand",
            &digits[..3]
        ));
    }
    let ribs = match letters.as_str() {
        "NU" => RibArrangement::Nu,
        "NJ" => RibArrangement::Nj,
        "NUP" => RibArrangement::Nup,
        "N" => RibArrangement::N,
        _ => {
            return Err(format!(
                "'{text}': type '{letters}' is not one of NU, NJ, NUP, N (single-row cylindrical \
                 roller bearings, e.g. NU2215, NJ 310)"
            ));
        }
    };
    if !suffix.is_empty() {
        return Err(format!(
            "'{text}': suffix '{suffix}' is not read (give the basic designation, e.g. NU2215, \
             and the catalogue's roller size and count with --roller-diameter, --roller-length, \
             --rollers; the clearance group with --clearance-group)"
        ));
    }
    if digits.len() < 3 || digits.len() > 4 {
        return Err(format!(
            "'{text}': expected the dimension series (10, 2, 22, 3, 23) and a two-digit bore \
             code after '{letters}', e.g. {letters}2215"
        ));
    }
    let (series_text, code_text) = digits.split_at(digits.len() - 2);
    let series = DimensionSeries::ALL
        .into_iter()
        .find(|s| s.designation() == series_text)
        .ok_or_else(|| {
            format!("'{text}': dimension series '{series_text}' is not one of 10, 2, 22, 3, 23")
        })?;
    let bore_code: u32 = code_text
        .parse()
        .map_err(|_| format!("'{text}': bad bore code"))?;
    let bore_mm = match bore_code {
        0 => 10.0,
        1 => 12.0,
        2 => 15.0,
        3 => 17.0,
        c => 5.0 * c as f64,
    };
    let row = iso15::boundary(series, bore_mm).ok_or_else(|| {
        let bores = iso15::tabulated_bores(series);
        format!(
            "'{text}': bore code {code_text} (d = {bore_mm} mm) has no row in series {} of the \
             tables (bores {}–{} mm, bore codes 04–40 where the series has them); give the \
             boundary form --bore --outside --width",
            series.designation(),
            bores[0],
            bores[bores.len() - 1]
        )
    })?;
    Ok(Designation {
        text: format!("{}{}{code_text}", letters, series.designation()),
        ribs,
        series,
        bore_code,
        row,
    })
}
