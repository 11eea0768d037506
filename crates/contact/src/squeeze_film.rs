//! The oil squeeze film between a roller and a flat face (the cage bar): a long rigid cylinder
//! approaching a plane through an isoviscous film, the outlet half cavitated. The elastic bar
//! law of [`crate::cage_bar`] matches its restitution and the lubricated law of
//! [`crate::bar_force`] carries it explicitly.
//!
//! SI units throughout (m, N, Pa·s, kg).

use std::f64::consts::{PI, SQRT_2};

/// Squeeze film between a long rigid cylinder (radius R, length L) and a plane, isoviscous,
/// the separating (outlet) half cavitated: `F = (3π/√2) η L R^{3/2} (−ḣ)/h^{3/2}` (the
/// Reynolds pressure `p = 6ηR(−ḣ)/h²` integrated over one half of the gap; the seed 002 rigid
/// solution (3.20) `λ = 6W₁′ηR^{3/2}ℓ/h^{3/2}` with `W₁′ = π/(2√2) = 1.111`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SqueezeFilm {
    /// Dynamic viscosity of the oil at the cage temperature (Pa·s).
    pub viscosity: f64,
    /// Length of the film along the roller (m).
    pub length: f64,
    /// Roller radius R_w (m).
    pub radius: f64,
}

impl SqueezeFilm {
    /// `λ₁ = (3π/√2) η L R^{3/2}` (N·s/m^{1/2}): `λ(h) = λ₁/h^{3/2}`.
    pub fn strength(&self) -> f64 {
        3.0 * PI / SQRT_2 * self.viscosity * self.length * self.radius.powf(1.5)
    }

    /// Damping coefficient `λ(h)` (N·s/m) at film thickness `h`.
    pub fn damping(&self, h: f64) -> f64 {
        self.strength() / h.powf(1.5)
    }

    /// Speed a roller of `mass` loses crossing the film from far away down to `h`
    /// (integral of `m dv = −λ₁ dh/h^{3/2}`): `Δv = 2λ₁/(m√h)`.
    pub fn speed_loss(&self, mass: f64, h: f64) -> f64 {
        2.0 * self.strength() / (mass * h.sqrt())
    }

    /// Largest film force while a roller of `mass` arriving at `speed` crosses the film down
    /// to `h_end`: with `u = h^{-1/2}`, `F = λ₁u³(v₀ − 2λ₁u/m)` peaks at `u* = 3mv₀/(8λ₁)`.
    pub fn peak_force(&self, mass: f64, speed: f64, h_end: f64) -> f64 {
        let l1 = self.strength();
        if l1 == 0.0 {
            return 0.0;
        }
        let u = (3.0 * mass * speed / (8.0 * l1)).min(1.0 / h_end.sqrt());
        l1 * u.powi(3) * (speed - 2.0 * l1 * u / mass)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn squeeze_force_matches_reynolds_integral() {
        // p = 6ηR(−ḣ)/h(x)², h = h₀ + x²/2R, over the inlet half x < 0 (h₀ ≪ R)
        let film = SqueezeFilm {
            viscosity: 0.02,
            length: 1.0,
            radius: 7.5e-3,
        };
        let (h0, hdot) = (2e-6, 1e-3);
        let scale = (2.0 * film.radius * h0).sqrt();
        let n = 200_000;
        let dx = 2000.0 * scale / n as f64;
        let force: f64 = (0..n)
            .map(|k| {
                let x = (k as f64 + 0.5) * dx;
                let h = h0 + x * x / (2.0 * film.radius);
                6.0 * film.viscosity * film.radius * hdot / (h * h) * dx
            })
            .sum();
        let closed = film.damping(h0) * hdot;
        assert!((force / closed - 1.0).abs() < 2e-3, "{force} vs {closed}");
    }

    #[test]
    fn film_peak_force_is_the_maximum_along_the_path() {
        let film = SqueezeFilm {
            viscosity: 0.016,
            length: 14e-3,
            radius: 7.5e-3,
        };
        let (m, v0) = (0.02, 0.1);
        let l1 = film.strength();
        let brute = (1..20_000)
            .map(|k| {
                let h = 1e-8 * 1.001_f64.powi(k);
                let v = v0 - film.speed_loss(m, h);
                if v > 0.0 { l1 * v / h.powf(1.5) } else { 0.0 }
            })
            .fold(0.0, f64::max);
        let peak = film.peak_force(m, v0, 1e-9);
        assert!((peak / brute - 1.0).abs() < 1e-3, "{peak} vs {brute}");
    }
}
