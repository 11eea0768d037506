//! The tetrahedral mesh gmsh writes (Abaqus `.inp`, C3D10): nodes, elements, the boundary
//! nodes and the lumped nodal masses of the inertia relief (theory §10.4).

use super::CalculixError;
use std::collections::HashMap;

/// Nodes and quadratic tetrahedra of the cage; `ids` are the node numbers of the deck.
#[derive(Debug, Clone, Default)]
pub struct Mesh {
    pub ids: Vec<usize>,
    pub coords: Vec<[f64; 3]>,
    /// C3D10 connectivity as indices into `coords` (Abaqus node order)
    pub tets: Vec<[usize; 10]>,
}

/// The four faces of a C3D10 by their corner indices (Abaqus order: corners 0–3, mid-side
/// nodes 4: 0–1, 5: 1–2, 6: 2–0, 7: 0–3, 8: 1–3, 9: 2–3) and their mid-side indices.
const FACES: [([usize; 3], [usize; 3]); 4] = [
    ([0, 1, 2], [4, 5, 6]),
    ([0, 1, 3], [4, 8, 7]),
    ([1, 2, 3], [5, 9, 8]),
    ([0, 2, 3], [6, 9, 7]),
];

impl Mesh {
    /// Reads the `*NODE` and the `C3D10` `*ELEMENT` blocks of a gmsh `.inp` file.
    pub fn parse_inp(text: &str) -> Result<Mesh, CalculixError> {
        let bad = |what: &str| CalculixError::Results(format!("mesh file: {what}"));
        let mut mesh = Mesh::default();
        let mut index = HashMap::new();
        let mut raw_tets: Vec<Vec<usize>> = Vec::new();
        let mut block = Block::Other;
        for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
            if line.starts_with('*') {
                block = Block::of(line);
                continue;
            }
            let fields: Vec<&str> = line
                .split(',')
                .map(str::trim)
                .filter(|f| !f.is_empty())
                .collect();
            match block {
                Block::Nodes => {
                    let v: Vec<f64> = fields.iter().filter_map(|f| f.parse().ok()).collect();
                    if v.len() != 4 {
                        return Err(bad(&format!("bad node line '{line}'")));
                    }
                    index.insert(v[0] as usize, mesh.ids.len());
                    mesh.ids.push(v[0] as usize);
                    mesh.coords.push([v[1], v[2], v[3]]);
                }
                Block::Tets => {
                    let v: Vec<usize> = fields.iter().filter_map(|f| f.parse().ok()).collect();
                    match raw_tets.last_mut() {
                        Some(open) if open.len() < 11 => open.extend(v),
                        _ => raw_tets.push(v),
                    }
                }
                Block::Other => {}
            }
        }
        for raw in raw_tets {
            if raw.len() != 11 {
                return Err(bad(&format!(
                    "element {} has {} nodes",
                    raw[0],
                    raw.len() - 1
                )));
            }
            let mut tet = [0; 10];
            for (slot, id) in tet.iter_mut().zip(&raw[1..]) {
                *slot = *index
                    .get(id)
                    .ok_or_else(|| bad(&format!("unknown node {id}")))?;
            }
            mesh.tets.push(tet);
        }
        if mesh.tets.is_empty() {
            return Err(bad("no C3D10 elements"));
        }
        Ok(mesh)
    }

    /// The whole cage from the mesh of one pitch (the sector between the centre planes of the
    /// bars at `θ = ∓π/Z`): `pockets` copies rotated by whole pitches, each copy's nodes on
    /// the `+π/Z` plane merged with the next copy's nodes on its `−π/Z` plane.
    pub fn cyclic(sector: &Mesh, pockets: usize) -> Result<Mesh, CalculixError> {
        let used = sector.used_nodes();
        let half = std::f64::consts::PI / pockets as f64;
        let (s, c) = half.sin_cos();
        let on_plane = |sign: f64, n: usize| {
            let [x, y, _] = sector.coords[n];
            used[n] && (y * c - sign * x * s).abs() < 1e-9
        };
        let minus: Vec<usize> = (0..used.len()).filter(|&n| on_plane(-1.0, n)).collect();
        // the node of the −π/Z plane that the rotation by a pitch brings onto each node
        let mut partner = vec![None; used.len()];
        for n in (0..used.len()).filter(|&n| on_plane(1.0, n)) {
            let (r, z) = radius_and_z(sector.coords[n]);
            let m = minus.iter().copied().min_by(|&a, &b| {
                let gap = |k: usize| {
                    let (rk, zk) = radius_and_z(sector.coords[k]);
                    (rk - r).hypot(zk - z)
                };
                gap(a).total_cmp(&gap(b))
            });
            let m = m.filter(|&m| {
                let (rm, zm) = radius_and_z(sector.coords[m]);
                (rm - r).hypot(zm - z) < 1e-7
            });
            partner[n] = Some(m.ok_or_else(|| {
                CalculixError::Results("the cut faces of the sector mesh do not match".into())
            })?);
        }
        let own: Vec<usize> = (0..used.len())
            .filter(|&n| used[n] && partner[n].is_none())
            .collect();
        let mut slot = vec![usize::MAX; used.len()];
        own.iter().enumerate().for_each(|(k, &n)| slot[n] = k);
        let global = |copy: usize, n: usize| match partner[n] {
            Some(m) => ((copy + 1) % pockets) * own.len() + slot[m],
            None => copy * own.len() + slot[n],
        };
        let mut mesh = Mesh::default();
        for copy in 0..pockets {
            let (sn, cs) = (2.0 * half * copy as f64).sin_cos();
            for &n in &own {
                let [x, y, z] = sector.coords[n];
                mesh.coords.push([cs * x - sn * y, sn * x + cs * y, z]);
            }
            let tets = sector.tets.iter().map(|tet| tet.map(|n| global(copy, n)));
            mesh.tets.extend(tets);
        }
        mesh.ids = (1..=mesh.coords.len()).collect();
        Ok(mesh)
    }

    /// Whether each node lies on the boundary: it belongs to a face used by one element only.
    pub fn boundary_nodes(&self) -> Vec<bool> {
        let mut count: HashMap<[usize; 3], (usize, [usize; 6])> = HashMap::new();
        for tet in &self.tets {
            for (corners, mids) in FACES {
                let nodes = [
                    tet[corners[0]],
                    tet[corners[1]],
                    tet[corners[2]],
                    tet[mids[0]],
                    tet[mids[1]],
                    tet[mids[2]],
                ];
                let mut key = [nodes[0], nodes[1], nodes[2]];
                key.sort_unstable();
                count.entry(key).or_insert((0, nodes)).0 += 1;
            }
        }
        let mut on = vec![false; self.coords.len()];
        for (uses, nodes) in count.into_values() {
            if uses == 1 {
                nodes.iter().for_each(|&n| on[n] = true);
            }
        }
        on
    }

    /// Nodes that belong to an element.
    pub fn used_nodes(&self) -> Vec<bool> {
        let mut used = vec![false; self.coords.len()];
        self.tets.iter().flatten().for_each(|&n| used[n] = true);
        used
    }

    /// Nodal masses `m_n = ρ ∫ N_n dV` of the straight-sided quadratic tetrahedra (corner
    /// `−V/20`, mid-side `V/5`): they reproduce the mass, centre of mass and inertia tensor
    /// of the mesh exactly (theory §10.4), kg.
    pub fn nodal_masses(&self, density: f64) -> Vec<f64> {
        let mut m = vec![0.0; self.coords.len()];
        for tet in &self.tets {
            let mass = density * self.volume(tet);
            for (k, &n) in tet.iter().enumerate() {
                m[n] += if k < 4 { -mass / 20.0 } else { mass / 5.0 };
            }
        }
        m
    }

    /// Volume of a tetrahedron from its corners, m³.
    fn volume(&self, tet: &[usize; 10]) -> f64 {
        let [a, b, c, d] = [0, 1, 2, 3].map(|k| self.coords[tet[k]]);
        let e = |p: [f64; 3]| [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
        let (u, v, w) = (e(b), e(c), e(d));
        (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))
            .abs()
            / 6.0
    }

    /// Index of the node of `candidates` nearest to `point`.
    pub fn nearest(
        &self,
        point: [f64; 3],
        candidates: impl Iterator<Item = usize>,
    ) -> Option<usize> {
        candidates.min_by(|&a, &b| {
            distance(self.coords[a], point).total_cmp(&distance(self.coords[b], point))
        })
    }
}

fn radius_and_z(x: [f64; 3]) -> (f64, f64) {
    (x[0].hypot(x[1]), x[2])
}

/// Euclidean distance, m.
pub fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[derive(Clone, Copy)]
enum Block {
    Nodes,
    Tets,
    Other,
}

impl Block {
    fn of(keyword_line: &str) -> Block {
        let upper = keyword_line.to_ascii_uppercase();
        if upper.starts_with("*NODE") && !upper.starts_with("*NODE ") {
            Block::Nodes
        } else if upper.starts_with("*ELEMENT") && upper.contains("C3D10") {
            Block::Tets
        } else {
            Block::Other
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One unit tetrahedron with straight mid-side nodes, element line wrapped like Abaqus.
    pub(crate) const ONE_TET: &str = "*Heading\n x\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n\
        4, 0, 0, 1\n5, 0.5, 0, 0\n6, 0.5, 0.5, 0\n7, 0, 0.5, 0\n8, 0, 0, 0.5\n9, 0.5, 0, 0.5\n\
        10, 0, 0.5, 0.5\n*ELEMENT, type=T3D2, ELSET=Line1\n1, 1, 2\n\
        *ELEMENT, type=C3D10, ELSET=Volume1\n1, 1, 2, 3, 4, 5, 6, 7, 8,\n9, 10\n*ELSET,ELSET=cage\n1\n";

    #[test]
    fn reads_nodes_and_wrapped_quadratic_tetrahedra() {
        let mesh = Mesh::parse_inp(ONE_TET).unwrap();
        assert_eq!(mesh.coords.len(), 10);
        assert_eq!(mesh.tets, vec![[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]]);
        assert!(mesh.boundary_nodes().iter().all(|&b| b));
        let m = mesh.nodal_masses(6.0);
        assert!((m.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!((m[0] + 0.05).abs() < 1e-12 && (m[4] - 0.2).abs() < 1e-12);
    }

    #[test]
    fn sector_copies_share_the_nodes_of_their_cut_planes() {
        // four pitches: the cut planes are y = ∓x; node 0 lies on +π/4, node 1 on −π/4
        let corners = [
            [1.0, 1.0, 0.0],
            [1.0, -1.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.5, 0.0, 1.0],
        ];
        let edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)];
        let mut coords = corners.to_vec();
        for (a, b) in edges {
            let (p, q) = (corners[a], corners[b]);
            coords.push([
                0.5 * (p[0] + q[0]),
                0.5 * (p[1] + q[1]),
                0.5 * (p[2] + q[2]),
            ]);
        }
        let sector = Mesh {
            ids: (1..=10).collect(),
            coords,
            tets: vec![[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]],
        };
        let cage = Mesh::cyclic(&sector, 4).unwrap();
        assert_eq!((cage.coords.len(), cage.tets.len()), (36, 4));
        for (copy, tet) in cage.tets.iter().enumerate() {
            let next = cage.tets[(copy + 1) % 4];
            assert_eq!(tet[0], next[1]);
            let volume = cage.volume(tet);
            assert!((volume - sector.volume(&sector.tets[0])).abs() < 1e-12);
        }
    }

    #[test]
    fn a_file_without_tetrahedra_is_an_error() {
        assert!(Mesh::parse_inp("*NODE\n1, 0, 0, 0\n").is_err());
    }
}
