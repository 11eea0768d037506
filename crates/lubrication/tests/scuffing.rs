//! Scuffing criterion (SPEC §4.8): critical-slip search outcomes and dN/ds diagnostics.
mod common;
use common::*;
use rolldyn_lubrication::scuffing::*;
use rolldyn_lubrication::*;

fn pao1() -> TractionModel {
    TractionModel::muraki(lubricant_by_name("pao1-vg320").unwrap()).unwrap()
}

/// The Brent result is a true local maximum: μ(s_cr) ≥ μ(s_cr(1 ± 10⁻³)), and it agrees with a
/// slow dense golden-free check (log grid, 4000 points) to the grid resolution (0.2 %).
#[test]
fn brent_finds_the_maximum() {
    let m = pao1();
    let st = ball_on_disc(1e9, 2.5, 0.0, 60.0);
    let cs = critical_slip(&st, &m, &SlipSearch::default()).unwrap();
    let (s, mu) = (cs.slip().unwrap(), cs.coefficient().unwrap());
    assert!(friction_curve(&st, &m, s * 1.001) <= mu && friction_curve(&st, &m, s * 0.999) <= mu);
    let (mut best_s, mut best) = (0.0, 0.0);
    for k in 0..4000 {
        let x = 1e-4 * (2.0f64 / 1e-4).powf(k as f64 / 3999.0);
        let v = friction_curve(&st, &m, x);
        if v > best {
            best = v;
            best_s = x;
        }
    }
    assert!((best_s / s - 1.0).abs() < 0.005, "{best_s} vs {s}");
    if let CriticalSlip::Maximum { evaluations, .. } = cs {
        assert!(evaluations < 60, "{evaluations} evaluations");
    }
}

/// Explicit "no maximum in range" outcomes.
#[test]
fn no_maximum_outcomes() {
    let m = pao1();
    let st = ball_on_disc(1e9, 2.5, 0.0, 40.0);
    // range ends before the maximum (s_cr ≈ 0.17)
    let r = critical_slip(
        &st,
        &m,
        &SlipSearch {
            s_max: 0.05,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(matches!(
        r,
        CriticalSlip::NoMaximumInRange {
            reason: NoMaximumReason::IncreasingAtUpperEnd,
            ..
        }
    ));
    // range starts after the maximum
    let r = critical_slip(
        &st,
        &m,
        &SlipSearch {
            s_min: 0.5,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(matches!(
        r,
        CriticalSlip::NoMaximumInRange {
            reason: NoMaximumReason::DecreasingFromLowerEnd,
            ..
        }
    ));
    // margin / safe flag
    let op = ball_on_disc(1e9, 2.5, 0.05, 40.0);
    let chk = scuffing_check(&op, &m, &SlipSearch::default()).unwrap();
    assert!(chk.safe && (chk.margin.unwrap() - 0.1706 / 0.05).abs() < 0.05);
    let op = ball_on_disc(1e9, 2.5, 0.3, 40.0);
    assert!(
        !scuffing_check(&op, &m, &SlipSearch::default())
            .unwrap()
            .safe
    );
    assert!(
        critical_slip(
            &ball_on_disc(1e9, 0.0, 0.0, 40.0),
            &m,
            &SlipSearch::default()
        )
        .is_err()
    );
}

/// F-33: root of (2.31) for raceway Ø180 / roller Ø21 (φ = 90/(2·100.5)) is 0.9526 (seed: 0.94).
#[test]
fn f33_root_of_2_31() {
    let phi = phi_ratio(0.09, 0.1005);
    let s = root_2_31(phi);
    assert!((s - 0.9526).abs() < 1e-4, "{s}");
    assert!((condition_2_31(s, phi) - 1.0).abs() < 1e-12);
    assert!(condition_2_31(0.5, phi) > 1.0 && condition_2_31(0.99, phi) < 1.0);
}

/// dN/ds diagnostics: (2.23) vs a finite difference of N = μQus on the PAO1 curve; exact vs printed
/// (2.26)/(2.28) (F-31); the seed's conclusion dN_i/ds_i > dN_o/ds_o at equal Q, s, μ, μ'.
#[test]
fn heat_power_derivatives() {
    let m = pao1();
    let st = ball_on_disc(1e9, 2.5, 0.0, 40.0);
    let (q, u) = (st.normal_force_n, 2.5);
    for s in [0.05, 0.3] {
        let (mu, dmu) = friction_curve_slope(&st, &m, s);
        let n = |s: f64| heat_power(friction_curve(&st, &m, s), q, u, s);
        let fd = (n(s * 1.0001) - n(s * 0.9999)) / (0.0002 * s);
        // 1e-4 relative: both are central differences with 1e-4 steps
        assert!((dn_ds_constant_rolling(mu, dmu, q, u, s) / fd - 1.0).abs() < 1e-4);
        // thermal zone at s = 0.3 (μ' < 0) but the heat power still grows (2.24)
        if s > 0.2 {
            assert!(dmu < 0.0 && heat_power_grows(mu, dmu, s));
        }
        // v2 = const: exact derivative of N(s) = μ(s) Q v(s), v = 2 s v2/(2 − s)
        let v2 = 2.0;
        let nv = |s: f64| friction_curve(&st, &m, s) * q * 2.0 * s * v2 / (2.0 - s);
        let fd2 = (nv(s * 1.0001) - nv(s * 0.9999)) / (0.0002 * s);
        assert!((dn_ds_v2_constant(mu, dmu, q, v2, s, true) / fd2 - 1.0).abs() < 1e-4);
        let nv1 = |s: f64| friction_curve(&st, &m, s) * q * 2.0 * s * v2 / (2.0 + s);
        let fd1 = (nv1(s * 1.0001) - nv1(s * 0.9999)) / (0.0002 * s);
        assert!((dn_ds_v1_constant(mu, dmu, q, v2, s, true) / fd1 - 1.0).abs() < 1e-4);
        assert!(
            dn_ds_v2_constant(mu, dmu, q, v2, s, true) > dn_ds_v1_constant(mu, dmu, q, v2, s, true)
        );
    }
    // inner vs outer raceway, equal Q, s, μ, μ' (raceway Ø180, roller Ø21, 530 rpm)
    let (omega, ri, rm) = (530.0 * std::f64::consts::PI / 30.0, 0.09, 0.1005);
    for s in [0.01, 0.1, 0.5] {
        let (mu, dmu) = (0.04, -0.01);
        let i = dn_ds_inner(mu, dmu, 100.0, s, omega, ri, rm, 0.01);
        let o = dn_ds_outer(mu, dmu, 100.0, s, omega, ri, rm, 0.01);
        assert!(i > o, "s = {s}: {i} <= {o}");
    }
}
