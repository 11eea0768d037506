//! Fourier thermal model of the bush, seed 002 eqs. (4.16)–(4.30), (4.33)–(4.35), SPEC §8.6.
//!
//! Per axial section, steady conduction in the annulus R₁ ≤ r ≤ R₃ (liner and housing with one
//! conductivity χ), T(R₃) = T₀, all the heat generated in the film entering the bore,
//! −χ ∂T/∂r(R₁) = Q(φ). The solution
//!
//! T(r, φ) = T₀ + Θ₀ã₀(r) + Σ_{k=1}^{N}[Θ_k cos kφ + Θ*_k sin kφ] ã_k(r),
//! ã₀(r) = (R₁/χ) ln(R₃/r), ã_k(r) = −(R₃/k)·((r/R₃)^k − (R₃/r)^k)/(χ[(R₁/R₃)^{k−1} + (R₃/R₁)^{k+1}]),
//!
//! (4.30; flag F-74 on (4.26)/(4.27)) is evaluated at the bore r = R₁, where with ρ = R₁/R₃ it
//! reduces to ã_k(R₁) = (R₁/(kχ))(1 − ρ^{2k})/(1 + ρ^{2k}) (stable for large k). The film
//! temperature is taken equal to the bore temperature (the seed's model). The heat flux is the
//! dimensional (4.16), Q = S|∇p|² + μV²/Γ(h) (flag F-76: the seed's normalised (4.35) has
//! inconsistent factors; the dimensional form is used).

use crate::error::{Result, positive};

/// Bush conduction model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalModel {
    /// Thermal conductivity χ of liner and housing, W/(m·K).
    pub conductivity: f64,
    /// Temperature T₀ of the housing outer surface R₃, K.
    pub ambient_temperature: f64,
    /// Housing outer radius R₃, m.
    pub outer_radius: f64,
    /// Number of Fourier harmonics N_F.
    pub harmonics: usize,
}

impl ThermalModel {
    /// Checks the inputs against the bore radius R₁.
    pub fn validate(&self, bore_radius: f64) -> Result<()> {
        positive("thermal conductivity", self.conductivity)?;
        positive("ambient temperature", self.ambient_temperature)?;
        positive("housing outer radius", self.outer_radius - bore_radius)?;
        Ok(())
    }

    /// Bore response factors ã_k(R₁), k = 0..=N, K per (W/m²).
    pub fn response(&self, r1: f64) -> Vec<f64> {
        let chi = self.conductivity;
        let rho = r1 / self.outer_radius;
        let mut out = Vec::with_capacity(self.harmonics + 1);
        out.push(r1 / chi * (self.outer_radius / r1).ln());
        for k in 1..=self.harmonics {
            let r2k = rho.powi(2 * k as i32);
            out.push(r1 / (k as f64 * chi) * (1.0 - r2k) / (1.0 + r2k));
        }
        out
    }

    /// Bore temperature T(R₁, φᵢ) for a heat flux `q` (W/m²) sampled on a uniform periodic grid
    /// φᵢ = i·2π/n (discrete Fourier sums (4.33)–(4.34)).
    pub fn bore_temperature(&self, response: &[f64], q: &[f64], out: &mut [f64]) {
        let n = q.len();
        let h = std::f64::consts::TAU / n as f64;
        let theta0: f64 = q.iter().sum::<f64>() * h / std::f64::consts::TAU;
        for v in out.iter_mut() {
            *v = self.ambient_temperature + theta0 * response[0];
        }
        for (k, &ak) in response.iter().enumerate().skip(1) {
            let (mut a, mut b) = (0.0, 0.0);
            for (i, &qi) in q.iter().enumerate() {
                let (s, c) = (k as f64 * i as f64 * h).sin_cos();
                a += qi * c;
                b += qi * s;
            }
            a *= h / std::f64::consts::PI;
            b *= h / std::f64::consts::PI;
            for (i, v) in out.iter_mut().enumerate() {
                let (s, c) = (k as f64 * i as f64 * h).sin_cos();
                *v += ak * (a * c + b * s);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form satisfies the conduction problem: a uniform flux q gives the 1-D radial
    /// solution T(R₁) − T₀ = q R₁ ln(R₃/R₁)/χ; a cos φ flux gives harmonic 1 with the amplitude of
    /// the exact a r + b/r solution (derived check of (4.30)).
    #[test]
    fn fourier_model_matches_exact_harmonics() {
        let m = ThermalModel {
            conductivity: 50.0,
            ambient_temperature: 300.0,
            outer_radius: 0.1,
            harmonics: 8,
        };
        let r1 = 0.03;
        let resp = m.response(r1);
        let n = 64;
        let q: Vec<f64> = (0..n)
            .map(|i| 1000.0 + 500.0 * (std::f64::consts::TAU * i as f64 / n as f64).cos())
            .collect();
        let mut t = vec![0.0; n];
        m.bore_temperature(&resp, &q, &mut t);
        let mean = 1000.0 * r1 * (0.1f64 / r1).ln() / 50.0;
        // harmonic 1: T = a r + b/r, T(R3) = 0, −χ T'(R1) = 500
        let r3 = 0.1;
        let a = -500.0 / (50.0 * (1.0 + r3 * r3 / (r1 * r1)));
        let b = -a * r3 * r3;
        let amp = a * r1 + b / r1;
        assert!((t[0] - 300.0 - mean - amp).abs() < 1e-9 * (mean + amp));
        assert!((t[n / 2] - 300.0 - mean + amp).abs() < 1e-9 * (mean + amp));
    }
}
