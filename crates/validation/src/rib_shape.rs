//! Convex vs flat inner-ring rib faces of bearing 2002834 (seed 000 §3.1.1.7; SPEC §1.2 "Ribs",
//! §1.7 "rib face", V-21, §6.7): the seed's claim that the convex rib of patent RU 2815566
//! (profile radius 430 mm or 37.5 mm, crest at the rib mid-height) moves the contact spot "far
//! away from the edge of the rib", which "reduces the sliding speed and makes a fluid-friction
//! regime possible" (Figs. 3.48–3.50 flat, 3.59–3.61 and 3.64 convex; no numbers besides
//! Λ = 2.5 and k = 4.55·10⁻¹¹ for the convex rib).
//!
//! The variants are the sweep file [`SWEEP_FILE`] (flat / R 430 mm / R 37.5 mm faces at the
//! Table 3.1 conditions of variants 12 and 36). Each runs the 6-DOF dynamics of
//! `rolldyn_dynamics` for [`Settings::revolutions`] cage revolutions; over the revolutions after
//! [`Settings::discard_revolutions`] every output sample of every roller with a rib contact is
//! collected: distance of the contact point from the rib edge (rim minus edge break), normal
//! force, sliding speed at the contact point, friction coefficient, power and regime.
//!
//! The simulation is the one `rolldyn simulate` builds (`rolldyn_setup::prepare`: quasi-static
//! start, hydrodynamic cage land, the model's cage drag) with the end-contact friction switch of
//! SPEC §6.7 set by the study ([`EndFrictionLaw::Ehl`] by default: film traction while the
//! contact spot stays inside the face overlap, boundary friction otherwise).

use rolldyn_dynamics::{EndContactRegime, OutputSink, Simulation, Snapshot};
use rolldyn_geometry::{BearingModel, RibFace};
use rolldyn_model::{EndFrictionLaw, Model};
use rolldyn_sweep::SweepFile;
use std::path::Path;

/// The sweep file of the study, relative to the workspace root.
pub const SWEEP_FILE: &str = "examples/2002834/rib-shape.toml";

/// A rib contact whose point lies within this distance of the rib edge counts as "on the edge"
/// (the flat rib's deepest point is exactly on it; 10 µm is a fifth of the seed's 0.05 mm FE
/// element), m.
pub const AT_EDGE_M: f64 = 10e-6;

/// Contacts below this force are grazing touches: they enter the force-weighted means with
/// their (negligible) weight but not the minimum edge distance or the maximum sliding speed, N.
pub const MIN_FORCE_N: f64 = 0.1;

/// Width of the bins of [`RibShapeRow::position_force_share`], m.
pub const POSITION_BIN_M: f64 = 0.25e-3;

/// Number of position bins (0…4 mm from the rib edge: the 2002834 rib face is 3.7 mm high).
pub const POSITION_BINS: usize = 16;

/// Run settings of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Cage revolutions simulated per variant (transient included).
    pub revolutions: f64,
    /// Cage revolutions at the start that are not collected (start transient).
    pub discard_revolutions: f64,
    /// Output step, s: the rib contacts are impacts of ≈ 0.1 ms; the seed's dynamic step is
    /// 0.002 ms (§3.1.1.7).
    pub output_step_s: f64,
    /// Friction law of the end–rib contacts.
    pub end_friction: EndFrictionLaw,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            revolutions: 4.0,
            discard_revolutions: 1.0,
            output_step_s: 1e-5,
            end_friction: EndFrictionLaw::Ehl,
        }
    }
}

/// Result of one variant. Means are force-weighted over all collected roller samples with a
/// rib contact (`Σ Q x / Σ Q`), which for the sliding speed is the wear-relevant mean of seed
/// 000 (2.37) weighted by force instead of by contact time.
#[derive(Debug, Clone, PartialEq)]
pub struct RibShapeRow {
    /// variant name of the sweep file
    pub variant: String,
    /// rib face of the inner ring (both ribs)
    pub face: RibFace,
    /// inner-ring misalignment, rad
    pub misalignment_rad: f64,
    /// share of the collected roller samples with a rib contact
    pub contact_share: f64,
    /// force-weighted mean distance of the contact point from the rib edge, m
    pub mean_edge_distance_m: f64,
    /// smallest distance from the rib edge (contacts ≥ [`MIN_FORCE_N`]), m
    pub min_edge_distance_m: f64,
    /// share of the contact force carried within [`AT_EDGE_M`] of the rib edge
    pub edge_force_share: f64,
    /// largest end–rib force of one roller, N
    pub max_force_n: f64,
    /// force-weighted mean sliding speed at the contact point, m/s
    pub mean_sliding_m_s: f64,
    /// largest sliding speed (contacts ≥ [`MIN_FORCE_N`]), m/s
    pub max_sliding_m_s: f64,
    /// force-weighted friction coefficient
    pub mean_mu: f64,
    /// time-mean friction power of all end–rib contacts of the bearing, W
    pub mean_power_w: f64,
    /// largest friction power of one roller's end–rib contacts, W
    pub max_power_w: f64,
    /// share of the contact force in the film (EHL) regime (SPEC §6.7)
    pub film_force_share: f64,
    /// time-mean cage slip over the collected revolutions
    pub cage_slip_mean: f64,
    /// force-weighted |yaw| (skew) of the rollers in rib contact, rad
    pub mean_abs_yaw_rad: f64,
    /// force-weighted |pitch| (tilt) of the rollers in rib contact, rad (the seed's "тангаж")
    pub mean_abs_pitch_rad: f64,
    /// share of the contact force whose point lies in bin `k` = [k, k+1)·[`POSITION_BIN_M`] from
    /// the rib edge (the last bin takes everything beyond): where the pressure spot sits
    pub position_force_share: [f64; POSITION_BINS],
    /// force-weighted sliding speed of the contacts in each position bin, m/s (NaN: empty)
    pub position_sliding_m_s: [f64; POSITION_BINS],
}

impl RibShapeRow {
    /// Names (SI units) of [`Self::values`], for tables.
    pub const COLUMNS: [&'static str; 19] = [
        "rib_curvature_1_m",
        "crest_offset_m",
        "misalignment_rad",
        "contact_share",
        "mean_edge_distance_m",
        "min_edge_distance_m",
        "edge_force_share",
        "max_force_n",
        "mean_sliding_m_s",
        "max_sliding_m_s",
        "mean_mu",
        "mean_power_w",
        "max_power_w",
        "film_force_share",
        "cage_slip_mean",
        "mean_abs_yaw_rad",
        "mean_abs_pitch_rad",
        "position_bin_m",
        "position_bins",
    ];

    /// The scalar results in the order of [`Self::COLUMNS`] (SI).
    pub fn values(&self) -> [f64; 19] {
        let crest = match self.face {
            RibFace::ConvexTorus { crest_offset, .. } => crest_offset,
            _ => 0.0,
        };
        [
            self.face_curvature(),
            crest,
            self.misalignment_rad,
            self.contact_share,
            self.mean_edge_distance_m,
            self.min_edge_distance_m,
            self.edge_force_share,
            self.max_force_n,
            self.mean_sliding_m_s,
            self.max_sliding_m_s,
            self.mean_mu,
            self.mean_power_w,
            self.max_power_w,
            self.film_force_share,
            self.cage_slip_mean,
            self.mean_abs_yaw_rad,
            self.mean_abs_pitch_rad,
            POSITION_BIN_M,
            POSITION_BINS as f64,
        ]
    }

    /// Profile curvature of the rib face, 1/m (0 flat; 1/R convex; −1/R concave).
    pub fn face_curvature(&self) -> f64 {
        match self.face {
            RibFace::ConvexTorus { radius, .. } => 1.0 / radius,
            RibFace::ConcaveTorus { radius } => -1.0 / radius,
            RibFace::Flat | RibFace::Cone { .. } => 0.0,
        }
    }

    /// Short description of the rib face ("flat", "convex R 430 mm").
    pub fn face_label(&self) -> String {
        match self.face {
            RibFace::Flat => "flat".into(),
            RibFace::Cone { angle } => format!("cone {:.2}°", angle.to_degrees()),
            RibFace::ConvexTorus {
                radius,
                crest_offset,
            } if crest_offset != 0.0 => format!(
                "convex R {} mm, crest {} mm toward the raceway",
                radius * 1e3,
                crest_offset * 1e3
            ),
            RibFace::ConvexTorus { radius, .. } => format!("convex R {} mm", radius * 1e3),
            RibFace::ConcaveTorus { radius } => format!("concave R {} mm", radius * 1e3),
        }
    }
}

/// Accumulates the rib-contact statistics of the samples at or after `t_start`.
#[derive(Debug, Clone)]
struct RibStats {
    t_start: f64,
    roller_samples: u64,
    contact_samples: u64,
    time_samples: u64,
    force: f64,
    force_edge: f64,
    force_sliding: f64,
    force_mu: f64,
    force_at_edge: f64,
    force_film: f64,
    power: f64,
    slip: f64,
    min_edge: f64,
    max_force: f64,
    max_sliding: f64,
    max_power: f64,
    force_yaw: f64,
    force_pitch: f64,
    bin_force: [f64; POSITION_BINS],
    bin_force_sliding: [f64; POSITION_BINS],
}

impl RibStats {
    fn new(t_start: f64) -> Self {
        Self {
            t_start,
            roller_samples: 0,
            contact_samples: 0,
            time_samples: 0,
            force: 0.0,
            force_edge: 0.0,
            force_sliding: 0.0,
            force_mu: 0.0,
            force_at_edge: 0.0,
            force_film: 0.0,
            power: 0.0,
            slip: 0.0,
            min_edge: f64::INFINITY,
            max_force: 0.0,
            max_sliding: 0.0,
            max_power: 0.0,
            force_yaw: 0.0,
            force_pitch: 0.0,
            bin_force: [0.0; POSITION_BINS],
            bin_force_sliding: [0.0; POSITION_BINS],
        }
    }

    fn row(&self, variant: String, face: RibFace, misalignment_rad: f64) -> RibShapeRow {
        let per_force = |x: f64| {
            if self.force > 0.0 {
                x / self.force
            } else {
                f64::NAN
            }
        };
        let per_time = |x: f64| x / self.time_samples.max(1) as f64;
        RibShapeRow {
            variant,
            face,
            misalignment_rad,
            contact_share: self.contact_samples as f64 / self.roller_samples.max(1) as f64,
            mean_edge_distance_m: per_force(self.force_edge),
            min_edge_distance_m: if self.min_edge.is_finite() {
                self.min_edge
            } else {
                f64::NAN
            },
            edge_force_share: per_force(self.force_at_edge),
            max_force_n: self.max_force,
            mean_sliding_m_s: per_force(self.force_sliding),
            max_sliding_m_s: self.max_sliding,
            mean_mu: per_force(self.force_mu),
            mean_power_w: per_time(self.power),
            max_power_w: self.max_power,
            film_force_share: per_force(self.force_film),
            cage_slip_mean: per_time(self.slip),
            mean_abs_yaw_rad: per_force(self.force_yaw),
            mean_abs_pitch_rad: per_force(self.force_pitch),
            position_force_share: self.bin_force.map(per_force),
            position_sliding_m_s: std::array::from_fn(|k| {
                if self.bin_force[k] > 0.0 {
                    self.bin_force_sliding[k] / self.bin_force[k]
                } else {
                    f64::NAN
                }
            }),
        }
    }
}

impl OutputSink for RibStats {
    fn sample(&mut self, t: f64, s: &Snapshot) {
        if t < self.t_start {
            return;
        }
        self.time_samples += 1;
        self.slip += s.cage_slip;
        let r = &s.rollers;
        for j in 0..r.rib_force_n.len() {
            self.roller_samples += 1;
            let q = r.rib_force_n[j];
            if q.is_nan() || q <= 0.0 {
                continue;
            }
            let (edge, vs, pw) = (
                r.rib_edge_distance_m[j],
                r.rib_sliding_speed_m_s[j],
                r.rib_power_w[j],
            );
            self.contact_samples += 1;
            self.force += q;
            self.force_edge += q * edge;
            self.force_sliding += q * vs;
            self.force_mu += q * r.rib_friction_coefficient[j];
            self.power += pw;
            self.force_yaw += q * r.yaw_rad[j].abs();
            self.force_pitch += q * r.pitch_rad[j].abs();
            let bin = ((edge / POSITION_BIN_M) as usize).min(POSITION_BINS - 1);
            self.bin_force[bin] += q;
            self.bin_force_sliding[bin] += q * vs;
            if edge < AT_EDGE_M {
                self.force_at_edge += q;
            }
            if r.rib_regime[j] == EndContactRegime::Elastohydrodynamic {
                self.force_film += q;
            }
            self.max_force = self.max_force.max(q);
            self.max_power = self.max_power.max(pw);
            if q >= MIN_FORCE_N {
                self.min_edge = self.min_edge.min(edge);
                self.max_sliding = self.max_sliding.max(vs);
            }
        }
    }
}

/// The 6-DOF simulation of `model` at its `[operating]` point with the study's end friction,
/// and its epicyclic cage revolution period, s. Errors name the missing model data.
pub fn simulation(model: &Model, settings: &Settings) -> Result<(Simulation, f64), String> {
    let mut model = model.clone();
    model.dynamics.roller_end_rib.friction_law = Some(settings.end_friction);
    rolldyn_setup::prepare(
        &model,
        &rolldyn_setup::Overrides::default(),
        settings.output_step_s,
        None,
    )
    .map_err(|e| e.to_string())
    .and_then(|(sim, period)| Ok((sim, period.ok_or("the rings start at rest")?)))
}

/// Runs one model for the study and collects its rib-contact statistics.
pub fn run_model(variant: &str, model: &Model, settings: &Settings) -> Result<RibShapeRow, String> {
    if !(settings.revolutions > settings.discard_revolutions && settings.discard_revolutions >= 0.0)
    {
        return Err(format!(
            "need revolutions ({}) > discarded revolutions ({}) ≥ 0",
            settings.revolutions, settings.discard_revolutions
        ));
    }
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Err(format!("{variant}: not a cylindrical bearing"));
    };
    let face = bearing
        .inner_ring
        .ribs
        .first()
        .map(|r| r.face)
        .ok_or_else(|| format!("{variant}: the inner ring has no ribs"))?;
    let (mut sim, period) = simulation(model, settings).map_err(|e| format!("{variant}: {e}"))?;
    let mut stats = RibStats::new(settings.discard_revolutions * period);
    sim.run_until(settings.revolutions * period, &mut stats, &mut |_| {})
        .map_err(|e| format!("{variant}: {e}"))?;
    Ok(stats.row(
        variant.to_string(),
        face,
        bearing.misalignment.inner_ring_tilt,
    ))
}

/// Runs the variants of the sweep file `sweep` whose names pass `keep`, in file order;
/// `progress` sees each row as it finishes.
pub fn run(
    sweep: &Path,
    settings: &Settings,
    keep: &dyn Fn(&str) -> bool,
    progress: &mut dyn FnMut(&RibShapeRow),
) -> Result<Vec<RibShapeRow>, String> {
    let file = SweepFile::load(sweep).map_err(|e| e.to_string())?;
    let mut rows = Vec::new();
    for variant in file.variants.iter().filter(|v| keep(&v.name)) {
        let model = file.model_of(variant).map_err(|e| e.to_string())?;
        let row = run_model(&variant.name, &model, settings)?;
        progress(&row);
        rows.push(row);
    }
    Ok(rows)
}
