//! Film parameter Λ, regime parameters and regime enums (SPEC §4.3, §4.7).

/// Friction regime selected by the film parameter (1.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FrictionRegime {
    /// Λ < Λ_bd: boundary friction μ_bd
    Boundary,
    /// Λ_bd ≤ Λ < Λ_hd: blend (1.3)
    Mixed,
    /// Λ ≥ Λ_hd: hydrodynamic (EHL) friction μ_hd
    #[default]
    Hydrodynamic,
}

/// Lubrication regime assumed by a film formula (Johnson / Hamrock–Dowson classification, seed 000 §1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LubricationRegime {
    /// (I) rigid–isoviscous
    RigidIsoviscous,
    /// (II) rigid–piezoviscous ((2.17))
    RigidPiezoviscous,
    /// (III) elastic–isoviscous
    ElasticIsoviscous,
    /// (IV) elastic–piezoviscous / EHL ((2.19), Pan–Hamrock, Hamrock–Dowson, seed 001)
    ElasticPiezoviscous,
}

/// Which film-parameter definition to use (F-44: each within its own model).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LambdaDefinition {
    /// seed 000 (1.2): Λ = h / (1.25 √(Ra₁² + Ra₂²)). Default.
    #[default]
    Seed000,
    /// seed 001 Tallian: Λ = h / √(Ra_w² + Ra₁²) (no factor 1.25).
    Tallian,
}

/// Film parameter Λ of seed 000 (1.2). Smooth surfaces (Ra₁ = Ra₂ = 0) give +∞.
#[inline]
pub fn film_parameter(h: f64, ra1: f64, ra2: f64) -> f64 {
    let s = (ra1 * ra1 + ra2 * ra2).sqrt();
    if s > 0.0 {
        h / (1.25 * s)
    } else {
        f64::INFINITY
    }
}

/// Tallian film parameter of seed 001: Λ = h₀ / √(Ra_w² + Ra₁²). Smooth surfaces give +∞.
#[inline]
pub fn tallian_lambda(h: f64, ra_w: f64, ra_1: f64) -> f64 {
    let s = (ra_w * ra_w + ra_1 * ra_1).sqrt();
    if s > 0.0 { h / s } else { f64::INFINITY }
}

impl LambdaDefinition {
    /// Evaluate Λ with this definition.
    #[inline]
    pub fn eval(self, h: f64, ra: [f64; 2]) -> f64 {
        match self {
            LambdaDefinition::Seed000 => film_parameter(h, ra[0], ra[1]),
            LambdaDefinition::Tallian => tallian_lambda(h, ra[0], ra[1]),
        }
    }
}

/// Regime parameter G₁ of seed 000 (1.10) (Johnson 1970): √(ᾱ² Q³ / (η₁ R'² l³ u)).
pub fn g1(alpha: f64, q: f64, eta1: f64, r: f64, l: f64, u: f64) -> f64 {
    (alpha * alpha * q.powi(3) / (eta1 * r * r * l.powi(3) * u)).sqrt()
}

/// Regime parameter G₂ of seed 000 (1.11): √(Q² / (η₁ R' E' l² u)).
pub fn g2(q: f64, eta1: f64, r: f64, e: f64, l: f64, u: f64) -> f64 {
    (q * q / (eta1 * r * e * l * l * u)).sqrt()
}

/// Piezoviscous-elastic condition seed 000 (2.20) as printed: lg g_V < 1.78 + 0.95 lg g_E
/// (direction unverifiable from the seeds, F-30).
#[inline]
pub fn pve_condition(g_v: f64, g_e: f64) -> bool {
    g_v.log10() < 1.78 + 0.95 * g_e.log10()
}
