//! The contact geometry of one row in the half-plane `(ρ, ζ)` of its body (distance from the
//! body's axis, axial position from the body's origin): raceway lines, rib and pocket faces.
//!
//! The lines and the large-rib contact come from the bearing's [`rolldyn_geometry::TaperedRow`]
//! (apex condition, cup moved by the per-row normal gap, rib tangent to the end sphere at mid rib
//! height); here they become the face descriptions of [`crate::ends`]. A generatrix of a roller
//! of half-angle β lies at the perpendicular distance `r cos β` from an axis point whose local
//! radius is `r`: the approach of a slice is `r cos β` minus that point's distance from the
//! raceway line.

use crate::ends::FaceGeometry;
use rolldyn_geometry::{DoubleRowTaperedBearing, RacewayLine};

/// A straight line of a body's half-plane: a point and the unit normal pointing to the roller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HalfPlaneLine {
    pub rho: f64,
    pub zeta: f64,
    pub n_rho: f64,
    pub n_zeta: f64,
}

impl HalfPlaneLine {
    /// Signed distance of `(ρ, ζ)` from the line, positive on the roller's side, m.
    #[inline]
    pub fn distance(&self, rho: f64, zeta: f64) -> f64 {
        self.n_rho * (rho - self.rho) + self.n_zeta * (zeta - self.zeta)
    }
}

/// One row: its large-end direction, seated roller, raceways and end faces.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RowGeometry {
    /// σ: +1 when the large ends point to +z
    pub sigma: f64,
    /// roller mid-point `(R_m, z_m)` (bearing frame), m
    pub mid: (f64, f64),
    /// unit roller axis towards the large end, `(u_ρ, u_ζ)`
    pub u: (f64, f64),
    /// cone raceway (inner-ring frame) and cup raceway (outer-ring frame)
    pub cone: HalfPlaneLine,
    pub cup: HalfPlaneLine,
    /// large and small rib faces of the cone (inner-ring frame)
    pub large_rib: FaceGeometry,
    pub small_rib: FaceGeometry,
    /// large-end and small-end pocket faces (frame of the row's cage, origin at `z_m`)
    pub pocket_large: FaceGeometry,
    pub pocket_small: FaceGeometry,
}

/// Height of the small (retaining) rib above the cone raceway as a fraction of the small-end
/// radius: the small end face is touched at its lower part only (0.35, design practice).
const SMALL_RIB_HEIGHT_FRACTION: f64 = 0.35;

/// The geometry of row `k` (0: z < 0, 1: z > 0) from the bearing's [`TaperedRow`].
pub(crate) fn row_geometry(b: &DoubleRowTaperedBearing, k: usize) -> RowGeometry {
    let row = b.row(k);
    let sigma = row.large_end_sign;
    let line = |l: &RacewayLine| HalfPlaneLine {
        rho: l.point.r,
        zeta: l.point.z,
        n_rho: l.normal.r,
        n_zeta: l.normal.z,
    };
    let cone = line(&row.cone);
    let mid = (row.roller_mid.r, row.roller_mid.z);
    let u = (row.roller_axis.r, row.roller_axis.z);
    let rib = &row.large_rib;
    let into_rib = (-rib.normal.r, -rib.normal.z);
    // the worn rib face recedes along its normal (seed 000 §3.2.2)
    let worn = b.wear.large_rib;
    let rib_point = (
        rib.point.r + worn * into_rib.0,
        rib.point.z + worn * into_rib.1,
    );
    let band = (
        rib.point.r + rib.band.0 * rib.tangent.r,
        rib.point.r + rib.band.1 * rib.tangent.r,
    );
    let mut large_rib = plane_face(sigma, rib_point, into_rib, band);
    // the graph ζ(ρ) of a profile arc of curvature κ at slope t curves by κ(1 + t²)^{3/2};
    // the geometry's sign is + for concave, the face's + for convex
    large_rib.curvature =
        -rib.face.curvature() * (1.0 + large_rib.slope * large_rib.slope).powf(1.5);
    let roller = &b.roller;
    let r_small = 0.5 * roller.small_diameter();
    let small_point = (row.small_rib.point.r, row.small_rib.point.z);
    let small_into = (-row.small_rib.normal.r, -row.small_rib.normal.z);
    let small_rib = plane_face(
        -sigma,
        small_point,
        small_into,
        face_band_from_cone(
            &cone,
            small_point,
            small_into,
            0.0,
            SMALL_RIB_HEIGHT_FRACTION * r_small,
        ),
    );
    let half = 0.5 * roller.length;
    let cage_origin_z = mid.1;
    let at = |x: f64| (mid.0 + x * u.0, mid.1 + x * u.1 - cage_origin_z);
    let r_large = 0.5 * roller.large_diameter();
    // the roller centred in its pocket clears each pocket face by half the end clearance
    let gap = 0.5 * b.cage.end_clearance;
    let (pl, ps) = (at(half + gap), at(-(half + gap)));
    let pocket_large = plane_face(sigma, pl, u, (pl.0 - r_large, pl.0 + r_large));
    let pocket_small = plane_face(-sigma, ps, (-u.0, -u.1), (ps.0 - r_small, ps.0 + r_small));
    RowGeometry {
        sigma,
        mid,
        u,
        cone,
        cup: line(&row.cup),
        large_rib,
        small_rib,
        pocket_large,
        pocket_small,
    }
}

/// A face through `p` whose normal `m` points from the roller into the face, on side `s`, over
/// the radial band `(ρ_lo, ρ_hi)`: `ζ = ζ_p − (m_ρ/m_ζ)(ρ − ρ_p)`, i.e. slope `t = s m_ρ/m_ζ` of
/// [`FaceGeometry`].
fn plane_face(s: f64, p: (f64, f64), m: (f64, f64), band: (f64, f64)) -> FaceGeometry {
    FaceGeometry {
        side: s,
        zeta: p.1,
        rho_lo: band.0.min(band.1),
        rho_hi: band.0.max(band.1),
        rho_edge: band.0.max(band.1),
        rho_c: p.0,
        slope: s * m.0 / m.1,
        curvature: 0.0,
    }
}

/// Radial band of a face through `p` with normal `m` between the heights `h_lo` and `h_hi`
/// above the cone raceway.
fn face_band_from_cone(
    cone: &HalfPlaneLine,
    p: (f64, f64),
    m: (f64, f64),
    h_lo: f64,
    h_hi: f64,
) -> (f64, f64) {
    // direction along the face, oriented away from the cone
    let mut f = (-m.1, m.0);
    if cone.n_rho * f.0 + cone.n_zeta * f.1 < 0.0 {
        f = (-f.0, -f.1);
    }
    let rise = cone.n_rho * f.0 + cone.n_zeta * f.1;
    let h_p = cone.distance(p.0, p.1);
    let rho_at = |h: f64| p.0 + (h - h_p) / rise * f.0;
    (rho_at(h_lo), rho_at(h_hi))
}
