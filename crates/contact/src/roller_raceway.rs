//! One roller pressed on one raceway, built from the bearing geometry: the gap of seed 004
//! (profile drop + transverse curvature + tilt) and the three ways rolldyn solves it —
//! the Boussinesq solver (SPEC §2.5), the slice model (SPEC §2.1) and Hertz (SPEC §2.3) —
//! reported with the same quantities so that they can be compared.

use crate::boussinesq::{
    BoussinesqError, BoussinesqOptions, BoussinesqSolver, Grid, combined_compliance,
};
use crate::hertz::{Conformity, LineApproachModel, LineContact, reduced_modulus, reduced_radius};
use crate::slices::{SliceError, SliceLaw, SlicedRoller, SolveOptions};
use rolldyn_geometry::{BearingModel, Profile, Ring};
use rolldyn_numerics::table::interpolate_held;
use std::time::Instant;

/// Why a roller–raceway contact could not be solved.
#[derive(Debug, Clone, PartialEq)]
pub enum RollerContactError {
    Geometry(String),
    Boussinesq(BoussinesqError),
    Slices(SliceError),
}

impl std::fmt::Display for RollerContactError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Geometry(m) => write!(f, "contact geometry: {m}"),
            Self::Boussinesq(e) => write!(f, "Boussinesq solver: {e}"),
            Self::Slices(e) => write!(f, "slice model: {e}"),
        }
    }
}

impl std::error::Error for RollerContactError {}

impl From<BoussinesqError> for RollerContactError {
    fn from(e: BoussinesqError) -> Self {
        Self::Boussinesq(e)
    }
}

impl From<SliceError> for RollerContactError {
    fn from(e: SliceError) -> Self {
        Self::Slices(e)
    }
}

/// Which solution method produced a [`ContactReport`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactMethod {
    Boussinesq,
    Slices,
    Hertz,
}

impl ContactMethod {
    pub fn name(self) -> &'static str {
        match self {
            Self::Boussinesq => "boussinesq",
            Self::Slices => "slices",
            Self::Hertz => "hertz",
        }
    }
}

/// Which slice law the slice method uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SliceLawChoice {
    /// Seed 000 eq. (2.3) on an inner raceway, (2.4) on an outer one; needs the whole bearing
    /// (pitch diameter, outside diameter, ring wall). Falls back to `Iso` for a single pair.
    #[default]
    Seed,
    /// ISO/TS 16281 lamina law, split equally between the two contacts of a roller
    /// (δ_total = 2 δ_contact for equal loads): `q = 35948·2^{10/9} L_we^{−1/9} L_s δ^{10/9}` (N, mm).
    Iso,
}

/// Pressure field on a grid (x fastest), for maps and plots.
#[derive(Debug, Clone, PartialEq)]
pub struct PressureMap {
    pub nx: usize,
    pub ny: usize,
    /// (x_min, x_max, y_min, y_max) [m].
    pub extent: (f64, f64, f64, f64),
    /// Pressure per cell [Pa].
    pub pressure: Vec<f64>,
}

/// The quantities of seed 004 Table 2 and Figs 5–6 for one solution, in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactReport {
    pub method: ContactMethod,
    pub load_n: f64,
    pub tilt_rad: f64,
    pub approach_m: f64,
    pub max_pressure_pa: f64,
    /// Pressure at the middle of the contact line (x = 0, y = 0).
    pub mid_pressure_pa: f64,
    /// Load divided by the contact area.
    pub mean_pressure_pa: f64,
    /// K = p_max / p̄ (seed 004 "коэффициент концентрации").
    pub concentration_factor: f64,
    /// Axial extent of the loaded zone.
    pub contact_length_m: f64,
    pub max_half_width_m: f64,
    /// Cells (Boussinesq) or slices (slice model) carrying load.
    pub cells_in_contact: usize,
    pub iterations: usize,
    pub converged: bool,
    pub solve_time_s: f64,
    /// Pressure along the central line: (x [m], p [Pa]).
    pub central_line: Vec<(f64, f64)>,
    /// Full pressure map (Boussinesq only).
    pub map: Option<PressureMap>,
}

/// A roller on a raceway with everything the three methods need (SI units).
#[derive(Debug, Clone)]
pub struct RollerRacewayContact {
    roller_profile: Profile,
    /// the raceway's ring (its drop: profile and mean wear)
    raceway: Ring,
    roller_length: f64,
    slice_count: usize,
    /// R' of seed 000 eq. (1.12).
    pub reduced_radius: f64,
    /// E' of seed 000 eq. (1.13).
    pub reduced_modulus: f64,
    /// (1−ν₁²)/(πE₁) + (1−ν₂²)/(πE₂) of seed 004 eq. (1).
    pub compliance: f64,
    /// Roller tilt relative to the raceway in the axial–radial plane [rad]; positive loads +x.
    pub tilt: f64,
    seed_law: Option<SliceLaw>,
}

impl RollerRacewayContact {
    /// The roller of `model` on its inner (`inner = true`) or outer raceway, tilted by `tilt`
    /// [rad] (the model's ring misalignment is *not* added: pass it in if wanted).
    pub fn from_model(
        model: &BearingModel,
        inner: bool,
        tilt: f64,
    ) -> Result<Self, RollerContactError> {
        let (Some(roller), Some((ring, is_inner))) = (model.roller(), model.raceway(inner)) else {
            return Err(RollerContactError::Geometry(
                "the roller–raceway contact study supports cylindrical bearings; for a double-row \
                 tapered bearing use `rolldyn check|loads|simulate`"
                    .into(),
            ));
        };
        let conformity = if is_inner {
            Conformity::ConvexConvex
        } else {
            Conformity::ConvexConcave
        };
        let r_prime = reduced_radius(
            0.5 * roller.diameter,
            0.5 * ring.raceway_diameter,
            conformity,
        )
        .map_err(|e| RollerContactError::Geometry(e.to_string()))?;
        let (m1, m2) = (&roller.material, &ring.material);
        let seed_law = match model {
            BearingModel::Cylindrical(b) => Some(if is_inner {
                SliceLaw::InnerRing {
                    pitch_diameter: b.pitch_diameter(),
                    youngs_modulus: m2.youngs_modulus,
                    poisson_ratio: m2.poisson_ratio,
                }
            } else {
                SliceLaw::OuterRing {
                    ring_wall_thickness: ring.wall_thickness(),
                    outside_diameter: ring.body_diameter,
                    pitch_diameter: b.pitch_diameter(),
                    youngs_modulus: m2.youngs_modulus,
                    poisson_ratio: m2.poisson_ratio,
                }
            }),
            BearingModel::RollerRaceway(_) | BearingModel::Tapered(_) => None,
        };
        if !tilt.is_finite() || tilt.abs() >= 0.1 {
            return Err(RollerContactError::Geometry(format!(
                "tilt {tilt} rad is not a small angle"
            )));
        }
        Ok(Self {
            roller_profile: roller.profile.clone(),
            raceway: ring.clone(),
            roller_length: roller.length,
            slice_count: roller.slice_count,
            reduced_radius: r_prime,
            reduced_modulus: reduced_modulus(
                m1.youngs_modulus,
                m1.poisson_ratio,
                m2.youngs_modulus,
                m2.poisson_ratio,
            ),
            compliance: combined_compliance(
                m1.youngs_modulus,
                m1.poisson_ratio,
                m2.youngs_modulus,
                m2.poisson_ratio,
            ),
            tilt,
            seed_law,
        })
    }

    /// Combined profile drop of roller and raceway at axial position `x` [m].
    pub fn profile_drop(&self, x: f64) -> f64 {
        self.roller_profile.drop(x) + self.raceway.raceway_drop(x)
    }

    /// Axial part of the gap: profile drop minus the tilt term.
    pub fn axial_gap(&self, x: f64) -> f64 {
        self.profile_drop(x) - x * self.tilt.tan()
    }

    /// Initial separation K(x, y) of seed 004 (SPEC §2.5): `z(x) + y²/(2R') − x tan φ`.
    pub fn gap(&self, x: f64, y: f64) -> f64 {
        self.axial_gap(x) + y * y / (2.0 * self.reduced_radius)
    }

    /// Hertz line contact over the effective (working) length.
    pub fn line_contact(&self) -> LineContact {
        LineContact {
            reduced_radius: self.reduced_radius,
            reduced_modulus: self.reduced_modulus,
            length: self.roller_profile.effective_length(),
        }
    }

    /// The cell size (along, across) [m] of an `nx × ny` Boussinesq grid: `nx` cells along the
    /// whole roller length, square cells unless `width` [m] (total transverse extent) is given.
    pub fn cell_size(&self, nx: usize, ny: usize, width: Option<f64>) -> (f64, f64) {
        let dx = self.roller_length / nx.max(1) as f64;
        (dx, width.map_or(dx, |w| w / ny.max(1) as f64))
    }

    /// The roller length [m], the extent of a Boussinesq grid along the roller.
    pub fn roller_length(&self) -> f64 {
        self.roller_length
    }

    /// Boussinesq solution for `load` [N] on `nx × ny` cells: `nx` along the whole roller
    /// length, square cells unless `width` [m] (total transverse extent) is given (SPEC F-12).
    pub fn boussinesq(
        &self,
        load: f64,
        nx: usize,
        ny: usize,
        width: Option<f64>,
        options: BoussinesqOptions,
    ) -> Result<ContactReport, RollerContactError> {
        let start = Instant::now();
        let (dx, dy) = self.cell_size(nx, ny, width);
        let grid = Grid::centered(nx, ny, dx, dy)?;
        let gap = grid.eval(|x, y| self.gap(x, y));
        let mut solver = BoussinesqSolver::new(grid, self.compliance, options)?;
        let s = solver.solve_force(&gap, load)?;
        let row = grid.central_row();
        let central_line = (0..nx)
            .map(|i| (grid.x(i), s.pressure_at(i, row)))
            .collect();
        Ok(ContactReport {
            method: ContactMethod::Boussinesq,
            load_n: load,
            tilt_rad: self.tilt,
            approach_m: s.approach_m,
            max_pressure_pa: s.max_pressure_pa,
            mid_pressure_pa: s.pressure_at_middle(),
            mean_pressure_pa: s.mean_pressure_pa(),
            concentration_factor: s.concentration_factor(),
            contact_length_m: s.contact_length_m(),
            max_half_width_m: s.max_half_width_m(),
            cells_in_contact: s.cells_in_contact,
            iterations: s.iterations,
            converged: s.converged,
            solve_time_s: start.elapsed().as_secs_f64(),
            central_line,
            map: Some(PressureMap {
                nx,
                ny,
                extent: (
                    grid.x_min,
                    grid.x_min + nx as f64 * dx,
                    grid.y_min,
                    grid.y_min + ny as f64 * dy,
                ),
                pressure: s.pressure.clone(),
            }),
        })
    }

    /// The slice law the slice method uses for `choice`.
    pub fn slice_law(&self, choice: SliceLawChoice) -> SliceLaw {
        match (choice, self.seed_law) {
            (SliceLawChoice::Seed, Some(law)) => law,
            _ => {
                let l_we_mm = self.roller_profile.effective_length() * 1e3;
                let exponent = 10.0 / 9.0;
                let k_mm = 35948.0 * 2f64.powf(exponent) * l_we_mm.powf(-1.0 / 9.0);
                SliceLaw::PowerPerLength {
                    k: k_mm * 1e3 * 1e3f64.powf(exponent),
                    exponent,
                }
            }
        }
    }

    /// Slice-model solution for `load` [N] at the fixed tilt: per-slice loads from the slice
    /// law, per-slice Hertz pressure `p = √(q E'/(2πR'))` with `q = Q_s/L_s` (SPEC §2.3).
    pub fn slices(
        &self,
        load: f64,
        choice: SliceLawChoice,
    ) -> Result<ContactReport, RollerContactError> {
        let start = Instant::now();
        let n = self.slice_count.max(1);
        let width = self.roller_length / n as f64;
        let positions: Vec<f64> = (0..n)
            .map(|k| -0.5 * self.roller_length + (k as f64 + 0.5) * width)
            .collect();
        let drops = positions.iter().map(|&x| self.profile_drop(x)).collect();
        let roller = SlicedRoller::new(
            self.slice_law(choice),
            positions.clone(),
            vec![width; n],
            drops,
        )?;
        let solution = roller.solve_approach(load, self.tilt, &SolveOptions::default())?;
        let mut forces = vec![0.0; n];
        roller.evaluate(solution.approach, self.tilt, &mut forces);
        let (mut area, mut half_width, mut loaded) = (0.0, 0.0f64, Vec::new());
        let central_line: Vec<(f64, f64)> = positions
            .iter()
            .zip(&forces)
            .map(|(&x, &q)| {
                let line = LineContact {
                    length: width,
                    ..self.line_contact()
                };
                let p = line.max_pressure(q);
                if q > 0.0 {
                    let b = line.half_width(q);
                    area += 2.0 * b * width;
                    half_width = half_width.max(b);
                    loaded.push(x);
                }
                (x, p)
            })
            .collect();
        let max_pressure = central_line.iter().map(|p| p.1).fold(0.0, f64::max);
        let mean = if area > 0.0 { load / area } else { 0.0 };
        let contact_length = match (loaded.first(), loaded.last()) {
            (Some(a), Some(b)) => b - a + width,
            _ => 0.0,
        };
        Ok(ContactReport {
            method: ContactMethod::Slices,
            load_n: load,
            tilt_rad: self.tilt,
            approach_m: solution.approach,
            max_pressure_pa: max_pressure,
            mid_pressure_pa: interpolate_held(&central_line, 0.0),
            mean_pressure_pa: mean,
            concentration_factor: if mean > 0.0 { max_pressure / mean } else { 0.0 },
            contact_length_m: contact_length,
            max_half_width_m: half_width,
            cells_in_contact: loaded.len(),
            iterations: solution.iterations,
            converged: true,
            solve_time_s: start.elapsed().as_secs_f64(),
            central_line,
            map: None,
        })
    }

    /// Hertz line contact over the effective length (profile and tilt ignored).
    pub fn hertz(&self, load: f64) -> ContactReport {
        let start = Instant::now();
        let line = self.line_contact();
        let p_max = line.max_pressure(load);
        let mean = line.mean_pressure(load);
        let half = 0.5 * line.length;
        ContactReport {
            method: ContactMethod::Hertz,
            load_n: load,
            tilt_rad: self.tilt,
            approach_m: line.approach(load, LineApproachModel::default()),
            max_pressure_pa: p_max,
            mid_pressure_pa: p_max,
            mean_pressure_pa: mean,
            concentration_factor: p_max / mean,
            contact_length_m: line.length,
            max_half_width_m: line.half_width(load),
            cells_in_contact: 0,
            iterations: 0,
            converged: true,
            solve_time_s: start.elapsed().as_secs_f64(),
            central_line: vec![(-half, p_max), (half, p_max)],
            map: None,
        }
    }
}
