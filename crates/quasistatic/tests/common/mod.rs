#![allow(dead_code)]
//! Shared helpers of the quasi-static tests: the example bearings of the repository.

use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use rolldyn_quasistatic::SkidResult;

/// Loads `examples/<name>` (a cylindrical bearing).
pub fn example(name: &str) -> CylindricalRollerBearing {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    let model = rolldyn_model::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    match model.bearing {
        BearingModel::Cylindrical(b) => b,
        other => panic!("{name} is not a cylindrical bearing: {other:?}"),
    }
}

/// The O'Brien–Taylor bearing (seed 000 Table 2.2).
pub fn obrien_taylor() -> CylindricalRollerBearing {
    example("obrien-taylor.toml")
}

/// Bearing 2002834 (seed 000 §3.1.1, SPEC F-02 geometry).
pub fn b2002834() -> CylindricalRollerBearing {
    example("2002834.toml")
}

/// Asserts that every number of a result is finite (the "never NaN" guarantee).
pub fn assert_finite(r: &SkidResult) {
    let mut all = vec![
        r.cage_speed_rad_s,
        r.epicyclic_cage_speed_rad_s,
        r.cage_slip,
        r.max_roller_load_n,
        r.operating_clearance_m,
        r.power_loss_w,
        r.power_input_w,
        r.cage.residual_n_m,
        r.cage.pressing_force_n,
        r.residuals.cage_moment_relative,
        r.residuals.roller_moment_relative,
        r.residuals.force_balance_relative,
    ];
    for x in &r.rollers {
        for c in [&x.inner, &x.outer] {
            all.extend([
                c.normal_force_n,
                c.max_pressure_pa,
                c.rolling_speed_m_s,
                c.sliding_speed_m_s,
                c.slide_roll_ratio,
                c.friction_coefficient,
                c.temperature_k,
                c.power_w,
            ]);
            all.extend(c.film_central_m);
            all.extend(c.lambda);
            all.extend(c.scuffing_margin);
        }
        all.extend([x.spin_rad_s, x.slip, x.bar.normal_force_n, x.power_w]);
    }
    for (k, v) in all.iter().enumerate() {
        assert!(v.is_finite(), "value #{k} is not finite: {v}");
    }
}

/// Force of the rollers on the inner ring (Σ Q_i sin ψ, Σ Q_i cos ψ), N: the radial load it
/// balances (along +y).
pub fn ring_force(ld: &rolldyn_quasistatic::LoadDistribution) -> [f64; 2] {
    ld.rollers.iter().fold([0.0, 0.0], |[x, y], r| {
        let (s, c) = r.azimuth_rad.sin_cos();
        [x + r.inner_force_n * s, y + r.inner_force_n * c]
    })
}

/// Slice totals of one solved roller against the inner and outer raceway.
pub fn raceway_loads(
    model: &rolldyn_quasistatic::LoadModel,
    r: &rolldyn_quasistatic::RollerLoad,
) -> (
    rolldyn_contact::slices::SliceLoad,
    rolldyn_contact::slices::SliceLoad,
) {
    let li = model
        .inner_slices()
        .evaluate_totals(r.inner_approach_m, r.ring_tilt_rad - r.roller_tilt_rad);
    let lo = model
        .outer_slices()
        .evaluate_totals(r.outer_approach_m, r.roller_tilt_rad);
    (li, lo)
}
