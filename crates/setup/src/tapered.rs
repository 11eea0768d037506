//! The double-row tapered bearing's dynamics from a model file (seed 000 §3.2.1).

use crate::{Overrides, SetupError, conditions, quasi_static};
use rolldyn_dynamics::conditions::InnerRingSupport;
use rolldyn_dynamics::tapered::{TaperedModel, TaperedParameters};
use rolldyn_geometry::BearingModel;

/// The tapered dynamics model of `model` with the overrides: the operating section's speed,
/// radial load (−y), axial load (+z) and oil temperature; the misalignment tilts the inner
/// ring in the plane of the radial load (seed 000 §3.2.1 case 3: "in the plane of the bearing
/// axis and the radial force", i.e. about x); the inner-ring assembly translates freely (its
/// axial play is an output, seed 000 Fig. 3.75).
pub fn prepare_tapered(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
) -> Result<TaperedModel, SetupError> {
    let BearingModel::Tapered(bearing) = &model.bearing else {
        return Err(model
            .source
            .error(
                "bearing.kind",
                "the tapered dynamics needs a double-row tapered bearing",
            )
            .into());
    };
    let lubrication = quasi_static::lubrication(model, "simulate")?;
    quasi_static::check_traction_oil(model, lubrication)?;
    let mut c = conditions(overrides, model)?;
    c.misalignment_azimuth_rad = -std::f64::consts::FRAC_PI_2;
    c.support = InnerRingSupport {
        radial_free: true,
        axial_free: true,
        mass_kg: None,
    };
    let traction = lubrication
        .traction_model()
        .map_err(|e| model.source.error("lubricant", e.to_string()))?;
    TaperedModel::new(
        bearing,
        c,
        TaperedParameters::for_bearing(bearing),
        traction,
    )
    .map_err(|e| SetupError(e.to_string()))
}
