//! Limit force of the roller large end on the cone's large rib (seed 000 §3.2.2, SPEC §6.7).
//!
//! Film friction between the roller's spherical end and the rib face is possible only while
//! the contact patch stays inside the mutual projection of the two faces; the *limit force* is
//! the normal force at which the patch reaches the boundary of that projection. Here the patch
//! is the Boussinesq solution (seed 004, SPEC §2.5) on the true initial gap of end sphere and
//! rib face ([`EndRibPair`]); the patch has reached the boundary when a boundary cell of the
//! projection (an inside cell with an edge-neighbour outside) carries pressure. The force is
//! bracketed and bisected on a logarithmic scale ([`limit_force`]).
//!
//! The seed's eight rib faces ([`SEED_RIB_FACES`]) give the limit force against the reduced
//! curvature `Σρ = 1/R_end − κ_rib` (seed Fig. 3.88); beside it the force at which the
//! dynamics' Hertz-spot criterion switches to boundary friction
//! ([`rolldyn_dynamics::tapered::end_rib_film_limit_force`]).

mod pair;

pub use pair::{EndRibPair, OUTSIDE_GAP_M, RibSurface};

use rolldyn_contact::boussinesq::{
    BoussinesqError, BoussinesqOptions, BoussinesqSolver, ContactSolution, StopRule,
};
use rolldyn_contact::hertz::{EllipticalContact, EllipticalMethod, elliptical_contact};
use rolldyn_dynamics::tapered::end_rib_film_limit_force;
use rolldyn_geometry::{DoubleRowTaperedBearing, TaperedRibFace};

/// The model of the study, relative to the workspace root.
pub const DEFAULT_MODEL: &str = "examples/tapered-cassette.toml";

/// The rib faces of seed 000 §3.2.2, cases 1–8: conical; concave torus R 800…1300 mm; convex
/// torus R 1100 mm.
pub const SEED_RIB_FACES: [TaperedRibFace; 8] = [
    TaperedRibFace::Conical,
    TaperedRibFace::ConcaveTorus { radius: 0.8 },
    TaperedRibFace::ConcaveTorus { radius: 0.9 },
    TaperedRibFace::ConcaveTorus { radius: 1.0 },
    TaperedRibFace::ConcaveTorus { radius: 1.1 },
    TaperedRibFace::ConcaveTorus { radius: 1.2 },
    TaperedRibFace::ConcaveTorus { radius: 1.3 },
    TaperedRibFace::ConvexTorus { radius: 1.1 },
];

/// The pressure fields of seed 000 Figs. 3.84–3.87: conical rib at 2500, 16 000 and 5000 N,
/// concave R 800 mm at 5000 N.
pub const SEED_PRESSURE_MAPS: [(TaperedRibFace, f64); 4] = [
    (TaperedRibFace::Conical, 2500.0),
    (TaperedRibFace::Conical, 5000.0),
    (TaperedRibFace::Conical, 16000.0),
    (TaperedRibFace::ConcaveTorus { radius: 0.8 }, 5000.0),
];

/// Largest force tried while bracketing the limit, N (far beyond the 16 000 N overloads of the
/// seed).
const MAX_FORCE_N: f64 = 1e7;

/// Smallest force tried while bracketing the limit, N.
const MIN_FORCE_N: f64 = 1e-2;

/// Numerical settings of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Square cell size of the tangent-plane grid, m. 0.05 mm puts ≈ 35 cells between the
    /// contact point and the nearest projection edge of the cassette bearing (1.75 mm).
    pub cell_m: f64,
    /// Bisection stops when the bracket `[below, above]` has `above/below ≤ 1 + this`.
    pub force_tolerance: f64,
    /// Boussinesq solver options.
    pub solver: BoussinesqOptions,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            cell_m: 0.05e-3,
            force_tolerance: 0.005,
            solver: BoussinesqOptions {
                stop: StopRule::PressureChange(1e-8),
                ..BoussinesqOptions::default()
            },
        }
    }
}

/// A bracketed limit force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitForce {
    /// Largest force tried whose patch stays inside the projection, N.
    pub below_n: f64,
    /// Smallest force tried whose patch reaches the projection boundary, N.
    pub above_n: f64,
    /// Boussinesq solves spent.
    pub solves: usize,
}

impl LimitForce {
    /// Geometric mean of the bracket, N.
    pub fn force_n(&self) -> f64 {
        (self.below_n * self.above_n).sqrt()
    }
}

/// Boussinesq solves of one pair at a sequence of forces, each started from the previous
/// pressure field.
struct Probe<'a> {
    pair: &'a EndRibPair,
    solver: BoussinesqSolver,
    last: Option<Vec<f64>>,
    solves: usize,
}

impl<'a> Probe<'a> {
    fn new(pair: &'a EndRibPair, options: &BoussinesqOptions) -> Result<Self, BoussinesqError> {
        Ok(Self {
            pair,
            solver: BoussinesqSolver::new(pair.grid, pair.compliance, options.clone())?,
            last: None,
            solves: 0,
        })
    }

    fn solve(&mut self, force: f64) -> Result<ContactSolution, BoussinesqError> {
        let solution = match &self.last {
            Some(guess) => self
                .solver
                .solve_force_with_guess(&self.pair.gap, force, guess)?,
            None => self.solver.solve_force(&self.pair.gap, force)?,
        };
        self.solves += 1;
        self.last = Some(solution.pressure.clone());
        Ok(solution)
    }

    fn reaches_boundary(&mut self, force: f64) -> Result<bool, BoussinesqError> {
        let solution = self.solve(force)?;
        Ok(self.pair.reaches_boundary(&solution.pressure))
    }
}

/// The force at which the Boussinesq patch of `pair` first reaches the projection boundary:
/// bracketed from `guess_n` by doubling or halving, then bisected in `ln Q`.
pub fn limit_force(
    pair: &EndRibPair,
    guess_n: f64,
    settings: &Settings,
) -> Result<LimitForce, BoussinesqError> {
    let mut probe = Probe::new(pair, &settings.solver)?;
    let (mut below, mut above) = (guess_n, guess_n);
    if probe.reaches_boundary(guess_n)? {
        while probe.reaches_boundary(below)? {
            above = below;
            below *= 0.5;
            if below < MIN_FORCE_N {
                return Err(BoussinesqError::InvalidLoad(below));
            }
        }
    } else {
        while !probe.reaches_boundary(above)? {
            below = above;
            above *= 2.0;
            if above > MAX_FORCE_N {
                return Err(BoussinesqError::InvalidLoad(above));
            }
        }
    }
    while above / below > 1.0 + settings.force_tolerance {
        let mid = (below * above).sqrt();
        if probe.reaches_boundary(mid)? {
            above = mid;
        } else {
            below = mid;
        }
    }
    Ok(LimitForce {
        below_n: below,
        above_n: above,
        solves: probe.solves,
    })
}

/// One rib face of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitRow {
    /// Seed case number (1…8) or 0 for a face outside the seed's list.
    pub case: usize,
    pub face: TaperedRibFace,
    /// Axial-section reduced curvature `1/R_end − κ_rib`, 1/m.
    pub reduced_curvature: f64,
    /// Circumferential reduced curvature `1/R_end + κ_rib,circ` of the true face, 1/m.
    pub circumferential_reduced_curvature: f64,
    /// Distance of the initial contact from the nearest projection edge, m.
    pub margin_m: f64,
    /// Limit force with the true rib face ([`RibSurface::Revolution`]).
    pub limit: LimitForce,
    /// Limit force with the axial-section profile only ([`RibSurface::AxialProfile`]).
    pub limit_axial_profile: LimitForce,
    /// Force at which the dynamics' Hertz-spot criterion switches to boundary friction, N.
    pub hertz_limit_n: f64,
    /// Cells of the grid and of the projection.
    pub cells: usize,
    pub cells_inside: usize,
}

impl LimitRow {
    /// CSV header of [`Self::values`].
    pub const COLUMNS: [&'static str; 12] = [
        "case",
        "rib_radius_m",
        "reduced_curvature_1_m",
        "circumferential_reduced_curvature_1_m",
        "margin_m",
        "limit_force_n",
        "limit_below_n",
        "limit_above_n",
        "limit_force_axial_profile_n",
        "hertz_limit_force_n",
        "solves",
        "cells_inside",
    ];

    /// The row as numbers (rib radius signed: + concave, − convex, ∞ conical).
    pub fn values(&self) -> [f64; 12] {
        [
            self.case as f64,
            1.0 / self.face.curvature(),
            self.reduced_curvature,
            self.circumferential_reduced_curvature,
            self.margin_m,
            self.limit.force_n(),
            self.limit.below_n,
            self.limit.above_n,
            self.limit_axial_profile.force_n(),
            self.hertz_limit_n,
            (self.limit.solves + self.limit_axial_profile.solves) as f64,
            self.cells_inside as f64,
        ]
    }
}

/// The limit force of `bearing` with its large rib given the face `face`.
pub fn limit_row(
    bearing: &DoubleRowTaperedBearing,
    face: TaperedRibFace,
    settings: &Settings,
) -> Result<LimitRow, BoussinesqError> {
    let pair = EndRibPair::new(bearing, face, RibSurface::Revolution, settings.cell_m)?;
    let axial = EndRibPair::new(bearing, face, RibSurface::AxialProfile, settings.cell_m)?;
    let mut with_face = bearing.clone();
    with_face.large_rib.face = face;
    let hertz_limit_n = end_rib_film_limit_force(&with_face, pair.margin);
    let limit = limit_force(&pair, hertz_limit_n, settings)?;
    let limit_axial_profile = limit_force(&axial, hertz_limit_n, settings)?;
    Ok(LimitRow {
        case: SEED_RIB_FACES
            .iter()
            .position(|f| *f == face)
            .map_or(0, |k| k + 1),
        face,
        reduced_curvature: pair.reduced_curvature(),
        circumferential_reduced_curvature: pair.circumferential_reduced_curvature(),
        margin_m: pair.margin,
        limit,
        limit_axial_profile,
        hertz_limit_n,
        cells: pair.grid.len(),
        cells_inside: pair.inside.iter().filter(|&&i| i).count(),
    })
}

/// The limit forces of the seed's eight rib faces, in case order.
pub fn seed_limit_table(
    bearing: &DoubleRowTaperedBearing,
    settings: &Settings,
) -> Result<Vec<LimitRow>, BoussinesqError> {
    SEED_RIB_FACES
        .iter()
        .map(|&face| limit_row(bearing, face, settings))
        .collect()
}

/// The pressure field of one rib face at one force.
#[derive(Debug, Clone)]
pub struct PressureMap {
    pub pair: EndRibPair,
    pub solution: ContactSolution,
    /// Whether the patch reaches the projection boundary.
    pub reaches_boundary: bool,
    /// Share of the projection's cells that carry pressure.
    pub projection_share: f64,
}

/// Boussinesq solution of `bearing` with the true rib face `face` at the normal force
/// `force_n`.
pub fn pressure_map(
    bearing: &DoubleRowTaperedBearing,
    face: TaperedRibFace,
    force_n: f64,
    settings: &Settings,
) -> Result<PressureMap, BoussinesqError> {
    let pair = EndRibPair::new(bearing, face, RibSurface::Revolution, settings.cell_m)?;
    let solution = Probe::new(&pair, &settings.solver)?.solve(force_n)?;
    let inside = pair.inside.iter().filter(|&&i| i).count();
    Ok(PressureMap {
        reaches_boundary: pair.reaches_boundary(&solution.pressure),
        projection_share: solution.cells_in_contact as f64 / inside as f64,
        pair,
        solution,
    })
}

/// The Boussinesq patch of a pair far from the projection edges beside the Hertz ellipse of
/// the same curvatures (axial section and parallel circle).
#[derive(Debug, Clone)]
pub struct HertzCheck {
    pub map: PressureMap,
    pub hertz: EllipticalContact,
}

impl HertzCheck {
    /// Boussinesq semi-axes from the extent of the contact cells: along the parallel circle
    /// (grid `x`) and up the rib face (grid `y`), m.
    pub fn semi_axes_m(&self) -> (f64, f64) {
        let s = &self.map.solution;
        (0.5 * s.contact_length_m(), s.max_half_width_m())
    }
}

/// [`pressure_map`] and the Hertz solution of the true rib face `face` at `force_n`.
pub fn hertz_check(
    bearing: &DoubleRowTaperedBearing,
    face: TaperedRibFace,
    force_n: f64,
    settings: &Settings,
) -> Result<HertzCheck, String> {
    let map = pressure_map(bearing, face, force_n, settings).map_err(|e| e.to_string())?;
    let e_reduced =
        2.0 / (bearing.roller.material.compliance() + bearing.inner_material.compliance());
    let hertz = elliptical_contact(
        &map.pair.curvatures,
        e_reduced,
        force_n,
        EllipticalMethod::Exact,
    )
    .map_err(|e| e.to_string())?;
    Ok(HertzCheck { map, hertz })
}

/// Short name of a rib face: `conical`, `concave R 800 mm`, `convex R 1100 mm`.
pub fn face_label(face: TaperedRibFace) -> String {
    match face {
        TaperedRibFace::Conical => "conical".into(),
        TaperedRibFace::ConcaveTorus { radius } => format!("concave R {:.0} mm", radius * 1e3),
        TaperedRibFace::ConvexTorus { radius } => format!("convex R {:.0} mm", radius * 1e3),
    }
}

/// File-name form of [`face_label`]: `conical`, `concave-800mm`, `convex-1100mm`.
pub fn face_slug(face: TaperedRibFace) -> String {
    face_label(face).replace(" R ", "-").replace(' ', "")
}
