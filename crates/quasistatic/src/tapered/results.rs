//! Results of the tapered load distribution.

use serde::Serialize;

/// Loads of one roller.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TaperedRollerLoad {
    /// Row 0 (z < 0) or 1 (z > 0).
    pub row: usize,
    /// Roller index in its row.
    pub index: usize,
    /// Azimuth from the radial load direction (+x), toward +y [rad].
    pub azimuth_rad: f64,
    /// Cone (inner raceway) normal load [N].
    pub cone_n: f64,
    /// Cup (outer raceway) normal load [N].
    pub cup_n: f64,
    /// Large-rib (flange) normal load [N].
    pub rib_n: f64,
    /// Centrifugal force [N].
    pub centrifugal_n: f64,
    /// Largest slice load on the cone [N]: against the mean slice load (load / slices) it
    /// shows edge loading.
    pub cone_slice_max_n: f64,
    /// Largest slice load on the cup [N].
    pub cup_slice_max_n: f64,
    /// Roller lift from the cone normal to its axis [m].
    pub lift_m: f64,
    /// Roller tilt relative to the cone [rad].
    pub tilt_rad: f64,
}

/// One row's summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TaperedRowLoads {
    /// Row 0 (z < 0) or 1 (z > 0).
    pub row: usize,
    /// Axial position of the row's roller mid-points [m].
    pub mid_z_m: f64,
    /// Radial displacement (x, y) of the cone at the row's plane [m] (translation plus tilt).
    pub radial_displacement_m: [f64; 2],
    /// Axial displacement of the inner-ring assembly [m].
    pub axial_displacement_m: f64,
    /// Tilt (θx, θy) of the inner-ring assembly [rad].
    pub tilt_rad: [f64; 2],
    /// Rollers whose cone contact carries load.
    pub loaded_rollers: usize,
    /// Half-angle of the load zone: the largest angle between a loaded roller and the row's
    /// radial displacement direction (π when every roller is loaded) [rad].
    pub load_zone_half_angle_rad: f64,
    /// Most loaded roller (by cup load).
    pub max_roller: usize,
    /// Its cup load [N].
    pub max_cup_n: f64,
    /// Its cone load [N].
    pub max_cone_n: f64,
    /// Its rib load [N].
    pub max_rib_n: f64,
    /// Force the row's cup carries from the rollers: radial (x, y) and axial [N].
    pub cup_force_n: [f64; 3],
}

/// Balance checks: the applied loads and what the two rings carry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TaperedSumChecks {
    /// Loads on the inner-ring assembly (F_x, F_y, F_z, M_x, M_y) [N, N·m]; with an imposed
    /// tilt the moments are the reaction that holds the tilt.
    pub applied: [f64; 5],
    /// Applied loads plus the forces of cone and rib contacts on the inner ring (the Newton
    /// residual) [N, N·m].
    pub inner_ring_residual: [f64; 5],
    /// Applied loads less what the cup carries less the rollers' centrifugal forces: the
    /// balance through the cup side, i.e. the roller equilibria [N, N·m].
    pub cup_side_residual: [f64; 5],
    /// Largest residual of both, relative to the force scale (moments over ℓ = half the row
    /// spacing).
    pub relative: f64,
}

/// The quasi-static load distribution of a double-row tapered bearing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TaperedLoads {
    /// Always true in a returned result: the residual test passed.
    pub converged: bool,
    /// Ring Newton iterations.
    pub iterations: usize,
    /// Inner-ring assembly displacement (δx, δy, δz) [m] and tilt (θx, θy) [rad].
    pub displacement: [f64; 5],
    /// Epicyclic cage speed [rad/s].
    pub cage_speed_rad_s: f64,
    /// Each roller's centrifugal force [N].
    pub centrifugal_force_n: f64,
    /// Per-row summaries.
    pub rows: [TaperedRowLoads; 2],
    /// Row 0's rollers, then row 1's.
    pub rollers: Vec<TaperedRollerLoad>,
    /// Balance checks.
    pub checks: TaperedSumChecks,
    /// Slice forces of each roller (in the order of `rollers`) on the cone and on the cup [N],
    /// slices in the order of the roller's slice stack (small end first): the lamina loads of
    /// ISO/TS 16281.
    #[serde(skip)]
    pub slice_loads_n: Vec<[Vec<f64>; 2]>,
}

/// Columns of the per-roller table ([`roller_row`]).
pub const ROLLER_COLUMNS: [&str; 11] = [
    "row",
    "roller",
    "azimuth_deg",
    "cone_n",
    "cup_n",
    "rib_n",
    "centrifugal_n",
    "cone_slice_max_n",
    "cup_slice_max_n",
    "lift_um",
    "tilt_arcmin",
];

/// One roller as a row of [`ROLLER_COLUMNS`] (engineering units: °, µm, ′).
pub fn roller_row(r: &TaperedRollerLoad) -> [f64; 11] {
    [
        r.row as f64,
        r.index as f64,
        r.azimuth_rad.to_degrees(),
        r.cone_n,
        r.cup_n,
        r.rib_n,
        r.centrifugal_n,
        r.cone_slice_max_n,
        r.cup_slice_max_n,
        r.lift_m * 1e6,
        r.tilt_rad.to_degrees() * 60.0,
    ]
}
