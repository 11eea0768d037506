//! Issue 23 "one answer from both models": the cage slip of the quasi-static model (seed 001,
//! theory §6) and of the dynamics (seed 000, theory §3) at one operating point, with the physics
//! that differs between them switched one at a time ([`Switches`]).
//!
//! Each row solves the quasi-static point the dynamics starts from
//! ([`rolldyn_setup::quasi_static::dynamics_start_conditions`]) and runs the dynamics that
//! `rolldyn simulate` builds ([`rolldyn_setup::prepare_with`]) from that start, both with the
//! row's switches. The dynamic slip is the mean of the per-revolution slips after the first
//! `skipped_revolutions` (the start transient), with their standard deviation; the power of each
//! loss is averaged over the same revolutions so that the two models' energy balances can be
//! compared term by term (theory §6.6 power balance).

use rolldyn_dynamics::conditions::OperatingConditions;
use rolldyn_dynamics::output::{OutputSink, RevolutionSummary, Snapshot};
use rolldyn_dynamics::{CageLandModel, TwoLevelLand};
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use rolldyn_model::Model;
use rolldyn_quasistatic::{QuasiStaticOptions, SkidResult, Zone};
use rolldyn_setup::quasi_static::{LandChoice, cage_land_model, dynamics_start_conditions};
use rolldyn_setup::{LoadDirection, Overrides};

/// One operating point of the comparison.
#[derive(Debug, Clone)]
pub struct Case {
    /// Short name for the table.
    pub name: String,
    /// The model (a cylindrical bearing with a `[lubricant]` section).
    pub model: Model,
    /// Inner-ring speed, rad/s.
    pub speed_rad_s: f64,
    /// Radial load, N.
    pub radial_load_n: f64,
    /// Direction of the radial load.
    pub load_direction: LoadDirection,
    /// Oil temperature, K (`None`: the model's).
    pub oil_temperature_k: Option<f64>,
}

/// The physics that differs between the two models, each switchable. [`Switches::today`] is
/// what `rolldyn simulate` and its quasi-static start use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Switches {
    /// Quasi-static only: seed 001 rolling resistance T_к = f_к (Q_i + Q_o) on every roller
    /// (theory §6.4); the dynamics has no such term.
    pub rolling_resistance: bool,
    /// Quasi-static only: the Newtonian roller-end films at the ribs and the pocket faces
    /// (seed 001, theory §6.4); the dynamics has end contacts that carry force (and boundary
    /// friction) only when they touch.
    pub end_films: bool,
    /// Both: the linear cage drag `[dynamics] cage_drag` (seed 000 §3.1.1).
    pub cage_drag: bool,
    /// Both: the land film (finite journal bearing). Off: no land torque in the quasi-static
    /// model; in the dynamics a land that only stops the cage (metal contact, frictionless).
    pub land_film: bool,
    /// Quasi-static only: the land film sees the load turning with a rotating load (the roller
    /// pushes follow the load zone); off: the load resultant is taken as fixed in space.
    pub rotating_load_on_land: bool,
    /// Quasi-static only: the cage is pressed on its land by the centrifugal force of its own
    /// displacement m_c e ω₀² (a synchronous whirl); off: by the roller forces alone.
    pub land_centrifugal: bool,
    /// Both: friction at the roller ↔ cage-bar contacts (off: frictionless bars in both).
    pub bar_friction: bool,
    /// Dynamics only: the roller-end contacts with the ribs and pocket faces (off: not
    /// evaluated; their boundary friction is what slows the unloaded rollers there).
    pub end_contacts: bool,
}

impl Switches {
    /// Today's defaults of both models.
    pub fn today() -> Self {
        Self {
            rolling_resistance: true,
            end_films: true,
            cage_drag: true,
            land_film: true,
            rotating_load_on_land: true,
            land_centrifugal: true,
            bar_friction: true,
            end_contacts: true,
        }
    }
}

/// One labelled row: a set of switches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// What the row changes from the baseline.
    pub label: &'static str,
    /// The switches.
    pub switches: Switches,
}

/// The rows of the table: the baseline, then each difference alone, then the quasi-static model
/// without the two terms the dynamics does not have.
pub fn rows() -> Vec<Row> {
    let t = Switches::today();
    vec![
        Row {
            label: "baseline (today's defaults)",
            switches: t,
        },
        Row {
            label: "QS: no rolling resistance f_k",
            switches: Switches {
                rolling_resistance: false,
                ..t
            },
        },
        Row {
            label: "QS: no roller-end films",
            switches: Switches {
                end_films: false,
                ..t
            },
        },
        Row {
            label: "QS: land load fixed in space",
            switches: Switches {
                rotating_load_on_land: false,
                ..t
            },
        },
        Row {
            label: "QS: no centrifugal pressing of the displaced cage",
            switches: Switches {
                land_centrifugal: false,
                ..t
            },
        },
        Row {
            label: "both: no cage drag",
            switches: Switches {
                cage_drag: false,
                ..t
            },
        },
        Row {
            label: "both: no land film torque",
            switches: Switches {
                land_film: false,
                ..t
            },
        },
        Row {
            label: "both: no drag and no land film (no cage torque)",
            switches: Switches {
                cage_drag: false,
                land_film: false,
                ..t
            },
        },
        Row {
            label: "both: frictionless cage bars",
            switches: Switches {
                bar_friction: false,
                ..t
            },
        },
        Row {
            label: "dynamics: no roller-end contacts",
            switches: Switches {
                end_contacts: false,
                ..t
            },
        },
        Row {
            label: "QS: no f_k and no end films (the dynamics' physics)",
            switches: Switches {
                rolling_resistance: false,
                end_films: false,
                ..t
            },
        },
    ]
}

/// Length of a dynamic run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunLength {
    /// Epicyclic cage revolutions simulated.
    pub revolutions: u32,
    /// Revolutions left out of the averages (start transient).
    pub skipped_revolutions: u32,
    /// Output samples per revolution for the power and land averages.
    pub samples_per_revolution: u32,
}

impl Default for RunLength {
    /// 10 revolutions, the first 4 skipped (the O'Brien–Taylor start settles within 2–3),
    /// 100 samples per revolution.
    fn default() -> Self {
        Self {
            revolutions: 10,
            skipped_revolutions: 4,
            samples_per_revolution: 100,
        }
    }
}

/// Time-mean power of each loss, W.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Powers {
    /// Both raceways.
    pub raceways_w: f64,
    /// Roller ↔ cage bars.
    pub bars_w: f64,
    /// Roller ends (ribs and pocket faces; films in the quasi-static model).
    pub ends_w: f64,
    /// Cage ↔ land.
    pub land_w: f64,
    /// Cage drag.
    pub drag_w: f64,
    /// Rolling resistance (quasi-static only).
    pub rolling_resistance_w: f64,
}

/// Mean roller kinematics and traction: how hard the raceways drive the rollers.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RollerTraction {
    /// Slide-to-roll ratio on the outer raceway of the rollers without inner contact force.
    pub outer_srr_unloaded: f64,
    /// Slide-to-roll ratio on the inner raceway of the rollers with inner contact force
    /// (weighted by that force, as the next three).
    pub inner_srr_loaded: f64,
    /// Slide-to-roll ratio on the outer raceway of those rollers.
    pub outer_srr_loaded: f64,
    /// Traction coefficient on the inner raceway of those rollers.
    pub inner_mu_loaded: f64,
    /// Film parameter Λ on the inner raceway of those rollers.
    pub inner_lambda_loaded: f64,
}

/// Accumulates [`RollerTraction`] over rollers (and samples); loaded rollers weighted by their
/// inner contact force.
#[derive(Debug, Clone, Default)]
struct TractionSums {
    unloaded: (f64, usize),
    loaded: [f64; 4],
    loaded_weight: f64,
}

impl TractionSums {
    fn add_unloaded(&mut self, outer_srr: f64) {
        if outer_srr.is_finite() {
            self.unloaded.0 += outer_srr;
            self.unloaded.1 += 1;
        }
    }

    fn add_loaded(&mut self, force: f64, srr: f64, outer_srr: f64, mu: f64, lambda: f64) {
        let values = [srr, outer_srr, mu, lambda];
        if values.iter().all(|v| v.is_finite()) {
            for (sum, v) in self.loaded.iter_mut().zip(values) {
                *sum += force * v;
            }
            self.loaded_weight += force;
        }
    }

    fn mean(&self) -> RollerTraction {
        let n = if self.loaded_weight > 0.0 {
            self.loaded_weight
        } else {
            1.0
        };
        RollerTraction {
            outer_srr_unloaded: self.unloaded.0 / self.unloaded.1.max(1) as f64,
            inner_srr_loaded: self.loaded[0] / n,
            outer_srr_loaded: self.loaded[1] / n,
            inner_mu_loaded: self.loaded[2] / n,
            inner_lambda_loaded: self.loaded[3] / n,
        }
    }
}

/// The dynamic result of one row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicResult {
    /// Mean of the per-revolution cage slips after the skipped ones.
    pub slip: f64,
    /// Standard deviation of those per-revolution slips.
    pub slip_scatter: f64,
    /// Revolutions averaged.
    pub revolutions: usize,
    /// Mean powers.
    pub powers: Powers,
    /// Mean land normal force, N.
    pub land_force_n: f64,
    /// Mean distance of the cage centre from the bearing axis, m.
    pub cage_offset_m: f64,
    /// Mean roller traction over the samples.
    pub traction: RollerTraction,
    /// Wall time, s.
    pub wall_s: f64,
}

/// The quasi-static result of one row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuasiStaticResult {
    /// Cage slip on the quasi-static model's own epicyclic reference (operating diameters).
    pub slip: f64,
    /// The same cage speed on the dynamics' epicyclic reference (rolling diameters).
    pub slip_on_dynamic_reference: f64,
    /// Powers of the losses.
    pub powers: Powers,
    /// Land pressing force F_RS, N.
    pub land_force_n: f64,
    /// Cage eccentricity ratio on the land.
    pub land_eccentricity_ratio: f64,
    /// Mean roller traction.
    pub traction: RollerTraction,
}

/// Both models at one row.
#[derive(Debug, Clone)]
pub struct RowResult {
    /// The row.
    pub row: Row,
    /// Quasi-static model, or why it failed.
    pub quasi_static: Result<QuasiStaticResult, String>,
    /// Dynamics, or why it failed.
    pub dynamic: Result<DynamicResult, String>,
}

fn bearing_of(model: &Model) -> Result<&CylindricalRollerBearing, String> {
    match &model.bearing {
        BearingModel::Cylindrical(b) => Ok(b),
        _ => Err("the comparison needs a cylindrical bearing".into()),
    }
}

fn operating_conditions(case: &Case, switches: &Switches) -> Result<OperatingConditions, String> {
    let overrides = Overrides {
        speed: Some(case.speed_rad_s),
        radial_load: Some(case.radial_load_n),
        axial_load: None,
        load_direction: Some(case.load_direction),
        oil_temperature: case.oil_temperature_k,
        ..Overrides::default()
    };
    let mut c = rolldyn_setup::conditions(&overrides, &case.model).map_err(|e| e.to_string())?;
    if !switches.cage_drag {
        c.cage_drag_n_m_s = 0.0;
    }
    Ok(c)
}

/// The quasi-static point of `case` under `switches`.
pub fn quasi_static(case: &Case, switches: &Switches) -> Result<QuasiStaticResult, String> {
    let bearing = bearing_of(&case.model)?;
    let conditions = operating_conditions(case, switches)?;
    let lubrication = rolldyn_setup::quasi_static::lubrication(&case.model, "simulate")
        .map_err(|e| e.to_string())?;
    let mut qs = dynamics_start_conditions(&conditions, lubrication);
    if !switches.rolling_resistance {
        qs.rolling_friction_m = 0.0;
    }
    qs.end_friction.ribs = switches.end_films;
    qs.end_friction.pocket = switches.end_films;
    qs.cage_land.enabled = switches.land_film;
    if !switches.rotating_load_on_land {
        qs.load_speed_rad_s = 0.0;
    }
    qs.cage_land.centrifugal_pressing = switches.land_centrifugal;
    if !switches.bar_friction {
        qs.bar_friction = rolldyn_quasistatic::BarFriction::Constant(0.0);
    }
    let land = cage_land_model(bearing, LandChoice::Finite);
    let r: SkidResult = rolldyn_quasistatic::solve_with_land_model(
        bearing,
        &qs,
        &QuasiStaticOptions::default(),
        land.as_ref(),
    )
    .map_err(|e| e.to_string())?;
    let dynamic_reference = bearing.epicyclic_cage_speed(qs.inner_speed_rad_s, 0.0);
    let p = &r.power;
    let mut traction = TractionSums::default();
    for roller in &r.rollers {
        match roller.zone {
            Zone::Loaded => traction.add_loaded(
                roller.inner.normal_force_n,
                roller.inner.slide_roll_ratio,
                roller.outer.slide_roll_ratio,
                roller.inner.friction_coefficient,
                roller.inner.lambda.unwrap_or(f64::NAN),
            ),
            Zone::Unloaded => traction.add_unloaded(roller.outer.slide_roll_ratio),
        }
    }
    Ok(QuasiStaticResult {
        slip: r.cage_slip,
        slip_on_dynamic_reference: 1.0 - r.cage_speed_rad_s / dynamic_reference,
        powers: Powers {
            raceways_w: p.inner_raceways_w + p.outer_raceways_w,
            bars_w: p.cage_bars_w,
            ends_w: p.ribs_w + p.pockets_w,
            land_w: p.cage_land_w,
            drag_w: p.drag_w,
            rolling_resistance_w: p.rolling_resistance_w,
        },
        land_force_n: r.cage.pressing_force_n,
        land_eccentricity_ratio: r.cage.eccentricity_ratio,
        traction: traction.mean(),
    })
}

/// Per-revolution slips and running sums of the sampled powers after `skip` revolutions.
#[derive(Default)]
struct Recorder {
    skip: u64,
    slips: Vec<f64>,
    samples: usize,
    powers: Powers,
    land_force: f64,
    cage_offset: f64,
    drag_n_m_s: f64,
    traction: TractionSums,
}

impl OutputSink for Recorder {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        if self.slips.is_empty() {
            return;
        }
        let r = &s.rollers;
        let sum = |v: &[f64]| v.iter().sum::<f64>();
        self.samples += 1;
        let p = &mut self.powers;
        p.raceways_w += sum(r.inner.friction_power_w) + sum(r.outer.friction_power_w);
        p.bars_w += sum(r.cage_bar_power_w);
        p.ends_w += sum(r.rib_power_w) + sum(r.pocket_face_power_w);
        p.land_w += s.cage_land_power_w;
        p.drag_w += self.drag_n_m_s * s.cage_speed_rad_s * s.cage_speed_rad_s;
        self.land_force += s.cage_land_force_n;
        self.cage_offset += s.cage_center_m[0].hypot(s.cage_center_m[1]);
        for (j, &force) in r.inner.force_n.iter().enumerate() {
            if force > 0.0 {
                self.traction.add_loaded(
                    force,
                    r.inner.slide_to_roll[j],
                    r.outer.slide_to_roll[j],
                    r.inner.traction_coefficient[j],
                    r.inner.lambda[j],
                );
            } else {
                self.traction.add_unloaded(r.outer.slide_to_roll[j]);
            }
        }
    }

    fn revolution(&mut self, summary: &RevolutionSummary) {
        if summary.revolution > self.skip {
            self.slips.push(summary.cage_slip_mean);
        }
    }
}

/// A land that only stops the cage: the dynamics' metal land contact without friction.
fn frictionless_land(bearing: &CylindricalRollerBearing) -> Box<dyn CageLandModel> {
    let mut parameters =
        rolldyn_dynamics::parameters::ContactParameters::for_bearing(bearing).cage_land;
    parameters.friction.mu_static = 0.0;
    parameters.friction.mu_dynamic = 0.0;
    Box::new(TwoLevelLand { parameters })
}

/// The dynamics of `case` under `switches`, started at the quasi-static solution.
pub fn dynamic(
    case: &Case,
    switches: &Switches,
    length: &RunLength,
) -> Result<DynamicResult, String> {
    let bearing = bearing_of(&case.model)?;
    let conditions = operating_conditions(case, switches)?;
    let drag_n_m_s = conditions.cage_drag_n_m_s;
    let lubrication = rolldyn_setup::quasi_static::lubrication(&case.model, "simulate")
        .map_err(|e| e.to_string())?;
    let epicyclic = bearing.epicyclic_cage_speed(case.speed_rad_s, 0.0).abs();
    let revolution_s = std::f64::consts::TAU / epicyclic;
    let mut inputs = case.model.dynamics;
    if !switches.bar_friction {
        inputs.roller_cage.mu_static = Some(0.0);
        inputs.roller_cage.mu_dynamic = Some(0.0);
    }
    if !switches.end_contacts {
        inputs.roller_end_rib.enabled = Some(false);
        inputs.roller_end_cage.enabled = Some(false);
    }
    let prepared = rolldyn_setup::prepare_with(
        bearing,
        lubrication,
        &inputs,
        conditions,
        revolution_s / length.samples_per_revolution.max(1) as f64,
        None,
    )
    .map_err(|e| e.to_string())?;
    let mut sim = prepared.simulation;
    if !switches.land_film {
        sim.set_cage_land_model(frictionless_land(bearing));
    }
    let mut recorder = Recorder {
        skip: length.skipped_revolutions as u64,
        drag_n_m_s,
        ..Recorder::default()
    };
    let end = sim.time() + length.revolutions as f64 * revolution_s;
    sim.run_until(end, &mut recorder, &mut |_| {})
        .map_err(|e| e.to_string())?;
    let n = recorder.slips.len();
    if n == 0 {
        return Err("no complete revolution after the skipped ones".into());
    }
    let mean = recorder.slips.iter().sum::<f64>() / n as f64;
    let var = recorder
        .slips
        .iter()
        .map(|s| (s - mean).powi(2))
        .sum::<f64>()
        / n as f64;
    let k = recorder.samples.max(1) as f64;
    let p = recorder.powers;
    Ok(DynamicResult {
        slip: mean,
        slip_scatter: var.sqrt(),
        revolutions: n,
        powers: Powers {
            raceways_w: p.raceways_w / k,
            bars_w: p.bars_w / k,
            ends_w: p.ends_w / k,
            land_w: p.land_w / k,
            drag_w: p.drag_w / k,
            rolling_resistance_w: 0.0,
        },
        land_force_n: recorder.land_force / k,
        cage_offset_m: recorder.cage_offset / k,
        traction: recorder.traction.mean(),
        wall_s: sim.summary().wall_time_s,
    })
}

/// Both models at every row of `rows`.
pub fn table(case: &Case, rows: &[Row], length: &RunLength) -> Vec<RowResult> {
    rows.iter()
        .map(|row| RowResult {
            row: *row,
            quasi_static: quasi_static(case, &row.switches),
            dynamic: dynamic(case, &row.switches, length),
        })
        .collect()
}

/// CSV header of [`csv_line`].
pub const CSV_HEADER: &str = "case,row,qs_slip,qs_slip_dynamic_reference,dyn_slip,dyn_slip_scatter,dyn_revolutions,ratio_dyn_qs,qs_land_force_n,qs_land_eccentricity,dyn_land_force_n,dyn_cage_offset_um,qs_raceways_w,dyn_raceways_w,qs_bars_w,dyn_bars_w,qs_ends_w,dyn_ends_w,qs_land_w,dyn_land_w,qs_drag_w,dyn_drag_w,qs_rolling_resistance_w,qs_outer_srr_unloaded,dyn_outer_srr_unloaded,qs_inner_srr_loaded,dyn_inner_srr_loaded,qs_outer_srr_loaded,dyn_outer_srr_loaded,qs_inner_mu_loaded,dyn_inner_mu_loaded,qs_inner_lambda_loaded,dyn_inner_lambda_loaded,dyn_wall_s,error";

/// One CSV line of a row (NaN where a model failed; the reason in the last column).
pub fn csv_line(case: &str, r: &RowResult) -> String {
    let nan = f64::NAN;
    let q = r.quasi_static.as_ref().ok();
    let d = r.dynamic.as_ref().ok();
    let qf = |f: &dyn Fn(&QuasiStaticResult) -> f64| q.map_or(nan, f);
    let df = |f: &dyn Fn(&DynamicResult) -> f64| d.map_or(nan, f);
    let error = [r.quasi_static.as_ref().err(), r.dynamic.as_ref().err()]
        .into_iter()
        .flatten()
        .map(|e| e.replace([',', '\n'], ";"))
        .collect::<Vec<_>>()
        .join(" | ");
    let values = [
        qf(&|q| q.slip),
        qf(&|q| q.slip_on_dynamic_reference),
        df(&|d| d.slip),
        df(&|d| d.slip_scatter),
        df(&|d| d.revolutions as f64),
        df(&|d| d.slip) / qf(&|q| q.slip_on_dynamic_reference),
        qf(&|q| q.land_force_n),
        qf(&|q| q.land_eccentricity_ratio),
        df(&|d| d.land_force_n),
        df(&|d| d.cage_offset_m * 1e6),
        qf(&|q| q.powers.raceways_w),
        df(&|d| d.powers.raceways_w),
        qf(&|q| q.powers.bars_w),
        df(&|d| d.powers.bars_w),
        qf(&|q| q.powers.ends_w),
        df(&|d| d.powers.ends_w),
        qf(&|q| q.powers.land_w),
        df(&|d| d.powers.land_w),
        qf(&|q| q.powers.drag_w),
        df(&|d| d.powers.drag_w),
        qf(&|q| q.powers.rolling_resistance_w),
        qf(&|q| q.traction.outer_srr_unloaded),
        df(&|d| d.traction.outer_srr_unloaded),
        qf(&|q| q.traction.inner_srr_loaded),
        df(&|d| d.traction.inner_srr_loaded),
        qf(&|q| q.traction.outer_srr_loaded),
        df(&|d| d.traction.outer_srr_loaded),
        qf(&|q| q.traction.inner_mu_loaded),
        df(&|d| d.traction.inner_mu_loaded),
        qf(&|q| q.traction.inner_lambda_loaded),
        df(&|d| d.traction.inner_lambda_loaded),
        df(&|d| d.wall_s),
    ];
    let numbers: Vec<String> = values.iter().map(|v| format!("{v:.6e}")).collect();
    format!("{case},{},{},{error}", r.row.label, numbers.join(","))
}
