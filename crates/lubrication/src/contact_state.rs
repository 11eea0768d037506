//! The operating point of one lubricated contact (one roller slice ↔ raceway, roller ↔ cage bar,
//! ball ↔ disc …) and the Hertz quantities the traction models need (SPEC §2.3, §4.6).

use std::f64::consts::PI;

/// Shape of the dry contact used to obtain p̄, p_max and the half-width b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactGeometry {
    /// Line contact of working length `length_m` (slice length L_s): Hertz (2.15), (2.16) of seed 000.
    Line {
        /// working (contact) length l, m
        length_m: f64,
    },
    /// Circular point contact (R_y = R_x = `reduced_radius_m`; ball on flat: R = ball radius).
    /// Hertz point formulas (standard form, SPEC §2.3); ellipticity k = 1.
    Circular,
    /// Elliptical point contact with reduced radius `transverse_radius_m` = R_y across the rolling
    /// direction (R_x = `reduced_radius_m`). Hamrock–Brewe approximations (standard form, not in the
    /// seeds): k = 1.0339 (R_y/R_x)^0.636, Ɛ = 1.0003 + 0.5968 R_x/R_y.
    Elliptical {
        /// R_y, m
        transverse_radius_m: f64,
    },
    /// Line contact whose p̄ and b come from elsewhere (Boussinesq solver, FE tables).
    Prescribed {
        /// contact half-width in the rolling direction b, m
        half_width_m: f64,
        /// mean contact pressure p̄, Pa
        mean_pressure_pa: f64,
        /// working length used for the load per unit length of the film formulas, m
        length_m: f64,
    },
}

impl ContactGeometry {
    /// Line contact ([`ContactGeometry::Line`] or [`ContactGeometry::Prescribed`])?
    pub fn is_line(&self) -> bool {
        matches!(self, Self::Line { .. } | Self::Prescribed { .. })
    }

    /// Working length of a line contact, m (NaN for point contacts).
    pub fn length_m(&self) -> f64 {
        match *self {
            Self::Line { length_m } | Self::Prescribed { length_m, .. } => length_m,
            Self::Circular | Self::Elliptical { .. } => f64::NAN,
        }
    }
}

/// Operating state of one contact. All SI. Plain `Copy` data: the dynamics builds one per slice.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// normal force Q (slice force Q_s), N (≥ 0)
    pub normal_force_n: f64,
    /// contact shape
    pub geometry: ContactGeometry,
    /// reduced radius R' = R_x in the rolling direction (1.12), m
    pub reduced_radius_m: f64,
    /// reduced modulus E' of (1.13) (= E/(1−ν²) for identical steels; twice Johnson's E*), Pa
    pub reduced_modulus_pa: f64,
    /// rolling (entrainment) speed u = (v₁ + v₂)/2 in the cage frame, m/s
    pub rolling_speed_m_s: f64,
    /// sliding speed v = v₁ − v₂ (signed), m/s; the traction coefficient has its sign
    pub sliding_speed_m_s: f64,
    /// oil (inlet/bulk) temperature of the contact, K
    pub temperature_k: f64,
    /// arithmetic mean roughness R_a of the two surfaces, m
    pub roughness_ra_m: [f64; 2],
    /// film thickness imposed by the caller (m); `None` → computed by the model's film formula
    pub film_thickness_m: Option<f64>,
}

impl ContactState {
    /// Signed relative slip s = v/u (2.11) with the rolling speed floored at `u_min` (> 0).
    #[inline]
    pub fn slip(&self, u_min: f64) -> f64 {
        self.sliding_speed_m_s / self.rolling_speed_m_s.abs().max(u_min)
    }

    /// Hertz quantities of this state, its [`SlicePressure`] and 1/`rolling_speed` (> 0; for
    /// a line contact all from one evaluation of (2.15)–(2.16), the same as a traction batch's).
    #[inline]
    pub(crate) fn hertz_and_pressure(
        &self,
        rolling_speed: f64,
    ) -> (HertzContact, SlicePressure, f64) {
        match self.geometry {
            ContactGeometry::Line { length_m } => {
                let (sp, inv_speed) = SlicePressure::line_with_speed(
                    self.normal_force_n.max(0.0),
                    length_m,
                    line_stiffness(self.reduced_modulus_pa, self.reduced_radius_m),
                    rolling_speed,
                );
                (HertzContact::line(&sp, length_m), sp, inv_speed)
            }
            _ => {
                let hz = self.hertz();
                let sp = SlicePressure::of(hz.mean_pressure_pa, hz.half_width_m);
                (hz, sp, 1.0 / rolling_speed)
            }
        }
    }

    /// Hertz quantities of this state.
    #[inline]
    pub fn hertz(&self) -> HertzContact {
        hertz(
            self.normal_force_n.max(0.0),
            &self.geometry,
            self.reduced_radius_m,
            self.reduced_modulus_pa,
        )
    }
}

/// Dry-contact (Hertz) quantities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzContact {
    /// mean pressure p̄, Pa
    pub mean_pressure_pa: f64,
    /// maximum pressure p_max, Pa
    pub max_pressure_pa: f64,
    /// half-width b in the rolling direction, m
    pub half_width_m: f64,
    /// ellipticity k = a_transverse / b_rolling (line contact: +∞; circular: 1)
    pub ellipticity: f64,
    /// true for line contacts (Line, Prescribed)
    pub is_line: bool,
    /// working length (line contacts), m; NaN for point contacts
    pub length_m: f64,
}

impl HertzContact {
    /// A line contact of length `length_m` with the pressure `sp` (2.15)–(2.16).
    #[inline(always)]
    fn line(sp: &SlicePressure, length_m: f64) -> Self {
        Self {
            mean_pressure_pa: sp.mean_pa,
            max_pressure_pa: sp.mean_pa * 4.0 / PI,
            half_width_m: sp.half_width_m,
            ellipticity: f64::INFINITY,
            is_line: true,
            length_m,
        }
    }
}

/// Mean Hertz pressure p̄ and half-width b of a loaded contact with their reciprocals: the
/// traction law (seed 000 (1.6)–(1.9)) divides by both, so a slice pays for the reciprocals once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlicePressure {
    /// p̄, Pa
    pub mean_pa: f64,
    /// b, m
    pub half_width_m: f64,
    /// 1/p̄, 1/Pa
    pub inv_mean: f64,
    /// 1/b, 1/m
    pub inv_half_width: f64,
}

impl SlicePressure {
    /// Line contact of load `q` (N) over the length `l` (m) with R' = `r`, E' = `e`:
    /// [`SlicePressure::line_with_speed`] and [`line_stiffness`].
    #[inline(always)]
    pub fn line(q: f64, l: f64, e: f64, r: f64) -> Self {
        Self::line_with_speed(q, l, line_stiffness(e, r), 1.0).0
    }

    /// Line contact with `k` = [`line_stiffness`] (a per-contact constant), and 1/u of a
    /// rolling speed `u` > 0: with the load per length w = Q/l and s = √(k w), p̄ = s/4 is
    /// (2.15) and b = 2w/s the load balance `Q = 2 b l p̄`, which is (2.16)
    /// b = 2 √(2 Q R' / (π l E')). One square root and two divisions give all five values
    /// (1/s, 1/w and 1/u from one reciprocal of w s u). Without load the four pressure values
    /// are 0 and 1/u is meaningless (a caller gives such a slice no traction).
    #[inline(always)]
    pub fn line_with_speed(q: f64, l: f64, k: f64, u: f64) -> (Self, f64) {
        let w = q / l;
        let s = (k * w).sqrt();
        let ws = w * s;
        let t = 1.0 / (ws * u);
        let inv_ws = t * u;
        let (inv_s, inv_w) = (w * inv_ws, s * inv_ws);
        let pressure = if w > 0.0 {
            Self {
                mean_pa: 0.25 * s,
                half_width_m: 2.0 * w * inv_s,
                inv_mean: 4.0 * inv_s,
                inv_half_width: 0.5 * s * inv_w,
            }
        } else {
            Self::UNLOADED
        };
        (pressure, ws * t)
    }

    /// Any contact from its p̄ and b (one division each).
    #[inline]
    pub fn of(mean_pa: f64, half_width_m: f64) -> Self {
        Self {
            mean_pa,
            half_width_m,
            inv_mean: 1.0 / mean_pa,
            inv_half_width: 1.0 / half_width_m,
        }
    }

    /// No load.
    pub const UNLOADED: Self = Self {
        mean_pa: 0.0,
        half_width_m: 0.0,
        inv_mean: 0.0,
        inv_half_width: 0.0,
    };
}

/// k = π E'/(2 R') of a line contact, Pa/m: p̄ = ¼ √(k Q/l), seed 000 (2.15).
#[inline(always)]
pub fn line_stiffness(e: f64, r: f64) -> f64 {
    PI * e / (2.0 * r)
}

/// Load of a line contact giving the maximum pressure `p_max` (inverse of p_max = √(QE'/(2πlR'))).
pub fn line_load_for_max_pressure(p_max: f64, l: f64, e: f64, r: f64) -> f64 {
    2.0 * PI * l * r * p_max * p_max / e
}

/// Load of a circular point contact (radius R, modulus E' of (1.13)) giving `p_max`:
/// a = π p_max R / E', Q = 2π a² p_max / 3 (standard Hertz, E* = E'/2).
pub fn circular_load_for_max_pressure(p_max: f64, r: f64, e: f64) -> f64 {
    let a = PI * p_max * r / e;
    2.0 * PI * a * a * p_max / 3.0
}

/// Hertz quantities for any [`ContactGeometry`].
#[inline]
pub fn hertz(q: f64, geometry: &ContactGeometry, r: f64, e: f64) -> HertzContact {
    match *geometry {
        ContactGeometry::Line { length_m } => {
            HertzContact::line(&SlicePressure::line(q, length_m, e, r), length_m)
        }
        ContactGeometry::Prescribed {
            half_width_m,
            mean_pressure_pa,
            length_m,
        } => HertzContact {
            mean_pressure_pa,
            max_pressure_pa: mean_pressure_pa * 4.0 / PI,
            half_width_m,
            ellipticity: f64::INFINITY,
            is_line: true,
            length_m,
        },
        ContactGeometry::Circular => {
            // a = (3 Q R / (4 E*))^(1/3) with E* = E'/2
            let a = (1.5 * q * r / e).cbrt();
            let pmax = if a > 0.0 { 1.5 * q / (PI * a * a) } else { 0.0 };
            HertzContact {
                mean_pressure_pa: pmax * 2.0 / 3.0,
                max_pressure_pa: pmax,
                half_width_m: a,
                ellipticity: 1.0,
                is_line: false,
                length_m: f64::NAN,
            }
        }
        ContactGeometry::Elliptical {
            transverse_radius_m: ry,
        } => {
            let k = 1.0339 * (ry / r).powf(0.636);
            let eps = 1.0003 + 0.5968 * r / ry;
            let rr = r * ry / (r + ry);
            let a_t = (6.0 * k * k * eps * q * rr / (PI * e)).cbrt();
            let b_r = (6.0 * eps * q * rr / (PI * k * e)).cbrt();
            let pmax = if a_t > 0.0 {
                1.5 * q / (PI * a_t * b_r)
            } else {
                0.0
            };
            HertzContact {
                mean_pressure_pa: pmax * 2.0 / 3.0,
                max_pressure_pa: pmax,
                half_width_m: b_r,
                ellipticity: k,
                is_line: false,
                length_m: f64::NAN,
            }
        }
    }
}
