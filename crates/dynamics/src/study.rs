//! The O'Brien–Taylor cage-slip study (SPEC V-06, seed 000 §2.3, Figs. 2.14–2.16): cage slip
//! vs radial load at 1500…4500 rpm and vs misalignment at 201 N, for the CLI to call.
//!
//! Inputs fixed by the seed: oil NVI 65 with only the elastic term of (1.4) (Γ = 3 GPa, linear
//! rheology), Λ_bd = 1.35, Λ_hd = 3.05 in (1.3), Ra = 0.32 µm on the raceways and 0.16 µm on the
//! rollers, oil temperature per speed from seed Table 2.4 (1500 → 44 °C, 2500 → 49.5 °C,
//! 4000 → 54.5 °C, 4500 → 59 °C; linear in between, constant outside).

use crate::conditions::OperatingConditions;
use crate::error::DynError;
use crate::model::RacewayTraction;
use crate::output::{NullSink, RunSummary};
use crate::parameters::ContactParameters;
use crate::settings::DynamicsSettings;
use crate::simulation::Simulation;
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_lubrication::{MurakiSettings, Rheology, TractionModel, lubricant_by_name};

/// Seed 000 Table 2.4: (speed rpm, oil temperature °C).
pub const TABLE_2_4: [(f64, f64); 4] = [
    (1500.0, 44.0),
    (2500.0, 49.5),
    (4000.0, 54.5),
    (4500.0, 59.0),
];

/// Oil temperature of the O'Brien–Taylor tests at `rpm` (Table 2.4, linear interpolation), K.
pub fn oil_temperature_k(rpm: f64) -> f64 {
    let t = &TABLE_2_4;
    let c = if rpm <= t[0].0 {
        t[0].1
    } else if rpm >= t[3].0 {
        t[3].1
    } else {
        let mut v = t[3].1;
        for w in t.windows(2) {
            if rpm <= w[1].0 {
                v = w[0].1 + (w[1].1 - w[0].1) * (rpm - w[0].0) / (w[1].0 - w[0].0);
                break;
            }
        }
        v
    };
    c + 273.15
}

/// NVI 65 traction model of V-06: Muraki with the linear-elastic rheology (Γ = 3 GPa from the
/// oil data), Kragelsky boundary friction, Λ blend 1.35/3.05 (from the oil data).
pub fn nvi65_traction() -> Result<TractionModel, DynError> {
    let oil = lubricant_by_name("nvi65").map_err(|e| DynError::InvalidInput(e.to_string()))?;
    TractionModel::lubricated(
        oil,
        MurakiSettings {
            rheology: Rheology::LinearElastic { cap: 0.1 },
            ..MurakiSettings::default()
        },
    )
    .map_err(|e| DynError::InvalidInput(e.to_string()))
}

/// Settings of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudySettings {
    /// inner-ring speeds, rpm
    pub speeds_rpm: Vec<f64>,
    /// radial loads, N
    pub loads_n: Vec<f64>,
    /// misalignments for the second series, rad
    pub misalignments_rad: Vec<f64>,
    /// load of the misalignment series, N (seed: 201 N)
    pub misalignment_load_n: f64,
    /// speed of the misalignment series, rpm
    pub misalignment_speed_rpm: f64,
    /// Most cage revolutions simulated per point (transient + averaging window). The run stops
    /// earlier once steady state is detected and `average_revolutions` whole revolutions after
    /// it are complete.
    pub cage_revolutions: f64,
    /// Whole cage revolutions averaged after steady state (or, if steady state is not detected
    /// within `cage_revolutions`, the last ones run; [`StudyPoint::steady`] is then false).
    pub average_revolutions: u32,
    /// Steady state: the mean cage speed of two consecutive cage revolutions differs by less
    /// than this fraction of the epicyclic speed (default 2e-4 — below the slip being measured;
    /// the run default 1e-3 of [`DynamicsSettings`] is too coarse for slips ~1e-3).
    pub steady_tolerance: f64,
    /// slices per roller (overrides the model)
    pub slices: Option<usize>,
    /// cage viscous drag coefficient, N·m·s/rad. The seed gives none for this bearing; the
    /// default scales the 2002834 CFD value (6.62e-4 at d_m = 180 mm, B = 20 mm, 100 °C) by
    /// d_m³·B (80/180)³·(19/20) and by the NVI 65 / 100 °C-oil viscosity ratio ≈ 10 at 55 °C
    /// → 5.5e-4 (an order-of-magnitude proposal; the rollers' own churning losses are neglected
    /// as in seed 000, so the absolute slip depends on this choice).
    pub cage_drag_n_m_s: f64,
    /// dynamics settings
    pub dynamics: DynamicsSettings,
}

impl Default for StudySettings {
    /// Seed 000 Fig. 2.14–2.16 ranges: 1500, 2500, 4000, 4500 rpm × 104…687 N; misalignment
    /// 0…8′ at 201 N and 4000 rpm (angles not tabulated in the seed; 0, 2, 4, 8′ proposed);
    /// 6 cage revolutions per point.
    fn default() -> Self {
        Self {
            speeds_rpm: vec![1500.0, 2500.0, 4000.0, 4500.0],
            loads_n: vec![104.0, 201.0, 300.0, 450.0, 687.0],
            misalignments_rad: [0.0, 2.0, 4.0, 8.0]
                .iter()
                .map(|m: &f64| (m / 60.0).to_radians())
                .collect(),
            misalignment_load_n: 201.0,
            misalignment_speed_rpm: 4000.0,
            cage_revolutions: 16.0,
            average_revolutions: 4,
            steady_tolerance: 2e-4,
            slices: None,
            cage_drag_n_m_s: 5.5e-4,
            dynamics: DynamicsSettings::default(),
        }
    }
}

/// One study point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyPoint {
    /// inner-ring speed, rpm
    pub speed_rpm: f64,
    /// radial load, N
    pub radial_load_n: f64,
    /// misalignment, rad
    pub misalignment_rad: f64,
    /// oil temperature, K
    pub temperature_k: f64,
    /// Cage slip `1 − ω̄_c/ω_epi` with `ω̄_c = Δφ/Δt` over the `K` cage-revolution periods
    /// averaged (seed 000 (2.19) with the cage speed measured by its rotation angle φ, so the
    /// cage's excursions inside the pocket and land clearances cancel except for the change of
    /// position between the window ends, ≤ clearance/(R·2πK))
    pub cage_slip: f64,
    /// whole cage revolutions in the averaging window
    pub revolutions_averaged: u32,
    /// steady state was detected before the averaging window
    pub steady: bool,
    /// start of the averaging window, s
    pub window_start_s: f64,
    /// run summary of the whole run after the first revolution (forces, sliding …)
    pub summary: RunSummary,
}

/// Runs one point of the study on `bearing` (the O'Brien–Taylor example model).
pub fn obrien_taylor_point(
    bearing: &CylindricalRollerBearing,
    speed_rpm: f64,
    radial_load_n: f64,
    misalignment_rad: f64,
    settings: &StudySettings,
) -> Result<StudyPoint, DynError> {
    let mut b = bearing.clone();
    b.inner_ring.roughness_ra = 0.32e-6;
    b.outer_ring.roughness_ra = 0.32e-6;
    b.roller.roughness_ra = 0.16e-6;
    if let Some(n) = settings.slices {
        b.roller.slice_count = n;
    }
    let w = speed_rpm * std::f64::consts::TAU / 60.0;
    let t_k = oil_temperature_k(speed_rpm);
    let mut cond = OperatingConditions::new(w, radial_load_n);
    cond.temperatures = crate::conditions::ContactTemperatures::uniform(t_k);
    cond.misalignment_rad = misalignment_rad;
    cond.cage_drag_n_m_s = settings.cage_drag_n_m_s;
    let params = ContactParameters::for_bearing(&b);
    let mut dynamics = settings.dynamics;
    let wc = b.epicyclic_cage_speed(w, 0.0).abs().max(1e-9);
    let rev_s = std::f64::consts::TAU / wc;
    let t_max = settings.cage_revolutions * rev_s;
    let k = settings.average_revolutions.max(1) as usize;
    dynamics.discard_revolutions = 1;
    // the start is pure rolling at the epicyclic cage speed with the cage centred on its land
    // (or the ring) and the rollers at their static radii (`Simulation::default_initial_state`)
    let mut sim = Simulation::new(
        &b,
        cond,
        params,
        dynamics,
        RacewayTraction::same(nvi65_traction()?),
    )?;
    // run one epicyclic cage-revolution period at a time and record the cage angle φ at the
    // ends; period means are Δφ/Δt (exact, no quadrature); steady once two consecutive period
    // means differ by less than `steady_tolerance` of the epicyclic speed
    let phi_index = sim.layout().cage() + 3;
    let mut marks = vec![(sim.time(), sim.state()[phi_index])];
    let speed = |a: (f64, f64), b: (f64, f64)| (b.1 - a.1) / (b.0 - a.0);
    let mut steady_after: Option<usize> = None;
    loop {
        let t_next = sim.time() + rev_s;
        sim.run_until(t_next, &mut NullSink, &mut |_| {})?;
        marks.push((sim.time(), sim.state()[phi_index]));
        let n = marks.len();
        if steady_after.is_none() && n >= 4 {
            let d = speed(marks[n - 2], marks[n - 1]) - speed(marks[n - 3], marks[n - 2]);
            if d.abs() < settings.steady_tolerance * wc {
                steady_after = Some(n - 1);
            }
        }
        if steady_after.is_some_and(|m| n > m + k) || sim.time() >= t_max {
            break;
        }
    }
    let n = marks.len();
    let (first, steady) = match steady_after {
        Some(m) if n > m + k => (m, true),
        _ => (n.saturating_sub(k + 1).max(1).min(n - 2), false),
    };
    let (a, b) = (marks[first], marks[n - 1]);
    let mean_speed = speed(a, b).abs();
    let t0 = a.0;
    let window_len = n - 1 - first;
    Ok(StudyPoint {
        speed_rpm,
        radial_load_n,
        misalignment_rad,
        temperature_k: t_k,
        cage_slip: 1.0 - mean_speed / wc,
        revolutions_averaged: window_len as u32,
        steady,
        window_start_s: t0,
        summary: sim.summary(),
    })
}

/// Runs the whole study: every speed × load, then the misalignment series. `progress` gets
/// each finished point.
pub fn obrien_taylor(
    bearing: &CylindricalRollerBearing,
    settings: &StudySettings,
    progress: &mut dyn FnMut(&StudyPoint),
) -> Result<Vec<StudyPoint>, DynError> {
    let mut out = Vec::new();
    for &n in &settings.speeds_rpm {
        for &f in &settings.loads_n {
            let p = obrien_taylor_point(bearing, n, f, 0.0, settings)?;
            progress(&p);
            out.push(p);
        }
    }
    for &m in &settings.misalignments_rad {
        let p = obrien_taylor_point(
            bearing,
            settings.misalignment_speed_rpm,
            settings.misalignment_load_n,
            m,
            settings,
        )?;
        progress(&p);
        out.push(p);
    }
    Ok(out)
}
