//! Assembly of one quasi-static point: setup from the bearing and the conditions, the nested
//! iterations of SPEC §5.6 and the result.
//!
//! ```text
//! ω₀ ← ω₀₀(1 − ε₀,init)
//! safeguarded Newton on ω₀ ∈ [min(ω_в, ω_н), max(ω_в, ω_н)]  (ε₀ ≥ 1 − ω_н/ω₀₀ holds, F-42)
//!    F_c(ω₀) → frictionless load distribution (warm start)
//!    every distinct roller: safeguarded Newton on ω_w (warm start)
//!    Φ = T_S + T_sб + T_ts
//! final evaluation, scuffing margins, powers
//! ```

use rolldyn_rating::RollerBearingGeometry;
use rolldyn_rating::iso76::static_radial_rating;
use std::time::Instant;

use crate::cage_equilibrium::{CageBalance, CageSetup, LandSetup, RollerOnCage, cage_balance};
use crate::cage_land::QuasiStaticLandModel;
use crate::conditions::{QuasiStaticConditions, QuasiStaticContactTemperatures};
use crate::drag::CageDragGeometry;
use crate::error::QsError;
use crate::friction::{BarLaw, bar_law, raceway_model};
use crate::kinematics::{KinematicCase, Kinematics, cage_slip};
use crate::load_distribution::{LoadCase, LoadDistribution, LoadModel, RollerLoad};
use crate::operating_geometry::{OperatingGeometry, operating_geometry};
use crate::options::{LandMomentArm, QuasiStaticOptions};
use crate::results::{
    BarResult, ContactResult, Iterations, PowerBreakdown, Residuals, RollerResult, SkidResult, Zone,
};
use crate::roller_equilibrium::{
    ContactSetup, RibFilm, RollerEnv, RollerEval, RollerLoads, circular_segment_area,
};
use rolldyn_contact::hertz::reduced_modulus;
use rolldyn_geometry::{CageGuidance, CylindricalRollerBearing};
use rolldyn_lubrication::scuffing::{CriticalSlip, SlipSearch, critical_slip};
use rolldyn_lubrication::traction::FrictionLaw;
use rolldyn_lubrication::{ContactState, FrictionRegime, Traction, TractionModel};
use rolldyn_numerics::{Bracket, Derivative, Point, Root1dOptions, Root1dStatus, find_root};

/// Largest operating preload accepted, as a fraction of the roller diameter (as the geometry
/// crate's mounting limit).
const MAX_OPERATING_PRELOAD: f64 = 0.002;

/// Everything that does not change during the iterations of one point.
struct Setup<'a> {
    bearing: &'a CylindricalRollerBearing,
    cond: &'a QuasiStaticConditions,
    opts: &'a QuasiStaticOptions,
    geometry: OperatingGeometry,
    load_model: LoadModel,
    traction: TractionModel,
    bar: BarLaw,
    inner: ContactSetup,
    outer: ContactSetup,
    bar_contact: ContactSetup,
    temperatures: QuasiStaticContactTemperatures,
    rib: Option<RibFilm>,
    pocket_coefficient: f64,
    cage: CageSetup,
    land_speed: f64,
    r_i: f64,
    r_o: f64,
    r_w: f64,
    r_c: f64,
    roller_mass: f64,
    misalignment: f64,
    epicyclic: f64,
    warnings: Vec<String>,
}

/// Mutable state of the iterations (warm starts and counters).
#[derive(Default)]
struct Workspace {
    load: Option<LoadDistribution>,
    spins: Vec<Option<f64>>,
    evals: Vec<Option<RollerEval>>,
    balance: CageBalance,
    /// Moment scale of the cage equation, fixed at the first evaluation, N·m.
    scale: Option<f64>,
    load_iterations: usize,
    roller_evaluations: usize,
}

/// Checked speeds `(ω_i, ω_o)` and ring misalignment of the operating conditions (finite
/// values, non-negative radial load, absolute temperatures, misalignment ≤ 1°).
fn checked_inputs(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
) -> Result<(f64, f64, f64), QsError> {
    let wi = finite("inner_speed_rad_s", cond.inner_speed_rad_s)?;
    let wo = finite("outer_speed_rad_s", cond.outer_speed_rad_s)?;
    let fr = finite("radial_load_n", cond.radial_load_n)?;
    finite("load_speed_rad_s", cond.load_speed_rad_s)?;
    if fr < 0.0 {
        return Err(QsError::InvalidInput(format!(
            "radial_load_n must be ≥ 0 (its direction is the reference), got {fr}"
        )));
    }
    let t = &cond.temperatures;
    for (n, v) in [
        ("temperatures.inner_ring", t.inner_ring),
        ("temperatures.outer_ring", t.outer_ring),
        ("temperatures.rollers", t.rollers),
        ("temperatures.cage", t.cage),
        ("temperatures.shaft", t.shaft),
        ("temperatures.housing", t.housing),
        ("temperatures.assembly", t.assembly),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(QsError::InvalidInput(format!(
                "{n} must be a positive absolute temperature in K, got {v}"
            )));
        }
    }
    let misalignment = finite(
        "misalignment_rad",
        cond.misalignment_rad
            .unwrap_or(bearing.misalignment.inner_ring_tilt),
    )?;
    if misalignment.abs() > 1f64.to_radians() {
        return Err(QsError::InvalidInput(format!(
            "misalignment {:.1}′ exceeds 1°",
            misalignment.to_degrees() * 60.0
        )));
    }
    if !(cond.rolling_friction_m.is_finite() && cond.rolling_friction_m >= 0.0) {
        return Err(QsError::InvalidInput(
            "rolling_friction_m must be ≥ 0".into(),
        ));
    }
    Ok((wi, wo, misalignment))
}

/// Viscous film between the roller end faces and the ribs of the guiding ring (the one with
/// the rib spacing, else the one with two ribs); `None` without such a ring or with the rib
/// drag switched off. `r_e` is the end-face radius, `(r_w, r_c)` the roller and pitch radii.
fn rib_film(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    geometry: &OperatingGeometry,
    r_e: f64,
    (r_w, r_c): (f64, f64),
) -> Result<Option<RibFilm>, QsError> {
    if !cond.end_friction.ribs {
        return Ok(None);
    }
    let (inner, outer) = (&bearing.inner_ring, &bearing.outer_ring);
    let guiding_outer = match (inner.rib_spacing.is_some(), outer.rib_spacing.is_some()) {
        (false, true) => Some(true),
        (true, _) => Some(false),
        (false, false) if outer.ribs.len() >= 2 => Some(true),
        (false, false) if inner.ribs.len() >= 2 => Some(false),
        (false, false) => None,
    };
    let (Some(outer_ring), Some(axial)) = (guiding_outer, &geometry.roller_rib) else {
        return Ok(None);
    };
    let ring = if outer_ring { outer } else { inner };
    if ring.ribs.is_empty() {
        return Ok(None);
    }
    let rim = ring.ribs.iter().map(|r| r.diameter).sum::<f64>() / ring.ribs.len() as f64;
    let h_rib = 0.5 * (rim - ring.raceway_diameter).abs();
    let rw0 = 0.5 * bearing.roller.diameter;
    let area = circular_segment_area(r_e, r_e - (rw0 - h_rib));
    let ring_t = if outer_ring {
        cond.temperatures.outer_ring
    } else {
        cond.temperatures.inner_ring
    };
    let eta = viscosity(cond, ring_t)?;
    let h = 0.5 * axial.operating_m;
    let lever_mag = r_w - 0.5 * h_rib;
    let lever = if outer_ring { lever_mag } else { -lever_mag };
    Ok(Some(RibFilm {
        outer_ring,
        radius_m: r_c + lever,
        lever_m: lever,
        coefficient: 2.0 * eta * area / h,
    }))
}

/// Drag coefficient of the two roller end faces in their pockets, `T = π μ ω r_e⁴/(2h)` each
/// (0 when switched off or without a cage).
fn pocket_coefficient(
    cond: &QuasiStaticConditions,
    geometry: &OperatingGeometry,
    r_e: f64,
) -> Result<f64, QsError> {
    let mean_t = cond.temperatures.mean_rings();
    let coefficient = match (&geometry.pocket_end, cond.end_friction.pocket) {
        (Some(p), true) => {
            let eta = viscosity(cond, mean_t)?;
            let h = 0.5 * p.operating_m;
            // two end faces, each T = π μ ω r_e⁴ /(2h)
            std::f64::consts::PI * eta * r_e.powi(4) / h
        }
        _ => 0.0,
    };
    Ok(coefficient)
}

/// Guiding land of a land-guided cage and the speed of its ring, rad/s (`(None, 0)` for a
/// roller-guided cage or with the land model switched off).
fn land_setup(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    geometry: &OperatingGeometry,
    cage_mass: f64,
) -> Result<(Option<LandSetup>, f64), QsError> {
    let Some(cage) = bearing.cage.as_ref() else {
        return Ok((None, 0.0));
    };
    let (wi, wo) = (cond.inner_speed_rad_s, cond.outer_speed_rad_s);
    let setup = match (cage.guidance, &geometry.cage, cond.cage_land.enabled) {
        (CageGuidance::Rollers, _, _) | (_, None, _) | (_, _, false) => (None, 0.0),
        (guidance, Some(cc), true) => {
            let outer_ring = guidance == CageGuidance::OuterLand;
            let ring = if outer_ring {
                &bearing.outer_ring
            } else {
                &bearing.inner_ring
            };
            let rail = cond
                .cage_land
                .rail_width_m
                .or(ring.guiding_land.map(|l| l.width))
                .unwrap_or_else(|| {
                    let w = 0.5 * (cage.width - cage.pocket.axial);
                    if w > 0.0 { w } else { 0.25 * cage.width }
                });
            let t_land = if outer_ring {
                cond.temperatures.outer_ring
            } else {
                cond.temperatures.inner_ring
            };
            (
                Some(LandSetup {
                    radius_m: 0.5 * cc.land_diameter_m,
                    rail_width_m: rail,
                    rails: cond.cage_land.rails.max(1),
                    radial_clearance_m: 0.5 * cc.operating_m,
                    viscosity_pa_s: viscosity(cond, t_land)?,
                    outer_ring,
                    cage_mass_kg: if cond.cage_land.centrifugal_pressing {
                        cage_mass
                    } else {
                        0.0
                    },
                }),
                if outer_ring { wo } else { wi },
            )
        }
    };
    Ok(setup)
}

fn finite(name: &str, v: f64) -> Result<f64, QsError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(QsError::InvalidInput(format!(
            "{name} must be finite, got {v}"
        )))
    }
}

fn viscosity(cond: &QuasiStaticConditions, t: f64) -> Result<f64, QsError> {
    let oil = &cond.lubricant;
    oil.dynamic_viscosity(oil.clamp_temperature(t))
        .map_err(|e| QsError::Lubrication(e.to_string()))
}

impl<'a> Setup<'a> {
    fn new(
        bearing: &'a CylindricalRollerBearing,
        cond: &'a QuasiStaticConditions,
        opts: &'a QuasiStaticOptions,
    ) -> Result<Self, QsError> {
        bearing
            .validate()
            .map_err(|e| QsError::Geometry(e.to_string()))?;
        let cage = bearing.cage.as_ref().ok_or_else(|| {
            QsError::InvalidInput(
                "the quasi-static skidding model needs a cage (the roller set speed is that of \
                 the cage, SPEC §5.5)"
                    .into(),
            )
        })?;
        let (wi, wo, misalignment) = checked_inputs(bearing, cond)?;
        let mut warnings = Vec::new();

        let nominal_epicyclic = bearing.epicyclic_cage_speed(wi, wo);
        let geometry = operating_geometry(bearing, cond, nominal_epicyclic);
        warnings.extend(geometry.warnings.iter().cloned());
        let g = geometry.clearance.operating_m;
        if g < -MAX_OPERATING_PRELOAD * bearing.roller.diameter {
            return Err(QsError::InvalidInput(format!(
                "operating radial clearance {:.1} µm is a preload beyond {:.1} % of the roller \
                 diameter: check the fits and temperatures",
                g * 1e6,
                MAX_OPERATING_PRELOAD * 100.0
            )));
        }

        let load_model = LoadModel::new(bearing, opts.slice_law)?;
        let traction = raceway_model(cond)?;
        let bar = bar_law(cond, &traction)?;

        let r_i = 0.5 * geometry.inner_raceway_diameter_m;
        let r_o = 0.5 * geometry.outer_raceway_diameter_m;
        let r_w = 0.5 * geometry.roller_diameter_m;
        let r_c = r_o - r_w;
        let roller = &bearing.roller;
        let l_eff = roller.profile.effective_length();
        let inner = ContactSetup {
            reduced_radius: load_model.inner_contact.reduced_radius,
            reduced_modulus: load_model.inner_contact.reduced_modulus,
            roughness: [bearing.inner_ring.roughness_ra, roller.roughness_ra],
            default_length: l_eff,
        };
        let outer = ContactSetup {
            reduced_radius: load_model.outer_contact.reduced_radius,
            reduced_modulus: load_model.outer_contact.reduced_modulus,
            roughness: [bearing.outer_ring.roughness_ra, roller.roughness_ra],
            default_length: l_eff,
        };
        let bar_contact = ContactSetup {
            reduced_radius: 0.5 * roller.diameter,
            reduced_modulus: reduced_modulus(
                roller.material.youngs_modulus,
                roller.material.poisson_ratio,
                cage.material.youngs_modulus,
                cage.material.poisson_ratio,
            ),
            roughness: [cage.roughness_ra, roller.roughness_ra],
            default_length: l_eff,
        };
        let temperatures = cond.resolved_contact_temperatures();

        // roller end-face radius: inside the chamfer / edge break
        let end_break = roller.profile.chamfer.map_or(roller.edge_break, |c| {
            c.radial_height.max(roller.edge_break)
        });
        let r_e = (0.5 * roller.diameter - end_break).max(0.25 * roller.diameter);

        let rib = rib_film(bearing, cond, &geometry, r_e, (r_w, r_c))?;

        let mean_t = cond.temperatures.mean_rings();
        let pocket_coefficient = pocket_coefficient(cond, &geometry, r_e)?;

        // cage
        let cage_mass = if cage.mass_properties.mass > 0.0 {
            cage.mass_properties.mass
        } else {
            cage.computed_mass_properties(&bearing.pocket_context(cage))
                .map_err(|e| QsError::InvalidInput(e.to_string()))?
                .mass
        };
        let (land, land_speed) = land_setup(bearing, cond, &geometry, cage_mass)?;
        let oil_density = cond
            .lubricant
            .density(mean_t)
            .unwrap_or(cond.drag.oil_density_kg_m3);
        let cage_setup = CageSetup {
            pitch_radius_m: r_c,
            roller_radius_m: r_w,
            land,
            drag: CageDragGeometry {
                outer_radius_m: 0.5 * cage.outer_diameter,
                inner_radius_m: 0.5 * cage.inner_diameter,
                width_m: cage.width,
            },
            drag_inputs: cond.drag.clone(),
            mixture_oil: (oil_density, viscosity(cond, mean_t)?),
            land_arm_factor: match opts.land_moment_arm {
                LandMomentArm::Radius => 1.0,
                LandMomentArm::SeedDiameter => 2.0,
            },
        };
        let roller_mass = if roller.mass_properties.mass > 0.0 {
            roller.mass_properties.mass
        } else {
            roller.computed_mass_properties().mass
        };
        let epicyclic = rolldyn_geometry::epicyclic_cage_speed(2.0 * r_i, 2.0 * r_o, wi, wo);
        Ok(Self {
            bearing,
            cond,
            opts,
            geometry,
            load_model,
            traction,
            bar,
            inner,
            outer,
            bar_contact,
            temperatures,
            rib,
            pocket_coefficient,
            cage: cage_setup,
            land_speed,
            r_i,
            r_o,
            r_w,
            r_c,
            roller_mass,
            misalignment,
            epicyclic,
            warnings,
        })
    }

    fn kinematics(&self, cage_speed: f64) -> Kinematics {
        Kinematics {
            inner_speed: self.cond.inner_speed_rad_s,
            outer_speed: self.cond.outer_speed_rad_s,
            cage_speed,
            inner_radius: self.r_i,
            outer_radius: self.r_o,
            roller_radius: self.r_w,
        }
    }

    fn env(&self, cage_speed: f64) -> RollerEnv<'_> {
        RollerEnv {
            traction: &self.traction,
            bar: &self.bar,
            kin: self.kinematics(cage_speed),
            inner: self.inner,
            outer: self.outer,
            bar_contact: self.bar_contact,
            temperatures: self.temperatures,
            rib: self.rib,
            pocket_coefficient: self.pocket_coefficient,
            rolling_friction_m: self.cond.rolling_friction_m,
            orbital_drag_n: {
                let v = cage_speed * self.r_c;
                -self.cond.drag.roller_drag_kg_m * v * v.abs()
            },
        }
    }

    fn load_case(&self, cage_speed: f64) -> LoadCase {
        LoadCase {
            radial_load_n: self.cond.radial_load_n,
            diametral_clearance_m: self.geometry.clearance.operating_m,
            misalignment_rad: self.misalignment,
            misalignment_azimuth_rad: self.cond.misalignment_azimuth_rad,
            centrifugal_force_n: self.roller_mass * self.r_c * cage_speed * cage_speed,
            roller_phase_rad: self.opts.roller_phase_rad,
        }
    }

    /// Φ(ω₀)/scale with all inner iterations; state left in `ws`.
    fn cage_residual(
        &self,
        cage_speed: f64,
        ws: &mut Workspace,
        land_model: &dyn QuasiStaticLandModel,
    ) -> Result<f64, QsError> {
        let ld = self
            .load_model
            .solve(&self.load_case(cage_speed), ws.load.as_ref(), self.opts)?;
        ws.load_iterations += ld.iterations;
        let env = self.env(cage_speed);
        let z = ld.rollers.len();
        ws.spins.resize(z, None);
        ws.evals.resize(z, None);
        let mut loads_seen: Vec<(RollerLoads, usize)> = Vec::with_capacity(z);
        let mut on_cage = Vec::with_capacity(z);
        for (j, r) in ld.rollers.iter().enumerate() {
            let loads = RollerLoads {
                inner_n: r.inner_force_n,
                outer_n: r.outer_force_n,
                inner_length_m: r.inner_effective_length_m,
                outer_length_m: r.outer_effective_length_m,
            };
            let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (a.abs() + b.abs()) + 1e-15;
            let reuse = loads_seen.iter().find(|(l, _)| {
                same(l.inner_n, loads.inner_n)
                    && same(l.outer_n, loads.outer_n)
                    && same(l.inner_length_m, loads.inner_length_m)
                    && same(l.outer_length_m, loads.outer_length_m)
            });
            let ev = match reuse {
                Some(&(_, k)) => ws.evals[k].expect("solved before"),
                None => {
                    let (ev, n) = env
                        .solve(
                            &loads,
                            ws.spins[j],
                            self.opts.roller_tolerance,
                            self.opts.fd_relative_step,
                            self.opts.fd_min_step_rad_s,
                            self.opts.max_roller_evaluations,
                        )
                        .map_err(|e| match e {
                            QsError::NotConverged {
                                iterations,
                                residuals,
                                ..
                            } => QsError::NotConverged {
                                stage: format!("roller {j} moment equation"),
                                iterations,
                                residuals,
                            },
                            other => other,
                        })?;
                    ws.roller_evaluations += n;
                    loads_seen.push((loads, j));
                    ev
                }
            };
            ws.spins[j] = Some(ev.spin);
            ws.evals[j] = Some(ev);
            on_cage.push(RollerOnCage {
                azimuth_rad: r.azimuth_rad,
                push_n: ev.push,
                bar_friction_n: ev.bar_mu * ev.push.abs(),
                pocket_couple_n_m: -ev.pocket_moment,
            });
        }
        let bal = cage_balance(
            &self.cage,
            &on_cage,
            cage_speed,
            self.land_speed,
            self.cond.load_speed_rad_s,
            land_model,
        );
        ws.balance = bal;
        ws.load = Some(ld);
        // a fixed scale keeps Φ's slope (Φ/Σ|T| would flatten to ±1 away from the root)
        let scale = *ws.scale.get_or_insert(bal.scale_n_m);
        Ok(bal.residual_n_m / scale)
    }
}

fn regime_name(t: &Traction) -> &'static str {
    match t.regime {
        FrictionRegime::Boundary => "boundary",
        FrictionRegime::Mixed => "mixed",
        FrictionRegime::Hydrodynamic => "hydrodynamic",
    }
}

fn contact_result(
    t: Option<&Traction>,
    state: &ContactState,
    length: f64,
    u_min: f64,
) -> ContactResult {
    let u = state.rolling_speed_m_s;
    let v = state.sliding_speed_m_s;
    let s = v / u.abs().max(u_min);
    match t {
        Some(t) => ContactResult {
            normal_force_n: state.normal_force_n,
            effective_length_m: length,
            max_pressure_pa: t.max_pressure_pa,
            half_width_m: t.half_width_m,
            rolling_speed_m_s: u,
            sliding_speed_m_s: v,
            slide_roll_ratio: s,
            friction_coefficient: t.coefficient,
            friction_force_n: t.coefficient * state.normal_force_n,
            film_central_m: t.film_central_m.is_finite().then_some(t.film_central_m),
            film_minimum_m: t.film_minimum_m.is_finite().then_some(t.film_minimum_m),
            lambda: t.lambda.is_finite().then_some(t.lambda),
            temperature_k: t.contact_temperature_k,
            power_w: t.heat_power_w,
            regime: regime_name(t),
            critical_slip: None,
            scuffing_margin: None,
            warnings: t.warnings.names(),
        },
        None => ContactResult {
            normal_force_n: 0.0,
            effective_length_m: 0.0,
            max_pressure_pa: 0.0,
            half_width_m: 0.0,
            rolling_speed_m_s: u,
            sliding_speed_m_s: v,
            slide_roll_ratio: s,
            friction_coefficient: 0.0,
            friction_force_n: 0.0,
            film_central_m: None,
            film_minimum_m: None,
            lambda: None,
            temperature_k: state.temperature_k,
            power_w: 0.0,
            regime: "unloaded",
            critical_slip: None,
            scuffing_margin: None,
            warnings: Vec::new(),
        },
    }
}

/// The internal dimensions of a cylindrical roller bearing that its ISO 76 / ISO 281 ratings
/// take: D_we, L_we (the profile's effective length), α = 0, D_pw, Z, one row.
pub fn rating_geometry(bearing: &CylindricalRollerBearing) -> RollerBearingGeometry {
    RollerBearingGeometry {
        roller_diameter_m: bearing.roller.diameter,
        effective_length_m: bearing.roller.profile.effective_length(),
        contact_angle_rad: 0.0,
        pitch_diameter_m: bearing.pitch_diameter(),
        rollers_per_row: bearing.roller_count,
        rows: 1,
    }
}

/// Basic static radial load rating of a cylindrical roller bearing, ISO 76 (standard form, not
/// in the seeds): C₀r = 44 (1 − D_we/D_pw) Z L_we D_we (N, mm), [`static_radial_rating`] with
/// α = 0 and one row.
pub fn static_load_rating(bearing: &CylindricalRollerBearing) -> f64 {
    static_radial_rating(&rating_geometry(bearing))
}

/// See [`crate::solve_with_land_model`].
pub(crate) fn run(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    opts: &QuasiStaticOptions,
    land_model: &dyn QuasiStaticLandModel,
) -> Result<SkidResult, QsError> {
    let start = Instant::now();
    let setup = Setup::new(bearing, cond, opts)?;
    let (wi, wo) = (cond.inner_speed_rad_s, cond.outer_speed_rad_s);
    let mut ws = Workspace::default();
    let (cage_speed, cage_evals) = if wi == 0.0 && wo == 0.0 {
        // both rings at rest: nothing moves
        setup.cage_residual(0.0, &mut ws, land_model)?;
        (0.0, 1)
    } else {
        // the cage runs between the ring speeds; the drag (reacting on the stationary housing)
        // can hold it below both, down to rest (e.g. rings rotating together)
        let (lo, hi) = (wi.min(wo).min(0.0), wi.max(wo).max(0.0));
        let w = wi.abs().max(wo.abs());
        let x0 = setup.epicyclic * (1.0 - opts.initial_cage_slip);
        let ropts = Root1dOptions {
            bracket: Bracket::Search {
                limits: (lo, hi),
                fd_step: (opts.fd_relative_step * w).max(opts.fd_min_step_rad_s),
                // 1 % of the ring speed difference (of the speed if the rings rotate together):
                // slips of 1e-4…0.3 are bracketed in a few steps and the equilibrium nearest to
                // the guess is found first
                max_first_step: 0.01 * ((wi - wo).abs().max(1e-3 * w)),
            },
            derivative: Derivative::Secant,
            x_tol: 1e-13 * w,
            max_evaluations: opts.max_cage_evaluations,
            ..Root1dOptions::default()
        };
        let root = find_root(
            |x| {
                setup
                    .cage_residual(x, &mut ws, land_model)
                    .map(|v| Point::residual(v, opts.cage_tolerance))
            },
            x0,
            &ropts,
        )?;
        if !root.converged() {
            let mut res = vec![
                ("cage moment / scale", root.value),
                ("cage speed / (rad/s)", root.x),
                ("cage slip", cage_slip(root.x, setup.epicyclic)),
            ];
            if root.status == Root1dStatus::NoSignChange {
                res.push(("no equilibrium between the ring speeds", 1.0));
            }
            return Err(QsError::not_converged(
                "cage moment equation",
                root.evaluations,
                &res,
            ));
        }
        // final state exactly at the root
        setup.cage_residual(root.x, &mut ws, land_model)?;
        (root.x, root.evaluations + 1)
    };
    // the residual the root finder tested: Φ over the moment sum of its first iterate
    let cage_residual = ws.balance.residual_n_m / ws.scale.unwrap_or(ws.balance.scale_n_m);
    let accepted = opts.cage_tolerance * opts.cage_residual_slack;
    let passed = cage_residual.abs() <= accepted;
    if !passed && (wi != 0.0 || wo != 0.0) {
        // the bracket can close on a jump of Φ (or an end of the speed range) without a root
        return Err(QsError::not_converged(
            "cage moment equation",
            cage_evals,
            &[
                ("cage moment / scale", cage_residual),
                ("accepted", accepted),
                ("cage slip", cage_slip(cage_speed, setup.epicyclic)),
            ],
        ));
    }
    finish(
        &setup,
        ws,
        cage_speed,
        cage_residual,
        cage_evals,
        land_model,
        start,
    )
}

#[allow(clippy::too_many_arguments)]
fn finish(
    setup: &Setup<'_>,
    ws: Workspace,
    cage_speed: f64,
    cage_residual: f64,
    cage_evals: usize,
    land_model: &dyn QuasiStaticLandModel,
    start: Instant,
) -> Result<SkidResult, QsError> {
    let cond = setup.cond;
    let ld = ws
        .load
        .ok_or_else(|| QsError::InvalidInput("no load distribution".into()))?;
    let kin = setup.kinematics(cage_speed);
    let reference_outer = kin.reference_is_outer(setup.opts.slip_reference);
    let RollerSums {
        rollers,
        mut power,
        power_in,
        max_roller_moment_rel,
        max_pressure,
    } = roller_results(setup, &kin, &ld, &ws.evals)?;
    let bal = ws.balance;
    power.cage_land_w = bal.land_power_w;
    power.drag_w = bal.drag.power_w;
    power.roller_drag_w = ld.rollers.len() as f64
        * cond.drag.roller_drag_kg_m
        * (cage_speed * setup.r_c).abs().powi(3);
    let power_in = power_in + bal.land_torque_n_m * setup.land_speed;
    let c0 = static_load_rating(setup.bearing);
    let warnings = point_warnings(setup, &bal, max_pressure, c0);
    let fr = cond.radial_load_n;
    let force_res = ld.force_residual_n[0].hypot(ld.force_residual_n[1]);
    let max_load = ld.max_inner_load_n.max(ld.max_outer_load_n);
    let min_scuffing_margin = rollers
        .iter()
        .flat_map(|x| [x.inner.scuffing_margin, x.outer.scuffing_margin])
        .flatten()
        .reduce(f64::min);
    Ok(SkidResult {
        kinematic_case: KinematicCase::of(cond.inner_speed_rad_s, cond.outer_speed_rad_s),
        inner_speed_rad_s: cond.inner_speed_rad_s,
        outer_speed_rad_s: cond.outer_speed_rad_s,
        radial_load_n: fr,
        misalignment_rad: setup.misalignment,
        cage_speed_rad_s: cage_speed,
        epicyclic_cage_speed_rad_s: setup.epicyclic,
        cage_slip: cage_slip(cage_speed, setup.epicyclic),
        roller_slip_reference: if reference_outer { "outer" } else { "inner" },
        rollers,
        max_roller_load_n: max_load,
        max_contact_pressure_pa: max_pressure,
        loaded_rollers: ld.loaded_rollers,
        load_zone_half_angle_rad: ld.load_zone_half_angle_rad,
        ring_displacement_m: ld.ring_displacement_m,
        operating_clearance_m: setup.geometry.clearance.operating_m,
        operating_geometry: setup.geometry.clone(),
        cage: bal,
        power_loss_w: power.total(),
        power_input_w: power_in,
        power,
        min_scuffing_margin,
        static_load_rating_n: c0,
        solve_time_s: start.elapsed().as_secs_f64(),
        iterations: Iterations {
            cage_evaluations: cage_evals,
            roller_evaluations: ws.roller_evaluations,
            load_iterations: ws.load_iterations,
        },
        converged: true,
        residuals: Residuals {
            cage_moment_relative: cage_residual,
            roller_moment_relative: max_roller_moment_rel,
            force_balance_relative: if fr > 0.0 { force_res / fr } else { force_res },
            roller_radial_balance_n: ld.roller_residual_n,
        },
        friction_model: friction_model_name(&setup.traction),
        cage_land_model: land_model.name(),
        cage_drag_law: cage_drag_law(&cond.drag),
        warnings,
        load_distribution: ld,
    })
}

/// The drag laws of a point, in words: the cage's (a given linear coefficient or the seed 001
/// mixture formula) and the rollers'.
fn cage_drag_law(d: &crate::conditions::DragInputs) -> String {
    let cage = match (d.enabled, d.viscous_coefficient_n_m_s) {
        (false, _) => "cage drag off".to_string(),
        (true, Some(c)) => format!("cage M = −c ω₀, c = {c:.4e} N·m·s (given per model)"),
        (true, None) => format!(
            "cage: seed 001 mixture formula (oil volume fraction {})",
            d.oil_volume_fraction
        ),
    };
    if d.roller_drag_kg_m > 0.0 {
        format!(
            "{cage}; rollers F = k v², k = ½ρ_eff C_D D l = {:.4e} kg/m",
            d.roller_drag_kg_m
        )
    } else {
        format!("{cage}; no roller drag")
    }
}

/// Per-roller results of the final state and their sums over the bearing.
struct RollerSums {
    rollers: Vec<RollerResult>,
    /// Contact powers (the cage land and drag are added by the caller), W.
    power: PowerBreakdown,
    /// Power delivered by the rings to the rollers (raceways and rib), W.
    power_in: f64,
    /// Largest roller moment residual relative to `R_w (Q_i + Q_o)`.
    max_roller_moment_rel: f64,
    /// Largest Hertz pressure of the loaded raceway contacts, Pa.
    max_pressure: f64,
}

/// Results of every roller at the final state `evals` of the load distribution `ld`, with
/// their scuffing margins, powers and residuals summed over the bearing.
fn roller_results(
    setup: &Setup<'_>,
    kin: &Kinematics,
    ld: &LoadDistribution,
    evals: &[Option<RollerEval>],
) -> Result<RollerSums, QsError> {
    let mut slips = CriticalSlips::new(setup.opts);
    let mut sums = RollerSums {
        rollers: Vec::with_capacity(ld.rollers.len()),
        power: PowerBreakdown::default(),
        power_in: 0.0,
        max_roller_moment_rel: 0.0,
        max_pressure: 0.0,
    };
    for (j, r) in ld.rollers.iter().enumerate() {
        let ev = evals[j].ok_or_else(|| QsError::InvalidInput("roller not solved".into()))?;
        let roller = roller_result(setup, kin, j, r, &ev, &mut slips);
        for c in [&roller.inner, &roller.outer] {
            if c.normal_force_n > 0.0 {
                sums.max_pressure = sums.max_pressure.max(c.max_pressure_pa);
            }
        }
        let power = &mut sums.power;
        power.inner_raceways_w += roller.inner.power_w;
        power.outer_raceways_w += roller.outer.power_w;
        power.cage_bars_w += roller.bar.power_w;
        power.ribs_w += roller.rib_power_w;
        power.pockets_w += roller.pocket_power_w;
        power.rolling_resistance_w += roller.rolling_resistance_power_w;
        sums.power_in += ev.inner_force * setup.r_i * kin.inner_speed
            + ev.outer_force * setup.r_o * kin.outer_speed;
        if let Some(rib) = &setup.rib {
            let ring = if rib.outer_ring {
                kin.outer_speed
            } else {
                kin.inner_speed
            };
            sums.power_in += ev.rib_force * rib.radius_m * ring;
        }
        let scale = setup.r_w * (r.inner_force_n + r.outer_force_n) + 1e-9;
        sums.max_roller_moment_rel = sums.max_roller_moment_rel.max((ev.moment / scale).abs());
        sums.rollers.push(roller);
    }
    Ok(sums)
}

/// Result of roller `j` (load `r`, final state `ev`): raceway contacts with scuffing margins,
/// cage bar, rib, pocket and rolling-resistance powers.
fn roller_result(
    setup: &Setup<'_>,
    kin: &Kinematics,
    j: usize,
    r: &RollerLoad,
    ev: &RollerEval,
    slips: &mut CriticalSlips<'_>,
) -> RollerResult {
    let u_min = setup.opts.min_rolling_speed_m_s;
    let mut inner = contact_result(
        ev.inner.as_ref(),
        &ev.inner_state,
        r.inner_effective_length_m,
        u_min,
    );
    let mut outer = contact_result(
        ev.outer.as_ref(),
        &ev.outer_state,
        r.outer_effective_length_m,
        u_min,
    );
    for (c, st) in [(&mut inner, &ev.inner_state), (&mut outer, &ev.outer_state)] {
        if c.normal_force_n > 0.0 {
            c.critical_slip = slips.of(st, &setup.traction);
            let s = c.slide_roll_ratio.abs();
            c.scuffing_margin = c.critical_slip.and_then(|sc| (s > 0.0).then(|| sc / s));
        }
    }
    let v_bar = ev.spin * setup.r_w;
    let q_bar = ev.push.abs();
    let bar = BarResult {
        normal_force_n: q_bar,
        push_n: ev.push,
        friction_coefficient: ev.bar_mu,
        sliding_speed_m_s: v_bar,
        power_w: (ev.bar_mu * q_bar * v_bar).abs(),
    };
    let rib_power = (ev.rib_force * ev.rib_sliding).abs();
    let pocket_power = (ev.pocket_moment * ev.spin).abs();
    let rr_power = (ev.rolling_moment * ev.spin).abs();
    let roller_power =
        inner.power_w + outer.power_w + bar.power_w + rib_power + pocket_power + rr_power;
    RollerResult {
        index: j,
        azimuth_rad: r.azimuth_rad,
        zone: if r.loaded {
            Zone::Loaded
        } else {
            Zone::Unloaded
        },
        spin_rad_s: ev.spin,
        slip: kin.roller_slip(ev.spin, setup.opts.slip_reference),
        centrifugal_force_n: r.centrifugal_force_n,
        tilt_rad: r.roller_tilt_rad,
        inner,
        outer,
        bar,
        rib_force_n: ev.rib_force,
        rib_power_w: rib_power,
        pocket_moment_n_m: ev.pocket_moment,
        pocket_power_w: pocket_power,
        rolling_resistance_moment_n_m: ev.rolling_moment,
        rolling_resistance_power_w: rr_power,
        power_w: roller_power,
        moment_residual_n_m: ev.moment,
    }
}

/// Critical slips of the friction curve (scuffing margins, SPEC §4.8), computed once per
/// distinct contact state.
struct CriticalSlips<'a> {
    opts: &'a QuasiStaticOptions,
    search: SlipSearch,
    cache: Vec<(ContactState, Option<f64>)>,
}

impl<'a> CriticalSlips<'a> {
    fn new(opts: &'a QuasiStaticOptions) -> Self {
        Self {
            opts,
            search: SlipSearch::default(),
            cache: Vec::new(),
        }
    }

    /// Critical slip of a loaded, rolling contact (`None` with the scuffing search switched
    /// off or without an interior maximum of the friction curve).
    fn of(&mut self, state: &ContactState, model: &TractionModel) -> Option<f64> {
        let u_min = self.opts.min_rolling_speed_m_s;
        if !self.opts.scuffing
            || state.normal_force_n <= 0.0
            || state.rolling_speed_m_s.abs() < u_min
        {
            return None;
        }
        if let Some((_, v)) = self.cache.iter().find(|(s, _)| s == state) {
            return *v;
        }
        let v = match critical_slip(state, model, &self.search) {
            Ok(CriticalSlip::Maximum { slip, .. }) => Some(slip),
            _ => None,
        };
        self.cache.push((*state, v));
        v
    }
}

/// Warnings of the point: those of the setup, a saturated cage-land film, a radial load above
/// the static load rating `c0` (N) and a Hertz pressure above the 4000 MPa of ISO 76.
fn point_warnings(setup: &Setup<'_>, bal: &CageBalance, max_pressure: f64, c0: f64) -> Vec<String> {
    let mut warnings = setup.warnings.clone();
    if bal.land_saturated {
        warnings.push(
            "cage land: the hydrodynamic capacity of the short-bearing film is exceeded \
             (eccentricity clamped)"
                .into(),
        );
    }
    if setup.cond.radial_load_n > c0 {
        warnings.push(format!(
            "radial load {:.0} N exceeds the basic static load rating C0r = {:.0} N (ISO 76)",
            setup.cond.radial_load_n, c0
        ));
    }
    if max_pressure > 4.0e9 {
        warnings.push(format!(
            "maximum Hertz pressure {:.0} MPa exceeds the 4000 MPa of the ISO 76 static rating",
            max_pressure * 1e-6
        ));
    }
    warnings
}

/// Name of the raceway friction law in the result.
fn friction_model_name(traction: &TractionModel) -> &'static str {
    match &traction.config().law {
        FrictionLaw::Seed001(_) => "seed 001 (asperity fraction + film shear + Blok flash)",
        FrictionLaw::Lubricated(_) => "seed 000 (Muraki/mixed (1.3))",
        FrictionLaw::TwoLevel(_) => "two-level",
    }
}
