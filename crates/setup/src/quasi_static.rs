//! From a model file to a quasi-static operating point (SPEC §5.6 "input"): the one mapping of
//! `[operating]` and `[lubricant]` to quasi-static conditions, the raceway friction law and the
//! cage–land model. Shared by `rolldyn skid`, `sweep`, `demo` and the quasi-static start of a
//! dynamics run.

use crate::SetupError;
use rolldyn_dynamics::conditions::OperatingConditions;
use rolldyn_geometry::{CageGuidance, CylindricalRollerBearing};
use rolldyn_lubrication::{FilmFormula, MurakiSettings};
use rolldyn_model::CageLandLaw;
use rolldyn_model::{Lubrication, Model, Temperatures};
use rolldyn_quasistatic::{
    ContactLand, FiniteLand, FrictionModel, QuasiStaticConditions, QuasiStaticLandModel,
    ShortBearing,
};

/// Raceway friction law of a quasi-static point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RacewayFriction {
    /// Muraki EHL traction (seed 000) with the model's rheology.
    #[default]
    Muraki,
    /// Asperity fraction + film shear + flash temperature (seed 001).
    Seed001,
}

/// Cage–guiding-land model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LandChoice {
    /// Finite journal bearing (Reynolds crate table, SPEC §8.6): the land of the dynamics.
    #[default]
    Finite,
    /// Short (Ocvirk) journal bearing (SPEC §5.5).
    Short,
}

/// Values that override the model's `[operating]` section for a quasi-static point, SI.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct QuasiStaticOverrides {
    pub speed: Option<f64>,
    pub outer_speed: Option<f64>,
    pub radial_load: Option<f64>,
    /// Part temperatures given on the command line; a part not given takes the model's value,
    /// then the oil temperature.
    pub temperatures: Temperatures,
    pub friction: RacewayFriction,
}

/// The `[lubricant]` section, or an error naming the command that needs it.
pub fn lubrication<'m>(model: &'m Model, command: &str) -> Result<&'m Lubrication, SetupError> {
    Ok(model.lubrication.as_ref().ok_or_else(|| {
        model.source.error(
            "lubricant",
            format!("{command} needs a [lubricant] section"),
        )
    })?)
}

/// Checks that the oil of `model` has every property the traction model (Muraki EHL) needs:
/// a missing one is bad input named at `[lubricant]`, not a failure of the run.
pub fn check_traction_oil(model: &Model, lubrication: &Lubrication) -> Result<(), SetupError> {
    lubrication
        .traction_model()
        .map(|_| ())
        .map_err(|e| model.source.error("lubricant", e.to_string()).into())
}

/// Muraki traction with the model's rheology, no mixed-friction blend, automatic film formula
/// (seed 000 §2.4).
pub fn muraki_friction(lubrication: &Lubrication) -> FrictionModel {
    FrictionModel::Muraki {
        settings: MurakiSettings {
            rheology: lubrication.rheology,
            ..MurakiSettings::default()
        },
        mixed: None,
        film: FilmFormula::Auto,
    }
}

/// The quasi-static operating point of `model`, overridden by `overrides`: speeds, radial load
/// (turning with the inner ring when the model's load rotates), part temperatures (oil temperature for the parts neither given), the bearing's ring tilt and
/// the raceway friction law.
pub fn quasi_static_conditions(
    model: &Model,
    overrides: &QuasiStaticOverrides,
) -> Result<QuasiStaticConditions, SetupError> {
    let op = &model.operating;
    let lubrication = lubrication(model, "skid")?;
    crate::FlagValues {
        speed: overrides.speed,
        outer_speed: overrides.outer_speed,
        radial_load: overrides.radial_load,
        ..Default::default()
    }
    .check(model)?;
    let inner = overrides.speed.or(op.inner_speed).ok_or_else(|| {
        model.source.error(
            "operating.inner_speed",
            "no inner-ring speed: give --speed or operating.inner_speed",
        )
    })?;
    let outer = overrides.outer_speed.or(op.outer_speed).unwrap_or(0.0);
    let load = overrides.radial_load.or(op.radial_load).ok_or_else(|| {
        model.source.error(
            "operating.radial_load",
            "no radial load: give --radial-load or operating.radial_load",
        )
    })?;
    let given = &overrides.temperatures;
    let file = &op.temperatures;
    let oil = given.oil.or(file.oil).ok_or_else(|| {
        model.source.error(
            "operating.temperatures.oil",
            "no oil temperature: give --temperatures oil=… or operating.temperatures.oil",
        )
    })?;
    let mut c = QuasiStaticConditions::new(inner, outer, load, lubrication.oil.clone(), oil);
    if op.load_rotates {
        // the land film sees the load zone turn with the inner ring (theory §6.5)
        c.load_speed_rad_s = inner;
    }
    let part = |given: Option<f64>, file: Option<f64>| given.or(file).unwrap_or(oil);
    let t = &mut c.temperatures;
    t.inner_ring = part(given.inner_ring, file.inner_ring);
    t.outer_ring = part(given.outer_ring, file.outer_ring);
    t.rollers = part(given.rollers, file.rollers);
    t.cage = part(given.cage, file.cage);
    t.shaft = part(given.shaft, file.shaft);
    t.housing = part(given.housing, file.housing);
    let tilt = model.bearing.misalignment().inner_ring_tilt;
    c.misalignment_rad = (tilt != 0.0).then_some(tilt);
    c.drag = drag_inputs(model, oil)?;
    c.friction = match overrides.friction {
        RacewayFriction::Muraki => {
            check_traction_oil(model, lubrication)?;
            muraki_friction(lubrication)
        }
        RacewayFriction::Seed001 => FrictionModel::Seed001(Default::default()),
    };
    Ok(c)
}

/// The model's drag inputs at oil temperature `oil_temperature_k`, the same as the dynamics'
/// (SPEC §3.6): its linear cage drag `[dynamics] cage_drag` when it gives one (else seed 001's
/// mixture formula), its oil volume fraction and its roller drag ([`crate::roller_drag_factor`]).
pub fn drag_inputs(
    model: &Model,
    oil_temperature_k: f64,
) -> Result<rolldyn_quasistatic::DragInputs, SetupError> {
    let mut d = rolldyn_quasistatic::DragInputs {
        viscous_coefficient_n_m_s: model.dynamics.cage_drag_n_m_s,
        roller_drag_kg_m: crate::roller_drag_factor(model, oil_temperature_k)?,
        ..Default::default()
    };
    if let Some(chi) = model.dynamics.oil_volume_fraction {
        d.oil_volume_fraction = chi;
    }
    Ok(d)
}

/// The cage–land model of `bearing` (the finite land on the ring that guides the cage).
pub fn cage_land_model(
    bearing: &CylindricalRollerBearing,
    land: LandChoice,
) -> Box<dyn QuasiStaticLandModel> {
    match land {
        LandChoice::Finite => {
            let inner_land = bearing
                .cage
                .as_ref()
                .is_some_and(|c| c.guidance == CageGuidance::InnerLand);
            Box::new(FiniteLand::new(inner_land))
        }
        LandChoice::Short => Box::new(ShortBearing::default()),
    }
}

/// The quasi-static land matching the dynamics' land law of `[dynamics] cage_land_law`: the
/// finite journal bearing for "hydrodynamic" (the film of the dynamics'
/// `HydrodynamicLand`, filled to `[dynamics] cage_land_fill`), [`ContactLand`] with the model's
/// pair-14 parameters for "contact".
pub fn matching_land_model(
    bearing: &CylindricalRollerBearing,
    inputs: &rolldyn_model::DynamicsInputs,
) -> Box<dyn QuasiStaticLandModel> {
    match inputs.cage_land_law {
        CageLandLaw::Hydrodynamic => {
            let inner_land = bearing
                .cage
                .as_ref()
                .is_some_and(|c| c.guidance == CageGuidance::InnerLand);
            let mut land = FiniteLand::new(inner_land);
            land.fill_fraction = inputs.cage_land_fill.unwrap_or(1.0);
            Box::new(land)
        }
        CageLandLaw::Contact => Box::new(ContactLand {
            friction: crate::contact_parameters(bearing, inputs)
                .cage_land
                .friction,
        }),
    }
}

/// The quasi-static point of a dynamics start (issue 6): the dynamics' speeds, oil and part
/// temperatures at t = 0, its linear cage drag, Muraki friction with the model's rheology. The
/// radial load is the r.m.s. over a shaft revolution of the vector sum of the fixed and rotating
/// loads, √(|F_fixed|² + |F_rot|²) (their cross term averages out); its direction turns with the
/// inner ring when the rotating part is the larger (the land film then sees a rotating load).
/// A clearance the bearing marks as operating (`Clearance::radial_is_operating`) is taken as
/// such by the quasi-static model itself.
pub fn dynamics_start_conditions(
    conditions: &OperatingConditions,
    lubrication: &Lubrication,
) -> QuasiStaticConditions {
    let (wi, wo) = (
        conditions.inner_speed.speed(0.0),
        conditions.outer_speed.speed(0.0),
    );
    let fixed_xyz = conditions.fixed_force(0.0);
    let fixed = fixed_xyz[0].hypot(fixed_xyz[1]);
    let rotating = conditions.rotating_force_magnitude(0.0);
    let t = conditions.temperatures;
    let mut qs = QuasiStaticConditions::new(
        wi,
        wo,
        fixed.hypot(rotating),
        lubrication.oil.clone(),
        t.inner_raceway_k,
    );
    if rotating > fixed {
        qs.load_speed_rad_s = wi;
    }
    qs.temperatures.outer_ring = t.outer_raceway_k;
    qs.temperatures.cage = t.cage_k;
    // the dynamics' drag law, so that the start is the dynamics' own steady state
    qs.drag.viscous_coefficient_n_m_s = Some(conditions.cage_drag_n_m_s);
    qs.drag.roller_drag_kg_m = conditions.roller_drag_kg_m;
    qs.friction = muraki_friction(lubrication);
    // the dynamics' misalignment (a command-line override included), not the model file's
    qs.misalignment_rad = Some(conditions.misalignment_rad);
    qs
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A load rotating with the inner ring (2002834) turns the land film's load with it; a
    /// fixed one (O'Brien–Taylor) does not.
    #[test]
    fn rotating_load_turns_with_the_inner_ring() {
        for (text, rotates) in [
            (include_str!("../../../examples/2002834.toml"), true),
            (include_str!("../../../examples/obrien-taylor.toml"), false),
        ] {
            let model = rolldyn_model::parse(text, "m.toml").unwrap();
            let c = quasi_static_conditions(&model, &QuasiStaticOverrides::default()).unwrap();
            let expected = if rotates { c.inner_speed_rad_s } else { 0.0 };
            assert_eq!(c.load_speed_rad_s, expected);
        }
    }

    /// Flags win over the file; parts not given take the file's value, then the oil's.
    #[test]
    fn overrides_and_part_temperatures() {
        let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "m.toml").unwrap();
        let overrides = QuasiStaticOverrides {
            radial_load: Some(1234.0),
            temperatures: Temperatures {
                oil: Some(330.0),
                cage: Some(340.0),
                ..Default::default()
            },
            ..Default::default()
        };
        let c = quasi_static_conditions(&model, &overrides).unwrap();
        assert_eq!(c.radial_load_n, 1234.0);
        assert_eq!(c.inner_speed_rad_s, model.operating.inner_speed.unwrap());
        assert_eq!(c.temperatures.cage, 340.0);
        let file_or_oil = model.operating.temperatures.housing.unwrap_or(330.0);
        assert_eq!(c.temperatures.housing, file_or_oil);
    }
}
