//! The run summary as named columns: each key of `rolldyn simulate --json` and of a sweep's
//! summary table together with its value, so that the two cannot drift apart.

use crate::output::RunSummary;

impl RunSummary {
    /// Every figure of the summary with its column name (SI; `precession` as 0 or 1, the step
    /// counts as numbers).
    pub fn columns(&self) -> [(&'static str, f64); 20] {
        [
            ("cage_slip_mean", self.cage_slip_mean),
            ("cage_speed_mean_rad_s", self.cage_speed_mean_rad_s),
            (
                "epicyclic_cage_speed_rad_s",
                self.epicyclic_cage_speed_rad_s,
            ),
            ("max_inner_contact_force_n", self.max_inner_contact_force_n),
            ("max_outer_contact_force_n", self.max_outer_contact_force_n),
            ("max_roller_cage_force_n", self.max_roller_cage_force_n),
            ("max_cage_land_force_n", self.max_cage_land_force_n),
            (
                "max_roller_end_rib_force_n",
                self.max_roller_end_rib_force_n,
            ),
            (
                "max_roller_end_cage_force_n",
                self.max_roller_end_cage_force_n,
            ),
            (
                "max_inner_sliding_speed_m_s",
                self.max_inner_sliding_speed_m_s,
            ),
            ("max_relative_slip", self.max_relative_slip),
            ("min_scuffing_margin", self.min_scuffing_margin),
            ("whirl_ratio", self.whirl_ratio),
            ("precession", f64::from(u8::from(self.precession))),
            ("cage_orbit_radius_m", self.cage_orbit_radius_m),
            ("simulated_time_s", self.simulated_time_s),
            ("wall_time_s", self.wall_time_s),
            ("steps", self.steps as f64),
            ("rejected_steps", self.rejected_steps as f64),
            ("rhs_evaluations", self.rhs_evaluations as f64),
        ]
    }
}
