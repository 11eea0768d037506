//! The machined cage as the stress models see it (theory §10.2): its geometry, the load
//! stations of one pocket and the evaluation points at the bar–rim fillets.
//!
//! **Cage coordinates** (the frame of the load export, SI): origin at the cage centre, `z` along
//! the cage axis (the axial mid-plane at `z = 0`), `x` through the centre of pocket 0. Pocket `j`
//! is centred at `θ_j = 2πj/Z`; bar `b` lies between pockets `b` and `b + 1`, at
//! `θ_b = θ_b^pocket + π/Z`. Rim 0 is at `z < 0`, rim 1 at `z > 0`.
//!
//! Stress tensors are stored in cylindrical components `[σ_rr, σ_θθ, σ_zz, τ_rθ, τ_θz, τ_zr]`
//! and forces in the local pocket frame `[radial, tangential (+θ), axial]`: both are invariant
//! under a rotation of the cage by whole pitches, which is how a unit load case at pocket 0
//! gives the stresses for a load at any pocket (cyclic symmetry of the cage).

use rolldyn_geometry::{BarSection, CagePocket, GeometryError, PocketContext, PocketWalls};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Geometry and material of a bar-type (machined window) cage, SI: the ring, and its pocket
/// as [`CagePocket`] (faces, retaining lips, axial size, fillet radius) resolved with the
/// roller and pitch radii — the one profile that also feeds the contact law and the mass.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CageGeometry {
    /// number of pockets Z
    pub pockets: usize,
    /// bore radius, m
    pub inner_radius: f64,
    /// outside radius, m
    pub outer_radius: f64,
    /// axial width, m
    pub width: f64,
    /// the pocket profile (`cage.pocket` of the model)
    pub pocket: CagePocket,
    /// roller radius and pitch radius, what the profile needs of the bearing, m
    pub roller_radius: f64,
    pub pitch_radius: f64,
    /// where a centred roller touches the bar, pocket coordinates `(ρ, h)` of pocket 0, m
    pub bar_contact: [f64; 2],
    /// Young's modulus, Pa
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    /// density, kg/m³
    pub density: f64,
}

impl CageGeometry {
    /// Angle of the centre of pocket `j`, rad.
    pub fn pocket_angle(&self, j: usize) -> f64 {
        2.0 * PI * j as f64 / self.pockets as f64
    }

    /// Angle of the centre line of bar `b` (between pockets `b` and `b + 1`), rad.
    pub fn bar_angle(&self, b: usize) -> f64 {
        self.pocket_angle(b) + PI / self.pockets as f64
    }

    /// Axial size of a window, m.
    pub fn pocket_axial(&self) -> f64 {
        self.pocket.axial
    }

    /// Radius of the window-corner fillet between bar and rim, m.
    pub fn fillet_radius(&self) -> f64 {
        self.pocket.fillet_radius
    }

    /// Axial thickness of one rim, m.
    pub fn rim_axial(&self) -> f64 {
        0.5 * (self.width - self.pocket.axial)
    }

    /// Radial thickness of rims and bars, m.
    pub fn radial_thickness(&self) -> f64 {
        self.outer_radius - self.inner_radius
    }

    /// Mean radius of rims and bars, m.
    pub fn mean_radius(&self) -> f64 {
        0.5 * (self.inner_radius + self.outer_radius)
    }

    /// What the pocket profile needs of the bearing.
    pub fn context(&self) -> PocketContext {
        PocketContext {
            roller_radius: self.roller_radius,
            pitch_radius: self.pitch_radius,
            cage_inner_radius: self.inner_radius,
            cage_outer_radius: self.outer_radius,
            pockets: self.pockets,
        }
    }

    /// The pocket walls ([`CagePocket::walls`]).
    pub fn walls(&self) -> Result<PocketWalls, GeometryError> {
        self.pocket.walls(&self.context())
    }

    /// The bar's cross-section ([`CagePocket::bar_section`]).
    pub fn bar_section(&self) -> Result<BarSection, GeometryError> {
        self.pocket.bar_section(&self.context())
    }

    /// Tangential half-width of the window at `ρ` ([`PocketWalls::half_window_at`]; NaN for a
    /// profile [`CageGeometry::problems`] refuses), m.
    pub fn half_window_at(&self, rho: f64) -> f64 {
        self.walls().map_or(f64::NAN, |w| w.half_window_at(rho))
    }

    /// Circumferential width of a bar at radius `r` ([`PocketWalls::bar_width_at`]), m.
    pub fn bar_width_at(&self, r: f64) -> f64 {
        self.walls()
            .map_or(f64::NAN, |w| w.bar_width_at(r, self.pockets))
    }

    /// Where the window's flank meets the cylinder of radius `r`, pocket coordinates `(ρ, h)`:
    /// `h = w(ρ)` with `ρ² + h² = r²`, by fixed-point iteration from `ρ = r` (a step of the
    /// profile at the crossing resolves to its narrower side), m.
    pub fn window_edge_on(&self, r: f64) -> [f64; 2] {
        let mut rho = r;
        let mut h = self.half_window_at(rho);
        for _ in 0..50 {
            let next = (r * r - h * h).max(0.0).sqrt();
            let next_h = self
                .half_window_at(next)
                .min(self.half_window_at(next + 1e-12));
            if (next_h - h).abs() < 1e-15 && (next - rho).abs() < 1e-15 {
                break;
            }
            (rho, h) = (next, next_h);
        }
        [(r * r - h * h).max(0.0).sqrt(), h]
    }

    /// The cage with the fillet radius `f` (the command line's override), or as it is.
    pub fn with_fillet_radius(mut self, f: Option<f64>) -> Self {
        if let Some(f) = f {
            self.pocket.fillet_radius = f;
        }
        self
    }

    /// The reasons this cage cannot be modelled (empty when it can).
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.pockets < 3 {
            out.push(format!("{} pockets (at least 3)", self.pockets));
        }
        if !(self.inner_radius > 0.0 && self.outer_radius > self.inner_radius) {
            out.push("the outside diameter must exceed the bore".into());
            return out;
        }
        if !(self.pocket.axial > 0.0 && self.pocket.axial < self.width) {
            out.push("the axial window size must be below the cage width".into());
        }
        let section = match self.bar_section() {
            Ok(s) => s,
            Err(e) => {
                out.push(format!("the windows leave no bar: {e}"));
                return out;
            }
        };
        let narrowest = [self.inner_radius, self.outer_radius]
            .map(|r| self.window_edge_on(r)[1])
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        let f = self.fillet_radius();
        if !(f >= 0.0
            && 2.0 * f < self.rim_axial().min(self.pocket.axial)
            && f < narrowest
            && f < 0.5 * section.width_min)
        {
            out.push("the fillet radius must be below half the rim, window and bar sizes".into());
        }
        out
    }
}

/// Side of a pocket: the bar at lower `θ` (bar `j − 1`) or at higher `θ` (bar `j`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PocketSide {
    Minus,
    Plus,
}

impl PocketSide {
    /// −1 or +1.
    pub fn sign(self) -> f64 {
        match self {
            PocketSide::Minus => -1.0,
            PocketSide::Plus => 1.0,
        }
    }
}

/// Where a unit load of one pocket acts (cage coordinates of pocket 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Station {
    /// on the flank of a bar where a centred roller touches it, at axial station `end` (0: `z < 0`)
    Bar { side: PocketSide, end: usize },
    /// on the rim face that closes the window axially (`end` 0: rim 0), at the mean radius
    PocketEnd { end: usize },
    /// on the bore of rim `rim`, at the pocket centre (`at_bar` false) or under the bar
    Land { rim: usize, at_bar: bool },
}

/// The stations of one pocket, in a fixed order (the unit cases' order).
pub const STATIONS: [Station; 10] = [
    Station::Bar {
        side: PocketSide::Minus,
        end: 0,
    },
    Station::Bar {
        side: PocketSide::Minus,
        end: 1,
    },
    Station::Bar {
        side: PocketSide::Plus,
        end: 0,
    },
    Station::Bar {
        side: PocketSide::Plus,
        end: 1,
    },
    Station::PocketEnd { end: 0 },
    Station::PocketEnd { end: 1 },
    Station::Land {
        rim: 0,
        at_bar: false,
    },
    Station::Land {
        rim: 0,
        at_bar: true,
    },
    Station::Land {
        rim: 1,
        at_bar: false,
    },
    Station::Land {
        rim: 1,
        at_bar: true,
    },
];

/// Axial position of the two bar stations, m: the ends of the roller's straight part, where
/// the dynamics evaluates the bar contacts (`±bar_station_z`).
pub type BarStationZ = f64;

impl Station {
    /// Point of the station of pocket 0 in cage coordinates, m (`bar_z`: the axial position of
    /// the bar stations).
    pub fn point(self, cage: &CageGeometry, bar_z: BarStationZ) -> [f64; 3] {
        let rim_z = 0.5 * (cage.pocket.axial + cage.rim_axial());
        let end_sign = |end: usize| if end == 0 { -1.0 } else { 1.0 };
        match self {
            Station::Bar { side, end } => [
                cage.bar_contact[0],
                side.sign() * cage.bar_contact[1].abs(),
                end_sign(end) * bar_z,
            ],
            Station::PocketEnd { end } => [
                cage.mean_radius(),
                0.0,
                end_sign(end) * 0.5 * cage.pocket.axial,
            ],
            Station::Land { rim, at_bar } => {
                let angle = if at_bar {
                    PI / cage.pockets as f64
                } else {
                    0.0
                };
                let (s, c) = angle.sin_cos();
                [
                    cage.inner_radius * c,
                    cage.inner_radius * s,
                    end_sign(rim) * rim_z,
                ]
            }
        }
    }
}

/// Radial face of a fillet evaluation point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Face {
    Outer,
    Inner,
}

/// A point where stresses are evaluated: the window-corner fillet of bar `bar` at rim `rim`, on
/// the window side `side` of the bar (`Minus`: facing pocket `bar`, `Plus`: facing pocket
/// `bar + 1`), on the outside or bore surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct FilletPoint {
    pub bar: usize,
    pub rim: usize,
    pub side: PocketSide,
    pub face: Face,
}

impl FilletPoint {
    /// The evaluation points of all bars, bar-major, in a fixed order (8 per bar).
    pub fn all(pockets: usize) -> Vec<FilletPoint> {
        let mut out = Vec::with_capacity(8 * pockets);
        for bar in 0..pockets {
            for rim in 0..2 {
                for side in [PocketSide::Minus, PocketSide::Plus] {
                    for face in [Face::Outer, Face::Inner] {
                        out.push(FilletPoint {
                            bar,
                            rim,
                            side,
                            face,
                        });
                    }
                }
            }
        }
        out
    }

    /// Index of this point in [`FilletPoint::all`].
    pub fn index(self) -> usize {
        let side = usize::from(self.side == PocketSide::Plus);
        let face = usize::from(self.face == Face::Inner);
        8 * self.bar + 4 * self.rim + 2 * side + face
    }

    /// The same point on the bar `shift` pitches lower (cyclic symmetry).
    pub fn shifted_down(self, shift: usize, pockets: usize) -> FilletPoint {
        FilletPoint {
            bar: (self.bar + pockets - shift % pockets) % pockets,
            ..self
        }
    }

    /// Position of the corner the fillet rounds, cage coordinates, m: where the bar flank (the
    /// profile's face or lip, [`CageGeometry::window_edge_on`]) meets the rim face on the
    /// outside or bore surface.
    pub fn corner(self, cage: &CageGeometry) -> [f64; 3] {
        let r = match self.face {
            Face::Outer => cage.outer_radius,
            Face::Inner => cage.inner_radius,
        };
        let pocket = match self.side {
            PocketSide::Minus => self.bar,
            PocketSide::Plus => (self.bar + 1) % cage.pockets,
        };
        let [along, half] = cage.window_edge_on(r);
        let flank = -self.side.sign() * half;
        let (s, c) = cage.pocket_angle(pocket).sin_cos();
        let z = if self.rim == 0 { -1.0 } else { 1.0 } * 0.5 * cage.pocket.axial;
        [along * c - flank * s, along * s + flank * c, z]
    }

    /// Short label, e.g. `bar3-rim0-minus-outer`.
    pub fn label(self) -> String {
        let side = match self.side {
            PocketSide::Minus => "minus",
            PocketSide::Plus => "plus",
        };
        let face = match self.face {
            Face::Outer => "outer",
            Face::Inner => "inner",
        };
        format!("bar{}-rim{}-{side}-{face}", self.bar, self.rim)
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The 2002834 cage: flat faces 19 mm apart, outer lips on Ø192.5 mm 11.25 mm apart.
    pub(crate) fn cage_2002834() -> CageGeometry {
        CageGeometry {
            pockets: 18,
            inner_radius: 86.75e-3,
            outer_radius: 97.0e-3,
            width: 20e-3,
            pocket: CagePocket {
                faces: rolldyn_geometry::PocketFaces::Flat,
                face_clearance: 4e-3,
                outer_lip: Some(rolldyn_geometry::RetainingLip {
                    diameter: 192.5e-3,
                    window: 11.25e-3,
                    tip_radius: 0.0,
                }),
                inner_lip: None,
                axial: 11.25e-3,
                fillet_radius: 1e-3,
            },
            roller_radius: 7.5e-3,
            pitch_radius: 90e-3,
            bar_contact: [96.085e-3, 5.625e-3],
            youngs_modulus: 211e9,
            poisson_ratio: 0.3,
            density: 7850.0,
        }
    }

    #[test]
    fn indices_follow_the_order_of_all() {
        for (i, p) in FilletPoint::all(5).into_iter().enumerate() {
            assert_eq!(p.index(), i);
            assert_eq!(p.shifted_down(7, 5).bar, (p.bar + 3) % 5);
        }
    }

    #[test]
    fn outer_corners_sit_on_the_lips_and_bore_corners_on_the_faces() {
        let cage = cage_2002834();
        assert!((cage.window_edge_on(cage.outer_radius)[1] - 5.625e-3).abs() < 1e-15);
        assert!((cage.window_edge_on(cage.inner_radius)[1] - 9.5e-3).abs() < 1e-15);
        let [rho, h] = cage.window_edge_on(cage.outer_radius);
        assert!((rho.hypot(h) - cage.outer_radius).abs() < 1e-15);
    }

    #[test]
    fn corners_sit_on_the_window_flanks() {
        let cage = cage_2002834();
        assert!(cage.problems().is_empty());
        for p in FilletPoint::all(cage.pockets) {
            let [x, y, _] = p.corner(&cage);
            let pocket = match p.side {
                PocketSide::Minus => p.bar,
                PocketSide::Plus => (p.bar + 1) % cage.pockets,
            };
            let (s, c) = cage.pocket_angle(pocket).sin_cos();
            let across = -x * s + y * c;
            let along = x * c + y * s;
            assert!((across.abs() - cage.half_window_at(along)).abs() < 1e-12);
            // the corner lies between the pocket centre and the bar centre line
            let theta = y.atan2(x).rem_euclid(2.0 * PI);
            let bar = cage.bar_angle(p.bar).rem_euclid(2.0 * PI);
            let d = (theta - bar + PI).rem_euclid(2.0 * PI) - PI;
            assert!(d.abs() < PI / cage.pockets as f64);
        }
    }
}
