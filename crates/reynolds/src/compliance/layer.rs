//! Finite-thickness elastic layer (plate) bonded to a rigid base, plane strain (SPEC §8.3,
//! "finite-thickness plate/roller compliance"; the seed identifies this kernel from an FE plate
//! model, §3.4 / V-31 — here it is computed from elasticity).
//!
//! Airy stress function φ = cos(kx)·[(A + Bz) cosh kz + (C + Dz) sinh kz] in the layer
//! 0 ≤ z ≤ H (z into the layer), normal pressure cos(kx) and no shear on z = 0, u = 0 at z = H.
//! The surface normal displacement is ū(k) = 2(1−ν²)/(E|k|)·F(kH), F → 1 for a half-space
//! (kH → ∞) and F → kH(1−2ν)/(2(1−ν)²) for a thin layer (the Winkler value H(1+ν)(1−2ν)/(E(1−ν)),
//! seed 002 (2.2)). The spatial kernel is the inverse cosine transform
//!
//! K(x) = (2(1−ν²)/(πE))·[½ ln(1 + s₀²/x²) + ∫₀^∞ R(k) cos kx dk],
//! R(k) = (F(kH) − 1 + e^{−k s₀})/k, s₀ = H(1−2ν)/(2(1−ν)²),
//!
//! where the subtracted term has the known transform ½ ln(1 + s₀²/x²) and makes R smooth and
//! exponentially decaying. The smooth part is tabulated once (and its antiderivative, for exact
//! cell integrals of the log part).

use super::{LineKernel, gauss_panels};

/// Elastic layer of thickness H bonded to a rigid base.
#[derive(Debug, Clone)]
pub struct ElasticLayer {
    /// Layer thickness H, m.
    pub thickness: f64,
    /// Young's modulus, Pa.
    pub e: f64,
    /// Poisson ratio.
    pub nu: f64,
    s0: f64,
    dx: f64,
    /// ∫₀^∞ R(k) cos(kx) dk at x = m·dx.
    ic: Vec<f64>,
    /// ∫₀^∞ R(k) sin(kx)/k dk at x = m·dx.
    is: Vec<f64>,
}

/// Transfer function F(t), t = kH, of the bonded layer (ratio of its surface displacement to
/// the half-space one for a cosine load).
pub fn bonded_layer_transfer(t: f64, nu: f64) -> f64 {
    if t > 40.0 {
        return 1.0;
    }
    let kap = nu / (1.0 - nu);
    // all hyperbolic terms divided by cosh t (the system is homogeneous in that scale)
    let (c, s) = (1.0, t.tanh());
    // E3: f'' + κ f = 0 ; E4: (2−ν) f' − (1−ν) f''' = 0, unknowns C, D (A = 1, B = −C)
    let e3_0 = c + kap * c;
    let e3_c = (-s - t * c) + kap * (s - t * c);
    let e3_d = (2.0 * c + t * s) + kap * t * s;
    let e4_0 = (2.0 - nu) * s - (1.0 - nu) * s;
    let e4_c = (2.0 - nu) * (-t * s) - (1.0 - nu) * (-2.0 * c - t * s);
    let e4_d = (2.0 - nu) * (s + t * c) - (1.0 - nu) * (3.0 * s + t * c);
    let det = e3_c * e4_d - e3_d * e4_c;
    let cc = (-e3_0 * e4_d + e3_d * e4_0) / det;
    -cc
}

impl ElasticLayer {
    /// Builds the kernel tables (≈ 0.4 M sine evaluations).
    pub fn bonded(thickness: f64, e: f64, nu: f64) -> Self {
        let h = thickness;
        let s0 = h * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu));
        let r = |k: f64| {
            if k * h < 1e-6 {
                // R(k) ≈ k·(F''(0)H²/2 − s0²/2); take the small linear term numerically
                let k2 = 1e-6 / h;
                return k / k2
                    * ((bonded_layer_transfer(k2 * h, nu) - 1.0 + (-k2 * s0).exp()) / k2);
            }
            (bonded_layer_transfer(k * h, nu) - 1.0 + (-k * s0).exp()) / k
        };
        let dx = h / 50.0;
        let nx = 8 * 50 + 1;
        let kmax = 40.0 / s0.min(h);
        // quadrature nodes in k: panels of width ≤ π/(2 x_max) per oscillation, 8 points each
        let xmax = dx * (nx - 1) as f64;
        let panels = ((kmax * xmax / std::f64::consts::PI) * 2.0)
            .ceil()
            .max(64.0) as usize;
        let mut nodes = Vec::new();
        let hp = kmax / panels as f64;
        const X: [f64; 4] = [
            0.183_434_642_495_649_8,
            0.525_532_409_916_329,
            0.796_666_477_413_626_7,
            0.960_289_856_497_536_3,
        ];
        const W: [f64; 4] = [
            0.362_683_783_378_362,
            0.313_706_645_877_887_3,
            0.222_381_034_453_374_5,
            0.101_228_536_290_376_3,
        ];
        for p in 0..panels {
            let c = (p as f64 + 0.5) * hp;
            for k in 0..4 {
                for sgn in [-1.0, 1.0] {
                    let kk = c + sgn * 0.5 * hp * X[k];
                    nodes.push((kk, W[k] * 0.5 * hp * r(kk)));
                }
            }
        }
        let mut ic = Vec::with_capacity(nx);
        let mut is = Vec::with_capacity(nx);
        for m in 0..nx {
            let x = m as f64 * dx;
            let (mut a, mut b) = (0.0, 0.0);
            for &(k, w) in &nodes {
                let (sn, cs) = (k * x).sin_cos();
                a += w * cs;
                b += w * if k > 0.0 { sn / k } else { x };
            }
            ic.push(a);
            is.push(b);
        }
        Self {
            thickness,
            e,
            nu,
            s0,
            dx,
            ic,
            is,
        }
    }

    fn c0(&self) -> f64 {
        2.0 * (1.0 - self.nu * self.nu) / (std::f64::consts::PI * self.e)
    }

    /// Cubic (Catmull–Rom) interpolation of a table at |x| (clamped to the last value).
    fn interp(table: &[f64], dx: f64, x: f64) -> f64 {
        let t = x / dx;
        let n = table.len();
        if t >= (n - 2) as f64 {
            return table[n - 1];
        }
        let i = t.floor() as usize;
        let f = t - i as f64;
        let p0 = if i > 0 {
            table[i - 1]
        } else {
            2.0 * table[0] - table[1]
        };
        let (p1, p2, p3) = (table[i], table[i + 1], table[(i + 2).min(n - 1)]);
        p1 + 0.5
            * f
            * (p2 - p0
                + f * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + f * (3.0 * (p1 - p2) + p3 - p0)))
    }

    /// Antiderivative ∫₀ˣ K(u) du (odd in x).
    pub fn antiderivative(&self, x: f64) -> f64 {
        if x == 0.0 {
            return 0.0;
        }
        // beyond the table (8 H) the bonded layer's kernel has decayed (exponentially): K ≈ 0 and
        // the antiderivative is constant
        let ax = x.abs().min(self.dx * (self.is.len() - 1) as f64);
        let s0 = self.s0;
        let a = 0.5 * (ax * (1.0 + s0 * s0 / (ax * ax)).ln() + 2.0 * s0 * (ax / s0).atan());
        let i_s = Self::interp(&self.is, self.dx, ax);
        x.signum() * self.c0() * (a + i_s)
    }
}

impl LineKernel for ElasticLayer {
    fn value(&self, u: f64) -> f64 {
        let ax = u.abs().max(1e-300);
        if ax > self.dx * (self.ic.len() - 1) as f64 {
            return 0.0;
        }
        let ic = Self::interp(&self.ic, self.dx, ax);
        self.c0() * (0.5 * (1.0 + self.s0 * self.s0 / (ax * ax)).ln() + ic)
    }

    fn integral(&self, u0: f64, u1: f64) -> f64 {
        self.antiderivative(u1) - self.antiderivative(u0)
    }
}

/// Numerical check helper: ∫₀^∞ of a function by the same panels (used in tests).
#[doc(hidden)]
pub fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    gauss_panels(f, a, b, 200)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compliance::half_space::HalfSpace;

    #[test]
    fn transfer_limits() {
        let nu = 0.3;
        assert!((bonded_layer_transfer(30.0, nu) - 1.0).abs() < 1e-9);
        let t = 1e-3;
        let thin = t * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu));
        assert!((bonded_layer_transfer(t, nu) - thin).abs() < 1e-3 * thin);
    }

    #[test]
    fn layer_kernel_behaves() {
        let lay = ElasticLayer::bonded(0.05, 2.1e11, 0.3);
        // near the load the layer looks like a half-space: K(x1) − K(x2) = (2(1−ν²)/πE) ln(x2/x1)
        let hs = HalfSpace::new(2.1e11, 0.3, 1.0);
        let (x1, x2) = (1e-5, 1e-4);
        let dl = lay.value(x1) - lay.value(x2);
        let dh = hs.value(x1) - hs.value(x2);
        assert!((dl - dh).abs() < 1e-3 * dh, "{dl} {dh}");
        // antiderivative consistent with the value (central difference)
        let x = 0.013;
        let d = (lay.antiderivative(x + 1e-6) - lay.antiderivative(x - 1e-6)) / 2e-6;
        assert!(
            (d - lay.value(x)).abs() < 1e-4 * lay.value(x).abs(),
            "{d} {}",
            lay.value(x)
        );
        // a uniform pressure over a width ≫ H gives the Winkler deflection H(1+ν)(1−2ν)/(E(1−ν))
        let w = lay.integral(-2.0, 2.0);
        let winkler = 0.05 * 1.3 * 0.4 / (2.1e11 * 0.7);
        assert!((w - winkler).abs() < 2e-3 * winkler, "{w} {winkler}");
    }
}
