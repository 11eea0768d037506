//! The run summary as named columns: each key of `rolldyn simulate --json` and of a sweep's
//! summary table together with its value, so that the two cannot drift apart.

use crate::output::RunSummary;

/// A figure of the run summary with its kind: a real number (SI), a count or a flag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SummaryValue {
    /// a real number, SI units (may be NaN or ∞, see the field docs of [`RunSummary`])
    Real(f64),
    /// a count (steps, evaluations)
    Count(u64),
    /// a yes/no figure
    Flag(bool),
}

impl SummaryValue {
    /// The value as a number (a flag as 0 or 1).
    pub fn as_f64(self) -> f64 {
        match self {
            Self::Real(v) => v,
            Self::Count(n) => n as f64,
            Self::Flag(b) => f64::from(u8::from(b)),
        }
    }
}

impl RunSummary {
    /// Every figure of the summary with its column name and kind.
    pub fn fields(&self) -> [(&'static str, SummaryValue); 24] {
        use SummaryValue::{Count, Flag, Real};
        [
            ("cage_slip_mean", Real(self.cage_slip_mean)),
            ("cage_speed_mean_rad_s", Real(self.cage_speed_mean_rad_s)),
            (
                "epicyclic_cage_speed_rad_s",
                Real(self.epicyclic_cage_speed_rad_s),
            ),
            (
                "max_inner_contact_force_n",
                Real(self.max_inner_contact_force_n),
            ),
            (
                "max_outer_contact_force_n",
                Real(self.max_outer_contact_force_n),
            ),
            (
                "max_roller_cage_force_n",
                Real(self.max_roller_cage_force_n),
            ),
            ("max_cage_land_force_n", Real(self.max_cage_land_force_n)),
            (
                "max_roller_end_rib_force_n",
                Real(self.max_roller_end_rib_force_n),
            ),
            (
                "max_roller_end_cage_force_n",
                Real(self.max_roller_end_cage_force_n),
            ),
            (
                "max_inner_sliding_speed_m_s",
                Real(self.max_inner_sliding_speed_m_s),
            ),
            (
                "max_inner_sliding_rolling_direction_m_s",
                Real(self.max_inner_sliding_rolling_direction_m_s),
            ),
            (
                "max_inner_sliding_axial_m_s",
                Real(self.max_inner_sliding_axial_m_s),
            ),
            (
                "max_inner_sliding_rolling_direction_most_loaded_m_s",
                Real(self.max_inner_sliding_rolling_direction_most_loaded_m_s),
            ),
            (
                "max_inner_sliding_axial_most_loaded_m_s",
                Real(self.max_inner_sliding_axial_most_loaded_m_s),
            ),
            ("max_relative_slip", Real(self.max_relative_slip)),
            ("min_scuffing_margin", Real(self.min_scuffing_margin)),
            ("whirl_ratio", Real(self.whirl_ratio)),
            ("precession", Flag(self.precession)),
            ("cage_orbit_radius_m", Real(self.cage_orbit_radius_m)),
            ("simulated_time_s", Real(self.simulated_time_s)),
            ("wall_time_s", Real(self.wall_time_s)),
            ("steps", Count(self.steps)),
            ("rejected_steps", Count(self.rejected_steps)),
            ("rhs_evaluations", Count(self.rhs_evaluations)),
        ]
    }

    /// Every figure of the summary as a number with its column name (SI; `precession` as 0 or
    /// 1, the step counts as numbers).
    pub fn columns(&self) -> [(&'static str, f64); 24] {
        self.fields().map(|(name, value)| (name, value.as_f64()))
    }
}
