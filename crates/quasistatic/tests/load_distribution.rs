//! Load distribution among the rollers (SPEC §5.4 / F-43 proposal, slice model of SPEC §2.1)
//! against the classical closed forms, and the force balance to 1e-9.

mod common;

use rolldyn_contact::roller_raceway::SliceLawChoice;
use rolldyn_geometry::Profile;
use rolldyn_quasistatic::{LoadCase, LoadModel, QuasiStaticOptions};
use std::f64::consts::PI;

/// Exponent of the ISO/TS 16281 lamina law used for the closed-form checks.
const N: f64 = 10.0 / 9.0;

/// The O'Brien–Taylor bearing with a straight roller without chamfers and the ISO lamina law
/// on both raceways: every slice has the same approach, so one roller obeys exactly
/// Q = K δ^n with n = 10/9 (δ = total approach of both contacts) — the premise of the
/// classical closed forms.
fn power_law_model() -> LoadModel {
    power_law_model_z(13)
}

/// As [`power_law_model`] with `z` rollers (the load distribution does not check that the
/// rollers fit on the pitch circle: large `z` only serves the continuous-integral limit).
fn power_law_model_z(z: usize) -> LoadModel {
    let mut b = common::obrien_taylor();
    b.roller.profile = Profile::straight(0.5 * b.roller.length);
    b.roller_count = z;
    LoadModel::new(&b, SliceLawChoice::Iso).unwrap()
}

fn case(fr: f64, g: f64) -> LoadCase {
    LoadCase {
        radial_load_n: fr,
        diametral_clearance_m: g,
        misalignment_rad: 0.0,
        misalignment_azimuth_rad: 0.0,
        centrifugal_force_n: 0.0,
        roller_phase_rad: 0.0,
    }
}

#[test]
fn zero_clearance_matches_stribeck() {
    let model = power_law_model();
    let fr = 1000.0;
    let ld = model
        .solve(&case(fr, 0.0), None, &QuasiStaticOptions::default())
        .unwrap();
    let z = ld.rollers.len();
    // Exact discrete form for Q = K δ^n at zero clearance: Q_j = Q_max cos^n ψ_j on |ψ_j| < 90°,
    // and F_r = Σ Q_j cos ψ_j ⇒ Q_max = F_r / Σ cos^(n+1) ψ_j.
    let sum: f64 = ld
        .rollers
        .iter()
        .map(|r| r.azimuth_rad.cos())
        .filter(|c| *c > 0.0)
        .map(|c| c.powf(N + 1.0))
        .sum();
    let q_max = fr / sum;
    // 1e-9: the solver tolerance is 1e-12 relative; the closed form is exact for this model
    assert!(
        (ld.max_inner_load_n / q_max - 1.0).abs() < 1e-9,
        "{} vs {q_max}",
        ld.max_inner_load_n
    );
    for r in &ld.rollers {
        let c = r.azimuth_rad.cos();
        let expected = if c > 0.0 { q_max * c.powf(N) } else { 0.0 };
        assert!(
            (r.inner_force_n - expected).abs() < 1e-9 * q_max,
            "ψ = {}",
            r.azimuth_rad
        );
    }
    // Stribeck's constant for line contact: Z Q_max / F_r → 1/J = 4.08 for Z → ∞
    // (J = (1/2π)∫cos^(n+1)ψ dψ over the half circle = 0.2450 for n = 10/9). With Z = 13 the
    // discrete sum gives 4.093; accept 0.5 % (the discretisation difference is 0.3 %).
    let stribeck = z as f64 * ld.max_inner_load_n / fr;
    println!("Z = {z}: Z·Q_max/F_r = {stribeck:.4} (Stribeck line contact 4.08)");
    assert!((stribeck / 4.08 - 1.0).abs() < 5e-3, "{stribeck}");
    // force balance
    assert!(ld.force_residual_n[1].abs() < 1e-9 * fr);
    assert!(ld.force_residual_n[0].abs() < 1e-9 * fr);
    assert_eq!(ld.load_zone_half_angle_rad, PI);
}

/// Sjoväll / Harris load integral J_r(ε) with this file's exponent.
fn j_r(eps: f64) -> f64 {
    rolldyn_quasistatic::load_integral::radial_load_integral(eps, N)
}

#[test]
fn clearance_load_zone_matches_closed_forms() {
    let model = power_law_model();
    let fr = 1000.0;
    let mut last_zone = f64::INFINITY;
    let mut last_qmax = 0.0;
    println!("| G, µm | δ_r, µm | ε | ψ_l, ° | loaded | Z·Q_max/F_r | 1/J_r(ε) continuous |");
    for g_um in [2.0, 5.0, 10.0, 20.0, 40.0] {
        let g = g_um * 1e-6;
        let ld = model
            .solve(&case(fr, g), None, &QuasiStaticOptions::default())
            .unwrap();
        let delta = ld.ring_displacement_m[1];
        let q0 = ld.max_inner_load_n;
        // exact discrete form: Q_j^(1/n) ∝ (δ cos ψ_j − G/2) on the loaded rollers
        for r in &ld.rollers {
            let e = delta * r.azimuth_rad.cos() - 0.5 * g;
            if e > 0.0 {
                let expected = q0 * (e / (delta - 0.5 * g)).powf(N);
                assert!((r.inner_force_n - expected).abs() < 1e-9 * q0);
            } else {
                assert_eq!(
                    r.inner_force_n, 0.0,
                    "roller outside the load zone carries load"
                );
            }
        }
        // load-zone half angle ψ_l = acos(G/(2δ)), Sjoväll ε = ½(1 − G/(2δ))
        let zone = (0.5 * g / delta).acos();
        assert!((ld.load_zone_half_angle_rad - zone).abs() < 1e-12);
        let eps = 0.5 * (1.0 - 0.5 * g / delta);
        let z = ld.rollers.len() as f64;
        let ratio = z * q0 / fr;
        println!(
            "| {g_um} | {:.3} | {eps:.4} | {:.1} | {} | {ratio:.4} | {:.4} |",
            delta * 1e6,
            zone.to_degrees(),
            ld.loaded_rollers,
            1.0 / j_r(eps)
        );
        // clearance narrows the load zone and raises the largest roller load
        assert!(zone < last_zone && q0 > last_qmax);
        last_zone = zone;
        last_qmax = q0;
        assert!(ld.force_residual_n[1].abs() < 1e-9 * fr);
    }
    // continuous limit: with Z = 120 rollers the discrete sums approach the Sjoväll integral;
    // 0.5 % covers the remaining discretisation of the load-zone edge (observed ≤ 0.1 %)
    let model = power_law_model_z(120);
    for g_um in [0.0, 5.0, 20.0] {
        let g = g_um * 1e-6;
        let ld = model
            .solve(&case(fr, g), None, &QuasiStaticOptions::default())
            .unwrap();
        let delta = ld.ring_displacement_m[1];
        let eps = 0.5 * (1.0 - 0.5 * g / delta);
        let ratio = 120.0 * ld.max_inner_load_n / fr;
        let expected = 1.0 / j_r(eps);
        println!(
            "Z = 120, G = {g_um} µm: ε = {eps:.4}, Z·Q_max/F_r = {ratio:.4}, 1/J_r = {expected:.4}"
        );
        assert!(
            (ratio / expected - 1.0).abs() < 0.005,
            "{ratio} vs {expected}"
        );
    }
}

#[test]
fn force_balance_general_case_1e9() {
    // 2002834: seed slice laws (2.3)/(2.4) with different exponents, crowned roller, 8′
    // misalignment, centrifugal force, a roller off the load line and both clearance and preload
    let b = common::b2002834();
    let model = LoadModel::new(&b, SliceLawChoice::Seed).unwrap();
    for g in [20e-6, 0.0, -5e-6] {
        let c = LoadCase {
            radial_load_n: 5000.0,
            diametral_clearance_m: g,
            misalignment_rad: (8.0 / 60.0f64).to_radians(),
            misalignment_azimuth_rad: 0.3,
            centrifugal_force_n: 120.0,
            roller_phase_rad: 0.1,
        };
        let ld = model
            .solve(&c, None, &QuasiStaticOptions::default())
            .unwrap();
        let [fx, fy] = common::ring_force(&ld);
        assert!(fx.abs() < 1e-9 * c.radial_load_n, "G = {g}: Fx = {fx}");
        assert!(
            (fy - c.radial_load_n).abs() < 1e-9 * c.radial_load_n,
            "G = {g}: Fy = {fy}"
        );
        // every roller in radial and moment equilibrium (friction neglected, seed 001)
        for r in &ld.rollers {
            let (li, lo) = common::raceway_loads(&model, r);
            let q = lo.force.max(1.0);
            assert!((lo.force - li.force - c.centrifugal_force_n).abs() < 1e-9 * q);
            assert!((lo.moment - li.moment).abs() < 1e-9 * q * 0.5 * b.roller.length);
        }
    }
}

#[test]
fn centrifugal_force_loads_the_outer_raceway_in_the_unloaded_zone() {
    let model = power_law_model();
    let c = LoadCase {
        centrifugal_force_n: 30.0,
        ..case(200.0, 10e-6)
    };
    let ld = model
        .solve(&c, None, &QuasiStaticOptions::default())
        .unwrap();
    for r in &ld.rollers {
        assert!((r.outer_force_n - r.inner_force_n - 30.0).abs() < 1e-9 * r.outer_force_n);
        if !r.loaded {
            assert_eq!(r.inner_force_n, 0.0);
        }
    }
    assert!(ld.rollers.iter().any(|r| !r.loaded));
}

/// A raceway wear map enters the slice drops by its circumferential mean at each slice (the
/// axisymmetric reading of a worn raceway).
#[test]
fn a_raceway_wear_map_deepens_the_slice_drops_by_its_mean() {
    let mut b = common::obrien_taylor();
    let unworn = LoadModel::new(&b, SliceLawChoice::Iso).unwrap();
    let half = 0.5 * b.roller.length;
    // 2 µm and 4 µm on two bins at one end, 0 at the other: mean 3 µm → 0 linearly
    let map =
        rolldyn_geometry::RacewayWearMap::new(vec![-half, half], 2, vec![2e-6, 4e-6, 0.0, 0.0])
            .unwrap();
    b.inner_ring.raceway_wear = Some(map);
    let worn = LoadModel::new(&b, SliceLawChoice::Iso).unwrap();
    let (a, w) = (unworn.inner_slices(), worn.inner_slices());
    for ((&x, &d0), &d1) in a.positions().iter().zip(a.drops()).zip(w.drops()) {
        let mean = 3e-6 * (half - x) / (2.0 * half);
        assert!((d1 - d0 - mean).abs() < 1e-15, "x {x}: {d0} → {d1}");
    }
    assert_eq!(unworn.outer_slices().drops(), worn.outer_slices().drops());
}
