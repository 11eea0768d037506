//! The wear a double-row tapered bearing has accumulated (seed 000 §3.2.2–3.2.4, SPEC §6.5):
//! depths on the wear lines of the roller and of both raceways, and on the large end and the
//! large rib. The unworn bearing carries [`TaperedWear::default`].

use rolldyn_numerics::table::interpolate_held;

/// Accumulated wear depths, m. The roller and raceway lines are circles at axial positions
/// along the roller axis from the roller's mid-length (+ toward the large end), the raceway
/// circles being those the seated roller's lines run on (seed 000 §3.2.3: the wear lines are
/// circles on the roller and on the raceway). Between lines the depth is linear, outside the
/// lines it is held (seed 000 §3.2.3: "linear interpolation between the lines").
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct TaperedWear {
    /// (position, depth) on the roller's rolling surface, positions increasing
    pub roller: Vec<(f64, f64)>,
    /// (position, depth) on the cone raceway (circumferential mean: the cone turns under a
    /// fixed load, so every circle passes the loaded zone)
    pub cone: Vec<(f64, f64)>,
    /// (position, depth) on the cup raceway
    pub cup: Vec<(f64, f64)>,
    /// depth of the large end face at the rib contact, along the roller axis
    pub large_end: f64,
    /// depth of the large rib face at the roller-end contact, along its normal
    pub large_rib: f64,
}

impl TaperedWear {
    /// Roller wear at axial position `x`, m.
    pub fn roller_at(&self, x: f64) -> f64 {
        interpolate_held(&self.roller, x)
    }

    /// Wear of the cone (`race = 0`) or the cup (`race = 1`) under the roller position `x`, m.
    pub fn raceway_at(&self, race: usize, x: f64) -> f64 {
        interpolate_held(if race == 0 { &self.cone } else { &self.cup }, x)
    }

    /// Growth of the play between a roller's large end and the large rib: both depths add
    /// along the contact normal (nearly the roller axis), m.
    pub fn end_rib_play(&self) -> f64 {
        self.large_end + self.large_rib
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unworn_is_zero_everywhere_and_lines_interpolate_linearly() {
        let w = TaperedWear::default();
        assert_eq!(w.roller_at(0.01), 0.0);
        assert_eq!(w.raceway_at(1, -0.02), 0.0);
        let w = TaperedWear {
            cone: vec![(-1e-2, 1e-6), (1e-2, 3e-6)],
            large_end: 1e-6,
            large_rib: 0.5e-6,
            ..TaperedWear::default()
        };
        assert!((w.raceway_at(0, 0.0) - 2e-6).abs() < 1e-18);
        assert_eq!(w.raceway_at(0, 5e-2), 3e-6);
        assert_eq!(w.raceway_at(1, 0.0), 0.0);
        assert!((w.end_rib_play() - 1.5e-6).abs() < 1e-18);
    }
}
