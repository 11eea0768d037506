//! The gmsh script of one pitch of the solid cage (theory §10.4): a ring sector centred on
//! pocket 0 and bounded by the centre planes of its two bars, minus the window whose corners
//! are rounded with the fillet radius, meshed with second-order tetrahedra refined around the
//! fillet corners; the two cut faces are meshed alike (periodic), so that the sector's copies
//! ([`super::mesh::Mesh::cyclic`]) join node to node and every pocket has the same mesh.

use super::CalculixSettings;
use crate::cage::CageGeometry;
use std::fmt::Write;

/// The `.geo` script (OpenCASCADE kernel, SI units) of one pitch of `cage` meshed per
/// `settings`.
///
/// The window is a rounded rectangle (tangential × axial, corner radius = fillet radius) in the
/// plane of the pocket, extruded radially through the ring; the rotation about (1,1,1) by
/// 2π/3 maps the extrusion's (x, y, z) onto (tangential, axial, radial) of pocket 0. The mesh
/// size is `fillet_mesh_size` within one fillet radius of the points where the fillet axes
/// pierce the outside and bore surfaces, growing linearly to `mesh_size` over
/// `refinement_growth`. Mid-side nodes stay on the straight edges (curved ones can invert
/// the thin tetrahedra at the fillets).
pub fn geo_script(cage: &CageGeometry, settings: &CalculixSettings) -> String {
    let mut s = String::new();
    let f = cage.fillet_radius;
    let _ = writeln!(s, "SetFactory(\"OpenCASCADE\");");
    let _ = writeln!(
        s,
        "ri = {:e}; ro = {:e}; w = {:e}; pa = {:e}; pc = {:e}; f = {:e}; Z = {};",
        cage.inner_radius,
        cage.outer_radius,
        cage.width,
        cage.pocket_axial,
        cage.pocket_circumferential,
        f,
        cage.pockets
    );
    s.push_str(RING_AND_WINDOWS);
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

/// Sector, window, boolean difference, periodic cut faces and the refinement points (both ends
/// of every fillet axis, on the bore and outside surfaces); uses the parameters set before it.
const RING_AND_WINDOWS: &str = r#"pitch = 2*Pi/Z;
outer = newv; Cylinder(outer) = {0, 0, -w/2, 0, 0, w, ro, pitch};
bore = newv; Cylinder(bore) = {0, 0, -w/2, 0, 0, w, ri};
sector() = BooleanDifference{ Volume{outer}; Delete; }{ Volume{bore}; Delete; };
Rotate {{0, 0, 1}, {0, 0, 0}, -pitch/2} { Volume{sector()}; }
s = news; Rectangle(s) = {-pc/2, -pa/2, ri/2, pc, pa, f};
e[] = Extrude {0, 0, ro} { Surface{s}; };
Rotate {{1, 1, 1}, {0, 0, 0}, 2*Pi/3} { Volume{e[1]}; }
cage() = BooleanDifference{ Volume{sector()}; Delete; }{ Volume{e[1]}; Delete; };
eps = 1e-3*f; c = Cos(pitch/2); sn = Sin(pitch/2);
minus() = Surface In BoundingBox{ri*c - eps, -ro*sn - eps, -w/2 - eps, ro*c + eps, -ri*sn + eps, w/2 + eps};
plus() = Surface In BoundingBox{ri*c - eps, ri*sn - eps, -w/2 - eps, ro*c + eps, ro*sn + eps, w/2 + eps};
Periodic Surface{plus()} = {minus()} Rotate {{0, 0, 1}, {0, 0, 0}, pitch};
radii[] = {ri, ro};
n = 0;
For side In {-1:1:2}
  For end In {-1:1:2}
    For k In {0:1}
      r = radii[k]; t = side*(pc/2 - f);
      corners[n] = newp; Point(corners[n]) = {Sqrt(r*r - t*t), t, end*(pa/2 - f)};
      n += 1;
    EndFor
  EndFor
EndFor
"#;
