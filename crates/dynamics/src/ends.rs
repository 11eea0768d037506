//! Roller end faces against annular faces of revolution: ring ribs (pair 56 of SPEC §3.2, the
//! seed's "roller ends ↔ inner-ring ribs"; outer-ring ribs likewise) and cage pocket faces
//! (pair 54). Geometry of SPEC §1.2 "Ribs" and §1.3 (roller end faces), force laws of SPEC §3.3
//! (Table "contact pairs", rows 56 and 54), friction of SPEC §3.4 with ⚠ F-23, regime of §6.7.
//!
//! ## Geometry
//! A face belongs to a body with axis `A` and origin `O` (ring or cage). It is the surface of
//! revolution `ζ = ζ_f − s·prot(ρ)` (axial coordinate `ζ`, distance `ρ` from the axis), where
//! `s = ±1` is the side of the face (`+1`: the face stands on the `+A` side of the roller and
//! pushes it towards `−A`), restricted to the radial band `ρ_lo ≤ ρ ≤ ρ_hi` (raceway … rib rim
//! minus its edge break; cage bore … outside diameter). The protrusion towards the roller is
//! `prot(ρ) = t (ρ − ρ_c) − κ (ρ − ρ_c)²/2`: `t = 0, κ = 0` flat; `t = ±tan α` cone; `κ = 1/R`
//! convex torus with crest at `ρ_c`, `κ = −1/R` concave torus. `ζ_f` is the face position at
//! `ρ_c` (rib spacing / 2 or axial pocket size / 2 from the body's mid-plane).
//!
//! The roller end `e = s` of a roller with centre `c`, axis `a`, length `L` is the disc of radius
//! `r_e = D_w/2 − drop(L/2) − r_b` (profile drop at the end = chamfer, `r_b` the roller's edge
//! break) centred at `P = c + e (L/2) a`; a spherical end face `R_s` recedes by
//! `(x² + y²)/(2R_s)` at distance `√(x² + y²)` from the axis. The approach of the end point
//! `X = P + x e₁ + y e₂` (`e₁` the radial direction projected on the end plane, `e₂ = a × e₁`) is
//! `δ(X) = s(ζ(X) − ζ_f) + prot(ρ(X))` with `ρ(X) ≈ ρ_P + βx + y²/(2ρ_P)` (`β = e₁·e_ρ`). The
//! contact point is the deepest point of the end disc inside the band: for fixed `x` the best `y`
//! is explicit (`y* = clamp(qR_s/(a·A), ±Y(x))`, `Y(x)` the half-chord limited by the disc and by
//! the upper band edge), and the remaining function of `x` is concave for flat, conical and convex
//! faces with flat or spherical ends: a flat end on a flat or conical face has its maximum at one
//! of five closed-form candidates (stationary points of the disc and band pieces, their kink, the
//! interval ends). Curved pairs (crowned end or curved face) split the interval at the kinks of
//! the function, all in closed form (where the disc and band half-chords cross, and where the
//! free `y₀ = q/(κ_s k_a)` of a crowned end meets either), and take the best of the interval
//! ends, the kinks and, on each smooth piece whose analytic slope falls from positive to
//! negative, its stationary point: exact in one step where `y` is free (the slope is linear in
//! `x`), otherwise by Newton with the analytic second derivative, safeguarded by bisection
//! inside the sign change. Nothing is carried from one call to the next. This is exact when `f`
//! is concave on each piece (flat, conical and convex faces); on a concave torus a piece whose
//! slope keeps its sign between its ends counts as monotone. The former search (five samples, 40
//! golden-section steps) is the test oracle. This is the seed's "contact on
//! the rib edge / on the roller edge" of SPEC §3.3 (Fig. 2.5 variants): a skewed flat end touches
//! with its edge, and it touches the rib at its rim when the deepest point would lie above it.
//!
//! ## Forces
//! `F_n = K_p δⁿ + STEP(δ, 0, 0, d, C_h) δ̇` clamped ≥ 0 along the face normal (the gradient of
//! `δ`), acting at `X`; friction `−μ F_n v̂_τ` with the relative sliding velocity at `X`.
//! μ: constant boundary 0.065 (regularised below `v_s`), Kragelsky μ_bd(s) (seed 000 (2.10)) or,
//! for the ribs, EHL point-contact traction when the contact spot (radius `√(R δ)`) stays inside
//! the overlap of end face and rib face (SPEC §6.7), boundary friction otherwise.

use crate::kinematics::RollerKinematics;
use crate::parameters::{EndFriction, RollerEndParameters};
use crate::vec3::{V3, add, axpy, cross, dot, norm, perp, power, scale, sub};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_lubrication::traction::kragelsky;
use rolldyn_lubrication::{ContactGeometry, ContactState, TractionModel, traction};

/// Friction regime of a roller-end contact (SPEC §6.7), reported per roller.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EndContactRegime {
    /// no contact
    #[default]
    None,
    /// boundary friction (constant μ or Kragelsky μ_bd(s))
    Boundary,
    /// film (EHL point-contact traction): the contact spot stays inside the face overlap
    Elastohydrodynamic,
}

/// One annular face of revolution (rib face or cage pocket face) in its body's frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FaceGeometry {
    /// side s = ±1
    pub side: f64,
    /// axial position of the face at ρ_c from the body origin, m
    pub zeta: f64,
    /// radial band of the face, m
    pub rho_lo: f64,
    pub rho_hi: f64,
    /// the face edge whose distance is reported (rib rim), m
    pub rho_edge: f64,
    /// reference radius (crest), m
    pub rho_c: f64,
    /// linear protrusion slope t
    pub slope: f64,
    /// curvature κ of the profile, 1/m (convex > 0)
    pub curvature: f64,
}

impl FaceGeometry {
    /// Largest protrusion `prot(ρ)` over the band (bound of the approach).
    fn max_protrusion(&self) -> f64 {
        let prot = |u: f64| self.slope * u - 0.5 * self.curvature * u * u;
        let (u0, u1) = (self.rho_lo - self.rho_c, self.rho_hi - self.rho_c);
        let mut m = prot(u0).max(prot(u1));
        if self.curvature > 0.0 {
            let uv = (self.slope / self.curvature).clamp(u0, u1);
            m = m.max(prot(uv));
        }
        m
    }
}

/// Roller end geometry shared by all end contacts.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EndGeometry {
    /// half length L/2, m
    pub half_length: f64,
    /// end disc radius r_e, m
    pub radius: f64,
    /// 1/R_s of a spherical end face (0 flat), 1/m
    pub sphere_curvature: f64,
}

/// A rigid body carrying faces: origin, velocity, axis, angular velocity.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BodyKin {
    pub o: V3,
    pub v: V3,
    pub axis: V3,
    pub omega: V3,
}

/// Deepest point of a roller end in a face band.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Deepest {
    pub delta: f64,
    pub point: V3,
    /// unit normal pushing the roller away from the face
    pub normal: V3,
    /// radius of the point from the body axis, m
    pub rho: f64,
    /// distance of the point from the roller axis (in the end-face plane), m
    pub end_radius: f64,
    /// distance of the point from the end disc rim and from the band edges (min), m
    pub margin: f64,
}

/// Axial position and tilt of a roller relative to the axis of a body that carries end faces.
/// It is the same for every face of that body, so the right-hand side computes it once per
/// roller and body and skips the faces that [`AxialReach::bound`] clears (most faces, most of
/// the time).
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxialReach {
    /// axial position of the roller centre `(c − O)·A`, m
    zeta_c: f64,
    /// `a·A`
    cos_a: f64,
    /// how far the end disc reaches axially by its tilt, `r_e sin∠(a, A)`, m
    tilt: f64,
}

impl AxialReach {
    #[inline]
    pub(crate) fn new(body: &BodyKin, end: &EndGeometry, c: V3, a: V3) -> Self {
        let cos_a = dot(a, body.axis);
        Self {
            zeta_c: dot(sub(c, body.o), body.axis),
            cos_a,
            tilt: end.radius * (1.0 - cos_a * cos_a).max(0.0).sqrt(),
        }
    }

    /// Upper bound of the approach of the roller end facing `face`; ≤ 0: no contact. The end
    /// centre `P = c + s (L/2) a` stands at `s(ζ_P − ζ_f) = s(ζ_c − ζ_f) + (L/2) a·A` from the
    /// face, and the disc tilts by at most `r_e sin∠(a, A)` towards it (in the (e1, e2) basis
    /// of [`deepest_within`] this is `r_e √(p² + q²)`, since `p² + q² = 1 − (a·A)²`).
    #[inline]
    pub(crate) fn bound(&self, face: &FaceGeometry, end: &EndGeometry) -> f64 {
        face.side * (self.zeta_c - face.zeta)
            + end.half_length * self.cos_a
            + self.tilt
            + face.max_protrusion()
    }
}

/// [`AxialReach`] of every roller on one body (struct of arrays), computed in one vector loop
/// with the expressions of [`AxialReach::new`].
#[derive(Debug, Clone)]
pub(crate) struct ReachColumns {
    zeta_c: Vec<f64>,
    cos_a: Vec<f64>,
    tilt: Vec<f64>,
}

impl ReachColumns {
    /// Columns for `rollers` rollers.
    pub(crate) fn new(rollers: usize) -> Self {
        Self {
            zeta_c: vec![0.0; rollers],
            cos_a: vec![1.0; rollers],
            tilt: vec![0.0; rollers],
        }
    }

    /// The reach on `body` of the rollers with centres `centre` and unit axes `axis` (columns
    /// x, y, z).
    pub(crate) fn compute(
        &mut self,
        body: &BodyKin,
        end: &EndGeometry,
        centre: &[Vec<f64>; 3],
        axis: &[Vec<f64>; 3],
    ) {
        let z = self.zeta_c.len();
        let [cx, cy, cz] = centre.each_ref().map(|c| &c[..z]);
        let [ax, ay, az] = axis.each_ref().map(|c| &c[..z]);
        let (zeta_c, cos_a, tilt) = (
            &mut self.zeta_c[..z],
            &mut self.cos_a[..z],
            &mut self.tilt[..z],
        );
        for j in 0..z {
            let r = AxialReach::new(body, end, [cx[j], cy[j], cz[j]], [ax[j], ay[j], az[j]]);
            (zeta_c[j], cos_a[j], tilt[j]) = (r.zeta_c, r.cos_a, r.tilt);
        }
    }

    /// The reach of roller `j`.
    #[inline]
    pub(crate) fn get(&self, j: usize) -> AxialReach {
        AxialReach {
            zeta_c: self.zeta_c[j],
            cos_a: self.cos_a[j],
            tilt: self.tilt[j],
        }
    }
}

/// Deepest point of the roller end facing `face` inside the face band, or `None` when the band
/// and the end disc do not overlap radially.
#[cfg(test)]
pub(crate) fn deepest(
    face: &FaceGeometry,
    end: &EndGeometry,
    body: &BodyKin,
    c: V3,
    a: V3,
) -> Option<Deepest> {
    deepest_within(face, end, body, &AxialReach::new(body, end, c, a), c, a)
}

/// [`deepest`] with the roller's [`AxialReach`] on `body` computed by the caller.
pub(crate) fn deepest_within(
    face: &FaceGeometry,
    end: &EndGeometry,
    body: &BodyKin,
    reach: &AxialReach,
    c: V3,
    a: V3,
) -> Option<Deepest> {
    deepest_by(face, end, body, reach, c, a, |f| f.deepest_curved())
}

/// [`deepest`] by the former golden-section search for curved pairs (the test oracle).
#[cfg(test)]
pub(crate) fn deepest_golden(
    face: &FaceGeometry,
    end: &EndGeometry,
    body: &BodyKin,
    c: V3,
    a: V3,
) -> Option<Deepest> {
    let reach = AxialReach::new(body, end, c, a);
    deepest_by(face, end, body, &reach, c, a, |f| f.deepest_curved_golden())
}

/// [`deepest_within`] with the maximiser `curved` for crowned ends or curved faces.
fn deepest_by(
    face: &FaceGeometry,
    end: &EndGeometry,
    body: &BodyKin,
    reach: &AxialReach,
    c: V3,
    a: V3,
    curved: impl FnOnce(&EndOnFace) -> (f64, f64, f64),
) -> Option<Deepest> {
    // cheap upper bound first
    if reach.bound(face, end) <= 0.0 {
        return None;
    }
    let frame = EndOnFace::new(face, end, body, reach, c, a)?;
    let (x, y, d) = if frame.cs == 0.0 && face.curvature == 0.0 {
        frame.deepest_flat()
    } else {
        curved(&frame)
    };
    frame.contact(x, y, d)
}

/// Most kinks of the approach along x inside the band ([`EndOnFace::breakpoints`]).
const MAX_BREAKPOINTS: usize = 5;

/// Sub-intervals searched on a rim piece that need not be concave ([`EndOnFace::deepest_curved`]).
const NONCONCAVE_PARTS: usize = 4;

/// Newton on the slope of the approach stops at a step of this fraction of the end disc
/// radius ([`EndOnFace::stationary`]): 10⁻¹² of r_e ≈ 10⁻¹⁴ m.
const NEWTON_X_TOLERANCE: f64 = 1e-12;

/// Cap of the Newton–bisection iterations (bisection alone halves a 10 mm bracket to 10⁻²⁰ m).
const NEWTON_MAX_ITERATIONS: usize = 60;

/// How the best `y` follows `x` on one smooth piece of the approach ([`EndOnFace::approach`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Chord {
    /// crowned end inside both limits: `y = y₀ = q/(κ_s k_a)`
    Free,
    /// at the end disc: `|y| = √(r² − x²)`
    Disc,
    /// at the upper band edge: `|y| = √(2ρ_P(ρ_hi − ρ_P − βx))`
    Band,
}

/// The roller end disc seen from one face: the end centre P, the radial direction e_ρ of P
/// from the body axis A, the in-disc basis (e1 ⟂ a in the (e_ρ, a) plane, e2 = a × e1) and
/// the approach δ(x, y) of the disc point P + x e1 + y e2 to the face, linearised in the
/// tilt (p, q) with the end's spherical crown.
struct EndOnFace<'a> {
    face: &'a FaceGeometry,
    /// end disc radius r_e
    r: f64,
    /// spherical curvature of the end face
    cs: f64,
    /// |cos ∠(a, A)|, bounded away from zero
    ka: f64,
    /// body axis A
    big_a: V3,
    p: V3,
    e_r: V3,
    e1: V3,
    e2: V3,
    /// ρ_P, radius of P from the body axis
    rho_p: f64,
    /// |e_ρ ⟂ a|: radial growth of ρ per unit x
    beta: f64,
    /// axial approach of P
    delta0: f64,
    /// tilt slopes of the approach along e1, e2
    p_lin: f64,
    q_lin: f64,
    /// the x interval where the disc overlaps the face band
    xa: f64,
    xb: f64,
    flat_face: bool,
}

impl<'a> EndOnFace<'a> {
    /// The frame, or `None` when P is on the body axis, the end is tilted past 60° from the
    /// radial plane, or the disc misses the face band radially.
    fn new(
        face: &'a FaceGeometry,
        end: &EndGeometry,
        body: &BodyKin,
        reach: &AxialReach,
        c: V3,
        a: V3,
    ) -> Option<Self> {
        let s = face.side;
        let big_a = body.axis;
        let p = axpy(c, s * end.half_length, a);
        let dp = sub(p, body.o);
        let zeta_p = dot(dp, big_a);
        let delta0 = s * (zeta_p - face.zeta);
        let r = end.radius;
        let radial = axpy(dp, -zeta_p, big_a);
        let rho_p = norm(radial);
        if rho_p <= 0.0 {
            return None;
        }
        let e_r = scale(radial, 1.0 / rho_p);
        let e1_raw = perp(e_r, a);
        let beta = norm(e1_raw);
        if beta < 0.5 {
            return None;
        }
        let e1 = scale(e1_raw, 1.0 / beta);
        let e2 = cross(a, e1);
        let xa = (-r).max((face.rho_lo - rho_p) / beta);
        let xb = r.min((face.rho_hi - rho_p) / beta);
        if xa >= xb {
            return None;
        }
        Some(Self {
            face,
            r,
            cs: end.sphere_curvature,
            ka: reach.cos_a.abs().max(1e-6),
            big_a,
            p,
            e_r,
            e1,
            e2,
            rho_p,
            beta,
            delta0,
            p_lin: s * dot(e1, big_a),
            q_lin: s * dot(e2, big_a),
            xa,
            xb,
            flat_face: face.slope == 0.0 && face.curvature == 0.0,
        })
    }

    /// The best y and the approach for a fixed x: `(δ, y)`.
    #[inline]
    fn approach(&self, x: f64) -> (f64, f64) {
        let (face, r, rho_p, cs, ka) = (self.face, self.r, self.rho_p, self.cs, self.ka);
        let disc = (r * r - x * x).max(0.0).sqrt();
        let band = (2.0 * rho_p * (face.rho_hi - rho_p - self.beta * x))
            .max(0.0)
            .sqrt();
        let ymax = disc.min(band);
        let y = if cs > 0.0 {
            (self.q_lin / (cs * ka)).clamp(-ymax, ymax)
        } else if self.q_lin >= 0.0 {
            ymax
        } else {
            -ymax
        };
        // the face's protrusion at the point (zero on a flat face: no division on that path)
        let prot = if self.flat_face {
            0.0
        } else {
            let u = rho_p + self.beta * x + y * y / (2.0 * rho_p) - face.rho_c;
            face.slope * u - 0.5 * face.curvature * u * u
        };
        let d =
            self.delta0 + self.p_lin * x + self.q_lin * y - 0.5 * cs * ka * (x * x + y * y) + prot;
        (d, y)
    }

    /// Flat end on a flat or conical face: f(x) = δ₀ + p'x + |q| min(D(x), B(x)) with the disc
    /// half-chord D = √(r² − x²) and the band half-chord B = √(2ρ_P(Δ − βx)), concave; its
    /// maximum is at a stationary point of either piece, at their kink or at an end of the
    /// interval — evaluate all candidates (each is feasible, so the best is exact). Returns
    /// `(x, y, δ)`.
    fn deepest_flat(&self) -> (f64, f64, f64) {
        let (r, rho_p, beta, xa, xb) = (self.r, self.rho_p, self.beta, self.xa, self.xb);
        let pp = self.p_lin + self.face.slope * beta;
        let qa = self.q_lin.abs();
        let dlt = self.face.rho_hi - rho_p;
        let mut cand = [xa, xb, xa, xa, xa];
        let hyp = (pp * pp + qa * qa).sqrt();
        if hyp > 0.0 {
            cand[2] = r * pp / hyp;
        }
        if pp > 0.0 {
            let bb = qa * rho_p * beta / pp;
            cand[3] = (dlt - bb * bb / (2.0 * rho_p)) / beta;
        }
        let rb = rho_p * beta;
        let disc = rb * rb - 2.0 * rho_p * dlt + r * r;
        if disc >= 0.0 {
            cand[4] = rb - disc.sqrt();
        }
        let (mut x, mut d, mut y) = (xa, f64::NEG_INFINITY, 0.0);
        for xc in cand {
            let xc = xc.clamp(xa, xb);
            let (dc, yc) = self.approach(xc);
            if dc > d {
                (x, d, y) = (xc, dc, yc);
            }
        }
        (x, y, d)
    }

    /// Crowned end or curved face: the maximum of the piecewise smooth `f(x) = δ(x, y*(x))`
    /// over `[x_a, x_b]`. The pieces are delimited by closed-form breakpoints ([`Self::
    /// breakpoints`]); on each piece `y*` follows one rule ([`Chord`]) and `f` is smooth with
    /// the analytic slope of [`Self::slope_on`]. The maximum is the best of the interval ends,
    /// the breakpoints (kinks: the rim, the switch of `y*` between free and clamped) and, on each
    /// piece whose slope falls from positive to negative, the stationary point found by
    /// [`Self::stationary`]. Returns `(x, y, δ)`.
    fn deepest_curved(&self) -> (f64, f64, f64) {
        let mut points = [0.0; 2 + MAX_BREAKPOINTS];
        points[0] = self.xa;
        let n_inner = self.breakpoints(&mut points[1..=MAX_BREAKPOINTS]);
        points[n_inner + 1] = self.xb;
        let points = &mut points[..n_inner + 2];
        points[1..=n_inner].sort_unstable_by(f64::total_cmp);
        let (mut d, mut y) = self.approach(self.xa);
        let mut x = self.xa;
        let mut consider = |xc: f64| {
            let (dc, yc) = self.approach(xc);
            if dc > d {
                (x, d, y) = (xc, dc, yc);
            }
        };
        for w in points.windows(2) {
            let (lo, hi) = (w[0], w[1]);
            if hi <= lo {
                continue;
            }
            let chord = self.chord_at(0.5 * (lo + hi));
            // a piece on the disc rim may bend both ways when the face leans away from the
            // roller (t < 0) or is a concave torus: search its quarters
            let parts =
                if chord == Chord::Disc && (self.face.slope < 0.0 || self.face.curvature < 0.0) {
                    NONCONCAVE_PARTS
                } else {
                    1
                };
            let step = (hi - lo) / parts as f64;
            for k in 0..parts {
                let a = lo + step * k as f64;
                let b = if k + 1 == parts { hi } else { a + step };
                if let Some(xs) = self.stationary(a, b, chord) {
                    consider(xs);
                }
                consider(b);
            }
        }
        (x, y, d)
    }

    /// The kinks of `f(x)` inside `(x_a, x_b)`, written to `out`; returns their number. The disc
    /// and band half-chords cross where `x² − 2ρ_Pβx + 2ρ_PΔ − r² = 0` (`Δ = ρ_hi − ρ_P`); with a
    /// crowned end the free `y₀ = q/(κ_s k_a)` meets the disc at `x = ±√(r² − y₀²)` and the band
    /// at `x = (Δ − y₀²/(2ρ_P))/β`.
    fn breakpoints(&self, out: &mut [f64]) -> usize {
        let (r, rho_p, beta) = (self.r, self.rho_p, self.beta);
        let dlt = self.face.rho_hi - rho_p;
        let mut cand = [f64::NAN; MAX_BREAKPOINTS];
        let rb = rho_p * beta;
        let disc = rb * rb - 2.0 * rho_p * dlt + r * r;
        if disc >= 0.0 {
            let root = disc.sqrt();
            cand[0] = rb - root;
            cand[1] = rb + root;
        }
        if self.cs > 0.0 {
            let y0 = self.free_y();
            if y0 != 0.0 {
                let on_disc = (r * r - y0 * y0).max(0.0).sqrt();
                cand[2] = -on_disc;
                cand[3] = on_disc;
                cand[4] = (dlt - y0 * y0 / (2.0 * rho_p)) / beta;
            }
        }
        let mut n = 0;
        for xc in cand {
            if xc > self.xa && xc < self.xb {
                out[n] = xc;
                n += 1;
            }
        }
        n
    }

    /// The unconstrained best y of a crowned end, `y₀ = q/(κ_s k_a)` (as in [`Self::approach`]).
    #[inline]
    fn free_y(&self) -> f64 {
        self.q_lin / (self.cs * self.ka)
    }

    /// The rule that sets `y*` at `x` in [`Self::approach`].
    fn chord_at(&self, x: f64) -> Chord {
        let (face, r, rho_p) = (self.face, self.r, self.rho_p);
        let disc = (r * r - x * x).max(0.0).sqrt();
        let band = (2.0 * rho_p * (face.rho_hi - rho_p - self.beta * x))
            .max(0.0)
            .sqrt();
        if self.cs > 0.0 && self.free_y().abs() <= disc.min(band) {
            Chord::Free
        } else if disc <= band {
            Chord::Disc
        } else {
            Chord::Band
        }
    }

    /// `(f'(x), f''(x))` of `f(x) = δ(x, y*(x))` with `y*` set by `chord` (analytic, from
    /// [`Self::approach`]; `u = ρ − ρ_c`, `prot' = t − κu`, `c = κ_s k_a`):
    /// * free `y₀`: `f' = p − c x + β prot'`, `f'' = −c − κβ²`;
    /// * disc `|y| = D = √(r² − x²)`: `f' = p − |q|x/D + prot' (β − x/ρ_P)`,
    ///   `f'' = −|q|r²/D³ − κ(β − x/ρ_P)² − prot'/ρ_P`;
    /// * band `|y| = B = √(2ρ_P(Δ − βx))` (ρ = ρ_hi): `f' = p − |q|ρ_Pβ/B − c(x − ρ_Pβ)`,
    ///   `f'' = −|q|(ρ_Pβ)²/B³ − c`.
    ///
    /// At a chord end (`D` or `B` = 0) the slope is infinite (NaN when `q = 0`).
    fn slope_on(&self, x: f64, chord: Chord) -> (f64, f64) {
        let face = self.face;
        let (r, rho_p, beta, p) = (self.r, self.rho_p, self.beta, self.p_lin);
        let (qa, c, kappa) = (self.q_lin.abs(), self.cs * self.ka, face.curvature);
        let dprot = |u: f64| face.slope - kappa * u;
        match chord {
            Chord::Free => {
                let y0 = self.free_y();
                let u = rho_p + beta * x + y0 * y0 / (2.0 * rho_p) - face.rho_c;
                (p - c * x + beta * dprot(u), -c - kappa * beta * beta)
            }
            Chord::Disc => {
                let d = (r * r - x * x).max(0.0).sqrt();
                let u = rho_p + beta * x + (r * r - x * x) / (2.0 * rho_p) - face.rho_c;
                let du = beta - x / rho_p;
                let dp = dprot(u);
                (
                    p - qa * x / d + dp * du,
                    -qa * r * r / (d * d * d) - kappa * du * du - dp / rho_p,
                )
            }
            Chord::Band => {
                let b = (2.0 * rho_p * (face.rho_hi - rho_p - beta * x))
                    .max(0.0)
                    .sqrt();
                let rb = rho_p * beta;
                (
                    p - qa * rb / b - c * (x - rb),
                    -qa * rb * rb / (b * b * b) - c,
                )
            }
        }
    }

    /// The stationary point of `f` on `(lo, hi)` with `y*` set by `chord`, when the slope falls
    /// from positive at `lo` to negative at `hi` (an infinite or undefined slope at a chord end
    /// counts as rising at `lo` and falling at `hi`); `None` otherwise. Newton on `f' = 0` from
    /// the secant root (exact in one step on a free piece, where `f'` is linear), kept inside the
    /// bracket of the sign change, with bisection whenever Newton leaves it or `f'' ≥ 0`. It stops
    /// when a step is at most [`NEWTON_X_TOLERANCE`] of the disc radius: Newton's error is then
    /// of the order of the step squared, and the approach at a smooth maximum is off by
    /// `|f''| dx²/2` — below the rounding of δ.
    fn stationary(&self, lo: f64, hi: f64, chord: Chord) -> Option<f64> {
        let g_lo = self.slope_on(lo, chord).0;
        let g_hi = self.slope_on(hi, chord).0;
        if g_lo <= 0.0 || g_hi >= 0.0 {
            return None;
        }
        let (mut lo, mut hi) = (lo, hi);
        let tol = NEWTON_X_TOLERANCE * self.r;
        let mut x = lo - g_lo * (hi - lo) / (g_hi - g_lo);
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        for _ in 0..NEWTON_MAX_ITERATIONS {
            let (g, dg) = self.slope_on(x, chord);
            if g > 0.0 {
                lo = x;
            } else if g < 0.0 {
                hi = x;
            } else {
                return Some(x);
            }
            let mut next = x - g / dg;
            if !(dg < 0.0 && next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            let step = (next - x).abs();
            x = next;
            if step <= tol {
                break;
            }
        }
        Some(x)
    }

    /// The former search for the crowned end or curved face, kept as the test oracle: bracket
    /// the maximum by the best of a few samples, refine by 40 golden-section steps, and compare
    /// with the interval ends. Returns `(x, y, δ)`.
    #[cfg(test)]
    fn deepest_curved_golden(&self) -> (f64, f64, f64) {
        use rolldyn_numerics::maximize1d::{GoldenSectionOptions, golden_section_max};

        const SAMPLES: usize = 4;
        let (xa, xb) = (self.xa, self.xb);
        let h = (xb - xa) / SAMPLES as f64;
        let mut best = 0;
        let mut best_d = f64::NEG_INFINITY;
        for k in 0..=SAMPLES {
            let d = self.approach(xa + h * k as f64).0;
            if d > best_d {
                best_d = d;
                best = k;
            }
        }
        let lo = xa + h * best.saturating_sub(1) as f64;
        let hi = (xa + h * (best + 1) as f64).min(xb);
        let search = golden_section_max(
            |x| self.approach(x).0,
            lo,
            hi,
            &GoldenSectionOptions::default(),
        );
        let (lo, hi) = search.bracket;
        let mut x = 0.5 * (lo + hi);
        let (mut d, mut y) = self.approach(x);
        for xe in [xa, xb] {
            let (de, ye) = self.approach(xe);
            if de > d {
                (x, d, y) = (xe, de, ye);
            }
        }
        (x, y, d)
    }

    /// Contact point, normal and margins of the deepest point (x, y) with approach `d`.
    fn contact(&self, x: f64, y: f64, d: f64) -> Option<Deepest> {
        if d <= 0.0 {
            return None;
        }
        let face = self.face;
        let rho = self.rho_p + self.beta * x + y * y / (2.0 * self.rho_p);
        let point = axpy(axpy(self.p, x, self.e1), y, self.e2);
        // normal: −∇δ = −(s A + prot'(ρ) e_ρ)
        let u = rho - face.rho_c;
        let dprot = face.slope - face.curvature * u;
        let grad = axpy(scale(self.big_a, face.side), dprot, self.e_r);
        let normal = scale(grad, -1.0 / norm(grad));
        let end_radius = (x * x + y * y).sqrt();
        let margin = (self.r - end_radius)
            .min(face.rho_hi - rho)
            .min(rho - face.rho_lo);
        Some(Deepest {
            delta: d,
            point,
            normal,
            rho,
            end_radius,
            margin,
        })
    }
}

/// Result of one roller-end contact.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct EndForce {
    /// force on the roller, N
    pub force: V3,
    /// contact point, m
    pub point: V3,
    /// moment on the roller about its centre, N·m
    pub moment: V3,
    /// moment on the face body about its origin, N·m
    pub body_moment: V3,
    /// normal force, N
    pub normal: f64,
    /// sliding speed, m/s
    pub sliding: f64,
    /// friction coefficient
    pub mu: f64,
    /// approach, m
    pub delta: f64,
    /// distance of the contact point from the face edge `rho_edge`, m
    pub edge_distance: f64,
    /// distance of the contact point from the roller axis and from the face body's axis, m
    pub end_radius: f64,
    pub body_radius: f64,
    pub regime: EndContactRegime,
    /// film parameter Λ of the EHL traction (NaN in boundary friction)
    pub lambda: f64,
}

/// Lubrication data for the EHL option of the rib contact.
pub(crate) struct EndLubrication<'a> {
    pub model: &'a TractionModel,
    /// reduced radius of the end/face pair (∞ = conformal or edge: no film model), m
    pub reduced_radius: f64,
    /// radius `R` of the film criterion's spot `√(R δ)` toward the nearest face edge
    /// ([`film_limit_approach`]): the reduced radius for a circular spot; for the tapered
    /// rib's elliptical spot the radius that puts the ellipse's axes at their edges
    /// (`crate::tapered::model::end_rib_film_limit_radius`), m
    pub film_limit_radius: f64,
    pub reduced_modulus: f64,
    pub roughness: [f64; 2],
    pub temperature_k: f64,
}

/// Approach at which the Hertz spot of the end-contact film criterion, radius `√(R δ)`, grows to
/// `margin` (the distance of the contact point from the nearest edge of the face overlap): film
/// friction below it, boundary friction from it on (SPEC §6.7), `δ = margin²/R`, m.
pub fn film_limit_approach(reduced_radius: f64, margin: f64) -> f64 {
    margin * margin / reduced_radius
}

/// Force of one roller end on one face (`None` without contact). `reach` is the roller's
/// [`AxialReach`] on `body`, computed once for all faces of that body.
#[allow(clippy::too_many_arguments)]
pub(crate) fn end_force(
    face: &FaceGeometry,
    end: &EndGeometry,
    body: &BodyKin,
    reach: &AxialReach,
    roller: &RollerKinematics,
    params: &RollerEndParameters,
    damping: &SliceDamping,
    lub: Option<&EndLubrication>,
) -> Option<EndForce> {
    let dp = deepest_within(face, end, body, reach, roller.c, roller.a)?;
    #[cfg(test)]
    recording::record(face, end, body, roller);
    force_at(&dp, face, body, roller, params, damping, lub)
}

/// Test builds: the geometry and kinematics of the end contacts a run meets, for the oracle
/// test on recorded states (`tests::end_contacts_of_a_tapered_run_match_the_oracle`).
#[cfg(test)]
pub(crate) mod recording {
    use super::*;
    use std::cell::RefCell;

    /// One end contact as [`end_force`] saw it.
    #[derive(Debug, Clone, Copy)]
    pub(crate) struct RecordedEnd {
        pub face: FaceGeometry,
        pub end: EndGeometry,
        pub body: BodyKin,
        pub roller: RollerKinematics,
    }

    struct Recorder {
        every: usize,
        calls: usize,
        states: Vec<RecordedEnd>,
    }

    thread_local! {
        static RECORDER: RefCell<Option<Recorder>> = const { RefCell::new(None) };
    }

    /// Records every `every`-th end contact on this thread from now on.
    pub(crate) fn start(every: usize) {
        RECORDER.set(Some(Recorder {
            every: every.max(1),
            calls: 0,
            states: Vec::new(),
        }));
    }

    /// Stops recording; the contacts recorded since [`start`].
    pub(crate) fn finish() -> Vec<RecordedEnd> {
        RECORDER.take().map(|r| r.states).unwrap_or_default()
    }

    pub(super) fn record(
        face: &FaceGeometry,
        end: &EndGeometry,
        body: &BodyKin,
        roller: &RollerKinematics,
    ) {
        RECORDER.with_borrow_mut(|r| {
            if let Some(r) = r {
                r.calls += 1;
                if r.calls % r.every == 0 {
                    r.states.push(RecordedEnd {
                        face: *face,
                        end: *end,
                        body: *body,
                        roller: *roller,
                    });
                }
            }
        });
    }
}

/// [`end_force`] at the deepest point `dp`.
fn force_at(
    dp: &Deepest,
    face: &FaceGeometry,
    body: &BodyKin,
    roller: &RollerKinematics,
    params: &RollerEndParameters,
    damping: &SliceDamping,
    lub: Option<&EndLubrication>,
) -> Option<EndForce> {
    let n = dp.normal;
    let r_cp = sub(dp.point, roller.c);
    let v_roll = add(roller.v, cross(roller.w, r_cp));
    let r_body = sub(dp.point, body.o);
    let v_body = add(body.v, cross(body.omega, r_body));
    let vrel = sub(v_roll, v_body);
    let delta_dot = -dot(vrel, n);
    let pp = &params.contact;
    let elastic = pp.k_p * power(dp.delta, pp.exponent);
    let q = damping.normal_force(elastic, dp.delta, delta_dot);
    if q <= 0.0 {
        return None;
    }
    let vt = perp(vrel, n);
    let vs = norm(vt);
    // entrainment speed in the roller's orbital frame (as for the raceways, SPEC §3.5)
    let w_frame = [0.0, 0.0, roller.orbit];
    let t_roll = sub(v_roll, cross(w_frame, dp.point));
    let t_body = sub(v_body, cross(w_frame, dp.point));
    let u = norm(perp(scale(add(t_roll, t_body), 0.5), n));
    let boundary = |regime| match params.friction {
        EndFriction::Kragelsky => (kragelsky(vs / u.max(1e-3)), regime, f64::NAN),
        _ => (pp.friction.coefficient(vs), regime, f64::NAN),
    };
    let (mu, regime, lambda) = match (params.friction, lub) {
        (EndFriction::Ehl, Some(l)) if l.reduced_radius.is_finite() => {
            if dp.margin > 0.0 && dp.delta < film_limit_approach(l.film_limit_radius, dp.margin) {
                let state = ContactState {
                    normal_force_n: q,
                    geometry: ContactGeometry::Circular,
                    reduced_radius_m: l.reduced_radius,
                    reduced_modulus_pa: l.reduced_modulus,
                    rolling_speed_m_s: u,
                    sliding_speed_m_s: vs,
                    temperature_k: l.temperature_k,
                    roughness_ra_m: l.roughness,
                    film_thickness_m: None,
                };
                let tr = traction(&state, l.model);
                let ehl = EndContactRegime::Elastohydrodynamic;
                (tr.coefficient.abs(), ehl, tr.lambda)
            } else {
                boundary(EndContactRegime::Boundary)
            }
        }
        _ => boundary(EndContactRegime::Boundary),
    };
    let mut f = scale(n, q);
    if vs > 0.0 {
        f = axpy(f, -mu * q / vs, vt);
    }
    let edge_distance = (dp.rho - face.rho_edge).abs();
    Some(EndForce {
        force: f,
        point: dp.point,
        moment: cross(r_cp, f),
        body_moment: cross(r_body, scale(f, -1.0)),
        normal: q,
        sliding: vs,
        mu,
        delta: dp.delta,
        edge_distance,
        end_radius: dp.end_radius,
        body_radius: dp.rho,
        regime,
        lambda,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat_rib() -> FaceGeometry {
        FaceGeometry {
            side: 1.0,
            zeta: 5.5e-3,
            rho_lo: 82.5e-3,
            rho_hi: 86.2e-3,
            rho_edge: 86.2e-3,
            rho_c: 84.5e-3,
            slope: 0.0,
            curvature: 0.0,
        }
    }

    fn end() -> EndGeometry {
        EndGeometry {
            half_length: 5.5e-3,
            radius: 6.7e-3,
            sphere_curvature: 0.0,
        }
    }

    fn ring() -> BodyKin {
        BodyKin {
            o: [0.0; 3],
            v: [0.0; 3],
            axis: [0.0, 0.0, 1.0],
            omega: [0.0; 3],
        }
    }

    #[test]
    fn aligned_roller_approach_is_axial_overlap() {
        let c = [90e-3, 0.0, 2e-6];
        let d = deepest(&flat_rib(), &end(), &ring(), c, [0.0, 0.0, 1.0]).unwrap();
        assert!((d.delta - 2e-6).abs() < 1e-12, "{}", d.delta);
        assert!((d.normal[2] + 1.0).abs() < 1e-12);
        assert!(
            deepest(
                &flat_rib(),
                &end(),
                &ring(),
                [90e-3, 0.0, -1e-6],
                [0.0, 0.0, 1.0]
            )
            .is_none()
        );
    }

    #[test]
    fn skewed_roller_touches_at_the_rib_rim() {
        // yaw ψ about the radial axis x: the end disc tilts toward +y
        let psi = 1e-3_f64;
        let a = [0.0, psi.sin(), psi.cos()];
        let c = [90e-3, 0.0, 0.0];
        let d = deepest(&flat_rib(), &end(), &ring(), c, a).unwrap();
        // contact at the rim, where the end disc meets ρ = 86.2 mm (chord half-length)
        assert!((d.rho - 86.2e-3).abs() < 1e-7, "{}", d.rho);
        // corner: x² + y² = r_e², ρ_P + x + y²/(2ρ_P) = ρ_rim
        let rho_p = (90e-3_f64.powi(2) + (5.5e-3 * psi.sin()).powi(2)).sqrt();
        let mut y = 5e-3_f64;
        for _ in 0..50 {
            let x = 86.2e-3 - rho_p - y * y / (2.0 * rho_p);
            y = (6.7e-3_f64.powi(2) - x * x).sqrt();
        }
        let expect = 5.5e-3 * (psi.cos() - 1.0) + y * psi.sin();
        assert!((d.delta - expect).abs() < 2e-8, "{} vs {}", d.delta, expect);
    }

    /// Brute-force maximum of the exact approach over a grid of end-disc points in the band.
    fn brute(face: &FaceGeometry, c: V3, a: V3) -> f64 {
        let e = end();
        let p = axpy(c, face.side * e.half_length, a);
        let e1 = crate::vec3::unit_or(perp([1.0, 0.0, 0.0], a), [1.0, 0.0, 0.0]);
        let e2 = cross(a, e1);
        let n = 600;
        let mut best = f64::NEG_INFINITY;
        for i in 0..=n {
            for k in 0..=n {
                let x = e.radius * (2.0 * i as f64 / n as f64 - 1.0);
                let y = e.radius * (2.0 * k as f64 / n as f64 - 1.0);
                if x * x + y * y > e.radius * e.radius {
                    continue;
                }
                let q = axpy(axpy(p, x, e1), y, e2);
                let rho = q[0].hypot(q[1]);
                if rho > face.rho_hi || rho < face.rho_lo {
                    continue;
                }
                let u = rho - face.rho_c;
                let d =
                    face.side * (q[2] - face.zeta) + face.slope * u - 0.5 * face.curvature * u * u;
                best = best.max(d);
            }
        }
        best
    }

    #[test]
    fn deepest_point_matches_brute_force() {
        let convex = FaceGeometry {
            curvature: 1.0 / 37.5e-3,
            ..flat_rib()
        };
        let cone = FaceGeometry {
            slope: 2e-3,
            ..flat_rib()
        };
        for face in [flat_rib(), convex, cone] {
            for (yaw, pitch, dz) in [
                (4e-3, 0.0, 0.0),
                (-6e-3, 1e-3, 0.0),
                (1e-3, -2e-3, 2e-5),
                (0.0, 3e-3, 1e-5),
                (2e-3, 2e-3, 1e-5),
            ] {
                let a = crate::vec3::unit_or([pitch, yaw, 1.0], [0.0, 0.0, 1.0]);
                let c = [90e-3, 0.0, dz];
                let d = deepest(&face, &end(), &ring(), c, a).map_or(0.0, |d| d.delta);
                let b = brute(&face, c, a).max(0.0);
                assert!(
                    (d - b).abs() < 1e-7 + 1e-3 * b,
                    "yaw {yaw} pitch {pitch} dz {dz} κ {}: {d} vs brute force {b}",
                    face.curvature
                );
            }
        }
    }

    /// A deterministic stream of uniform numbers (64-bit LCG, Knuth's MMIX constants).
    struct Stream(u64);

    impl Stream {
        fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
        }
    }

    /// Roller motion for comparing forces: spin about the roller axis, orbit about the body
    /// axis, the body turning (a ring) or not (a cage).
    fn moving_roller(c: V3, a: V3, spin: f64) -> RollerKinematics {
        let orbit = 0.1 * spin;
        RollerKinematics {
            c,
            a,
            v: cross([0.0, 0.0, orbit], c),
            w: axpy([0.0, 0.0, orbit], spin, a),
            orbit,
        }
    }

    /// Contact law and friction for comparing forces.
    fn end_parameters(friction: EndFriction) -> RollerEndParameters {
        RollerEndParameters {
            enabled: true,
            contact: crate::parameters::PairParameters {
                k_p: 5.8e9,
                exponent: 1.5,
                c_h: 100.0,
                d: 1e-6,
                friction: rolldyn_contact::damping::TwoLevelFriction {
                    mu_static: 0.065,
                    mu_dynamic: 0.065,
                    v_static: 5e-3,
                    v_dynamic: 1e-2,
                },
            },
            friction,
        }
    }

    /// Largest relative differences (approach, contact point from the roller centre, normal,
    /// force, moment) between the closed-form/Newton search and the golden-section oracle.
    #[derive(Debug, Default)]
    struct Spread {
        delta: f64,
        point: f64,
        normal: f64,
        force: f64,
        moment: f64,
        cases: usize,
        kinks: usize,
        flat_maxima: usize,
        /// largest relative force difference on flat maxima, where the oracle's point is known
        /// only to its resolution (reported, bounded loosely in [`Spread::check`])
        flat_force: f64,
        oracle_missed: usize,
    }

    impl Spread {
        /// Compares both searches on one state, the roller moving as `roller`.
        fn compare(
            &mut self,
            face: &FaceGeometry,
            end: &EndGeometry,
            body: &BodyKin,
            roller: &RollerKinematics,
            label: &str,
        ) {
            let (c, a) = (roller.c, roller.a);
            let new = deepest(face, end, body, c, a);
            let old = deepest_golden(face, end, body, c, a);
            let (new, old) = match (new, old) {
                (Some(n), Some(o)) => (n, o),
                (None, None) => return,
                (n, o) => panic!(
                    "{label}: contact {:?} vs oracle {:?}",
                    n.map(|d| d.delta),
                    o.map(|d| d.delta)
                ),
            };
            // the new search takes the best of its candidates: never shallower than the oracle beyond the
            // rounding of δ (that of ρ ≈ |X| times a face slope below 1)
            let rounding = 4.0 * f64::EPSILON * norm(old.point);
            assert!(
                new.delta >= old.delta - rounding,
                "{label}: {} < {}",
                new.delta,
                old.delta
            );
            let rel = |x: V3, y: V3, scale_: f64| norm(sub(x, y)) / scale_;
            // δ differences within that rounding are no differences: a barely touching end
            // (δ ≈ 10⁻⁹ m) cannot be compared to 10⁻⁹ of δ
            let gap = ((new.delta - old.delta).abs() - rounding).max(0.0);
            if gap > 1e-9 * old.delta {
                // a maximum at a kink (rim corner, chord switch): the new search lands on it
                // exactly, the oracle within its last golden-section bracket (0.618⁴⁰ of half
                // the interval), which moves δ by the slope times that width
                let reach = AxialReach::new(body, end, c, a);
                let frame = EndOnFace::new(face, end, body, &reach, c, a).unwrap();
                let width = 0.5 * (frame.xb - frame.xa) * 0.618_f64.powi(40);
                let (x_new, x_old) = (frame.deepest_curved().0, frame.deepest_curved_golden().0);
                if (x_new - x_old).abs() <= width {
                    self.kinks += 1;
                    return;
                }
                // otherwise the oracle's five samples missed a deeper local maximum (the
                // approach along x need not be concave: the free y₀ ignores the face's
                // protrusion, a concave torus or a face leaning away bends it up): counted
                assert!(
                    new.delta > old.delta,
                    "{label}: x {x_new} vs oracle {x_old} (bracket {width:e}): {new:?} vs {old:?}"
                );
                self.oracle_missed += 1;
                return;
            }
            self.delta = self.delta.max(gap / old.delta);
            // on a flat maximum the oracle's x is only known to √(2 ε_δ/|f''|) (golden-section
            // comparisons of δ values within their rounding ε_δ), where the new search solves
            // f' = 0: the point and the forces (damping and friction at the point) are compared
            // where that resolution is below 10⁻¹² of the disc radius, x everywhere
            let reach = AxialReach::new(body, end, c, a);
            let frame = EndOnFace::new(face, end, body, &reach, c, a).unwrap();
            if frame.cs != 0.0 || face.curvature != 0.0 {
                let (x_new, x_old) = (frame.deepest_curved().0, frame.deepest_curved_golden().0);
                let bend = frame.slope_on(x_new, frame.chord_at(x_new)).1.abs();
                let width = 0.5 * (frame.xb - frame.xa) * 0.618_f64.powi(40);
                let resolution = (2.0 * rounding / bend).sqrt().max(width);
                assert!(
                    (x_new - x_old).abs() <= 4.0 * resolution,
                    "{label}: x {x_new} vs oracle {x_old} (resolution {resolution:e})"
                );
                if resolution > 1e-12 * frame.r {
                    self.flat_maxima += 1;
                    let (force, _) = Self::force_gap(&new, &old, face, body, roller, label);
                    self.flat_force = self.flat_force.max(force);
                    return;
                }
            }
            self.cases += 1;
            self.point = self
                .point
                .max(rel(new.point, old.point, norm(sub(old.point, c))));
            self.normal = self.normal.max(rel(new.normal, old.normal, 1.0));
            let (force, moment) = Self::force_gap(&new, &old, face, body, roller, label);
            self.force = self.force.max(force);
            self.moment = self.moment.max(moment);
        }

        /// Largest relative differences of force and moment at the two deepest points, with
        /// boundary and with Kragelsky friction.
        fn force_gap(
            new: &Deepest,
            old: &Deepest,
            face: &FaceGeometry,
            body: &BodyKin,
            roller: &RollerKinematics,
            label: &str,
        ) -> (f64, f64) {
            let rel = |x: V3, y: V3| norm(sub(x, y)) / norm(y);
            let damping = SliceDamping::new(100.0, 1e-6);
            let (mut force, mut moment) = (0.0_f64, 0.0_f64);
            for friction in [EndFriction::Boundary, EndFriction::Kragelsky] {
                let params = end_parameters(friction);
                let fnew = force_at(new, face, body, roller, &params, &damping, None);
                let fold = force_at(old, face, body, roller, &params, &damping, None);
                if let (Some(fnew), Some(fold)) = (fnew, fold) {
                    force = force.max(rel(fnew.force, fold.force));
                    moment = moment.max(rel(fnew.moment, fold.moment));
                } else {
                    assert!(
                        fnew.is_none() && fold.is_none(),
                        "{label}: force on one side only: {new:?} vs {old:?}"
                    );
                }
            }
            (force, moment)
        }

        /// Asserts `tolerance` on the approach everywhere and on the point, normal, force and
        /// moment where the oracle resolves the point; on flat maxima the force may differ by
        /// the oracle's point resolution (≲ 10⁻⁸ m) times the velocity gradient over the sliding
        /// speed: bounded at 10⁻³.
        fn check(&self, what: &str, tolerance: f64) {
            eprintln!("{what}: {self:?}");
            assert!(self.cases + self.flat_maxima > 0, "{what}: no contact");
            assert!(
                self.flat_force <= 1e-3,
                "{what}: force on a flat maximum differs by {:e}",
                self.flat_force
            );
            for (name, v) in [
                ("approach", self.delta),
                ("point", self.point),
                ("normal", self.normal),
                ("force", self.force),
                ("moment", self.moment),
            ] {
                assert!(v <= tolerance, "{what}: {name} differs by {v:e} (relative)");
            }
        }
    }

    /// The face shapes the models have: flat, conical (either lean), convex torus (2002834's
    /// R 430 and 37.5 mm variants, crest offset), concave torus (R 800…1300 mm of the tapered
    /// variants, and a tight one), and a tapered rib's cone with a torus on it.
    fn face_shapes(base: &FaceGeometry) -> Vec<(&'static str, FaceGeometry)> {
        let with = |slope: f64, curvature: f64, crest: f64| FaceGeometry {
            slope,
            curvature,
            rho_c: base.rho_c + crest,
            ..*base
        };
        vec![
            ("flat", with(0.0, 0.0, 0.0)),
            ("cone +", with(0.146, 0.0, 0.0)),
            ("cone −", with(-0.05, 0.0, 0.0)),
            ("convex R 430 mm", with(0.0, 1.0 / 430e-3, 0.0)),
            ("convex R 37.5 mm", with(0.0, 1.0 / 37.5e-3, -0.5e-3)),
            ("concave R 800 mm", with(0.0, -1.0 / 800e-3, 0.0)),
            ("concave R 100 mm", with(0.0, -1.0 / 100e-3, 0.0)),
            ("cone + convex R 1100 mm", with(0.146, 1.0 / 1100e-3, 0.0)),
            ("cone + concave R 1300 mm", with(0.146, -1.0 / 1300e-3, 0.0)),
        ]
    }

    /// Roller end shapes: flat, and spheres of R 640 mm (tapered-cassette), 100 and 30 mm.
    fn end_shapes(base: &EndGeometry) -> Vec<EndGeometry> {
        [0.0, 1.0 / 640e-3, 1.0 / 100e-3, 1.0 / 30e-3]
            .map(|sphere_curvature| EndGeometry {
                sphere_curvature,
                ..*base
            })
            .to_vec()
    }

    /// Moves the roller along the body axis so that the oracle's approach is `target`, or
    /// `None` when the end disc misses the face band.
    fn at_approach(
        face: &FaceGeometry,
        end: &EndGeometry,
        body: &BodyKin,
        c: V3,
        a: V3,
        target: f64,
    ) -> Option<V3> {
        let reach = AxialReach::new(body, end, c, a);
        let frame = EndOnFace::new(face, end, body, &reach, c, a)?;
        let d = frame.deepest_curved_golden().2;
        Some(axpy(c, face.side * (target - d), body.axis))
    }

    #[test]
    fn curved_search_matches_the_golden_section_oracle_on_generated_states() {
        let mut stream = Stream(40);
        let mut spread = Spread::default();
        for side in [1.0, -1.0] {
            let base = FaceGeometry {
                side,
                zeta: side * 5.5e-3,
                ..flat_rib()
            };
            for (name, face) in face_shapes(&base) {
                for e in end_shapes(&end()) {
                    for k in 0..60 {
                        // skew and tilt up to 10 mrad (every fourth roller nearly aligned: an
                        // aligned flat end ties along the rim, where either search may take any
                        // point of the tie), the roller's axis from below the raceway to above
                        // the rim (contact inside the face, at the rim, at the raceway edge)
                        let mut tilt = || match k % 4 {
                            0 => stream.uniform(-1e-4, 1e-4),
                            _ => stream.uniform(-1e-2, 1e-2),
                        };
                        let (yaw, pitch) = (tilt(), tilt());
                        let radius = stream.uniform(78e-3, 92e-3);
                        let azimuth = stream.uniform(0.0, std::f64::consts::TAU);
                        let (s, co) = azimuth.sin_cos();
                        let a0 = crate::vec3::unit_or([pitch, yaw, 1.0], [0.0, 0.0, 1.0]);
                        let a = [co * a0[0] - s * a0[1], s * a0[0] + co * a0[1], a0[2]];
                        let c = [radius * co, radius * s, 0.0];
                        let target = 10f64.powf(stream.uniform(-7.0, -4.5));
                        let Some(c) = at_approach(&face, &e, &ring(), c, a, target) else {
                            continue;
                        };
                        let label = format!(
                            "{name}, side {side}, 1/R_s {}, state {k}",
                            e.sphere_curvature
                        );
                        let roller = moving_roller(c, a, 1000.0);
                        spread.compare(&face, &e, &ring(), &roller, &label);
                    }
                }
            }
        }
        spread.check("generated states", 1e-9);
        assert!(spread.cases > 0, "no state with a resolved point");
    }

    /// States recorded from a run instead of generated: the end contacts of the tapered
    /// cassette (the rollers' R 640 mm end spheres on the conical large ribs, the pocket faces)
    /// over the first 0.5 ms from the seated start, every 7th contact evaluation.
    #[test]
    fn end_contacts_of_a_tapered_run_match_the_oracle() {
        let model = crate::tapered::cassette();
        let settings = crate::tapered::TaperedRunSettings::default();
        recording::start(7);
        let mut sim = crate::tapered::TaperedSimulation::new(&model, &settings, false);
        sim.run_until(5e-4, None, &mut |_| std::ops::ControlFlow::Continue(()))
            .unwrap();
        let states = recording::finish();
        let mut spread = Spread::default();
        for (k, st) in states.iter().enumerate() {
            let label = format!("recorded contact {k}");
            spread.compare(&st.face, &st.end, &st.body, &st.roller, &label);
        }
        spread.check(&format!("{} recorded contacts", states.len()), 1e-9);
    }

    #[test]
    fn convex_rib_moves_the_contact_away_from_the_rim() {
        let psi = 1e-3_f64;
        let a = [0.0, psi.sin(), psi.cos()];
        let c = [90e-3, 0.0, 0.0];
        let flat = deepest(&flat_rib(), &end(), &ring(), c, a).unwrap();
        let convex = FaceGeometry {
            curvature: 1.0 / 37.5e-3,
            ..flat_rib()
        };
        let cv = deepest(&convex, &end(), &ring(), c, a).unwrap();
        assert!(86.2e-3 - cv.rho > 1e-3, "convex contact at ρ = {}", cv.rho);
        assert!(86.2e-3 - flat.rho < 1e-7);
    }
}
