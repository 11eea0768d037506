//! ISO 281:2007 — basic dynamic load rating, equivalent dynamic load, basic and modified
//! rating life of radial roller bearings. The standard writes its equations in N and mm (and
//! r/min, mm²/s); the functions take and return SI and convert inside.

use crate::RatingError;
use crate::geometry::RollerBearingGeometry;
use rolldyn_numerics::table::interpolate_held;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Rating factor b_m of cylindrical and tapered roller bearings (ISO 281:2007 Table 1:
/// contemporary, commonly used high-quality hardened bearing steel, good manufacturing).
pub const RATING_FACTOR_ROLLER: f64 = 1.1;

/// Life exponent p of roller bearings (ISO 281:2007 §7.3, eq. (9)).
pub const LIFE_EXPONENT_ROLLER: f64 = 10.0 / 3.0;

/// Largest life modification factor a_ISO (ISO 281:2007 §9.3.2: "a_ISO ≤ 50").
pub const A_ISO_MAX: f64 = 50.0;

/// ISO 281:2007 Table 7: factor f_c of radial roller bearings against D_we cos α / D_pw.
const FC_TABLE: [(f64, f64); 30] = [
    (0.01, 52.1),
    (0.02, 60.8),
    (0.03, 66.5),
    (0.04, 70.7),
    (0.05, 74.1),
    (0.06, 76.9),
    (0.07, 79.2),
    (0.08, 81.2),
    (0.09, 82.8),
    (0.10, 84.2),
    (0.11, 85.4),
    (0.12, 86.4),
    (0.13, 87.1),
    (0.14, 87.7),
    (0.15, 88.2),
    (0.16, 88.5),
    (0.17, 88.7),
    (0.18, 88.8),
    (0.19, 88.8),
    (0.20, 88.7),
    (0.21, 88.5),
    (0.22, 88.2),
    (0.23, 87.9),
    (0.24, 87.5),
    (0.25, 87.0),
    (0.26, 86.4),
    (0.27, 85.8),
    (0.28, 85.2),
    (0.29, 84.5),
    (0.30, 83.8),
];

/// f_c of ISO 281:2007 Table 7 at γ = D_we cos α / D_pw, linearly interpolated between the
/// tabulated values as the table's footnote prescribes; γ outside 0.01…0.30 is refused.
pub fn geometry_factor(gamma: f64) -> Result<f64, RatingError> {
    let (lo, hi) = (FC_TABLE[0].0, FC_TABLE[FC_TABLE.len() - 1].0);
    if !(lo..=hi).contains(&gamma) {
        return Err(RatingError::OutOfRange(format!(
            "D_we cos α / D_pw = {gamma:.4} outside ISO 281 Table 7 ({lo}…{hi})"
        )));
    }
    Ok(interpolate_held(&FC_TABLE, gamma))
}

/// Basic dynamic radial load rating of a radial roller bearing, ISO 281:2007 §7.1.1 eq. (7):
/// C_r = b_m f_c (i L_we cos α)^{7/9} Z^{3/4} D_we^{29/27} (N, mm) [N].
pub fn dynamic_radial_rating(g: &RollerBearingGeometry) -> Result<f64, RatingError> {
    g.validate()?;
    let fc = geometry_factor(g.gamma())?;
    let (lwe, dwe) = (g.effective_length_m * 1e3, g.roller_diameter_m * 1e3);
    let i = g.rows as f64;
    Ok(RATING_FACTOR_ROLLER
        * fc
        * (i * lwe * g.contact_angle_rad.cos()).powf(7.0 / 9.0)
        * (g.rollers_per_row as f64).powf(0.75)
        * dwe.powf(29.0 / 27.0))
}

/// The equivalent dynamic radial load and the factors it was formed with.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EquivalentLoad {
    /// P_r = X F_r + Y F_a [N].
    pub load_n: f64,
    pub x: f64,
    pub y: f64,
    /// The limit e of F_a/F_r (`None` for α = 0, where the axial load does not enter).
    pub e: Option<f64>,
}

/// Equivalent dynamic radial load of a radial roller bearing, ISO 281:2007 §7.2 eq. (8) with
/// Table 8: α = 0 → P_r = F_r (a cylindrical bearing's rating covers radial load only); α ≠ 0
/// → e = 1.5 tan α and, single row, X = 1, Y = 0 for F_a/F_r ≤ e, else X = 0.4, Y = 0.4 cot α;
/// double row, X = 1, Y = 0.45 cot α for F_a/F_r ≤ e, else X = 0.67, Y = 0.67 cot α.
pub fn equivalent_dynamic_load(
    radial_n: f64,
    axial_n: f64,
    contact_angle_rad: f64,
    rows: usize,
) -> EquivalentLoad {
    let (fr, fa) = (radial_n.abs(), axial_n.abs());
    if contact_angle_rad == 0.0 {
        return EquivalentLoad {
            load_n: fr,
            x: 1.0,
            y: 0.0,
            e: None,
        };
    }
    let e = 1.5 * contact_angle_rad.tan();
    let cot = 1.0 / contact_angle_rad.tan();
    let within = fa <= e * fr;
    let (x, y) = match (rows > 1, within) {
        (false, true) => (1.0, 0.0),
        (false, false) => (0.4, 0.4 * cot),
        (true, true) => (1.0, 0.45 * cot),
        (true, false) => (0.67, 0.67 * cot),
    };
    EquivalentLoad {
        load_n: x * fr + y * fa,
        x,
        y,
        e: Some(e),
    }
}

/// Basic rating life L10 = (C/P)^{10/3} of a roller bearing, ISO 281:2007 §7.3 eq. (9), in
/// revolutions (the standard's unit is 10⁶ revolutions); infinite without load.
pub fn basic_rating_life(rating_n: f64, load_n: f64) -> f64 {
    if load_n <= 0.0 {
        return f64::INFINITY;
    }
    1e6 * (rating_n / load_n).powf(LIFE_EXPONENT_ROLLER)
}

/// A life in revolutions as operating hours at `speed_rad_s` (ISO 281:2007 §7.3: L_10h =
/// 10⁶ L_10 / (60 n)); infinite at rest.
pub fn hours(revolutions: f64, speed_rad_s: f64) -> f64 {
    let rev_per_s = speed_rad_s.abs() / (2.0 * PI);
    if rev_per_s == 0.0 {
        return f64::INFINITY;
    }
    revolutions / rev_per_s / 3600.0
}

/// ISO 281:2007 Table 12: reliability [%] and life modification factor a1.
const RELIABILITY_TABLE: [(f64, f64); 14] = [
    (90.0, 1.0),
    (95.0, 0.64),
    (96.0, 0.55),
    (97.0, 0.47),
    (98.0, 0.37),
    (99.0, 0.25),
    (99.2, 0.22),
    (99.4, 0.19),
    (99.6, 0.16),
    (99.8, 0.12),
    (99.9, 0.093),
    (99.92, 0.087),
    (99.94, 0.080),
    (99.95, 0.077),
];

/// Life modification factor for reliability a1, ISO 281:2007 §9.2 Table 12. The standard
/// tabulates it at the listed reliabilities only; any other value is refused.
pub fn reliability_factor(reliability_percent: f64) -> Result<f64, RatingError> {
    RELIABILITY_TABLE
        .iter()
        .find(|(r, _)| (r - reliability_percent).abs() < 1e-9)
        .map(|(_, a1)| *a1)
        .ok_or_else(|| {
            let listed: Vec<String> = RELIABILITY_TABLE
                .iter()
                .map(|(r, _)| r.to_string())
                .collect();
            RatingError::OutOfRange(format!(
                "reliability {reliability_percent} % is not in ISO 281 Table 12 ({} %)",
                listed.join(", ")
            ))
        })
}

/// Reference kinematic viscosity ν1 for adequate lubrication, ISO 281:2007 §9.3.3 (the
/// equations of its Fig. 13): ν1 = 45 000 n^{−0.83} D_pw^{−0.5} for n < 1 000 r/min,
/// ν1 = 4 500 n^{−0.5} D_pw^{−0.5} for n ≥ 1 000 r/min (mm²/s, r/min, mm) [m²/s].
/// `speed_rad_s` is the speed of the rotating ring relative to the other.
pub fn reference_viscosity(speed_rad_s: f64, pitch_diameter_m: f64) -> Result<f64, RatingError> {
    let n = speed_rad_s.abs() * 30.0 / PI;
    if !(n > 0.0) {
        return Err(RatingError::OutOfRange(
            "ν1 (ISO 281 §9.3.3) needs a rotating ring: the speed is 0".into(),
        ));
    }
    let dpw = pitch_diameter_m * 1e3;
    let nu1_mm2_s = if n < 1000.0 {
        45_000.0 * n.powf(-0.83) / dpw.sqrt()
    } else {
        4_500.0 / (n.sqrt() * dpw.sqrt())
    };
    Ok(nu1_mm2_s * 1e-6)
}

/// Contamination levels of ISO 281:2007 Table 13.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContaminationLevel {
    /// Particle size of the order of the lubricant film thickness; laboratory conditions.
    ExtremeCleanliness,
    /// Oil filtered through an extremely fine filter; typical of greased-for-life sealed bearings.
    HighCleanliness,
    /// Oil filtered through a fine filter; typical of greased-for-life shielded bearings.
    NormalCleanliness,
    /// Slight contamination in the lubricant.
    SlightContamination,
    /// Typical contamination: bearings without integral seals, coarse filtering, wear particles.
    TypicalContamination,
    /// Bearing environment heavily contaminated, insufficient sealing.
    SevereContamination,
    /// Very severe contamination.
    VerySevereContamination,
}

impl ContaminationLevel {
    /// Every level, cleanest first.
    pub const ALL: [Self; 7] = [
        Self::ExtremeCleanliness,
        Self::HighCleanliness,
        Self::NormalCleanliness,
        Self::SlightContamination,
        Self::TypicalContamination,
        Self::SevereContamination,
        Self::VerySevereContamination,
    ];

    /// The level's name as written in a request (`normal-cleanliness`).
    pub fn name(self) -> &'static str {
        match self {
            Self::ExtremeCleanliness => "extreme-cleanliness",
            Self::HighCleanliness => "high-cleanliness",
            Self::NormalCleanliness => "normal-cleanliness",
            Self::SlightContamination => "slight-contamination",
            Self::TypicalContamination => "typical-contamination",
            Self::SevereContamination => "severe-contamination",
            Self::VerySevereContamination => "very-severe-contamination",
        }
    }

    /// The range (lowest, highest) of e_C that ISO 281:2007 Table 13 gives for the level, in
    /// its column for D_pw < 100 mm or D_pw ≥ 100 mm.
    pub fn factor_range(self, pitch_diameter_m: f64) -> (f64, f64) {
        let small = pitch_diameter_m < 0.1;
        match (self, small) {
            (Self::ExtremeCleanliness, _) => (1.0, 1.0),
            (Self::HighCleanliness, true) => (0.6, 0.8),
            (Self::HighCleanliness, false) => (0.8, 0.9),
            (Self::NormalCleanliness, true) => (0.5, 0.6),
            (Self::NormalCleanliness, false) => (0.6, 0.8),
            (Self::SlightContamination, true) => (0.3, 0.5),
            (Self::SlightContamination, false) => (0.4, 0.6),
            (Self::TypicalContamination, true) => (0.1, 0.3),
            (Self::TypicalContamination, false) => (0.2, 0.4),
            (Self::SevereContamination, _) => (0.0, 0.1),
            (Self::VerySevereContamination, _) => (0.0, 0.0),
        }
    }
}

impl std::str::FromStr for ContaminationLevel {
    type Err = String;
    /// A level by its name (`normal-cleanliness`).
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|l| l.name() == text.trim())
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|l| l.name()).collect();
                format!(
                    "'{text}' is no ISO 281 Table 13 level ({})",
                    names.join(", ")
                )
            })
    }
}

/// Contamination factor e_C of a level: the low (conservative) end of its ISO 281:2007
/// Table 13 range. The table gives ranges, to be narrowed by experience; the low end is the
/// value that does not overstate the life.
pub fn contamination_factor(level: ContaminationLevel, pitch_diameter_m: f64) -> f64 {
    level.factor_range(pitch_diameter_m).0
}

/// Fatigue load limit C_u of a roller bearing by the simplified method of ISO 281:2007
/// Annex B (as in ISO/TR 1281-2): C_u = C0/8.2 for D_pw ≤ 100 mm, C_u = C0/8.2 (100/D_pw)^0.3
/// above [N].
pub fn fatigue_load_limit(static_rating_n: f64, pitch_diameter_m: f64) -> f64 {
    let dpw = pitch_diameter_m * 1e3;
    let size = if dpw > 100.0 {
        (100.0 / dpw).powf(0.3)
    } else {
        1.0
    };
    static_rating_n / 8.2 * size
}

/// The life modification factor and how it was bounded.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LifeModification {
    /// a_ISO.
    pub a_iso: f64,
    /// κ used in the equation (κ > 4 is taken as 4, ISO 281:2007 §9.3.2).
    pub kappa_used: f64,
    /// a_ISO reached the cap 50.
    pub capped: bool,
}

/// Life modification factor a_ISO of radial roller bearings, ISO 281:2007 §9.3.2 (the
/// equations of its figure for radial roller bearings), x = e_C C_u / P:
/// a_ISO = 0.1 [1 − (1.5859 − 1.3993 κ^{−0.054381}) x^{0.4}]^{−9.185} for 0.1 ≤ κ < 0.4,
/// a_ISO = 0.1 [1 − (1.5859 − 1.2348 κ^{−0.19087}) x^{0.4}]^{−9.185} for 0.4 ≤ κ < 1,
/// a_ISO = 0.1 [1 − (1.5859 − 1.2348 κ^{−0.071739}) x^{0.4}]^{−9.185} for 1 ≤ κ ≤ 4;
/// κ > 4 is taken as 4, κ < 0.1 lies outside the standard (refused); a_ISO ≤ 50.
pub fn life_modification_factor(
    kappa: f64,
    ec_cu_over_p: f64,
) -> Result<LifeModification, RatingError> {
    if !(kappa >= 0.1) {
        return Err(RatingError::OutOfRange(format!(
            "κ = {kappa:.3} < 0.1: outside ISO 281 §9.3 (a_ISO is not defined)"
        )));
    }
    let k = kappa.min(4.0);
    let (c, e) = if k < 0.4 {
        (1.3993, 0.054381)
    } else if k < 1.0 {
        (1.2348, 0.19087)
    } else {
        (1.2348, 0.071739)
    };
    let base = 1.0 - (1.5859 - c / k.powf(e)) * ec_cu_over_p.max(0.0).powf(0.4);
    let a = if base > 0.0 {
        0.1 * base.powf(-9.185)
    } else {
        f64::INFINITY
    };
    Ok(LifeModification {
        a_iso: a.min(A_ISO_MAX),
        kappa_used: k,
        capped: a >= A_ISO_MAX,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nu2215_like() -> RollerBearingGeometry {
        RollerBearingGeometry::issue_38_bearing()
    }

    /// Table 7 is the ISO/TR 1281-1 line-contact f_c with λν = 0.83:
    /// f_c = 207.9 λν γ^{2/9} (1−γ)^{29/27} (1+γ)^{−1/4} [1 + (1.04 ((1−γ)/(1+γ))^{143/108})^{9/2}]^{−2/9}.
    #[test]
    fn table_7_follows_the_tr_1281_formula() {
        for (gamma, fc) in FC_TABLE {
            let g: f64 = gamma;
            let ratio = ((1.0 - g) / (1.0 + g)).powf(143.0 / 108.0);
            let formula = 207.9 * 0.83 * g.powf(2.0 / 9.0) * (1.0 - g).powf(29.0 / 27.0)
                / (1.0 + g).powf(0.25)
                * (1.0 + (1.04 * ratio).powf(4.5)).powf(-2.0 / 9.0);
            assert!((formula - fc).abs() < 0.06, "γ {gamma}: {formula} vs {fc}");
        }
        assert!((geometry_factor(0.105).unwrap() - 84.8).abs() < 1e-9);
        assert!(geometry_factor(0.005).is_err());
    }

    /// Worked by hand: γ = 15/102.5 = 0.14634, f_c = 87.7 + 0.634 (88.2 − 87.7) = 88.017;
    /// C_r = 1.1 · 88.017 · 22^{7/9} · 16^{3/4} · 15^{29/27} = 1.1 · 88.017 · 11.072 · 8 · 18.32.
    #[test]
    fn dynamic_rating_of_the_issue_bearing() {
        let g = nu2215_like();
        let fc = geometry_factor(g.gamma()).unwrap();
        assert!((fc - 88.0171).abs() < 1e-3, "{fc}");
        let c = dynamic_radial_rating(&g).unwrap();
        let hand = 1.1 * fc * 22f64.powf(7.0 / 9.0) * 8.0 * 15f64.powf(29.0 / 27.0);
        assert!((c - hand).abs() < 1e-6 * hand);
        assert!((c / 1e3 - 157.1).abs() < 0.5, "{c}");
    }

    #[test]
    fn double_row_rates_two_to_the_seven_ninths() {
        let one = nu2215_like();
        let two = RollerBearingGeometry { rows: 2, ..one };
        let ratio = dynamic_radial_rating(&two).unwrap() / dynamic_radial_rating(&one).unwrap();
        assert!((ratio - 2f64.powf(7.0 / 9.0)).abs() < 1e-12);
    }

    #[test]
    fn equivalent_load_of_a_tapered_bearing() {
        let a = 12f64.to_radians();
        let e = 1.5 * a.tan();
        let single = equivalent_dynamic_load(10e3, 0.5 * e * 10e3, a, 1);
        assert_eq!((single.x, single.y, single.load_n), (1.0, 0.0, 10e3));
        let heavy = equivalent_dynamic_load(10e3, 2.0 * e * 10e3, a, 1);
        assert!((heavy.load_n - (0.4 * 10e3 + 0.4 / a.tan() * 2.0 * e * 10e3)).abs() < 1e-9);
        let double = equivalent_dynamic_load(10e3, 1e3, a, 2);
        assert!((double.load_n - (10e3 + 0.45 / a.tan() * 1e3)).abs() < 1e-9);
        let cylindrical = equivalent_dynamic_load(10e3, 1e3, 0.0, 1);
        assert_eq!(cylindrical.load_n, 10e3);
    }

    /// L10 = (C/P)^{10/3}: C/P = 10 → 2154.4 · 10⁶ revolutions; at 1000 r/min 35 907 h.
    #[test]
    fn basic_life_and_hours() {
        let l = basic_rating_life(100e3, 10e3);
        assert!((l / 1e6 - 2154.43).abs() < 0.01);
        let h = hours(l, 1000.0 * PI / 30.0);
        assert!((h - 35_907.2).abs() < 0.1, "{h}");
        assert!(basic_rating_life(1.0, 0.0).is_infinite());
    }

    #[test]
    fn reliability_factors_of_table_12() {
        assert_eq!(reliability_factor(90.0).unwrap(), 1.0);
        assert_eq!(reliability_factor(99.0).unwrap(), 0.25);
        assert!(reliability_factor(93.0).is_err());
        // the Weibull relation behind the table: a1 = 0.95 (ln(100/R)/ln(100/90))^{2/3} + 0.05
        for (r, a1) in RELIABILITY_TABLE {
            let w: f64 = 0.95 * ((100.0 / r).ln() / (100.0f64 / 90.0).ln()).powf(2.0 / 3.0) + 0.05;
            assert!((w - a1).abs() < 0.005, "{r}: {w} vs {a1}");
        }
    }

    /// ν1 at n = 5000 r/min, D_pw = 102.5 mm: 4500/√5000/√102.5 = 6.286 mm²/s; at 500 r/min:
    /// 45000 · 500^{−0.83} / √102.5 = 25.57 mm²/s.
    #[test]
    fn reference_viscosity_of_both_speed_ranges() {
        let rpm = |n: f64| n * PI / 30.0;
        let fast = reference_viscosity(rpm(5000.0), 0.1025).unwrap() * 1e6;
        assert!((fast - 6.2858).abs() < 1e-3, "{fast}");
        let slow = reference_viscosity(rpm(500.0), 0.1025).unwrap() * 1e6;
        let hand = 45_000.0 * 500f64.powf(-0.83) / 102.5f64.sqrt();
        assert!(
            (slow - hand).abs() < 1e-9 && (slow - 25.57).abs() < 0.01,
            "{slow}"
        );
        assert!(reference_viscosity(0.0, 0.1).is_err());
    }

    #[test]
    fn fatigue_load_limit_with_the_size_factor() {
        assert!((fatigue_load_limit(82e3, 0.09) - 10e3).abs() < 1e-9);
        let big = fatigue_load_limit(82e3, 0.2);
        assert!((big - 10e3 * 0.5f64.powf(0.3)).abs() < 1e-9);
    }

    /// a_ISO: 0.1 without load (x = 0); κ = 1, x = 0.5 by hand:
    /// 0.1 [1 − (1.5859 − 1.2348) 0.5^{0.4}]^{−9.185} = 0.1 · 0.73404^{−9.185} = 1.7141.
    #[test]
    fn life_modification_factor_of_roller_bearings() {
        assert!((life_modification_factor(1.0, 0.0).unwrap().a_iso - 0.1).abs() < 1e-12);
        let a = life_modification_factor(1.0, 0.5).unwrap().a_iso;
        let hand = 0.1 * (1.0 - 0.3511 * 0.5f64.powf(0.4)).powf(-9.185);
        assert!((a - hand).abs() < 1e-9 && (a - 1.7141).abs() < 1e-3, "{a}");
        // continuous at κ = 1 (both branches give 1.2348), capped at 50, κ > 4 taken as 4
        let below = life_modification_factor(1.0 - 1e-12, 0.5).unwrap().a_iso;
        assert!((below - a).abs() < 1e-6);
        let capped = life_modification_factor(4.0, 5.0).unwrap();
        assert!(capped.capped && capped.a_iso == 50.0);
        let k8 = life_modification_factor(8.0, 0.3).unwrap();
        assert_eq!(k8.kappa_used, 4.0);
        assert!(life_modification_factor(0.05, 0.3).is_err());
    }

    #[test]
    fn contamination_columns_split_at_100_mm() {
        let l = ContaminationLevel::NormalCleanliness;
        assert_eq!(l.factor_range(0.099), (0.5, 0.6));
        assert_eq!(l.factor_range(0.1), (0.6, 0.8));
        assert_eq!(contamination_factor(l, 0.2), 0.6);
        for level in ContaminationLevel::ALL {
            assert_eq!(level.name().parse::<ContaminationLevel>(), Ok(level));
        }
        assert!("dirty".parse::<ContaminationLevel>().is_err());
    }
}
