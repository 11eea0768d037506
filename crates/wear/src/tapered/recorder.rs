//! The direct and the averaged wear methods on the contact record of the tapered dynamics
//! (seed 000 §2.4.1–2.4.2, §3.2.2–3.2.3; docs/theory.md §8.10).
//!
//! Direct: every output step, every loaded slice of every roller on the cone and the cup gives
//! k(Λ) p̄ v / H on its wear line (p̄ the mean pressure of the slice's Hertz patch on the line);
//! every loaded large end gives k p̄ v / H at its rib. Averaged: per contact kind one equivalent
//! force (2.36), mean sliding speed (2.37) and k at the mean Λ, the equivalent force spread
//! over the lines in the recorded load shape. Both give two rates per line: the rate *while in
//! contact* (what seed 000 Tables 3.7 and Fig. 3.95 print) and the *surface* rate, the former
//! times the fraction of time a point of the surface spends under a patch (SPEC §6.5).

use crate::WearError;
use crate::law::seed_literal_hardness_pa;
use crate::rates::ContactDiagnostics;
use crate::recorder::AveragedSums;
use crate::settings::WearMethod;
use crate::tapered::settings::TaperedWearSettings;
use crate::wear_line::{LinePatch, point_patch, slice_patch};
use rolldyn_dynamics::tapered::{
    ContactRecorder, RollerContacts, SliceContacts, TaperedModel, TaperedSample,
};
use std::f64::consts::TAU;

/// Rows of the bearing: each cone, cup raceway and large rib is passed by one row's rollers.
const ROWS: f64 = 2.0;

/// What the wear calculation needs of the bearing, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedWearData {
    /// slice centres (the wear lines) from the roller's mid-length, m
    pub positions_m: Vec<f64>,
    pub lengths_m: Vec<f64>,
    /// roller radius at the slice centres, m
    pub roller_radii_m: Vec<f64>,
    pub rollers_per_row: usize,
    /// Meyer hardness of roller, cone and cup, Pa
    pub roller_hardness_pa: f64,
    pub ring_hardness_pa: [f64; 2],
    /// E' of the roller–ring contacts, Pa; reduced radius of the end–rib pair, m
    pub reduced_modulus_pa: f64,
    pub rib_reduced_radius_m: f64,
}

impl TaperedWearData {
    pub fn new(model: &TaperedModel, settings: &TaperedWearSettings) -> Result<Self, WearError> {
        let b = model.bearing();
        let hardness = |m: &rolldyn_geometry::Material, key: &str| {
            let meyer = m.meyer_hardness.ok_or_else(|| WearError::Key {
                key: key.into(),
                reason: "the material has no hardness, which wear needs".into(),
            })?;
            Ok::<f64, WearError>(if settings.seed_literal_hardness {
                seed_literal_hardness_pa(meyer)
            } else {
                meyer
            })
        };
        let stack = b.roller.slices();
        Ok(Self {
            roller_radii_m: stack.radius.clone(),
            positions_m: stack.position,
            lengths_m: stack.length,
            rollers_per_row: b.rollers_per_row,
            roller_hardness_pa: hardness(&b.roller.material, "roller.material")?,
            ring_hardness_pa: [
                hardness(&b.inner_material, "bearing.inner_ring_material")?,
                hardness(&b.outer_material, "bearing.outer_ring_material")?,
            ],
            reduced_modulus_pa: model.reduced_modulus(),
            rib_reduced_radius_m: model.rib_reduced_radius(),
        })
    }

    fn lines(&self) -> usize {
        self.positions_m.len()
    }

    fn rollers(&self) -> usize {
        2 * self.rollers_per_row
    }
}

/// Wear rates of one window by one method, m/s of depth.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct TaperedRates {
    /// surface rates on the lines: roller (from cone and cup, mean over the rollers), cone and
    /// cup (mean of the two rows' raceways)
    pub roller: Vec<f64>,
    pub cone: Vec<f64>,
    pub cup: Vec<f64>,
    /// surface rates of the large end (mean over the rollers) and of the large rib (mean of
    /// the two rows)
    pub roller_end: f64,
    pub rib: f64,
    /// rates while in contact, k p̄ v / H: cone lines, large end, rib (seed 000 Table 3.7)
    pub cone_in_contact: Vec<f64>,
    /// mean pressure on the cone lines while in contact, Pa
    pub cone_pressure_pa: Vec<f64>,
    pub end_in_contact: f64,
    pub rib_in_contact: f64,
}

impl TaperedRates {
    /// The line of the cone with the highest mean pressure while in contact (seed 000 §3.2.3:
    /// line 3 of its 9).
    pub fn max_pressure_line(&self) -> usize {
        let p = &self.cone_pressure_pa;
        (0..p.len())
            .max_by(|&a, &b| p[a].total_cmp(&p[b]))
            .unwrap_or(0)
    }
}

/// What the rates came from, per window.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct TaperedDiagnostics {
    /// cone, cup, large rib (contact fraction per roller)
    pub contacts: [ContactDiagnostics; 3],
    /// relative change of the equivalent force and of the mean sliding speed from the first
    /// to the second half of the window: cone, cup, rib
    pub half_window_change: [(f64, f64); 3],
    /// largest and mean |yaw| and |pitch| over the rollers and samples, rad
    pub yaw_max_rad: f64,
    pub yaw_mean_rad: f64,
    pub pitch_max_rad: f64,
    pub pitch_mean_rad: f64,
    /// time-mean large-end–rib force of a roller and largest rib force, N
    pub rib_force_mean_n: f64,
    pub rib_force_max_n: f64,
    /// mean cage speed of the two rows, rad/s
    pub cage_speed_rad_s: f64,
}

/// Direct-method sums of one ring's lines.
#[derive(Debug, Clone)]
struct RingSums {
    /// Σ k p̄ v dt / H_ring × exposure, summed over the rollers, m
    surface: Vec<f64>,
    /// Σ k p̄ v dt / H_ring while loaded, m; Σ dt loaded, s (per line, all rollers)
    in_contact: Vec<f64>,
    contact_time: Vec<f64>,
    /// Σ p̄ dt while loaded, Pa·s
    pressure_time: Vec<f64>,
    /// Σ dt × (reduced radius, ring radius) while loaded, for the averaged patches
    geometry_time: Vec<[f64; 2]>,
    averaged: AveragedSums,
    halves: [AveragedSums; 2],
}

impl RingSums {
    fn new(lines: usize, exponent: f64) -> Self {
        Self {
            surface: vec![0.0; lines],
            in_contact: vec![0.0; lines],
            contact_time: vec![0.0; lines],
            pressure_time: vec![0.0; lines],
            geometry_time: vec![[0.0; 2]; lines],
            averaged: AveragedSums::new(lines, exponent),
            halves: std::array::from_fn(|_| AveragedSums::new(lines, exponent)),
        }
    }
}

/// Direct-method sums of the large-end–rib contacts.
#[derive(Debug, Clone)]
struct RibSums {
    /// Σ over the rollers of k p̄ v dt / H × exposure: end, rib (both rows), m
    end_surface: f64,
    rib_surface: f64,
    /// Σ k p̄ v dt / H while loaded: end, rib, m; Σ dt loaded, s
    end_in_contact: f64,
    rib_in_contact: f64,
    contact_time: f64,
    /// Σ dt × (end radius, rib radius) while loaded
    geometry_time: [f64; 2],
    /// Σ force dt over all rollers, N·s; largest force, N
    force_time: f64,
    force_max: f64,
    averaged: AveragedSums,
    halves: [AveragedSums; 2],
}

/// The wear sink of a tapered dynamics window: samples before `start_s` are ignored.
pub struct TaperedWearRecorder<'a> {
    data: &'a TaperedWearData,
    settings: &'a TaperedWearSettings,
    start_s: f64,
    middle_s: f64,
    recorded_s: f64,
    samples: u64,
    rings: [RingSums; 2],
    rib: RibSums,
    roller_surface: Vec<f64>,
    /// Σ |yaw|, Σ |pitch| over rollers and samples; their largest values
    yaw_pitch_sum: [f64; 2],
    yaw_pitch_max: [f64; 2],
    cage_speed_sum: f64,
}

impl<'a> TaperedWearRecorder<'a> {
    /// A recorder of the window [`start_s`, `start_s + window_s`].
    pub fn new(data: &'a TaperedWearData, settings: &'a TaperedWearSettings, start_s: f64) -> Self {
        let (lines, e) = (data.lines(), settings.equivalent_force_exponent);
        Self {
            data,
            settings,
            start_s,
            middle_s: start_s + 0.5 * settings.window_s,
            recorded_s: 0.0,
            samples: 0,
            rings: [RingSums::new(lines, e), RingSums::new(lines, e)],
            rib: RibSums {
                end_surface: 0.0,
                rib_surface: 0.0,
                end_in_contact: 0.0,
                rib_in_contact: 0.0,
                contact_time: 0.0,
                geometry_time: [0.0; 2],
                force_time: 0.0,
                force_max: 0.0,
                averaged: AveragedSums::new(1, e),
                halves: std::array::from_fn(|_| AveragedSums::new(1, e)),
            },
            roller_surface: vec![0.0; lines],
            yaw_pitch_sum: [0.0; 2],
            yaw_pitch_max: [0.0; 2],
            cage_speed_sum: 0.0,
        }
    }

    /// Output steps recorded.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// Fraction of its circle a point of a surface spends under a patch of `patch` per pass,
    /// the circle of radius `radius_m` (SPEC §6.5, flag F-47).
    fn exposure(&self, patch: LinePatch, radius_m: f64) -> f64 {
        self.settings.exposure_width.width(patch.half_width_m) / (TAU * radius_m)
    }

    /// k of a raceway contact at the film parameter `lambda` of the dry film, the grease's
    /// reduced film applied (seed 000 §3.2.3).
    fn raceway_k(&self, lambda: f64) -> f64 {
        self.settings
            .coefficient
            .for_contact(lambda * self.settings.raceway_film_factor, false)
    }

    /// One roller's slices on ring `race` (0 cone, 1 cup) for `dt` (direct method).
    fn raceway(&mut self, race: usize, c: &SliceContacts, dt: f64, second_half: bool) {
        let d = self.data;
        let h_ring = d.ring_hardness_pa[race];
        let mut total = 0.0;
        let (mut sliding, mut ln_lambda) = (0.0, 0.0);
        for s in 0..d.lines() {
            let force = c.force_n[s];
            let loaded = force > 0.0; // false for NaN too
            if !loaded {
                continue;
            }
            let patch = slice_patch(
                force,
                d.lengths_m[s],
                c.reduced_radius_m[s],
                d.reduced_modulus_pa,
            );
            let kpv = self.raceway_k(c.lambda[s]) * patch.mean_pressure_pa * c.sliding_m_s[s];
            let ring = &mut self.rings[race];
            ring.in_contact[s] += kpv / h_ring * dt;
            ring.contact_time[s] += dt;
            ring.pressure_time[s] += patch.mean_pressure_pa * dt;
            ring.geometry_time[s][0] += c.reduced_radius_m[s] * dt;
            ring.geometry_time[s][1] += c.ring_radius_m[s] * dt;
            let on_ring = kpv / h_ring * self.exposure(patch, c.ring_radius_m[s]);
            let on_roller = kpv / d.roller_hardness_pa * self.exposure(patch, d.roller_radii_m[s]);
            self.rings[race].surface[s] += on_ring * dt;
            self.roller_surface[s] += on_roller * dt / d.rollers() as f64;
            total += force;
            sliding += force * c.sliding_m_s[s];
            ln_lambda += force * c.lambda[s].ln();
        }
        if total > 0.0 {
            // one contact of the averaged method: its force, load-weighted sliding and Λ
            let (v, lambda) = (sliding / total, (ln_lambda / total).exp());
            let ring = &mut self.rings[race];
            ring.averaged.add(total, v, dt, lambda, false, &c.force_n);
            ring.halves[usize::from(second_half)].add(total, v, dt, lambda, false, &c.force_n);
        }
    }

    /// One roller's large end on its rib for `dt` (direct method).
    fn rib(&mut self, r: &RollerContacts, dt: f64, second_half: bool) {
        let c = &r.large_rib;
        let loaded = c.force_n > 0.0; // false for NaN too
        if !loaded {
            return;
        }
        let d = self.data;
        let boundary = !c.elastohydrodynamic;
        let k = self.settings.coefficient.for_contact(c.lambda, boundary);
        let patch = point_patch(c.force_n, d.rib_reduced_radius_m, d.reduced_modulus_pa);
        let kpv = k * patch.mean_pressure_pa * c.sliding_m_s;
        let (h_end, h_rib) = (d.roller_hardness_pa, d.ring_hardness_pa[0]);
        let rib = &mut self.rib;
        rib.end_in_contact += kpv / h_end * dt;
        rib.rib_in_contact += kpv / h_rib * dt;
        rib.contact_time += dt;
        rib.geometry_time[0] += c.end_radius_m * dt;
        rib.geometry_time[1] += c.rib_radius_m * dt;
        rib.force_time += c.force_n * dt;
        rib.force_max = rib.force_max.max(c.force_n);
        let end_exposure = self.exposure(patch, c.end_radius_m);
        let rib_exposure = self.exposure(patch, c.rib_radius_m);
        let rib = &mut self.rib;
        rib.end_surface += kpv / h_end * end_exposure * dt / d.rollers() as f64;
        rib.rib_surface += kpv / h_rib * rib_exposure * dt;
        let lambda = if boundary { f64::NAN } else { c.lambda };
        let force = [c.force_n];
        rib.averaged
            .add(c.force_n, c.sliding_m_s, dt, lambda, boundary, &force);
        rib.halves[usize::from(second_half)].add(
            c.force_n,
            c.sliding_m_s,
            dt,
            lambda,
            boundary,
            &force,
        );
    }

    /// Rates of the direct method.
    fn direct(&self) -> TaperedRates {
        let t = self.recorded_s;
        let per_time = |v: &[f64], f: f64| v.iter().map(|x| f * x / t).collect::<Vec<_>>();
        let per_contact_time = |sums: &[f64], r: &RingSums| {
            sums.iter()
                .zip(&r.contact_time)
                .map(|(x, tc)| if *tc > 0.0 { x / tc } else { 0.0 })
                .collect()
        };
        let rib = &self.rib;
        let per_contact = |x: f64| {
            if rib.contact_time > 0.0 {
                x / rib.contact_time
            } else {
                0.0
            }
        };
        TaperedRates {
            roller: per_time(&self.roller_surface, 1.0),
            cone: per_time(&self.rings[0].surface, 1.0 / ROWS),
            cup: per_time(&self.rings[1].surface, 1.0 / ROWS),
            roller_end: rib.end_surface / t,
            rib: rib.rib_surface / (ROWS * t),
            cone_in_contact: per_contact_time(&self.rings[0].in_contact, &self.rings[0]),
            cone_pressure_pa: per_contact_time(&self.rings[0].pressure_time, &self.rings[0]),
            end_in_contact: per_contact(rib.end_in_contact),
            rib_in_contact: per_contact(rib.rib_in_contact),
        }
    }

    /// Rates of the averaged method (seed 000 eq. 2.35).
    fn averaged(&self) -> TaperedRates {
        let d = self.data;
        let t = self.recorded_s;
        let z = d.rollers() as f64;
        let lines = d.lines();
        let mut rates = TaperedRates {
            roller: vec![0.0; lines],
            cone: vec![0.0; lines],
            cup: vec![0.0; lines],
            cone_in_contact: vec![0.0; lines],
            cone_pressure_pa: vec![0.0; lines],
            ..TaperedRates::default()
        };
        for race in 0..2 {
            let ring = &self.rings[race];
            let sums = &ring.averaged;
            let contact_time = sums.contact.contact_time();
            if contact_time <= 0.0 {
                continue;
            }
            let k = self.raceway_k(sums.mean_lambda());
            let kv = k * sums.contact.mean_sliding_speed();
            let h_ring = d.ring_hardness_pa[race];
            for (s, force) in sums.equivalent_line_forces().into_iter().enumerate() {
                let time = ring.contact_time[s];
                if time <= 0.0 {
                    continue;
                }
                let [radius, ring_radius] = ring.geometry_time[s].map(|x| x / time);
                let patch = slice_patch(force, d.lengths_m[s], radius, d.reduced_modulus_pa);
                let kpv = kv * patch.mean_pressure_pa;
                let on_ring =
                    kpv / h_ring * self.exposure(patch, ring_radius) * contact_time / (ROWS * t);
                let on_roller = kpv / d.roller_hardness_pa
                    * self.exposure(patch, d.roller_radii_m[s])
                    * contact_time
                    / (z * t);
                rates.roller[s] += on_roller;
                if race == 0 {
                    rates.cone[s] = on_ring;
                    rates.cone_in_contact[s] = kpv / h_ring;
                    rates.cone_pressure_pa[s] = patch.mean_pressure_pa;
                } else {
                    rates.cup[s] = on_ring;
                }
            }
        }
        let rib = &self.rib;
        let sums = &rib.averaged;
        let contact_time = sums.contact.contact_time();
        if contact_time > 0.0 {
            let [end_radius, rib_radius] = rib.geometry_time.map(|x| x / contact_time);
            let (patch, kpv) = sums.point_wear(
                &self.settings.coefficient,
                d.rib_reduced_radius_m,
                d.reduced_modulus_pa,
            );
            let (h_end, h_rib) = (d.roller_hardness_pa, d.ring_hardness_pa[0]);
            rates.end_in_contact = kpv / h_end;
            rates.rib_in_contact = kpv / h_rib;
            rates.roller_end =
                kpv / h_end * self.exposure(patch, end_radius) * contact_time / (z * t);
            // per row: the rollers of one row pass its rib
            rates.rib = kpv / h_rib * self.exposure(patch, rib_radius) * contact_time / (ROWS * t);
        }
        rates
    }

    /// Rates of the method `method`.
    pub fn rates(&self, method: WearMethod) -> Result<TaperedRates, WearError> {
        if self.samples == 0 {
            return Err(WearError::Numerical(
                "the tapered dynamics gave no output step in the wear window".into(),
            ));
        }
        Ok(match method {
            WearMethod::Direct => self.direct(),
            WearMethod::Averaged => self.averaged(),
        })
    }

    /// What the rates came from.
    pub fn diagnostics(&self) -> TaperedDiagnostics {
        let t = self.recorded_s;
        let rollers = self.data.rollers() as f64;
        let sums = [
            &self.rings[0].averaged,
            &self.rings[1].averaged,
            &self.rib.averaged,
        ];
        let halves = [
            &self.rings[0].halves,
            &self.rings[1].halves,
            &self.rib.halves,
        ];
        let change = |h: &[AveragedSums; 2]| {
            let rel = |a: f64, b: f64| if a > 0.0 { b / a - 1.0 } else { f64::NAN };
            (
                rel(
                    h[0].contact.equivalent_force(),
                    h[1].contact.equivalent_force(),
                ),
                rel(
                    h[0].contact.mean_sliding_speed(),
                    h[1].contact.mean_sliding_speed(),
                ),
            )
        };
        let count = self.samples as f64 * rollers;
        TaperedDiagnostics {
            contacts: sums.map(|a| ContactDiagnostics {
                equivalent_force_n: a.contact.equivalent_force(),
                mean_sliding_speed_m_s: a.contact.mean_sliding_speed(),
                contact_fraction: a.contact.contact_time() / (t * rollers),
                mean_lambda: a.mean_lambda(),
                boundary_fraction: a.boundary_time
                    / a.contact.contact_time().max(f64::MIN_POSITIVE),
            }),
            half_window_change: halves.map(change),
            yaw_max_rad: self.yaw_pitch_max[0],
            yaw_mean_rad: self.yaw_pitch_sum[0] / count,
            pitch_max_rad: self.yaw_pitch_max[1],
            pitch_mean_rad: self.yaw_pitch_sum[1] / count,
            rib_force_mean_n: self.rib.force_time / (t * rollers),
            rib_force_max_n: self.rib.force_max,
            cage_speed_rad_s: self.cage_speed_sum / self.samples as f64,
        }
    }
}

impl ContactRecorder for TaperedWearRecorder<'_> {
    fn record(&mut self, sample: &TaperedSample, rollers: &[RollerContacts]) {
        if sample.time_s < self.start_s - 1e-12 {
            return;
        }
        let dt = self.settings.sample_interval_s;
        let second_half = sample.time_s >= self.middle_s;
        self.samples += 1;
        self.recorded_s += dt;
        self.cage_speed_sum += 0.5 * (sample.cage_speed[0] + sample.cage_speed[1]);
        for r in rollers {
            self.raceway(0, &r.cone, dt, second_half);
            self.raceway(1, &r.cup, dt, second_half);
            self.rib(r, dt, second_half);
            for (i, angle) in [r.yaw_rad, r.pitch_rad].into_iter().enumerate() {
                self.yaw_pitch_sum[i] += angle.abs();
                self.yaw_pitch_max[i] = self.yaw_pitch_max[i].max(angle.abs());
            }
        }
    }
}
