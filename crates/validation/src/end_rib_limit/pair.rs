//! The roller's spherical large end against the cone's large rib, seen from the common tangent
//! plane at their initial contact (seed 000 §3.2.2, SPEC §6.7): the true initial gap between the
//! two surfaces on a grid of that plane, and the region where the two faces project onto each
//! other (the end sphere inside its chamfer edge, the rib face between undercut and rib top).
//!
//! Frame: the contact point `P` of the seated roller (mid rib height), the unit normal `n` from
//! the rib toward the roller, `e_u` up the rib face in the axial section, `e_v` circumferential.
//! A tangent-plane point `(u, v)` is the foot of the normal line `P + u e_u + v e_v + h n`; a
//! surface's height `h(u, v)` along that line is found exactly (no quadratic approximation).
//! Grid columns run along `v`, rows along `u`.

use rolldyn_contact::boussinesq::{BoussinesqError, Grid, combined_compliance};
use rolldyn_contact::hertz::ContactCurvatures;
use rolldyn_geometry::{DoubleRowTaperedBearing, LargeRibContact, Rz, TaperedRibFace};

/// Initial gap given to cells outside the mutual projection, m: there the chamfer, the undercut
/// or the missing rib leave far more clearance (≥ 0.1 mm) than the ≈ 20 µm approaches of the
/// contact, so no pressure can arise.
pub const OUTSIDE_GAP_M: f64 = 1e-3;

/// Iterations of the height search along the normal: each removes a factor `1 − n·∇d ≤ 0.03`
/// of the error (the face normal turns by less than 10° over the grid).
const HEIGHT_ITERATIONS: usize = 12;

/// A point in the bearing's 3-D frame: `x` radial through the contact, `y` circumferential,
/// `z` along the bearing axis.
#[derive(Debug, Clone, Copy)]
struct P3([f64; 3]);

impl P3 {
    fn in_axial_section(p: Rz) -> Self {
        Self([p.r, 0.0, p.z])
    }

    fn along(self, d: P3, s: f64) -> Self {
        Self([
            self.0[0] + s * d.0[0],
            self.0[1] + s * d.0[1],
            self.0[2] + s * d.0[2],
        ])
    }

    fn minus(self, o: P3) -> Self {
        self.along(o, -1.0)
    }

    fn dot(self, o: P3) -> f64 {
        self.0[0] * o.0[0] + self.0[1] * o.0[1] + self.0[2] * o.0[2]
    }

    /// The point's (r, z) in the axial half-plane of the bearing.
    fn section(self) -> Rz {
        Rz::new(self.0[0].hypot(self.0[1]), self.0[2])
    }
}

/// The rib face's axial-section profile: signed distance of a half-plane point from it,
/// positive on the roller's side.
fn rib_clearance(rib: &LargeRibContact, q: Rz) -> f64 {
    match (rib.face, rib.face_centre) {
        (TaperedRibFace::ConcaveTorus { radius }, Some(c)) => radius - (q - c).norm(),
        (TaperedRibFace::ConvexTorus { radius }, Some(c)) => (q - c).norm() - radius,
        _ => (q - rib.point).dot(rib.normal),
    }
}

/// How the rib face is shaped away from the axial section through the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RibSurface {
    /// The true face: the axial-section profile revolved about the bearing axis (it is concave
    /// along the parallel circle, curvature `n_r / r`).
    Revolution,
    /// The axial-section profile swept straight along the circumferential direction: the
    /// reading of the seed's `Σρ = 1/R_end ∓ 1/R_rib` and of the dynamics' Hertz law, which
    /// leave the circumferential curvature out.
    AxialProfile,
}

/// The end sphere and the rib face of one bearing in the tangent-plane frame.
#[derive(Debug, Clone, Copy)]
struct TangentFrame {
    rib: LargeRibContact,
    p: P3,
    n: P3,
    e_u: P3,
    e_v: P3,
    /// roller axis (small → large end)
    axis: P3,
    sphere_radius: f64,
    /// radius of the end face at its chamfer edge
    face_radius: f64,
    surface: RibSurface,
}

impl TangentFrame {
    fn of(bearing: &DoubleRowTaperedBearing, surface: RibSurface) -> Self {
        let row = bearing.row(0);
        let rib = row.large_rib;
        Self {
            rib,
            p: P3::in_axial_section(rib.point),
            n: P3::in_axial_section(rib.normal),
            e_u: P3::in_axial_section(rib.tangent),
            e_v: P3([0.0, 1.0, 0.0]),
            axis: P3::in_axial_section(row.roller_axis),
            sphere_radius: bearing.roller.large_end_sphere_radius,
            face_radius: bearing.roller.large_end_face_radius(),
            surface,
        }
    }

    fn foot(&self, u: f64, v: f64) -> P3 {
        self.p.along(self.e_u, u).along(self.e_v, v)
    }

    /// Height of the end sphere above the tangent plane along `n` (toward the roller), m.
    fn sphere_height(&self, u: f64, v: f64) -> f64 {
        let r = self.sphere_radius;
        r - (r * r - u * u - v * v).max(0.0).sqrt()
    }

    /// The rib-face point over `(u, v)` lies in the axial section through this foot point.
    fn rib_foot(&self, u: f64, v: f64) -> P3 {
        match self.surface {
            RibSurface::Revolution => self.foot(u, v),
            RibSurface::AxialProfile => self.foot(u, 0.0),
        }
    }

    /// Height of the rib face above the tangent plane along `n`, m (negative where the face
    /// falls away from the roller): the root of the profile clearance along the normal line.
    fn rib_height(&self, u: f64, v: f64) -> f64 {
        let foot = self.rib_foot(u, v);
        let mut h = 0.0;
        for _ in 0..HEIGHT_ITERATIONS {
            h -= rib_clearance(&self.rib, foot.along(self.n, h).section());
        }
        h
    }

    /// Distance of a point from the roller axis (through the end-sphere centre), m.
    fn distance_to_roller_axis(&self, point: P3) -> f64 {
        let w = point.minus(self.p.along(self.n, self.sphere_radius));
        let along_axis = w.dot(self.axis);
        (w.dot(w) - along_axis * along_axis).max(0.0).sqrt()
    }

    /// Whether the end-sphere point over `(u, v)` lies inside the chamfer edge.
    fn on_end_face(&self, u: f64, v: f64) -> bool {
        let point = self.foot(u, v).along(self.n, self.sphere_height(u, v));
        self.distance_to_roller_axis(point) <= self.face_radius
    }

    /// Whether the rib-face point over `(u, v)` lies in the band between undercut and rib top
    /// (measured along the face tangent in the axial section, as [`LargeRibContact::band`]).
    fn on_rib_band(&self, u: f64, v: f64) -> bool {
        let q = self
            .rib_foot(u, v)
            .along(self.n, self.rib_height(u, v))
            .section();
        let s = (q - self.rib.point).dot(self.rib.tangent);
        (self.rib.band.0..=self.rib.band.1).contains(&s)
    }

    /// Signed curvature of the rib face along the parallel circle (Meusnier: `n_r / r`),
    /// convex > 0 as in [`ContactCurvatures`], 1/m.
    fn rib_circumferential_curvature(&self) -> f64 {
        match self.surface {
            RibSurface::Revolution => self.rib.circumferential_curvature(),
            RibSurface::AxialProfile => 0.0,
        }
    }
}

/// The end–rib pair of one bearing and rib face on its tangent-plane grid.
#[derive(Debug, Clone)]
pub struct EndRibPair {
    pub face: TaperedRibFace,
    pub surface: RibSurface,
    /// Grid of the tangent plane: `x` circumferential (`v`), `y` up the rib face (`u`); it
    /// covers the mutual projection plus one ring of cells outside it.
    pub grid: Grid,
    /// Initial gap per cell (true geometry inside, [`OUTSIDE_GAP_M`] outside), m.
    pub gap: Vec<f64>,
    /// Cells whose centre lies in the mutual projection of end face and rib face.
    pub inside: Vec<bool>,
    /// Inside cells with an edge-neighbour outside: the projection boundary.
    pub boundary: Vec<bool>,
    /// Combined compliance `(1−ν₁²)/(πE₁) + (1−ν₂²)/(πE₂)` of roller and cone, 1/Pa.
    pub compliance: f64,
    /// Principal curvatures of end sphere and rib face at the contact (axial section,
    /// circumferential), convex > 0.
    pub curvatures: ContactCurvatures,
    /// Shortest distance from the contact point to the projection boundary along the face
    /// (to the chamfer edge, to the undercut, to the rib top), m.
    pub margin: f64,
}

impl EndRibPair {
    /// Builds the pair for `bearing` with its large rib given the face `face` (placed, as in
    /// the seed, so that the initial contact lies at mid rib height), its surface read as
    /// `surface`, on square cells of size `cell` (m).
    pub fn new(
        bearing: &DoubleRowTaperedBearing,
        face: TaperedRibFace,
        surface: RibSurface,
        cell: f64,
    ) -> Result<Self, BoussinesqError> {
        let mut bearing = bearing.clone();
        bearing.large_rib.face = face;
        let frame = TangentFrame::of(&bearing, surface);
        let search = search_grid(&frame, cell)?;
        let inside_search = search.eval(|v, u| inside_flag(&frame, u, v));
        let grid = crop_to(&search, &inside_search)?;
        let inside: Vec<bool> = grid
            .eval(|v, u| inside_flag(&frame, u, v))
            .iter()
            .map(|&f| f > 0.0)
            .collect();
        let gap = grid
            .eval(|v, u| frame.sphere_height(u, v) - frame.rib_height(u, v))
            .iter()
            .zip(&inside)
            .map(|(&g, &i)| if i { g } else { OUTSIDE_GAP_M })
            .collect();
        let boundary = boundary_cells(&grid, &inside);
        let end = &bearing.roller.material;
        let cone = &bearing.inner_material;
        let sphere = 1.0 / frame.sphere_radius;
        Ok(Self {
            face,
            surface,
            grid,
            gap,
            inside,
            boundary,
            compliance: combined_compliance(
                end.youngs_modulus,
                end.poisson_ratio,
                cone.youngs_modulus,
                cone.poisson_ratio,
            ),
            curvatures: ContactCurvatures {
                body1: (sphere, sphere),
                body2: (-face.curvature(), frame.rib_circumferential_curvature()),
                angle: 0.0,
            },
            margin: contact_margin(&frame),
        })
    }

    /// Reduced curvature of the axial section, `Σρ = 1/R_end − κ_rib` (seed 000 §3.2.2), 1/m.
    pub fn reduced_curvature(&self) -> f64 {
        self.curvatures.body1.0 + self.curvatures.body2.0
    }

    /// Reduced curvature along the parallel circle, `1/R_end + κ_rib,circ`, 1/m.
    pub fn circumferential_reduced_curvature(&self) -> f64 {
        self.curvatures.body1.1 + self.curvatures.body2.1
    }

    /// Whether any projection-boundary cell carries pressure.
    pub fn reaches_boundary(&self, pressure: &[f64]) -> bool {
        pressure
            .iter()
            .zip(&self.boundary)
            .any(|(&p, &b)| b && p > 0.0)
    }

    /// Projection boundary as cell-edge segments `((v₀, u₀), (v₁, u₁))` between inside and
    /// outside cells, m (for plots).
    pub fn outline(&self) -> Vec<[(f64, f64); 2]> {
        let g = &self.grid;
        let (hx, hy) = (0.5 * g.dx, 0.5 * g.dy);
        let mut segments = Vec::new();
        for j in 0..g.ny {
            for i in 0..g.nx {
                if !self.inside[g.index(i, j)] {
                    continue;
                }
                let (x, y) = (g.x(i), g.y(j));
                let out = |di: isize, dj: isize| !self.inside[neighbour(g, i, j, di, dj)];
                if out(-1, 0) {
                    segments.push([(x - hx, y - hy), (x - hx, y + hy)]);
                }
                if out(1, 0) {
                    segments.push([(x + hx, y - hy), (x + hx, y + hy)]);
                }
                if out(0, -1) {
                    segments.push([(x - hx, y - hy), (x + hx, y - hy)]);
                }
                if out(0, 1) {
                    segments.push([(x - hx, y + hy), (x + hx, y + hy)]);
                }
            }
        }
        segments
    }
}

/// 1.0 where the cell centre `(u, v)` lies in the mutual projection, else 0.0.
fn inside_flag(frame: &TangentFrame, u: f64, v: f64) -> f64 {
    f64::from(u8::from(frame.on_end_face(u, v) && frame.on_rib_band(u, v)))
}

/// Distance from the contact point to the nearest edge of the projection: rib band ends and
/// the end face's chamfer edge (measured from the roller axis, as the dynamics' margin), m.
fn contact_margin(frame: &TangentFrame) -> f64 {
    let (below, above) = frame.rib.band;
    (frame.face_radius - frame.distance_to_roller_axis(frame.p))
        .min(-below)
        .min(above)
}

/// A grid that surely contains the projection: the rib band along `u`, the end face's
/// diameter along `v`, one cell beyond each side.
fn search_grid(frame: &TangentFrame, cell: f64) -> Result<Grid, BoussinesqError> {
    let (below, above) = frame.rib.band;
    let half_width = frame.face_radius + cell;
    let nx = (2.0 * half_width / cell).ceil() as usize;
    let ny = ((above - below) / cell).ceil() as usize + 2;
    Grid::new(nx, ny, cell, cell, -0.5 * nx as f64 * cell, below - cell)
}

/// The sub-grid of `grid` spanning the cells flagged in `flags` plus one ring around them.
fn crop_to(grid: &Grid, flags: &[f64]) -> Result<Grid, BoussinesqError> {
    let flagged = |i: usize, j: usize| flags[grid.index(i, j)] > 0.0;
    let cols: Vec<usize> = (0..grid.nx)
        .filter(|&i| (0..grid.ny).any(|j| flagged(i, j)))
        .collect();
    let rows: Vec<usize> = (0..grid.ny)
        .filter(|&j| (0..grid.nx).any(|i| flagged(i, j)))
        .collect();
    let (Some(&i0), Some(&i1), Some(&j0), Some(&j1)) =
        (cols.first(), cols.last(), rows.first(), rows.last())
    else {
        return Err(BoussinesqError::InvalidGrid(
            "the end face and the rib face do not overlap".into(),
        ));
    };
    Grid::new(
        i1 - i0 + 3,
        j1 - j0 + 3,
        grid.dx,
        grid.dy,
        grid.x_min + (i0 as f64 - 1.0) * grid.dx,
        grid.y_min + (j0 as f64 - 1.0) * grid.dy,
    )
}

/// Index of the edge-neighbour `(i + di, j + dj)`, clamped to the grid.
fn neighbour(g: &Grid, i: usize, j: usize, di: isize, dj: isize) -> usize {
    let clamp = |k: usize, d: isize, n: usize| (k as isize + d).clamp(0, n as isize - 1) as usize;
    g.index(clamp(i, di, g.nx), clamp(j, dj, g.ny))
}

fn boundary_cells(g: &Grid, inside: &[bool]) -> Vec<bool> {
    let mut boundary = vec![false; g.len()];
    for j in 0..g.ny {
        for i in 0..g.nx {
            let k = g.index(i, j);
            boundary[k] = inside[k]
                && [(-1, 0), (1, 0), (0, -1), (0, 1)]
                    .iter()
                    .any(|&(di, dj)| !inside[neighbour(g, i, j, di, dj)]);
        }
    }
    boundary
}
