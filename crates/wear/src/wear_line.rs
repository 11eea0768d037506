//! Pressure on a wear line: the mean pressure along a line of the surface that crosses the
//! contact patch (seed 000 §2.4.1 step 3, docs/theory.md §8.5).
//!
//! A wear line is a circle of the surface (a roller circle, a raceway circle, a line along the
//! bar, a circle on the roller end or the rib) that runs through the patch across its width.
//! Along it the pressure integrates to the load per unit length of the patch, so the mean over
//! the patch width is that load over the width: for a Hertz line contact p̄ = q/(2b) = π p₀/4;
//! for the central line of a circular Hertz patch p̄ = π p₀/4 = 3Q/(8a²).

use rolldyn_contact::hertz::{line_half_width, point_contact_sphere_flat};
use std::f64::consts::PI;

/// A contact patch as one wear line sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinePatch {
    /// half-width of the patch across the wear line, m
    pub half_width_m: f64,
    /// mean pressure along the wear line inside the patch, Pa
    pub mean_pressure_pa: f64,
}

impl LinePatch {
    /// No contact.
    pub const NONE: LinePatch = LinePatch {
        half_width_m: 0.0,
        mean_pressure_pa: 0.0,
    };
}

/// The wear line through slice `force_n` / `length_m` of a sliced line contact (seed 000 eq.
/// 2.16 for the half-width): p̄ = q/(2b) with q = F/L.
pub fn slice_patch(
    force_n: f64,
    length_m: f64,
    reduced_radius_m: f64,
    reduced_modulus_pa: f64,
) -> LinePatch {
    let loaded = force_n > 0.0; // false for NaN too
    if !loaded {
        return LinePatch::NONE;
    }
    let q = force_n / length_m;
    let b = line_half_width(q, reduced_radius_m, reduced_modulus_pa);
    LinePatch {
        half_width_m: b,
        mean_pressure_pa: q / (2.0 * b),
    }
}

/// The central wear line of a circular Hertz patch of reduced radius `reduced_radius_m`
/// (sphere on flat, SPEC §2.3): a = (3QR/(4E*))^{1/3}, p̄ = π p₀/4.
pub fn point_patch(force_n: f64, reduced_radius_m: f64, reduced_modulus_pa: f64) -> LinePatch {
    let loaded = force_n > 0.0; // false for NaN too
    if !loaded {
        return LinePatch::NONE;
    }
    match point_contact_sphere_flat(reduced_radius_m, reduced_modulus_pa, force_n) {
        Ok(c) => LinePatch {
            half_width_m: c.semi_major,
            mean_pressure_pa: 0.25 * PI * c.max_pressure,
        },
        Err(_) => LinePatch::NONE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slice_mean_pressure_is_pi_over_four_of_the_peak() {
        let (f, l, r, e) = (500.0, 1e-3, 6.5e-3, 2.3e11);
        let p = slice_patch(f, l, r, e);
        let p0 = 2.0 * (f / l) / (PI * p.half_width_m);
        assert!((p.mean_pressure_pa / p0 - 0.25 * PI).abs() < 1e-12);
    }

    #[test]
    fn point_patch_central_line_carries_three_q_over_eight_a_squared() {
        let p = point_patch(10.0, 0.43, 2.3e11);
        let a = p.half_width_m;
        assert!(
            (p.mean_pressure_pa - 3.0 * 10.0 / (8.0 * a * a)).abs() < 1e-6 * p.mean_pressure_pa
        );
    }

    #[test]
    fn no_force_no_patch() {
        assert_eq!(slice_patch(0.0, 1e-3, 1e-3, 1e11), LinePatch::NONE);
        assert_eq!(point_patch(-1.0, 1e-3, 1e11), LinePatch::NONE);
    }
}
