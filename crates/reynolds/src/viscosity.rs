//! Viscosity and density laws used by the solvers (SPEC §8.2 / §4.1).
//!
//! The solvers take any [`Viscosity`]: the structs below (Barus, Petrusevich, Roelands,
//! isoviscous) or a closure `|pressure_pa, temperature_k| viscosity_pa_s`. The Roelands formulas
//! are the lubrication crate's ([`rolldyn_lubrication::viscosity::roelands`]).

use rolldyn_lubrication::viscosity::{
    ROELANDS_P_REF, roelands, roelands_dln_dp, roelands_z_from_alpha,
};

/// Dynamic viscosity as a function of gauge pressure (Pa) and absolute temperature (K), Pa·s.
pub trait Viscosity {
    /// μ(p, T), Pa·s.
    fn viscosity(&self, pressure_pa: f64, temperature_k: f64) -> f64;

    /// ∂ ln μ / ∂p, 1/Pa. Default: central difference; the structs override it exactly.
    fn dln_viscosity_dp(&self, pressure_pa: f64, temperature_k: f64) -> f64 {
        let dp = 1.0e3_f64.max(1.0e-6 * pressure_pa.abs());
        let a = self.viscosity(pressure_pa + dp, temperature_k).ln();
        let b = self.viscosity(pressure_pa - dp, temperature_k).ln();
        (a - b) / (2.0 * dp)
    }

    /// True when μ does not depend on pressure (lets solvers skip the viscosity update).
    fn pressure_independent(&self) -> bool {
        false
    }
}

impl<F: Fn(f64, f64) -> f64> Viscosity for F {
    fn viscosity(&self, pressure_pa: f64, temperature_k: f64) -> f64 {
        self(pressure_pa, temperature_k)
    }
}

/// Constant viscosity μ₀.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Isoviscous {
    /// Viscosity, Pa·s.
    pub mu: f64,
}

impl Viscosity for Isoviscous {
    fn viscosity(&self, _: f64, _: f64) -> f64 {
        self.mu
    }
    fn dln_viscosity_dp(&self, _: f64, _: f64) -> f64 {
        0.0
    }
    fn pressure_independent(&self) -> bool {
        true
    }
}

/// Barus law μ = μ₀ exp(αp), seed 002 eq. (3.8) (SPEC §4.1). Temperature is ignored.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Barus {
    /// Viscosity at ambient pressure, Pa·s.
    pub mu0: f64,
    /// Pressure–viscosity coefficient α, 1/Pa.
    pub alpha: f64,
}

impl Viscosity for Barus {
    fn viscosity(&self, p: f64, _: f64) -> f64 {
        self.mu0 * (self.alpha * p).exp()
    }
    fn dln_viscosity_dp(&self, _: f64, _: f64) -> f64 {
        self.alpha
    }
    fn pressure_independent(&self) -> bool {
        self.alpha == 0.0
    }
}

/// Petrusevich pressure–temperature law μ = μ₀ exp(αp − Ω₀(T − T_ref)), seed 002 eqs. (1.16),
/// (3.7) (SPEC §4.1; T measured from the reference temperature of μ₀, SPEC proposal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Petrusevich {
    /// Viscosity at ambient pressure and `t_ref_k`, Pa·s.
    pub mu0: f64,
    /// Pressure–viscosity coefficient α, 1/Pa.
    pub alpha: f64,
    /// Viscosity–temperature slope Ω₀, 1/K.
    pub omega0: f64,
    /// Reference temperature of μ₀, K.
    pub t_ref_k: f64,
}

impl Viscosity for Petrusevich {
    fn viscosity(&self, p: f64, t: f64) -> f64 {
        self.mu0 * (self.alpha * p - self.omega0 * (t - self.t_ref_k)).exp()
    }
    fn dln_viscosity_dp(&self, _: f64, _: f64) -> f64 {
        self.alpha
    }
    fn pressure_independent(&self) -> bool {
        self.alpha == 0.0
    }
}

/// Roelands law μ = μ₀ exp{(ln μ₀ + 9.67)[(1 + p/p_r)^Z − 1]}, p_r = 1.96×10⁸ Pa, with Z from
/// the equivalent α = Z (ln μ₀ + 9.67)/p_r (standard form, not in the seeds; used only to compare
/// with film-thickness formulas fitted with it). Temperature is ignored.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roelands {
    /// Viscosity at ambient pressure, Pa·s.
    pub mu0: f64,
    /// Pressure–viscosity index Z.
    pub z: f64,
}

impl Roelands {
    /// Reference pressure p_r, Pa.
    pub const P_REF: f64 = ROELANDS_P_REF;

    /// Roelands law with the same initial slope as Barus with coefficient `alpha`.
    pub fn from_alpha(mu0: f64, alpha: f64) -> Self {
        Self {
            mu0,
            z: roelands_z_from_alpha(mu0, alpha),
        }
    }
}

impl Viscosity for Roelands {
    fn viscosity(&self, p: f64, _: f64) -> f64 {
        roelands(self.mu0, self.z, p.max(0.0))
    }
    fn dln_viscosity_dp(&self, p: f64, _: f64) -> f64 {
        roelands_dln_dp(self.mu0, self.z, p.max(0.0))
    }
}

/// Lubricant density law relative to the density at ambient pressure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Density {
    /// ρ/ρ₀ = 1 (the seed's assumption). Default.
    #[default]
    Incompressible,
    /// Dowson–Higginson ρ/ρ₀ = 1 + 0.6×10⁻⁹p/(1 + 1.7×10⁻⁹p) (standard form, not in the seeds).
    DowsonHigginson,
}

impl Density {
    /// ρ/ρ₀ at gauge pressure p (Pa).
    #[inline]
    pub fn ratio(self, p: f64) -> f64 {
        match self {
            Density::Incompressible => 1.0,
            Density::DowsonHigginson => {
                let p = p.max(0.0);
                1.0 + 0.6e-9 * p / (1.0 + 1.7e-9 * p)
            }
        }
    }

    /// d(ρ/ρ₀)/dp, 1/Pa.
    #[inline]
    pub fn derivative(self, p: f64) -> f64 {
        match self {
            Density::Incompressible => 0.0,
            Density::DowsonHigginson => {
                if p <= 0.0 {
                    0.6e-9
                } else {
                    let d = 1.0 + 1.7e-9 * p;
                    0.6e-9 / (d * d)
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closure_and_structs_agree() {
        let b = Barus {
            mu0: 0.024,
            alpha: 2e-8,
        };
        let c = |p: f64, _t: f64| 0.024 * (2e-8 * p).exp();
        for p in [0.0, 1e8, 5e8] {
            assert!(
                (b.viscosity(p, 300.0) - c.viscosity(p, 300.0)).abs()
                    < 1e-12 * b.viscosity(p, 300.0)
            );
            assert!((b.dln_viscosity_dp(p, 300.0) - c.dln_viscosity_dp(p, 300.0)).abs() < 1e-12);
        }
        let r = Roelands::from_alpha(0.04, 2e-8);
        let d = r.dln_viscosity_dp(0.0, 300.0);
        assert!((d - 2e-8).abs() < 1e-14);
    }
}
