//! ISO/TS 16281:2008 — reference rating life of a roller bearing from the loads of its
//! laminae (slices): each roller is cut into n_s laminae of length L_we/n_s; every lamina k
//! has a dynamic load rating q_c,k on each ring and, from the loads q_kj of the Z rollers, an
//! equivalent load q_e,k; the ring lives combine the laminae, the bearing life the rings, all
//! with the Weibull slope e = 9/8 of the Lundberg–Palmgren line-contact theory (ISO/TR 1281-1)
//! that ISO 281's C_r (Table 7) derives from.

use crate::geometry::RollerBearingGeometry;
use crate::iso281::RATING_FACTOR_ROLLER;

/// The constant of the roller–raceway contact rating, 552 (N, mm), of ISO/TR 1281-1 and
/// ISO/TS 16281 (ISO 281's 207.9 for the whole bearing is 552 times the load-zone factor).
pub const CONTACT_RATING_CONSTANT: f64 = 552.0;

/// Reduction factor λν = 0.83 for line contact: the value that makes ISO/TR 1281-1's f_c
/// equation reproduce ISO 281 Table 7 (see `iso281` tests).
pub const LINE_CONTACT_REDUCTION: f64 = 0.83;

/// Life exponent of one lamina (line contact, Lundberg–Palmgren): L = (q_c/q_e)^4.
pub const LAMINA_LIFE_EXPONENT: f64 = 4.0;

/// Weibull slope of the life scatter, e = 9/8.
pub const WEIBULL_SLOPE: f64 = 9.0 / 8.0;

/// How a ring moves relative to the load: it decides the exponent of its equivalent load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RingMotion {
    /// Every point of the ring passes all rollers' loads: exponent 4.
    RotatingRelativeToLoad,
    /// Every point of the ring sees the same roller positions: exponent 4.5 (= 4 · 9/8).
    StationaryRelativeToLoad,
}

impl RingMotion {
    /// The exponent of the equivalent lamina load.
    pub fn exponent(self) -> f64 {
        match self {
            Self::RotatingRelativeToLoad => LAMINA_LIFE_EXPONENT,
            Self::StationaryRelativeToLoad => LAMINA_LIFE_EXPONENT * WEIBULL_SLOPE,
        }
    }
}

/// Dynamic load ratings of one lamina on the inner and the outer ring [N].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LaminaRatings {
    pub inner_n: f64,
    pub outer_n: f64,
}

/// Lamina dynamic load ratings, ISO/TS 16281:2008 (roller bearings), for laminae of length
/// w = L_we/n_s:
/// q_c = 552 b_m λν (1 ∓ γ)^{29/27} (1 ± γ)^{−1/4} (γ/cos α)^{2/9} D_we^{29/27} w^{7/9} Z^{−1/4}
/// (upper signs inner ring, lower outer; N, mm), with b_m = 1.1 as in ISO 281's C_r, so that a
/// bearing rated by laminae carries ISO 281's material and manufacturing factor.
pub fn lamina_ratings(g: &RollerBearingGeometry, lamina_length_m: f64) -> LaminaRatings {
    let gamma = g.gamma();
    let dwe = g.roller_diameter_m * 1e3;
    let lamina = lamina_length_m * 1e3;
    let common = CONTACT_RATING_CONSTANT
        * RATING_FACTOR_ROLLER
        * LINE_CONTACT_REDUCTION
        * (gamma / g.contact_angle_rad.cos()).powf(2.0 / 9.0)
        * dwe.powf(29.0 / 27.0)
        * lamina.powf(7.0 / 9.0)
        * (g.rollers_per_row as f64).powf(-0.25);
    LaminaRatings {
        inner_n: common * (1.0 - gamma).powf(29.0 / 27.0) / (1.0 + gamma).powf(0.25),
        outer_n: common * (1.0 + gamma).powf(29.0 / 27.0) / (1.0 - gamma).powf(0.25),
    }
}

/// Equivalent load of one lamina of a ring from its loads on the Z rollers of a row,
/// ISO/TS 16281:2008: q_e = ((1/Z) Σ_j q_j^w)^{1/w}, w = 4 for a ring rotating relative to the
/// load, 4.5 for a ring stationary relative to it [N].
pub fn equivalent_lamina_load(roller_loads_n: &[f64], motion: RingMotion) -> f64 {
    if roller_loads_n.is_empty() {
        return 0.0;
    }
    let w = motion.exponent();
    let mean = roller_loads_n
        .iter()
        .map(|q| q.max(0.0).powf(w))
        .sum::<f64>()
        / roller_loads_n.len() as f64;
    mean.powf(1.0 / w)
}

/// Life of a ring from the equivalent loads of its laminae (of all rows) and the lamina rating,
/// ISO/TS 16281:2008: L = (Σ_k (q_c/q_e,k)^{−4·9/8})^{−8/9} × 10⁶ revolutions; infinite
/// without load.
pub fn ring_life(lamina_rating_n: f64, equivalent_loads_n: &[f64]) -> f64 {
    let damage: f64 = equivalent_loads_n
        .iter()
        .filter(|q| **q > 0.0)
        .map(|q| (lamina_rating_n / q).powf(-LAMINA_LIFE_EXPONENT * WEIBULL_SLOPE))
        .sum();
    if damage == 0.0 {
        return f64::INFINITY;
    }
    1e6 * damage.powf(-1.0 / WEIBULL_SLOPE)
}

/// Reference rating life of the bearing from its ring lives, ISO/TS 16281:2008:
/// L10r = (L_i^{−9/8} + L_e^{−9/8})^{−8/9} [revolutions].
pub fn bearing_life(inner_revolutions: f64, outer_revolutions: f64) -> f64 {
    let sum = inner_revolutions.powf(-WEIBULL_SLOPE) + outer_revolutions.powf(-WEIBULL_SLOPE);
    if sum == 0.0 {
        return f64::INFINITY;
    }
    sum.powf(-1.0 / WEIBULL_SLOPE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::iso281::{dynamic_radial_rating, geometry_factor};

    fn geometry() -> RollerBearingGeometry {
        RollerBearingGeometry::issue_38_bearing()
    }

    /// The laminae of a uniformly loaded roller make up the whole roller: the life does not
    /// depend on n_s.
    #[test]
    fn lamina_count_does_not_change_a_uniform_life() {
        let g = geometry();
        let life = |n: usize| {
            let q = lamina_ratings(&g, g.effective_length_m / n as f64);
            let loads = vec![1000.0 / n as f64; n];
            ring_life(q.inner_n, &loads)
        };
        assert!((life(1) / life(30) - 1.0).abs() < 1e-12);
    }

    /// ISO 281's C_r is the Lundberg–Palmgren bearing rating of the contact ratings:
    /// C_r = 0.3766 Z cos α Q_ci [1 + (1.04 Q_ci/Q_ce)^{9/2}]^{−2/9} (i = 1; 207.9/552 =
    /// 0.3766), which with the lamina ratings at n_s = 1 gives back Table 7 to its rounding.
    #[test]
    fn contact_ratings_rebuild_the_iso_281_rating() {
        let g = geometry();
        let q = lamina_ratings(&g, g.effective_length_m);
        let z = g.rollers_per_row as f64;
        let c = 207.9 / 552.0
            * z
            * q.inner_n
            * (1.0 + (1.04 * q.inner_n / q.outer_n).powf(4.5)).powf(-2.0 / 9.0);
        let iso = dynamic_radial_rating(&g).unwrap();
        let fc = geometry_factor(g.gamma()).unwrap();
        assert!((c / iso - 1.0).abs() < 0.05 / fc, "{c} vs {iso}");
    }

    #[test]
    fn equivalent_loads_and_lives() {
        let loads = [3.0, 1.0, 0.0, 0.0];
        let rot = equivalent_lamina_load(&loads, RingMotion::RotatingRelativeToLoad);
        assert!((rot - (82.0f64 / 4.0).powf(0.25)).abs() < 1e-12);
        let st = equivalent_lamina_load(&loads, RingMotion::StationaryRelativeToLoad);
        assert!((st - ((3f64.powf(4.5) + 1.0) / 4.0).powf(1.0 / 4.5)).abs() < 1e-12);
        assert!(st > rot);
        assert!(ring_life(1.0, &[0.0, 0.0]).is_infinite());
        // two equal rings: 2^{−8/9} of one
        let l = bearing_life(1e6, 1e6);
        assert!((l - 1e6 * 2f64.powf(-8.0 / 9.0)).abs() < 1e-6);
        assert!((bearing_life(1e6, f64::INFINITY) / 1e6 - 1.0).abs() < 1e-12);
    }
}
