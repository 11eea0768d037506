//! Issue 22 item 5: `converged` means the cage moment residual passed its test; a point
//! whose iteration stopped without meeting it is an error, never a "converged" result.

mod common;

use rolldyn_geometry::BearingModel;
use rolldyn_quasistatic::{QsError, QuasiStaticConditions, QuasiStaticOptions, solve};

/// Bearing 2002834 whose cage is absurdly heavy (~1e306 kg, the mass of a cage 1e308 mm wide,
/// which the model file now rejects): the cage equation cannot balance between the ring speeds. Before the fix the solver returned slip 1.0
/// flagged converged with a relative cage moment residual of ~1.
#[test]
fn an_unbalanced_cage_is_not_reported_as_converged() {
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
    let BearingModel::Cylindrical(mut bearing) = model.bearing else {
        unreachable!("2002834 is cylindrical")
    };
    let cage = bearing.cage.as_mut().expect("2002834 has a cage");
    cage.mass_properties = cage.mass_properties.scaled(1e306);
    let oil = model.lubrication.expect("2002834 has a lubricant").oil;
    let rpm = std::f64::consts::PI / 30.0;
    let c = QuasiStaticConditions::new(6371.0 * rpm, 0.0, 1000.0, oil, 373.15);
    let options = QuasiStaticOptions::default();
    match solve(&bearing, &c, &options) {
        Ok(r) => {
            assert!(
                r.residuals.cage_moment_relative.abs()
                    <= options.cage_tolerance * options.cage_residual_slack,
                "converged = {} with cage moment residual {}",
                r.converged,
                r.residuals.cage_moment_relative
            );
            assert!(r.converged);
        }
        Err(e) => assert!(matches!(e, QsError::NotConverged { .. }), "{e}"),
    }
}
