//! The gmsh script of one pitch of the solid cage (theory §10.4): a ring sector centred on
//! pocket 0 and bounded by the centre planes of its two bars, minus the window of the pocket
//! profile (faces and lips) whose corners are rounded with the fillet radius, meshed with second-order tetrahedra refined around the
//! fillet corners; the two cut faces are meshed alike (periodic), so that the sector's copies
//! ([`super::mesh::Mesh::cyclic`]) join node to node and every pocket has the same mesh.

use super::CalculixSettings;
use crate::cage::CageGeometry;
use rolldyn_geometry::PocketFaces;
use std::fmt::Write;

/// Sub-bands per band of concave faces: their half-width varies along `ρ`, cut as a staircase
/// of constant-width steps at the sub-band's widest (6 keep the step below 2 % of a face's
/// sagitta).
const CONCAVE_STEPS: usize = 6;

/// The window's cross-section as radial bands `(ρ₀, ρ₁, w)` of constant half-width `w` (the
/// profile's [`rolldyn_geometry::PocketWalls::half_window_at`]; lip steps split the bands), from
/// inside the bore to outside the cage; each band reaches over a wider neighbour, which its
/// narrower window fits in, so that the cuts overlap instead of touching.
pub fn window_bands(cage: &CageGeometry) -> Vec<(f64, f64, f64)> {
    let Ok(walls) = cage.walls() else {
        return Vec::new();
    };
    let (lo, hi) = (0.5 * cage.inner_radius, 1.1 * cage.outer_radius);
    let mut edges = vec![lo];
    edges.extend(walls.steps());
    edges.push(hi);
    let steps = match walls.faces() {
        PocketFaces::Flat => 1,
        PocketFaces::Concave => CONCAVE_STEPS,
    };
    let mut bands = Vec::new();
    for pair in edges.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        for k in 0..steps {
            let (r0, r1) = (
                a + (b - a) * k as f64 / steps as f64,
                a + (b - a) * (k + 1) as f64 / steps as f64,
            );
            // the widest of the sub-band (a step's narrow side lies at its ends' insides)
            let w = (0..=8)
                .map(|i| walls.half_window_at(r0 + (r1 - r0) * (0.01 + 0.98 * i as f64 / 8.0)))
                .fold(0.0, f64::max);
            bands.push((r0, r1, w));
        }
    }
    let reach: Vec<(f64, f64, f64)> = (0..bands.len())
        .map(|k| {
            let (mut r0, mut r1, w) = bands[k];
            if k > 0 && bands[k - 1].2 >= w {
                r0 = bands[k - 1].0;
            }
            if k + 1 < bands.len() && bands[k + 1].2 >= w {
                r1 = bands[k + 1].1;
            }
            (r0, r1, w)
        })
        .collect();
    reach
}

/// The `.geo` script (OpenCASCADE kernel, SI units) of one pitch of `cage` meshed per
/// `settings`.
///
/// The window is cut band by band ([`window_bands`]): in each, a rounded rectangle (tangential
/// `2w` × axial, corner radius = fillet radius) in the plane of the pocket, extruded radially
/// over the band; the rotation about (1,1,1) by 2π/3 maps the extrusion's (x, y, z) onto
/// (tangential, axial, radial) of pocket 0. The fillet rounds the window's corners where bar
/// (face or lip) meets rim. The mesh size is `fillet_mesh_size` within one fillet radius of
/// the points where the fillet axes pierce the outside and bore surfaces, growing linearly to
/// `mesh_size` over `refinement_growth`. Mid-side nodes stay on the straight edges (curved ones
/// can invert the thin tetrahedra at the fillets).
pub fn geo_script(cage: &CageGeometry, settings: &CalculixSettings) -> String {
    let mut s = String::new();
    let f = cage.fillet_radius();
    let _ = writeln!(s, "SetFactory(\"OpenCASCADE\");");
    let _ = writeln!(
        s,
        "ri = {:e}; ro = {:e}; w = {:e}; pa = {:e}; f = {:e}; Z = {};",
        cage.inner_radius, cage.outer_radius, cage.width, cage.pocket.axial, f, cage.pockets
    );
    s.push_str(SECTOR);
    for (k, (r0, r1, hw)) in window_bands(cage).into_iter().enumerate() {
        let _ = writeln!(
            s,
            "s = news; Rectangle(s) = {{{:e}, -pa/2, {r0:e}, {:e}, pa, f}};\n\
             e[] = Extrude {{0, 0, {:e}}} {{ Surface{{s}}; }};\nwindow[{k}] = e[1];",
            -hw,
            2.0 * hw,
            r1 - r0
        );
    }
    s.push_str(CUT);
    let mut n = 0;
    for side in [-1.0, 1.0] {
        for end in [-1.0, 1.0] {
            for r in [cage.inner_radius, cage.outer_radius] {
                let t = side * (cage.window_edge_on(r)[1] - f);
                let _ = writeln!(
                    s,
                    "corners[{n}] = newp; Point(corners[{n}]) = {{{:e}, {t:e}, {:e}}};",
                    (r * r - t * t).sqrt(),
                    end * (0.5 * cage.pocket.axial - f)
                );
                n += 1;
            }
        }
    }
    let _ = writeln!(
        s,
        "Field[1] = Distance;\nField[1].NodesList = {{corners[]}};\n\
         Field[2] = Threshold;\nField[2].IField = 1;\nField[2].LcMin = {:e};\n\
         Field[2].LcMax = {:e};\nField[2].DistMin = f;\nField[2].DistMax = f + {:e};\n\
         Background Field = 2;",
        settings.fillet_mesh_size, settings.mesh_size, settings.refinement_growth
    );
    let _ = writeln!(
        s,
        "Mesh.MeshSizeExtendFromBoundary = 0;\nMesh.MeshSizeMax = {:e};\n\
         Mesh.ElementOrder = 2;\nMesh.SecondOrderLinear = 1;\nMesh.SaveAll = 0;\nPhysical Volume(\"cage\") = {{cage()}};",
        settings.mesh_size
    );
    s
}

/// The ring sector of one pitch centred on pocket 0; uses the parameters set before it.
const SECTOR: &str = r#"pitch = 2*Pi/Z;
outer = newv; Cylinder(outer) = {0, 0, -w/2, 0, 0, w, ro, pitch};
bore = newv; Cylinder(bore) = {0, 0, -w/2, 0, 0, w, ri};
sector() = BooleanDifference{ Volume{outer}; Delete; }{ Volume{bore}; Delete; };
Rotate {{0, 0, 1}, {0, 0, 0}, -pitch/2} { Volume{sector()}; }
"#;

/// The window's bands turned onto pocket 0 and cut from the sector, and the periodic cut faces.
const CUT: &str = r#"Rotate {{1, 1, 1}, {0, 0, 0}, 2*Pi/3} { Volume{window[]}; }
cage() = BooleanDifference{ Volume{sector()}; Delete; }{ Volume{window[]}; Delete; };
eps = 1e-3*f; c = Cos(pitch/2); sn = Sin(pitch/2);
minus() = Surface In BoundingBox{ri*c - eps, -ro*sn - eps, -w/2 - eps, ro*c + eps, -ri*sn + eps, w/2 + eps};
plus() = Surface In BoundingBox{ri*c - eps, ri*sn - eps, -w/2 - eps, ro*c + eps, ro*sn + eps, w/2 + eps};
Periodic Surface{plus()} = {minus()} Rotate {{0, 0, 1}, {0, 0, 0}, pitch};
"#;
