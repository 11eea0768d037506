//! Wall-slip flow functions of the generalised Reynolds equation, seed 002 eqs. (1.10)–(1.15),
//! SPEC §8.1, with the general Couette flux of flag F-58.

/// Navier slip lengths k₁ (surface 1, at z = 0) and k₂ (surface 2, at z = h), m. Zero = no slip.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SlipLengths {
    /// Slip length of surface 1, m (≥ 0).
    pub k1: f64,
    /// Slip length of surface 2, m (≥ 0).
    pub k2: f64,
}

impl SlipLengths {
    /// No slip on either surface (S = h³/12μ, Γ = h; seed 002 (1.14)).
    pub const NONE: SlipLengths = SlipLengths { k1: 0.0, k2: 0.0 };

    /// True when both slip lengths are zero.
    pub fn is_none(&self) -> bool {
        self.k1 == 0.0 && self.k2 == 0.0
    }

    /// μ·S(h): S = h²[h(4k₁ + 4k₂ + h) + 12k₁k₂] / (12μ(k₁ + k₂ + h)), seed 002 eq. (1.15).
    /// Reduces to h³/12 without slip.
    #[inline]
    pub fn poiseuille(&self, h: f64) -> f64 {
        if self.is_none() {
            return h * h * h / 12.0;
        }
        let (k1, k2) = (self.k1, self.k2);
        h * h * (h * (4.0 * k1 + 4.0 * k2 + h) + 12.0 * k1 * k2) / (12.0 * (k1 + k2 + h))
    }

    /// d(μS)/dh.
    #[inline]
    pub fn d_poiseuille(&self, h: f64) -> f64 {
        if self.is_none() {
            return 0.25 * h * h;
        }
        let (k1, k2) = (self.k1, self.k2);
        let s = k1 + k2 + h;
        let num = h * h * (h * (4.0 * k1 + 4.0 * k2 + h) + 12.0 * k1 * k2);
        let dnum = 2.0 * h * (h * (4.0 * k1 + 4.0 * k2 + h) + 12.0 * k1 * k2)
            + h * h * (4.0 * k1 + 4.0 * k2 + 2.0 * h);
        (dnum * s - num) / (12.0 * s * s)
    }

    /// Seed's Γ(h) = h(h + 2k₁)/(k₁ + k₂ + h), eq. (1.15).
    #[inline]
    pub fn gamma(&self, h: f64) -> f64 {
        h * (h + 2.0 * self.k1) / (self.k1 + self.k2 + h)
    }

    /// Couette flux per unit width for surface velocities u₁, u₂ (flag F-58, SPEC §8.1):
    /// q_C = h[u₁(k₂ + h/2) + u₂(k₁ + h/2)]/(k₁ + k₂ + h). Equals ½(u₁+u₂)Γ(h)·… only when
    /// u₁ = 0 or k₁ = k₂; without slip q_C = h(u₁ + u₂)/2.
    #[inline]
    pub fn couette(&self, h: f64, u1: f64, u2: f64) -> f64 {
        if self.is_none() {
            return 0.5 * h * (u1 + u2);
        }
        let (k1, k2) = (self.k1, self.k2);
        h * (u1 * (k2 + 0.5 * h) + u2 * (k1 + 0.5 * h)) / (k1 + k2 + h)
    }

    /// ∂q_C/∂h.
    #[inline]
    pub fn d_couette(&self, h: f64, u1: f64, u2: f64) -> f64 {
        if self.is_none() {
            return 0.5 * (u1 + u2);
        }
        let (k1, k2) = (self.k1, self.k2);
        let s = k1 + k2 + h;
        let num = h * (u1 * (k2 + 0.5 * h) + u2 * (k1 + 0.5 * h));
        let dnum = u1 * (k2 + h) + u2 * (k1 + h);
        (dnum * s - num) / (s * s)
    }

    /// Wall shear stresses (τ on surface 1 in the direction of u, τ on surface 2) for a film of
    /// thickness h, viscosity μ, pressure gradient g = ∂p/∂x and surface speeds u₁, u₂, from the
    /// velocity profile (1.10). Returned as the traction the fluid exerts on each surface along +x.
    pub fn wall_tractions(&self, h: f64, mu: f64, g: f64, u1: f64, u2: f64) -> (f64, f64) {
        let (k1, k2) = (self.k1, self.k2);
        // V(z) = g/μ [z²/2 − (k1+z)(k2+h/2)h/(k1+k2+h)] + (u2−u1)(z+k1)/(k1+k2+h) + u1
        let s = k1 + k2 + h;
        let dvdz = |z: f64| g / mu * (z - (k2 + 0.5 * h) * h / s) + (u2 - u1) / s;
        // traction on surface 1 (below the fluid, normal +z into fluid): +μ dV/dz(0)
        // traction on surface 2 (above, normal −z into fluid): −μ dV/dz(h)
        (mu * dvdz(0.0), -mu * dvdz(h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slip_reduces_to_known_forms() {
        let s = SlipLengths { k1: 2e-6, k2: 2e-6 };
        let h = 5e-6;
        // k1 = k2 = k: S·μ = h³/12 + k h²/2 (SPEC §8.1 derived check)
        let want = h * h * h / 12.0 + 2e-6 * h * h / 2.0;
        assert!((s.poiseuille(h) - want).abs() < 1e-12 * want);
        // q_C = ½ V Γ for k1 = k2
        let (u1, u2) = (1.0, 3.0);
        assert!((s.couette(h, u1, u2) - 0.5 * (u1 + u2) * s.gamma(h)).abs() < 1e-18);
        // numeric derivatives
        let s2 = SlipLengths { k1: 1e-6, k2: 3e-6 };
        let dh = 1e-12;
        let d = (s2.poiseuille(h + dh) - s2.poiseuille(h - dh)) / (2.0 * dh);
        assert!((d - s2.d_poiseuille(h)).abs() < 1e-6 * d);
        let d = (s2.couette(h + dh, u1, u2) - s2.couette(h - dh, u1, u2)) / (2.0 * dh);
        assert!((d - s2.d_couette(h, u1, u2)).abs() < 1e-6 * d.abs());
        // no slip tractions: Couette τ = μ(u2−u1)/h on both, pressure part ∓ g h/2
        let (t1, t2) = SlipLengths::NONE.wall_tractions(h, 0.1, 1e6, 0.0, 2.0);
        assert!((t1 - (0.1 * 2.0 / h - 1e6 * h / 2.0)).abs() < 1e-9);
        assert!((t2 - (-0.1 * 2.0 / h - 1e6 * h / 2.0)).abs() < 1e-9);
    }
}
