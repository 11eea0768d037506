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

    /// Solid of revolution of radius `r(x)`, `x ∈ [-h, h]`: [`Self::solid_of_revolution_with_centroid`]
    /// without the centroid.
    pub fn solid_of_revolution(radius: impl Fn(f64) -> f64, h: f64, rho: f64, n: usize) -> Self {
        Self::solid_of_revolution_with_centroid(radius, h, rho, n).0
    }

    /// Solid of revolution of radius `r(x)`, `x ∈ [-h, h]`, by composite Simpson rule with
    /// `n` (even) intervals: m = ρ∫πr², x_c = ρ∫πr²x / m, I_ax = ρ∫πr⁴/2,
    /// I_tr = ρ∫(πr⁴/4 + πr²x²) − m x_c² (about the centre of mass). Returns the properties and
    /// the centroid position x_c.
    pub fn solid_of_revolution_with_centroid(
        radius: impl Fn(f64) -> f64,
        h: f64,
        rho: f64,
        n: usize,
    ) -> (Self, f64) {
        let n = n.max(2) + n % 2;
        let dx = 2.0 * h / n as f64;
        let pi = std::f64::consts::PI;
        let (mut m, mut mx, mut ia, mut it) = (0.0, 0.0, 0.0, 0.0);
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
            mx += w * area * x;
            ia += w * 0.5 * area * r * r;
            it += w * (0.25 * area * r * r + area * x * x);
        }
        let f = rho * dx / 3.0;
        let mass = f * m;
        let centroid = if mass > 0.0 { f * mx / mass } else { 0.0 };
        let properties = Self {
            mass,
            axial_inertia: f * ia,
            transverse_inertia: f * it - mass * centroid * centroid,
        };
        (properties, centroid)
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
