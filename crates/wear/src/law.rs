//! Archard's wear law, hardness conversions and the life conversion (seed 000 §2.4, §3.1.1.5;
//! docs/theory.md §8.1, §8.4).

use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Errors of the wear law and the wear coefficient; each message names the bad value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WearLawError {
    #[error("hardness {value} must be positive and finite")]
    NonPositiveHardness { value: f64 },
    #[error("{scale} hardness {value} lies outside the ASTM E140 steel table ({min} … {max})")]
    HardnessOutsideTable {
        scale: &'static str,
        value: f64,
        min: f64,
        max: f64,
    },
    #[error("the wear-coefficient table has no points")]
    NoPoints,
    #[error(
        "wear-coefficient point {index} (Λ = {lambda}, k = {k:e}) needs positive finite Λ and k"
    )]
    NonPositivePoint { index: usize, lambda: f64, k: f64 },
    #[error(
        "wear-coefficient point {index} (Λ = {lambda}, k = {k:e}) must have a larger Λ and a k not \
         larger than the point before it (Λ = {previous_lambda}, k = {previous_k:e})"
    )]
    NotMonotone {
        index: usize,
        lambda: f64,
        k: f64,
        previous_lambda: f64,
        previous_k: f64,
    },
    #[error("{name} = {value:e} must be positive and finite")]
    NonPositive { name: &'static str, value: f64 },
    #[error("wear-coefficient clamp [{k_min:e}, {k_max:e}] is empty")]
    EmptyClamp { k_min: f64, k_max: f64 },
}

/// Archard wear rate dh/dt = k p v / H, m/s (seed 000 eq. 2.34; with averaged k̄, p̄, v̄ it is
/// eq. 2.35, flag F-46). `k` dimensionless, pressure and hardness in Pa, sliding speed in m/s;
/// the sign of the sliding velocity does not matter.
pub fn archard_rate(k: f64, pressure_pa: f64, sliding_speed_m_s: f64, hardness_pa: f64) -> f64 {
    k * pressure_pa * sliding_speed_m_s.abs() / hardness_pa
}

/// Hardness scales a user may give (converted once to Meyer hardness in Pa).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HardnessScale {
    /// Meyer hardness already in Pa.
    MeyerPa,
    /// Vickers number HV (kgf/mm²).
    Vickers,
    /// Brinell number HB (10 mm ball, 3000 kgf).
    Brinell,
    /// Rockwell C number HRC.
    RockwellC,
}

// the hardness units and the Meyer/Vickers ratio live with the material (one definition)
pub use rolldyn_geometry::{MEYER_PER_VICKERS, PA_PER_KGF_PER_MM2};

/// ASTM E140-12b Table 1 (non-austenitic steels), as reprinted in ASTM A370-03a: Rockwell C
/// → Vickers, every whole HRC from 20 to 68.
const HRC_TO_HV: [(f64, f64); 49] = [
    (20.0, 238.0),
    (21.0, 243.0),
    (22.0, 248.0),
    (23.0, 254.0),
    (24.0, 260.0),
    (25.0, 266.0),
    (26.0, 272.0),
    (27.0, 279.0),
    (28.0, 286.0),
    (29.0, 294.0),
    (30.0, 302.0),
    (31.0, 310.0),
    (32.0, 318.0),
    (33.0, 327.0),
    (34.0, 336.0),
    (35.0, 345.0),
    (36.0, 354.0),
    (37.0, 363.0),
    (38.0, 372.0),
    (39.0, 382.0),
    (40.0, 392.0),
    (41.0, 402.0),
    (42.0, 412.0),
    (43.0, 423.0),
    (44.0, 434.0),
    (45.0, 446.0),
    (46.0, 458.0),
    (47.0, 471.0),
    (48.0, 484.0),
    (49.0, 498.0),
    (50.0, 513.0),
    (51.0, 528.0),
    (52.0, 544.0),
    (53.0, 560.0),
    (54.0, 577.0),
    (55.0, 595.0),
    (56.0, 613.0),
    (57.0, 633.0),
    (58.0, 653.0),
    (59.0, 674.0),
    (60.0, 697.0),
    (61.0, 720.0),
    (62.0, 746.0),
    (63.0, 772.0),
    (64.0, 800.0),
    (65.0, 832.0),
    (66.0, 865.0),
    (67.0, 900.0),
    (68.0, 940.0),
];

/// The same table's Brinell (10 mm ball, 3000 kgf) and Vickers columns, rows HRC 20 … 40
/// (HB 226 … 371), the range of unhardened and tempered cage steels.
const HB_TO_HV: [(f64, f64); 21] = [
    (226.0, 238.0),
    (231.0, 243.0),
    (237.0, 248.0),
    (243.0, 254.0),
    (247.0, 260.0),
    (253.0, 266.0),
    (258.0, 272.0),
    (264.0, 279.0),
    (271.0, 286.0),
    (279.0, 294.0),
    (286.0, 302.0),
    (294.0, 310.0),
    (301.0, 318.0),
    (311.0, 327.0),
    (319.0, 336.0),
    (327.0, 345.0),
    (336.0, 354.0),
    (344.0, 363.0),
    (353.0, 372.0),
    (362.0, 382.0),
    (371.0, 392.0),
];

/// Meyer hardness in Pa from a value in `scale`: HV → Meyer 1.0787·HV kgf/mm² (seed 000
/// §3.1.1.5), HB → HV and HRC → HV by linear interpolation between the rows of ASTM E140
/// Table 1 (`HRC_TO_HV`, `HB_TO_HV`; the table lists whole numbers, so a conversion is good to
/// about ±1 HV). Values outside the table are an error, not an extrapolation.
pub fn meyer_hardness_pa(value: f64, scale: HardnessScale) -> Result<f64, WearLawError> {
    if !(value.is_finite() && value > 0.0) {
        return Err(WearLawError::NonPositiveHardness { value });
    }
    let vickers = match scale {
        HardnessScale::MeyerPa => return Ok(value),
        HardnessScale::Vickers => value,
        HardnessScale::Brinell => interpolate_within(&HB_TO_HV, value, "Brinell")?,
        HardnessScale::RockwellC => interpolate_within(&HRC_TO_HV, value, "Rockwell C")?,
    };
    Ok(rolldyn_geometry::meyer_from_vickers(vickers))
}

/// The seed's literal usage (flag F-45): the kgf/mm² number read as MPa ("H = 305 MPa").
pub fn seed_literal_hardness_pa(meyer_pa: f64) -> f64 {
    meyer_pa / PA_PER_KGF_PER_MM2 * 1e6
}

/// Number of cage revolutions in `period_s` at `cage_speed_rad_s` (SPEC §6.5: N = ω T / 2π); the
/// sense of rotation does not matter.
pub fn revolutions_in(period_s: f64, cage_speed_rad_s: f64) -> f64 {
    cage_speed_rad_s.abs() * period_s / TAU
}

/// Linear interpolation in a table sorted by its first column; outside the table an error.
fn interpolate_within(
    table: &[(f64, f64)],
    x: f64,
    scale: &'static str,
) -> Result<f64, WearLawError> {
    let (first, last) = (table[0], table[table.len() - 1]);
    if !(first.0..=last.0).contains(&x) {
        return Err(WearLawError::HardnessOutsideTable {
            scale,
            value: x,
            min: first.0,
            max: last.0,
        });
    }
    Ok(rolldyn_numerics::table::interpolate_held(table, x))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const HOURS: f64 = 3600.0;

    #[test]
    fn archard_rate_is_k_p_v_over_h_in_metres_per_second() {
        // 1e-10 · 1 GPa · 1 m/s / 10 GPa = 1e-11 m/s, whatever the sign of the sliding velocity
        assert_relative_eq!(
            archard_rate(1e-10, 1e9, 1.0, 1e10),
            1e-11,
            max_relative = 1e-15
        );
        assert_relative_eq!(
            archard_rate(1e-10, 1e9, -1.0, 1e10),
            1e-11,
            max_relative = 1e-15
        );
        // doubling p or v doubles the rate, doubling H halves it
        let base = archard_rate(2.3e-10, 1.41e7, 40.0, 3.0e9);
        assert_relative_eq!(archard_rate(2.3e-10, 2.82e7, 40.0, 3.0e9), 2.0 * base);
        assert_relative_eq!(archard_rate(2.3e-10, 1.41e7, 40.0, 6.0e9), 0.5 * base);
    }

    #[test]
    fn cage_hardness_hv_283_is_meyer_305_kgf_per_mm2() {
        // seed 000 §3.1.1.5: HV 283 → H = 1.0787·283 = 305 "MPa" (flag F-45: kgf/mm²)
        let meyer = meyer_hardness_pa(283.0, HardnessScale::Vickers).unwrap();
        assert_relative_eq!(meyer / PA_PER_KGF_PER_MM2, 305.27, max_relative = 1e-4);
        assert_relative_eq!(meyer, 2.9937e9, max_relative = 1e-4);
    }

    #[test]
    fn brinell_269_converts_to_the_seed_vickers_283_within_the_table_rounding() {
        // E140 rows HB 264 / 271 ↔ HV 279 / 286 interpolate HB 269 to HV 284.0; the seed says
        // 283. The table lists whole numbers, so ±1 HV is its accuracy.
        let meyer = meyer_hardness_pa(269.0, HardnessScale::Brinell).unwrap();
        let vickers = meyer / (MEYER_PER_VICKERS * PA_PER_KGF_PER_MM2);
        assert_relative_eq!(vickers, 284.0, max_relative = 1e-12);
        assert!((vickers - 283.0).abs() <= 1.0, "HV {vickers}");
    }

    #[test]
    fn roller_hardness_61_to_65_hrc_is_meyer_777_to_895_kgf_per_mm2() {
        // seed 000 §3.1.1.5: "61…65 HRC, or Meyer 777…895". E140 gives HV 720 / 832, i.e.
        // Meyer 776.7 / 897.5: within 0.3 % of the seed, tolerance 0.5 %.
        for (hrc, seed_meyer) in [(61.0, 777.0), (65.0, 895.0)] {
            let meyer = meyer_hardness_pa(hrc, HardnessScale::RockwellC).unwrap();
            let kgf_mm2 = meyer / PA_PER_KGF_PER_MM2;
            assert_relative_eq!(kgf_mm2, seed_meyer, max_relative = 5e-3);
        }
        let mid = meyer_hardness_pa(63.0, HardnessScale::RockwellC).unwrap();
        assert_relative_eq!(mid, MEYER_PER_VICKERS * 772.0 * PA_PER_KGF_PER_MM2);
    }

    #[test]
    fn hardness_outside_the_table_or_not_positive_is_an_error_naming_the_value() {
        let error = meyer_hardness_pa(70.0, HardnessScale::RockwellC).unwrap_err();
        assert!(error.to_string().contains("70"), "{error}");
        assert!(meyer_hardness_pa(150.0, HardnessScale::Brinell).is_err());
        assert!(meyer_hardness_pa(-1.0, HardnessScale::Vickers).is_err());
        assert!(meyer_hardness_pa(f64::NAN, HardnessScale::MeyerPa).is_err());
        assert_eq!(meyer_hardness_pa(7.6e9, HardnessScale::MeyerPa), Ok(7.6e9));
        // the table ends are inside it
        assert!(meyer_hardness_pa(20.0, HardnessScale::RockwellC).is_ok());
        assert!(meyer_hardness_pa(68.0, HardnessScale::RockwellC).is_ok());
    }

    #[test]
    fn literal_switch_reads_the_kgf_per_mm2_number_as_mpa() {
        // flag F-45: the seed's "H = 305 MPa" is 305 kgf/mm² ≈ 2.99 GPa; the switch gives 305 MPa
        let meyer = 305.0 * PA_PER_KGF_PER_MM2;
        assert_relative_eq!(seed_literal_hardness_pa(meyer), 305e6, max_relative = 1e-12);
        // so the literal reading gives a wear rate 9.80665 times larger
        let ratio = archard_rate(1.0, 1.0, 1.0, seed_literal_hardness_pa(meyer))
            / archard_rate(1.0, 1.0, 1.0, meyer);
        assert_relative_eq!(ratio, 9.806_65, max_relative = 1e-12);
    }

    #[test]
    fn v19_life_conversion_25000_hours_at_391_8_rad_per_second() {
        // SPEC §6.8 V-19: N = 391.8 · 25 000 h / 2π = 5.612e9 cage revolutions; bar wear
        // 0.44e-8 … 1.7e-8 µm per revolution gives 24.7 … 95.4 µm (seed: "25…96 µm")
        let revolutions = revolutions_in(25_000.0 * HOURS, 391.8);
        assert_relative_eq!(revolutions, 5.612e9, max_relative = 1e-3);
        assert_relative_eq!(revolutions_in(25_000.0 * HOURS, -391.8), revolutions);
        let depth_um = |per_revolution_um: f64| per_revolution_um * revolutions;
        assert_relative_eq!(depth_um(0.44e-8), 24.7, max_relative = 2e-3);
        assert_relative_eq!(depth_um(1.7e-8), 95.4, max_relative = 2e-3);
    }
}
