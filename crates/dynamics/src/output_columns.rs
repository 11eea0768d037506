//! The schemas of the streamed tables of a run: `bearing` (one row per output time), `rollers`
//! (one row per roller and output time) and `revolutions` (one row per cage revolution). Each
//! column is its name, its meaning with unit, and how its value is read, in one list — so a
//! writer cannot put a name in the header without its value.

use crate::output::{RevolutionSummary, Snapshot};

/// One column of an output table: `name` (SI unit as suffix), `description` (meaning and unit)
/// and `value`, the accessor that reads it from a record.
#[derive(Clone, Copy)]
pub struct Column<Accessor> {
    /// column name in the header
    pub name: &'static str,
    /// meaning and unit
    pub description: &'static str,
    /// reads the value from a record
    pub value: Accessor,
}

/// A column of the `bearing` table, read from a [`Snapshot`].
pub type BearingColumn = Column<fn(&Snapshot) -> f64>;
/// A column of the `rollers` table, read from a [`Snapshot`] and a roller index (0-based).
pub type RollerColumn = Column<fn(&Snapshot, usize) -> f64>;
/// A column of the `revolutions` table, read from a [`RevolutionSummary`].
pub type RevolutionColumn = Column<fn(&RevolutionSummary) -> f64>;

/// The header of a table.
pub fn column_names<A>(columns: &[Column<A>]) -> Vec<String> {
    columns.iter().map(|c| c.name.to_string()).collect()
}

/// Columns of the `bearing` table.
pub const BEARING_COLUMNS: [BearingColumn; 12] = [
    Column {
        name: "time_s",
        description: "time, s",
        value: |s| s.time_s,
    },
    Column {
        name: "inner_ring_speed_rad_s",
        description: "prescribed inner-ring speed, rad/s",
        value: |s| s.inner_ring_speed_rad_s,
    },
    Column {
        name: "inner_ring_x_m",
        description: "inner-ring centre x, m",
        value: |s| s.inner_ring_center_m[0],
    },
    Column {
        name: "inner_ring_y_m",
        description: "inner-ring centre y, m",
        value: |s| s.inner_ring_center_m[1],
    },
    Column {
        name: "cage_x_m",
        description: "cage centre x, m",
        value: |s| s.cage_center_m[0],
    },
    Column {
        name: "cage_y_m",
        description: "cage centre y, m",
        value: |s| s.cage_center_m[1],
    },
    Column {
        name: "cage_angle_rad",
        description: "cage rotation angle (unwrapped), rad",
        value: |s| s.cage_angle_rad,
    },
    Column {
        name: "cage_speed_rad_s",
        description: "cage spin speed, rad/s",
        value: |s| s.cage_speed_rad_s,
    },
    Column {
        name: "epicyclic_cage_speed_rad_s",
        description: "epicyclic cage speed, rad/s",
        value: |s| s.epicyclic_cage_speed_rad_s,
    },
    Column {
        name: "cage_slip",
        description: "cage slip 1 − ω_c/ω_c0 (SPEC §3.5)",
        value: |s| s.cage_slip,
    },
    Column {
        name: "cage_land_force_n",
        description: "cage ↔ land normal force, N",
        value: |s| s.cage_land_force_n,
    },
    Column {
        name: "cage_land_power_w",
        description: "cage ↔ land friction power, W",
        value: |s| s.cage_land_power_w,
    },
];

/// Columns of the `rollers` table (the raceway contacts as `inner_*` then `outer_*`, each in
/// the order of [`crate::output::ContactSnapshot`]).
pub const ROLLER_COLUMNS: [RollerColumn; 28] = [
    Column {
        name: "time_s",
        description: "time, s",
        value: |s, _| s.time_s,
    },
    Column {
        name: "roller",
        description: "roller number (1-based)",
        value: |_, j| (j + 1) as f64,
    },
    Column {
        name: "azimuth_rad",
        description: "azimuth θ of the roller centre (unwrapped), rad",
        value: |s, j| s.rollers.azimuth_rad[j],
    },
    Column {
        name: "radius_m",
        description: "radius r of the roller centre, m",
        value: |s, j| s.rollers.radius_m[j],
    },
    Column {
        name: "orbital_speed_rad_s",
        description: "orbital speed θ̇, rad/s",
        value: |s, j| s.rollers.orbital_speed_rad_s[j],
    },
    Column {
        name: "spin_speed_rad_s",
        description: "spin speed about the roller axis (inertial), rad/s",
        value: |s, j| s.rollers.spin_speed_rad_s[j],
    },
    Column {
        name: "yaw_rad",
        description: "yaw (skew) of the roller axis, rad",
        value: |s, j| s.rollers.yaw_rad[j],
    },
    Column {
        name: "pitch_rad",
        description: "pitch (tilt) of the roller axis, rad",
        value: |s, j| s.rollers.pitch_rad[j],
    },
    Column {
        name: "inner_force_n",
        description: "inner raceway normal force, N",
        value: |s, j| s.rollers.inner.force_n[j],
    },
    Column {
        name: "inner_sliding_speed_m_s",
        description: "inner raceway sliding speed, m/s",
        value: |s, j| s.rollers.inner.sliding_speed_m_s[j],
    },
    Column {
        name: "inner_rolling_speed_m_s",
        description: "inner raceway rolling speed, m/s",
        value: |s, j| s.rollers.inner.rolling_speed_m_s[j],
    },
    Column {
        name: "inner_slide_to_roll",
        description: "inner raceway slide-to-roll ratio",
        value: |s, j| s.rollers.inner.slide_to_roll[j],
    },
    Column {
        name: "inner_film_m",
        description: "inner raceway minimum film thickness, m",
        value: |s, j| s.rollers.inner.film_thickness_m[j],
    },
    Column {
        name: "inner_lambda",
        description: "inner raceway film parameter Λ",
        value: |s, j| s.rollers.inner.lambda[j],
    },
    Column {
        name: "inner_traction",
        description: "inner raceway traction coefficient μ",
        value: |s, j| s.rollers.inner.traction_coefficient[j],
    },
    Column {
        name: "inner_friction_power_w",
        description: "inner raceway friction power, W",
        value: |s, j| s.rollers.inner.friction_power_w[j],
    },
    Column {
        name: "outer_force_n",
        description: "outer raceway normal force, N",
        value: |s, j| s.rollers.outer.force_n[j],
    },
    Column {
        name: "outer_sliding_speed_m_s",
        description: "outer raceway sliding speed, m/s",
        value: |s, j| s.rollers.outer.sliding_speed_m_s[j],
    },
    Column {
        name: "outer_rolling_speed_m_s",
        description: "outer raceway rolling speed, m/s",
        value: |s, j| s.rollers.outer.rolling_speed_m_s[j],
    },
    Column {
        name: "outer_slide_to_roll",
        description: "outer raceway slide-to-roll ratio",
        value: |s, j| s.rollers.outer.slide_to_roll[j],
    },
    Column {
        name: "outer_film_m",
        description: "outer raceway minimum film thickness, m",
        value: |s, j| s.rollers.outer.film_thickness_m[j],
    },
    Column {
        name: "outer_lambda",
        description: "outer raceway film parameter Λ",
        value: |s, j| s.rollers.outer.lambda[j],
    },
    Column {
        name: "outer_traction",
        description: "outer raceway traction coefficient μ",
        value: |s, j| s.rollers.outer.traction_coefficient[j],
    },
    Column {
        name: "outer_friction_power_w",
        description: "outer raceway friction power, W",
        value: |s, j| s.rollers.outer.friction_power_w[j],
    },
    Column {
        name: "cage_bar_force_n",
        description: "roller ↔ cage bar normal force, N",
        value: |s, j| s.rollers.cage_bar_force_n[j],
    },
    Column {
        name: "rib_force_n",
        description: "roller ends ↔ ribs normal force, N",
        value: |s, j| s.rollers.rib_force_n[j],
    },
    Column {
        name: "rib_friction_power_w",
        description: "roller ends ↔ ribs friction power, W",
        value: |s, j| s.rollers.rib_power_w[j],
    },
    Column {
        name: "pocket_face_force_n",
        description: "roller ends ↔ cage pocket faces normal force, N",
        value: |s, j| s.rollers.pocket_face_force_n[j],
    },
];

/// Columns of the `revolutions` table (flags as 0 or 1).
pub const REVOLUTION_COLUMNS: [RevolutionColumn; 23] = [
    Column {
        name: "revolution",
        description: "revolution number (1 = first completed)",
        value: |v| v.revolution as f64,
    },
    Column {
        name: "start_s",
        description: "start time, s",
        value: |v| v.start_s,
    },
    Column {
        name: "end_s",
        description: "end time, s",
        value: |v| v.end_s,
    },
    Column {
        name: "cage_speed_mean_rad_s",
        description: "mean cage speed, rad/s",
        value: |v| v.cage_speed_mean_rad_s,
    },
    Column {
        name: "cage_slip_mean",
        description: "mean cage slip",
        value: |v| v.cage_slip_mean,
    },
    Column {
        name: "max_inner_contact_force_n",
        description: "largest roller ↔ inner-raceway force, N",
        value: |v| v.max_inner_contact_force_n,
    },
    Column {
        name: "max_outer_contact_force_n",
        description: "largest roller ↔ outer-raceway force, N",
        value: |v| v.max_outer_contact_force_n,
    },
    Column {
        name: "max_roller_cage_force_n",
        description: "largest roller ↔ cage-bar force, N",
        value: |v| v.max_roller_cage_force_n,
    },
    Column {
        name: "max_cage_land_force_n",
        description: "largest cage ↔ land force, N",
        value: |v| v.max_cage_land_force_n,
    },
    Column {
        name: "max_roller_end_rib_force_n",
        description: "largest roller-end ↔ rib force, N",
        value: |v| v.max_roller_end_rib_force_n,
    },
    Column {
        name: "max_roller_end_cage_force_n",
        description: "largest roller-end ↔ cage pocket-face force, N",
        value: |v| v.max_roller_end_cage_force_n,
    },
    Column {
        name: "max_inner_sliding_speed_m_s",
        description: "largest inner-raceway sliding speed, m/s",
        value: |v| v.max_inner_sliding_speed_m_s,
    },
    Column {
        name: "max_inner_sliding_rolling_direction_m_s",
        description: "largest rolling-direction component of the inner-raceway sliding, m/s",
        value: |v| v.max_inner_sliding_rolling_direction_m_s,
    },
    Column {
        name: "max_inner_sliding_axial_m_s",
        description: "largest axial component of the inner-raceway sliding, m/s",
        value: |v| v.max_inner_sliding_axial_m_s,
    },
    Column {
        name: "max_inner_sliding_rolling_direction_most_loaded_m_s",
        description: "largest rolling-direction sliding component of the most loaded roller, m/s",
        value: |v| v.max_inner_sliding_rolling_direction_most_loaded_m_s,
    },
    Column {
        name: "max_inner_sliding_axial_most_loaded_m_s",
        description: "largest axial sliding component of the most loaded roller, m/s",
        value: |v| v.max_inner_sliding_axial_most_loaded_m_s,
    },
    Column {
        name: "max_relative_slip",
        description: "largest inner-raceway relative slip v/u",
        value: |v| v.max_relative_slip,
    },
    Column {
        name: "scuffing_margin",
        description: "scuffing margin s_cr/s at the largest relative slip",
        value: |v| v.scuffing_margin,
    },
    Column {
        name: "whirl_ratio",
        description: "cage spin / cage-centre orbital speed",
        value: |v| v.whirl_ratio,
    },
    Column {
        name: "precession",
        description: "the cage precesses (0 or 1)",
        value: |v| f64::from(u8::from(v.precession)),
    },
    Column {
        name: "cage_orbit_radius_m",
        description: "RMS distance of the cage centre from the bearing axis, m",
        value: |v| v.cage_orbit_radius_m,
    },
    Column {
        name: "friction_power_mean_w",
        description: "mean total friction power of all contacts, W",
        value: |v| v.friction_power_mean_w,
    },
    Column {
        name: "steady",
        description: "the mean cage speed is steady (0 or 1)",
        value: |v| f64::from(u8::from(v.steady)),
    },
];

/// Values in the three tables of a run with `samples` output times, `revolutions` cage
/// revolutions and `rollers` rollers (for the estimate of their size).
pub fn table_values(samples: f64, revolutions: f64, rollers: usize) -> f64 {
    let per_sample = BEARING_COLUMNS.len() + rollers * ROLLER_COLUMNS.len();
    samples * per_sample as f64 + revolutions * REVOLUTION_COLUMNS.len() as f64
}

/// The `bearing` row of a snapshot, in the order of [`BEARING_COLUMNS`].
pub fn bearing_row(s: &Snapshot, row: &mut Vec<f64>) {
    row.clear();
    row.extend(BEARING_COLUMNS.iter().map(|c| (c.value)(s)));
}

/// The `rollers` row of roller `j` (0-based) of a snapshot, in the order of [`ROLLER_COLUMNS`].
pub fn roller_row(s: &Snapshot, j: usize, row: &mut Vec<f64>) {
    row.clear();
    row.extend(ROLLER_COLUMNS.iter().map(|c| (c.value)(s, j)));
}

/// The `revolutions` row of a revolution summary, in the order of [`REVOLUTION_COLUMNS`].
pub fn revolution_row(v: &RevolutionSummary, row: &mut Vec<f64>) {
    row.clear();
    row.extend(REVOLUTION_COLUMNS.iter().map(|c| (c.value)(v)));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::ContactSnapshot;
    use std::collections::HashSet;

    fn unique<A>(columns: &[Column<A>]) -> bool {
        let names = column_names(columns);
        names.iter().collect::<HashSet<_>>().len() == names.len()
    }

    #[test]
    fn column_names_are_unique() {
        assert!(unique(&BEARING_COLUMNS));
        assert!(unique(&ROLLER_COLUMNS));
        assert!(unique(&REVOLUTION_COLUMNS));
    }

    #[test]
    fn contact_columns_follow_the_contact_snapshot() {
        // a column per per-roller field; `slice_force_n` (one value per slice) has none
        let fields = std::mem::size_of::<ContactSnapshot>() / std::mem::size_of::<&[f64]>() - 1;
        let inner = ROLLER_COLUMNS
            .iter()
            .filter(|c| c.name.starts_with("inner_"))
            .count();
        let outer = ROLLER_COLUMNS
            .iter()
            .filter(|c| c.name.starts_with("outer_"))
            .count();
        assert_eq!((inner, outer), (fields, fields));
    }
}

/// The three tables of a run kept in memory, row after row (row-major, the columns of
/// [`BEARING_COLUMNS`], [`ROLLER_COLUMNS`] and [`REVOLUTION_COLUMNS`]): the `--out` tables for a
/// caller that wants them as arrays (the Python package).
#[derive(Debug, Clone, Default)]
pub struct MemoryTables {
    pub bearing: Vec<f64>,
    pub rollers: Vec<f64>,
    pub revolutions: Vec<f64>,
    row: Vec<f64>,
}

impl crate::output::OutputSink for MemoryTables {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        bearing_row(s, &mut self.row);
        self.bearing.extend_from_slice(&self.row);
        for j in 0..s.rollers.azimuth_rad.len() {
            roller_row(s, j, &mut self.row);
            self.rollers.extend_from_slice(&self.row);
        }
    }

    fn revolution(&mut self, v: &RevolutionSummary) {
        revolution_row(v, &mut self.row);
        self.revolutions.extend_from_slice(&self.row);
    }
}
