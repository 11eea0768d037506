//! Hertz contact formulas (SPEC §2.3): line contact of a roller on a raceway, point contact
//! of a sphere on a flat and general elliptical contact (roller end ↔ rib).
//!
//! SI units throughout (m, N, Pa). Moduli follow the seed's definition (seed 000 eq. (1.13)):
//! the *reduced modulus* `E'` with `1/E' = ½[(1−ν₁²)/E₁ + (1−ν₂²)/E₂]`, i.e. `E' = 2E*` where
//! `E*` is Johnson's contact modulus (for identical steels `E' = E/(1−ν²)`).
//!
//! * Line contact: [`reduced_radius`], [`reduced_modulus`], [`line_half_width`], [`LineContact`].
//! * Point / elliptical contact: [`ContactCurvatures`], [`elliptical_contact`],
//!   [`point_contact_sphere_flat`], [`EllipticalStiffness`] (`Q = K δ^1.5`).
//! * Complete elliptic integrals by the arithmetic–geometric mean: [`elliptic_ke`].

use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt;

/// Errors of the Hertz formulas (invalid geometry or load).
#[derive(Debug, Clone, PartialEq)]
pub enum HertzError {
    /// A length, modulus or load is not finite or has the wrong sign.
    InvalidInput(&'static str),
    /// The curvature sum is not positive in both principal directions: the bodies are conforming
    /// (or concave) and Hertz theory does not apply.
    NonConvexGap,
    /// The ellipticity iteration did not converge (should not happen for valid input).
    NoConvergence,
}

impl fmt::Display for HertzError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HertzError::InvalidInput(what) => write!(f, "invalid Hertz input: {what}"),
            HertzError::NonConvexGap => write!(
                f,
                "curvature sum not positive in both principal planes: contact is conforming, Hertz theory does not apply"
            ),
            HertzError::NoConvergence => write!(f, "Hertz ellipticity iteration did not converge"),
        }
    }
}

impl std::error::Error for HertzError {}

// ---------------------------------------------------------------------------------------------
// Line contact (SPEC §2.3, seed 000 eqs. (1.12), (1.13), (2.15), (2.16))
// ---------------------------------------------------------------------------------------------

/// Which raceway the roller touches: selects the sign in seed 000 eq. (1.12).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Conformity {
    /// Inner ring: convex–convex, `1/R' = 1/R₁ + 1/R₂`.
    ConvexConvex,
    /// Outer ring: convex–concave, `1/R' = 1/R₁ − 1/R₂` (requires `R₂ > R₁`).
    ConvexConcave,
}

/// Reduced radius `R'` (seed 000 eq. (1.12)): `1/R' = 1/R₁ ± 1/R₂`, `R₁` = roller radius,
/// `R₂` = raceway radius (both positive, m); "+" for the inner ring, "−" for the outer ring.
/// Returns `+∞` for a flat (`R₂ = ∞`) counterpart handled naturally; a non-positive curvature sum
/// (outer raceway smaller than the roller) returns an error.
pub fn reduced_radius(r1: f64, r2: f64, conformity: Conformity) -> Result<f64, HertzError> {
    if !(r1 > 0.0 && r2 > 0.0) || r1.is_nan() || r2.is_nan() {
        return Err(HertzError::InvalidInput("radii must be positive"));
    }
    let k = match conformity {
        Conformity::ConvexConvex => 1.0 / r1 + 1.0 / r2,
        Conformity::ConvexConcave => 1.0 / r1 - 1.0 / r2,
    };
    if k > 0.0 {
        Ok(1.0 / k)
    } else {
        Err(HertzError::NonConvexGap)
    }
}

/// Reduced modulus `E'` (seed 000 eq. (1.13)): `1/E' = ½[(1−ν₁²)/E₁ + (1−ν₂²)/E₂]` (Pa).
/// `E' = 2E*` (Johnson's contact modulus); for identical materials `E' = E/(1−ν²)`.
pub fn reduced_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    2.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

/// Johnson's contact modulus `E* = E'/2` (Pa).
pub fn contact_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    0.5 * reduced_modulus(e1, nu1, e2, nu2)
}

/// Approach (normal compliance) model of a line contact. Two-dimensional Hertz theory gives no
/// absolute approach (it depends on where the far-field reference is taken), so an empirical
/// law is used.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LineApproachModel {
    /// Palmgren's roller–raceway law as quoted by Harris & Kotzalas ("Rolling Bearing Analysis"):
    /// `δ = 3.84·10⁻⁵ Q^0.9 / l^0.8` (δ in mm, Q in N, l in mm), valid for steel
    /// (`E = 207 GPa`, `ν = 0.3`, i.e. `E'_ref = 227.5 GPa`). Approach of **one** contact
    /// (roller ↔ one raceway). Material-independent as printed.
    PalmgrenSteel,
    /// **Default.** Palmgren's law rescaled to the actual reduced modulus,
    /// `δ = 3.84·10⁻⁵ (E'_ref/E')^0.9 Q^0.9 / l^0.8` (mm, N): the dimensionally consistent
    /// form `δ = C (Q/(E' l))^0.9 l^0.1` calibrated on steel. Chosen because it is the law on
    /// which ISO/TS 16281's lamina constant 35948 is based (same exponents 10/9, 8/9 when
    /// inverted), it needs no extra geometry (Houpert's / Teutsch–Sauer's refinements need the
    /// roller diameter and a depth datum and differ from it by a few per cent) and it is exact
    /// for steel where all seed cases live.
    #[default]
    PalmgrenScaled,
}

/// The largest maximum Hertz pressure an elastic contact of bearing materials can carry, Pa:
/// bearing steels yield near 4 GPa and ceramics fail below 10 GPa, so beyond this the elastic
/// contact does not apply. Every load of a command is refused above it (docs/model-format.md,
/// "Plausibility bounds").
pub const MAX_CREDIBLE_PRESSURE_PA: f64 = 10e9;

/// Reference reduced modulus of Palmgren's steel law: `207 GPa / (1 − 0.3²)`.
pub const PALMGREN_E_REDUCED_REF: f64 = 207.0e9 / (1.0 - 0.09);

/// Hertz line-contact **half**-width `b = 2 √(2 Q R' / (π l E')) = √(8 w R' / (π E'))` (m) for
/// the load per length w = Q/l (N/m), reduced radius R' (m) and reduced modulus E' (Pa), seed 000
/// eq. (2.16).
#[inline]
pub fn line_half_width(load_per_length: f64, reduced_radius: f64, reduced_modulus: f64) -> f64 {
    (8.0 * load_per_length * reduced_radius / (PI * reduced_modulus)).sqrt()
}

/// Hertz line contact of a cylinder (roller) on a raceway over a working length `l`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineContact {
    /// Reduced radius `R'` (m), seed 000 eq. (1.12).
    pub reduced_radius: f64,
    /// Reduced modulus `E'` (Pa), seed 000 eq. (1.13).
    pub reduced_modulus: f64,
    /// Working (contact) length `l` (m); for slice-wise evaluation use the slice length `L_s`.
    pub length: f64,
}

impl LineContact {
    /// Mean Hertz pressure `p̄ = ¼ √(π Q E' / (2 l R'))` (Pa), seed 000 eq. (2.15).
    pub fn mean_pressure(&self, q: f64) -> f64 {
        let q = q.max(0.0);
        0.25 * (PI * q * self.reduced_modulus / (2.0 * self.length * self.reduced_radius)).sqrt()
    }

    /// Maximum Hertz pressure `p_max = (4/π) p̄ = √(Q E' / (2π l R'))` (Pa), SPEC §2.3 (derived).
    pub fn max_pressure(&self, q: f64) -> f64 {
        let q = q.max(0.0);
        (q * self.reduced_modulus / (2.0 * PI * self.length * self.reduced_radius)).sqrt()
    }

    /// Contact **half**-width of the load `q` (N) over the length: [`line_half_width`].
    pub fn half_width(&self, q: f64) -> f64 {
        line_half_width(
            q.max(0.0) / self.length,
            self.reduced_radius,
            self.reduced_modulus,
        )
    }

    /// Approach of the roller with **one** raceway (m) for force `q` (N) with the chosen model
    /// (see [`LineApproachModel`]); 0 for `q ≤ 0`.
    pub fn approach(&self, q: f64, model: LineApproachModel) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        let l_mm = self.length * 1e3;
        let scale = match model {
            LineApproachModel::PalmgrenSteel => 1.0,
            LineApproachModel::PalmgrenScaled => {
                (PALMGREN_E_REDUCED_REF / self.reduced_modulus).powf(0.9)
            }
        };
        3.84e-5 * scale * q.powf(0.9) / l_mm.powf(0.8) * 1e-3
    }

    /// Inverse of [`LineContact::approach`]: force (N) for approach `delta` (m); 0 for `δ ≤ 0`.
    pub fn force_from_approach(&self, delta: f64, model: LineApproachModel) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let unit = self.approach(1.0, model); // δ(1 N)
        (delta / unit).powf(1.0 / 0.9)
    }
}

// ---------------------------------------------------------------------------------------------
// Complete elliptic integrals (AGM)
// ---------------------------------------------------------------------------------------------

/// Complete elliptic integrals by the arithmetic–geometric mean, parametrised by the
/// complementary modulus `k' = √(1−m)` (for a contact ellipse `k' = b/a`, `m = e²`).
///
/// Returns `(K(m), E(m), (K−E)/(m K))`; the last term (`S/m`) is evaluated without cancellation
/// so that `K − E` stays accurate for nearly circular contacts (`m → 0`, limit ½).
/// `k'` is clamped to `(0, 1]`; `k' → 0` gives `K → ∞`.
pub fn elliptic_ke(k_prime: f64) -> (f64, f64, f64) {
    let kp = k_prime.clamp(f64::MIN_POSITIVE, 1.0);
    let m = (1.0 - kp) * (1.0 + kp); // e² without cancellation for k' near 1
    // AGM: a₀ = 1, b₀ = k', c₀² = m; c_{n+1} = (a_n − b_n)/2 = c_n² / (4 a_{n+1}).
    // K = π / (2 AGM(1, k')),  E = K (1 − S),  S = Σ_{n≥0} 2^{n−1} c_n².
    // S/m = ½ + Σ_{n≥1} 2^{n−1} c_n²/m is accumulated from c₁²/m = (1−k')/(4(1+k')) with the
    // recurrence, so nothing cancels.
    let mut a = 1.0_f64;
    let mut b = kp;
    let mut cn2_over_m = (1.0 - kp) / (4.0 * (1.0 + kp)); // c₁²/m
    let mut cn2 = cn2_over_m * m; // c₁²
    let mut weight = 1.0_f64; // 2^{n−1}, n = 1
    let mut s_over_m = 0.5_f64;
    for _ in 0..64 {
        // (a, b) ← (a_n, b_n)
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
        s_over_m += weight * cn2_over_m;
        // c_{n+1}² = c_n⁴ / (16 a_{n+1}²)
        let a_next = 0.5 * (a + b);
        let r = cn2 / (16.0 * a_next * a_next);
        cn2 *= r;
        cn2_over_m *= r;
        weight *= 2.0;
        if (a - b).abs() <= 4.0 * f64::EPSILON * a && weight * cn2_over_m <= 1e-17 * s_over_m {
            break;
        }
    }
    let agm = 0.5 * (a + b);
    let k = FRAC_PI_2 / agm;
    let e = k * (1.0 - s_over_m * m);
    (k, e, s_over_m)
}

// ---------------------------------------------------------------------------------------------
// Elliptical (point) contact
// ---------------------------------------------------------------------------------------------

/// Principal curvatures of two bodies at the contact point (1/m; convex > 0, concave < 0,
/// flat = 0) and the angle between their principal planes.
///
/// Example (roller end sphere of radius `r_e` on a toroidal rib face with radii `r_1`, `r_2`):
/// `body1 = (1/r_e, 1/r_e)`, `body2 = (±1/r_1, ±1/r_2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactCurvatures {
    /// Principal curvatures `(κ₁ₓ, κ₁ᵧ)` of body 1 (1/m).
    pub body1: (f64, f64),
    /// Principal curvatures `(κ₂ₓ, κ₂ᵧ)` of body 2 (1/m), same orientation as body 1's when
    /// `angle = 0`.
    pub body2: (f64, f64),
    /// Angle between the principal x-planes of the two bodies (rad). Default 0.
    pub angle: f64,
}

impl ContactCurvatures {
    /// Sphere of radius `r` on a flat.
    pub fn sphere_on_flat(r: f64) -> Self {
        Self {
            body1: (1.0 / r, 1.0 / r),
            body2: (0.0, 0.0),
            angle: 0.0,
        }
    }

    /// Gap coefficients `(A, B)` with `h = A x'² + B y'²` in the principal axes of the gap,
    /// `0 < A ≤ B` (Johnson, Contact Mechanics §4.2): `A + B = ½ Σκ`,
    /// `B − A = ½ √((κ₁ₓ−κ₁ᵧ)² + (κ₂ₓ−κ₂ᵧ)² + 2(κ₁ₓ−κ₁ᵧ)(κ₂ₓ−κ₂ᵧ) cos 2ω)`.
    pub fn gap_coefficients(&self) -> Result<(f64, f64), HertzError> {
        let (k1x, k1y) = self.body1;
        let (k2x, k2y) = self.body2;
        let sum = 0.5 * (k1x + k1y + k2x + k2y);
        let d1 = k1x - k1y;
        let d2 = k2x - k2y;
        let diff = 0.5
            * (d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * (2.0 * self.angle).cos())
                .max(0.0)
                .sqrt();
        let a = 0.5 * (sum - diff);
        let b = 0.5 * (sum + diff);
        if !(a.is_finite() && b.is_finite()) {
            return Err(HertzError::InvalidInput("curvatures must be finite"));
        }
        if a <= 0.0 {
            return Err(HertzError::NonConvexGap);
        }
        Ok((a, b))
    }
}

/// Solution method for elliptical contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EllipticalMethod {
    /// **Default.** Exact Hertz solution: ellipticity from `B/A = (E/k'² − K)/(K − E)` solved by
    /// a safeguarded Newton iteration in `ln k'`, elliptic integrals by the AGM.
    #[default]
    Exact,
    /// Hamrock & Brewe (1983) closed-form approximations: `κ = a/b = α_r^{2/π}`,
    /// `E ≈ 1 + (π/2−1)/α_r`, `K ≈ π/2 + (π/2−1) ln α_r`, `α_r = B/A`. Exact for circular
    /// contact; errors of a few per cent for very elongated ellipses.
    HamrockBrewe,
}

/// Result of a Hertz elliptical contact evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticalContact {
    /// Semi-major axis `a` (m), along the direction of the smaller gap coefficient `A`.
    pub semi_major: f64,
    /// Semi-minor axis `b` (m), along the direction of `B`.
    pub semi_minor: f64,
    /// Maximum pressure `p₀ = 3Q/(2π a b)` (Pa).
    pub max_pressure: f64,
    /// Mean pressure `Q/(π a b) = ⅔ p₀` (Pa).
    pub mean_pressure: f64,
    /// Mutual approach of distant points `δ` (m).
    pub approach: f64,
    /// Ellipticity `k' = b/a ∈ (0, 1]`.
    pub ellipticity: f64,
    /// Complete elliptic integral of the first kind `K(e)` used (exact or approximated).
    pub k_integral: f64,
    /// Complete elliptic integral of the second kind `E(e)` used (exact or approximated).
    pub e_integral: f64,
}

/// Ratio `B/A` as a function of `k' = b/a` (exact Hertz, cancellation-free form):
/// `B/A = (E/k'² − K)/(K − E) = (m − S)/(k'² S)` with `S = (K−E)/K`.
fn gap_ratio_exact(kp: f64) -> f64 {
    let (_, _, s_over_m) = elliptic_ke(kp);
    // (m − S)/(k'² S) = (1 − S/m) / (k'² S/m)
    (1.0 - s_over_m) / (kp * kp * s_over_m)
}

/// Solve `B/A = ratio` (≥ 1) for `k' = b/a` by a safeguarded Newton iteration on
/// `g(u) = ln(B/A)(e^u) − ln ratio`, `u = ln k'`, with bisection fallback inside a bracket.
fn solve_ellipticity(ratio: f64) -> Result<f64, HertzError> {
    if ratio <= 1.0 + 1e-15 {
        return Ok(1.0);
    }
    let target = ratio.ln();
    let g = |u: f64| gap_ratio_exact(u.exp()).ln() - target;
    // bracket: g(0) = −target < 0, g decreasing in u; find lo with g(lo) > 0.
    let mut hi = 0.0_f64;
    let mut lo = -2.0 / PI * target - 1.0; // (B/A)^{-2/π} initial guess less a margin
    let mut g_lo = g(lo);
    let mut n = 0;
    while g_lo <= 0.0 {
        hi = lo;
        lo *= 2.0;
        g_lo = g(lo);
        n += 1;
        if n > 60 || lo < -700.0 {
            return Err(HertzError::NoConvergence);
        }
    }
    // start from the Hamrock–Brewe estimate u = −(2/π) ln ratio
    let mut u = (-2.0 / PI * target).clamp(lo, hi);
    let mut gu = g(u);
    for _ in 0..100 {
        if gu > 0.0 {
            lo = u;
        } else {
            hi = u;
        }
        // numerical derivative (central, small step in u)
        let h = 1e-6;
        let dg = (g(u + h) - g(u - h)) / (2.0 * h);
        let mut u_new = if dg < 0.0 { u - gu / dg } else { f64::NAN };
        if !(u_new > lo && u_new < hi) {
            u_new = 0.5 * (lo + hi);
        }
        let converged = (u_new - u).abs() <= 1e-14 * (1.0 + u.abs());
        u = u_new;
        gu = g(u);
        if converged || gu.abs() <= 1e-15 || (hi - lo) <= 1e-15 * (1.0 + lo.abs()) {
            return Ok(u.exp());
        }
    }
    Err(HertzError::NoConvergence)
}

/// Hertz elliptical contact for normal force `q` (N), curvature geometry and reduced modulus
/// `E'` (Pa, seed 000 eq. (1.13); `E* = E'/2`).
///
/// Exact solution (Johnson, Contact Mechanics §4.2), with `k' = b/a`, `m = e² = 1 − k'²`:
/// `a³ = 3Q (K − E) / (2π m E* A)`, `b = k' a`, `p₀ = 3Q/(2π a b)`, `δ = p₀ b K / E*`.
/// Hamrock–Brewe: see [`EllipticalMethod::HamrockBrewe`]. `q ≤ 0` gives the zero contact.
pub fn elliptical_contact(
    curv: &ContactCurvatures,
    e_reduced: f64,
    q: f64,
    method: EllipticalMethod,
) -> Result<EllipticalContact, HertzError> {
    if !(e_reduced > 0.0 && e_reduced.is_finite()) {
        return Err(HertzError::InvalidInput("reduced modulus must be positive"));
    }
    if q.is_nan() {
        return Err(HertzError::InvalidInput("force is NaN"));
    }
    let (a_coef, b_coef) = curv.gap_coefficients()?;
    let ratio = b_coef / a_coef;
    let e_star = 0.5 * e_reduced;
    let q = q.max(0.0);
    let (kp, k_int, e_int, k_minus_e_over_m) = match method {
        EllipticalMethod::Exact => {
            let kp = solve_ellipticity(ratio)?;
            let (k, e, s_over_m) = elliptic_ke(kp);
            (kp, k, e, k * s_over_m)
        }
        EllipticalMethod::HamrockBrewe => {
            let qa = FRAC_PI_2 - 1.0;
            let kp = ratio.powf(-2.0 / PI);
            let e = 1.0 + qa / ratio;
            let k = FRAC_PI_2 + qa * ratio.ln();
            let m = (1.0 - kp) * (1.0 + kp);
            // consistent with the approximated integrals; circular limit (K−E)/m → π/4
            let kme = if m > 1e-12 { (k - e) / m } else { PI / 4.0 };
            (kp, k, e, kme)
        }
    };
    let (semi_major, semi_minor, p0, delta) = match method {
        EllipticalMethod::Exact => {
            let a = (3.0 * q * k_minus_e_over_m / (2.0 * PI * e_star * a_coef)).cbrt();
            let b = kp * a;
            let p0 = if q > 0.0 {
                3.0 * q / (2.0 * PI * a * b)
            } else {
                0.0
            };
            (a, b, p0, p0 * b * k_int / e_star)
        }
        EllipticalMethod::HamrockBrewe => {
            // Hamrock–Brewe: R = 1/(2(A+B)), κ = a/b = 1/k'
            //   D_y = 2 (6 κ² E Q R / (π E'))^{1/3},  D_x = 2 (6 E Q R / (π κ E'))^{1/3}
            //   δ = K [ (9/(2 E R)) (Q/(π κ E'))² ]^{1/3}
            let r = 1.0 / (2.0 * (a_coef + b_coef));
            let kappa = 1.0 / kp;
            let a = (6.0 * kappa * kappa * e_int * q * r / (PI * e_reduced)).cbrt();
            let b = (6.0 * e_int * q * r / (PI * kappa * e_reduced)).cbrt();
            let p0 = if q > 0.0 {
                3.0 * q / (2.0 * PI * a * b)
            } else {
                0.0
            };
            let t = q / (PI * kappa * e_reduced);
            let delta = k_int * (9.0 / (2.0 * e_int * r) * t * t).cbrt();
            (a, b, p0, delta)
        }
    };
    Ok(EllipticalContact {
        semi_major,
        semi_minor,
        max_pressure: p0,
        mean_pressure: 2.0 / 3.0 * p0,
        approach: delta,
        ellipticity: kp,
        k_integral: k_int,
        e_integral: e_int,
    })
}

/// Hertz point contact of a sphere of radius `r` (m) on a flat (SPEC §2.3):
/// `a = (3QR/(4E*))^{1/3}`, `p_max = 3Q/(2π a²)`, `p̄ = ⅔ p_max`, `δ = a²/R`, `E* = E'/2`.
pub fn point_contact_sphere_flat(
    r: f64,
    e_reduced: f64,
    q: f64,
) -> Result<EllipticalContact, HertzError> {
    if !(r > 0.0 && r.is_finite() && e_reduced > 0.0 && e_reduced.is_finite()) || q.is_nan() {
        return Err(HertzError::InvalidInput(
            "sphere radius and modulus must be positive",
        ));
    }
    let q = q.max(0.0);
    let e_star = 0.5 * e_reduced;
    let a = (3.0 * q * r / (4.0 * e_star)).cbrt();
    let p0 = if q > 0.0 {
        3.0 * q / (2.0 * PI * a * a)
    } else {
        0.0
    };
    Ok(EllipticalContact {
        semi_major: a,
        semi_minor: a,
        max_pressure: p0,
        mean_pressure: 2.0 / 3.0 * p0,
        approach: a * a / r,
        ellipticity: 1.0,
        k_integral: FRAC_PI_2,
        e_integral: FRAC_PI_2,
    })
}

/// Force–approach law of an elliptical Hertz contact, `Q = K δ^{3/2}` (SPEC §3.3 roller end ↔
/// rib and other point contacts). The ellipticity is load-independent, so `K` is computed once
/// from a reference solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticalStiffness {
    /// Load–deflection constant `K` (N/m^1.5).
    pub k: f64,
}

impl EllipticalStiffness {
    /// Build from the contact geometry and reduced modulus `E'` (Pa).
    pub fn new(
        curv: &ContactCurvatures,
        e_reduced: f64,
        method: EllipticalMethod,
    ) -> Result<Self, HertzError> {
        let sol = elliptical_contact(curv, e_reduced, 1.0, method)?;
        Ok(Self {
            k: 1.0 / sol.approach.powf(1.5),
        })
    }

    /// Force `Q = K δ^{3/2}` and stiffness `dQ/dδ = 1.5 K δ^{1/2}`; both 0 for `δ ≤ 0`.
    #[inline]
    pub fn force(&self, delta: f64) -> (f64, f64) {
        if delta > 0.0 {
            let s = delta.sqrt();
            (self.k * delta * s, 1.5 * self.k * s)
        } else {
            (0.0, 0.0)
        }
    }

    /// Approach for force `q`: `δ = (Q/K)^{2/3}`; 0 for `q ≤ 0`.
    pub fn approach(&self, q: f64) -> f64 {
        if q > 0.0 {
            (q / self.k).powf(2.0 / 3.0)
        } else {
            0.0
        }
    }
}
