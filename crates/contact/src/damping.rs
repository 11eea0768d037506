//! Contact damping and the regularised two-level friction law (SPEC §2.2, §3.4), both built on
//! the STEP ramp of [`rolldyn_numerics::step`].
//!
//! * [`SliceDamping`] — variable damping coefficient `C(δ) = STEP(δ, 0, 0, δ*, C_max)` (seed 000
//!   eqs. (2.5), (2.6) with the corrections ⚠ F-16, F-17, F-18).
//! * [`normal_force`] — composition `Q = Q' + C(δ) δ̇` (seed 000 eq. (2.8)), clamped at ≥ 0.
//! * [`TwoLevelFriction`] — friction coefficient `μ(v)` with static/dynamic levels (SPEC §3.4,
//!   ⚠ F-19, F-20).
//!
//! Sign conventions: `δ > 0` is penetration, `δ̇ > 0` approaching; the viscous force `C(δ) δ̇`
//! is repulsive while approaching (it opposes the relative normal velocity).

use rolldyn_numerics::step::{step, step_with_derivative};

/// Variable contact damping of a slice (or any contact), SPEC §2.2:
/// `C(δ) = STEP(δ, 0, 0, δ*, C_max)` — zero at first touch, full damping `C_max` from the
/// critical approach `δ*` on (seed 000 eq. (2.6) with ⚠ F-17: both ratios are `δ/δ*`;
/// ⚠ F-18: argument order `(δ, 0, 0, d, C_h)`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliceDamping {
    /// Maximum damping coefficient `C_max` (N·s/m). No seed value (⚠ F-21); default 0
    /// (undamped) so that an unset value never adds spurious forces.
    pub c_max: f64,
    /// Critical approach `δ*` (`d_XY` of Table 2.1) at which full damping is reached (m).
    /// Default 1 µm (ADAMS' customary IMPACT penetration depth of 0.001 mm).
    pub delta_star: f64,
    /// ⚠ F-16 switch: `true` (default, proposal) → viscous force `C(δ)·δ̇`; `false` → the
    /// seed's printed `C(δ)·δ` (kept for reproducing the seed only; not a damping force).
    pub uses_velocity: bool,
    /// Clamp the total normal force at ≥ 0 (no adhesion; SPEC §2.2 proposal). Default `true`.
    pub clamp_non_negative: bool,
}

impl Default for SliceDamping {
    fn default() -> Self {
        Self {
            c_max: 0.0,
            delta_star: 1e-6,
            uses_velocity: true,
            clamp_non_negative: true,
        }
    }
}

impl SliceDamping {
    /// Damping with coefficient `c_max` (N·s/m) reaching full value at `delta_star` (m); other
    /// switches at their defaults.
    pub fn new(c_max: f64, delta_star: f64) -> Self {
        Self {
            c_max,
            delta_star,
            ..Self::default()
        }
    }

    /// Damping coefficient `C(δ)` (N·s/m); 0 for `δ ≤ 0`.
    #[inline]
    pub fn coefficient(&self, delta: f64) -> f64 {
        step(delta, 0.0, 0.0, self.delta_star, self.c_max)
    }

    /// `(C(δ), dC/dδ)`.
    #[inline]
    pub fn coefficient_with_derivative(&self, delta: f64) -> (f64, f64) {
        step_with_derivative(delta, 0.0, 0.0, self.delta_star, self.c_max)
    }

    /// Viscous part `Q'' = C(δ)·δ̇` (N) (seed 000 eqs. (2.5), (2.7) with ⚠ F-16), or the seed's
    /// `C(δ)·δ` when `uses_velocity` is false. Not clamped.
    #[inline]
    pub fn viscous_force(&self, delta: f64, delta_dot: f64) -> f64 {
        let rate = if self.uses_velocity { delta_dot } else { delta };
        self.coefficient(delta) * rate
    }

    /// Total normal force `Q = Q' + C(δ)·δ̇` (seed 000 eq. (2.8)), clamped at ≥ 0 when
    /// `clamp_non_negative`; 0 whenever `δ ≤ 0`. `elastic` is the elastic part `Q'(δ)` (N).
    #[inline]
    pub fn normal_force(&self, elastic: f64, delta: f64, delta_dot: f64) -> f64 {
        self.normal_force_with_partials(elastic, 0.0, delta, delta_dot)
            .0
    }

    /// Total normal force and its partials `(Q, ∂Q/∂δ, ∂Q/∂δ̇)` given the elastic part and its
    /// stiffness `(Q', dQ'/dδ)` — for implicit integrators. Partials are 0 where the clamp is
    /// active.
    #[inline]
    pub fn normal_force_with_partials(
        &self,
        elastic: f64,
        elastic_stiffness: f64,
        delta: f64,
        delta_dot: f64,
    ) -> (f64, f64, f64) {
        if delta <= 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let (c, dc) = self.coefficient_with_derivative(delta);
        let (q, dq_dd, dq_dv) = if self.uses_velocity {
            (
                elastic + c * delta_dot,
                elastic_stiffness + dc * delta_dot,
                c,
            )
        } else {
            (elastic + c * delta, elastic_stiffness + dc * delta + c, 0.0)
        };
        if self.clamp_non_negative && q < 0.0 {
            (0.0, 0.0, 0.0)
        } else {
            (q, dq_dd, dq_dv)
        }
    }
}

/// Normal-force composition `Q = max(0, Q' + C(δ)·δ̇)` for penetration `δ > 0`, 0 otherwise
/// (seed 000 eq. (2.8); SPEC §2.2 no-adhesion clamp). `damping` gives `C(δ)`.
#[inline]
pub fn normal_force(elastic: f64, delta: f64, delta_dot: f64, damping: &SliceDamping) -> f64 {
    damping.normal_force(elastic, delta, delta_dot)
}

/// Errors of the friction-law parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionParameterError(pub &'static str);

impl std::fmt::Display for FrictionParameterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid two-level friction parameters: {}", self.0)
    }
}

impl std::error::Error for FrictionParameterError {}

/// Two-level regularised friction law (seed 000 Fig. 2.6, SPEC §3.4, ⚠ F-19/F-20: `μ_s` is the
/// static, `μ_d` the dynamic level for every pair).
///
/// [`TwoLevelFriction::coefficient`] returns the friction coefficient **signed with the sliding
/// velocity** (odd in `v`, positive for `v > 0`):
/// * `|v| ≤ v_s`: `STEP(v, −v_s, −μ_s, v_s, μ_s)` (passes through 0 at `v = 0`);
/// * `v_s < |v| < v_d`: `sign(v)·STEP(|v|, v_s, μ_s, v_d, μ_d)`;
/// * `|v| ≥ v_d`: `sign(v)·μ_d`.
///
/// SPEC §3.4 writes `μ(v)` with the opposing sign built in (`μ(v_s) = −μ_s`); that value is
/// [`TwoLevelFriction::opposing`] `= −coefficient(v)`, so that `F_τ = opposing(v)·F_n` along the
/// sliding direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoLevelFriction {
    /// Static coefficient `μ_s`, reached at `|v| = v_s`.
    pub mu_static: f64,
    /// Dynamic coefficient `μ_d`, for `|v| ≥ v_d`.
    pub mu_dynamic: f64,
    /// Stiction velocity `v_s` (m/s, > 0).
    pub v_static: f64,
    /// Transition velocity `v_d` (m/s, > `v_s`).
    pub v_dynamic: f64,
}

impl Default for TwoLevelFriction {
    /// Roller end ↔ rib / cage boundary friction: `μ_s = μ_d = 0.065` (seed 000 §2.1), with a
    /// regularisation band `v_s = 1 mm/s`, `v_d = 10 mm/s` (proposal, not in the seeds: ⚠ F-21
    /// gives no values; choose per pair).
    fn default() -> Self {
        Self {
            mu_static: 0.065,
            mu_dynamic: 0.065,
            v_static: 1e-3,
            v_dynamic: 1e-2,
        }
    }
}

impl TwoLevelFriction {
    /// Validated constructor: `0 < v_s < v_d`, `μ_s, μ_d ≥ 0` and finite.
    pub fn new(
        mu_static: f64,
        mu_dynamic: f64,
        v_static: f64,
        v_dynamic: f64,
    ) -> Result<Self, FrictionParameterError> {
        if !(mu_static >= 0.0
            && mu_static.is_finite()
            && mu_dynamic >= 0.0
            && mu_dynamic.is_finite())
        {
            return Err(FrictionParameterError(
                "friction coefficients must be finite and non-negative",
            ));
        }
        if !(v_static > 0.0 && v_dynamic > v_static && v_dynamic.is_finite()) {
            return Err(FrictionParameterError(
                "velocities must satisfy 0 < v_s < v_d",
            ));
        }
        Ok(Self {
            mu_static,
            mu_dynamic,
            v_static,
            v_dynamic,
        })
    }

    /// Constant friction coefficient `μ` regularised near `v = 0` (e.g. the boundary friction
    /// 0.065 of roller ends): `μ_s = μ_d = μ`.
    pub fn constant(
        mu: f64,
        v_static: f64,
        v_dynamic: f64,
    ) -> Result<Self, FrictionParameterError> {
        Self::new(mu, mu, v_static, v_dynamic)
    }

    /// Friction coefficient signed with the sliding velocity `v` (m/s); odd and continuous.
    #[inline]
    pub fn coefficient(&self, v: f64) -> f64 {
        self.coefficient_with_derivative(v).0
    }

    /// `(μ(v), dμ/dv)` for [`TwoLevelFriction::coefficient`].
    #[inline]
    pub fn coefficient_with_derivative(&self, v: f64) -> (f64, f64) {
        let a = v.abs();
        if a <= self.v_static {
            // STEP(v, −v_s, −μ_s, v_s, μ_s) written as the equivalent odd cubic
            // μ_s u (3 − u²)/2, u = v/v_s, so that μ(−v) = −μ(v) holds exactly in floating point
            let u = v / self.v_static;
            (
                0.5 * self.mu_static * u * (3.0 - u * u),
                1.5 * self.mu_static * (1.0 - u * u) / self.v_static,
            )
        } else {
            let (mu, dmu) = step_with_derivative(
                a,
                self.v_static,
                self.mu_static,
                self.v_dynamic,
                self.mu_dynamic,
            );
            // μ(−v) = −μ(v) ⇒ dμ/dv is even
            (mu.copysign(v), dmu)
        }
    }

    /// SPEC §3.4 sign convention: `μ(v) = −coefficient(v)` (negative for `v > 0`, i.e. the
    /// tangential force opposes sliding): `F_τ = opposing(v)·F_n·t̂`.
    #[inline]
    pub fn opposing(&self, v: f64) -> f64 {
        -self.coefficient(v)
    }
}
