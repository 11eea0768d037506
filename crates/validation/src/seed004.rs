//! Seed 004 (Klebanov, Petrov, Adeyanov 2019): roller of bearing 32206 on its inner raceway,
//! five generatrix profiles, Boussinesq / modified-Hartnett solver (SPEC §2.5–2.6, V-01, V-02).

use rolldyn_contact::boussinesq::BoussinesqOptions;
use rolldyn_contact::roller_raceway::{ContactReport, RollerRacewayContact, SliceLawChoice};

/// The five profiles of seed 004 Table 1 as example model files: (file, label, text).
pub const PROFILES: [(&str, &str, &str); 5] = [
    (
        "32206-straight.toml",
        "1 straight",
        include_str!("../../../examples/contact/32206-straight.toml"),
    ),
    (
        "32206-crowned-3.2um.toml",
        "2 crowned 3.2 µm",
        include_str!("../../../examples/contact/32206-crowned-3.2um.toml"),
    ),
    (
        "32206-crowned-6.5um.toml",
        "3 crowned 6.5 µm",
        include_str!("../../../examples/contact/32206-crowned-6.5um.toml"),
    ),
    (
        "32206-log-small.toml",
        "4 logarithmic k 0.000443 mm",
        include_str!("../../../examples/contact/32206-log-small.toml"),
    ),
    (
        "32206-log-large.toml",
        "5 logarithmic k 0.002217 mm",
        include_str!("../../../examples/contact/32206-log-large.toml"),
    ),
];

/// Index of the crowned 3.2 µm profile (the profile of Table 2).
pub const TABLE2_PROFILE: usize = 1;

/// Loads of the profile study (seed 004; "2234 N" in the text is 2334 N, F-09).
pub const LOADS_N: [f64; 3] = [583.0, 1167.0, 2334.0];
/// Skews of the profile study, arc-minutes.
pub const TILTS_ARCMIN: [f64; 3] = [0.0, 4.0, 8.0];

/// One row of seed 004 Table 2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Table2Row {
    pub cells_along: usize,
    pub cells_across: usize,
    pub cell_side_mm: f64,
    pub relative_time: f64,
    pub max_pressure_mpa: f64,
    pub mid_pressure_mpa: f64,
    pub approach_mm: f64,
}

const fn row(
    a: usize,
    b: usize,
    side: f64,
    t: f64,
    pmax: f64,
    pmid: f64,
    approach: f64,
) -> Table2Row {
    Table2Row {
        cells_along: a,
        cells_across: b,
        cell_side_mm: side,
        relative_time: t,
        max_pressure_mpa: pmax,
        mid_pressure_mpa: pmid,
        approach_mm: approach,
    }
}

/// Seed 004 Table 2 (SPEC V-01), stated for Q = 2334 N but reproducible at 1167 N (F-08).
pub const TABLE2: [Table2Row; 7] = [
    row(50, 1, 0.15, 1.0, 1446.0, 1271.0, 0.005957),
    row(100, 3, 0.075, 9.0, 1699.0, 1550.0, 0.006109),
    row(150, 3, 0.05, 114.0, 1645.0, 1493.0, 0.006093),
    row(200, 5, 0.0375, 594.0, 1648.0, 1465.0, 0.006072),
    row(250, 7, 0.03, 2137.0, 1671.0, 1483.0, 0.006103),
    row(300, 7, 0.025, 6404.0, 1638.0, 1465.0, 0.006084),
    row(350, 9, 0.0214, 14853.0, 1685.0, 1473.0, 0.006091),
];

/// The roller of profile `index` (into [`PROFILES`]) on the 32206 inner raceway, skewed by
/// `tilt` [rad].
pub fn contact(index: usize, tilt: f64) -> RollerRacewayContact {
    let (file, _, text) = PROFILES[index];
    let model = rolldyn_model::parse(text, file)
        .expect("example models are valid")
        .bearing;
    RollerRacewayContact::from_model(&model, true, tilt).expect("example geometry is valid")
}

/// Boussinesq solution of profile `index` with `nx × ny` square cells over the roller length.
pub fn solve(index: usize, tilt: f64, load: f64, nx: usize, ny: usize) -> ContactReport {
    contact(index, tilt)
        .boussinesq(load, nx, ny, None, BoussinesqOptions::default())
        .expect("seed 004 grids are valid")
}

/// V-01: the Table 2 grids on the crowned 3.2 µm profile at `load`.
pub fn grid_study(load: f64) -> Vec<(Table2Row, ContactReport)> {
    TABLE2
        .iter()
        .map(|r| {
            (
                *r,
                solve(TABLE2_PROFILE, 0.0, load, r.cells_along, r.cells_across),
            )
        })
        .collect()
}

/// One case of the profile study.
#[derive(Debug, Clone)]
pub struct ProfileCase {
    pub profile: usize,
    pub load_n: f64,
    pub tilt_arcmin: f64,
    pub report: ContactReport,
}

impl ProfileCase {
    /// Largest central-line pressure in the outer `fraction` of each half of the roller,
    /// divided by the pressure at the middle: > 1 means an edge peak. `None` when the middle
    /// of the roller is unloaded (large skew at small load).
    pub fn edge_ratio(&self, fraction: f64) -> Option<f64> {
        let half = self
            .report
            .central_line
            .iter()
            .fold(0.0f64, |m, p| m.max(p.0.abs()));
        let edge = self
            .report
            .central_line
            .iter()
            .filter(|p| p.0.abs() >= (1.0 - fraction) * half)
            .fold(0.0f64, |m, p| m.max(p.1));
        (self.report.mid_pressure_pa > 0.0).then(|| edge / self.report.mid_pressure_pa)
    }
}

/// V-02: every profile × load × tilt on an `nx × ny` grid of `width` [m] across.
pub fn profile_study(nx: usize, ny: usize, width: f64) -> Vec<ProfileCase> {
    let mut cases = Vec::new();
    for profile in 0..PROFILES.len() {
        for tilt_arcmin in TILTS_ARCMIN {
            let contact = contact(profile, tilt_arcmin * std::f64::consts::PI / 10_800.0);
            for load_n in LOADS_N {
                let report = contact
                    .boussinesq(load_n, nx, ny, Some(width), BoussinesqOptions::default())
                    .expect("seed 004 grids are valid");
                cases.push(ProfileCase {
                    profile,
                    load_n,
                    tilt_arcmin,
                    report,
                });
            }
        }
    }
    cases
}

/// Concentration factor K = p_max/p̄ against load at zero skew, per profile: `(Q, K)` rows.
pub fn concentration_vs_load(
    loads: &[f64],
    nx: usize,
    ny: usize,
    width: f64,
) -> Vec<Vec<(f64, f64)>> {
    (0..PROFILES.len())
        .map(|profile| {
            let contact = contact(profile, 0.0);
            loads
                .iter()
                .map(|&q| {
                    let r = contact
                        .boussinesq(q, nx, ny, Some(width), BoussinesqOptions::default())
                        .expect("valid grid");
                    (q, r.concentration_factor)
                })
                .collect()
        })
        .collect()
}

/// Load per unit length along the roller, q(x) = ∫p dy [N/m], from a Boussinesq report.
pub fn line_load(report: &ContactReport) -> Vec<(f64, f64)> {
    let Some(map) = &report.map else {
        return Vec::new();
    };
    let (x0, x1, y0, y1) = map.extent;
    let (dx, dy) = ((x1 - x0) / map.nx as f64, (y1 - y0) / map.ny as f64);
    (0..map.nx)
        .map(|i| {
            let q: f64 = (0..map.ny)
                .map(|j| map.pressure[j * map.nx + i])
                .sum::<f64>()
                * dy;
            (x0 + (i as f64 + 0.5) * dx, q)
        })
        .collect()
}

/// Slices against Boussinesq for one profile: both reports and both line loads.
pub struct SlicesVsBoussinesq {
    pub slices: ContactReport,
    pub boussinesq: ContactReport,
    /// Slice loads per unit length (x, Q_s/L_s) [N/m].
    pub slice_line_load: Vec<(f64, f64)>,
    pub boussinesq_line_load: Vec<(f64, f64)>,
}

/// Compares the slice model (ISO/TS 16281 laminae, 30 slices) with Boussinesq for `profile`.
pub fn slices_vs_boussinesq(
    profile: usize,
    load: f64,
    nx: usize,
    ny: usize,
    width: f64,
) -> SlicesVsBoussinesq {
    let contact = contact(profile, 0.0);
    let slices = contact
        .slices(load, SliceLawChoice::Iso)
        .expect("slice model solves");
    let boussinesq = contact
        .boussinesq(load, nx, ny, Some(width), BoussinesqOptions::default())
        .expect("valid grid");
    let slice_line_load = slices_line_load(&contact, &slices);
    let boussinesq_line_load = line_load(&boussinesq);
    SlicesVsBoussinesq {
        slices,
        boussinesq,
        slice_line_load,
        boussinesq_line_load,
    }
}

/// Per-slice load per length, inverting the slice report's Hertz pressure p = √(q E′/(2πR′)).
fn slices_line_load(contact: &RollerRacewayContact, slices: &ContactReport) -> Vec<(f64, f64)> {
    let k = 2.0 * std::f64::consts::PI * contact.reduced_radius / contact.reduced_modulus;
    slices
        .central_line
        .iter()
        .map(|&(x, p)| (x, p * p * k))
        .collect()
}
