//! Slice force–deflection laws (SPEC §2.1).
//!
//! Every law is a power law in the slice approach, `Q_s = k_s δ^n` (SI, [`PowerForm`]), with a
//! coefficient `k_s` that depends on the slice length `L_s`. [`super::SlicedRoller`] precomputes
//! `k_s` per slice so that the inner loop only evaluates one power per loaded slice.

use super::SliceError;

/// Millimetres per metre (seed-unit conversion, ⚠ F-15).
const MM: f64 = 1e3;
/// Pascals per megapascal.
const MPA: f64 = 1e6;

/// Exponent of seed 000 eq. (2.3) (inner ring).
pub const SEED_2_3_EXPONENT: f64 = 0.92;
/// Exponent of seed 000 eq. (2.4) (outer ring).
pub const SEED_2_4_EXPONENT: f64 = 0.91;
/// ISO/TS 16281 line-contact constant (N, mm units): `Q = 35948 L_we^{8/9} δ^{10/9}`.
pub const ISO_TS_16281_CONSTANT: f64 = 35948.0;

/// A slice force–deflection law. `δ` is the slice approach (penetration, m; `δ ≤ 0` → no
/// force), `L_s` the slice length (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SliceLaw {
    /// Inner ring, seed 000 eq. (2.3) (literature ref. \[54\] of the seed):
    /// `δ_i = 3.17 (d_m/2)^0.08 (Q(1−ν²)/(E L_s))^0.92` in N, mm, MPa (⚠ F-15: dimensionally
    /// inhomogeneous, evaluated in seed units). Inverted exactly as the power law (2.9) with
    /// `α_i = 1/0.92`, `c_i = 3.17 (d_m/2)^0.08 ((1−ν²)/E)^0.92`.
    InnerRing {
        /// Pitch diameter `d_m` (m).
        pitch_diameter: f64,
        /// Young's modulus `E` (Pa).
        youngs_modulus: f64,
        /// Poisson's ratio `ν`.
        poisson_ratio: f64,
    },
    /// Outer ring, seed 000 eq. (2.4):
    /// `δ_o = 2.66 (t_b/(D/d_m))^0.08 (Q(1−ν²)/(E L_s))^0.91` in N, mm, MPa (⚠ F-15).
    /// Inverted as (2.9) with `α_o = 1/0.91`, `c_o = 2.66 (t_b/(D/d_m))^0.08 ((1−ν²)/E)^0.91`.
    OuterRing {
        /// Distance `t_b` from the raceway to the outer surface of the ring (m).
        ring_wall_thickness: f64,
        /// Bearing outside diameter `D` (m).
        outside_diameter: f64,
        /// Pitch diameter `d_m` (m).
        pitch_diameter: f64,
        /// Young's modulus `E` (Pa).
        youngs_modulus: f64,
        /// Poisson's ratio `ν`.
        poisson_ratio: f64,
    },
    /// Generalised slice law, seed 000 eq. (2.9): `Q = L_s (δ/c)^α` with `Q` in N and `L_s` in
    /// **mm** as in the seed (⚠ F-15); `c` is stored in metres (the ratio `δ/c` is
    /// unit-free once both are in the same unit), so `c[m] = c[mm]·10⁻³`.
    Generalized {
        /// Compliance `c` (m, i.e. the seed's mm value × 10⁻³).
        c: f64,
        /// Exponent `α` (> 0).
        alpha: f64,
    },
    /// ISO/TS 16281:2008 lamina law for steel (see e.g. the open implementation
    /// github.com/minzhun/ISO16281, `RollerBearing.stiffness`: `c_s = 35948 L_we^{8/9} / n_s`):
    /// `q_k = 35948 L_we^{8/9} (L_s/L_we) δ_k^{10/9}` (N, mm), which for equal laminae
    /// (`L_s = L_we/n_s`) is `35948 L_we^{8/9}/n_s · δ^{10/9}` and sums to the ISO line-contact
    /// relation `Q = 35948 L_we^{8/9} δ^{10/9}`. `δ` is the **total** roller deflection between
    /// both raceways (inner + outer contact). Note: a per-lamina form
    /// `35948 (L_we/n_s)^{8/9} δ^{10/9}` would *not* sum to the line relation (off by
    /// `n_s^{1/9}`), hence the length-proportional form.
    IsoTs16281 {
        /// Effective roller length `L_we` (m).
        effective_length: f64,
    },
    /// Power law per slice, `Q_s = K_p δ^n` (SPEC §3.3 form), independent of the slice length.
    Power {
        /// Coefficient `K_p` (N/mⁿ).
        k_p: f64,
        /// Exponent `n` (> 0).
        exponent: f64,
    },
    /// Power law per unit slice length, `Q_s = k L_s δ^n`.
    PowerPerLength {
        /// Coefficient `k` (N/m^{n+1}).
        k: f64,
        /// Exponent `n` (> 0).
        exponent: f64,
    },
}

/// A law reduced to `Q = coefficient · δ^exponent` for one slice (SI: N, m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerForm {
    /// Coefficient (N/m^exponent).
    pub coefficient: f64,
    /// Exponent.
    pub exponent: f64,
}

impl PowerForm {
    /// Force and stiffness `(Q, dQ/dδ)`; `(0, 0)` for `δ ≤ 0`.
    #[inline]
    pub fn force(&self, delta: f64) -> (f64, f64) {
        if delta > 0.0 {
            let q = self.coefficient * delta.powf(self.exponent);
            (q, self.exponent * q / delta)
        } else {
            (0.0, 0.0)
        }
    }

    /// Approach for force `q`: `(q/k)^{1/n}`; 0 for `q ≤ 0`.
    pub fn approach(&self, q: f64) -> f64 {
        if q > 0.0 {
            (q / self.coefficient).powf(1.0 / self.exponent)
        } else {
            0.0
        }
    }
}

fn positive(v: f64, what: &'static str) -> Result<f64, SliceError> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(SliceError::InvalidInput(what))
    }
}

fn poisson(nu: f64) -> Result<f64, SliceError> {
    if nu.is_finite() && nu > -1.0 && nu < 0.5 {
        Ok(nu)
    } else {
        Err(SliceError::InvalidInput(
            "Poisson's ratio must lie in (-1, 0.5)",
        ))
    }
}

/// Seed 000 eq. (2.3), inner ring, evaluated literally in seed units (N, mm, MPa; ⚠ F-15):
/// approach (m) of a slice of length `l_s` (m) under force `q` (N); 0 for `q ≤ 0`.
pub fn seed_eq_2_3_approach(
    q: f64,
    l_s: f64,
    pitch_diameter: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
) -> f64 {
    if q <= 0.0 {
        return 0.0;
    }
    let dm = pitch_diameter * MM;
    let e = youngs_modulus / MPA;
    let l = l_s * MM;
    let nu2 = poisson_ratio * poisson_ratio;
    3.17 * (dm / 2.0).powf(0.08) * (q * (1.0 - nu2) / (e * l)).powf(SEED_2_3_EXPONENT) / MM
}

/// Seed 000 eq. (2.4), outer ring, evaluated literally in seed units (N, mm, MPa; ⚠ F-15):
/// approach (m) of a slice of length `l_s` (m) under force `q` (N); 0 for `q ≤ 0`.
pub fn seed_eq_2_4_approach(
    q: f64,
    l_s: f64,
    ring_wall_thickness: f64,
    outside_diameter: f64,
    pitch_diameter: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
) -> f64 {
    if q <= 0.0 {
        return 0.0;
    }
    let tb = ring_wall_thickness * MM;
    let ratio = outside_diameter / pitch_diameter;
    let e = youngs_modulus / MPA;
    let l = l_s * MM;
    let nu2 = poisson_ratio * poisson_ratio;
    2.66 * (tb / ratio).powf(0.08) * (q * (1.0 - nu2) / (e * l)).powf(SEED_2_4_EXPONENT) / MM
}

impl SliceLaw {
    /// Generalised law (2.9) derived from (2.3)/(2.4) (SPEC §2.1, derived): returns `(c, α)`
    /// with `c` in metres, or `None` for laws that are not of the (2.9) family.
    pub fn generalized_parameters(&self) -> Option<(f64, f64)> {
        match *self {
            SliceLaw::InnerRing {
                pitch_diameter,
                youngs_modulus,
                poisson_ratio,
            } => {
                let dm = pitch_diameter * MM;
                let e = youngs_modulus / MPA;
                let nu2 = poisson_ratio * poisson_ratio;
                let c_mm = 3.17 * (dm / 2.0).powf(0.08) * ((1.0 - nu2) / e).powf(SEED_2_3_EXPONENT);
                Some((c_mm / MM, 1.0 / SEED_2_3_EXPONENT))
            }
            SliceLaw::OuterRing {
                ring_wall_thickness,
                outside_diameter,
                pitch_diameter,
                youngs_modulus,
                poisson_ratio,
            } => {
                let tb = ring_wall_thickness * MM;
                let ratio = outside_diameter / pitch_diameter;
                let e = youngs_modulus / MPA;
                let nu2 = poisson_ratio * poisson_ratio;
                let c_mm =
                    2.66 * (tb / ratio).powf(0.08) * ((1.0 - nu2) / e).powf(SEED_2_4_EXPONENT);
                Some((c_mm / MM, 1.0 / SEED_2_4_EXPONENT))
            }
            SliceLaw::Generalized { c, alpha } => Some((c, alpha)),
            _ => None,
        }
    }

    /// The law as a (2.9) `Generalized` law when it belongs to that family (inner/outer ring).
    pub fn to_generalized(&self) -> Option<SliceLaw> {
        self.generalized_parameters()
            .map(|(c, alpha)| SliceLaw::Generalized { c, alpha })
    }

    /// Check the parameters (positive, finite).
    pub fn validate(&self) -> Result<(), SliceError> {
        match *self {
            SliceLaw::InnerRing {
                pitch_diameter,
                youngs_modulus,
                poisson_ratio,
            } => {
                positive(pitch_diameter, "pitch diameter must be positive")?;
                positive(youngs_modulus, "Young's modulus must be positive")?;
                poisson(poisson_ratio)?;
            }
            SliceLaw::OuterRing {
                ring_wall_thickness,
                outside_diameter,
                pitch_diameter,
                youngs_modulus,
                poisson_ratio,
            } => {
                positive(
                    ring_wall_thickness,
                    "ring wall thickness t_b must be positive",
                )?;
                positive(outside_diameter, "outside diameter must be positive")?;
                positive(pitch_diameter, "pitch diameter must be positive")?;
                positive(youngs_modulus, "Young's modulus must be positive")?;
                poisson(poisson_ratio)?;
            }
            SliceLaw::Generalized { c, alpha } => {
                positive(c, "compliance c must be positive")?;
                positive(alpha, "exponent alpha must be positive")?;
            }
            SliceLaw::IsoTs16281 { effective_length } => {
                positive(effective_length, "effective roller length must be positive")?;
            }
            SliceLaw::Power { k_p, exponent } => {
                positive(k_p, "K_p must be positive")?;
                positive(exponent, "exponent must be positive")?;
            }
            SliceLaw::PowerPerLength { k, exponent } => {
                positive(k, "k must be positive")?;
                positive(exponent, "exponent must be positive")?;
            }
        }
        Ok(())
    }

    /// Exponent `n` of the law (`Q ∝ δ^n`).
    pub fn exponent(&self) -> f64 {
        match *self {
            SliceLaw::InnerRing { .. } => 1.0 / SEED_2_3_EXPONENT,
            SliceLaw::OuterRing { .. } => 1.0 / SEED_2_4_EXPONENT,
            SliceLaw::Generalized { alpha, .. } => alpha,
            SliceLaw::IsoTs16281 { .. } => 10.0 / 9.0,
            SliceLaw::Power { exponent, .. } | SliceLaw::PowerPerLength { exponent, .. } => {
                exponent
            }
        }
    }

    /// SI power form `Q_s = k_s δ^n` for a slice of length `slice_length` (m).
    ///
    /// * (2.3)/(2.4)/(2.9): `Q = (L_s/1 mm)(δ/c)^α` → `k_s = 10³ L_s c^{−α}` (c in m).
    /// * ISO/TS 16281: `k_s = 35948·10⁶ · L_we^{−1/9} · L_s` (from N, mm units).
    pub fn power_form(&self, slice_length: f64) -> Result<PowerForm, SliceError> {
        self.validate()?;
        let l_s = positive(slice_length, "slice length must be positive")?;
        let (coefficient, exponent) = match *self {
            SliceLaw::InnerRing { .. }
            | SliceLaw::OuterRing { .. }
            | SliceLaw::Generalized { .. } => {
                let (c, alpha) = self.generalized_parameters().expect("(2.9) family");
                (MM * l_s * c.powf(-alpha), alpha)
            }
            SliceLaw::IsoTs16281 { effective_length } => (
                // N·mm^{-10/9}·mm^{8/9}·mm → SI: factor (10³)^{−1/9 + 1 + 10/9} = 10⁶
                ISO_TS_16281_CONSTANT * 1e6 * effective_length.powf(-1.0 / 9.0) * l_s,
                10.0 / 9.0,
            ),
            SliceLaw::Power { k_p, exponent } => (k_p, exponent),
            SliceLaw::PowerPerLength { k, exponent } => (k * l_s, exponent),
        };
        if !(coefficient > 0.0 && coefficient.is_finite()) {
            return Err(SliceError::InvalidInput(
                "slice law coefficient is not finite and positive",
            ));
        }
        Ok(PowerForm {
            coefficient,
            exponent,
        })
    }

    /// Force `Q_s` (N) and stiffness `dQ_s/dδ` (N/m) of one slice of length `slice_length` (m)
    /// at approach `delta` (m); `(0, 0)` for `δ ≤ 0`.
    pub fn force(&self, slice_length: f64, delta: f64) -> Result<(f64, f64), SliceError> {
        Ok(self.power_form(slice_length)?.force(delta))
    }

    /// Approach (m) of one slice under force `q` (N) — the inverse of [`SliceLaw::force`];
    /// 0 for `q ≤ 0`.
    pub fn approach(&self, slice_length: f64, q: f64) -> Result<f64, SliceError> {
        Ok(self.power_form(slice_length)?.approach(q))
    }
}
