//! Load capacity W₀(h_m) and damping λ(h_m) = −∂W/∂V_y of the line contact, seed 002
//! (3.16)–(3.20) and §3.6 / §5 (SPEC §8.4 "Damping coefficient with deformation/piezoviscosity"):
//! tabulated from steady solutions at ±V_y and interpolated (monotone cubic in ln h of ln W₀ and
//! ln λ, i.e. exact for power laws such as the rigid isoviscous W₀ ∝ h⁻¹, λ ∝ h^{−3/2}).

use super::analytic;
use super::{Constraint, LineContactOptions, LubricatedLineContact, solve};
use crate::error::{Result, ReynoldsError};
use crate::viscosity::Viscosity;

/// Tabulated W₀(h), λ(h) and p_max(h) per unit length.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDampingTable {
    /// Film parameter h (the seed's h_m: rigid approach), m, increasing.
    pub h: Vec<f64>,
    /// Load capacity at V_y = 0, N/m.
    pub w0: Vec<f64>,
    /// Damping λ = −∂W/∂V_y, N·s/m².
    pub lambda: Vec<f64>,
    /// Maximum pressure at V_y = 0, Pa.
    pub p_max: Vec<f64>,
    slopes: [Vec<f64>; 3],
}

/// Fritsch–Carlson monotone slopes of (x, y).
fn pchip_slopes(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    if n < 2 {
        return vec![0.0; n];
    }
    let d: Vec<f64> = (0..n - 1)
        .map(|i| (y[i + 1] - y[i]) / (x[i + 1] - x[i]))
        .collect();
    let mut m = vec![0.0; n];
    m[0] = d[0];
    m[n - 1] = d[n - 2];
    for i in 1..n - 1 {
        if d[i - 1] * d[i] <= 0.0 {
            m[i] = 0.0;
        } else {
            let (h0, h1) = (x[i] - x[i - 1], x[i + 1] - x[i]);
            let (w1, w2) = (2.0 * h1 + h0, h1 + 2.0 * h0);
            m[i] = (w1 + w2) / (w1 / d[i - 1] + w2 / d[i]);
        }
    }
    m
}

fn pchip_eval(x: &[f64], y: &[f64], m: &[f64], t: f64) -> f64 {
    let n = x.len();
    if n == 1 {
        return y[0];
    }
    if t <= x[0] {
        return y[0] + m[0] * (t - x[0]);
    }
    if t >= x[n - 1] {
        return y[n - 1] + m[n - 1] * (t - x[n - 1]);
    }
    let i = x.partition_point(|&v| v <= t).min(n - 1) - 1;
    let h = x[i + 1] - x[i];
    let s = (t - x[i]) / h;
    let (h00, h10, h01, h11) = (
        (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s),
        s * (1.0 - s) * (1.0 - s),
        s * s * (3.0 - 2.0 * s),
        s * s * (s - 1.0),
    );
    h00 * y[i] + h10 * h * m[i] + h01 * y[i + 1] + h11 * h * m[i + 1]
}

impl LoadDampingTable {
    /// Builds the table from data (h increasing, all values positive).
    pub fn from_data(h: Vec<f64>, w0: Vec<f64>, lambda: Vec<f64>, p_max: Vec<f64>) -> Result<Self> {
        let n = h.len();
        if n < 2 || w0.len() != n || lambda.len() != n || p_max.len() != n {
            return Err(ReynoldsError::InvalidInput {
                what: "load–damping table",
                reason: "needs ≥ 2 points of equal length".into(),
            });
        }
        if !h.windows(2).all(|w| w[1] > w[0]) || h[0] <= 0.0 {
            return Err(ReynoldsError::InvalidInput {
                what: "load–damping table",
                reason: "h must be positive and increasing".into(),
            });
        }
        if w0
            .iter()
            .chain(&lambda)
            .chain(&p_max)
            .any(|v| !(*v > 0.0 && v.is_finite()))
        {
            return Err(ReynoldsError::InvalidInput {
                what: "load–damping table",
                reason: "W₀, λ and p_max must be positive".into(),
            });
        }
        let lx: Vec<f64> = h.iter().map(|v| v.ln()).collect();
        let ln = |v: &Vec<f64>| v.iter().map(|a| a.ln()).collect::<Vec<f64>>();
        let slopes = [
            pchip_slopes(&lx, &ln(&w0)),
            pchip_slopes(&lx, &ln(&lambda)),
            pchip_slopes(&lx, &ln(&p_max)),
        ];
        Ok(Self {
            h,
            w0,
            lambda,
            p_max,
            slopes,
        })
    }

    /// Solves the contact at each h (as the rigid approach, seed's h_m) with the damping
    /// perturbation and tabulates W₀, λ and p_max.
    pub fn build(
        contact: &LubricatedLineContact,
        viscosity: &dyn Viscosity,
        h_values: &[f64],
        options: &LineContactOptions,
    ) -> Result<Self> {
        let mut hs = h_values.to_vec();
        hs.sort_by(|a, b| a.total_cmp(b));
        let opt = LineContactOptions {
            damping: true,
            squeeze_velocity: 0.0,
            ..*options
        };
        let (mut w, mut l, mut p) = (Vec::new(), Vec::new(), Vec::new());
        for &h in &hs {
            let r = solve(contact, viscosity, Constraint::RigidApproach(h), &opt)?;
            if !r.converged {
                return Err(ReynoldsError::NotConverged {
                    what: "load–damping table entry",
                    iterations: r.iterations,
                    residual: 0.0,
                });
            }
            w.push(r.load_per_length_n_per_m);
            l.push(r.damping_ns_per_m2);
            p.push(r.max_pressure_pa);
        }
        Self::from_data(hs, w, l, p)
    }

    /// Rigid isoviscous closed forms (3.17)–(3.20) on the given h values: W₀ = 6W₀′μVR/h,
    /// λ = 6W₁′μR^{3/2}/h^{3/2}, p_max = q_max P₀ (pass the seed's 0.401/1.125 to reproduce its
    /// transients, or [`analytic::load_coefficients`] for the exact values).
    pub fn rigid_isoviscous(
        mu: f64,
        v: f64,
        r: f64,
        w0c: f64,
        w1c: f64,
        h_values: &[f64],
    ) -> Result<Self> {
        let qm = analytic::q_max(0.0)?;
        let mut hs = h_values.to_vec();
        hs.sort_by(|a, b| a.total_cmp(b));
        let w = hs.iter().map(|h| 6.0 * w0c * mu * v * r / h).collect();
        let l = hs
            .iter()
            .map(|h| 6.0 * w1c * mu * r.powf(1.5) / h.powf(1.5))
            .collect();
        let p = hs
            .iter()
            .map(|&h| qm * analytic::pressure_scale(mu, v, r, h))
            .collect();
        Self::from_data(hs, w, l, p)
    }

    fn eval(&self, k: usize, h: f64) -> f64 {
        let lx: Vec<f64> = self.h.iter().map(|v| v.ln()).collect();
        let y: Vec<f64> = match k {
            0 => self.w0.iter().map(|v| v.ln()).collect(),
            1 => self.lambda.iter().map(|v| v.ln()).collect(),
            _ => self.p_max.iter().map(|v| v.ln()).collect(),
        };
        pchip_eval(&lx, &y, &self.slopes[k], h.max(1e-300).ln()).exp()
    }

    /// W₀(h), N/m.
    pub fn load(&self, h: f64) -> f64 {
        self.eval(0, h)
    }

    /// λ(h), N·s/m².
    pub fn damping(&self, h: f64) -> f64 {
        self.eval(1, h)
    }

    /// p_max(h) at V_y = 0, Pa.
    pub fn max_pressure(&self, h: f64) -> f64 {
        self.eval(2, h)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_laws_are_interpolated_exactly() {
        let hs = [2e-7, 5e-7, 1e-6, 3e-6];
        let t = LoadDampingTable::rigid_isoviscous(0.024, 7.0, 0.005, 0.4079, 1.0914, &hs).unwrap();
        for h in [2.5e-7f64, 7e-7, 2e-6, 5e-6] {
            let w = 6.0 * 0.4079 * 0.024 * 7.0 * 0.005 / h;
            let l = 6.0 * 1.0914 * 0.024 * 0.005f64.powf(1.5) / h.powf(1.5);
            assert!((t.load(h) / w - 1.0).abs() < 1e-12);
            assert!((t.damping(h) / l - 1.0).abs() < 1e-12);
        }
    }
}
