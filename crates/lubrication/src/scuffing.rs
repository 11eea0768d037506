//! Scuffing criterion — critical relative slip and heat-power diagnostics (SPEC §4.8,
//! seed 000 (2.21)–(2.32)).
//!
//! s_cr is the relative slip at which the friction curve μ_hd(s) (at fixed p̄/p_max, u, T) reaches
//! its maximum, i.e. the start of the thermal zone. Operation is **safe when s < s_cr** (F-32: the
//! seed's wording is reversed); the margin is s_cr/s.
//!
//! The maximum is found robustly in x = ln s: a geometric **bracketing walk** (growing steps) from
//! s_min until μ decreases, then **Brent's** parabolic/golden-section maximisation inside the bracket
//! ([`rolldyn_numerics::maximize1d::brent_max`]).
//! No grid scan. If μ is still increasing at s_max, or already decreasing at s_min, the outcome is
//! [`CriticalSlip::NoMaximumInRange`].

use crate::contact_state::ContactState;
use crate::error::LubError;
use crate::traction::{TractionModel, traction};
use rolldyn_numerics::maximize1d::{BrentMaxOptions, brent_max};

/// Search range and tolerances for [`critical_slip`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipSearch {
    /// lower end of the slip range (> 0), default 1e-4
    pub s_min: f64,
    /// upper end, default 2 (physical range 0 ≤ s < 2)
    pub s_max: f64,
    /// first bracketing step in ln s, default 0.25
    pub initial_step: f64,
    /// step growth factor, default 1.6
    pub growth: f64,
    /// largest bracketing step in ln s, default 0.7
    pub max_step: f64,
    /// relative tolerance on s_cr, default 1e-6
    pub tolerance: f64,
    /// evaluation budget, default 200
    pub max_evaluations: u32,
}

impl Default for SlipSearch {
    fn default() -> Self {
        SlipSearch {
            s_min: 1e-4,
            s_max: 2.0,
            initial_step: 0.25,
            growth: 1.6,
            max_step: 0.7,
            tolerance: 1e-6,
            max_evaluations: 200,
        }
    }
}

/// Why no interior maximum was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NoMaximumReason {
    /// μ_hd still increases at s_max (no thermal zone in range)
    IncreasingAtUpperEnd,
    /// μ_hd already decreases at s_min (maximum at or below s_min)
    DecreasingFromLowerEnd,
}

/// Outcome of [`critical_slip`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CriticalSlip {
    /// interior maximum of μ_hd(s)
    Maximum {
        /// s_cr
        slip: f64,
        /// μ_hd(s_cr)
        coefficient: f64,
        /// friction-curve evaluations used
        evaluations: u32,
    },
    /// "no thermal zone within range"
    NoMaximumInRange {
        /// reason
        reason: NoMaximumReason,
        /// slip at the end where the search stopped
        slip_at_end: f64,
        /// μ_hd there
        coefficient_at_end: f64,
        /// evaluations used
        evaluations: u32,
    },
}

impl CriticalSlip {
    /// s_cr if an interior maximum exists.
    pub fn slip(&self) -> Option<f64> {
        match self {
            CriticalSlip::Maximum { slip, .. } => Some(*slip),
            _ => None,
        }
    }
    /// μ_max if an interior maximum exists.
    pub fn coefficient(&self) -> Option<f64> {
        match self {
            CriticalSlip::Maximum { coefficient, .. } => Some(*coefficient),
            _ => None,
        }
    }
}

/// Friction-curve value μ_hd(s) (≥ 0) of `model` at relative slip `s` (v = s·|u|, other state kept).
pub fn friction_curve(state: &ContactState, model: &TractionModel, s: f64) -> f64 {
    let mut st = *state;
    st.sliding_speed_m_s = s * state.rolling_speed_m_s.abs();
    traction(&st, model).hydrodynamic
}

/// μ_hd(s) and dμ_hd/ds by a central difference (relative step 10⁻⁴).
pub fn friction_curve_slope(state: &ContactState, model: &TractionModel, s: f64) -> (f64, f64) {
    let h = 1e-4 * s.abs().max(1e-6);
    let fp = friction_curve(state, model, s + h);
    let fm = friction_curve(state, model, s - h);
    (friction_curve(state, model, s), (fp - fm) / (2.0 * h))
}

/// Critical relative slip s_cr = arg max μ_hd(s) (see the module docs). Errors: |u| = 0, or a bad
/// search range.
pub fn critical_slip(
    state: &ContactState,
    model: &TractionModel,
    search: &SlipSearch,
) -> Result<CriticalSlip, LubError> {
    if state.rolling_speed_m_s.abs() <= 0.0 {
        return Err(LubError::InvalidInput(
            "critical slip needs a rolling speed > 0".into(),
        ));
    }
    if !(search.s_min > 0.0 && search.s_max > search.s_min && search.growth >= 1.0) {
        return Err(LubError::InvalidInput("bad slip search range".into()));
    }
    let n = std::cell::Cell::new(0u32);
    let mut f = |x: f64| {
        n.set(n.get() + 1);
        friction_curve(state, model, x.exp())
    };
    let x_end = search.s_max.ln();
    let mut x0 = search.s_min.ln();
    let mut f0 = f(x0);
    let mut h = search.initial_step;
    let mut x1 = (x0 + h).min(x_end);
    let mut f1 = f(x1);
    if f1 < f0 {
        return Ok(CriticalSlip::NoMaximumInRange {
            reason: NoMaximumReason::DecreasingFromLowerEnd,
            slip_at_end: search.s_min,
            coefficient_at_end: f0,
            evaluations: 2,
        });
    }
    let (a, b, xm, fm) = loop {
        if x1 >= x_end {
            return Ok(CriticalSlip::NoMaximumInRange {
                reason: NoMaximumReason::IncreasingAtUpperEnd,
                slip_at_end: search.s_max,
                coefficient_at_end: f1,
                evaluations: n.get(),
            });
        }
        h = (h * search.growth).min(search.max_step);
        let x2 = (x1 + h).min(x_end);
        let f2 = f(x2);
        if f2 < f1 {
            break (x0, x2, x1, f1);
        }
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = f2;
        if n.get() >= search.max_evaluations {
            return Err(LubError::InvalidInput(
                "critical slip: evaluation budget exhausted".into(),
            ));
        }
    };
    let _ = f0;
    let options = BrentMaxOptions {
        tolerance: search.tolerance,
        max_iterations: search.max_evaluations,
    };
    let (xs, fs) = brent_max(&mut f, (a, b), (xm, fm), &options);
    Ok(CriticalSlip::Maximum {
        slip: xs.exp(),
        coefficient: fs,
        evaluations: n.get(),
    })
}

/// Result of [`scuffing_check`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScuffingCheck {
    /// operating relative slip |s| = |v/u|
    pub slip: f64,
    /// critical slip outcome
    pub critical: CriticalSlip,
    /// margin s_cr/|s| (∞ if s = 0; `None` if no maximum in range)
    pub margin: Option<f64>,
    /// safe operation: |s| < s_cr (or no thermal zone up to s_max > |s|)
    pub safe: bool,
}

/// Compare the operating slip of `state` with s_cr at the same p̄, u, T (SPEC §3.8 per-contact check).
pub fn scuffing_check(
    state: &ContactState,
    model: &TractionModel,
    search: &SlipSearch,
) -> Result<ScuffingCheck, LubError> {
    let s = (state.sliding_speed_m_s / state.rolling_speed_m_s).abs();
    let critical = critical_slip(state, model, search)?;
    let (margin, safe) = match critical {
        CriticalSlip::Maximum { slip, .. } => (
            Some(if s > 0.0 { slip / s } else { f64::INFINITY }),
            s < slip,
        ),
        CriticalSlip::NoMaximumInRange { reason, .. } => (
            None,
            reason == NoMaximumReason::IncreasingAtUpperEnd && s < search.s_max,
        ),
    };
    Ok(ScuffingCheck {
        slip: s,
        critical,
        margin,
        safe,
    })
}

/// Heat power N = μ_hd Q u s, (2.22) (= μ Q v, (2.21)), W.
#[inline]
pub fn heat_power(mu: f64, q: f64, u: f64, s: f64) -> f64 {
    mu * q * u * s
}

/// dN/ds at constant rolling speed, (2.23): Q u s μ (μ'/μ + 1/s) = Q u (μ + s μ').
#[inline]
pub fn dn_ds_constant_rolling(mu: f64, dmu_ds: f64, q: f64, u: f64, s: f64) -> f64 {
    q * u * (mu + s * dmu_ds)
}

/// Heat-power growth condition in the thermal zone, (2.24): |dμ/ds| < μ/s.
#[inline]
pub fn heat_power_grows(mu: f64, dmu_ds: f64, s: f64) -> bool {
    dmu_ds.abs() < mu / s
}

/// dN/ds with v₂ constant, v = 2 s v₂/(2 − s). `exact = true`: exact derivative (F-31)
/// Q v₂ μ (2s/(2 − s) μ'/μ + 4/(2 − s)²); `false`: as printed in (2.26) (factor 2s/(2 − s) omitted).
#[inline]
pub fn dn_ds_v2_constant(mu: f64, dmu_ds: f64, q: f64, v2: f64, s: f64, exact: bool) -> f64 {
    let f = if exact { 2.0 * s / (2.0 - s) } else { 1.0 };
    q * v2 * mu * (f * dmu_ds / mu + 4.0 / ((2.0 - s) * (2.0 - s)))
}

/// dN/ds with v₁ constant, v = 2 s v₁/(2 + s); exact (F-31) or as printed (2.28).
#[inline]
pub fn dn_ds_v1_constant(mu: f64, dmu_ds: f64, q: f64, v1: f64, s: f64, exact: bool) -> f64 {
    let f = if exact { 2.0 * s / (2.0 + s) } else { 1.0 };
    q * v1 * mu * (f * dmu_ds / mu + 4.0 / ((2.0 + s) * (2.0 + s)))
}

/// φ = R_i/(2R_m) of (2.30)–(2.32).
#[inline]
pub fn phi_ratio(r_i: f64, r_m: f64) -> f64 {
    r_i / (2.0 * r_m)
}

/// Inner-raceway contact, rotating inner ring / fixed outer ring, (2.30) as printed:
/// dN_i/ds_i = Q μ 2s_i[ω_iR_i(1−φ) + φ v_o]/(2 + s_i(1−2φ)) · {μ'/μ + 2/(s_i[2 + s_i(1−2φ)])}.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn dn_ds_inner(
    mu: f64,
    dmu_ds: f64,
    q: f64,
    s_i: f64,
    omega_i: f64,
    r_i: f64,
    r_m: f64,
    v_o: f64,
) -> f64 {
    let phi = phi_ratio(r_i, r_m);
    let den = 2.0 + s_i * (1.0 - 2.0 * phi);
    q * mu * 2.0 * s_i * (omega_i * r_i * (1.0 - phi) + phi * v_o) / den
        * (dmu_ds / mu + 2.0 / (s_i * den))
}

/// Outer-raceway contact, (2.32) as printed:
/// dN_o/ds_o = Q μ 2s_o(1−φ)[ω_iR_i − v_i]/(2 + s_o(1−2φ)) · {μ'/μ + 2/(s_o[2 + s_o(1−2φ)])}.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn dn_ds_outer(
    mu: f64,
    dmu_ds: f64,
    q: f64,
    s_o: f64,
    omega_i: f64,
    r_i: f64,
    r_m: f64,
    v_i: f64,
) -> f64 {
    let phi = phi_ratio(r_i, r_m);
    let den = 2.0 + s_o * (1.0 - 2.0 * phi);
    q * mu * 2.0 * s_o * (1.0 - phi) * (omega_i * r_i - v_i) / den
        * (dmu_ds / mu + 2.0 / (s_o * den))
}

/// Left side of (2.31): 2/(s[2 + s(1 − 2φ)]) (the condition is ≥ 1).
#[inline]
pub fn condition_2_31(s: f64, phi: f64) -> f64 {
    2.0 / (s * (2.0 + s * (1.0 - 2.0 * phi)))
}

/// Slip at which (2.31) becomes an equality: root of (1 − 2φ)s² + 2s − 2 = 0 (F-33: 0.953 for
/// raceway Ø180 mm, roller Ø21 mm; the seed prints 0.94).
pub fn root_2_31(phi: f64) -> f64 {
    let c = 1.0 - 2.0 * phi;
    if c.abs() < 1e-12 {
        1.0
    } else {
        (-2.0 + (4.0 + 8.0 * c).sqrt()) / (2.0 * c)
    }
}
