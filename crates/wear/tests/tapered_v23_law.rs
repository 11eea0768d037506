//! V-23 at the level of the wear law (seed 000 §3.2.2, Tables 3.6–3.7; SPEC §6.8): the seed's
//! averaged inputs through the averaged formula (2.35) and its direct rates through the life
//! conversion.

use approx::assert_relative_eq;
use rolldyn_wear::coefficient::WearCoefficient;
use rolldyn_wear::law::{PA_PER_KGF_PER_MM2, archard_rate, seed_literal_hardness_pa};

const HOUR: f64 = 3600.0;

/// One column of Table 3.6 with the matching column of Table 3.7.
struct SeedCase {
    name: &'static str,
    sliding_m_s: f64,
    lambda_min: f64,
    k: f64,
    /// mean pressure on the roller end and on the inner-ring rib, Pa
    pressure_pa: [f64; 2],
    /// Table 3.7, direct method: roller end, rib, m/s
    direct_m_s: [f64; 2],
    /// Table 3.7, averaged method: roller end, rib, m/s
    averaged_m_s: [f64; 2],
    /// the 1000 h depths of the text after Table 3.7: roller end, rib, µm
    depth_1000_h_um: [f64; 2],
}

const CASES: [SeedCase; 2] = [
    SeedCase {
        name: "without wear",
        sliding_m_s: 0.0022,
        lambda_min: 0.75,
        k: 2.52342e-10,
        pressure_pa: [7.64e8, 6.27e8],
        direct_m_s: [3.02e-13, 2.61e-13],
        averaged_m_s: [2.65e-16, 3.06e-15],
        depth_1000_h_um: [1.08629, 0.9396],
    },
    SeedCase {
        name: "with wear",
        sliding_m_s: 0.0102,
        lambda_min: 0.75,
        k: 2.52342e-10,
        pressure_pa: [7.00e8, 6.73e8],
        direct_m_s: [1.64e-13, 1.42e-13],
        averaged_m_s: [3.98e-16, 9.37e-15],
        depth_1000_h_um: [0.59217, 0.51191],
    },
];

/// Meyer hardness of the roller and the cone, Pa: the workspace's bearing steel (7.6 GPa,
/// ≈ 62 HRC), the material of examples/tapered-cassette.toml; the seed gives none for this
/// bearing.
fn hardness_pa() -> f64 {
    rolldyn_geometry::Material::bearing_steel()
        .meyer_hardness
        .unwrap()
}

/// Whether `value` rounds to `printed` at the printed number of significant digits (3).
fn rounds_to(value: f64, printed: f64) -> bool {
    let unit = 10f64.powf(printed.abs().log10().floor() - 2.0);
    (value - printed).abs() <= 0.5 * unit * (1.0 + 1e-9)
}

#[test]
fn table_3_6_lambda_gives_the_seed_k_through_the_default_k_of_lambda() {
    // lg Λ = −0.124938737 ⇔ Λ = 0.75; the default table passes through (0.75, 2.52342e-10)
    let k_of = WearCoefficient::seed_default();
    for case in &CASES {
        assert_relative_eq!(case.lambda_min.log10(), -0.124938737, max_relative = 1e-8);
        assert_relative_eq!(k_of.film(case.lambda_min), case.k, max_relative = 1e-12);
    }
}

#[test]
fn direct_rates_of_table_3_7_times_1000_hours_are_the_seed_depths() {
    // the seed's 1000 h depths are rate × time (no exposure factor, flag F-47): each printed
    // rate is the depth over 3.6e6 s rounded to three digits
    for case in &CASES {
        for (surface, (&rate, &depth_um)) in ["roller end", "rib"]
            .iter()
            .zip(case.direct_m_s.iter().zip(&case.depth_1000_h_um))
        {
            let period_s = 1000.0 * HOUR;
            let rate_from_depth = depth_um * 1e-6 / period_s;
            println!(
                "{} {surface}: seed depth {depth_um} µm / 1000 h = {rate_from_depth:.5e} m/s, \
                 Table 3.7 {rate:.2e} m/s, rate × 1000 h = {:.5} µm",
                case.name,
                rate * period_s * 1e6
            );
            assert!(
                rounds_to(rate_from_depth, rate),
                "{} {surface}: {rate_from_depth:e} does not round to {rate:e}",
                case.name
            );
        }
    }
    // the decrease from the first to the second calculation, roller end and rib
    let ratio = |i: usize| CASES[1].depth_1000_h_um[i] / CASES[0].depth_1000_h_um[i];
    assert_relative_eq!(ratio(0), 0.545131, max_relative = 1e-5);
    assert_relative_eq!(ratio(1), 0.544817, max_relative = 1e-5);
}

#[test]
fn averaged_formula_on_table_3_6_against_table_3_7() {
    // (2.35) with the Table 3.6 inputs, H of bearing steel (SI) and the seed's literal kgf/mm²
    // reading (flag F-45); reported against the averaged and the direct rows of Table 3.7
    // (flag F-51: the text says "one order", the table shows 2–3 orders)
    let h_si = hardness_pa();
    let h_literal = seed_literal_hardness_pa(h_si);
    assert_relative_eq!(
        h_si / h_literal,
        PA_PER_KGF_PER_MM2 / 1e6,
        max_relative = 1e-12
    );
    println!(
        "case | surface | (2.35) H=7.6 GPa | (2.35) H literal | Table 3.7 averaged | Table 3.7 \
         direct | (2.35)/averaged | direct/averaged"
    );
    for case in &CASES {
        for (i, surface) in ["roller end", "rib"].iter().enumerate() {
            let formula = archard_rate(case.k, case.pressure_pa[i], case.sliding_m_s, h_si);
            let literal = archard_rate(case.k, case.pressure_pa[i], case.sliding_m_s, h_literal);
            let (averaged, direct) = (case.averaged_m_s[i], case.direct_m_s[i]);
            println!(
                "{} | {surface} | {formula:.3e} | {literal:.3e} | {averaged:.2e} | {direct:.2e} \
                 | {:.1} | {:.1}",
                case.name,
                formula / averaged,
                direct / averaged
            );
            // by hand, without wear, roller end: 2.52342e-10 · 7.64e8 · 0.0022 / 7.6e9
            if i == 0 && case.sliding_m_s == 0.0022 {
                assert_relative_eq!(formula, 5.5808e-14, max_relative = 1e-4);
            }
            // the seed's averaged rates lie 2–3 orders below its direct rates (F-51) ...
            let orders = (direct / averaged).log10();
            assert!((1.0..3.2).contains(&orders), "{orders}");
            // ... and (2.35) on its own inputs gives rates of the direct method's order, not of
            // its averaged row: the printed averaged rates carry a factor the seed does not state
            let against_direct = (formula / direct).log10();
            assert!(against_direct.abs() < 1.0, "{against_direct}");
        }
    }
}
