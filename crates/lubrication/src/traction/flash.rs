//! seed 001 friction model: asperity-contact fraction + Newtonian film shear + Blok flash-temperature
//! iteration (SPEC §4.9; symbols mapped per F-36).
//!
//! * film h₀: seed 001 formula with K_p ([`crate::film::seed001_film`]) at the contact temperature t_c;
//! * Λ (Tallian) = h₀/√(Ra_w² + Ra₁²);
//! * asperity-contact fraction η = 0.25 − Φ(Λ)/2, Φ = Laplace function (F-37; η ∈ [0, 0.25]);
//! * f = f_мет η + f_см (1 − η), f_мет by [`BoundaryFriction`] (value "from Kragelsky", F-43:
//!   default (2.10));
//! * f_см = W Δl/F, W = 2μ0 U_S J/h₀ ± p₀h₀, J = b_m Φ(x_a) e^{αp₀} √(π/(αp₀)), x_a = √(2αp₀),
//!   p₀ = p_max. The sliding part 2μ0U_SJ/h₀ is the Newtonian Couette shear with Barus viscosity over
//!   the Hertz pressure (F-37). The rolling term ±p₀h₀ (F-40, meaning unexplained in the seed) does
//!   not vanish with slip; it is returned separately ([`Seed001Result::rolling_term_n_per_m`]) and is
//!   added to f only if [`Seed001Settings::include_rolling_term`] (sign "+" = surface 1, the faster one
//!   for v > 0);
//! * Blok: Δt = 0.83 f (F/Δl) U_S / (√b_m (√(λ₁γ₁c₁V₁) + √(λ₂γ₂c₂V₂))), t_c = t_n + ⅔Δt, iterated to
//!   convergence. The fixed point is found by a bracketed Illinois (regula falsi) iteration on
//!   F(t) = t − t_n − ⅔Δt(t) in [t_n, t_n + ⅔Δt(t_n)] (Δt decreases with t), which is robust where
//!   plain substitution may oscillate.
//!
//! The Newtonian shear with e^{αp₀} is the seed's model and gives very large f at high αp₀ (≳ 15);
//! the model is meant for the lightly loaded intershaft rollers of seed 001.

use crate::film::{Seed001FilmOptions, seed001_film};
use crate::lubricant::{Lubricant, SolidThermal};
pub use crate::special::laplace_phi;

use super::boundary::BoundaryFriction;

/// Settings of the seed 001 model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seed001Settings {
    /// asperity friction f_мет (default Kragelsky (2.10), F-43)
    pub asperity: BoundaryFriction,
    /// thermal properties of surface 1 (the one moving at u + v/2) and surface 2 (λ, γ, c)
    pub solids: [SolidThermal; 2],
    /// film formula switches (F-38, F-39)
    pub film: Seed001FilmOptions,
    /// run the Blok flash-temperature iteration (default true)
    pub thermal_iteration: bool,
    /// temperature tolerance, K (default 0.01)
    pub tolerance_k: f64,
    /// maximum iterations (default 50)
    pub max_iterations: u32,
    /// add the rolling term p₀h₀/(F/Δl) to f (default false, see module docs)
    pub include_rolling_term: bool,
}

impl Default for Seed001Settings {
    fn default() -> Self {
        Seed001Settings {
            asperity: BoundaryFriction::Kragelsky,
            solids: [SolidThermal::STEEL; 2],
            film: Seed001FilmOptions::default(),
            thermal_iteration: true,
            tolerance_k: 0.01,
            max_iterations: 50,
            include_rolling_term: false,
        }
    }
}

/// Inputs of [`seed001_friction`] (SI, line contact).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seed001Inputs {
    /// normal force F, N
    pub normal_force: f64,
    /// contact length Δl, m
    pub length: f64,
    /// reduced radius R_пр, m
    pub reduced_radius: f64,
    /// reduced modulus E_пр (= E' of (1.13), F-39), Pa
    pub reduced_modulus: f64,
    /// half-width b_m, m
    pub half_width: f64,
    /// maximum Hertz pressure p₀, Pa
    pub max_pressure: f64,
    /// rolling speed u = (V₁ + V₂)/2, m/s
    pub rolling_speed: f64,
    /// sliding speed U_S = V₁ − V₂ (signed), m/s
    pub sliding_speed: f64,
    /// ring (bulk) temperature t_n, K
    pub ring_temperature: f64,
    /// Ra of roller and ring, m
    pub roughness: [f64; 2],
}

/// Result of [`seed001_friction`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Seed001Result {
    /// friction coefficient f ≥ 0 (magnitude)
    pub f: f64,
    /// asperity friction f_мет
    pub f_asperity: f64,
    /// film shear friction f_см (sliding part)
    pub f_film: f64,
    /// asperity contact fraction η
    pub asperity_fraction: f64,
    /// Tallian Λ
    pub lambda: f64,
    /// film h₀, m
    pub film: f64,
    /// thermal factor K_p
    pub kp: f64,
    /// flash temperature rise Δt, K
    pub flash_rise_k: f64,
    /// converged contact oil temperature t_c, K
    pub contact_temperature_k: f64,
    /// rolling term p₀h₀ of W, N/m (magnitude)
    pub rolling_term_n_per_m: f64,
    /// iterations used
    pub iterations: u32,
    /// false if the iteration did not reach the tolerance
    pub converged: bool,
    /// the property temperature had to be clamped to the oil's range
    pub temperature_clamped: bool,
}

/// Evaluate the model at a given contact temperature (no iteration). Returns (result, Δt).
fn evaluate(inp: &Seed001Inputs, oil: &Lubricant, st: &Seed001Settings, t_c: f64) -> Seed001Result {
    let tp = oil.clamp_temperature(t_c);
    let eta0 = oil.dynamic_viscosity(tp).unwrap_or(f64::NAN);
    let alpha = oil.pressure_viscosity(tp).unwrap_or(f64::NAN);
    let beta = oil.beta0(tp).unwrap_or(f64::NAN);
    let kf = oil.thermal_conductivity(tp).unwrap_or(f64::NAN);
    let u = inp.rolling_speed.abs();
    let us = inp.sliding_speed.abs();
    let q_l = inp.normal_force / inp.length;
    let (h0, kp) = seed001_film(
        eta0,
        alpha,
        beta,
        kf,
        u,
        q_l,
        inp.reduced_modulus,
        inp.reduced_radius,
        st.film,
    );
    let h0 = h0.max(1e-9);
    let lambda = crate::regime::tallian_lambda(h0, inp.roughness[0], inp.roughness[1]);
    let eta = 0.25 - laplace_phi(lambda) / 2.0;
    let ap = alpha * inp.max_pressure;
    let j = if ap > 1e-8 {
        inp.half_width
            * laplace_phi((2.0 * ap).sqrt())
            * ap.exp()
            * (std::f64::consts::PI / ap).sqrt()
    } else {
        inp.half_width
    };
    let w_slide = 2.0 * eta0 * us * j / h0;
    let rolling = inp.max_pressure * h0;
    let f_film = w_slide / q_l
        + if st.include_rolling_term {
            rolling / q_l
        } else {
            0.0
        };
    let s = us / u.max(1e-3);
    let f_asp = st.asperity.eval(s);
    let f = f_asp * eta + f_film * (1.0 - eta);
    // Blok flash temperature
    let v1 = (u + 0.5 * inp.sliding_speed).abs();
    let v2 = (u - 0.5 * inp.sliding_speed).abs();
    let den = inp.half_width.sqrt()
        * ((st.solids[0].krc() * v1).sqrt() + (st.solids[1].krc() * v2).sqrt());
    let dt = if den > 0.0 {
        0.83 * f * q_l * us / den
    } else {
        0.0
    };
    Seed001Result {
        f,
        f_asperity: f_asp,
        f_film,
        asperity_fraction: eta,
        lambda,
        film: h0,
        kp,
        flash_rise_k: dt,
        contact_temperature_k: t_c,
        rolling_term_n_per_m: rolling,
        iterations: 0,
        converged: true,
        temperature_clamped: tp != t_c,
    }
}

/// seed 001 friction coefficient with the Blok flash-temperature iteration (see module docs).
pub fn seed001_friction(
    inp: &Seed001Inputs,
    oil: &Lubricant,
    st: &Seed001Settings,
) -> Seed001Result {
    let tn = inp.ring_temperature;
    let r0 = evaluate(inp, oil, st, tn);
    if !st.thermal_iteration || r0.flash_rise_k <= 1e-9 {
        return r0;
    }
    // F(t) = t − t_n − ⅔Δt(t): F(t_n) < 0, F(t_n + ⅔Δt(t_n)) ≥ 0 when Δt decreases with t.
    let g = |r: &Seed001Result, t: f64| t - tn - 2.0 / 3.0 * r.flash_rise_k;
    let (mut a, mut fa) = (tn, g(&r0, tn));
    let mut b = tn + 2.0 / 3.0 * r0.flash_rise_k;
    let mut rb = evaluate(inp, oil, st, b);
    let mut fb = g(&rb, b);
    let mut it = 1;
    // expand if Δt is not monotone
    while fb < 0.0 && it < st.max_iterations {
        a = b;
        fa = fb;
        b = tn + 2.0 / 3.0 * rb.flash_rise_k + (b - tn);
        rb = evaluate(inp, oil, st, b);
        fb = g(&rb, b);
        it += 1;
    }
    let mut side = 0i8;
    let mut best = rb;
    let mut converged = false;
    while it < st.max_iterations {
        let c = (a * fb - b * fa) / (fb - fa);
        let rc = evaluate(inp, oil, st, c);
        let fc = g(&rc, c);
        it += 1;
        best = rc;
        if fc.abs() < st.tolerance_k || (b - a).abs() < st.tolerance_k {
            converged = true;
            break;
        }
        if fc * fb > 0.0 {
            b = c;
            fb = fc;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    best.iterations = it;
    best.converged = converged;
    best
}
