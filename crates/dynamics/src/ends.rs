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
//! interval ends); curved pairs use a golden-section search (a concave torus gives the local
//! maximum next to the best of the bracket samples). This is the seed's "contact on
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
use rolldyn_numerics::maximize1d::{GoldenSectionOptions, golden_section_max};

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
    // cheap upper bound first
    if reach.bound(face, end) <= 0.0 {
        return None;
    }
    let frame = EndOnFace::new(face, end, body, reach, c, a)?;
    let (x, y, d) = if frame.cs == 0.0 && face.curvature == 0.0 {
        frame.deepest_flat()
    } else {
        frame.deepest_curved()
    };
    frame.contact(x, y, d)
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

    /// Crowned end or curved face: bracket the maximum by the best of a few samples (exact for
    /// concave functions), refine by golden section, and compare with the interval ends (a
    /// maximum on the band edge). Returns `(x, y, δ)`.
    fn deepest_curved(&self) -> (f64, f64, f64) {
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
