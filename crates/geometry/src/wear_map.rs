//! Raceway wear as a map over axial position × angle on the ring (SPEC §6.5 "geometry update";
//! seed 000 §3.1.1.6: under a load rotating with the ring the inner-raceway wear is not uniform
//! around the circumference).

use crate::error::GeometryError;
use std::f64::consts::TAU;

/// Wear depth of a ring raceway over axial position × angle in the ring's own frame (depth ≥ 0,
/// m, measured along the raceway normal, into the ring), bilinear: linear in x between the
/// axial lines (the end values held beyond them), periodic linear in the angle between bin
/// centres ψ_k = (k + ½)·2π/bins.
/// Centre ψ_k = (k + ½)·2π/bins of angular bin `k` of `bins`, rad.
pub fn angle_bin_centre_rad(k: usize, bins: usize) -> f64 {
    (k as f64 + 0.5) * TAU / bins as f64
}

/// The angular bin of `bins` that ring-frame angle `angle_rad` (any real angle) falls in.
pub fn angle_bin_of(angle_rad: f64, bins: usize) -> usize {
    ((angle_rad.rem_euclid(TAU) / TAU * bins as f64) as usize).min(bins - 1)
}

#[derive(Debug, Clone, PartialEq)]
pub struct RacewayWearMap {
    axial_m: Vec<f64>,
    angle_bins: usize,
    /// axial-major: `depth_m[i * angle_bins + k]` at axial line i and angle bin k
    depth_m: Vec<f64>,
}

impl RacewayWearMap {
    /// A map over the strictly increasing axial lines `axial_m` and `angle_bins` ≥ 1 angle bins,
    /// with finite depths ≥ 0, axial-major (`axial_m.len() × angle_bins` values).
    pub fn new(
        axial_m: Vec<f64>,
        angle_bins: usize,
        depth_m: Vec<f64>,
    ) -> Result<Self, GeometryError> {
        let bad = |reason: String| Err(GeometryError::new("raceway_wear", reason));
        if axial_m.is_empty() || angle_bins == 0 {
            return bad("needs at least one axial line and one angle bin".into());
        }
        if axial_m.iter().any(|x| !x.is_finite()) || axial_m.windows(2).any(|w| w[1] <= w[0]) {
            return bad("axial positions must be finite and strictly increasing".into());
        }
        if depth_m.len() != axial_m.len() * angle_bins {
            return bad(format!(
                "{} depths for {} axial lines × {angle_bins} angle bins",
                depth_m.len(),
                axial_m.len()
            ));
        }
        if let Some(d) = depth_m.iter().find(|d| !(d.is_finite() && **d >= 0.0)) {
            return bad(format!("depths must be finite and ≥ 0, got {d}"));
        }
        Ok(Self {
            axial_m,
            angle_bins,
            depth_m,
        })
    }

    /// The axial lines, m.
    pub fn axial_m(&self) -> &[f64] {
        &self.axial_m
    }

    /// The number of angle bins around the ring.
    pub fn angle_bins(&self) -> usize {
        self.angle_bins
    }

    /// The depths, axial-major, m.
    pub fn depth_m(&self) -> &[f64] {
        &self.depth_m
    }

    /// Centre of angle bin `k`, ψ_k = (k + ½)·2π/bins, rad.
    pub fn bin_centre_rad(&self, k: usize) -> f64 {
        angle_bin_centre_rad(k, self.angle_bins)
    }

    /// Depth at axial position `x` and ring-frame angle `angle_rad` (any real angle), m.
    pub fn depth(&self, x: f64, angle_rad: f64) -> f64 {
        self.at_angle(angle_rad).depth(x)
    }

    /// The map at one ring-frame angle, to be read at many axial positions (the angular
    /// interpolation done once).
    #[inline]
    pub fn at_angle(&self, angle_rad: f64) -> WearAtAngle<'_> {
        let bins = self.angle_bins;
        let u = angle_rad.rem_euclid(TAU) / TAU * bins as f64 - 0.5;
        let below = u.floor();
        let k0 = (below as isize).rem_euclid(bins as isize) as usize;
        WearAtAngle {
            map: self,
            bins: [k0, (k0 + 1) % bins],
            weight: u - below,
        }
    }

    /// Circumferential mean depth at axial position `x`, m (the axisymmetric reading).
    pub fn mean_depth(&self, x: f64) -> f64 {
        let bins = self.angle_bins;
        let line_mean =
            |i: usize| self.depth_m[i * bins..(i + 1) * bins].iter().sum::<f64>() / bins as f64;
        let ([i0, i1], w) = self.axial_cell(x);
        (1.0 - w) * line_mean(i0) + w * line_mean(i1)
    }

    /// The deepest point of the map, m.
    pub fn max_depth(&self) -> f64 {
        self.depth_m.iter().copied().fold(0.0, f64::max)
    }

    /// The axial lines around `x` and the weight of the second: linear between them, the end
    /// line alone beyond the ends.
    #[inline]
    fn axial_cell(&self, x: f64) -> ([usize; 2], f64) {
        let xs = &self.axial_m;
        let last = xs.len() - 1;
        if x <= xs[0] {
            return ([0, 0], 0.0);
        }
        if x >= xs[last] {
            return ([last, last], 0.0);
        }
        let i = xs.partition_point(|&xi| xi <= x) - 1;
        ([i, i + 1], (x - xs[i]) / (xs[i + 1] - xs[i]))
    }
}

/// A [`RacewayWearMap`] at one ring-frame angle: the two angle bins around it and the weight of
/// the second.
#[derive(Debug, Clone, Copy)]
pub struct WearAtAngle<'a> {
    map: &'a RacewayWearMap,
    bins: [usize; 2],
    weight: f64,
}

impl WearAtAngle<'_> {
    /// Depth at axial position `x`, m (bilinear, RacewayWearMap).
    #[inline]
    pub fn depth(&self, x: f64) -> f64 {
        let m = self.map;
        let ([i0, i1], wx) = m.axial_cell(x);
        let [k0, k1] = self.bins;
        let at = |i: usize, k: usize| m.depth_m[i * m.angle_bins + k];
        let wk = self.weight;
        (1.0 - wx) * ((1.0 - wk) * at(i0, k0) + wk * at(i0, k1))
            + wx * ((1.0 - wk) * at(i1, k0) + wk * at(i1, k1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two axial lines, four bins; depth = (1 + i) µm·(k + 1).
    fn map() -> RacewayWearMap {
        let depth = (0..2)
            .flat_map(|i| (0..4).map(move |k| 1e-6 * (1 + i) as f64 * (k + 1) as f64))
            .collect();
        RacewayWearMap::new(vec![-0.01, 0.01], 4, depth).unwrap()
    }

    #[test]
    fn bilinear_between_lines_and_bin_centres() {
        let m = map();
        let centre = |k: usize| m.bin_centre_rad(k);
        assert!((m.depth(-0.01, centre(2)) - 3e-6).abs() < 1e-18);
        assert!((m.depth(0.0, centre(2)) - 4.5e-6).abs() < 1e-18);
        // halfway between bins 0 and 1 on line 0
        assert!((m.depth(-0.01, 0.5 * (centre(0) + centre(1))) - 1.5e-6).abs() < 1e-18);
        // end values held beyond the lines
        assert_eq!(m.depth(-1.0, centre(1)), m.depth(-0.01, centre(1)));
        assert_eq!(m.depth(1.0, centre(3)), 8e-6);
    }

    #[test]
    fn periodic_in_the_angle() {
        let m = map();
        // angle 0 lies halfway between the last bin (k = 3) and the first (k = 0)
        assert!((m.depth(-0.01, 0.0) - 2.5e-6).abs() < 1e-18);
        assert!((m.depth(0.003, 1.0) - m.depth(0.003, 1.0 + 3.0 * TAU)).abs() < 1e-18);
        assert!((m.depth(0.003, -1.0) - m.depth(0.003, TAU - 1.0)).abs() < 1e-18);
    }

    #[test]
    fn mean_and_max() {
        let m = map();
        assert!((m.mean_depth(-0.01) - 2.5e-6).abs() < 1e-18);
        assert!((m.mean_depth(0.0) - 3.75e-6).abs() < 1e-18);
        assert_eq!(m.max_depth(), 8e-6);
    }

    #[test]
    fn rejects_bad_maps() {
        assert!(RacewayWearMap::new(vec![0.0, 0.0], 1, vec![0.0; 2]).is_err());
        assert!(RacewayWearMap::new(vec![0.0], 0, vec![]).is_err());
        assert!(RacewayWearMap::new(vec![0.0], 2, vec![0.0]).is_err());
        assert!(RacewayWearMap::new(vec![0.0], 1, vec![-1e-6]).is_err());
        assert!(RacewayWearMap::new(vec![0.0], 1, vec![f64::NAN]).is_err());
    }
}
