//! Film-thickness formulas (SPEC §4.7) and the combined [`film_thickness`] function.
//!
//! Symbols: η0 = viscosity at the oil temperature and atmospheric pressure (Pa·s), ᾱ = Barus
//! coefficient (1/Pa), u = rolling (entrainment) speed (m/s), Q = normal force (N), l = working
//! length (m), E' = reduced modulus of (1.13) (Pa), R' = R_x reduced radius (m), k = ellipticity.
//! The seed's thermal factor e^{−βξ} of (2.12) is taken as 1 (F-29: η0 is already evaluated at the
//! contact temperature).

use crate::contact_state::{ContactState, HertzContact};
use crate::error::LubError;
use crate::lubricant::Lubricant;
use crate::regime::{self, LambdaDefinition, LubricationRegime};
use rolldyn_numerics::fastmath;

/// Film reduction for grease starvation: −30 % (seed 000 §3.2.1 citing Larsson).
pub const GREASE_STARVATION_FACTOR: f64 = 0.7;

/// Which film formula to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FilmFormula {
    /// SPEC §4.7 proposal: (2.17) for line contacts (as seed 000 does for cylindrical-bearing raceway and
    /// cage contacts), (2.19) for point contacts. Default.
    #[default]
    Auto,
    /// Rigid–piezoviscous line contact, Houpert, seed 000 (2.17) with A of (2.13).
    RigidPiezoviscousLine,
    /// Piezoviscous–elastic (EHL) point contact, seed 000 (2.19), Hamrock–Dowson minimum film in the
    /// (g_V, g_E) form; validity (2.20) reported.
    PiezoviscousElasticPoint,
    /// seed 001 formula with the thermal reduction factor K_p (line contacts).
    Seed001,
    /// Pan–Hamrock line contact, central and minimum (standard form, not in the seeds).
    PanHamrockLine,
    /// Hamrock–Dowson point contact, central and minimum (standard form, not in the seeds).
    HamrockDowsonPoint,
}

impl FilmFormula {
    /// Human-readable formula name with its source.
    pub fn name(self) -> &'static str {
        match self {
            FilmFormula::Auto => "auto",
            FilmFormula::RigidPiezoviscousLine => {
                "rigid-piezoviscous line, Houpert, seed 000 eq. (2.17)"
            }
            FilmFormula::PiezoviscousElasticPoint => {
                "piezoviscous-elastic point, seed 000 eq. (2.19)"
            }
            FilmFormula::Seed001 => "seed 001 EHL line formula with thermal factor K_p",
            FilmFormula::PanHamrockLine => "Pan-Hamrock line contact (standard form)",
            FilmFormula::HamrockDowsonPoint => "Hamrock-Dowson point contact (standard form)",
        }
    }

    fn is_line_only(self) -> bool {
        matches!(
            self,
            FilmFormula::RigidPiezoviscousLine | FilmFormula::Seed001 | FilmFormula::PanHamrockLine
        )
    }

    fn is_point_only(self) -> bool {
        matches!(
            self,
            FilmFormula::PiezoviscousElasticPoint | FilmFormula::HamrockDowsonPoint
        )
    }
}

/// Switches of the seed 001 film formula (F-38, F-39).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Seed001FilmOptions {
    /// U_Σ = v₁ + v₂ = 2u (F-39 proposal, default `true`); `false`: U_Σ = u.
    pub u_sigma_is_sum: bool,
    /// P_T = μ0 β U_Σ² / λ_c (F-38 proposal, dimensionless; default `true`); `false`: printed μ0β/λ_c.
    pub pt_dimensionless: bool,
    /// Clamp K_p ≥ 1 (a thermal *reduction* factor cannot thicken the film; the printed fit gives
    /// K_p < 1 when its log argument is < 1, i.e. at low speed). Default `true`; not in the seeds.
    pub kp_at_least_one: bool,
}

impl Default for Seed001FilmOptions {
    fn default() -> Self {
        Seed001FilmOptions {
            u_sigma_is_sum: true,
            pt_dimensionless: true,
            kp_at_least_one: true,
        }
    }
}

/// Film settings of a traction model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmSettings {
    /// formula
    pub formula: FilmFormula,
    /// multiplicative inlet-starvation factor on both films (1 = fully flooded;
    /// [`GREASE_STARVATION_FACTOR`] = 0.7 for grease)
    pub starvation_factor: f64,
    /// seed 001 switches
    pub seed001: Seed001FilmOptions,
}

impl Default for FilmSettings {
    fn default() -> Self {
        FilmSettings {
            formula: FilmFormula::Auto,
            starvation_factor: 1.0,
            seed001: Seed001FilmOptions::default(),
        }
    }
}

/// Result of [`film_thickness`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmResult {
    /// central film thickness h_c, m (formulas giving a single value report it as both)
    pub central_m: f64,
    /// minimum film thickness h_min, m
    pub minimum_m: f64,
    /// film parameter Λ from the minimum film and the requested definition
    pub lambda: f64,
    /// formula actually used (never `Auto`)
    pub formula: FilmFormula,
    /// lubrication regime the formula assumes
    pub regime: LubricationRegime,
    /// (2.20) piezoviscous-elastic condition (point contacts)
    pub pve_condition: Option<bool>,
    /// G₁ of (1.10) (line contacts)
    pub g1: Option<f64>,
    /// G₂ of (1.11) (line contacts)
    pub g2: Option<f64>,
    /// thermal factor K_p of the seed 001 formula
    pub thermal_factor_kp: Option<f64>,
}

impl FilmResult {
    /// Name of the formula used.
    pub fn formula_name(&self) -> &'static str {
        self.formula.name()
    }
}

/// Dimensionless piezoviscous parameter A of seed 000 (2.13): A = 1.89 U Ḡ (4.9 U / W_LC)^−1.5.
#[inline]
pub fn houpert_a(u_dim: f64, g: f64, w_lc: f64) -> f64 {
    let x = 4.9 * u_dim / w_lc;
    1.89 * u_dim * g / (x * x.sqrt())
}

/// Rigid–piezoviscous line-contact film, seed 000 (2.17):
/// h = 4.9 (A/(1 − e^{−A}))^{2/3} (U/W_LC) R', U = η0 u/(E'R') (2.12), W_LC = Q/(E'R'l) (2.18),
/// Ḡ = ᾱE' (2.14). A → 0 gives the rigid–isoviscous Martin film 4.9 U R'/W_LC; u ≤ 0 gives 0.
///
/// Branch-free (both sides of each choice are computed, then one is selected), so that
/// [`rigid_piezoviscous_line_many`] vectorises a loop of it and gives the same bits as this
/// function. Accuracy: a few ulp against the closed form with `expm1` and `cbrt`.
#[inline(always)]
pub fn rigid_piezoviscous_line(
    eta0: f64,
    alpha: f64,
    u: f64,
    q: f64,
    l: f64,
    e: f64,
    r: f64,
) -> f64 {
    let u_dim = eta0 * u / (e * r);
    let w = q / (e * r * l);
    let f = piezoviscous_factor(houpert_a(u_dim, alpha * e, w));
    let h = 4.9 * fastmath::exp((2.0 / 3.0) * fastmath::ln(f)) * u_dim / w * r;
    if u > 0.0 { h } else { 0.0 }
}

/// A/(1 − e^{−A}) of seed 000 (2.17), A ≥ 0, branch-free: below A = 0.1 its Bernoulli series
/// 1 + A/2 + A²/12 − A⁴/720 + A⁶/30240 (next term A⁸/1209600 < 1e-14), above it the closed
/// form, whose cancellation in 1 − e^{−A} costs < 3e-15 there.
#[inline(always)]
fn piezoviscous_factor(a: f64) -> f64 {
    let a2 = a * a;
    let series = 1.0 + a * (0.5 + a * (1.0 / 12.0 + a2 * (-1.0 / 720.0 + a2 * (1.0 / 30_240.0))));
    let closed = a / (1.0 - fastmath::exp(-a.min(50.0)));
    if a < 0.1 { series } else { closed }
}

/// [`rigid_piezoviscous_line`] of many contacts: `h[i]` from the `i`-th element of each
/// input array (all at least as long as `h`), in one vectorised loop; the same bits as the
/// scalar function.
#[allow(clippy::too_many_arguments)]
pub fn rigid_piezoviscous_line_many(
    eta0: &[f64],
    alpha: &[f64],
    u: &[f64],
    q: &[f64],
    l: &[f64],
    e: &[f64],
    r: &[f64],
    h: &mut [f64],
) {
    let n = h.len();
    let (eta0, alpha, u, q) = (&eta0[..n], &alpha[..n], &u[..n], &q[..n]);
    let (l, e, r) = (&l[..n], &e[..n], &r[..n]);
    for i in 0..n {
        h[i] = rigid_piezoviscous_line(eta0[i], alpha[i], u[i], q[i], l[i], e[i], r[i]);
    }
}

/// Piezoviscous–elastic point-contact minimum film, seed 000 (2.19) with the Hamrock–Dowson
/// definitions (F-30): h = 3.42 R_x (U/W)² g_V^0.49 g_E^0.17 (1 − e^{−0.68k}), g_V = G W³/U²,
/// g_E = W^{8/3}/U², W = Q/(E'R_x²), U = η0 u/(E'R_x), G = ᾱE'. Returns (h, condition (2.20)).
pub fn piezoviscous_elastic_point(
    eta0: f64,
    alpha: f64,
    u: f64,
    q: f64,
    e: f64,
    rx: f64,
    k: f64,
) -> (f64, bool) {
    if u <= 0.0 {
        return (0.0, true);
    }
    // Evaluated in logarithms (one exp instead of three powf): with g_V = G W³/U², g_E = W^{8/3}/U²,
    // (U/W)² g_V^0.49 g_E^0.17 = G^0.49 U^0.68 W^(−2 + 1.47 + 0.17·8/3) exactly.
    let ln_u = (eta0 * u / (e * rx)).ln();
    let ln_w = (q / (e * rx * rx)).ln();
    let ln_g = (alpha * e).ln();
    let ln_gv = ln_g + 3.0 * ln_w - 2.0 * ln_u;
    let ln_ge = 8.0 / 3.0 * ln_w - 2.0 * ln_u;
    let ell = if k == 1.0 {
        ONE_MINUS_EXP_068
    } else {
        1.0 - (-0.68 * k).exp()
    };
    let h = 3.42
        * rx
        * (0.49 * ln_g + 0.68 * ln_u + (-2.0 + 1.47 + 0.17 * 8.0 / 3.0) * ln_w).exp()
        * ell;
    // (2.20) lg g_V < 1.78 + 0.95 lg g_E
    let ok = ln_gv < 1.78 * std::f64::consts::LN_10 + 0.95 * ln_ge;
    (h, ok)
}

/// 1 − e^{−0.68} (circular contact, k = 1).
const ONE_MINUS_EXP_068: f64 = 0.493_383_007_634_410_45;

/// A power-law film fit H = c W'^a U^b G^d, H = h/R_x, W' = (Q/l)/(E'R_x), U = η0 u/(E'R_x),
/// G = ᾱE'.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmFit {
    /// c
    pub coefficient: f64,
    /// a (of W')
    pub load_exponent: f64,
    /// b (of U)
    pub speed_exponent: f64,
    /// d (of G)
    pub material_exponent: f64,
}

impl FilmFit {
    /// Dimensionless film H = c W'^a U^b G^d.
    #[inline]
    pub fn film(&self, w: f64, u: f64, g: f64) -> f64 {
        self.coefficient
            * w.powf(self.load_exponent)
            * u.powf(self.speed_exponent)
            * g.powf(self.material_exponent)
    }

    /// Dimensionless load W' giving the film H (the fit inverted).
    #[inline]
    pub fn load(&self, h: f64, u: f64, g: f64) -> f64 {
        (h / (self.coefficient * u.powf(self.speed_exponent) * g.powf(self.material_exponent)))
            .powf(1.0 / self.load_exponent)
    }
}

/// Pan–Hamrock line-contact central film H_c = 2.922 W'^−0.166 U^0.692 G^0.470 (standard form,
/// not in the seeds).
pub const PAN_HAMROCK_CENTRAL: FilmFit = FilmFit {
    coefficient: 2.922,
    load_exponent: -0.166,
    speed_exponent: 0.692,
    material_exponent: 0.470,
};

/// Pan–Hamrock line-contact minimum film H_min = 1.714 W'^−0.128 U^0.694 G^0.568 (standard
/// form, not in the seeds).
pub const PAN_HAMROCK_MINIMUM: FilmFit = FilmFit {
    coefficient: 1.714,
    load_exponent: -0.128,
    speed_exponent: 0.694,
    material_exponent: 0.568,
};

/// Pan–Hamrock line contact ([`PAN_HAMROCK_CENTRAL`], [`PAN_HAMROCK_MINIMUM`]) for viscosity
/// η0, pressure–viscosity coefficient ᾱ, rolling speed u, load Q over length l, E' and R_x.
/// Returns (h_c, h_min).
pub fn pan_hamrock_line(
    eta0: f64,
    alpha: f64,
    u: f64,
    q: f64,
    l: f64,
    e: f64,
    rx: f64,
) -> (f64, f64) {
    if u <= 0.0 {
        return (0.0, 0.0);
    }
    let u_dim = eta0 * u / (e * rx);
    let w = q / (l * e * rx);
    let g = alpha * e;
    let hc = PAN_HAMROCK_CENTRAL.film(w, u_dim, g) * rx;
    let hm = PAN_HAMROCK_MINIMUM.film(w, u_dim, g) * rx;
    (hc, hm)
}

/// Hamrock–Dowson point contact (standard form, not in the seeds):
/// H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73k}), H_min = 3.63 U^0.68 G^0.49 W^−0.073
/// (1 − e^{−0.68k}), H = h/R_x, W = Q/(E'R_x²). Returns (h_c, h_min).
pub fn hamrock_dowson_point(
    eta0: f64,
    alpha: f64,
    u: f64,
    q: f64,
    e: f64,
    rx: f64,
    k: f64,
) -> (f64, f64) {
    if u <= 0.0 {
        return (0.0, 0.0);
    }
    let u_dim = eta0 * u / (e * rx);
    let w = q / (e * rx * rx);
    let g = alpha * e;
    let hc = 2.69
        * u_dim.powf(0.67)
        * g.powf(0.53)
        * w.powf(-0.067)
        * (1.0 - 0.61 * (-0.73 * k).exp())
        * rx;
    let hm =
        3.63 * u_dim.powf(0.68) * g.powf(0.49) * w.powf(-0.073) * (1.0 - (-0.68 * k).exp()) * rx;
    (hc, hm)
}

/// seed 001 film: h₀ = 1.864 P_S^0.723 P_U^0.558 P_N^0.167 R / K_p,
/// K_p = 1 + P_T^0.65 lg(0.9 P_S^0.114 P_U^0.285 P_N^0.085), P_S = μ0U_Σ/(E R), P_U = αE,
/// P_N = E R / (F/Δl), P_T = μ0 β U_Σ²/λ_c (F-38). `u` is the rolling speed u = (v₁+v₂)/2;
/// U_Σ per F-39 switch. Returns (h₀, K_p).
#[allow(clippy::too_many_arguments)]
pub fn seed001_film(
    eta0: f64,
    alpha: f64,
    beta: f64,
    k_f: f64,
    u: f64,
    q_per_length: f64,
    e: f64,
    r: f64,
    opts: Seed001FilmOptions,
) -> (f64, f64) {
    if u <= 0.0 {
        return (0.0, 1.0);
    }
    let u_sigma = if opts.u_sigma_is_sum { 2.0 * u } else { u };
    let ps = eta0 * u_sigma / (e * r);
    let pu = alpha * e;
    let pn = e * r / q_per_length;
    let pt = if opts.pt_dimensionless {
        eta0 * beta * u_sigma * u_sigma / k_f
    } else {
        eta0 * beta / k_f
    };
    let mut kp =
        1.0 + pt.powf(0.65) * (0.9 * ps.powf(0.114) * pu.powf(0.285) * pn.powf(0.085)).log10();
    if opts.kp_at_least_one {
        kp = kp.max(1.0);
    } else {
        kp = kp.max(0.05);
    }
    let h = 1.864 * ps.powf(0.723) * pu.powf(0.558) * pn.powf(0.167) * r / kp;
    (h, kp)
}

/// Inputs of the film core (properties already evaluated).
#[derive(Debug, Clone, Copy)]
pub(crate) struct FilmInputs {
    pub eta0: f64,
    pub alpha: f64,
    pub beta0: f64,
    pub k_f: f64,
    pub u: f64,
    pub q: f64,
    pub e: f64,
    pub r: f64,
}

/// Resolve `Auto` and geometry mismatches. Returns (formula, mismatch?).
#[inline]
pub(crate) fn resolve_formula(formula: FilmFormula, is_line: bool) -> (FilmFormula, bool) {
    let auto = if is_line {
        FilmFormula::RigidPiezoviscousLine
    } else {
        FilmFormula::PiezoviscousElasticPoint
    };
    match formula {
        FilmFormula::Auto => (auto, false),
        f if (is_line && f.is_point_only()) || (!is_line && f.is_line_only()) => (auto, true),
        f => (f, false),
    }
}

/// Film core: (h_c, h_min, pve condition, K_p) before starvation.
#[inline]
pub(crate) fn film_core(
    f: FilmFormula,
    inp: &FilmInputs,
    hz: &HertzContact,
    opts: Seed001FilmOptions,
) -> (f64, f64, Option<bool>, Option<f64>) {
    let FilmInputs {
        eta0,
        alpha,
        beta0,
        k_f,
        u,
        q,
        e,
        r,
    } = *inp;
    let l = hz.length_m;
    match f {
        FilmFormula::RigidPiezoviscousLine | FilmFormula::Auto => {
            let h = rigid_piezoviscous_line(eta0, alpha, u, q, l, e, r);
            (h, h, None, None)
        }
        FilmFormula::PiezoviscousElasticPoint => {
            let (h, ok) = piezoviscous_elastic_point(eta0, alpha, u, q, e, r, hz.ellipticity);
            (h, h, Some(ok), None)
        }
        FilmFormula::Seed001 => {
            let (h, kp) = seed001_film(eta0, alpha, beta0, k_f, u, q / l, e, r, opts);
            (h, h, None, Some(kp))
        }
        FilmFormula::PanHamrockLine => {
            let (hc, hm) = pan_hamrock_line(eta0, alpha, u, q, l, e, r);
            (hc, hm, None, None)
        }
        FilmFormula::HamrockDowsonPoint => {
            let (hc, hm) = hamrock_dowson_point(eta0, alpha, u, q, e, r, hz.ellipticity);
            (hc, hm, None, None)
        }
    }
}

pub(crate) fn regime_of(f: FilmFormula, pve: Option<bool>) -> LubricationRegime {
    match f {
        FilmFormula::RigidPiezoviscousLine | FilmFormula::Auto => {
            LubricationRegime::RigidPiezoviscous
        }
        _ => {
            let _ = pve;
            LubricationRegime::ElasticPiezoviscous
        }
    }
}

/// Film thickness of a contact: central and minimum film, Λ (from the minimum film), regime, formula,
/// G₁/G₂ (line contacts), (2.20) (point contacts). Oil properties at `state.temperature_k` (no clamping).
///
/// Errors: the oil lacks a property the formula needs (η0, ᾱ; β0 and K_f for seed 001); the formula
/// does not fit the geometry (line formula on a point contact or vice versa); Q ≤ 0 or u < 0.
pub fn film_thickness(
    state: &ContactState,
    oil: &Lubricant,
    settings: &FilmSettings,
    lambda_definition: LambdaDefinition,
) -> Result<FilmResult, LubError> {
    let t = state.temperature_k;
    let hz = state.hertz();
    let (f, mismatch) = resolve_formula(settings.formula, hz.is_line);
    if mismatch {
        return Err(LubError::InvalidInput(format!(
            "film formula '{}' does not apply to this contact geometry",
            settings.formula.name()
        )));
    }
    if state.normal_force_n <= 0.0 {
        return Err(LubError::InvalidInput("normal force must be > 0".into()));
    }
    let seed001 = f == FilmFormula::Seed001;
    let inp = FilmInputs {
        eta0: oil.dynamic_viscosity(t)?,
        alpha: oil.pressure_viscosity(t)?,
        beta0: if seed001 { oil.beta0(t)? } else { 0.0 },
        k_f: if seed001 {
            oil.thermal_conductivity(t)?
        } else {
            1.0
        },
        u: state.rolling_speed_m_s.abs(),
        q: state.normal_force_n,
        e: state.reduced_modulus_pa,
        r: state.reduced_radius_m,
    };
    let (hc, hm, pve, kp) = film_core(f, &inp, &hz, settings.seed001);
    let (hc, hm) = (
        hc * settings.starvation_factor,
        hm * settings.starvation_factor,
    );
    let (g1, g2) = if hz.is_line && inp.u > 0.0 {
        let l = hz.length_m;
        (
            Some(regime::g1(inp.alpha, inp.q, inp.eta0, inp.r, l, inp.u)),
            Some(regime::g2(inp.q, inp.eta0, inp.r, inp.e, l, inp.u)),
        )
    } else {
        (None, None)
    };
    Ok(FilmResult {
        central_m: hc,
        minimum_m: hm,
        lambda: lambda_definition.eval(hm, state.roughness_ra_m),
        formula: f,
        regime: regime_of(f, pve),
        pve_condition: pve,
        g1,
        g2,
        thermal_factor_kp: kp,
    })
}
