//! Light radial loads (F_r = 1…30 N) with radial clearance and misalignment and no centrifugal
//! force: the regime of roller skidding. Every case must solve, the rollers must balance F_r
//! and every roller must be in radial and moment equilibrium.
//!
//! Before the fix 259 of these 864 cases failed ("roller radial/moment balance did not
//! converge"): the roller residual scale collapsed to its 1e-12 N floor for barely loaded
//! rollers (Q ≈ 1e-17…1e-4 N, tolerance out of reach of the rounding of the slice approaches),
//! rollers that fit between the raceways only when tilted were iterated instead of returned
//! unloaded, and the stiffness of a roller pivoting about one edge slice was wrong (Newton
//! steps of the ring then overshot into the unloaded dead zone).

mod common;

use rolldyn_contact::roller_raceway::SliceLawChoice;
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_quasistatic::{LoadCase, LoadModel, QuasiStaticOptions};

fn bearings() -> Vec<(&'static str, CylindricalRollerBearing)> {
    vec![
        ("2002834", common::b2002834()),
        ("obrien-taylor", common::obrien_taylor()),
    ]
}

/// Checks one solved case; returns ΣQ_i/F_r or a description of the first violation.
fn check(model: &LoadModel, b: &CylindricalRollerBearing, c: &LoadCase) -> Result<f64, String> {
    let ld = model
        .solve(c, None, &QuasiStaticOptions::default())
        .map_err(|e| e.to_string())?;
    let fr = c.radial_load_n;
    let fx: f64 = ld
        .rollers
        .iter()
        .map(|r| r.inner_force_n * r.azimuth_rad.sin())
        .sum();
    let fy: f64 = ld
        .rollers
        .iter()
        .map(|r| r.inner_force_n * r.azimuth_rad.cos())
        .sum();
    let sum_q: f64 = ld.rollers.iter().map(|r| r.inner_force_n).sum();
    // Global equilibrium. The ring solve converges to load_tolerance·(F_r + ΣQ_i) =
    // 1e-12·(F_r + ΣQ_i) (each roller to 1e-13·max(its load, F_r/Z) or its rounding floor, a
    // fraction of that). Misalignment pinches rollers on both sides of the tilt axis, so ΣQ_i
    // can exceed F_r by far (≈ 2700 F_r for O'Brien–Taylor at F_r = 1 N, G = 10 µm, θ = 8′);
    // the bound is the 1e-9·F_r, or 10× the solver tolerance where the internal loads
    // make that the larger one.
    let tol = (1e-9 * fr).max(1e-11 * (fr + sum_q));
    if fx.abs() > tol || (fy - fr).abs() > tol {
        return Err(format!(
            "imbalance: Fx = {fx:e} N, Fy − F_r = {:e} N (ΣQ_i = {sum_q} N)",
            fy - fr
        ));
    }
    if ld.loaded_rollers == 0 {
        return Err("no roller loaded".into());
    }
    // every roller in radial and moment equilibrium, relative to its load with the floor F_r/Z
    // of the roller solve (the ring tolerance is absolute in F_r; 1e-9 as in
    // tests/load_distribution.rs)
    let floor = fr / b.roller_count as f64;
    for r in &ld.rollers {
        let li = model
            .inner_slices()
            .evaluate_totals(r.inner_approach_m, r.ring_tilt_rad - r.roller_tilt_rad);
        let lo = model
            .outer_slices()
            .evaluate_totals(r.outer_approach_m, r.roller_tilt_rad);
        let q = lo.force.max(floor);
        if (lo.force - li.force).abs() > 1e-9 * q
            || (lo.moment - li.moment).abs() > 1e-9 * q * 0.5 * b.roller.length
        {
            return Err(format!(
                "roller at ψ = {:.3}: Q_o − Q_i = {:e} N, M_o − M_i = {:e} N·m",
                r.azimuth_rad,
                lo.force - li.force,
                lo.moment - li.moment
            ));
        }
        // without centrifugal force an unloaded roller touches neither raceway (a roller just
        // touching may keep a force within the roller tolerance 1e-13·F_r/Z)
        if !r.loaded && (r.inner_force_n != 0.0 || r.outer_force_n > 1e-13 * floor) {
            return Err(format!(
                "unloaded roller at ψ = {:.3} carries Q_o = {:e} N",
                r.azimuth_rad, r.outer_force_n
            ));
        }
    }
    Ok(sum_q / fr)
}

#[test]
fn light_loads_with_clearance_and_misalignment_solve_and_balance() {
    let mut failures = Vec::new();
    let mut count = 0;
    let mut max_ratio = 0.0_f64;
    for (name, b) in bearings() {
        for law in [SliceLawChoice::Seed, SliceLawChoice::Iso] {
            let model = LoadModel::new(&b, law).unwrap();
            for fr in [1.0, 10.0, 30.0] {
                for g_um in [10.0, 20.0, 40.0, 60.0] {
                    for arcmin in [2.0, 4.0, 8.0] {
                        for azimuth in [0.0, 0.3, 1.0] {
                            for phase in [0.0, 0.1] {
                                count += 1;
                                let c = LoadCase {
                                    radial_load_n: fr,
                                    diametral_clearance_m: g_um * 1e-6,
                                    misalignment_rad: (arcmin / 60.0f64).to_radians(),
                                    misalignment_azimuth_rad: azimuth,
                                    centrifugal_force_n: 0.0,
                                    roller_phase_rad: phase,
                                };
                                match check(&model, &b, &c) {
                                    Ok(ratio) => max_ratio = max_ratio.max(ratio),
                                    Err(e) => failures.push(format!(
                                        "{name} {law:?} F_r = {fr} N, G = {g_um} µm, θ = {arcmin}′, \
                                         ψ_θ = {azimuth}, phase = {phase}: {e}"
                                    )),
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    for f in &failures {
        println!("{f}");
    }
    println!(
        "{} of {count} cases fail; largest ΣQ_i/F_r = {max_ratio:.1}",
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} of {count} cases fail",
        failures.len()
    );
}
