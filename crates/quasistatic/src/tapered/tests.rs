//! Tests of the tapered load distribution on the seed 000 cassette bearing.

use super::plane::PlaneMotion;
use super::roller::RollerLoading;
use super::*;
use crate::load_integral::radial_load_integral;
use rolldyn_geometry::{BearingModel, Rz};

pub(crate) fn cassette() -> DoubleRowTaperedBearing {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/tapered-cassette.toml"
    );
    let model = rolldyn_model::load(std::path::Path::new(path)).expect("example model");
    match model.bearing {
        BearingModel::Tapered(b) => b,
        _ => panic!("the example is a tapered bearing"),
    }
}

fn case(fr: f64, fa: f64, tilt: TiltCondition, speed: f64) -> TaperedLoadCase {
    TaperedLoadCase {
        radial_load_n: fr,
        axial_load_n: fa,
        tilt,
        inner_speed_rad_s: speed,
    }
}

const NO_MOMENT: TiltCondition = TiltCondition::Moment([0.0; 2]);

/// 663 rpm, the seed's inner-ring speed.
const SEED_SPEED: f64 = 663.0 * std::f64::consts::TAU / 60.0;

/// `(a, b)` with `a n₁ + b n₂ = rhs`.
fn components(n1: Rz, n2: Rz, rhs: Rz) -> (f64, f64) {
    let det = n1.r * n2.z - n1.z * n2.r;
    (
        (rhs.r * n2.z - rhs.z * n2.r) / det,
        (n1.r * rhs.z - n1.z * rhs.r) / det,
    )
}

#[test]
fn pure_axial_load_shares_equally_with_the_analytic_roller_balance() {
    let b = cassette();
    let fa = 31_192.0;
    let z = b.rollers_per_row as f64;
    let sin_a = b.cup_angle().sin();
    let (row0, row1) = (b.row(0), b.row(1));
    for speed in [0.0, SEED_SPEED] {
        let r = solve_tapered_loads(
            &b,
            &case(0.0, fa, NO_MOMENT, speed),
            &TaperedLoadSettings::default(),
        )
        .unwrap();
        let centrifugal = Rz::new(r.centrifugal_force_n, 0.0);
        // row 1 (unloaded): its rollers pressed on the cup by F_c, held by the rib:
        // Q_o n_o + Q_f n_f + F_c e_r = 0
        let (cup1, rib1) = components(row1.cup.normal, row1.large_rib.normal, -centrifugal);
        // row 0: the axial balance of the inner ring, Z Q_o0 sin α_o = F_a + Z Q_o1 sin α_o
        // (Harris & Kotzalas, Essential Concepts ch. 7: Q = F_a/(Z sin α) at rest)
        let cup0 = fa / (z * sin_a) + cup1;
        // its cone and rib loads from the roller balance Q_i n_i + Q_o n_o + Q_f n_f + F_c = 0
        let (cone0, rib0) = components(
            row0.cone.normal,
            row0.large_rib.normal,
            -(cup0 * row0.cup.normal + centrifugal),
        );
        println!(
            "speed {speed:.1} rad/s, F_c {:.3} N: row 0 Q_cup {cup0:.3} N, Q_cone {cone0:.3} N, \
             Q_rib {rib0:.3} N; row 1 Q_cup {cup1:.4} N, Q_rib {rib1:.4} N",
            r.centrifugal_force_n
        );
        // +F_a pushes the inner ring to +z, onto row 0 (large ends at −z in the O arrangement)
        let expected = [(cup0, cone0, rib0), (cup1, 0.0, rib1)];
        for x in &r.rollers {
            let (cup, cone, rib) = expected[x.row];
            let close = |a: f64, e: f64| (a - e).abs() <= 1e-6 * e.abs();
            assert!(close(x.cup_n, cup), "{x:?} vs {cup}");
            assert!(close(x.cone_n, cone), "{x:?} vs {cone}");
            assert!(close(x.rib_n, rib), "{x:?} vs {rib}");
        }
        assert!(r.checks.relative < 1e-8, "{:?}", r.checks);
    }
}

/// Rigid interference of a seated roller with the cup at azimuth ψ for ring displacement `x`.
fn interference(model: &TaperedLoadModel, x: &[f64; 5], psi: f64) -> f64 {
    let motion = PlaneMotion::at(x, psi);
    let loading = RollerLoading {
        cup: motion.line_to_ring(&model.rows[0].cup),
        centrifugal: Rz::default(),
    };
    model.rows[0].seated_cup_interference(&loading)
}

/// The discrete counterpart of J_r: (1/Z) Σ [1 − (1 − cos ψ_j)/(2ε)]^n cos ψ_j.
fn discrete_j_r(eps: f64, n: f64, z: usize) -> f64 {
    (0..z)
        .map(|j| {
            let psi = std::f64::consts::TAU * j as f64 / z as f64;
            let x = 1.0 - (1.0 - psi.cos()) / (2.0 * eps);
            if x > 0.0 { x.powf(n) * psi.cos() } else { 0.0 }
        })
        .sum::<f64>()
        / z as f64
}

/// One pure radial case: (ε, J_r obtained, discrete J_r, continuous J_r).
fn radial_case(model: &TaperedLoadModel, b: &DoubleRowTaperedBearing, fr: f64, n: f64) -> [f64; 4] {
    let r = model
        .solve(
            &case(fr, 0.0, NO_MOMENT, 0.0),
            &TaperedLoadSettings::default(),
        )
        .unwrap();
    assert!(r.checks.relative < 1e-8);
    let x = r.displacement;
    // i(ψ) = A cos ψ − B: the load-zone parameter ε = ½(1 − B/A) (Harris ch. 7)
    let (i0, i180) = (
        interference(model, &x, 0.0),
        interference(model, &x, std::f64::consts::PI),
    );
    let (a, bb) = (0.5 * (i0 - i180), -0.5 * (i0 + i180));
    let eps = 0.5 * (1.0 - bb / a);
    let z = b.rollers_per_row;
    let obtained = 0.5 * fr / (z as f64 * r.rows[0].max_cup_n * b.cup_angle().cos());
    [
        eps,
        obtained,
        discrete_j_r(eps, n, z),
        radial_load_integral(eps, n),
    ]
}

#[test]
fn pure_radial_load_follows_the_sjovall_integral() {
    // Harris' line-contact exponent 1.1 on both raceways, no centrifugal force
    let n = 1.1;
    let law = rolldyn_contact::slices::SliceLaw::PowerPerLength {
        k: 6.6e10,
        exponent: n,
    };
    let mut b = cassette();
    println!(
        "| c_a, mm | F_r, kN | ε | J_r obtained | J_r discrete (Z = 23) (error) | J_r integral (error) |"
    );
    for (clearance, fr) in [
        (0.0, 118_862.0),
        (0.34e-3, 400_000.0),
        (0.34e-3, 118_862.0),
        (0.34e-3, 40_000.0),
    ] {
        b.axial_clearance = clearance;
        let model = TaperedLoadModel::with_laws(&b, &[law, law]).unwrap();
        let [eps, obtained, discrete, integral] = radial_case(&model, &b, fr, n);
        println!(
            "| {:.2} | {:.1} | {eps:.4} | {obtained:.6} | {discrete:.6} ({:+.1e}) | {integral:.6} ({:+.2} %) |",
            clearance * 1e3,
            fr * 1e-3,
            obtained / discrete - 1.0,
            100.0 * (obtained / integral - 1.0)
        );
        // the model against the exact discrete form (rigid-ring Sjövall model, Z = 23); the
        // ring and roller tolerances (1e-9, 1e-10) bound the difference
        assert!(
            (obtained / discrete - 1.0).abs() < 1e-6,
            "{obtained} vs {discrete}"
        );
        // the discrete sum against the continuous integral: the load-zone edge (a kink of
        // power 1.1) between two rollers 15.65° apart, ≤ 1.5 % for ε ≥ 0.2
        assert!(
            (obtained / integral - 1.0).abs() < 0.015,
            "{obtained} vs {integral}"
        );
        if clearance == 0.0 {
            // zero clearance: ε = ½ and Stribeck's Q_max = 4.08 F_r/(Z cos α) (line contact,
            // NSK Cat. E728g §5.1; Harris Table 7.1 J_r(0.5) = 0.2453)
            assert!((eps - 0.5).abs() < 1e-6, "{eps}");
            assert!(
                (1.0 / obtained / 4.08 - 1.0).abs() < 0.01,
                "{}",
                1.0 / obtained
            );
        }
    }
}

#[test]
fn seed_load_cases_converge_and_balance() {
    let b = cassette();
    let arcmin = (1.0_f64 / 60.0).to_radians();
    let cases = [
        (
            "1: Fr 118 862 N",
            case(118_862.0, 0.0, NO_MOMENT, SEED_SPEED),
        ),
        (
            "2: Fr 32 568 N + Fa 31 192 N",
            case(32_568.0, 31_192.0, NO_MOMENT, SEED_SPEED),
        ),
        (
            "3: Fr 118 862 N + 4′",
            case(
                118_862.0,
                0.0,
                TiltCondition::Imposed(4.0 * arcmin),
                SEED_SPEED,
            ),
        ),
    ];
    for (name, c) in cases {
        let r = solve_tapered_loads(&b, &c, &TaperedLoadSettings::default()).unwrap();
        println!(
            "case {name}: max roller load (cup) row 0 {:.0} N, row 1 {:.0} N; loaded {} / {}; \
             edge (loaded rollers): largest slice / mean slice {:.2}; iterations {}; balance {:.1e}",
            r.rows[0].max_cup_n,
            r.rows[1].max_cup_n,
            r.rows[0].loaded_rollers,
            r.rows[1].loaded_rollers,
            r.rollers
                .iter()
                .filter(|x| x.cone_n > 0.0)
                .map(|x| x.cup_slice_max_n * b.roller.slice_count as f64 / x.cup_n)
                .fold(0.0, f64::max),
            r.iterations,
            r.checks.relative
        );
        assert!(r.converged);
        assert!(r.checks.relative < 1e-8, "{:?}", r.checks);
        for x in &r.rollers {
            assert!(x.rib_n >= 0.0, "tensile rib force {x:?}");
        }
    }
}

#[test]
fn tilting_moment_tilts_the_ring_and_is_carried() {
    let b = cassette();
    let m = 5_000.0;
    let r = solve_tapered_loads(
        &b,
        &case(50_000.0, 0.0, TiltCondition::Moment([0.0, m]), 0.0),
        &TaperedLoadSettings::default(),
    )
    .unwrap();
    assert!(r.displacement[4] > 0.0, "{:?}", r.displacement);
    assert!(r.checks.relative < 1e-8);
    assert!((r.checks.applied[4] - m).abs() < 1e-9);
}

#[test]
fn unloaded_bearing_at_rest_is_in_equilibrium_without_contact() {
    let b = cassette();
    let r = solve_tapered_loads(
        &b,
        &case(0.0, 0.0, NO_MOMENT, 0.0),
        &TaperedLoadSettings::default(),
    )
    .unwrap();
    assert!(r.rollers.iter().all(|x| x.cone_n == 0.0 && x.cup_n == 0.0));
}

#[test]
fn non_finite_input_is_refused() {
    let b = cassette();
    let e = solve_tapered_loads(
        &b,
        &case(f64::NAN, 0.0, NO_MOMENT, 0.0),
        &TaperedLoadSettings::default(),
    );
    assert!(matches!(e, Err(crate::QsError::InvalidInput(_))));
}
