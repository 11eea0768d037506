//! ISO 76:2006 — basic static radial load rating and equivalent static load of radial roller
//! bearings, and the static safety factor.

use crate::geometry::RollerBearingGeometry;

/// Basic static radial load rating of a radial roller bearing, ISO 76:2006 §6.1 (radial roller
/// bearings, 4 000 MPa at the most loaded contact):
/// C0r = 44 (1 − D_we cos α / D_pw) i Z L_we D_we cos α (N, mm) [N].
pub fn static_radial_rating(g: &RollerBearingGeometry) -> f64 {
    let (lwe, dwe) = (g.effective_length_m * 1e3, g.roller_diameter_m * 1e3);
    let cos = g.contact_angle_rad.cos();
    44.0 * (1.0 - g.gamma()) * g.rows as f64 * g.rollers_per_row as f64 * lwe * dwe * cos
}

/// Equivalent static radial load of a radial roller bearing, ISO 76:2006 §6.2 (Table 2 factors):
/// α = 0 → P0r = F_r; α ≠ 0, single row → P0r = max(0.5 F_r + 0.22 cot α F_a, F_r); double row
/// → P0r = F_r + 0.44 cot α F_a [N].
pub fn equivalent_static_load(
    radial_n: f64,
    axial_n: f64,
    contact_angle_rad: f64,
    rows: usize,
) -> f64 {
    let (fr, fa) = (radial_n.abs(), axial_n.abs());
    if contact_angle_rad == 0.0 {
        return fr;
    }
    let cot = 1.0 / contact_angle_rad.tan();
    if rows > 1 {
        fr + 0.44 * cot * fa
    } else {
        (0.5 * fr + 0.22 * cot * fa).max(fr)
    }
}

/// Static safety factor s0 = C0r / P0r (ISO 76:2006 Annex, the guide values of s0); infinite
/// without load.
pub fn static_safety(static_rating_n: f64, static_load_n: f64) -> f64 {
    if static_load_n <= 0.0 {
        f64::INFINITY
    } else {
        static_rating_n / static_load_n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 16 rollers 15 × 22 mm on D_pw 102.5 mm: 44 (1 − 15/102.5) · 16 · 22 · 15 = 198 322 N.
    #[test]
    fn static_rating_by_hand() {
        let g = RollerBearingGeometry::issue_38_bearing();
        let c0 = static_radial_rating(&g);
        assert!((c0 - 44.0 * (1.0 - 15.0 / 102.5) * 16.0 * 22.0 * 15.0).abs() < 1e-6);
        assert!((c0 - 198_322.0).abs() < 1.0, "{c0}");
        let tapered = RollerBearingGeometry {
            contact_angle_rad: 10f64.to_radians(),
            rows: 2,
            ..g
        };
        let cos = 10f64.to_radians().cos();
        let hand = 44.0 * (1.0 - 15.0 * cos / 102.5) * 2.0 * 16.0 * 22.0 * 15.0 * cos;
        assert!((static_radial_rating(&tapered) - hand).abs() < 1e-6);
    }

    #[test]
    fn equivalent_static_loads() {
        let a = 10f64.to_radians();
        assert_eq!(equivalent_static_load(5e3, 1e3, 0.0, 1), 5e3);
        assert_eq!(equivalent_static_load(5e3, 0.0, a, 1), 5e3);
        let single = equivalent_static_load(5e3, 5e3, a, 1);
        assert!((single - (2.5e3 + 0.22 / a.tan() * 5e3)).abs() < 1e-9);
        let double = equivalent_static_load(5e3, 1e3, a, 2);
        assert!((double - (5e3 + 0.44 / a.tan() * 1e3)).abs() < 1e-9);
        assert_eq!(static_safety(10.0, 4.0), 2.5);
    }
}
