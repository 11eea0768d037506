//! Stress-concentration factors of the window-corner fillet: the bar joins the rim like the
//! narrow part of a flat member with a square shoulder and fillets (Young & Budynas, Roark's
//! Formulas for Stress and Strain, 7th ed., 2002, Table 17.1, "square shoulder with fillet in a
//! member of rectangular section": axial tension and in-plane bending; after Peterson's charts).
//! `K_t = C₁ + C₂ (2h/D) + C₃ (2h/D)² + C₄ (2h/D)³` with `h` the shoulder height, `D` the wide
//! width, `r` the fillet radius, the `Cᵢ` quadratic in `√(h/r)` for `0.1 ≤ h/r ≤ 2` and
//! `2 ≤ h/r ≤ 20`.

/// Coefficient rows `[c0, c_sqrt, c_lin]` of `C₁…C₄` for `h/r ≤ 2` and `h/r > 2`.
type Coefficients = [[[f64; 3]; 4]; 2];

/// Axial tension (Roark Table 17.1, the tension case of the rectangular shoulder).
const TENSION: Coefficients = [
    [
        [1.007, 1.000, -0.031],
        [-0.114, -0.585, 0.314],
        [0.241, -0.992, -0.271],
        [-0.134, 0.577, -0.012],
    ],
    [
        [1.042, 0.982, -0.036],
        [-0.074, -0.156, -0.010],
        [-3.418, 1.220, -0.005],
        [3.450, -2.046, 0.051],
    ],
];

/// In-plane bending (Roark Table 17.1, the bending case of the rectangular shoulder).
const BENDING: Coefficients = [
    [
        [1.007, 1.000, -0.031],
        [-0.270, -2.404, 0.749],
        [0.677, 1.133, -0.904],
        [-0.414, 0.271, 0.186],
    ],
    [
        [1.042, 0.982, -0.036],
        [-3.599, 1.619, -0.431],
        [6.084, -5.607, 1.158],
        [-2.527, 3.006, -0.691],
    ],
];

/// Load case of a shoulder fillet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShoulderLoad {
    Tension,
    InPlaneBending,
}

/// `K_t` of a shoulder of height `h` (each side) on a member of wide width `d_wide` with
/// fillet radius `r`; `h/r` is clamped to the fitted range 0.1…20.
pub fn shoulder_fillet_kt(load: ShoulderLoad, h: f64, d_wide: f64, r: f64) -> f64 {
    let table = match load {
        ShoulderLoad::Tension => &TENSION,
        ShoulderLoad::InPlaneBending => &BENDING,
    };
    let hr = (h / r).clamp(0.1, 20.0);
    let rows = &table[usize::from(hr > 2.0)];
    let c = rows.map(|[a, b, l]| a + b * hr.sqrt() + l * hr);
    let x = 2.0 * h / d_wide;
    c[0] + c[1] * x + c[2] * x * x + c[3] * x * x * x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vanishing_shoulder_concentrates_nothing() {
        // 2h/D → 1 would be a crack; 2h/D → 0 with h/r small tends to K_t ≈ 1 + √(h/r)
        let kt = shoulder_fillet_kt(ShoulderLoad::Tension, 0.1e-3, 1.0, 1e-3);
        assert!((kt - (1.007 + 0.1f64.sqrt() - 0.0031)).abs() < 1e-3);
    }

    #[test]
    fn sharper_fillets_concentrate_more() {
        for load in [ShoulderLoad::Tension, ShoulderLoad::InPlaneBending] {
            let blunt = shoulder_fillet_kt(load, 5e-3, 32e-3, 2e-3);
            let sharp = shoulder_fillet_kt(load, 5e-3, 32e-3, 0.5e-3);
            assert!(sharp > blunt && blunt > 1.0, "{load:?}: {sharp} {blunt}");
        }
    }
}
