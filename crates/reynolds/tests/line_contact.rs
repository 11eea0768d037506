//! Validation of the roller–plate line contact (SPEC §8.4, V-29…V-38, flags F-62…F-71).
//! Every tolerance is stated and justified next to its assertion.

use rolldyn_reynolds::compliance::half_space::HalfSpace;
use rolldyn_reynolds::compliance::layer::ElasticLayer;
use rolldyn_reynolds::line_contact::analytic;
use rolldyn_reynolds::line_contact::{
    Compliance, Constraint, LineContactOptions, LubricatedLineContact, solve,
};
use rolldyn_reynolds::{Barus, Density, Isoviscous, ReynoldsError, Roelands};
use std::sync::Arc;

/// Seed 002 §3.5 data: μ = 0.024 Pa·s, V = 7 m/s (sum speed), R = 5 mm.
const MU: f64 = 0.024;
const V: f64 = 7.0;
const R: f64 = 0.005;

fn rigid() -> LubricatedLineContact {
    LubricatedLineContact::new(R, V)
}

/// Rigid isoviscous contact against the analytic (Martin) solution of seed (3.15)/(3.66):
/// exit c, pressure maximum, load and damping. SPEC acceptance: |Δc| ≤ 5×10⁻⁴, p_max and load
/// ≤ 0.5 %. Obtained with 1000 clustered nodes: Δc ≈ 3×10⁻⁴, p_max −0.03 %, W −0.08 %,
/// λ +0.3 % (λ from ±Δν = 0.01 central differences of two more solves).
#[test]
fn rigid_isoviscous_matches_martin() {
    let h = 1e-6;
    let res = solve(
        &rigid(),
        &Isoviscous { mu: MU },
        Constraint::MinFilm(h),
        &LineContactOptions::default(),
    )
    .unwrap();
    assert!(res.converged);
    let lh = (R * h).sqrt();
    let p0 = analytic::pressure_scale(MU, V, R, h);
    let c_exact = analytic::exit_parameter(0.0).unwrap();
    let (w0, w1) = analytic::load_coefficients().unwrap();
    let c_num = res.outlet_position_m / lh;
    assert!((c_num - c_exact).abs() <= 5e-4, "c = {c_num} vs {c_exact}");
    let qm = analytic::q_max(0.0).unwrap();
    assert!((res.max_pressure_pa / (qm * p0) - 1.0).abs() <= 5e-3);
    assert!((res.load_per_length_n_per_m / (w0 * p0 * lh) - 1.0).abs() <= 5e-3);
    let lambda = 6.0 * w1 * MU * R.powf(1.5) / h.powf(1.5);
    assert!(
        (res.damping_ns_per_m2 / lambda - 1.0).abs() <= 5e-3,
        "{} {lambda}",
        res.damping_ns_per_m2
    );
    // SPEC derived numbers: P_max = 1.278×10⁷ Pa, W = 2056 N/m (Table 3.4 first row, F-70)
    assert!((res.max_pressure_pa - 1.2776e7).abs() < 0.005 * 1.2776e7);
    assert!((res.load_per_length_n_per_m - 2056.0).abs() < 0.005 * 2056.0);
}

/// Seed constants vs exact values (flags F-64, F-65, F-66): the seed's exit root 0.67155 is
/// 3.9×10⁻⁴ below the exact 0.671935; its fitted W₀′ = 0.401 and W₁′ = 1.125 differ from the
/// exact 0.4079 (−1.7 %) and 1.091 (+3.1 %). The corrected Kapitsa formulas equal q_max·P₀ and
/// 6W₀′μVR/h to their printed 3 digits (0.5 %).
#[test]
fn seed_constants_and_kapitsa() {
    let c = analytic::exit_parameter(0.0).unwrap();
    assert!((c - 0.67155).abs() < 5e-4 && (c - 0.671935).abs() < 1e-5);
    let (w0, w1) = analytic::load_coefficients().unwrap();
    assert!((w0 - 0.4079).abs() < 1e-4 && (w1 - 1.091).abs() < 3e-3);
    assert!(((analytic::SEED_W0 - w0) / w0 + 0.017).abs() < 2e-3);
    let h = 1e-6;
    let (pk, wk) = analytic::kapitsa(MU, V, R, h);
    let p0 = analytic::pressure_scale(MU, V, R, h);
    assert!((pk / (analytic::q_max(0.0).unwrap() * p0) - 1.0).abs() < 5e-3);
    assert!((wk / (6.0 * w0 * MU * V * R / h) - 1.0).abs() < 5e-3);
}

/// Squeeze term (3.13)–(3.16) with the derived q₁ (flag F-63): numerical loads for ν = ±0.05
/// against the SPEC table W′ = 0.4656 / 0.3564 (tolerance 0.5 % as for ν = 0).
#[test]
fn squeeze_loads_match_the_derived_table() {
    let h = 1e-6;
    for (nu, w) in [(-0.05, 0.4656), (0.05, 0.3564)] {
        let vy = nu * V * (h / R).sqrt();
        let opt = LineContactOptions {
            squeeze_velocity: vy,
            damping: false,
            ..Default::default()
        };
        let res = solve(
            &rigid(),
            &Isoviscous { mu: MU },
            Constraint::RigidApproach(h),
            &opt,
        )
        .unwrap();
        let p0 = analytic::pressure_scale(MU, V, R, h);
        let wn = res.load_per_length_n_per_m / (p0 * (R * h).sqrt());
        assert!((wn / w - 1.0).abs() < 5e-3, "ν = {nu}: {wn} vs {w}");
    }
}

/// Table 3.4 rigid columns (V-33) and Table 3.5 piezoviscous rigid column (V-34), α = 0.75×10⁻⁸:
/// the numerical solver against the derived closed forms (0.5 %) and the seed's values (SPEC
/// acceptance 2 %; the seed's rigid numbers are 1–2 % low because of its exit root and
/// rounding; at h = 2.5×10⁻⁷ m its piezoviscous 19.1 is 1.6 % below the derived 19.40).
#[test]
fn seed_table_3_4_rigid_columns() {
    let rows = [
        (1e-6, 1.26e7, 1.33e7),
        (5e-7, 3.59e7, 4.18e7),
        (3.5e-7, 6.13e7, 8.2e7),
        (2.5e-7, 10.02e7, 19.1e7),
    ];
    let opt = LineContactOptions {
        damping: false,
        nodes: 600,
        ..Default::default()
    };
    for (h, iso_seed, piezo_seed) in rows {
        let iso = solve(
            &rigid(),
            &Isoviscous { mu: MU },
            Constraint::MinFilm(h),
            &opt,
        )
        .unwrap();
        let piezo = solve(
            &rigid(),
            &Barus {
                mu0: MU,
                alpha: 0.75e-8,
            },
            Constraint::MinFilm(h),
            &opt,
        )
        .unwrap();
        let iso_exact = analytic::q_max(0.0).unwrap() * analytic::pressure_scale(MU, V, R, h);
        let piezo_exact = analytic::piezoviscous_max_pressure(MU, 0.75e-8, V, R, h).unwrap();
        assert!((iso.max_pressure_pa / iso_exact - 1.0).abs() < 5e-3);
        assert!(
            (piezo.max_pressure_pa / piezo_exact - 1.0).abs() < 5e-3,
            "{h}"
        );
        assert!((iso.max_pressure_pa / iso_seed - 1.0).abs() < 0.02, "{h}");
        assert!(
            (piezo.max_pressure_pa / piezo_seed - 1.0).abs() < 0.02,
            "{h}"
        );
    }
    // Table 3.5: α = 2.3×10⁻⁸ has no rigid solution (α̃·q₀,max = 1.42 > 1); the other rows
    // follow the derived column 27.3 / 14.2 / 10.3 / 8.28 / 6.95 ×10⁷ Pa (the seed's 24.5 / 13.24
    // / 10.6 / 8.20 / 6.89 differ by up to 10 % near the singularity, as SPEC V-34 notes).
    assert!(matches!(
        analytic::piezoviscous_max_pressure(MU, 2.3e-8, V, R, 3.5e-7),
        Err(ReynoldsError::NoSolution(_))
    ));
    for (a, derived) in [
        (1.6e-8, 27.3e7),
        (1.4e-8, 14.2e7),
        (1.1e-8, 10.3e7),
        (0.75e-8, 8.28e7),
        (0.35e-8, 6.95e7),
    ] {
        let p = analytic::piezoviscous_max_pressure(MU, a, V, R, 3.5e-7).unwrap();
        assert!((p / derived - 1.0).abs() < 0.01, "{a}: {p}");
    }
}

/// Tables 3.3–3.5 deformation columns (V-32…V-34), the seed's h_m taken as the rigid approach
/// (its (3.74)–(3.75)). The seed's kernels come from FE with an unstated normalisation and
/// identification period (flags F-69, F-70: its Fourier coefficients of Table 3.1 give
/// deflections ~10⁴ times too small for its own Table 3.3), so they cannot be reused; here the
/// plate is a bonded elastic layer of 50 mm (its L_y) and the roller a half-space held at its
/// axis, E = 2.1×10¹¹ Pa, ν = 0.3.
///
/// What reproduces: h_m = 1 µm — p_max 1.2365×10⁷ Pa vs the seed's converged 1.22687×10⁷ (+0.8 %),
/// total deflection 6.1×10⁻⁸ m vs the seed's ring + roller 5.54×10⁻⁸ m (+10 %). What does not:
/// at smaller h_m the seed's deformation column (3.48, 5.6, 8.37 ×10⁷ Pa) lies 14–43 % above
/// ours (3.05, 4.43, 5.87 ×10⁷ Pa) and its Table 3.5 claim that deformation exactly compensates
/// piezoviscosity at α = 1.1×10⁻⁸ is not found (ours 4.76×10⁷ vs rigid isoviscous 6.17×10⁷):
/// with the seed's kernel unknown, these are regression targets only (our values ±2 %). The
/// seed's load column (4.871…4.521 "10³ N") is ≈ 2.3× the load from (3.78) (flag F-70): our
/// converged load at 1 µm is 2002 N/m; only its ratio iteration 5/iteration 0 = 0.928 is
/// comparable with our elastic/rigid ratio 2002/2119 = 0.945.
#[test]
fn seed_tables_with_deformation() {
    let plate = Arc::new(ElasticLayer::bonded(0.05, 2.1e11, 0.3));
    let mut c = rigid();
    c.compliance = Compliance::Sum(vec![
        Compliance::Layer(plate),
        Compliance::HalfSpace(HalfSpace::roller_on_axis(R, 2.1e11, 0.3)),
    ]);
    let b = Barus {
        mu0: MU,
        alpha: 0.75e-8,
    };
    let opt = LineContactOptions {
        damping: false,
        nodes: 400,
        ..Default::default()
    };
    let res = solve(&c, &b, Constraint::RigidApproach(1e-6), &opt).unwrap();
    assert!(res.converged);
    assert!(
        (res.max_pressure_pa / 1.22687e7 - 1.0).abs() < 0.015,
        "{}",
        res.max_pressure_pa
    );
    let dmax = res
        .film
        .iter()
        .map(|(x, h)| h - 1e-6 - x * x / (2.0 * R))
        .fold(f64::MIN, f64::max);
    assert!((dmax / 5.54e-8 - 1.0).abs() < 0.15, "{dmax}");
    let rig = solve(&rigid(), &b, Constraint::RigidApproach(1e-6), &opt).unwrap();
    assert!((res.load_per_length_n_per_m / rig.load_per_length_n_per_m - 0.945).abs() < 0.01);
    for (h, ours) in [(5e-7, 3.0516e7), (3.5e-7, 4.4348e7), (2.5e-7, 5.8658e7)] {
        let r = solve(&c, &b, Constraint::RigidApproach(h), &opt).unwrap();
        assert!(
            r.converged && (r.max_pressure_pa / ours - 1.0).abs() < 0.02,
            "{h}: {}",
            r.max_pressure_pa
        );
    }
}

fn ehl_contact(um: f64) -> LubricatedLineContact {
    let mut c = LubricatedLineContact::new(0.01, 2.0 * um);
    c.compliance = Compliance::HalfSpace(HalfSpace::pair(2.06e11, 0.3, 2.06e11, 0.3, 1.0));
    c.density = Density::DowsonHigginson;
    c
}

/// Heavily loaded EHL line contact against the film formulas (written here, standard forms not
/// in the seeds), R = 10 mm, u_m = 1 m/s, μ₀ = 0.04 Pa·s, α = 2×10⁻⁸ 1/Pa (Roelands with the same
/// initial slope), Dowson–Higginson density, E′ = 2.26×10¹¹ Pa (G = 4530, U = 1.8×10⁻¹¹,
/// W′ = 1.3×10⁻⁴ … 1.3×10⁻³, i.e. p_h = 1.0 … 3.3 GPa):
/// Pan–Hamrock H_min = 1.714 W′^−0.128 U^0.694 G^0.568, H_c = 2.922 W′^−0.166 U^0.692 G^0.470;
/// Dowson–Higginson H_min = 2.65 U^0.70 G^0.54 W′^−0.13.
/// Obtained (1000 nodes): h_min +5 % / +5 % / +1 % against Pan–Hamrock and −2 % / −2 % / −6 %
/// against Dowson–Higginson; h_c +8 % / +10 % / +10 % against Pan–Hamrock. Tolerances: h_min 10 %
/// (both formulas are curve fits of ±5–10 % to numerical solutions with different grids and
/// viscosity laws), h_c 15 % (Pan–Hamrock's central-film fit is the looser one).
#[test]
fn ehl_films_against_pan_hamrock_and_dowson_higginson() {
    let ep = 2.06e11 / (1.0 - 0.09);
    let vis = Roelands::from_alpha(0.04, 2e-8);
    for w in [3e5, 1e6, 3e6] {
        let res = solve(
            &ehl_contact(1.0),
            &vis,
            Constraint::LoadPerLength(w),
            &LineContactOptions {
                damping: false,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(res.converged, "{w}");
        let (u, wd, g, r) = (0.04 / (ep * 0.01), w / (ep * 0.01), 2e-8 * ep, 0.01);
        let ph_min = 1.714 * wd.powf(-0.128) * u.powf(0.694) * g.powf(0.568) * r;
        let ph_c = 2.922 * wd.powf(-0.166) * u.powf(0.692) * g.powf(0.470) * r;
        let dh_min = 2.65 * u.powf(0.70) * g.powf(0.54) * wd.powf(-0.13) * r;
        assert!(
            (res.min_film_m / ph_min - 1.0).abs() < 0.10,
            "{w}: {} {ph_min}",
            res.min_film_m
        );
        assert!(
            (res.min_film_m / dh_min - 1.0).abs() < 0.10,
            "{w}: {} {dh_min}",
            res.min_film_m
        );
        assert!(
            (res.central_film_m / ph_c - 1.0).abs() < 0.15,
            "{w}: {} {ph_c}",
            res.central_film_m
        );
        // the load is met and the pressure maximum is Hertzian (within the spike)
        let load: f64 = res.load_per_length_n_per_m;
        assert!((load / w - 1.0).abs() < 1e-6);
        assert!(res.max_pressure_pa > 0.95 * res.hertz_pressure_pa);
    }
}

/// Pressure spike at high speed: at u_m = 10 m/s and w = 3×10⁵ N/m (p_h = 1.04 GPa) a second
/// pressure maximum appears near the outlet (x ≈ 0.78 b) and exceeds the central pressure
/// (1.18 p_h vs 0.98 p_h); at u_m = 0.5 m/s the outlet bump stays below the centre (0.57 p_h).
#[test]
fn pressure_spike_visible_at_high_speed() {
    let vis = Roelands::from_alpha(0.04, 2e-8);
    let spike = |um: f64| -> (f64, f64, f64) {
        let res = solve(
            &ehl_contact(um),
            &vis,
            Constraint::LoadPerLength(3e5),
            &LineContactOptions {
                damping: false,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(res.converged);
        let b = res.hertz_half_width_m;
        let p = &res.pressure;
        // largest local maximum in the outlet half 0.3 b < x < 1.2 b, and the pressure at x = 0
        let mut best = (0.0, 0.0);
        for i in 1..p.len() - 1 {
            let (x, v) = p[i];
            if x > 0.3 * b && x < 1.2 * b && v > p[i - 1].1 && v >= p[i + 1].1 && v > best.1 {
                best = (x / b, v);
            }
        }
        let centre = p
            .iter()
            .min_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))
            .map(|v| v.1)
            .unwrap_or(0.0);
        (
            best.0,
            best.1 / res.hertz_pressure_pa,
            centre / res.hertz_pressure_pa,
        )
    };
    let (x_hi, spike_hi, centre_hi) = spike(10.0);
    assert!(
        spike_hi > 1.05 * centre_hi && x_hi > 0.6 && x_hi < 1.0,
        "{x_hi} {spike_hi} {centre_hi}"
    );
    let (_, spike_lo, centre_lo) = spike(0.5);
    assert!(spike_lo < centre_lo);
}

/// Inverse mode (given load) and direct modes agree: (a) seed plate + roller kernels, rigid
/// approach 1 µm → load → back to the approach (to 10⁻⁴ relative, the Newton tolerance on a
/// quantity that is a small difference of deflection and film); (b) EHL at 5×10⁵ N/m → minimum
/// film → load back to 0.1 % on the same domain (the discrete minimum is parabola-interpolated,
/// and the load is ~8 times more sensitive than h_min, h_min ∝ W^−0.13).
#[test]
fn inverse_and_direct_modes_agree() {
    let plate = Arc::new(ElasticLayer::bonded(0.05, 2.1e11, 0.3));
    let mut c = rigid();
    c.compliance = Compliance::Sum(vec![
        Compliance::Layer(plate),
        Compliance::HalfSpace(HalfSpace::roller_on_axis(R, 2.1e11, 0.3)),
    ]);
    let b = Barus {
        mu0: MU,
        alpha: 0.75e-8,
    };
    let opt = LineContactOptions {
        damping: false,
        nodes: 300,
        ..Default::default()
    };
    let dir = solve(&c, &b, Constraint::RigidApproach(1e-6), &opt).unwrap();
    let opt_same = LineContactOptions {
        inlet: Some(dir.pressure[0].0),
        outlet: Some(dir.pressure[dir.pressure.len() - 1].0),
        ..opt
    };
    let inv = solve(
        &c,
        &b,
        Constraint::LoadPerLength(dir.load_per_length_n_per_m),
        &opt_same,
    )
    .unwrap();
    assert!(inv.converged);
    assert!(
        (inv.rigid_approach_m / 1e-6 - 1.0).abs() < 1e-4,
        "{}",
        inv.rigid_approach_m
    );

    let vis = Roelands::from_alpha(0.04, 2e-8);
    let c = ehl_contact(1.0);
    let inv = solve(&c, &vis, Constraint::LoadPerLength(5e5), &opt).unwrap();
    let opt_same = LineContactOptions {
        inlet: Some(inv.pressure[0].0),
        outlet: Some(inv.pressure[inv.pressure.len() - 1].0),
        ..opt
    };
    let mf = solve(&c, &vis, Constraint::MinFilm(inv.min_film_m), &opt_same).unwrap();
    assert!(
        (mf.load_per_length_n_per_m / 5e5 - 1.0).abs() < 1e-3,
        "{}",
        mf.load_per_length_n_per_m
    );
}

/// Bad input gives errors, not NaN.
#[test]
fn bad_input_is_rejected() {
    let still = LubricatedLineContact::new(R, 0.0);
    let e = solve(
        &still,
        &Isoviscous { mu: MU },
        Constraint::MinFilm(1e-6),
        &LineContactOptions::default(),
    );
    assert!(matches!(
        e,
        Err(ReynoldsError::InvalidInput { what: "speed", .. })
    ));
    let e = solve(
        &rigid(),
        &Isoviscous { mu: MU },
        Constraint::MinFilm(-1e-6),
        &LineContactOptions::default(),
    );
    assert!(e.is_err());
    let e = solve(
        &rigid(),
        &Isoviscous { mu: MU },
        Constraint::LoadPerLength(f64::NAN),
        &LineContactOptions::default(),
    );
    assert!(e.is_err());
}
