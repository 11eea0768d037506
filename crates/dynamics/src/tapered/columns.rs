//! Named columns of the tapered run's time series and summary (the `--out` table and the
//! `--json` keys); units in the names.

use super::sample::TaperedSample;
use super::summary::TaperedSummary;

/// Columns of [`sample_row`].
pub const SAMPLE_COLUMNS: [&str; 26] = [
    "time_s",
    "inner_x_m",
    "inner_y_m",
    "inner_z_m",
    "cage0_angle_rad",
    "cage1_angle_rad",
    "cage0_speed_rad_s",
    "cage1_speed_rad_s",
    "row0_max_cone_load_n",
    "row1_max_cone_load_n",
    "row0_rollers_near_max",
    "row1_rollers_near_max",
    "row0_max_rib_force_n",
    "row1_max_rib_force_n",
    "row0_total_rib_force_n",
    "row1_total_rib_force_n",
    "row0_cone_sliding_m_s",
    "row1_cone_sliding_m_s",
    "row0_cup_sliding_m_s",
    "row1_cup_sliding_m_s",
    "max_slip",
    "row0_roller0_large_rib_n",
    "row1_roller0_large_rib_n",
    "row0_roller0_small_rib_n",
    "row1_roller0_small_rib_n",
    "rib_ehl_share",
];

/// The values of `s` in the order of [`SAMPLE_COLUMNS`].
pub fn sample_row(s: &TaperedSample) -> [f64; 26] {
    [
        s.time_s,
        s.inner_ring[0],
        s.inner_ring[1],
        s.inner_ring[2],
        s.cage_angle[0],
        s.cage_angle[1],
        s.cage_speed[0],
        s.cage_speed[1],
        s.max_cone_load[0],
        s.max_cone_load[1],
        s.rollers_near_max[0] as f64,
        s.rollers_near_max[1] as f64,
        s.max_rib_force[0],
        s.max_rib_force[1],
        s.total_rib_force[0],
        s.total_rib_force[1],
        s.cone_sliding[0],
        s.cone_sliding[1],
        s.cup_sliding[0],
        s.cup_sliding[1],
        s.max_slip,
        s.tracked_large_rib[0],
        s.tracked_large_rib[1],
        s.tracked_small_rib[0],
        s.tracked_small_rib[1],
        s.rib_ehl_share,
    ]
}

/// The sample whose [`sample_row`] is `r` (a row read back).
pub fn sample_from_row(r: &[f64; 26]) -> TaperedSample {
    let pair = |k: usize| [r[k], r[k + 1]];
    TaperedSample {
        time_s: r[0],
        inner_ring: [r[1], r[2], r[3]],
        cage_angle: pair(4),
        cage_speed: pair(6),
        max_cone_load: pair(8),
        rollers_near_max: [r[10] as usize, r[11] as usize],
        max_rib_force: pair(12),
        total_rib_force: pair(14),
        cone_sliding: pair(16),
        cup_sliding: pair(18),
        max_slip: r[20],
        tracked_large_rib: pair(21),
        tracked_small_rib: pair(23),
        rib_ehl_share: r[25],
    }
}

/// The summary as named values (SI; frequencies Hz), in print order.
pub fn summary_entries(s: &TaperedSummary) -> Vec<(String, f64)> {
    let mut v: Vec<(String, f64)> = vec![
        ("steady_from_s".into(), s.steady_from_s),
        ("pass_frequency_outer_hz".into(), s.pass_frequency_outer_hz),
        ("pass_frequency_inner_hz".into(), s.pass_frequency_inner_hz),
    ];
    for (i, (f, a)) in s.axial_peaks.iter().enumerate() {
        v.push((format!("axial_peak{}_hz", i + 1), *f));
        v.push((format!("axial_peak{}_amplitude_m", i + 1), *a));
    }
    v.extend([
        ("axial_range_m".into(), s.axial_range_m),
        ("radial_range_m".into(), s.radial_range_m),
        ("inner_mean_x_m".into(), s.inner_ring_mean[0]),
        ("inner_mean_y_m".into(), s.inner_ring_mean[1]),
        ("inner_mean_z_m".into(), s.inner_ring_mean[2]),
        ("cage0_speed_mean_rad_s".into(), s.cage_speed_mean[0]),
        ("cage1_speed_mean_rad_s".into(), s.cage_speed_mean[1]),
        ("cage_speed_epicyclic_rad_s".into(), s.cage_speed_epicyclic),
        ("cage_lag_pitch_fraction".into(), s.cage_lag_pitch_fraction),
        (
            "row0_rollers_near_max_mean".into(),
            s.rollers_near_max_mean[0],
        ),
        (
            "row1_rollers_near_max_mean".into(),
            s.rollers_near_max_mean[1],
        ),
        ("one_and_two_share".into(), s.one_and_two_share),
        ("row0_max_cone_load_n".into(), s.max_cone_load[0]),
        ("row1_max_cone_load_n".into(), s.max_cone_load[1]),
        ("row0_max_rib_force_n".into(), s.max_rib_force[0]),
        ("row1_max_rib_force_n".into(), s.max_rib_force[1]),
        ("row0_cone_sliding_mean_m_s".into(), s.cone_sliding_mean[0]),
        ("row1_cone_sliding_mean_m_s".into(), s.cone_sliding_mean[1]),
        ("row0_cup_sliding_mean_m_s".into(), s.cup_sliding_mean[0]),
        ("row1_cup_sliding_mean_m_s".into(), s.cup_sliding_mean[1]),
        ("max_slip".into(), s.max_slip),
        ("rib_ehl_share".into(), s.rib_ehl_share),
    ]);
    v
}
