//! The ccx input deck (theory §10.4): mesh, material, the 3-2-1 support and one linear static
//! step per load: the unit force cases (patch force plus the translational inertia relief as a
//! uniform `GRAV` body load), the three unit angular-acceleration inertia cases and the unit
//! spin² (`CENTRIF`) case, each printing the support reactions and the fillet-node stresses.
//! Numbers are written with 11 significant digits: ccx reads at most 20 characters a field.

use super::loads::RigidBody;
use super::mesh::Mesh;
use crate::cage::CageGeometry;
use std::fmt::Write;

/// A unit force (1 N along `direction`) shared equally by the `patch` nodes.
#[derive(Debug, Clone)]
pub struct ForceCase {
    pub patch: Vec<usize>,
    pub direction: [f64; 3],
}

/// Everything the deck is made of.
pub struct DeckInput<'a> {
    pub mesh: &'a Mesh,
    pub used: &'a [bool],
    pub masses: &'a [f64],
    pub body: &'a RigidBody,
    pub cage: &'a CageGeometry,
    /// support nodes and the in-plane degree of freedom of the second one
    pub supports: ([usize; 3], usize),
    pub evaluation: &'a [usize],
    /// a further node whose stresses are written (a check far from the windows)
    pub reference: usize,
    pub cases: &'a [ForceCase],
}

/// Steps after the force cases: angular accelerations about x, y, z, then the spin².
pub const ANGULAR_STEPS: usize = 3;

/// The complete deck.
pub fn write_deck(input: &DeckInput) -> String {
    let mut s = String::from("*HEADING\nrolldyn cage unit stresses\n");
    write_model(&mut s, input);
    for case in input.cases {
        let lines = case.patch.iter().flat_map(|&n| {
            let share = 1.0 / case.patch.len() as f64;
            (0..3).map(move |k| (n, k, share * case.direction[k]))
        });
        // translational inertia relief: body force −ρ a, a = F / m
        let grav = format!(
            "EALL,GRAV,{:.10e},{:.10e},{:.10e},{:.10e}",
            1.0 / input.body.mass,
            -case.direction[0],
            -case.direction[1],
            -case.direction[2]
        );
        write_step(&mut s, input, lines, &grav);
    }
    for k in 0..ANGULAR_STEPS {
        let lines = (0..input.mesh.coords.len())
            .filter(|&n| input.used[n])
            .flat_map(|n| {
                let load =
                    input
                        .body
                        .angular_inertia_load(k, input.masses[n], input.mesh.coords[n]);
                (0..3).map(move |i| (n, i, load[i]))
            });
        write_step(&mut s, input, lines, "");
    }
    write_step(
        &mut s,
        input,
        std::iter::empty(),
        "EALL,CENTRIF,1.,0.,0.,0.,0.,0.,1.",
    );
    s
}

/// Nodes, elements, node sets, material and support.
fn write_model(s: &mut String, input: &DeckInput) {
    let mesh = input.mesh;
    s.push_str("*NODE\n");
    for n in (0..mesh.coords.len()).filter(|&n| input.used[n]) {
        let [x, y, z] = mesh.coords[n];
        let _ = writeln!(s, "{},{x:.10e},{y:.10e},{z:.10e}", mesh.ids[n]);
    }
    s.push_str("*ELEMENT,TYPE=C3D10,ELSET=EALL\n");
    for (e, tet) in mesh.tets.iter().enumerate() {
        let ids: Vec<String> = tet.iter().map(|&n| mesh.ids[n].to_string()).collect();
        let _ = writeln!(s, "{},{}", e + 1, ids[..8].join(","));
        let _ = writeln!(s, "{}", ids[8..].join(","));
    }
    write_set(s, "SUPPORT", &input.supports.0, mesh);
    let mut evaluation = input.evaluation.to_vec();
    evaluation.push(input.reference);
    write_set(s, "EVAL", &evaluation, mesh);
    let c = input.cage;
    let _ = write!(
        s,
        "*MATERIAL,NAME=CAGE\n*ELASTIC\n{:.10e},{}\n*DENSITY\n{:.10e}\n\
         *SOLID SECTION,ELSET=EALL,MATERIAL=CAGE\n",
        c.youngs_modulus, c.poisson_ratio, c.density
    );
    let [a, b, third] = input.supports.0.map(|n| mesh.ids[n]);
    let _ = write!(
        s,
        "*BOUNDARY\n{a},1,3\n{b},3,3\n{b},{dof},{dof}\n{third},3,3\n",
        dof = input.supports.1
    );
}

fn write_set(s: &mut String, name: &str, nodes: &[usize], mesh: &Mesh) {
    let _ = writeln!(s, "*NSET,NSET={name}");
    let mut unique: Vec<usize> = nodes.iter().map(|&n| mesh.ids[n]).collect();
    unique.sort_unstable();
    unique.dedup();
    for chunk in unique.chunks(8) {
        let ids: Vec<String> = chunk.iter().map(usize::to_string).collect();
        let _ = writeln!(s, "{}", ids.join(","));
    }
}

/// One static step with concentrated loads `(node, component 0..3, value)` and a `*DLOAD`
/// line (empty: none), replacing the loads of the previous step.
fn write_step(
    s: &mut String,
    input: &DeckInput,
    cloads: impl Iterator<Item = (usize, usize, f64)>,
    dload: &str,
) {
    s.push_str("*STEP\n*STATIC\n*CLOAD,OP=NEW\n");
    for (n, k, value) in cloads.filter(|l| l.2 != 0.0) {
        let _ = writeln!(s, "{},{},{value:.10e}", input.mesh.ids[n], k + 1);
    }
    s.push_str("*DLOAD,OP=NEW\n");
    if !dload.is_empty() {
        let _ = writeln!(s, "{dload}");
    }
    s.push_str("*NODE PRINT,NSET=SUPPORT\nRF\n*EL FILE,NSET=EVAL\nS\n*END STEP\n");
}
