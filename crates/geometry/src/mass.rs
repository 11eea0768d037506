//! Mass properties of axisymmetric parts.

/// Mass and principal moments of inertia about the centre of mass of an axisymmetric body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MassProperties {
    /// Mass [kg].
    pub mass: f64,
    /// Moment of inertia about the symmetry axis [kg·m²].
    pub axial_inertia: f64,
    /// Moment of inertia about a transverse axis through the centre of mass [kg·m²].
    pub transverse_inertia: f64,
}

impl MassProperties {
    /// Hollow cylinder of radii `r_in < r_out`, length `width`, density `rho`.
    pub fn hollow_cylinder(r_in: f64, r_out: f64, width: f64, rho: f64) -> Self {
        let mass = rho * std::f64::consts::PI * (r_out * r_out - r_in * r_in) * width;
        let sum_sq = r_out * r_out + r_in * r_in;
        Self {
            mass,
            axial_inertia: 0.5 * mass * sum_sq,
            transverse_inertia: mass * (3.0 * sum_sq + width * width) / 12.0,
        }
    }

    /// Solid of revolution of radius `r(x)`, `x ∈ [-h, h]`, by composite Simpson rule with
    /// `n` (even) intervals: m = ρ∫πr², I_ax = ρ∫πr⁴/2, I_tr = ρ∫(πr⁴/4 + πr²x²).
    pub fn solid_of_revolution(radius: impl Fn(f64) -> f64, h: f64, rho: f64, n: usize) -> Self {
        let n = n.max(2) + n % 2;
        let dx = 2.0 * h / n as f64;
        let pi = std::f64::consts::PI;
        let (mut m, mut ia, mut it) = (0.0, 0.0, 0.0);
        for k in 0..=n {
            let x = -h + k as f64 * dx;
            let r = radius(x).max(0.0);
            let w = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            let area = pi * r * r;
            m += w * area;
            ia += w * 0.5 * area * r * r;
            it += w * (0.25 * area * r * r + area * x * x);
        }
        let f = rho * dx / 3.0;
        Self {
            mass: f * m,
            axial_inertia: f * ia,
            transverse_inertia: f * it,
        }
    }

    /// Scales all properties by `factor` (e.g. to remove pocket material uniformly).
    pub fn scaled(self, factor: f64) -> Self {
        Self {
            mass: self.mass * factor,
            axial_inertia: self.axial_inertia * factor,
            transverse_inertia: self.transverse_inertia * factor,
        }
    }
}
