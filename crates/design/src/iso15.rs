//! ISO 15 boundary dimensions of radial bearings (d, D, B, r_s min) for the dimension series of
//! single-row cylindrical roller bearings: 10 (ISO 15 Table 4, diameter series 0), 02 and 22
//! (Table 6, diameter series 2) and 03 and 23 (Table 7, diameter series 3), bores 20–200 mm
//! (bore codes 04–40). The rows are the ones the manufacturers' catalogues list for NU 10, NU 2,
//! NU 22, NU 3 and NU 23 bearings (e.g. SKF *Rolling bearings* catalogue, cylindrical roller
//! bearings tables), which follow ISO 15; the chamfer r_s min is ISO 15's (maximum values in
//! ISO 582).

/// An ISO 15 dimension series of single-row cylindrical roller bearings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DimensionSeries {
    /// Width series 1, diameter series 0 (NU 10..).
    S10,
    /// Width series 0, diameter series 2 (NU 2..).
    S02,
    /// Width series 2, diameter series 2 (NU 22..).
    S22,
    /// Width series 0, diameter series 3 (NU 3..).
    S03,
    /// Width series 2, diameter series 3 (NU 23..).
    S23,
}

impl DimensionSeries {
    /// The series as a designation writes it ("10", "2", "22", "3", "23").
    pub fn designation(self) -> &'static str {
        match self {
            Self::S10 => "10",
            Self::S02 => "2",
            Self::S22 => "22",
            Self::S03 => "3",
            Self::S23 => "23",
        }
    }

    /// The ISO 15 table the series' rows come from.
    pub fn table(self) -> &'static str {
        match self {
            Self::S10 => "ISO 15:2017 Table 4 (diameter series 0), dimension series 10",
            Self::S02 => "ISO 15:2017 Table 6 (diameter series 2), dimension series 02",
            Self::S22 => "ISO 15:2017 Table 6 (diameter series 2), dimension series 22",
            Self::S03 => "ISO 15:2017 Table 7 (diameter series 3), dimension series 03",
            Self::S23 => "ISO 15:2017 Table 7 (diameter series 3), dimension series 23",
        }
    }

    /// Every series, in the order of the tables.
    pub const ALL: [Self; 5] = [Self::S10, Self::S02, Self::S22, Self::S03, Self::S23];
}

/// Boundary dimensions of one bearing, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundaryRow {
    pub bore_mm: f64,
    pub outside_mm: f64,
    pub width_mm: f64,
    pub chamfer_min_mm: f64,
}

/// Diameter series 0: d, D, r_s min; width series 1 gives B.
/// Columns: d, D, B (dimension series 10), r_s min.
const DIAMETER_SERIES_0: [[f64; 4]; 28] = [
    [20.0, 42.0, 12.0, 0.6],
    [25.0, 47.0, 12.0, 0.6],
    [30.0, 55.0, 13.0, 1.0],
    [35.0, 62.0, 14.0, 1.0],
    [40.0, 68.0, 15.0, 1.0],
    [45.0, 75.0, 16.0, 1.0],
    [50.0, 80.0, 16.0, 1.0],
    [55.0, 90.0, 18.0, 1.1],
    [60.0, 95.0, 18.0, 1.1],
    [65.0, 100.0, 18.0, 1.1],
    [70.0, 110.0, 20.0, 1.1],
    [75.0, 115.0, 20.0, 1.1],
    [80.0, 125.0, 22.0, 1.1],
    [85.0, 130.0, 22.0, 1.1],
    [90.0, 140.0, 24.0, 1.5],
    [95.0, 145.0, 24.0, 1.5],
    [100.0, 150.0, 24.0, 1.5],
    [105.0, 160.0, 26.0, 2.0],
    [110.0, 170.0, 28.0, 2.0],
    [120.0, 180.0, 28.0, 2.0],
    [130.0, 200.0, 33.0, 2.0],
    [140.0, 210.0, 33.0, 2.0],
    [150.0, 225.0, 35.0, 2.1],
    [160.0, 240.0, 38.0, 2.1],
    [170.0, 260.0, 42.0, 2.1],
    [180.0, 280.0, 46.0, 2.1],
    [190.0, 290.0, 46.0, 2.1],
    [200.0, 310.0, 51.0, 2.1],
];

/// Diameter series 2. Columns: d, D, B (02), B (22), r_s min.
const DIAMETER_SERIES_2: [[f64; 5]; 28] = [
    [20.0, 47.0, 14.0, 18.0, 1.0],
    [25.0, 52.0, 15.0, 18.0, 1.0],
    [30.0, 62.0, 16.0, 20.0, 1.0],
    [35.0, 72.0, 17.0, 23.0, 1.1],
    [40.0, 80.0, 18.0, 23.0, 1.1],
    [45.0, 85.0, 19.0, 23.0, 1.1],
    [50.0, 90.0, 20.0, 23.0, 1.1],
    [55.0, 100.0, 21.0, 25.0, 1.5],
    [60.0, 110.0, 22.0, 28.0, 1.5],
    [65.0, 120.0, 23.0, 31.0, 1.5],
    [70.0, 125.0, 24.0, 31.0, 1.5],
    [75.0, 130.0, 25.0, 31.0, 1.5],
    [80.0, 140.0, 26.0, 33.0, 2.0],
    [85.0, 150.0, 28.0, 36.0, 2.0],
    [90.0, 160.0, 30.0, 40.0, 2.0],
    [95.0, 170.0, 32.0, 43.0, 2.1],
    [100.0, 180.0, 34.0, 46.0, 2.1],
    [105.0, 190.0, 36.0, 50.0, 2.1],
    [110.0, 200.0, 38.0, 53.0, 2.1],
    [120.0, 215.0, 40.0, 58.0, 2.1],
    [130.0, 230.0, 40.0, 64.0, 3.0],
    [140.0, 250.0, 42.0, 68.0, 3.0],
    [150.0, 270.0, 45.0, 73.0, 3.0],
    [160.0, 290.0, 48.0, 80.0, 3.0],
    [170.0, 310.0, 52.0, 86.0, 4.0],
    [180.0, 320.0, 52.0, 86.0, 4.0],
    [190.0, 340.0, 55.0, 92.0, 4.0],
    [200.0, 360.0, 58.0, 98.0, 4.0],
];

/// Diameter series 3. Columns: d, D, B (03), B (23), r_s min.
const DIAMETER_SERIES_3: [[f64; 5]; 28] = [
    [20.0, 52.0, 15.0, 21.0, 1.1],
    [25.0, 62.0, 17.0, 24.0, 1.1],
    [30.0, 72.0, 19.0, 27.0, 1.1],
    [35.0, 80.0, 21.0, 31.0, 1.5],
    [40.0, 90.0, 23.0, 33.0, 1.5],
    [45.0, 100.0, 25.0, 36.0, 1.5],
    [50.0, 110.0, 27.0, 40.0, 2.0],
    [55.0, 120.0, 29.0, 43.0, 2.0],
    [60.0, 130.0, 31.0, 46.0, 2.1],
    [65.0, 140.0, 33.0, 48.0, 2.1],
    [70.0, 150.0, 35.0, 51.0, 2.1],
    [75.0, 160.0, 37.0, 55.0, 2.1],
    [80.0, 170.0, 39.0, 58.0, 2.1],
    [85.0, 180.0, 41.0, 60.0, 3.0],
    [90.0, 190.0, 43.0, 64.0, 3.0],
    [95.0, 200.0, 45.0, 67.0, 3.0],
    [100.0, 215.0, 47.0, 73.0, 3.0],
    [105.0, 225.0, 49.0, 77.0, 3.0],
    [110.0, 240.0, 50.0, 80.0, 3.0],
    [120.0, 260.0, 55.0, 86.0, 3.0],
    [130.0, 280.0, 58.0, 93.0, 4.0],
    [140.0, 300.0, 62.0, 102.0, 4.0],
    [150.0, 320.0, 65.0, 108.0, 4.0],
    [160.0, 340.0, 68.0, 114.0, 4.0],
    [170.0, 360.0, 72.0, 120.0, 4.0],
    [180.0, 380.0, 75.0, 126.0, 4.0],
    [190.0, 400.0, 78.0, 132.0, 5.0],
    [200.0, 420.0, 80.0, 138.0, 5.0],
];

/// The ISO 15 row of `series` for the bore `bore_mm`, if the series has one.
pub fn boundary(series: DimensionSeries, bore_mm: f64) -> Option<BoundaryRow> {
    let matches = |d: f64| (d - bore_mm).abs() < 1e-9;
    let row = |d: f64, outside: f64, width: f64, chamfer: f64| BoundaryRow {
        bore_mm: d,
        outside_mm: outside,
        width_mm: width,
        chamfer_min_mm: chamfer,
    };
    match series {
        DimensionSeries::S10 => DIAMETER_SERIES_0
            .iter()
            .find(|r| matches(r[0]))
            .map(|r| row(r[0], r[1], r[2], r[3])),
        DimensionSeries::S02 | DimensionSeries::S22 => {
            DIAMETER_SERIES_2.iter().find(|r| matches(r[0])).map(|r| {
                let width = if series == DimensionSeries::S02 {
                    r[2]
                } else {
                    r[3]
                };
                row(r[0], r[1], width, r[4])
            })
        }
        DimensionSeries::S03 | DimensionSeries::S23 => {
            DIAMETER_SERIES_3.iter().find(|r| matches(r[0])).map(|r| {
                let width = if series == DimensionSeries::S03 {
                    r[2]
                } else {
                    r[3]
                };
                row(r[0], r[1], width, r[4])
            })
        }
    }
}

/// The bores the tables hold, mm.
pub fn tabulated_bores(series: DimensionSeries) -> Vec<f64> {
    match series {
        DimensionSeries::S10 => DIAMETER_SERIES_0.iter().map(|r| r[0]).collect(),
        DimensionSeries::S02 | DimensionSeries::S22 => {
            DIAMETER_SERIES_2.iter().map(|r| r[0]).collect()
        }
        DimensionSeries::S03 | DimensionSeries::S23 => {
            DIAMETER_SERIES_3.iter().map(|r| r[0]).collect()
        }
    }
}

/// The tabulated row (any series) nearest to d × D × B, with its series: where a boundary form
/// gives no chamfer, its r_s min is taken from here.
pub fn nearest(bore_mm: f64, outside_mm: f64, width_mm: f64) -> (DimensionSeries, BoundaryRow) {
    let distance = |r: &BoundaryRow| {
        (r.bore_mm - bore_mm).abs()
            + (r.outside_mm - outside_mm).abs()
            + (r.width_mm - width_mm).abs()
    };
    DimensionSeries::ALL
        .iter()
        .flat_map(|&s| {
            tabulated_bores(s)
                .into_iter()
                .filter_map(move |d| boundary(s, d).map(|r| (s, r)))
        })
        .min_by(|a, b| distance(&a.1).total_cmp(&distance(&b.1)))
        .expect("the tables are not empty")
}
