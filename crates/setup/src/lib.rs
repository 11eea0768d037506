//! From a model file to a dynamics run (SPEC §3.7–3.8): the operating conditions of the
//! `[operating]` section with its schedules, loads and frozen points, the contact parameters of
//! `[dynamics]` (SPEC Table 2.1), and a [`Simulation`] started at the quasi-static cage speed
//! with the cage-land law of `[dynamics] cage_land_law` (hydrodynamic land or plain contact). Shared by `rolldyn simulate`, `sweep`, `startup` and `demo`;
//! [`speed`] times such runs for `rolldyn bench`.

pub mod quasi_static;
pub mod speed;
mod tapered;

pub use tapered::prepare_tapered;

use rolldyn_dynamics::conditions::{ContactTemperatures, InnerRingLoad, OperatingConditions};
use rolldyn_dynamics::parameters::ContactParameters;
use rolldyn_dynamics::settings::DynamicsSettings;
use rolldyn_dynamics::{RacewayTraction, Simulation};
use rolldyn_model::CageLandLaw;

/// The model cannot be turned into a simulation (missing section, bad override, invalid
/// parameters). One line naming what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct SetupError(pub String);

impl From<rolldyn_model::ModelError> for SetupError {
    fn from(e: rolldyn_model::ModelError) -> Self {
        Self(e.to_string())
    }
}

impl From<rolldyn_geometry::GeometryError> for SetupError {
    /// A flag out of its bounds: `--flag: reason`.
    fn from(e: rolldyn_geometry::GeometryError) -> Self {
        Self(e.to_string())
    }
}

/// Command-line values checked against the plausibility bounds of [`rolldyn_model::bounds`]
/// (a radial load must not be negative nor press beyond any material), SI; an error names the
/// flag.
#[derive(Debug, Clone, Copy, Default)]
pub struct FlagValues {
    pub speed: Option<f64>,
    pub outer_speed: Option<f64>,
    pub radial_load: Option<f64>,
    pub oil_temperature: Option<f64>,
}

impl FlagValues {
    pub fn check(&self, model: &rolldyn_model::Model) -> Result<(), SetupError> {
        use rolldyn_model::bounds::{check_radial_load, check_speed, check_temperature};
        for (flag, speed) in [("--speed", self.speed), ("--outer-speed", self.outer_speed)] {
            if let Some(w) = speed {
                check_speed(&model.bearing, flag, w)?;
            }
        }
        if let Some(load) = self.radial_load {
            check_radial_load(&model.bearing, "--radial-load", load)?;
        }
        if let Some(t) = self.oil_temperature {
            check_temperature("--oil-temperature", t)?;
        }
        Ok(())
    }
}

/// Direction of the main radial load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadDirection {
    /// fixed in space
    Fixed,
    /// rotating with the inner ring
    Rotating,
}

/// Values given on the command line (or by a study) that override the model's `[operating]`
/// section, SI.
#[derive(Clone, Copy, Default)]
pub struct Overrides {
    pub speed: Option<f64>,
    pub outer_speed: Option<f64>,
    pub radial_load: Option<f64>,
    /// axial load on the inner ring along +z, N
    pub axial_load: Option<f64>,
    pub load_direction: Option<LoadDirection>,
    pub oil_temperature: Option<f64>,
    /// inner-ring tilt, rad (overrides misalignment.inner_ring)
    pub misalignment: Option<f64>,
}

/// Operating conditions from the model's `[operating]` section and the overrides (oil
/// temperature of a schedule taken at t = 0: contact temperatures are constant during a run).
pub fn conditions(
    args: &Overrides,
    model: &rolldyn_model::Model,
) -> Result<OperatingConditions, SetupError> {
    conditions_with_temperature_at(args, model, 0.0)
}

/// The conditions of `model` frozen at time `t` of its schedules (seed 000 §3.1.2, SPEC
/// §3.1): constant speed, loads, clearance and oil temperature equal to their values at `t`
/// ([`OperatingConditions::frozen_at`]; a load step takes its value before the step at the
/// step time itself).
pub fn frozen_conditions(
    args: &Overrides,
    model: &rolldyn_model::Model,
    t: f64,
) -> Result<OperatingConditions, SetupError> {
    Ok(conditions_with_temperature_at(args, model, t)?.frozen_at(t))
}

/// SPEC §3.7: speed (constant or schedule), the main radial load (fixed or rotating), the
/// unbalance `U ω²`, the fixed loads with their steps, the clearance schedule and the oil
/// temperature (constant, or its schedule at `t_temperature`). Overrides win: `--speed`
/// replaces a speed schedule by a constant, `--radial-load` sets the main radial load (the
/// unbalance and `[[operating.loads]]` still apply), `--oil-temperature` replaces the oil
/// temperature schedule and the part temperatures.
fn conditions_with_temperature_at(
    args: &Overrides,
    model: &rolldyn_model::Model,
    t_temperature: f64,
) -> Result<OperatingConditions, SetupError> {
    use rolldyn_dynamics::conditions::SpeedLaw;
    let op = &model.operating;
    let sched = &model.schedules;
    FlagValues {
        speed: args.speed,
        outer_speed: args.outer_speed,
        radial_load: args.radial_load,
        oil_temperature: args.oil_temperature,
    }
    .check(model)?;
    let speed = match (args.speed.or(op.inner_speed), &sched.speed) {
        (Some(w), _) => SpeedLaw::Constant(w),
        (None, Some(points)) => SpeedLaw::Schedule(points.clone()),
        (None, None) => {
            return Err(model.source.error(
                "operating.inner_speed",
                "no inner-ring speed: give --speed, operating.inner_speed or operating.speed_schedule",
            ).into());
        }
    };
    let load = args.radial_load.or(op.radial_load);
    if load.is_none() && sched.loads.is_empty() && op.unbalance.is_none() {
        return Err(model.source.error(
            "operating.radial_load",
            "no radial load: give --radial-load, operating.radial_load, operating.unbalance or [[operating.loads]]",
        ).into());
    }
    let oil_t = match (
        args.oil_temperature,
        op.temperatures.oil,
        &sched.oil_temperature,
    ) {
        (Some(t), _, _) | (None, Some(t), _) => t,
        (None, None, Some(points)) => {
            rolldyn_dynamics::conditions::piecewise_linear(points, t_temperature)
        }
        (None, None, None) => {
            return Err(model.source.error(
                "operating.temperatures.oil",
                "no oil temperature: give --oil-temperature, operating.temperatures.oil or operating.oil_temperature_schedule",
            ).into());
        }
    };
    let mut c = OperatingConditions::new(0.0, 0.0);
    c.inner_speed = speed;
    let rotating = match args.load_direction {
        Some(d) => d == LoadDirection::Rotating,
        None => op.load_rotates,
    };
    c.loads = match load {
        Some(magnitude_n) if rotating => vec![InnerRingLoad::Rotating {
            magnitude_n,
            phase_rad: 0.0,
        }],
        Some(l) => vec![InnerRingLoad::Fixed {
            force_n: [0.0, -l, 0.0],
        }],
        None => Vec::new(),
    };
    if let Some(unbalance_kg_m) = op.unbalance {
        c.loads.push(InnerRingLoad::Unbalance {
            unbalance_kg_m,
            phase_rad: op.unbalance_phase,
        });
    }
    for l in &sched.loads {
        let along = |m: f64| [m * l.direction.cos(), m * l.direction.sin(), 0.0];
        c.loads.push(match l.step {
            None => InnerRingLoad::Fixed {
                force_n: along(l.magnitude),
            },
            Some((after, at_s)) => InnerRingLoad::FixedStep {
                before_n: along(l.magnitude),
                after_n: along(after),
                at_s,
            },
        });
    }
    if let Some(axial) = args.axial_load.or(op.axial_load) {
        c.loads.push(InnerRingLoad::Fixed {
            force_n: [0.0, 0.0, axial],
        });
    }
    if let Some(outer) = args.outer_speed.or(op.outer_speed) {
        c.outer_speed = SpeedLaw::Constant(outer);
    }
    c.clearance_schedule = sched.clearance.clone();
    let t = |part: Option<f64>| part.unwrap_or(oil_t);
    c.temperatures = ContactTemperatures {
        inner_raceway_k: t(op
            .temperatures
            .inner_ring
            .filter(|_| args.oil_temperature.is_none())),
        outer_raceway_k: t(op
            .temperatures
            .outer_ring
            .filter(|_| args.oil_temperature.is_none())),
        cage_k: t(op
            .temperatures
            .cage
            .filter(|_| args.oil_temperature.is_none())),
    };
    c.misalignment_rad = args
        .misalignment
        .unwrap_or(model.bearing.misalignment().inner_ring_tilt);
    // SPEC §3.6: an input per model (`[dynamics] cage_drag`), none when the file is silent
    c.cage_drag_n_m_s = model.dynamics.cage_drag_n_m_s.unwrap_or(0.0);
    c.roller_drag_kg_m = roller_drag_factor(model, oil_t)?;
    Ok(c)
}

/// The roller drag factor k = ½ ρ_eff C_D D l (`rolldyn_lubrication::mixture::roller_drag_factor`)
/// of the model at oil temperature `oil_temperature_k`: C_D from `[dynamics]
/// roller_drag_coefficient` (none: no roller drag, seed 000 §3.6), ρ_eff the seed 001 mixture
/// density of the oil at that temperature with the oil volume fraction `[dynamics]
/// oil_volume_fraction` (default 0.05, the seed 000 CFD). One value for both models.
pub fn roller_drag_factor(
    model: &rolldyn_model::Model,
    oil_temperature_k: f64,
) -> Result<f64, SetupError> {
    use rolldyn_lubrication::mixture::{
        SEED000_OIL_VOLUME_FRACTION, air_oil_density_seed001, roller_drag_factor,
    };
    let Some(c_d) = model.dynamics.roller_drag_coefficient.filter(|&c| c > 0.0) else {
        return Ok(0.0);
    };
    let Some(lubrication) = model.lubrication.as_ref() else {
        return Err(model
            .source
            .error(
                "dynamics.roller_drag_coefficient",
                "roller drag needs a [lubricant] section",
            )
            .into());
    };
    let rho_oil = lubrication
        .oil
        .density(lubrication.oil.clamp_temperature(oil_temperature_k))
        .map_err(|e| model.source.error("lubricant", format!("roller drag: {e}")))?;
    let chi = model
        .dynamics
        .oil_volume_fraction
        .unwrap_or(SEED000_OIL_VOLUME_FRACTION);
    let roller = match &model.bearing.require_cylindrical("roller drag") {
        Ok(b) => &b.roller,
        Err(reason) => return Err(SetupError(reason.to_string())),
    };
    Ok(roller_drag_factor(
        air_oil_density_seed001(rho_oil, chi),
        c_d,
        roller.diameter,
        roller.length,
    ))
}

/// What the model gives, or what stands in for it, for the land film and the drag of the
/// air–oil mixture (named in the output of `simulate` and `skid`): (input, value and source).
pub fn drag_and_land_inputs(model: &rolldyn_model::Model) -> Vec<(&'static str, String)> {
    use rolldyn_lubrication::mixture::SEED000_OIL_VOLUME_FRACTION;
    let d = &model.dynamics;
    let mut out = vec![(
        "cage land fill",
        match (d.cage_land_law, d.cage_land_fill) {
            (CageLandLaw::Contact, _) => "— (plain contact land law, no film)".to_string(),
            (_, Some(f)) => format!("{f} ([dynamics] cage_land_fill)"),
            (_, None) => "1, flooded (default: [dynamics] cage_land_fill not given)".to_string(),
        },
    )];
    out.push((
        "roller–cage law",
        match (d.roller_cage.k_p, d.roller_cage.exponent) {
            (None, None) => "K_p, n derived at load from the cage pocket, the roller and the oil \
                             (docs/theory.md §2.3.1; [dynamics.roller_cage] stiffness, exponent not given)"
                .to_string(),
            (Some(_), Some(_)) => "K_p, n given ([dynamics.roller_cage] stiffness, exponent)".to_string(),
            _ => "K_p or n given, the other the rolldyn default ([dynamics.roller_cage]; give both, or neither to derive them)".to_string(),
        },
    ));
    out.push((
        "cage drag",
        match d.cage_drag_n_m_s {
            Some(c) => format!("M = −c ω, c = {c:.4e} N·m·s ([dynamics] cage_drag)"),
            None => "none in the dynamics; seed 001 mixture formula in skid (default: [dynamics] cage_drag not given)".to_string(),
        },
    ));
    out.push((
        "roller drag",
        match d.roller_drag_coefficient {
            Some(c) if c > 0.0 => {
                format!("F = ½ρ_eff C_D D l v², C_D = {c} ([dynamics] roller_drag_coefficient)")
            }
            Some(_) => "none ([dynamics] roller_drag_coefficient = 0)".to_string(),
            None => {
                "none (default, as seed 000 §3.6: [dynamics] roller_drag_coefficient not given)"
                    .to_string()
            }
        },
    ));
    out.push((
        "oil volume fraction",
        match d.oil_volume_fraction {
            Some(x) => format!("{x} ([dynamics] oil_volume_fraction)"),
            None => format!(
                "{SEED000_OIL_VOLUME_FRACTION} (default: the seed 000 CFD; [dynamics] oil_volume_fraction not given)"
            ),
        },
    ));
    out
}

/// The contact parameters of SPEC Table 2.1: the dynamics defaults for the bearing, with every
/// value the model's `[dynamics]` section gives (checked together when the simulation is built).
fn contact_parameters(
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    inputs: &rolldyn_model::DynamicsInputs,
) -> ContactParameters {
    use rolldyn_dynamics::{EndFriction, PairParameters, RollerEndParameters};
    use rolldyn_model::{EndFrictionLaw, EndPairInputs, PairInputs};
    fn pair(p: &mut PairParameters, i: &PairInputs) {
        let f = &mut p.friction;
        for (value, given) in [
            (&mut p.k_p, i.k_p),
            (&mut p.exponent, i.exponent),
            (&mut p.c_h, i.c_h),
            (&mut p.d, i.d),
            (&mut f.mu_static, i.mu_static),
            (&mut f.mu_dynamic, i.mu_dynamic),
            (&mut f.v_static, i.v_static),
            (&mut f.v_dynamic, i.v_dynamic),
        ] {
            if let Some(x) = given {
                *value = x;
            }
        }
    }
    fn end(p: &mut RollerEndParameters, i: &EndPairInputs) {
        pair(&mut p.contact, &i.pair);
        if let Some(on) = i.enabled {
            p.enabled = on;
        }
        if let Some(law) = i.friction_law {
            p.friction = match law {
                EndFrictionLaw::Boundary => EndFriction::Boundary,
                EndFrictionLaw::Kragelsky => EndFriction::Kragelsky,
                EndFrictionLaw::Ehl => EndFriction::Ehl,
            };
        }
    }
    let mut c = ContactParameters::for_bearing(bearing);
    for r in [&mut c.inner_raceway, &mut c.outer_raceway] {
        if let Some(d) = inputs.raceway_damping {
            r.damping_n_s_m = d;
        }
        if let Some(ramp) = inputs.raceway_damping_ramp {
            r.damping_ramp_m = ramp;
        }
    }
    pair(&mut c.roller_cage, &inputs.roller_cage);
    pair(&mut c.cage_land, &inputs.cage_land);
    end(&mut c.roller_end_rib, &inputs.roller_end_rib);
    end(&mut c.roller_end_cage, &inputs.roller_end_cage);
    c
}

/// Pair 34 of a bearing with a cage. Without `stiffness` and `exponent` in
/// `[dynamics.roller_cage]` the elastic law is derived from the cage pocket profile, the roller
/// and the oil at the cage temperature (`rolldyn_contact::cage_bar::derive_for_bearing`,
/// docs/theory.md §2.3.1: the bar's section from the one pocket description), and so are
/// `damping` and `damping_ramp` when not given. For `law = "lubricated"` the oil film between
/// roller and bar (`rolldyn_contact::bar_force::BarFilm::of_bearing`) is added, and without a
/// `damping` key `C_h = 0`: the film is the damper the elastic law's `C_h` stands for, so both
/// would count it twice.
fn with_roller_cage_law(
    mut parameters: ContactParameters,
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    lubrication: &rolldyn_model::Lubrication,
    cage_k: f64,
    inputs: &rolldyn_model::DynamicsInputs,
) -> Result<ContactParameters, SetupError> {
    let given = &inputs.roller_cage;
    let derive = given.k_p.is_none() && given.exponent.is_none();
    let lubricated = inputs.roller_cage_law == rolldyn_model::RollerCageLaw::Lubricated;
    if bearing.cage.is_none() || !(derive || lubricated) {
        return Ok(parameters);
    }
    let oil = &lubrication.oil;
    let viscosity = oil
        .dynamic_viscosity(oil.clamp_temperature(cage_k))
        .map_err(|e| SetupError(format!("dynamics.roller_cage: oil viscosity: {e}")))?;
    if derive {
        let (_, law) = rolldyn_contact::cage_bar::derive_for_bearing(
            bearing,
            viscosity,
            &rolldyn_contact::cage_bar::DerivationSettings::default(),
        )
        .ok_or_else(|| {
            SetupError("dynamics.roller_cage: no bar law derives from this cage".into())
        })?;
        let p = &mut parameters.roller_cage;
        (p.k_p, p.exponent) = (law.elastic.k_p, law.elastic.exponent);
        p.c_h = given.c_h.unwrap_or(law.c_h);
        p.d = given.d.unwrap_or(law.d);
    }
    if lubricated {
        let film = rolldyn_contact::bar_force::BarFilm::of_bearing(
            bearing,
            viscosity,
            &rolldyn_contact::bar_force::BarFilmSettings::default(),
        )
        .ok_or_else(|| SetupError("dynamics.roller_cage.law: the bearing has no cage".into()))?;
        parameters.roller_cage_film = Some(film);
        if given.c_h.is_none() {
            parameters.roller_cage.c_h = 0.0;
        }
    }
    Ok(parameters)
}

/// A simulation of `model` ready to run, and its cage revolution period [s] (`None`: the
/// rings start at rest, see [`Prepared::revolution_s`]).
pub fn prepare(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
    output_step_s: f64,
    tolerance: Option<f64>,
) -> Result<(Simulation, Option<f64>), SetupError> {
    let (bearing, lubrication) = bearing_and_oil(model)?;
    let conditions = conditions(overrides, model)?;
    let p = prepare_with(
        bearing,
        lubrication,
        &model.dynamics,
        conditions,
        output_step_s,
        tolerance,
    )?;
    Ok((p.simulation, p.revolution_s))
}

/// A constant-condition simulation of `model` frozen at time `t` of its schedules (seed 000
/// §3.1.2): [`frozen_conditions`], with the bearing's radial clearance set to the scheduled
/// operating clearance at `t` (so that the initial load distribution, the quasi-static start
/// and the dynamics all see it).
pub fn prepare_frozen(
    model: &rolldyn_model::Model,
    overrides: &Overrides,
    t: f64,
    output_step_s: f64,
    tolerance: Option<f64>,
) -> Result<Prepared, SetupError> {
    let (bearing, lubrication) = bearing_and_oil(model)?;
    let conditions = frozen_conditions(overrides, model, t)?;
    let mut bearing = bearing.clone();
    if let Some(g) = conditions.clearance_at(0.0) {
        bearing.clearance.radial = g;
        bearing.clearance.allow_preload = g < 0.0;
    }
    // a frozen point's clearance (scheduled or given) is the operating one of that instant
    bearing.clearance.radial_is_operating = true;
    prepare_with(
        &bearing,
        lubrication,
        &model.dynamics,
        conditions,
        output_step_s,
        tolerance,
    )
}

/// A simulation ready to run, with what was used to build it.
pub struct Prepared {
    pub simulation: Simulation,
    /// Cage revolution period at the epicyclic cage speed at t = 0, s; `None` when that speed
    /// is zero (the rings start at rest, e.g. a speed schedule from 0).
    pub revolution_s: Option<f64>,
    /// Quasi-static solution at t = 0 (the start of the cage and roller speeds), or why the
    /// quasi-static model could not solve the point.
    pub quasi_static: Result<rolldyn_quasistatic::SkidResult, String>,
}

fn bearing_and_oil(
    model: &rolldyn_model::Model,
) -> Result<
    (
        &rolldyn_geometry::CylindricalRollerBearing,
        &rolldyn_model::Lubrication,
    ),
    SetupError,
> {
    let bearing = model
        .bearing
        .require_cylindrical("simulate")
        .map_err(|reason| model.source.error("bearing.kind", reason))?;
    let lubrication = quasi_static::lubrication(model, "simulate")?;
    quasi_static::check_traction_oil(model, lubrication)?;
    Ok((bearing, lubrication))
}

/// Builds the simulation of `bearing` under `conditions`, started at the quasi-static cage
/// speed. A clearance the bearing marks as operating (`Clearance::radial_is_operating`, e.g. a
/// start-up clearance schedule, seed 000 Fig. 3.71) is used by the quasi-static start as such,
/// without its own fit, thermal and centrifugal contributions.
pub fn prepare_with(
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    lubrication: &rolldyn_model::Lubrication,
    inputs: &rolldyn_model::DynamicsInputs,
    conditions: OperatingConditions,
    output_step_s: f64,
    tolerance: Option<f64>,
) -> Result<Prepared, SetupError> {
    let traction = lubrication
        .traction_model()
        .map_err(|e| SetupError(format!("[lubricant]: {e}")))?;
    let epicyclic = bearing.epicyclic_cage_speed(
        conditions.inner_speed.speed(0.0),
        conditions.outer_speed.speed(0.0),
    );
    let mut settings = DynamicsSettings {
        output_step_s,
        ..DynamicsSettings::default()
    };
    if let Some(tol) = tolerance {
        if !(tol > 0.0 && tol < 1.0) {
            return Err(SetupError("--tolerance must lie in (0, 1)".into()));
        }
        settings.integrator.tolerance = tol;
    }
    let cage_temperature = conditions.temperatures.cage_k;
    let parameters = with_roller_cage_law(
        contact_parameters(bearing, inputs),
        bearing,
        lubrication,
        cage_temperature,
        inputs,
    )?;
    let land_contact = rolldyn_dynamics::TwoLevelLand {
        parameters: parameters.cage_land,
    };
    let traction = RacewayTraction::same(traction);
    let mut initial = Simulation::default_initial_state(
        bearing,
        conditions.clone(),
        parameters,
        traction.clone(),
    )
    .map_err(|e| SetupError(e.to_string()))?;
    let quasi_static = start_at_quasi_static_speeds(
        bearing,
        &conditions,
        lubrication,
        quasi_static::matching_land_model(bearing, inputs).as_ref(),
        &mut initial,
    );
    let mut sim = Simulation::with_initial_state(
        bearing, conditions, parameters, settings, traction, &initial,
    )
    .map_err(|e| SetupError(e.to_string()))?;
    // The simulation's own land law is the plain pair-14 contact (`TwoLevelLand`); the
    // hydrodynamic land replaces it where the model asks for it (theory §3.3).
    if inputs.cage_land_law == CageLandLaw::Hydrodynamic
        && let Some(land) = hydrodynamic_land(
            bearing,
            lubrication,
            cage_temperature,
            inputs.cage_land_fill.unwrap_or(1.0),
            land_contact,
        )?
    {
        sim.set_cage_land_model(Box::new(land));
    }
    Ok(Prepared {
        simulation: sim,
        revolution_s: (epicyclic != 0.0).then(|| std::f64::consts::TAU / epicyclic.abs()),
        quasi_static,
    })
}

/// The hydrodynamic cage land (Reynolds crate, issue 7 item 3) on the land that guides the
/// cage, its clearance filled to `fill_fraction` (`[dynamics] cage_land_fill`, flooded = 1),
/// with `contact` beyond the film; `None` for a roller-guided cage.
fn hydrodynamic_land(
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    lubrication: &rolldyn_model::Lubrication,
    cage_temperature_k: f64,
    fill_fraction: f64,
    contact: rolldyn_dynamics::TwoLevelLand,
) -> Result<Option<rolldyn_dynamics::HydrodynamicLand>, SetupError> {
    let Some(cage) = bearing
        .cage
        .as_ref()
        .filter(|c| c.guidance != rolldyn_geometry::CageGuidance::Rollers)
    else {
        return Ok(None);
    };
    let inner = cage.guidance == rolldyn_geometry::CageGuidance::InnerLand;
    let ring = if inner {
        &bearing.inner_ring
    } else {
        &bearing.outer_ring
    };
    let width = ring
        .guiding_land
        .map_or(cage.width, |l| l.width)
        .min(cage.width);
    let viscosity = lubrication
        .oil
        .dynamic_viscosity(lubrication.oil.clamp_temperature(cage_temperature_k))
        .map_err(|e| SetupError(format!("[lubricant]: {e}")))?;
    rolldyn_dynamics::HydrodynamicLand::new(
        0.5 * cage.land_diameter().unwrap_or(0.0),
        width,
        2,
        0.5 * cage.floating_clearance,
        inner,
        viscosity,
        fill_fraction,
        contact,
    )
    .map(Some)
    .map_err(|e| SetupError(e.to_string()))
}

/// Issue 6 "start from the quasi-static solution": the rollers keep the static load
/// distribution of the default start, but cage and roller orbit speeds take the quasi-static
/// cage speed (Muraki friction, `land` the quasi-static land matching the dynamics' land law,
/// [`quasi_static::matching_land_model`]), spins pure rolling on the outer raceway at
/// that speed. When the quasi-static model cannot solve the point the epicyclic start is kept.
/// The quasi-static point is [`quasi_static::dynamics_start_conditions`].
fn start_at_quasi_static_speeds(
    bearing: &rolldyn_geometry::CylindricalRollerBearing,
    conditions: &OperatingConditions,
    lubrication: &rolldyn_model::Lubrication,
    land: &dyn rolldyn_quasistatic::QuasiStaticLandModel,
    initial: &mut rolldyn_dynamics::InitialState,
) -> Result<rolldyn_quasistatic::SkidResult, String> {
    let qs = quasi_static::dynamics_start_conditions(conditions, lubrication);
    let wo = qs.outer_speed_rad_s;
    let options = rolldyn_quasistatic::QuasiStaticOptions::default();
    let result = rolldyn_quasistatic::solve_with_land_model(bearing, &qs, &options, land)
        .map_err(|e| e.to_string())?;
    let wc = result.cage_speed_rad_s;
    initial.cage_speed_rad_s = wc;
    for r in &mut initial.rollers {
        r.orbital_speed_rad_s = wc;
        r.spin_speed_rad_s =
            rolldyn_dynamics::pure_rolling_spin(wc, wo, r.radius_m, 0.5 * bearing.roller.diameter);
    }
    Ok(result)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rolldyn_dynamics::conditions::SpeedLaw;

    const RPM: f64 = std::f64::consts::PI / 30.0;

    /// `[dynamics]` reaches the simulation: cage drag into the conditions, each given contact
    /// parameter replaces its default and the others keep theirs.
    #[test]
    fn dynamics_section_sets_drag_and_contact_parameters() {
        let text = format!(
            "{}\n[dynamics.roller_cage]\nstiffness = 5e8\n[dynamics.roller_end_rib]\nenabled = false\nfriction_law = \"ehl\"\n",
            &rolldyn_model::DEFAULT_MODEL[..rolldyn_model::DEFAULT_MODEL
                .find("[dynamics.roller_cage]")
                .expect("the example's bar law")]
        );
        let model = rolldyn_model::parse(&text, "m.toml").unwrap();
        let c = conditions(&Overrides::default(), &model).unwrap();
        assert!((c.cage_drag_n_m_s - 6.62e-4).abs() < 1e-15);
        let (bearing, _) = bearing_and_oil(&model).unwrap();
        let p = contact_parameters(bearing, &model.dynamics);
        let default = ContactParameters::for_bearing(bearing);
        assert_eq!(p.roller_cage.k_p, 5e8);
        assert_eq!(p.roller_cage.exponent, default.roller_cage.exponent);
        assert!(!p.roller_end_rib.enabled);
        assert_eq!(
            p.roller_end_rib.friction,
            rolldyn_dynamics::EndFriction::Ehl
        );
        assert_eq!(p.cage_land, default.cage_land);
        assert_eq!(p.inner_raceway, default.inner_raceway);
        assert_eq!(p.roller_cage_film, None);
    }

    /// `law = "lubricated"` gives the dynamics the film of the bearing's oil at the cage
    /// temperature, and C_h = 0 unless the file sets `damping`.
    #[test]
    fn lubricated_roller_cage_law_reaches_the_parameters() {
        let text = format!(
            "{}\n[dynamics.roller_cage]\nlaw = \"lubricated\"\n",
            &rolldyn_model::DEFAULT_MODEL[..rolldyn_model::DEFAULT_MODEL
                .find("[dynamics.roller_cage]")
                .expect("the example's bar law")]
        );
        let model = rolldyn_model::parse(&text, "m.toml").unwrap();
        let (bearing, oil) = bearing_and_oil(&model).unwrap();
        let p = with_roller_cage_law(
            contact_parameters(bearing, &model.dynamics),
            bearing,
            oil,
            373.15,
            &model.dynamics,
        )
        .unwrap();
        let film = p.roller_cage_film.expect("a film");
        assert_eq!(film.radius, 0.5 * bearing.roller.diameter);
        assert!(film.viscosity > 0.0 && film.cutoff > film.contact_film);
        assert_eq!(p.roller_cage.c_h, 0.0);
        assert!(matches!(
            p.roller_cage_law(5e-3),
            rolldyn_contact::bar_force::BarForceLaw::Lubricated(_)
        ));
    }

    /// Without stiffness and exponent in `[dynamics.roller_cage]` pair 34 is derived from the
    /// cage pocket: 2002834's pocket gives the law of docs/validation/bar-contact-law.md
    /// (K_p = 7.254·10⁸ N/m^1.1106, C_h 1774 N·s/m, d 3.13 µm), and a narrower pocket face
    /// (reading (b), a wider and stiffer bar) a stiffer law.
    #[test]
    fn the_bar_law_follows_the_cage_pocket() {
        let law = |text: &str| {
            let model = rolldyn_model::parse(text, "m.toml").unwrap();
            let (bearing, oil) = bearing_and_oil(&model).unwrap();
            with_roller_cage_law(
                contact_parameters(bearing, &model.dynamics),
                bearing,
                oil,
                373.15,
                &model.dynamics,
            )
            .unwrap()
            .roller_cage
        };
        let a = law(rolldyn_model::DEFAULT_MODEL);
        assert!((a.k_p / 7.254e8 - 1.0).abs() < 1e-3, "{}", a.k_p);
        assert!((a.exponent - 1.1106).abs() < 1e-3, "{}", a.exponent);
        assert!((a.c_h / 1774.5 - 1.0).abs() < 1e-2 && (a.d / 3.13e-6 - 1.0).abs() < 1e-2);
        let narrow = rolldyn_model::DEFAULT_MODEL.replacen(
            "face_clearance = \"4 mm\"",
            "face_clearance = \"0.6 mm\"",
            1,
        );
        assert_ne!(narrow, rolldyn_model::DEFAULT_MODEL);
        let b = law(&narrow);
        let force = |p: &rolldyn_dynamics::PairParameters| p.k_p * 1e-6f64.powf(p.exponent);
        assert!(force(&b) > force(&a), "{} vs {}", force(&b), force(&a));
    }

    fn model_1032930() -> rolldyn_model::Model {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/1032930.toml");
        rolldyn_model::load(&path).expect("the 1032930 example loads")
    }

    /// SPEC §3.7 loads of 1032930 from the model file: weight 578.8 N and gearbox step, both
    /// downwards, unbalance U ω², speed schedule, clearance schedule.
    #[test]
    fn start_up_conditions_from_the_model() {
        let model = model_1032930();
        let c = conditions(&Overrides::default(), &model).unwrap();
        assert!(matches!(c.inner_speed, SpeedLaw::Schedule(ref p) if p.len() == 3));
        assert_eq!(c.loads.len(), 3);
        let f = c.fixed_force(10.0);
        assert!(f[0].abs() < 1e-9 && (f[1] + 578.8 + 3708.8).abs() < 1e-9);
        let f = c.fixed_force(100.0);
        assert!((f[1] + 578.8 + 406.5).abs() < 1e-9);
        assert!((c.rotating_force_magnitude(82.0988) - 1376.0).abs() < 1.0);
        assert!((c.clearance_at(0.0).unwrap() - 10e-6).abs() < 1e-15);
        // oil temperature of the schedule at t = 0 for a whole dynamic run
        assert!((c.temperatures.inner_raceway_k - 288.15).abs() < 1e-9);
        // --speed replaces the schedule by a constant, --oil-temperature the temperature
        let overrides = Overrides {
            speed: Some(7000.0 * RPM),
            oil_temperature: Some(330.0),
            ..Overrides::default()
        };
        let c = conditions(&overrides, &model).unwrap();
        assert_eq!(c.inner_speed, SpeedLaw::Constant(7000.0 * RPM));
        assert_eq!(c.temperatures.cage_k, 330.0);
    }

    /// Seed 000 Table 3.4: the frozen points take the schedules' values; point 2 (starter
    /// cut-off) is still loaded by the gearbox, point 3 is not.
    #[test]
    fn frozen_points_of_table_3_4() {
        let model = model_1032930();
        let expected = [
            // t, rpm, fixed load N, clearance µm, oil °C
            (82.0988, 6300.0, 4287.6, 2.15, 49.0),
            (85.2988, 6348.83, 985.3, 1.92, 50.0),
            (270.4988, 9175.0, 985.3, -5.0, 80.0),
        ];
        for (t, rpm, load, g_um, oil_c) in expected {
            let c = frozen_conditions(&Overrides::default(), &model, t).unwrap();
            let w = c.inner_speed.speed(0.0);
            assert!((w / RPM - rpm).abs() < 0.01, "{t}: {}", w / RPM);
            assert_eq!(c.inner_speed.speed(1.0), w);
            let f = c.fixed_force(0.0);
            assert!((f[0].hypot(f[1]) - load).abs() < 1e-9, "{t}");
            assert!((c.rotating_force_magnitude(0.0) - 3.1625e-3 * w * w).abs() < 1e-9);
            let g = c.clearance_at(0.0).unwrap();
            assert!((g * 1e6 - g_um).abs() < 1e-9, "{t}: {g}");
            assert!((c.temperatures.outer_raceway_k - (oil_c + 273.15)).abs() < 1e-9);
        }
    }
}
