//! The finite journal-bearing land model (Reynolds crate) against the short-bearing formula on a
//! narrow cage rail, where short-bearing theory is close to exact: friction torques within 5 %
//! and eccentricities within 10 % (the Reynolds crate measured short-bearing theory up to 14 %
//! off its full solver at high eccentricity; at these light loads the film is nearly concentric).

use rolldyn_quasistatic::{CageLandInput, FiniteLand, QuasiStaticLandModel, ShortBearing};

#[test]
fn finite_land_agrees_with_short_bearing_on_a_narrow_rail() {
    let finite = FiniteLand::new(true);
    for load in [5.0, 50.0] {
        let input = CageLandInput {
            land_radius_m: 0.0865,
            rail_width_m: 0.004,
            rails: 2,
            radial_clearance_m: 0.25e-3,
            viscosity_pa_s: 0.005,
            cage_speed_rad_s: 306.0,
            land_speed_rad_s: 667.0,
            load_speed_rad_s: 0.0,
            roller_force_n: load,
            cage_mass_kg: 0.75,
        };
        let a = finite.evaluate(&input);
        let b = ShortBearing::default().evaluate(&input);
        assert!(
            a.torque_on_cage_n_m > 0.0,
            "the faster land drags the cage forward"
        );
        let dt = (a.torque_on_cage_n_m / b.torque_on_cage_n_m - 1.0).abs();
        assert!(
            dt < 0.05,
            "{load} N: torque {} vs {}",
            a.torque_on_cage_n_m,
            b.torque_on_cage_n_m
        );
        let de = (a.eccentricity_ratio - b.eccentricity_ratio).abs();
        assert!(
            de < 0.1,
            "{load} N: ε {} vs {}",
            a.eccentricity_ratio,
            b.eccentricity_ratio
        );
    }
}
