//! The meshed cage with its unit load cases, supports and evaluation nodes, and the
//! superposition of ccx's step results into the unit stresses (theory §10.4).

use super::{
    CalculixError, CalculixReport, CalculixSettings, CalculixSolution, deck, loads, mesh, points,
    results,
};
use crate::cage::{CageGeometry, STATIONS};
use crate::unit_stresses::{Stress, UnitStresses};
use std::collections::HashMap;

/// The meshed cage with its load cases, supports and evaluation nodes.
pub struct Model {
    mesh: mesh::Mesh,
    used: Vec<bool>,
    masses: Vec<f64>,
    body: loads::RigidBody,
    supports: ([usize; 3], usize),
    /// node of each fillet point ([`crate::cage::FilletPoint::all`] order)
    evaluation: Vec<usize>,
    /// largest distance of an evaluation node from its fillet arc mid-point, m
    evaluation_offset: f64,
    /// node at the outside surface of rim 0 over the centre of pocket 0
    rim_reference: usize,
    cases: Vec<deck::ForceCase>,
    /// application point of each case (the centroid of its patch), m
    points: Vec<[f64; 3]>,
}

impl Model {
    pub fn build(
        mesh: mesh::Mesh,
        cage: &CageGeometry,
        bar_station_z: f64,
        settings: &CalculixSettings,
    ) -> Result<Model, CalculixError> {
        let used = mesh.used_nodes();
        let boundary = mesh.boundary_nodes();
        let masses = mesh.nodal_masses(cage.density);
        let body = loads::RigidBody::of(&mesh, &masses);
        let mut cases = Vec::new();
        let mut points = Vec::new();
        for station in STATIONS {
            let patch = loads::patch(&mesh, &boundary, station, cage, bar_station_z, settings)?;
            for direction in loads::station_frame(station, cage) {
                cases.push(deck::ForceCase {
                    patch: patch.clone(),
                    direction,
                });
                points.push(centroid(&mesh, &patch));
            }
        }
        let evaluation = points::evaluation_nodes(&mesh, &used, cage);
        let rim_z = -0.5 * (cage.pocket.axial + cage.rim_axial());
        let rim_reference = mesh
            .nearest(
                [cage.outer_radius, 0.0, rim_z],
                (0..used.len()).filter(|&n| used[n]),
            )
            .expect("a mesh with elements has used nodes");
        Ok(Model {
            rim_reference,
            supports: loads::supports(&mesh, &used, cage),
            evaluation_offset: evaluation.iter().map(|e| e.1).fold(0.0, f64::max),
            evaluation: evaluation.into_iter().map(|e| e.0).collect(),
            mesh,
            used,
            masses,
            body,
            cases,
            points,
        })
    }

    pub fn deck_input<'a>(&'a self, cage: &'a CageGeometry) -> deck::DeckInput<'a> {
        deck::DeckInput {
            mesh: &self.mesh,
            used: &self.used,
            masses: &self.masses,
            body: &self.body,
            cage,
            supports: self.supports,
            evaluation: &self.evaluation,
            reference: self.rim_reference,
            cases: &self.cases,
        }
    }
}

impl Model {
    /// Superposes the steps into the unit cases (each force case plus its angular inertia
    /// relief `Σ α_k` × the unit angular-acceleration steps) and converts the fillet-node
    /// stresses to cylindrical components.
    pub fn read_results(
        &self,
        frd: &str,
        dat: &str,
        cage: &CageGeometry,
        bar_station_z: f64,
        (mesh_seconds, solve_seconds): (f64, f64),
    ) -> Result<CalculixSolution, CalculixError> {
        let steps = self.cases.len() + deck::ANGULAR_STEPS + 1;
        let stresses = results::parse_frd_stresses(frd)?;
        let reactions = results::parse_dat_forces(dat);
        if stresses.len() != steps || reactions.len() != steps {
            return Err(CalculixError::Results(format!(
                "{} stress and {} reaction blocks for {steps} steps",
                stresses.len(),
                reactions.len()
            )));
        }
        let at = |step: usize, nodes: &[usize]| -> Result<Vec<[f64; 6]>, CalculixError> {
            nodes
                .iter()
                .map(|&n| {
                    stresses[step]
                        .get(&self.mesh.ids[n])
                        .copied()
                        .ok_or_else(|| {
                            CalculixError::Results(format!(
                                "no stress at node {}",
                                self.mesh.ids[n]
                            ))
                        })
                })
                .collect()
        };
        let step_stress = |step: usize| at(step, &self.evaluation);
        let angular: Vec<Vec<[f64; 6]>> = (0..deck::ANGULAR_STEPS)
            .map(|k| step_stress(self.cases.len() + k))
            .collect::<Result<_, _>>()?;
        let mut per_unit_force = Vec::with_capacity(self.cases.len() * self.evaluation.len());
        let mut largest_reaction_ratio: f64 = 0.0;
        for (i, case) in self.cases.iter().enumerate() {
            let alpha = self
                .body
                .angular_acceleration(case.direction, self.points[i]);
            let mut stress = step_stress(i)?;
            for (k, basis) in angular.iter().enumerate() {
                stress
                    .iter_mut()
                    .zip(basis)
                    .for_each(|(s, b)| add_scaled(s, b, alpha[k]));
            }
            per_unit_force.extend(self.cylindrical(&stress));
            let a = case.direction.map(|f| f / self.body.mass);
            // the nodal inertial load −m (a + α × (x − c))
            let inertia = |m: f64, x: [f64; 3]| {
                let mut f = a.map(|v| -m * v);
                for (k, alpha_k) in alpha.iter().enumerate() {
                    add_scaled(&mut f, &self.body.angular_inertia_load(k, m, x), *alpha_k);
                }
                f
            };
            let reaction = self.largest_reaction(&reactions, i, alpha, inertia);
            largest_reaction_ratio = largest_reaction_ratio.max(reaction);
        }
        let spin = steps - 1;
        let centrifugal_scale = self.body.mass * cage.mean_radius();
        let report = CalculixReport {
            nodes: self.used.iter().filter(|&&u| u).count(),
            elements: self.mesh.tets.len(),
            largest_reaction_ratio,
            centrifugal_reaction_ratio: self.largest_reaction(
                &reactions,
                spin,
                [0.0; 3],
                |m, x| [m * x[0], m * x[1], 0.0],
            ) / centrifugal_scale,
            largest_evaluation_offset: self.evaluation_offset,
            rim_hoop_per_spin_squared: {
                let node = self.rim_reference;
                points::to_cylindrical(at(spin, &[node])?[0], self.mesh.coords[node])[1]
            },
            mesh_seconds,
            solve_seconds,
        };
        let unit_stresses = UnitStresses {
            model: "calculix".into(),
            cage: cage.clone(),
            bar_station_z,
            per_unit_force,
            per_unit_spin_squared: self.cylindrical(&step_stress(spin)?),
        };
        Ok(CalculixSolution {
            unit_stresses,
            report,
        })
    }

    /// Largest support reaction (vector norm) of step `step` plus the `alpha`-weighted
    /// angular-acceleration steps, N. ccx prints the nodal force balance `K u`, which holds the
    /// support node's own share of the body load, `load(m_n, x_n)`: it is taken off.
    fn largest_reaction(
        &self,
        reactions: &[Vec<(usize, [f64; 3])>],
        step: usize,
        alpha: [f64; 3],
        load: impl Fn(f64, [f64; 3]) -> [f64; 3],
    ) -> f64 {
        let index: HashMap<usize, usize> = self
            .supports
            .0
            .iter()
            .map(|&n| (self.mesh.ids[n], n))
            .collect();
        let mut largest: f64 = 0.0;
        for (row, (id, force)) in reactions[step].iter().enumerate() {
            let mut total = *force;
            for (k, a) in alpha.iter().enumerate() {
                add_scaled(&mut total, &reactions[self.cases.len() + k][row].1, *a);
            }
            if let Some(&n) = index.get(id) {
                add_scaled(&mut total, &load(self.masses[n], self.mesh.coords[n]), -1.0);
            }
            largest = largest.max(total.iter().map(|v| v * v).sum::<f64>().sqrt());
        }
        largest
    }

    fn cylindrical(&self, cartesian: &[[f64; 6]]) -> Vec<Stress> {
        cartesian
            .iter()
            .zip(&self.evaluation)
            .map(|(s, &n)| points::to_cylindrical(*s, self.mesh.coords[n]))
            .collect()
    }
}

/// Mean position of `nodes`, m.
fn centroid(mesh: &mesh::Mesh, nodes: &[usize]) -> [f64; 3] {
    let mut c = [0.0; 3];
    for &n in nodes {
        (0..3).for_each(|k| c[k] += mesh.coords[n][k] / nodes.len() as f64);
    }
    c
}

fn add_scaled<const N: usize>(target: &mut [f64; N], source: &[f64; N], factor: f64) {
    target
        .iter_mut()
        .zip(source)
        .for_each(|(t, s)| *t += factor * s);
}
