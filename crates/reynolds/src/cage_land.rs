//! Hydrodynamic force and friction torque of a cage running on its guiding land, for the
//! bearing dynamics (seed 001 treats the cage–land contact as a narrow journal bearing; issue
//! item 5).
//!
//! **Model.** The land is a narrow journal bearing of radius R, width B and radial clearance c.
//! The force comes from the short-bearing (Dubois–Ocvirk) solution with squeeze and half-
//! Sommerfeld cavitation, in closed form for any whirl/squeeze state (Booker-type integrals over
//! the pressurised half period), multiplied by a *finite-length correction* measured once with
//! the full finite-difference Reynolds solver ([`crate::journal`], Reynolds cavitation, ambient
//! pressure at both land edges): the finite force normalised by the short-bearing force magnitude
//! is tabulated over the eccentricity ratio ε and the squeeze-to-rotation angle
//! φ₁ = atan2(ε̇, εΩ̄) and interpolated bicubically. By homogeneity of the Reynolds equation this
//! table is exact for all speeds and viscosities of a given B/D (up to grid and interpolation
//! error, stated in `tests/cage_land.rs`).
//!
//! Pressure field p = (6μ/h³)·G·(z² − B²/4), G = c[εΩ̄ sin ϑ − ε̇ cos ϑ], h = c(1 − ε cos ϑ),
//! Ω̄ = (ω_inner + ω_outer)/2 − α̇, ϑ measured from the line of centres (minimum film at ϑ = 0).
//! Torque: Couette shear of a full (flooded) film, μΔω R³B·2π/(c√(1−ε²)), plus the pressure
//! couple ±eF_t/2.
//!
//! **Starved land** ([`CageLandOptions::fill_fraction`] f < 1). The land holds the oil volume
//! f·2πRBc (f = oil volume in the land clearance / clearance volume). The oil fills the gap
//! completely over the arc |ϑ| ≤ ϑ_w around the minimum film and the rest is air, with ϑ_w from
//! the volume, ∫₋ϑ_w^ϑ_w h dϑ = 2πc f, i.e. ϑ_w − ε sin ϑ_w = π f ([`starved_half_angle`];
//! derived: the film-extent picture of a starved journal bearing, Artiles & Heshmat, ASME J.
//! Tribol. 107 (1985) 1–13, with the film content of Elrod's mass-conserving cavitation,
//! ASME J. Lubr. Technol. 103 (1981) 350–354). The short-bearing pressure acts only where the
//! pressurised half period overlaps the wetted arc (the short-bearing field is local in ϑ, so
//! this is the starved short-bearing solution); its magnitude takes the finite-length correction
//! of the flooded film at the same (ε, φ₁) (an approximation: the table is measured flooded).
//! The Couette shear acts only on the wetted arc: the flooded torque times
//! (2/π)·atan(√((1+ε)/(1−ε))·tan(ϑ_w/2)) ([`wetted_shear_fraction`]).

use crate::error::{Result, ReynoldsError, positive};
use crate::journal::{
    CavitatedShear, FilmStart, JournalBearing, JournalOperating, JournalOptions, solve_state,
};
use crate::viscosity::Isoviscous;

/// Couette shear torque of a full (flooded) film between a journal and its bush turning
/// `relative_speed` ω_j − ω_b apart, μ Δω R³ B·2π/(c√(1−ε²)) [N·m] (radius R, width B, radial
/// clearance c, eccentricity ratio ε); ε = 0 is Petroff's 2πμωR³B/c.
#[inline]
pub fn couette_land_torque(
    viscosity: f64,
    relative_speed: f64,
    radius: f64,
    width: f64,
    clearance: f64,
    eccentricity_ratio: f64,
) -> f64 {
    let eps = eccentricity_ratio;
    viscosity * relative_speed * radius.powi(3) * width * std::f64::consts::TAU
        / (clearance * (1.0 - eps * eps).sqrt())
}

/// Which ring carries the guiding land.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LandPosition {
    /// Outer-ring guided cage: the cage outside surface runs inside the ring land (the cage is
    /// the inner member). Default.
    #[default]
    OuterRing,
    /// Inner-ring guided cage: the cage bore runs on the ring land (the cage is the outer member).
    InnerRing,
}

/// Land geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageLandGeometry {
    /// Land radius R, m.
    pub radius: f64,
    /// Land width B (axial), m.
    pub width: f64,
    /// Radial clearance c, m.
    pub clearance: f64,
    /// Land position.
    pub position: LandPosition,
}

/// Settings of the finite-length correction table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageLandOptions {
    /// Build the finite-length correction (otherwise pure short-bearing theory). Default true.
    pub finite_correction: bool,
    /// Grid of the finite solver used for the table (circumferential × axial nodes over the
    /// width). Default 96 × 17.
    pub grid: (usize, usize),
    /// Number of eccentricity nodes (uniform in s = −ln(1 − ε) from ε = 0.02 to
    /// `max_eccentricity`). Default 24.
    pub eccentricity_nodes: usize,
    /// Number of φ₁ nodes on [−90°, 90°], uniform in u with φ₁ = 90°·sin(90°·u) (clustered near
    /// pure squeeze, where the correction varies fastest). Default 19.
    pub angle_nodes: usize,
    /// Eccentricity ratio at which evaluations are clamped (metal contact must be modelled
    /// separately). Default 0.98.
    pub max_eccentricity: f64,
    /// Fill fraction f of the land clearance (oil volume / clearance volume, 0 < f ≤ 1): 1 is
    /// the flooded film, f < 1 a starved land (module doc). Default 1.
    pub fill_fraction: f64,
}

impl Default for CageLandOptions {
    fn default() -> Self {
        Self {
            finite_correction: true,
            grid: (96, 17),
            eccentricity_nodes: 24,
            angle_nodes: 19,
            max_eccentricity: 0.98,
            fill_fraction: 1.0,
        }
    }
}

/// Force on the cage and torque on the cage about its axis.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CageLandForce {
    /// Hydrodynamic force on the cage in the input frame, N.
    pub force_n: [f64; 2],
    /// Friction torque on the cage about its axis (counter-clockwise positive), N·m.
    pub torque_nm: f64,
    /// Eccentricity ratio used (after clamping).
    pub eccentricity: f64,
}

/// Fast cage–land model.
#[derive(Debug, Clone)]
pub struct CageLand {
    geom: CageLandGeometry,
    eps_max: f64,
    fill: f64,
    s_min: f64,
    s_step: f64,
    phi_step: f64,
    n_s: usize,
    n_phi: usize,
    /// f_r, f_t (finite force / short-bearing magnitude), index is·n_phi + ip; empty = none.
    fr: Vec<f64>,
    ft: Vec<f64>,
}

/// Short-bearing integrals over the pressurised half period (φ₁ − π, φ₁):
/// returns (I_r, I_t) with I_r = ∫ sin(ϑ−φ₁) cos ϑ /D³, I_t = ∫ sin(ϑ−φ₁) sin ϑ /D³, D = 1 − ε cos ϑ.
pub fn short_bearing_integrals(eps: f64, phi1: f64) -> (f64, f64) {
    if eps < 0.02 {
        return gauss2(integrand(eps, phi1), phi1 - std::f64::consts::PI, phi1);
    }
    let s1 = phi1.sin();
    let c1 = phi1.cos();
    // at a = φ₁ − π: sin a = −sin φ₁, cos a = −cos φ₁, tan(a/2) = −1/tan(φ₁/2)
    let tan_half = (0.5 * phi1).tan();
    let xa = antiderivatives(eps, phi1 - std::f64::consts::PI, -s1, -c1, -1.0 / tan_half);
    let xb = antiderivatives(eps, phi1, s1, c1, tan_half);
    combine(phi1, xa, xb)
}

/// The integrals of [`short_bearing_integrals`] over the part of the pressurised half period
/// (φ₁ − π, φ₁), |φ₁| ≤ π/2, inside the wetted arc |ϑ| < ϑ_w (mod 2π) of a starved film,
/// 0 ≤ ϑ_w < π: the overlap with (−ϑ_w, ϑ_w) and, for φ₁ − π < ϑ_w − 2π, with the arc's copy
/// (−2π − ϑ_w, ϑ_w − 2π).
pub fn short_bearing_integrals_wetted(eps: f64, phi1: f64, half_angle: f64) -> (f64, f64) {
    use std::f64::consts::{PI, TAU};
    let start = phi1 - PI;
    let pieces = [
        (start.max(-half_angle), phi1.min(half_angle)),
        (start, phi1.min(half_angle - TAU)),
    ];
    let (mut r, mut t) = (0.0, 0.0);
    for (lo, hi) in pieces {
        if hi <= lo {
            continue;
        }
        let (pr, pt) = if eps < 0.02 {
            gauss2(integrand(eps, phi1), lo, hi)
        } else {
            // the ends lie off ϑ = ±π, where tan(ϑ/2) is finite
            let at = |x: f64| {
                let (s, c) = x.sin_cos();
                antiderivatives(eps, x, s, c, (0.5 * x).tan())
            };
            combine(phi1, at(lo), at(hi))
        };
        r += pr;
        t += pt;
    }
    (r, t)
}

/// sin(ϑ−φ₁)(cos ϑ, sin ϑ)/D³, the integrand of [`short_bearing_integrals`].
fn integrand(eps: f64, phi1: f64) -> impl Fn(f64) -> (f64, f64) {
    move |t: f64| {
        let d = 1.0 - eps * t.cos();
        let w = (t - phi1).sin() / (d * d * d);
        (w * t.cos(), w * t.sin())
    }
}

/// (J_sc, J_cc, J_ss) = antiderivatives of sin ϑ cos ϑ/D³, cos²ϑ/D³, sin²ϑ/D³ at ϑ = t (from
/// sin t, cos t and tan(t/2); continuous across t = ±π), ε ≥ 0.02 (Booker-type reduction
/// formulas for ∫dϑ/Dⁿ).
fn antiderivatives(eps: f64, t: f64, s: f64, c: f64, tan_half: f64) -> (f64, f64, f64) {
    let q = 1.0 - eps * eps;
    let k = ((1.0 + eps) / (1.0 - eps)).sqrt();
    // continuous antiderivative of 1/D, from tan(t/2)
    let m = ((t + std::f64::consts::PI) / std::f64::consts::TAU).floor();
    let a1 = 2.0 / q.sqrt() * ((k * tan_half).atan() + std::f64::consts::PI * m);
    let d = 1.0 - eps * c;
    let a2 = eps * s / (q * d) + a1 / q;
    let a3 = eps * s / (2.0 * q * d * d) + 3.0 / (2.0 * q) * a2 - 1.0 / (2.0 * q) * a1;
    let jsc = (2.0 * d - 1.0) / (2.0 * eps * eps * d * d);
    let jcc = (a3 - 2.0 * a2 + a1) / (eps * eps);
    (jsc, jcc, a3 - jcc)
}

/// (I_r, I_t) from the antiderivatives at the ends `xa`, `xb` of the interval.
fn combine(phi1: f64, xa: (f64, f64, f64), xb: (f64, f64, f64)) -> (f64, f64) {
    let (s1, c1) = phi1.sin_cos();
    let (jsc, jcc, jss) = (xb.0 - xa.0, xb.1 - xa.1, xb.2 - xa.2);
    (c1 * jsc - s1 * jcc, c1 * jss - s1 * jsc)
}

/// Half angle ϑ_w of the wetted arc of a starved land with fill fraction `fill` at eccentricity
/// ratio `eps`: the root of ϑ − ε sin ϑ = π f on [0, π] (oil volume ∫h dϑ over the arc equal to
/// f times the clearance volume, module doc). π for f ≥ 1. Safeguarded Newton.
pub fn starved_half_angle(eps: f64, fill: f64) -> f64 {
    use std::f64::consts::PI;
    if fill >= 1.0 {
        return PI;
    }
    let target = PI * fill.max(0.0);
    let (mut lo, mut hi) = (0.0, PI);
    let mut x = target.clamp(0.0, PI);
    for _ in 0..200 {
        let g = x - eps * x.sin() - target;
        if g.abs() < 1e-15 || hi - lo < 1e-15 {
            break;
        }
        if g > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let slope = 1.0 - eps * x.cos();
        let next = x - g / slope;
        x = if slope > 0.0 && next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
    }
    x
}

/// Share of the flooded Couette torque carried by the wetted arc |ϑ| ≤ ϑ_w:
/// ∫₋ϑ_w^ϑ_w dϑ/D ÷ ∫₀^2π dϑ/D = (2/π)·atan(√((1+ε)/(1−ε))·tan(ϑ_w/2)); 1 for ϑ_w ≥ π.
pub fn wetted_shear_fraction(eps: f64, half_angle: f64) -> f64 {
    if half_angle >= std::f64::consts::PI {
        return 1.0;
    }
    let eps = eps.clamp(0.0, 0.999_999);
    let k = ((1.0 + eps) / (1.0 - eps)).sqrt();
    std::f64::consts::FRAC_2_PI * (k * (0.5 * half_angle).tan()).atan()
}

fn gauss2(f: impl Fn(f64) -> (f64, f64), a: f64, b: f64) -> (f64, f64) {
    const X: [f64; 8] = [
        0.095_012_509_837_637_44,
        0.281_603_550_779_258_9,
        0.458_016_777_657_227_4,
        0.617_876_244_402_643_7,
        0.755_404_408_355_003,
        0.865_631_202_387_831_7,
        0.944_575_023_073_232_6,
        0.989_400_934_991_649_9,
    ];
    const W: [f64; 8] = [
        0.189_450_610_455_068_5,
        0.182_603_415_044_923_6,
        0.169_156_519_395_002_5,
        0.149_595_988_816_576_7,
        0.124_628_971_255_533_9,
        0.095_158_511_682_492_78,
        0.062_253_523_938_647_89,
        0.027_152_459_411_754_09,
    ];
    let (mut r, mut t) = (0.0, 0.0);
    let h = 0.5 * (b - a);
    for p in 0..2 {
        let (lo, hi) = (a + p as f64 * h, a + (p + 1) as f64 * h);
        let (c, rr) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        for k in 0..8 {
            for sg in [-1.0, 1.0] {
                let (u, v) = f(c + sg * rr * X[k]);
                r += W[k] * rr * u;
                t += W[k] * rr * v;
            }
        }
    }
    (r, t)
}

/// Catmull–Rom weights for fractional position t ∈ [0, 1) between nodes 1 and 2 of 4.
#[inline]
fn cr(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

impl CageLand {
    /// Pure short-bearing model (no finite-length correction).
    pub fn short_bearing(geom: CageLandGeometry) -> Result<Self> {
        Self::new(
            geom,
            &CageLandOptions {
                finite_correction: false,
                ..Default::default()
            },
        )
    }

    /// Builds the model; with `finite_correction` the table is measured with the finite solver
    /// (24 × 19 solves on the default 96 × 17 grid, ≈ 0.3 s optimised).
    pub fn new(geom: CageLandGeometry, options: &CageLandOptions) -> Result<Self> {
        positive("land radius", geom.radius)?;
        positive("land width", geom.width)?;
        positive("land clearance", geom.clearance)?;
        let eps_max = options.max_eccentricity;
        if !(eps_max > 0.05 && eps_max < 0.999) {
            return Err(ReynoldsError::InvalidInput {
                what: "max eccentricity",
                reason: format!("{eps_max} must lie in (0.05, 0.999)"),
            });
        }
        let (n_s, n_phi) = (
            options.eccentricity_nodes.max(4),
            options.angle_nodes.max(4),
        );
        let s_min = -(1.0f64 - 0.02).ln();
        let s_max = -(1.0 - eps_max).ln();
        let fill = options.fill_fraction;
        if !(fill > 0.0 && fill <= 1.0) {
            return Err(ReynoldsError::InvalidInput {
                what: "land fill fraction",
                reason: format!("{fill} must lie in (0, 1]"),
            });
        }
        let mut me = Self {
            geom,
            eps_max,
            fill,
            s_min,
            s_step: (s_max - s_min) / (n_s - 1) as f64,
            phi_step: 2.0 / (n_phi - 1) as f64,
            n_s,
            n_phi,
            fr: Vec::new(),
            ft: Vec::new(),
        };
        if options.finite_correction {
            me.build_table(options)?;
        }
        Ok(me)
    }

    fn build_table(&mut self, options: &CageLandOptions) -> Result<()> {
        let g = self.geom;
        let b = JournalBearing::new(g.radius, g.width, g.clearance);
        let visc = Isoviscous { mu: 1.0 };
        let opt = JournalOptions {
            n_circumferential: options.grid.0,
            n_axial: options.grid.1,
            film_start: FilmStart::Free,
            cavitated_shear: CavitatedShear::FullFilm,
            coefficients: false,
            ..Default::default()
        };
        let (n_s, n_phi) = (self.n_s, self.n_phi);
        let mut fr = vec![0.0; n_s * n_phi];
        let mut ft = vec![0.0; n_s * n_phi];
        for is in 0..n_s {
            let eps = 1.0 - (-(self.s_min + is as f64 * self.s_step)).exp();
            let mut warm = None;
            for ip in 0..n_phi {
                let u = -1.0 + ip as f64 * self.phi_step;
                let phi1 = std::f64::consts::FRAC_PI_2 * (std::f64::consts::FRAC_PI_2 * u).sin();
                // εΩ̄ = cos φ₁, ε̇ = sin φ₁ (C = 1 rad/s): journal speed 2Ω̄, radial speed c·ε̇
                let omega = 2.0 * phi1.cos() / eps;
                let op = JournalOperating {
                    journal_speed: if omega.abs() < 1e-12 { 0.0 } else { omega },
                    bearing_speed: 0.0,
                    temperature: 300.0,
                };
                let st = solve_state(
                    &b,
                    &visc,
                    &op,
                    [eps * g.clearance, 0.0],
                    [g.clearance * phi1.sin(), 0.0],
                    &opt,
                    warm.as_ref(),
                )?;
                // short-bearing force for μ = 1, C = 1
                let (ir, it) = short_bearing_integrals(eps, phi1);
                let scale = g.width.powi(3) * g.radius / (g.clearance * g.clearance);
                let mag = scale * ir.hypot(it);
                fr[is * n_phi + ip] = st.force[0] / mag;
                ft[is * n_phi + ip] = st.force[1] / mag;
                warm = Some(st);
            }
        }
        self.fr = fr;
        self.ft = ft;
        Ok(())
    }

    /// Geometry.
    pub fn geometry(&self) -> CageLandGeometry {
        self.geom
    }

    /// Fill fraction of the land clearance (1: flooded).
    pub fn fill_fraction(&self) -> f64 {
        self.fill
    }

    /// True when the finite-length correction table is present.
    pub fn is_corrected(&self) -> bool {
        !self.fr.is_empty()
    }

    fn table(&self, eps: f64, phi1: f64) -> (f64, f64) {
        let s = -(1.0 - eps).ln();
        let ts = ((s - self.s_min) / self.s_step).clamp(0.0, (self.n_s - 1) as f64 - 1e-9);
        let u = (phi1 / std::f64::consts::FRAC_PI_2).clamp(-1.0, 1.0).asin()
            / std::f64::consts::FRAC_PI_2;
        let tp = ((u + 1.0) / self.phi_step).clamp(0.0, (self.n_phi - 1) as f64 - 1e-9);
        let (is, ip) = (ts.floor() as usize, tp.floor() as usize);
        let (ws, wp) = (cr(ts - is as f64), cr(tp - ip as f64));
        let (mut r, mut t) = (0.0, 0.0);
        for (a, wa) in ws.iter().enumerate() {
            let i = (is + a).saturating_sub(1).min(self.n_s - 1);
            for (bb, wb) in wp.iter().enumerate() {
                let j = (ip + bb).saturating_sub(1).min(self.n_phi - 1);
                let w = wa * wb;
                r += w * self.fr[i * self.n_phi + j];
                t += w * self.ft[i * self.n_phi + j];
            }
        }
        (r, t)
    }

    /// Force and torque on the cage for cage-centre position `e` relative to the land centre
    /// (m), its velocity `edot` (m/s), cage and land angular speeds (rad/s, counter-clockwise
    /// positive) and viscosity (Pa·s). Non-finite inputs give a zero result; ε is clamped at
    /// `max_eccentricity`. Allocation-free; ≲ 1 µs.
    pub fn evaluate(
        &self,
        e: [f64; 2],
        edot: [f64; 2],
        cage_speed: f64,
        land_speed: f64,
        viscosity: f64,
    ) -> CageLandForce {
        let g = &self.geom;
        let inputs = [
            e[0], e[1], edot[0], edot[1], cage_speed, land_speed, viscosity,
        ];
        if inputs.iter().any(|v| !v.is_finite()) || viscosity <= 0.0 {
            return CageLandForce::default();
        }
        // journal = inner member: the cage (outer-ring land) or the land (inner-ring land)
        let (ej, ejd, wj, wb, sign) = match g.position {
            LandPosition::OuterRing => (e, edot, cage_speed, land_speed, 1.0),
            LandPosition::InnerRing => (
                [-e[0], -e[1]],
                [-edot[0], -edot[1]],
                land_speed,
                cage_speed,
                -1.0,
            ),
        };
        let c = g.clearance;
        // √(x² + y²) rather than hypot: no overflow at these magnitudes, and cheaper
        let emag = (ej[0] * ej[0] + ej[1] * ej[1]).sqrt();
        let mut eps = emag / c;
        let (ca, sa) = if emag > 0.0 {
            (ej[0] / emag, ej[1] / emag)
        } else {
            // concentric: orient the frame along the squeeze velocity
            let v = ejd[0].hypot(ejd[1]);
            if v > 0.0 {
                (ejd[0] / v, ejd[1] / v)
            } else {
                (1.0, 0.0)
            }
        };
        eps = eps.min(self.eps_max);
        let wetted = starved_half_angle(eps, self.fill);
        let er = ejd[0] * ca + ejd[1] * sa; // radial velocity
        let et = -ejd[0] * sa + ejd[1] * ca; // tangential velocity = e α̇
        let alpha_dot = if emag > 0.0 { et / emag } else { 0.0 };
        let omega_bar = 0.5 * (wj + wb) - alpha_dot;
        let (a_rot, a_sq) = (eps * omega_bar, er / c);
        let cmag = (a_rot * a_rot + a_sq * a_sq).sqrt();
        let (mut fr, mut ft) = (0.0, 0.0);
        if cmag > 0.0 {
            let phi1 = a_sq.atan2(a_rot);
            // fold φ₁ into [−π/2, π/2]: reversing Ω̄ mirrors the field (F_t changes sign)
            let (phi_f, mirror) = if phi1 > std::f64::consts::FRAC_PI_2 {
                (std::f64::consts::PI - phi1, true)
            } else if phi1 < -std::f64::consts::FRAC_PI_2 {
                (-std::f64::consts::PI - phi1, true)
            } else {
                (phi1, false)
            };
            let (ir, it) = short_bearing_integrals(eps.max(1e-12), phi_f);
            let k = viscosity * g.width.powi(3) * g.radius * cmag / (c * c);
            let flooded_mag = (ir * ir + it * it).sqrt();
            if wetted < std::f64::consts::PI {
                // starved: the short-bearing field on the wetted arc, scaled by the finite
                // correction's magnitude of the flooded film (module doc)
                let (sr, st) = short_bearing_integrals_wetted(eps.max(1e-12), phi_f, wetted);
                let correction = if self.fr.is_empty() {
                    1.0
                } else {
                    let (tr, tt) = self.table(eps.max(0.02), phi_f);
                    (tr * tr + tt * tt).sqrt()
                };
                fr = k * correction * sr;
                ft = k * correction * st;
            } else if self.fr.is_empty() {
                fr = k * ir;
                ft = k * it;
            } else {
                let (tr, tt) = self.table(eps.max(0.02), phi_f);
                let mag = k * flooded_mag;
                fr = mag * tr;
                ft = mag * tt;
            }
            if mirror {
                ft = -ft;
            }
        }
        // force on the journal in the input frame
        let fj = [fr * ca - ft * sa, fr * sa + ft * ca];
        // torques: Couette shear of the wetted arc + pressure couple ∓ e F_t / 2
        let couette = couette_land_torque(viscosity, wj - wb, g.radius, g.width, c, eps)
            * wetted_shear_fraction(eps, wetted);
        let e_used = eps * c;
        let m_journal = -couette - 0.5 * e_used * ft;
        let m_bearing = couette - 0.5 * e_used * ft;
        let (force, torque) = if sign > 0.0 {
            (fj, m_journal)
        } else {
            ([-fj[0], -fj[1]], m_bearing)
        };
        CageLandForce {
            force_n: force,
            torque_nm: torque,
            eccentricity: eps,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed-form half-period integrals equal direct quadrature (Booker-type reduction
    /// formulas for ∫dϑ/(1 − ε cos ϑ)ⁿ).
    #[test]
    fn integrals_match_quadrature() {
        for &eps in &[0.03, 0.3, 0.7, 0.95] {
            for &phi in &[-1.2, -0.3, 0.0, 0.8, 1.5] {
                let (r, t) = short_bearing_integrals(eps, phi);
                let f = |th: f64| {
                    let d = 1.0 - eps * th.cos();
                    let w = (th - phi).sin() / (d * d * d);
                    (w * th.cos(), w * th.sin())
                };
                // 64 panels of the 16-point rule
                let (mut qr, mut qt) = (0.0, 0.0);
                let (a, b) = (phi - std::f64::consts::PI, phi);
                for p in 0..64 {
                    let lo = a + (b - a) * p as f64 / 64.0;
                    let hi = a + (b - a) * (p + 1) as f64 / 64.0;
                    let (x, y) = gauss2(f, lo, hi);
                    qr += x;
                    qt += y;
                }
                let m = qr.hypot(qt);
                assert!(
                    (r - qr).abs() < 1e-9 * m && (t - qt).abs() < 1e-9 * m,
                    "{eps} {phi}: {r} {qr} {t} {qt}"
                );
            }
        }
        // Ocvirk: φ₁ = 0 gives I_r = −2ε/(1−ε²)², I_t = π/(2(1−ε²)^{3/2})
        let eps: f64 = 0.6;
        let (r, t) = short_bearing_integrals(eps, 0.0);
        assert!((r + 2.0 * eps / (1.0 - eps * eps).powi(2)).abs() < 1e-12);
        assert!((t - std::f64::consts::PI / (2.0 * (1.0 - eps * eps).powf(1.5))).abs() < 1e-12);
    }

    /// The wetted-arc integrals equal quadrature over the overlap of the pressurised half period
    /// and the wetted arc (midpoint rule with an indicator: error ≈ the step, 2e-4 asserted), and
    /// tend to the flooded integrals as ϑ_w → π.
    #[test]
    fn wetted_integrals_match_quadrature() {
        for &eps in &[0.01, 0.3, 0.7, 0.97] {
            for &phi in &[-1.2, -0.3, 0.0, 0.8, 1.5] {
                for &w in &[0.2, 0.9, 2.0, 3.0] {
                    let (r, t) = short_bearing_integrals_wetted(eps, phi, w);
                    // midpoint rule over the half period with the indicator cos ϑ > cos ϑ_w
                    let (mut qr, mut qt) = (0.0, 0.0);
                    let n = 400_000;
                    let h = std::f64::consts::PI / n as f64;
                    let f = integrand(eps, phi);
                    for i in 0..n {
                        let x = phi - std::f64::consts::PI + (i as f64 + 0.5) * h;
                        if x.cos() > w.cos() {
                            let (a, b) = f(x);
                            qr += a * h;
                            qt += b * h;
                        }
                    }
                    let m = short_bearing_integrals(eps, phi);
                    let m = m.0.hypot(m.1);
                    assert!(
                        (r - qr).abs() < 2e-4 * m && (t - qt).abs() < 2e-4 * m,
                        "{eps} {phi} {w}: {r} {qr} {t} {qt}"
                    );
                }
                let full = short_bearing_integrals(eps, phi);
                let near = short_bearing_integrals_wetted(eps, phi, std::f64::consts::PI - 1e-9);
                let m = full.0.hypot(full.1);
                assert!((full.0 - near.0).abs() < 1e-6 * m && (full.1 - near.1).abs() < 1e-6 * m);
            }
        }
    }

    /// ϑ_w solves ϑ − ε sin ϑ = π f; the shear share equals quadrature of 1/D over the arc.
    #[test]
    fn starved_arc_and_shear_share() {
        assert_eq!(starved_half_angle(0.5, 1.0), std::f64::consts::PI);
        for &eps in &[0.0, 0.3, 0.9, 0.97, 0.98] {
            for &f in &[0.001, 0.05, 0.3, 0.7, 0.999] {
                let w = starved_half_angle(eps, f);
                let g = w - eps * w.sin() - std::f64::consts::PI * f;
                assert!(g.abs() < 1e-12, "{eps} {f}: {w} {g}");
                let (mut q, mut full) = (0.0, 0.0);
                let n = 20000;
                for i in 0..n {
                    let x = -w + 2.0 * w * (i as f64 + 0.5) / n as f64;
                    q += 2.0 * w / n as f64 / (1.0 - eps * x.cos());
                    let y = std::f64::consts::TAU * (i as f64 + 0.5) / n as f64;
                    full += std::f64::consts::TAU / n as f64 / (1.0 - eps * y.cos());
                }
                let share = wetted_shear_fraction(eps, w);
                assert!(
                    (share - q / full).abs() < 1e-4,
                    "{eps} {f}: {share} {}",
                    q / full
                );
            }
        }
    }

    /// A starved land carries less force and torque than the flooded one; f → 1 is continuous.
    #[test]
    fn starved_land_is_weaker_and_continuous() {
        let g = CageLandGeometry {
            radius: 0.1,
            width: 0.01,
            clearance: 2.5e-4,
            position: LandPosition::InnerRing,
        };
        let land = |fill: f64| {
            CageLand::new(
                g,
                &CageLandOptions {
                    finite_correction: false,
                    fill_fraction: fill,
                    ..CageLandOptions::default()
                },
            )
            .unwrap()
        };
        let at = |l: &CageLand| l.evaluate([0.0, 2.4e-4], [0.0, 0.0], 400.0, 850.0, 0.005);
        let flooded = at(&land(1.0));
        let almost = at(&land(1.0 - 1e-9));
        let starved = at(&land(0.05));
        let mag = |f: &CageLandForce| f.force_n[0].hypot(f.force_n[1]);
        assert!((mag(&almost) - mag(&flooded)).abs() < 1e-6 * mag(&flooded));
        assert!((almost.torque_nm - flooded.torque_nm).abs() < 1e-6 * flooded.torque_nm.abs());
        assert!(mag(&starved) < mag(&flooded));
        assert!(starved.torque_nm.abs() < flooded.torque_nm.abs());
        assert!(
            CageLand::new(
                g,
                &CageLandOptions {
                    fill_fraction: 0.0,
                    ..CageLandOptions::default()
                }
            )
            .is_err()
        );
    }
}
