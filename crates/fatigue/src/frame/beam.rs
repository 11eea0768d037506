//! The 3-D Timoshenko beam element of the frame model (Przemieniecki, Theory of Matrix
//! Structural Analysis, 1968, §5.6: the 12 × 12 stiffness with shear deformation) and the
//! sections it uses: rectangles (the rims) and the bar's section of the pocket profile.

// matrix algebra on index grids reads best with indices
#![allow(clippy::needless_range_loop)]

/// A rectangular section: `height` along the element's local y axis, `width` along local z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RectangularSection {
    pub height: f64,
    pub width: f64,
}

impl RectangularSection {
    pub fn area(&self) -> f64 {
        self.height * self.width
    }

    /// Second moment about the local y axis (bending with stress varying along z), m⁴.
    pub fn i_y(&self) -> f64 {
        self.height * self.width.powi(3) / 12.0
    }

    /// Second moment about the local z axis (stress varying along y), m⁴.
    pub fn i_z(&self) -> f64 {
        self.width * self.height.powi(3) / 12.0
    }

    /// Saint-Venant torsion constant `J = β a b³` of a rectangle with sides `a ≥ b`, `β = 1/3 −
    /// 0.21 (b/a)(1 − b⁴/(12 a⁴))` (Roark's Formulas for Stress and Strain, 7th ed., Table 10.1,
    /// case 4), m⁴.
    pub fn torsion_constant(&self) -> f64 {
        let (a, b) = if self.height >= self.width {
            (self.height, self.width)
        } else {
            (self.width, self.height)
        };
        let r = b / a;
        a * b.powi(3) * (1.0 / 3.0 - 0.21 * r * (1.0 - r.powi(4) / 12.0))
    }
}

/// The section properties a beam element needs (local y, z through the centroid), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    pub area: f64,
    /// second moment about local y (stress varying along z), m⁴
    pub i_y: f64,
    /// second moment about local z (stress varying along y), m⁴
    pub i_z: f64,
    /// Saint-Venant torsion constant, m⁴
    pub torsion_constant: f64,
}

impl From<RectangularSection> for Section {
    fn from(r: RectangularSection) -> Self {
        Self {
            area: r.area(),
            i_y: r.i_y(),
            i_z: r.i_z(),
            torsion_constant: r.torsion_constant(),
        }
    }
}

impl Section {
    /// A bar of the pocket profile ([`rolldyn_geometry::BarSection`]), local y radial and z
    /// tangential: `A`, `I_y = ∫ b³/12 dr`, `I_z = ∫ b (r − r̄)² dr` from the profile; the torsion
    /// constant that of the rectangle of equal depth and area (Roark Table 10.1 case 4: a lip
    /// widens the bar over a thin band that adds little torsional stiffness beyond its area).
    pub fn of_bar(bar: &rolldyn_geometry::BarSection) -> Self {
        let equivalent = RectangularSection {
            height: bar.depth,
            width: bar.area / bar.depth,
        };
        Self {
            area: bar.area,
            i_y: bar.second_moment,
            i_z: bar.second_moment_radial,
            torsion_constant: equivalent.torsion_constant(),
        }
    }
}

/// Shear correction factor of a rectangle (Timoshenko), κ = 5/6.
pub const SHEAR_FACTOR_RECTANGLE: f64 = 5.0 / 6.0;

/// Material of the frame: Young's and shear moduli, Pa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    pub youngs_modulus: f64,
    pub shear_modulus: f64,
}

impl Elastic {
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Self {
        Self {
            youngs_modulus,
            shear_modulus: youngs_modulus / (2.0 * (1.0 + poisson_ratio)),
        }
    }
}

/// Local stiffness of a Timoshenko beam of length `l`, DOFs `[u, v, w, θx, θy, θz]` at end 1
/// then end 2 (x along the beam), row-major 12 × 12. The shear parameters are
/// `Φ_y = 12 E I_z/(κ G A l²)` (bending in x–y) and `Φ_z = 12 E I_y/(κ G A l²)` (x–z).
pub fn local_stiffness(section: &Section, material: &Elastic, l: f64) -> [[f64; 12]; 12] {
    let (e, g) = (material.youngs_modulus, material.shear_modulus);
    let a = section.area;
    let (iy, iz, j) = (section.i_y, section.i_z, section.torsion_constant);
    let shear = SHEAR_FACTOR_RECTANGLE * g * a * l * l;
    let phi_y = 12.0 * e * iz / shear;
    let phi_z = 12.0 * e * iy / shear;
    let mut k = [[0.0; 12]; 12];
    let mut put = |dofs: &[usize], m: &[f64]| {
        let n = dofs.len();
        for r in 0..n {
            for c in 0..n {
                k[dofs[r]][dofs[c]] += m[r * n + c];
            }
        }
    };
    let axial = e * a / l;
    put(&[0, 6], &[axial, -axial, -axial, axial]);
    let torsion = g * j / l;
    put(&[3, 9], &[torsion, -torsion, -torsion, torsion]);
    put(&[1, 5, 7, 11], &bending(e * iz, phi_y, l, 1.0));
    put(&[2, 4, 8, 10], &bending(e * iy, phi_z, l, -1.0));
    k
}

/// The 4 × 4 bending block on (deflection 1, rotation 1, deflection 2, rotation 2); `sign` +1 for
/// the x–y plane (v, θz), −1 for x–z (w, θy).
fn bending(ei: f64, phi: f64, l: f64, sign: f64) -> [f64; 16] {
    let c = ei / ((1.0 + phi) * l.powi(3));
    let s = sign * 6.0 * l;
    let (a, b) = ((4.0 + phi) * l * l, (2.0 - phi) * l * l);
    [
        12.0, s, -12.0, s, //
        s, a, -s, b, //
        -12.0, -s, 12.0, -s, //
        s, b, -s, a,
    ]
    .map(|v| c * v)
}

/// Rotates a 12 × 12 local matrix to global axes: `Tᵀ K T` with `T` = four copies of the 3 × 3
/// matrix whose rows are the local axes `axes` in global coordinates.
pub fn to_global(local: &[[f64; 12]; 12], axes: &[[f64; 3]; 3]) -> [[f64; 12]; 12] {
    let t = |r: usize, c: usize| -> f64 {
        if r / 3 == c / 3 {
            axes[r % 3][c % 3]
        } else {
            0.0
        }
    };
    let kt: [[f64; 12]; 12] = std::array::from_fn(|r| {
        std::array::from_fn(|c| (0..12).map(|m| local[r][m] * t(m, c)).sum())
    });
    std::array::from_fn(|r| std::array::from_fn(|c| (0..12).map(|m| t(m, r) * kt[m][c]).sum()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_torsion_constant_matches_roark() {
        // β = 0.1406 for a square (Roark Table 10.1 case 4: K = 2.25 a⁴ with a the half side)
        let s = RectangularSection {
            height: 2.0,
            width: 2.0,
        };
        assert!((s.torsion_constant() - 2.25).abs() / 2.25 < 2e-3);
    }

    #[test]
    fn stiffness_is_symmetric_and_has_rigid_modes() {
        let s = RectangularSection {
            height: 0.01,
            width: 0.004,
        };
        let k = local_stiffness(&s.into(), &Elastic::new(2.1e11, 0.3), 0.02);
        for r in 0..12 {
            for c in 0..12 {
                assert!((k[r][c] - k[c][r]).abs() <= 1e-9 * k[r][r].abs().max(1.0));
            }
        }
        // a rigid rotation about z: v = x θ, θz = θ gives no forces
        let mut u = [0.0; 12];
        u[5] = 1e-3;
        u[11] = 1e-3;
        u[7] = 0.02 * 1e-3;
        for row in &k {
            let f: f64 = row.iter().zip(&u).map(|(a, b)| a * b).sum();
            assert!(f.abs() < 1e-6 * k[1][1]);
        }
    }

    /// A cantilever with a tip load: `w = P l³/(3 E I) + P l/(κ G A)` (Timoshenko) and the
    /// clamped-end moment `P l`.
    #[test]
    fn cantilever_tip_load() {
        let s = RectangularSection {
            height: 0.01,
            width: 0.02,
        };
        let m = Elastic::new(2.1e11, 0.3);
        let l = 0.011;
        let k = local_stiffness(&s.into(), &m, l);
        // free end 2: solve the (w2, θy2) block under P along local z
        let (a, b, c, d) = (k[8][8], k[8][10], k[10][8], k[10][10]);
        let p = 1.0;
        let det = a * d - b * c;
        let (w2, t2) = (d * p / det, -c * p / det);
        let expected = p * l.powi(3) / (3.0 * m.youngs_modulus * s.i_y())
            + p * l / (SHEAR_FACTOR_RECTANGLE * m.shear_modulus * s.area());
        assert!(
            (w2 - expected).abs() < 1e-9 * expected,
            "{w2:e} {expected:e}"
        );
        // reaction moment at the clamp (θy1 row) magnitude P l
        let m1 = k[4][8] * w2 + k[4][10] * t2;
        assert!((m1.abs() - p * l).abs() < 1e-9, "{m1:e}");
    }
}
