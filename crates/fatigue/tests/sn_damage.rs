//! S–N curve, mean-stress corrections, Miner damage and the fatigue plots against hand values.

use rolldyn_fatigue::damage::{MeanStressSettings, life_hours, miner_damage};
use rolldyn_fatigue::mean_stress::MeanStressCorrection;
use rolldyn_fatigue::plots::{RainflowMatrix, rainflow_matrix, sn_diagram};
use rolldyn_fatigue::sn::{BelowKnee, SnCurve, SnError, SnSettings};
use rolldyn_fatigue::{Cycle, HistoryKind, rainflow};

const MPA: f64 = 1e6;

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

macro_rules! assert_close {
    ($a:expr, $b:expr) => {
        assert_close!($a, $b, 1e-9)
    };
    ($a:expr, $b:expr, $rel:expr) => {{
        let (a, b) = ($a, $b);
        assert!(close(a, b, $rel), "{a} vs {b}");
    }};
}

/// (10³, 800 MPa), (10⁵, 400 MPa), (10⁷, 300 MPa) without knock-down.
fn two_segment(below_knee: BelowKnee) -> SnCurve {
    SnCurve::new(vec![
        (1e3, 800.0 * MPA),
        (1e5, 400.0 * MPA),
        (1e7, 300.0 * MPA),
    ])
    .unwrap()
    .with_settings(SnSettings {
        coating_factor: 1.0,
        stress_safety_factor: 1.0,
        below_knee,
    })
    .unwrap()
}

#[test]
fn default_curve_passes_the_seed_point_with_the_aisi_4340_slope() {
    let curve = SnCurve::aisi_4340();
    let (n, s): (Vec<f64>, Vec<f64>) = curve.points().iter().copied().unzip();
    assert_eq!(n, vec![1e3, 1e4, 1e5, 1e6, 1e7]);
    assert_close!(s[3], 480.0 * MPA);
    assert_close!(s[0], 942.63 * MPA, 1e-5);
    assert_close!(s[4], 383.30 * MPA, 1e-5);
    assert_eq!(curve.settings(), &SnSettings::default());
    // the seed's lg 1.5 shift: 320 MPa allowable at 10⁶ cycles
    assert_close!(curve.allowable_amplitude(1e6), 320.0 * MPA);
}

#[test]
fn interpolation_is_linear_in_log_log_and_the_inverse_returns_the_life() {
    let curve = two_segment(BelowKnee::NoDamage);
    // halfway in lg N between 10³ and 10⁵: the geometric mean of 800 and 400 MPa
    assert_close!(curve.base_amplitude(1e4), (800.0f64 * 400.0).sqrt() * MPA);
    assert_close!(curve.base_amplitude(1e6), (400.0f64 * 300.0).sqrt() * MPA);
    for lg_n in [2.0, 3.0, 3.7, 5.0, 6.2, 7.0] {
        let n = 10f64.powf(lg_n);
        assert_close!(curve.cycles_to_failure(curve.allowable_amplitude(n)), n);
    }
}

#[test]
fn the_low_cycle_side_continues_the_first_segment() {
    let curve = two_segment(BelowKnee::NoDamage);
    // first segment: N ∝ σ^−k with k = 2 / lg 2
    let k = 2.0 / 2f64.log10();
    assert_close!(curve.cycles_to_failure(1600.0 * MPA), 1e3 * 2f64.powf(-k));
    assert_close!(
        curve.base_amplitude(10.0),
        800.0 * MPA * 100f64.powf(1.0 / k)
    );
    assert_eq!(curve.cycles_to_failure(f64::INFINITY), 0.0);
    assert_eq!(curve.cycles_to_failure(0.0), f64::INFINITY);
}

#[test]
fn coating_and_safety_factors_divide_the_amplitudes() {
    let settings = SnSettings {
        coating_factor: 1.5,
        stress_safety_factor: 1.5,
        below_knee: BelowKnee::NoDamage,
    };
    let curve = two_segment(BelowKnee::NoDamage)
        .with_settings(settings)
        .unwrap();
    assert_close!(curve.allowable_amplitude(1e5), 400.0 * MPA / 2.25);
    assert_close!(curve.cycles_to_failure(400.0 * MPA / 2.25), 1e5);
    // the base curve is not knocked down
    assert_close!(curve.base_amplitude(1e5), 400.0 * MPA);
    let bad = SnSettings {
        coating_factor: 0.0,
        ..settings
    };
    assert!(matches!(
        two_segment(BelowKnee::NoDamage).with_settings(bad),
        Err(SnError::Settings(_))
    ));
}

#[test]
fn below_the_knee_no_damage_extrapolation_or_haibach() {
    // last segment: N ∝ σ^−k with k = 2 / lg(4/3); half the knee amplitude, 150 MPa
    let k = 2.0 / (4.0f64 / 3.0).log10();
    let half = 150.0 * MPA;
    let none = two_segment(BelowKnee::NoDamage);
    assert_eq!(none.cycles_to_failure(half), f64::INFINITY);
    assert_eq!(none.base_amplitude(1e9), 300.0 * MPA);
    let extrapolated = two_segment(BelowKnee::Extrapolate);
    assert_close!(extrapolated.cycles_to_failure(half), 1e7 * 2f64.powf(k));
    let haibach = two_segment(BelowKnee::Haibach);
    assert_close!(
        haibach.cycles_to_failure(half),
        1e7 * 2f64.powf(2.0 * k - 1.0)
    );
    // and the forward curves agree with their inverses
    for curve in [&extrapolated, &haibach] {
        assert_close!(curve.base_amplitude(curve.cycles_to_failure(half)), half);
    }
    // at the knee all three agree
    for curve in [&none, &extrapolated, &haibach] {
        assert_close!(curve.cycles_to_failure(300.0 * MPA), 1e7);
    }
}

#[test]
fn mean_stress_corrections_against_hand_values() {
    let (a, m, u) = (100.0, 200.0, 1000.0);
    let eq = |c: MeanStressCorrection, mean: f64| c.equivalent_amplitude(a, mean, u);
    use MeanStressCorrection::*;
    assert_eq!(eq(None, m), 100.0);
    assert_close!(eq(Goodman, m), 125.0);
    assert_close!(eq(Gerber, m), 100.0 / 0.96);
    assert_close!(eq(SmithWatsonTopper, m), (300.0f64 * 100.0).sqrt());
    // compressive means: Goodman and Gerber take σ_m = 0; SWT keeps σ_max = σ_m + σ_a
    assert_eq!(eq(Goodman, -m), 100.0);
    assert_eq!(eq(Gerber, -m), 100.0);
    assert_close!(eq(SmithWatsonTopper, -50.0), (50.0f64 * 100.0).sqrt());
    assert_eq!(eq(SmithWatsonTopper, -m), 0.0);
    // a tensile mean at σ_u: static failure
    assert_eq!(eq(Goodman, u), f64::INFINITY);
    assert_eq!(eq(Gerber, 1.5 * u), f64::INFINITY);
}

fn cycle(amplitude_mpa: f64, mean_mpa: f64, count: f64) -> Cycle {
    Cycle {
        range: 2.0 * amplitude_mpa * MPA,
        mean: mean_mpa * MPA,
        count,
    }
}

#[test]
fn miner_sums_two_amplitudes_and_skips_the_cycles_below_the_knee() {
    let curve = two_segment(BelowKnee::NoDamage);
    // 400 MPa: N = 10⁵; √(800·400) MPa: N = 10⁴, counted as a half cycle; 200 MPa: below the knee
    let cycles = [
        cycle(400.0, 0.0, 1.0),
        cycle((800.0f64 * 400.0).sqrt(), 0.0, 0.5),
        cycle(200.0, 0.0, 1.0),
    ];
    let result = miner_damage(&cycles, &curve, &MeanStressSettings::default());
    assert_close!(result.damage_per_repeat, 1e-5 + 0.5e-4);
    assert_close!(result.life_repeats, 1.0 / 6e-5);
    assert_close!(result.cycles[1].cycles_to_failure, 1e4);
    assert_eq!(result.cycles[2].damage, 0.0);
    assert_eq!(result.largest(1)[0], result.cycles[1]);
    // JSON: an infinite N_j is written as null
    let json = serde_json::to_value(&result).unwrap();
    assert!(json["cycles"][2]["cycles_to_failure"].is_null());
    // nothing above the knee: no damage, infinite life
    let harmless = miner_damage(&cycles[2..], &curve, &MeanStressSettings::default());
    assert_eq!(harmless.damage_per_repeat, 0.0);
    assert_eq!(harmless.life_repeats, f64::INFINITY);
}

#[test]
fn a_tensile_mean_adds_damage_under_goodman() {
    let curve = two_segment(BelowKnee::NoDamage);
    let goodman = MeanStressSettings {
        correction: MeanStressCorrection::Goodman,
        ultimate_strength_pa: 1000.0 * MPA,
    };
    // 320 MPa at a 200 MPa mean is 400 MPa fully reversed: N = 10⁵
    let result = miner_damage(&[cycle(320.0, 200.0, 1.0)], &curve, &goodman);
    assert_close!(result.cycles[0].equivalent_amplitude_pa, 400.0 * MPA);
    assert_close!(result.damage_per_repeat, 1e-5);
}

#[test]
fn a_counted_history_end_to_end() {
    // one period 0 → 10 → 4 → 6 → −10 → 0 (×50 MPa): full cycles of range 1000 and 100 MPa
    let history: Vec<f64> = [0.0, 10.0, 4.0, 6.0, -10.0, 0.0]
        .iter()
        .map(|x| x * 50.0 * MPA)
        .collect();
    let cycles = rainflow(&history, HistoryKind::Periodic);
    let result = miner_damage(
        &cycles,
        &two_segment(BelowKnee::NoDamage),
        &Default::default(),
    );
    // 500 MPa amplitude on the first segment: N = 10³ (800/500)^k, k = 2/lg 2; 50 MPa: no damage
    let n = 1e3 * (800.0f64 / 500.0).powf(2.0 / 2f64.log10());
    assert_close!(result.damage_per_repeat, 1.0 / n);
}

#[test]
fn hours_from_revolutions_and_cage_speed() {
    // L_h = L_rev / (60 n_c): the seed's 27 457 revolutions at 10 000 rpm
    let hours = life_hours(27_457.0, 10_000.0 * rolldyn_units::RPM);
    assert_close!(hours, 27_457.0 / (60.0 * 10_000.0));
    assert_eq!(life_hours(f64::INFINITY, 100.0), f64::INFINITY);
    assert_close!(life_hours(1.0, -100.0), life_hours(1.0, 100.0));
}

#[test]
fn csv_tables_in_mpa_with_errors_naming_the_line() {
    let text = "N,sigma_a_MPa\n# a comment\n1e3, 800\n\n1e5, 400 # knee next\n1e7, 300\n";
    let curve = SnCurve::from_csv_text(text).unwrap();
    assert_eq!(
        curve.points(),
        &[(1e3, 800.0 * MPA), (1e5, 400.0 * MPA), (1e7, 300.0 * MPA)]
    );
    let line = |text: &str| match SnCurve::from_csv_text(text) {
        Err(SnError::Line { line, reason }) => (line, reason),
        other => panic!("{other:?}"),
    };
    assert_eq!(line("N,S\n1e3,800\n1e5,abc\n").0, 3);
    assert_eq!(line("1e3,800\n1e5,400,7\n").0, 2);
    let (at, reason) = line("1e3,800\n\n1e5,900\n");
    assert_eq!(at, 3);
    assert!(reason.contains("decrease"), "{reason}");
    assert_eq!(line("1e3,800\n-1e5,400\n").0, 2);
    assert_eq!(
        SnCurve::from_csv_text("N,S\n1e3,800\n"),
        Err(SnError::TooFewPoints(1))
    );
    let message = SnCurve::from_csv_text("1e3,800\nx,1\n")
        .unwrap_err()
        .to_string();
    assert!(message.starts_with("line 2:"), "{message}");
}

#[test]
fn rainflow_matrix_bins_the_counts() {
    let cycles = [
        cycle(100.0, -50.0, 1.0),
        cycle(100.0, -50.0, 0.5),
        cycle(400.0, 150.0, 1.0),
    ];
    let m = RainflowMatrix::from_cycles(&cycles, 4);
    assert_eq!(m.extent, (-50.0 * MPA, 150.0 * MPA, 0.0, 800.0 * MPA));
    assert_eq!(m.counts.iter().sum::<f64>(), 2.5);
    // range 200 MPa of 800 → row 1, mean at the low end → column 0; the largest → last cell
    assert_eq!(m.counts[4], 1.5);
    assert_eq!(m.counts[15], 1.0);
    assert_eq!(RainflowMatrix::from_cycles(&[], 3).counts, vec![0.0; 9]);
}

#[test]
fn the_plots_write_svg_files() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    let curve = SnCurve::aisi_4340();
    let cycles = [
        cycle(350.0, 20.0, 1.0),
        cycle(120.0, -10.0, 1.0),
        cycle(500.0, 0.0, 0.5),
    ];
    let result = miner_damage(&cycles, &curve, &MeanStressSettings::default());
    for (name, write) in [
        (
            "sn_diagram.svg",
            sn_diagram(&dir.join("sn_diagram.svg"), &curve, &result),
        ),
        (
            "rainflow_matrix.svg",
            rainflow_matrix(&dir.join("rainflow_matrix.svg"), &cycles, 8),
        ),
    ] {
        write.unwrap();
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(text.starts_with("<svg") && text.len() > 1000, "{name}");
    }
}
