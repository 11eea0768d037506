//! The cage pocket as it is built (docs/theory.md §1.6): the bar's cross-section in the cage's
//! transverse plane, defined once for contact, bar stiffness, mass and stress.
//!
//! **Pocket coordinates.** `ρ` runs along the pocket's radial line from the cage axis, `h` across
//! it from the pocket's mid-plane. The two walls of a pocket are mirror images; the material of
//! the `+` wall lies at `h > 0`. It is the union of convex pieces, each with an exact signed
//! distance:
//! * the **face**, over the cage's radial wall `r_i ≤ ρ ≤ r_o`: flat, `h ≥ w_f`, or concave, outside
//!   the circle of radius `R_c = w_f` about the roller's nominal axis `(r_m, 0)`; `w_f = R_w + c/2`
//!   with `c` the face clearance (pocket width at the pitch circle − roller diameter);
//! * a **retaining lip** at the outside diameter (`ρ ≥ ρ_L`) and/or at the bore (`ρ ≤ ρ_L`), its
//!   edge at half the window `w_L` from the mid-plane and on the lip circle `ρ_L² + w_L² = (D_L/2)²`,
//!   rounded by the tip radius.
//!
//! The distance of a point from the union is the smallest of the pieces' distances (exact
//! outside the material), so a roller slice of radius `R` centred at `(ρ, h)` overlaps the wall
//! by `δ = R − d` along the distance's gradient, the contact normal.

use crate::error::GeometryError;
use crate::mass::MassProperties;
use std::f64::consts::TAU;

/// Shape of the pocket faces in the cage's transverse plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PocketFaces {
    /// Parallel flat faces (a broached or milled window).
    Flat,
    /// Faces on a cylinder coaxial with the roller's nominal axis (a bored pocket).
    Concave,
}

/// A retaining lip: the window narrows below the roller diameter at the lip circle.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RetainingLip {
    /// Diameter of the circle through the lip edges [m].
    pub diameter: f64,
    /// Circumferential opening between the two lip edges of a pocket (the seed's "window size")
    /// [m].
    pub window: f64,
    /// Radius that rounds the lip edge [m].
    pub tip_radius: f64,
}

/// The pocket of a machined window cage: faces, lips, axial size and the window-corner fillet.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CagePocket {
    pub faces: PocketFaces,
    /// Pocket width at the pitch circle minus the roller diameter [m].
    pub face_clearance: f64,
    pub outer_lip: Option<RetainingLip>,
    pub inner_lip: Option<RetainingLip>,
    /// Axial size of the window [m].
    pub axial: f64,
    /// Radius of the window-corner fillet between bar and rim (stress models) [m].
    pub fillet_radius: f64,
}

/// Which piece of a pocket wall a point is nearest to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WallPiece {
    Face,
    OuterLip,
    InnerLip,
}

impl WallPiece {
    /// The model key that sets this piece's position.
    pub fn key(self) -> &'static str {
        match self {
            WallPiece::Face => "cage.pocket.face_clearance",
            WallPiece::OuterLip => "cage.pocket.outer_lip.window",
            WallPiece::InnerLip => "cage.pocket.inner_lip.window",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            WallPiece::Face => "face",
            WallPiece::OuterLip => "outer lip",
            WallPiece::InnerLip => "inner lip",
        }
    }
}

/// Distance of a point from the `+` wall and the wall's outward normal there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WallDistance {
    /// Signed distance [m] (negative inside the material).
    pub distance: f64,
    /// Unit vector `(n_ρ, n_h)` from the wall towards the point (the gradient of the distance).
    pub normal: [f64; 2],
    pub piece: WallPiece,
}

/// A lip resolved to pocket coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
struct LipWall {
    /// ρ of the lip edge.
    rho: f64,
    half_window: f64,
    tip_radius: f64,
}

/// Far extent standing for "unbounded" in the pieces' boxes [m] (a cage is far smaller).
const FAR: f64 = 1.0;

/// The walls of a pocket resolved for one bearing: the hot-path form of [`CagePocket`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketWalls {
    faces: PocketFaces,
    /// Half-width of flat faces / radius of concave faces, `w_f` [m].
    face_half_width: f64,
    /// ρ of the roller's nominal axis (pitch radius) [m].
    pitch_radius: f64,
    /// Radial extent of the cage wall (bore, outside radius) [m].
    band: (f64, f64),
    outer_lip: Option<LipWall>,
    inner_lip: Option<LipWall>,
}

/// Signed distance of `p` from the axis-aligned box `[lo, hi]` rounded by `round`, with its
/// gradient (Quílez's box distance).
fn box_distance(p: [f64; 2], lo: [f64; 2], hi: [f64; 2], round: f64) -> (f64, [f64; 2]) {
    let c = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let b = [
        (0.5 * (hi[0] - lo[0]) - round).max(0.0),
        (0.5 * (hi[1] - lo[1]) - round).max(0.0),
    ];
    let s = [(p[0] - c[0]).signum(), (p[1] - c[1]).signum()];
    let q = [(p[0] - c[0]).abs() - b[0], (p[1] - c[1]).abs() - b[1]];
    if q[0] > 0.0 || q[1] > 0.0 {
        let v = [q[0].max(0.0), q[1].max(0.0)];
        let d = v[0].hypot(v[1]);
        (d - round, [s[0] * v[0] / d, s[1] * v[1] / d])
    } else if q[0] > q[1] {
        (q[0] - round, [s[0], 0.0])
    } else {
        (q[1] - round, [0.0, s[1]])
    }
}

impl PocketWalls {
    /// Distance of `(ρ, h)` from the `+` wall (the nearest of its pieces).
    #[inline]
    pub fn distance(&self, rho: f64, h: f64) -> WallDistance {
        let p = [rho, h];
        let (lo, hi) = self.band;
        let (d, n) = match self.faces {
            PocketFaces::Flat => box_distance(
                p,
                [lo, self.face_half_width],
                [hi, self.face_half_width + FAR],
                0.0,
            ),
            PocketFaces::Concave => {
                // outside the face circle ∩ the wall band at h ≥ 0: the larger of the distances
                let (dx, dy) = (rho - self.pitch_radius, h);
                let from_axis = dx.hypot(dy).max(1e-12);
                let circle = (
                    self.face_half_width - from_axis,
                    [-dx / from_axis, -dy / from_axis],
                );
                let band = box_distance(p, [lo, 0.0], [hi, FAR], 0.0);
                if circle.0 >= band.0 { circle } else { band }
            }
        };
        let mut best = WallDistance {
            distance: d,
            normal: n,
            piece: WallPiece::Face,
        };
        let mut take = |(d, n): (f64, [f64; 2]), piece| {
            if d < best.distance {
                best = WallDistance {
                    distance: d,
                    normal: n,
                    piece,
                };
            }
        };
        if let Some(l) = self.outer_lip {
            take(
                box_distance(p, [l.rho, l.half_window], [hi, FAR], l.tip_radius),
                WallPiece::OuterLip,
            );
        }
        if let Some(l) = self.inner_lip {
            take(
                box_distance(p, [lo, l.half_window], [l.rho, FAR], l.tip_radius),
                WallPiece::InnerLip,
            );
        }
        best
    }

    /// Clearance of a disc of radius `r` at `(ρ, h)` to the nearer wall (negative: overlap),
    /// with that wall's distance record and side (±1).
    pub fn clearance(&self, rho: f64, h: f64, r: f64) -> (f64, WallDistance, f64) {
        let plus = self.distance(rho, h);
        let minus = self.distance(rho, -h);
        if plus.distance <= minus.distance {
            (plus.distance - r, plus, 1.0)
        } else {
            (minus.distance - r, minus, -1.0)
        }
    }

    /// Distance a disc of radius `r` starting at `start` travels along the unit vector `dir`
    /// before it touches a wall (sphere tracing: the distance never overestimates the free
    /// travel); `None` beyond `limit`.
    pub fn travel(&self, start: [f64; 2], dir: [f64; 2], r: f64, limit: f64) -> Option<f64> {
        let mut t = 0.0;
        for _ in 0..10_000 {
            let g = self
                .clearance(start[0] + t * dir[0], start[1] + t * dir[1], r)
                .0;
            if g < 1e-10 {
                return Some(t);
            }
            t += g;
            if t > limit {
                return None;
            }
        }
        Some(t)
    }

    /// Tangential half-width of the window at radius `ρ` (lip tip radii ignored): the face's
    /// half-width, narrowed by a lip where the lip stands [m].
    pub fn half_window_at(&self, rho: f64) -> f64 {
        let mut w = match self.faces {
            PocketFaces::Flat => self.face_half_width,
            PocketFaces::Concave => {
                let dx = rho - self.pitch_radius;
                (self.face_half_width.powi(2) - dx * dx).max(0.0).sqrt()
            }
        };
        if let Some(l) = self.outer_lip
            && rho >= l.rho
        {
            w = w.min(l.half_window);
        }
        if let Some(l) = self.inner_lip
            && rho <= l.rho
        {
            w = w.min(l.half_window);
        }
        w
    }

    /// Tangential width of the bar between two of `pockets` windows at radius `r`, `b(r) =
    /// 2πr/Z − 2w(r)` [m].
    pub fn bar_width_at(&self, r: f64, pockets: usize) -> f64 {
        TAU * r / pockets as f64 - 2.0 * self.half_window_at(r)
    }

    /// The radii `ρ` where the window half-width steps (the lip edges), ascending [m].
    pub fn steps(&self) -> Vec<f64> {
        let mut out: Vec<f64> = [self.inner_lip, self.outer_lip]
            .into_iter()
            .flatten()
            .map(|l| l.rho)
            .collect();
        out.sort_by(f64::total_cmp);
        out
    }

    pub fn faces(&self) -> PocketFaces {
        self.faces
    }
}

/// Cross-section of a bar between two pockets, in the transverse plane: width
/// `b(r) = 2πr/Z − 2w(r)` from the window half-width `w(r)` ([`PocketWalls::half_window_at`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarSection {
    /// Radial depth `r_o − r_i` [m].
    pub depth: f64,
    /// Tangential width at the cage bore and at the cage outside diameter [m].
    pub width_inner: f64,
    pub width_outer: f64,
    /// Narrowest width over the depth and the radius where it occurs [m].
    pub width_min: f64,
    pub radius_of_min: f64,
    /// Area `A = ∫ b dr` [m²].
    pub area: f64,
    /// Radius of the centroid `∫ b r dr / A` [m].
    pub centroid_radius: f64,
    /// Second moment for bending in the circumferential direction, `∫ b³/12 dr` [m⁴].
    pub second_moment: f64,
    /// Second moment for bending in the radial direction, `∫ b (r − r̄)² dr` [m⁴].
    pub second_moment_radial: f64,
}

/// Points of the midpoint rule over the cage depth for section and mass integrals (the width
/// is piecewise smooth with steps at the lips: 2000 points resolve a step to 0.05 % of the
/// depth).
const SECTION_POINTS: usize = 2000;

/// The circumferential play of a roller in its pocket and what stops it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketPlay {
    /// Circumferential travel of a roller at the pitch radius from the pocket centre to a wall
    /// [m].
    pub circumferential_per_side: f64,
    /// The piece it touches and the diameter of the contact point [m].
    pub circumferential_stop: WallPiece,
    pub circumferential_contact_diameter: f64,
    /// The contact point in pocket coordinates `(ρ, h)` [m].
    pub circumferential_contact: [f64; 2],
    /// Radial travel outwards / inwards from the pitch radius to a lip (`None`: no lip stops it
    /// within a roller diameter) [m].
    pub radial_outward: Option<f64>,
    pub radial_inward: Option<f64>,
    /// Smallest displacement of the cage, over all directions, that closes a pocket on its
    /// centred roller [m].
    pub closing_displacement: f64,
}

/// What a pocket needs of its bearing to be resolved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketContext {
    pub roller_radius: f64,
    pub pitch_radius: f64,
    pub cage_inner_radius: f64,
    pub cage_outer_radius: f64,
    pub pockets: usize,
}

impl CagePocket {
    /// The walls in pocket coordinates for a bearing, checked: positive sizes, lips inside the
    /// cage wall and narrower than the face, tip radii that fit the lip.
    pub fn walls(&self, ctx: &PocketContext) -> Result<PocketWalls, GeometryError> {
        crate::error::require_positive("cage.pocket_axial", self.axial)?;
        if !(self.face_clearance > 0.0) || !self.face_clearance.is_finite() {
            return Err(GeometryError::new(
                "cage.pocket.face_clearance",
                format!("must be positive, got {}", self.face_clearance),
            ));
        }
        if !(self.fillet_radius >= 0.0) {
            return Err(GeometryError::new(
                "cage.pocket.fillet_radius",
                "must not be negative",
            ));
        }
        let face_half_width = ctx.roller_radius + 0.5 * self.face_clearance;
        let band = (ctx.cage_inner_radius, ctx.cage_outer_radius);
        let lip = |lip: &RetainingLip, key: &str, outer: bool| -> Result<LipWall, GeometryError> {
            let w = 0.5 * lip.window;
            if !(w > 0.0) || w >= face_half_width {
                return Err(GeometryError::new(
                    format!("{key}.window"),
                    format!(
                        "{:.3} mm must be positive and narrower than the pocket faces ({:.3} mm apart)",
                        lip.window * 1e3,
                        2e3 * face_half_width
                    ),
                ));
            }
            let r = 0.5 * lip.diameter;
            let rho = (r * r - w * w).max(0.0).sqrt();
            if !(rho > band.0 && rho < band.1) {
                return Err(GeometryError::new(
                    format!("{key}.diameter"),
                    format!(
                        "Ø{:.3} mm must lie within the cage wall Ø{:.3}…Ø{:.3} mm",
                        lip.diameter * 1e3,
                        2e3 * band.0,
                        2e3 * band.1
                    ),
                ));
            }
            let thickness = if outer { band.1 - rho } else { rho - band.0 };
            if !(lip.tip_radius >= 0.0 && 2.0 * lip.tip_radius <= thickness.min(2.0 * w)) {
                return Err(GeometryError::new(
                    format!("{key}.tip_radius"),
                    format!(
                        "{:.3} mm must be at most half the lip's radial thickness {:.3} mm",
                        lip.tip_radius * 1e3,
                        thickness * 1e3
                    ),
                ));
            }
            Ok(LipWall {
                rho,
                half_window: w,
                tip_radius: lip.tip_radius,
            })
        };
        let outer_lip = self
            .outer_lip
            .as_ref()
            .map(|l| lip(l, "cage.pocket.outer_lip", true))
            .transpose()?;
        let inner_lip = self
            .inner_lip
            .as_ref()
            .map(|l| lip(l, "cage.pocket.inner_lip", false))
            .transpose()?;
        if let (Some(o), Some(i)) = (outer_lip, inner_lip)
            && i.rho >= o.rho
        {
            return Err(GeometryError::new(
                "cage.pocket.inner_lip.diameter",
                "the bore lip must lie below the outside lip",
            ));
        }
        Ok(PocketWalls {
            faces: self.faces,
            face_half_width,
            pitch_radius: ctx.pitch_radius,
            band,
            outer_lip,
            inner_lip,
        })
    }

    /// The physical invariant: a roller at the pitch radius, anywhere within `radial_play` of
    /// it, fits its pocket (exit 2 naming the key of the wall piece that cuts it).
    pub fn check_fit(&self, ctx: &PocketContext, radial_play: f64) -> Result<(), GeometryError> {
        let walls = self.walls(ctx)?;
        let steps = 16;
        for k in 0..=steps {
            let s = radial_play * (2.0 * k as f64 / steps as f64 - 1.0);
            let (g, wall, _) = walls.clearance(ctx.pitch_radius + s, 0.0, ctx.roller_radius);
            if g < 0.0 {
                return Err(GeometryError::new(
                    wall.piece.key(),
                    format!(
                        "the roller (Ø{:.3} mm at {:+.3} mm from the pitch circle) does not fit its pocket: the {} cuts it by {:.3} mm",
                        2e3 * ctx.roller_radius,
                        s * 1e3,
                        wall.piece.name(),
                        -g * 1e3
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Plays of a centred roller ([`PocketPlay`]).
    pub fn play(&self, ctx: &PocketContext) -> Result<PocketPlay, GeometryError> {
        let walls = self.walls(ctx)?;
        let (r, rm) = (ctx.roller_radius, ctx.pitch_radius);
        let limit = 2.0 * r + ctx.cage_outer_radius;
        let side = walls
            .travel([rm, 0.0], [0.0, 1.0], r, limit)
            .unwrap_or(f64::INFINITY);
        let stop = walls.distance(rm, side.min(limit));
        let contact = [
            rm - r * stop.normal[0],
            side.min(limit) - r * stop.normal[1],
        ];
        let radial = |dir: f64| walls.travel([rm, 0.0], [dir, 0.0], r, 2.0 * r);
        let directions = 720;
        let closing = (0..directions)
            .filter_map(|k| {
                let (s, c) = (TAU * k as f64 / directions as f64).sin_cos();
                walls.travel([rm, 0.0], [c, s], r, limit)
            })
            .fold(f64::INFINITY, f64::min);
        Ok(PocketPlay {
            circumferential_per_side: side,
            circumferential_stop: stop.piece,
            circumferential_contact_diameter: 2.0 * contact[0].hypot(contact[1]),
            circumferential_contact: contact,
            radial_outward: radial(1.0),
            radial_inward: radial(-1.0),
            closing_displacement: closing,
        })
    }

    /// The bar's cross-section ([`BarSection`]) by the midpoint rule over the cage depth.
    pub fn bar_section(&self, ctx: &PocketContext) -> Result<BarSection, GeometryError> {
        let walls = self.walls(ctx)?;
        let (ri, ro) = (ctx.cage_inner_radius, ctx.cage_outer_radius);
        let width = |r: f64| walls.bar_width_at(r, ctx.pockets);
        let dr = (ro - ri) / SECTION_POINTS as f64;
        let radii = (0..SECTION_POINTS).map(|k| ri + (k as f64 + 0.5) * dr);
        let (mut area, mut first, mut cube) = (0.0, 0.0, 0.0);
        let (mut width_min, mut radius_of_min) = (f64::INFINITY, ri);
        for r in radii.clone() {
            let b = width(r);
            area += b * dr;
            first += b * r * dr;
            cube += b.powi(3) / 12.0 * dr;
            if b < width_min {
                (width_min, radius_of_min) = (b, r);
            }
        }
        if !(width_min > 0.0) {
            return Err(GeometryError::new(
                "cage.pocket.face_clearance",
                format!(
                    "{} pockets leave no bar at Ø{:.3} mm",
                    ctx.pockets,
                    2e3 * radius_of_min
                ),
            ));
        }
        let centroid = first / area;
        let radial: f64 = radii.map(|r| width(r) * (r - centroid).powi(2) * dr).sum();
        Ok(BarSection {
            depth: ro - ri,
            width_inner: width(ri),
            width_outer: width(ro),
            width_min,
            radius_of_min,
            area,
            centroid_radius: centroid,
            second_moment: cube,
            second_moment_radial: radial,
        })
    }

    /// Mass properties of a cage ring (`width`, density `rho`) with its windows cut: the ring
    /// less `Z` prisms of the window section `2w(r)` over the axial size; the windows' polar
    /// inertia `Z ρ L ∫ 2w r² dr` and transverse inertia `Z ρ L ∫ 2w (r²/2 + L²/12) dr` (pockets
    /// evenly spread: Σ sin²θ_j = Z/2) are subtracted exactly.
    pub fn cage_mass(
        &self,
        ctx: &PocketContext,
        width: f64,
        rho: f64,
    ) -> Result<MassProperties, GeometryError> {
        let walls = self.walls(ctx)?;
        let (ri, ro) = (ctx.cage_inner_radius, ctx.cage_outer_radius);
        let ring = MassProperties::hollow_cylinder(ri, ro, width, rho);
        let dr = (ro - ri) / SECTION_POINTS as f64;
        let (l, z) = (self.axial, ctx.pockets as f64);
        let (mut m, mut polar, mut transverse) = (0.0, 0.0, 0.0);
        for k in 0..SECTION_POINTS {
            let r = ri + (k as f64 + 0.5) * dr;
            let dm = z * rho * l * 2.0 * walls.half_window_at(r) * dr;
            m += dm;
            polar += dm * r * r;
            transverse += dm * (0.5 * r * r + l * l / 12.0);
        }
        Ok(MassProperties {
            mass: ring.mass - m,
            axial_inertia: ring.axial_inertia - polar,
            transverse_inertia: ring.transverse_inertia - transverse,
        })
    }

    /// The pocket after `depth` of wear on the wall its roller pushes: the face clearance and
    /// the lip windows grow by `depth`.
    pub fn worn(&self, depth: f64) -> Self {
        let widen = |l: RetainingLip| RetainingLip {
            window: l.window + depth,
            ..l
        };
        Self {
            face_clearance: self.face_clearance + depth,
            outer_lip: self.outer_lip.map(widen),
            inner_lip: self.inner_lip.map(widen),
            ..*self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2002834 (docs/theory.md §1.6): 18 rollers Ø15 on the pitch circle Ø180, cage Ø173.5–Ø194.
    fn ctx() -> PocketContext {
        PocketContext {
            roller_radius: 7.5e-3,
            pitch_radius: 90e-3,
            cage_inner_radius: 86.75e-3,
            cage_outer_radius: 97e-3,
            pockets: 18,
        }
    }

    fn lips_at_192_5() -> CagePocket {
        CagePocket {
            faces: PocketFaces::Flat,
            face_clearance: 4e-3,
            outer_lip: Some(RetainingLip {
                diameter: 192.5e-3,
                window: 11.25e-3,
                tip_radius: 0.0,
            }),
            inner_lip: None,
            axial: 11.25e-3,
            fillet_radius: 0.5e-3,
        }
    }

    #[test]
    fn lip_edge_play_by_hand() {
        // sharp lip edge at (ρ_L, w_L), ρ_L² + w_L² = 96.25²: the roller at the pitch radius
        // touches it when (ρ_L − r_m)² + (w_L − s)² = R_w²
        let p = lips_at_192_5();
        let play = p.play(&ctx()).unwrap();
        let w = 5.625e-3;
        let rho = (96.25e-3f64.powi(2) - w * w).sqrt();
        let hand = w - (7.5e-3f64.powi(2) - (rho - 90e-3).powi(2)).sqrt();
        assert!(
            (play.circumferential_per_side - hand).abs() < 1e-9,
            "{play:?} vs {hand}"
        );
        assert_eq!(play.circumferential_stop, WallPiece::OuterLip);
        assert!((play.circumferential_contact_diameter - 192.5e-3).abs() < 1e-6);
        // radially outwards the lips stop the roller where its chord equals the window
        let out = play.radial_outward.unwrap();
        let hand_out = rho - 90e-3 - (7.5e-3f64.powi(2) - w * w).sqrt();
        assert!((out - hand_out).abs() < 1e-9, "{out} vs {hand_out}");
        assert!(play.radial_inward.is_none());
        assert!(play.closing_displacement <= play.circumferential_per_side);
    }

    #[test]
    fn flat_faces_play_is_half_the_clearance() {
        let p = CagePocket {
            face_clearance: 0.6e-3,
            ..lips_at_192_5()
        };
        let play = p.play(&ctx()).unwrap();
        assert!((play.circumferential_per_side - 0.3e-3).abs() < 1e-9);
        assert_eq!(play.circumferential_stop, WallPiece::Face);
        assert!((play.closing_displacement - 0.3e-3).abs() < 1e-6);
    }

    #[test]
    fn concave_faces_fit_like_a_bore() {
        let p = CagePocket {
            faces: PocketFaces::Concave,
            face_clearance: 0.4e-3,
            outer_lip: None,
            ..lips_at_192_5()
        };
        let play = p.play(&ctx()).unwrap();
        // every direction closes after the radial clearance 0.2 mm
        assert!(
            (play.closing_displacement - 0.2e-3).abs() < 1e-6,
            "{play:?}"
        );
        assert!((play.circumferential_per_side - 0.2e-3).abs() < 1e-9);
    }

    #[test]
    fn a_pocket_that_cuts_its_roller_is_refused() {
        let tight = CagePocket {
            outer_lip: Some(RetainingLip {
                diameter: 186e-3,
                window: 11.25e-3,
                tip_radius: 0.0,
            }),
            ..lips_at_192_5()
        };
        let e = tight.check_fit(&ctx(), 10e-6).unwrap_err();
        assert_eq!(e.key, "cage.pocket.outer_lip.window");
        assert!(lips_at_192_5().check_fit(&ctx(), 10e-6).is_ok());
    }

    #[test]
    fn section_of_parallel_walls_by_hand() {
        // no lip: b(r) = 2πr/Z − w, linear in r: area and I by Simpson's rule are exact
        let p = CagePocket {
            outer_lip: None,
            ..lips_at_192_5()
        };
        let s = p.bar_section(&ctx()).unwrap();
        let window = 15e-3 + 4e-3;
        let b = |r: f64| TAU * r / 18.0 - window;
        let (ri, ro) = (86.75e-3, 97e-3);
        let area = 0.5 * (b(ri) + b(ro)) * (ro - ri);
        let cube = (b(ri).powi(3) + 4.0 * b(0.5 * (ri + ro)).powi(3) + b(ro).powi(3)) / 6.0
            * (ro - ri)
            / 12.0;
        assert!((s.area / area - 1.0).abs() < 1e-9);
        assert!((s.second_moment / cube - 1.0).abs() < 1e-6);
        assert!((s.width_min - b(ri)).abs() < 1e-5);
    }

    #[test]
    fn cage_mass_without_windows_is_the_ring() {
        let p = lips_at_192_5();
        let ring = MassProperties::hollow_cylinder(86.75e-3, 97e-3, 20e-3, 7850.0);
        let cut = p.cage_mass(&ctx(), 20e-3, 7850.0).unwrap();
        assert!(cut.mass < ring.mass && cut.mass > 0.5 * ring.mass);
        // removed mass = Z ρ L ∫ 2w dr
        let walls = p.walls(&ctx()).unwrap();
        let n = 100_000;
        let dr = (97e-3 - 86.75e-3) / n as f64;
        let window_area: f64 = (0..n)
            .map(|k| 2.0 * walls.half_window_at(86.75e-3 + (k as f64 + 0.5) * dr) * dr)
            .sum();
        let removed = 18.0 * 7850.0 * 11.25e-3 * window_area;
        assert!(((ring.mass - cut.mass) / removed - 1.0).abs() < 1e-3);
    }

    #[test]
    fn distance_is_one_lipschitz_and_normal_is_its_gradient() {
        let walls = lips_at_192_5().walls(&ctx()).unwrap();
        let eps = 1e-8;
        for i in 0..40 {
            for j in 0..40 {
                let rho = 84e-3 + 14e-3 * i as f64 / 39.0;
                let h = 10e-3 * j as f64 / 39.0;
                let d = walls.distance(rho, h);
                if d.distance <= 1e-6 {
                    continue;
                }
                let gr = (walls.distance(rho + eps, h).distance - d.distance) / eps;
                let gh = (walls.distance(rho, h + eps).distance - d.distance) / eps;
                let near_kink = (gr - d.normal[0]).abs() + (gh - d.normal[1]).abs() > 1e-3;
                assert!(gr.hypot(gh) <= 1.0 + 1e-5);
                if !near_kink {
                    assert!((d.normal[0].hypot(d.normal[1]) - 1.0).abs() < 1e-9);
                }
            }
        }
    }
}
