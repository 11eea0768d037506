//! The direct and the averaged wear methods as a sink of the dynamics' output steps (seed 000
//! §2.4.1, §2.4.2; docs/theory.md §8.5–8.6): every output step's contact forces, sliding speeds
//! and films become wear on the wear lines of every surface, summed over the recorded
//! revolutions; [`WearRecorder::rates`] divides by the recorded time.

use crate::WearError;
use crate::averaged::AveragedContact;
use crate::bar_load::bar_slice_forces;
use crate::bearing_data::WearData;
use crate::boussinesq_lines::boussinesq_patches;
use crate::coefficient::WearCoefficient;
use crate::rates::{ContactDiagnostics, SurfaceWear};
use crate::settings::{PressureModel, WearMethod, WearSettings};
use crate::wear_line::{LinePatch, point_patch, slice_patch};
use rolldyn_dynamics::output::{ContactSnapshot, OutputSink, Snapshot};
use rolldyn_geometry::angle_bin_of;
use std::f64::consts::{PI, TAU};

/// Samples of one contact kind for the averaged method: the equivalent-force sums, the
/// force-weighted shape of the load over the wear lines and the contact-time-weighted ln Λ.
#[derive(Debug, Clone)]
pub(crate) struct AveragedSums {
    pub(crate) contact: AveragedContact,
    line_share: Vec<f64>,
    ln_lambda_time: f64,
    lambda_time: f64,
    pub(crate) boundary_time: f64,
}

impl AveragedSums {
    pub(crate) fn new(lines: usize, exponent: f64) -> Self {
        Self {
            contact: AveragedContact::new(exponent),
            line_share: vec![0.0; lines],
            ln_lambda_time: 0.0,
            lambda_time: 0.0,
            boundary_time: 0.0,
        }
    }

    pub(crate) fn add(
        &mut self,
        force: f64,
        speed: f64,
        dt: f64,
        lambda: f64,
        boundary: bool,
        lines: &[f64],
    ) {
        let loaded = force > 0.0; // false for NaN too
        if !loaded {
            return;
        }
        self.contact.add(force, speed, dt);
        for (s, &f) in self.line_share.iter_mut().zip(lines) {
            *s += f * dt;
        }
        if boundary {
            self.boundary_time += dt;
        } else if lambda.is_finite() && lambda > 0.0 {
            self.ln_lambda_time += lambda.ln() * dt;
            self.lambda_time += dt;
        }
    }

    /// Mean Λ over the contact time (geometric mean; NaN without film samples).
    pub(crate) fn mean_lambda(&self) -> f64 {
        (self.ln_lambda_time / self.lambda_time).exp()
    }

    /// Whether boundary friction held for most of the contact time.
    pub(crate) fn mostly_boundary(&self) -> bool {
        self.boundary_time > 0.5 * self.contact.contact_time()
    }

    /// k at the mean Λ — the boundary k when boundary friction held for most of the contact
    /// time.
    pub(crate) fn coefficient(&self, coefficient: &WearCoefficient) -> f64 {
        coefficient.for_contact(self.mean_lambda(), self.mostly_boundary())
    }

    /// The circular Hertz patch of the equivalent force at reduced radius `radius` and
    /// k p̄ v̄ on its central line (seed 000 eq. 2.35 before the hardness).
    pub(crate) fn point_wear(
        &self,
        coefficient: &WearCoefficient,
        radius: f64,
        modulus: f64,
    ) -> (LinePatch, f64) {
        let patch = point_patch(self.contact.equivalent_force(), radius, modulus);
        let kpv = self.coefficient(coefficient)
            * patch.mean_pressure_pa
            * self.contact.mean_sliding_speed();
        (patch, kpv)
    }

    /// The equivalent force spread over the lines in the recorded load shape.
    pub(crate) fn equivalent_line_forces(&self) -> Vec<f64> {
        let total: f64 = self.line_share.iter().sum();
        let qe = self.contact.equivalent_force();
        self.line_share
            .iter()
            .map(|s| if total > 0.0 { qe * s / total } else { 0.0 })
            .collect()
    }
}

/// `(line, k p̄ v Δt, patch)` on every loaded wear line of a sliced line contact: eq. (45) of
/// docs/theory.md §8.6 before the hardness and the exposure; `k_v_dt` is k v Δt (k v̄ for a rate).
fn loaded_lines<'a>(
    forces: &'a [f64],
    lengths: &'a [f64],
    reduced_radius_m: f64,
    reduced_modulus_pa: f64,
    k_v_dt: f64,
) -> impl Iterator<Item = (usize, f64, LinePatch)> + 'a {
    forces
        .iter()
        .zip(lengths)
        .enumerate()
        .map(move |(s, (&f, &l))| (s, slice_patch(f, l, reduced_radius_m, reduced_modulus_pa)))
        .filter(|(_, patch)| patch.mean_pressure_pa > 0.0)
        .map(move |(s, patch)| (s, k_v_dt * patch.mean_pressure_pa, patch))
}

/// Wear of one output-step window, summed (depth in m) on every wear line.
pub struct WearRecorder<'a> {
    data: &'a WearData,
    settings: &'a WearSettings,
    recorded_s: f64,
    samples: u64,
    cage_angle_travel: f64,
    /// wall time spent in this sink, s (the wear side of the dynamics/wear split)
    wall_s: f64,
    /// direct-method depth sums, m
    depth: SurfaceWear,
    /// averaged-method sums: inner, outer, bar, rib; raceway bins separately
    averaged: [AveragedSums; 4],
    inner_bins: Vec<AveragedSums>,
    outer_bins: Vec<AveragedSums>,
    /// Σ dt × (reduced radius, contact radius on the roller, on the ring) of the rib contacts
    rib_geometry_time: [f64; 3],
    scratch: Vec<f64>,
}

impl<'a> WearRecorder<'a> {
    pub fn new(data: &'a WearData, settings: &'a WearSettings) -> Self {
        let lines = data.lines();
        let e = settings.equivalent_force_exponent;
        let bins = settings.angle_bins;
        Self {
            data,
            settings,
            recorded_s: 0.0,
            samples: 0,
            cage_angle_travel: 0.0,
            wall_s: 0.0,
            depth: SurfaceWear::zero(lines, bins, data.roller_count),
            averaged: std::array::from_fn(|_| AveragedSums::new(lines, e)),
            inner_bins: vec![AveragedSums::new(lines, e); bins],
            outer_bins: vec![AveragedSums::new(lines, e); bins],
            rib_geometry_time: [0.0; 3],
            scratch: vec![0.0; lines],
        }
    }

    /// Mean cage speed over the recorded time, rad/s.
    pub fn mean_cage_speed(&self) -> f64 {
        self.cage_angle_travel / self.recorded_s
    }

    /// Wall time spent computing wear in the sink, s.
    pub fn wall_s(&self) -> f64 {
        self.wall_s
    }

    /// Output steps recorded.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// The map bin of a roller at `azimuth` on a ring turned by `ring_angle`.
    fn bin(&self, azimuth: f64, ring_angle: f64) -> usize {
        angle_bin_of(azimuth - ring_angle, self.settings.angle_bins)
    }

    fn exposure(&self, patch: LinePatch, length: f64) -> f64 {
        self.settings.exposure_width.width(patch.half_width_m) / length
    }

    /// One raceway contact of roller `j` (direct method): raceway map bin and roller lines.
    fn raceway(&mut self, inner: bool, j: usize, c: &ContactSnapshot, bin: usize, dt: f64) {
        let d = self.data;
        let pair = if inner { &d.inner } else { &d.outer };
        let ns = d.lines();
        let forces = &c.slice_force_n[j * ns..(j + 1) * ns];
        let (v, lambda) = (c.sliding_speed_m_s[j], c.lambda[j]);
        let k = self.settings.coefficient.for_contact(lambda, false);
        let arc = pair.raceway_radius_m * TAU / self.settings.angle_bins as f64;
        let lines = loaded_lines(
            forces,
            &d.slice_lengths_m,
            pair.reduced_radius_m,
            pair.reduced_modulus_pa,
            k * v * dt,
        );
        for (s, pv, patch) in lines {
            let ring = pv / pair.ring_hardness_pa * self.exposure(patch, arc);
            let roller = pv / d.roller_hardness_pa * self.exposure(patch, PI * d.roller_diameter_m);
            let map = if inner {
                &mut self.depth.inner_map
            } else {
                &mut self.depth.outer_map
            };
            map[s * self.settings.angle_bins + bin] += ring;
            self.depth.roller[s] += roller / d.roller_count as f64;
        }
        let sums = if inner {
            &mut self.inner_bins[bin]
        } else {
            &mut self.outer_bins[bin]
        };
        sums.add(c.force_n[j], v, dt, lambda, false, forces);
        self.averaged[if inner { 0 } else { 1 }].add(c.force_n[j], v, dt, lambda, false, forces);
    }

    /// Roller `j` on its cage bar (direct method): bar lines of its pocket and roller lines.
    fn bar(&mut self, j: usize, force: f64, v: f64, dt: f64) {
        let d = self.data;
        let bar = &d.bar;
        bar_slice_forces(
            force,
            &d.slice_lengths_m,
            &d.slice_drops_m,
            bar.reduced_radius_m,
            bar.reduced_modulus_pa,
            &mut self.scratch,
        );
        let lambda = d.bar_lambda(force, v);
        let k = self.settings.coefficient.for_contact(lambda, false);
        let ns = d.lines();
        let lines = loaded_lines(
            &self.scratch,
            &d.slice_lengths_m,
            bar.reduced_radius_m,
            bar.reduced_modulus_pa,
            k * v * dt,
        );
        for (s, pv, patch) in lines {
            let on_bar = pv / bar.hardness_pa * self.exposure(patch, bar.exposure_length_m);
            let on_roller =
                pv / d.roller_hardness_pa * self.exposure(patch, PI * d.roller_diameter_m);
            self.depth.bar_by_pocket[j * ns + s] += on_bar;
            self.depth.roller_at_bar[s] += on_roller / d.roller_count as f64;
        }
        self.averaged[2].add(force, v, dt, lambda, false, &self.scratch);
    }

    /// Roller `j` on the ribs (direct method): one wear line on the end, one on the rib.
    fn rib(&mut self, j: usize, snapshot: &Snapshot, dt: f64) {
        let r = &snapshot.rollers;
        let force = r.rib_force_n[j];
        let loaded = force > 0.0; // false for NaN too
        if !loaded {
            return;
        }
        let d = self.data;
        let ends = &d.ends;
        let radius = r.rib_reduced_radius_m[j];
        let radius = if radius.is_finite() && radius > 0.0 {
            radius
        } else {
            ends.edge_radius_m
        };
        let patch = point_patch(force, radius, ends.reduced_modulus_pa);
        let v = r.rib_sliding_speed_m_s[j];
        // seed 000 §3.2.2 (theory §3.5): film friction only while the patch stays inside the
        // faces' overlap; a flat end on a flat rib (no reduced radius) meets it on an edge
        let flat_on_flat =
            !(r.rib_reduced_radius_m[j].is_finite() && r.rib_reduced_radius_m[j] > 0.0);
        let inside = r.rib_edge_distance_m[j] > patch.half_width_m;
        let boundary = flat_on_flat || !inside;
        let (on_roller_r, on_ring_r) = (r.rib_contact_radius_m[j], r.rib_contact_ring_radius_m[j]);
        let entrainment = 0.5
            * ((snapshot.inner_ring_speed_rad_s - snapshot.cage_speed_rad_s).abs() * on_ring_r
                + (r.spin_speed_rad_s[j] - snapshot.cage_speed_rad_s).abs() * on_roller_r);
        let lambda = if boundary {
            f64::NAN
        } else {
            d.rib_lambda(force, entrainment, radius)
        };
        let k = self.settings.coefficient.for_contact(lambda, boundary);
        let pv = k * patch.mean_pressure_pa * v * dt;
        if on_roller_r > 0.0 {
            // both ends share the wear (the roller touches either rib)
            self.depth.roller_end += 0.5 * pv / d.roller_hardness_pa
                * self.exposure(patch, TAU * on_roller_r)
                / d.roller_count as f64;
        }
        if on_ring_r > 0.0 {
            // every roller passes the rib circle; both ribs share it
            self.depth.rib +=
                0.5 * pv / ends.ring_hardness_pa * self.exposure(patch, TAU * on_ring_r);
        }
        self.averaged[3].add(force, v, dt, lambda, boundary, &[force]);
        for (sum, x) in self
            .rib_geometry_time
            .iter_mut()
            .zip([radius, on_roller_r, on_ring_r])
        {
            *sum += x * dt;
        }
    }

    /// Rates of the averaged method (seed 000 eq. 2.35): per contact kind the equivalent force
    /// spread over the lines in the recorded load shape, the mean sliding speed and k at the
    /// mean Λ, times the fraction of time in contact.
    fn averaged_rates(&self) -> Result<SurfaceWear, WearError> {
        let d = self.data;
        let t = self.recorded_s;
        let z = d.roller_count as f64;
        let mut w = SurfaceWear::zero(d.lines(), self.settings.angle_bins, d.roller_count);
        // (line, rate while in contact, patch) on every loaded line of one contact kind: the
        // slices' Hertz patches under the equivalent force in the recorded load shape, or the
        // given patches (Boussinesq at the raceway's equivalent force)
        let on_lines = |sums: &AveragedSums,
                        radius: f64,
                        modulus: f64,
                        given: Option<&[LinePatch]>|
         -> Vec<(usize, f64, LinePatch)> {
            let k_v =
                sums.coefficient(&self.settings.coefficient) * sums.contact.mean_sliding_speed();
            match given {
                Some(patches) => patches
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| p.mean_pressure_pa > 0.0)
                    .map(|(s, &p)| (s, k_v * p.mean_pressure_pa, p))
                    .collect(),
                None => {
                    let forces = sums.equivalent_line_forces();
                    loaded_lines(&forces, &d.slice_lengths_m, radius, modulus, k_v).collect()
                }
            }
        };
        for (inner, bins) in [(true, &self.inner_bins), (false, &self.outer_bins)] {
            let pair = if inner { &d.inner } else { &d.outer };
            let sums = &self.averaged[if inner { 0 } else { 1 }];
            let given = match (self.settings.pressure_model, d.boussinesq(inner)) {
                (PressureModel::Boussinesq, Some(contact)) => Some(boussinesq_patches(
                    contact,
                    sums.contact.equivalent_force(),
                    &d.slice_lengths_m,
                )?),
                _ => None,
            };
            let arc = pair.raceway_radius_m * TAU / self.settings.angle_bins as f64;
            let map = if inner {
                &mut w.inner_map
            } else {
                &mut w.outer_map
            };
            for (b, bin) in bins.iter().enumerate() {
                let time = bin.contact.contact_time() / t;
                let lines = on_lines(
                    bin,
                    pair.reduced_radius_m,
                    pair.reduced_modulus_pa,
                    given.as_deref(),
                );
                for (s, kpv, patch) in lines {
                    map[s * self.settings.angle_bins + b] +=
                        kpv / pair.ring_hardness_pa * self.exposure(patch, arc) * time;
                }
            }
            let time = sums.contact.contact_time() / (z * t);
            let lines = on_lines(
                sums,
                pair.reduced_radius_m,
                pair.reduced_modulus_pa,
                given.as_deref(),
            );
            for (s, kpv, patch) in lines {
                w.roller[s] += kpv / d.roller_hardness_pa
                    * self.exposure(patch, PI * d.roller_diameter_m)
                    * time;
            }
        }
        let sums = &self.averaged[2];
        let time = sums.contact.contact_time() / (z * t);
        for (s, kpv, patch) in
            on_lines(sums, d.bar.reduced_radius_m, d.bar.reduced_modulus_pa, None)
        {
            let on_bar =
                kpv / d.bar.hardness_pa * self.exposure(patch, d.bar.exposure_length_m) * time;
            for j in 0..d.roller_count {
                w.bar_by_pocket[j * d.lines() + s] = on_bar;
            }
            w.roller_at_bar[s] =
                kpv / d.roller_hardness_pa * self.exposure(patch, PI * d.roller_diameter_m) * time;
        }
        let sums = &self.averaged[3];
        let contact_time = sums.contact.contact_time();
        if contact_time > 0.0 {
            let [radius, on_roller, on_ring] = self.rib_geometry_time.map(|x| x / contact_time);
            let (patch, kpv) = sums.point_wear(
                &self.settings.coefficient,
                radius,
                d.ends.reduced_modulus_pa,
            );
            w.roller_end = 0.5 * kpv / d.roller_hardness_pa
                * self.exposure(patch, TAU * on_roller)
                * contact_time
                / (z * t);
            w.rib = 0.5 * kpv / d.ends.ring_hardness_pa
                * self.exposure(patch, TAU * on_ring)
                * contact_time
                / t;
        }
        Ok(w)
    }

    /// Wear rates of the recorded window, m/s of depth, by the chosen method.
    pub fn rates(&self) -> Result<SurfaceWear, WearError> {
        let t = self.recorded_s;
        let mut rates = match self.settings.method {
            WearMethod::Direct => self.depth.scaled(1.0 / t),
            WearMethod::Averaged => self.averaged_rates()?,
        };
        rates.diagnostics = self.diagnostics();
        rates.recorded_s = t;
        Ok(rates)
    }

    fn diagnostics(&self) -> [ContactDiagnostics; 4] {
        let t = self.recorded_s;
        std::array::from_fn(|i| {
            let a = &self.averaged[i];
            ContactDiagnostics {
                equivalent_force_n: a.contact.equivalent_force(),
                mean_sliding_speed_m_s: a.contact.mean_sliding_speed(),
                contact_fraction: a.contact.contact_time() / (t * self.data.roller_count as f64),
                mean_lambda: a.mean_lambda(),
                boundary_fraction: a.boundary_time
                    / a.contact.contact_time().max(f64::MIN_POSITIVE),
            }
        })
    }
}

impl OutputSink for WearRecorder<'_> {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        let wall = std::time::Instant::now();
        let dt = self.settings.output_step_s;
        self.samples += 1;
        self.recorded_s += dt;
        self.cage_angle_travel += s.cage_speed_rad_s * dt;
        let r = &s.rollers;
        for j in 0..self.data.roller_count {
            let az = r.azimuth_rad[j];
            if r.inner.force_n[j] > 0.0 {
                let bin = self.bin(az, s.inner_ring_angle_rad);
                self.raceway(true, j, &r.inner, bin, dt);
            }
            if r.outer.force_n[j] > 0.0 {
                let bin = self.bin(az, s.outer_ring_angle_rad);
                self.raceway(false, j, &r.outer, bin, dt);
            }
            if r.cage_bar_force_n[j] > 0.0 {
                self.bar(
                    j,
                    r.cage_bar_force_n[j],
                    r.cage_bar_sliding_speed_m_s[j],
                    dt,
                );
            }
            self.rib(j, s, dt);
        }
        self.wall_s += wall.elapsed().as_secs_f64();
    }
}
