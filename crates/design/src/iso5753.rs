//! Radial internal clearance of cylindrical roller bearings with a cylindrical bore, ISO 5753-1:2009
//! Table 4 (the groups C2, CN, C3, C4 by bore d; the same values are printed in the
//! manufacturers' catalogues, e.g. SKF *Rolling bearings*, "Radial internal clearance of
//! cylindrical roller bearings with a cylindrical bore").

/// A clearance group of ISO 5753-1.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ClearanceGroup {
    C2,
    #[default]
    CN,
    C3,
    C4,
}

impl ClearanceGroup {
    pub fn name(self) -> &'static str {
        match self {
            Self::C2 => "C2",
            Self::CN => "CN",
            Self::C3 => "C3",
            Self::C4 => "C4",
        }
    }
}

/// Rows: d over, d up to (mm), then min/max of C2, CN, C3, C4 (µm).
const TABLE_4: [[f64; 10]; 13] = [
    [0.0, 24.0, 0.0, 25.0, 20.0, 45.0, 35.0, 60.0, 50.0, 75.0],
    [24.0, 30.0, 0.0, 25.0, 20.0, 45.0, 35.0, 60.0, 50.0, 75.0],
    [30.0, 40.0, 5.0, 30.0, 25.0, 50.0, 45.0, 70.0, 60.0, 85.0],
    [40.0, 50.0, 5.0, 35.0, 30.0, 60.0, 50.0, 80.0, 70.0, 100.0],
    [50.0, 65.0, 10.0, 40.0, 40.0, 70.0, 60.0, 90.0, 80.0, 110.0],
    [65.0, 80.0, 10.0, 45.0, 40.0, 75.0, 65.0, 100.0, 90.0, 125.0],
    [
        80.0, 100.0, 15.0, 50.0, 50.0, 85.0, 75.0, 110.0, 105.0, 140.0,
    ],
    [
        100.0, 120.0, 15.0, 55.0, 50.0, 90.0, 85.0, 125.0, 125.0, 165.0,
    ],
    [
        120.0, 140.0, 15.0, 60.0, 60.0, 105.0, 100.0, 145.0, 145.0, 190.0,
    ],
    [
        140.0, 160.0, 20.0, 70.0, 70.0, 120.0, 115.0, 165.0, 165.0, 215.0,
    ],
    [
        160.0, 180.0, 25.0, 75.0, 75.0, 125.0, 120.0, 170.0, 170.0, 220.0,
    ],
    [
        180.0, 200.0, 35.0, 90.0, 90.0, 145.0, 140.0, 195.0, 195.0, 250.0,
    ],
    [
        200.0, 225.0, 45.0, 105.0, 105.0, 165.0, 160.0, 220.0, 220.0, 280.0,
    ],
];

/// The bores the table covers, mm (over 0 up to 225).
pub const BORE_RANGE_MM: [f64; 2] = [0.0, 225.0];

/// The group's clearance range [min, max] in µm for the bore `bore_mm` (over / up to and
/// including, as the table reads), or `None` outside the table.
pub fn radial_clearance_um(group: ClearanceGroup, bore_mm: f64) -> Option<[f64; 2]> {
    let row = TABLE_4.iter().find(|r| bore_mm > r[0] && bore_mm <= r[1])?;
    let column = 2 + 2 * group as usize;
    Some([row[column], row[column + 1]])
}
