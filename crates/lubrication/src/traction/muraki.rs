//! Muraki's simplified thermal visco-elastic (Maxwell–Eyring) traction theory, seed 000 (1.4)–(1.9),
//! SPEC §4.5.
//!
//! μ_hd = τ0 S / p̄ (1.6), S = τ̄/τ0 (1.7) from (1.8) with
//! σ_i = η_Ni v/(τ0 h), D_i = η_Ni u/(Γ b), Φ = (β0 + κ p̄) ζ τ0² h / η_Ni,
//! ζ = 0.97 b^½/(π K_m ρ_m c_m u)^½ + h/(12 K_f) (1.9), η_Ni = η_N0 exp(ᾱ p̄) (1.5).
//!
//! ### Small shear rates and the elastic limit (F-34)
//! (1.8) uses L = ln(2σ), the large-σ form of sinh⁻¹σ, and is meaningless for σ ≲ 0.5 (L < 0).
//! Its isothermal limit S = L − D L²/(4σ) is exactly the mean stress of a fluid element that is
//! loaded elastically (slope Γγ̇) until it reaches the Eyring plateau τ0 L and then flows; this
//! holds while the plateau is reached inside the transit time (D L < 2σ). When D L ≥ 2σ the element
//! never yields and the mean stress is the linear-elastic one, S = σ/D (μ = Γ s b/(h p̄)); the two
//! branches touch with equal value and slope at D L = 2σ. Default [`SmallShearRate::Asinh`]:
//! * L = sinh⁻¹σ (identical to ln 2σ to O(σ⁻²), exact Eyring law for all σ, → 0 as σ → 0);
//! * D L < 2σ: cancellation-free form of (1.8),
//!   S = L[σ + (2σ + Φσ² − D L)/(r + 1)] / (σ(a + r)), a = 1 + Φσ, r = √(a² − DΦL)
//!   (the square-root argument is > 1 + Φ²σ² > 0 in this branch, so it never goes negative);
//! * D L ≥ 2σ: S = 2σ / (D (1 + √(1 + Φ²σ²))) — the elastic branch, equal to the thermal (1.8) at
//!   the touching point so that S is continuous for every Φ (→ σ/D when Φ → 0).
//!
//! The literal SPEC F-34 proposal (linear branch σ/D below σ_min, min(linear, Muraki) above, STEP
//! blend over [σ_min, 2σ_min], L = ln 2σ) is available as [`SmallShearRate::SpecLinearBranch`]; for
//! D ≪ 1 (the usual case, e.g. PAO1: D ≈ 5×10⁻³) it produces a large spurious spike μ ≈ Γ s b/(h p̄)
//! just below σ_min (see the test `spec_f34_literal_branch_spikes`), which is why it is not the default.

use crate::contact_state::SlicePressure;
use crate::lubricant::SolidThermal;
use crate::viscosity::{PiezoViscosity, viscosity_at_pressure};
use rolldyn_numerics::fastmath;
use rolldyn_numerics::step::step;

/// How (1.8) is continued to small dimensionless shear rates (F-34). See the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum SmallShearRate {
    /// L = sinh⁻¹σ with the exact elastic branch for D·L ≥ 2σ. Default.
    #[default]
    Asinh,
    /// SPEC F-34 literal proposal with L = ln 2σ and the threshold σ_min (SPEC default 1).
    SpecLinearBranch {
        /// σ_min
        sigma_min: f64,
    },
}

/// Rheology switch of the Muraki model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Rheology {
    /// Full thermal visco-elastic model (1.8). Default.
    #[default]
    ViscoElastic,
    /// Self-heating switched off (Φ = 0): "friction curve without self-heating" (seed 000 Fig. 2.13
    /// curve 4), S = L − D L²/(4σ).
    Isothermal,
    /// Elastic (first) term of (1.4) only, as seed 000 uses for NVI 65: μ_hd = Γ s b/(h p̄), capped at
    /// `cap` (not in the seeds: the linear law is unbounded; the cap keeps a dynamics run finite
    /// during transients — default 0.1, the large-slip boundary value of (2.10)).
    LinearElastic {
        /// upper bound of μ_hd
        cap: f64,
    },
}

/// Settings of the Muraki model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MurakiSettings {
    /// rheology switch
    pub rheology: Rheology,
    /// small-σ continuation (F-34)
    pub small_shear_rate: SmallShearRate,
    /// solids' K_m, ρ_m, c_m (default steel with ρ_m = 7830 kg/m³, F-25)
    pub solid: SolidThermal,
    /// pressure–viscosity law for η_Ni (default Barus, as (1.5))
    pub piezo: PiezoViscosity,
}

/// Inputs of [`muraki`] (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MurakiInputs {
    /// mean Hertz pressure p̄, Pa
    pub mean_pressure: f64,
    /// half-width b in the rolling direction, m
    pub half_width: f64,
    /// film thickness h, m (> 0)
    pub film: f64,
    /// rolling speed u, m/s (> 0)
    pub rolling_speed: f64,
    /// sliding speed |v|, m/s (≥ 0)
    pub sliding_speed: f64,
    /// η_N0 at the oil temperature, Pa·s
    pub eta0: f64,
    /// ᾱ, 1/Pa
    pub alpha: f64,
    /// Roelands Z (only with `PiezoViscosity::Roelands`; `None` → from ᾱ)
    pub roelands_z: Option<f64>,
    /// Γ, Pa
    pub shear_modulus: f64,
    /// τ0, Pa
    pub tau0: f64,
    /// β0, 1/K
    pub beta0: f64,
    /// κ, 1/(K·Pa)
    pub kappa: f64,
    /// K_f, W/(m·K)
    pub k_f: f64,
}

/// Output of [`muraki`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MurakiOutput {
    /// μ_hd ≥ 0
    pub mu: f64,
    /// S = τ̄/τ0
    pub s: f64,
    /// σ_i
    pub sigma: f64,
    /// D_i
    pub deborah: f64,
    /// Φ
    pub phi: f64,
    /// η_Ni, Pa·s
    pub eta_ni: f64,
    /// the elastic branch (D L ≥ 2σ) was used
    pub elastic_limited: bool,
    /// F-34: negative square-root argument met (literal mode only)
    pub sqrt_negative: bool,
    /// F-34: σ below the validity of ln 2σ (literal mode, σ < 0.5)
    pub sigma_invalid: bool,
}

/// Cancellation-free (1.8) with a given L, from σ, D, x = Φσ and DΦ. Returns
/// (S, sqrt_negative).
#[inline]
fn s_thermal(sigma: f64, d: f64, x: f64, d_phi: f64, l: f64) -> (f64, bool) {
    let a = 1.0 + x;
    let arg = a * a - d_phi * l;
    let (num, den) = s_thermal_parts(sigma, d, x, l, a, arg.max(0.0).sqrt());
    (num / den, arg < 0.0)
}

/// Numerator and denominator of the cancellation-free (1.8):
/// (l/σ)·(σ + (2σ + Φσ² − D l)/(r + 1))/(a + r) over one common denominator, with
/// `x = Φσ`, `a = 1 + Φσ` and `r = √(a² − DΦl)` given.
#[inline(always)]
fn s_thermal_parts(sigma: f64, d: f64, x: f64, l: f64, a: f64, r: f64) -> (f64, f64) {
    (
        l * (sigma * (r + 1.0) + 2.0 * sigma + x * sigma - d * l),
        sigma * (r + 1.0) * (a + r),
    )
}

/// Dimensionless mean shear stress S(σ, D, Φ) with the selected small-σ continuation.
/// Returns (S, elastic_limited, sqrt_negative, sigma_invalid).
#[inline]
pub fn dimensionless_stress(
    sigma: f64,
    d: f64,
    phi: f64,
    mode: SmallShearRate,
) -> (f64, bool, bool, bool) {
    stress_of_products(sigma, d, phi * sigma, d * phi, mode)
}

/// [`dimensionless_stress`] from σ, D and the products x = Φσ and DΦ, which are all that (1.8)
/// needs: both are free of η_Ni (Φσ = (β0 + κp̄) ζ τ0 v, DΦ = (β0 + κp̄) ζ τ0² h u/(Γ b)), so
/// Φ itself is never divided out.
#[inline(always)]
fn stress_of_products(
    sigma: f64,
    d: f64,
    x: f64,
    d_phi: f64,
    mode: SmallShearRate,
) -> (f64, bool, bool, bool) {
    if sigma <= 0.0 {
        return (0.0, false, false, false);
    }
    match mode {
        SmallShearRate::Asinh => {
            // sinh⁻¹σ = ln(σ + √(1 + σ²)): no division (a ln(1 + x) form needs two), accurate
            // to ≈ 1e-16 absolute, which is all S needs: for small σ, S ≈ sinh⁻¹σ/(…) and
            // μ = τ0 S/p̄, so μ's absolute error stays ≈ 1e-16·τ0/p̄
            let l = fastmath::ln(sigma + (1.0 + sigma * sigma).sqrt());
            let elastic = d * l >= 2.0 * sigma;
            // both branches share one square root and one division (a vectorised caller
            // evaluates both): the elastic branch 2σ/(D(1 + √(1 + Φ²σ²))), the thermal one
            // `s_thermal`
            let a = 1.0 + x;
            let thermal_arg = a * a - d_phi * l;
            let root = if elastic {
                1.0 + x * x
            } else {
                thermal_arg.max(0.0)
            }
            .sqrt();
            let (num, den) = if elastic {
                (2.0 * sigma, d * (1.0 + root))
            } else {
                s_thermal_parts(sigma, d, x, l, a, root)
            };
            (num / den, elastic, !elastic && thermal_arg < 0.0, false)
        }
        SmallShearRate::SpecLinearBranch { sigma_min } => {
            let lin = sigma / d;
            let invalid = sigma < 0.5;
            if sigma < sigma_min {
                return (lin, true, false, invalid);
            }
            let (sm, neg) = s_thermal(sigma, d, x, d_phi, (2.0 * sigma).ln());
            let m = lin.min(sm);
            let s = if sigma < 2.0 * sigma_min {
                step(sigma, sigma_min, lin, 2.0 * sigma_min, m)
            } else {
                m
            };
            (s, lin <= sm, neg, invalid)
        }
    }
}

/// The quantities of (1.4)–(1.9) that depend on the contact (oil properties at its
/// temperature and its central film) but not on the slice. The batch computes them once per
/// roller–raceway contact, the single-contact path once per call, with the same expressions,
/// so both give the same bits; every division of the traction law that does not involve the
/// slice is here.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct MurakiContact {
    /// η_N0, Pa·s
    pub eta0: f64,
    /// ᾱ, 1/Pa
    pub alpha: f64,
    /// Γ, Pa
    pub shear_modulus: f64,
    /// 1/Γ, 1/Pa
    pub inv_shear_modulus: f64,
    /// τ0, Pa
    pub tau0: f64,
    /// β0, 1/K
    pub beta0: f64,
    /// film thickness h, m
    pub film: f64,
    /// 1/(τ0 h) of σ_i (1.8)
    pub inv_tau0_film: f64,
    /// τ0² h of Φ (1.8)
    pub tau0_sq_film: f64,
    /// h/(12 K_f), the oil-conduction term of ζ (1.9), m²·K/W
    pub film_conduction: f64,
}

impl MurakiContact {
    /// From the oil properties and the film `film` (m, floored at 1 nm as the single-contact
    /// path always did).
    #[inline(always)]
    pub(crate) fn new(
        eta0: f64,
        alpha: f64,
        shear_modulus: f64,
        tau0: f64,
        beta0: f64,
        k_f: f64,
        film: f64,
    ) -> Self {
        let h = film.max(1e-9);
        Self {
            eta0,
            alpha,
            shear_modulus,
            inv_shear_modulus: 1.0 / shear_modulus,
            tau0,
            beta0,
            film: h,
            inv_tau0_film: 1.0 / (tau0 * h),
            tau0_sq_film: tau0 * tau0 * h,
            film_conduction: h / (12.0 * k_f),
        }
    }
}

/// The slice's side of (1.4)–(1.9): pressure and half-width with their reciprocals, rolling
/// speed u > 0 with its reciprocal, sliding speed |v| ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MurakiSlice {
    /// p̄, b and their reciprocals
    pub pressure: SlicePressure,
    /// u, m/s (> 0)
    pub rolling_speed: f64,
    /// 1/u, s/m
    pub inv_rolling_speed: f64,
    /// |v|, m/s
    pub sliding_speed: f64,
}

/// Muraki hydrodynamic traction coefficient μ_hd ≥ 0 (magnitude; the caller applies the sign).
#[inline]
pub fn muraki(inp: &MurakiInputs, settings: &MurakiSettings) -> MurakiOutput {
    let contact = MurakiContact::new(
        inp.eta0,
        inp.alpha,
        inp.shear_modulus,
        inp.tau0,
        inp.beta0,
        inp.k_f,
        inp.film,
    );
    let slice = MurakiSlice {
        pressure: SlicePressure::of(inp.mean_pressure, inp.half_width),
        rolling_speed: inp.rolling_speed,
        inv_rolling_speed: 1.0 / inp.rolling_speed,
        sliding_speed: inp.sliding_speed,
    };
    muraki_slice(&contact, &slice, inp.kappa, inp.roelands_z, settings)
}

/// [`muraki`] from the per-contact and per-slice parts: the one implementation behind the
/// single-contact path and the batch. κ (1/(K·Pa)) and the Roelands Z belong to the oil.
#[inline(always)]
pub(crate) fn muraki_slice(
    c: &MurakiContact,
    sl: &MurakiSlice,
    kappa: f64,
    roelands_z: Option<f64>,
    settings: &MurakiSettings,
) -> MurakiOutput {
    let pr = &sl.pressure;
    let p = pr.mean_pa;
    let (u, v, b) = (sl.rolling_speed, sl.sliding_speed, pr.half_width_m);
    if let Rheology::LinearElastic { cap } = settings.rheology {
        // first term of (1.4) only: τ̄ = Γ v b/(h u)  ⇒  μ = Γ s b/(h p̄)
        let mu = (c.shear_modulus * v * b * sl.inv_rolling_speed * pr.inv_mean / c.film).min(cap);
        return MurakiOutput {
            mu,
            elastic_limited: true,
            ..Default::default()
        };
    }
    let eta_ni = viscosity_at_pressure(settings.piezo, c.eta0, c.alpha, roelands_z, p);
    let tau0 = c.tau0;
    let sigma = eta_ni * v * c.inv_tau0_film;
    // u/(Γ b): D = η_Ni u/(Γ b), and DΦ without η_Ni
    let u_per_gb = u * pr.inv_half_width * c.inv_shear_modulus;
    let d = eta_ni * u_per_gb;
    let (x, d_phi, phi) = match settings.rheology {
        Rheology::Isothermal => (0.0, 0.0, 0.0),
        _ => {
            let inv_pi_krc = 1.0 / (std::f64::consts::PI * settings.solid.krc());
            let zeta = 0.97 * (b * sl.inv_rolling_speed * inv_pi_krc).sqrt() + c.film_conduction;
            // Φ = g τ0² h/η_Ni with g = (β0 + κ p̄) ζ
            let g = (c.beta0 + kappa * p) * zeta;
            (
                g * tau0 * v,
                g * c.tau0_sq_film * u_per_gb,
                g * c.tau0_sq_film / eta_ni,
            )
        }
    };
    let (s, el, neg, inv) = stress_of_products(sigma, d, x, d_phi, settings.small_shear_rate);
    MurakiOutput {
        mu: (tau0 * s * pr.inv_mean).max(0.0),
        s,
        sigma,
        deborah: d,
        phi,
        eta_ni,
        elastic_limited: el,
        sqrt_negative: neg,
        sigma_invalid: inv,
    }
}
