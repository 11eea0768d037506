//! The solid-model cage stresses (theory §10.4): the cage meshed by gmsh with quadratic
//! tetrahedra and solved by CalculiX ccx for every unit case of [`UnitStresses`], with inertia
//! relief, read back at the fillet points and cached per model fingerprint.

mod cache;
mod deck;
mod geometry;
mod loads;
mod mesh;
mod points;
mod results;
mod run;

use crate::cage::{CageGeometry, STATIONS};
use crate::unit_stresses::{Stress, UnitStresses};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

pub use points::fillet_arc_midpoint;

/// Knobs of the solid model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CalculixSettings {
    /// largest element size away from the fillets, m; default 8 mm: the fillet refinement
    /// fills most of the rims and bars of the reference cage (2002834), and the 34 ccx solves
    /// (one factorization each) stay within the 2-minute budget (35 700 nodes, 101 s on 2
    /// cores)
    pub mesh_size: f64,
    /// element size at the fillet corners, m; default 0.6 mm: about three quadratic elements
    /// along the quarter arc of a 1 mm fillet
    pub fillet_mesh_size: f64,
    /// distance over which the size grows from the fillet size to `mesh_size`, m; default
    /// 2.5 mm (a growth ratio of about 1.5 per element next to the fillet)
    pub refinement_growth: f64,
    /// radius of the surface patch that shares a station's unit force, m; default 1 mm: small
    /// against the bar (avoids the point-load singularity, keeps the load local)
    pub patch_radius: f64,
    /// fewest nodes of a patch (the nearest ones when the radius holds fewer); default 3
    pub patch_min_nodes: usize,
    /// gmsh executable; default "gmsh"
    pub gmsh: String,
    /// CalculiX executable; default "ccx"
    pub ccx: String,
    /// threads of ccx (OMP_NUM_THREADS); default 2, the cores of the reference machine
    pub threads: usize,
    /// keep the scratch directory (geometry script, mesh, deck, results) for inspection;
    /// default false
    pub keep_work_dir: bool,
}

impl Default for CalculixSettings {
    fn default() -> Self {
        CalculixSettings {
            mesh_size: 8e-3,
            fillet_mesh_size: 0.6e-3,
            refinement_growth: 2.5e-3,
            patch_radius: 1e-3,
            patch_min_nodes: 3,
            gmsh: "gmsh".into(),
            ccx: "ccx".into(),
            threads: 2,
            keep_work_dir: false,
        }
    }
}

/// Why the solid model failed.
#[derive(Debug, thiserror::Error)]
pub enum CalculixError {
    #[error("the cage cannot be modelled: {0}")]
    Geometry(String),
    #[error("executable '{0}' not found (install it: apt-get install gmsh calculix-ccx)")]
    Missing(String),
    #[error("{0} failed:\n{1}")]
    Failed(String, String),
    #[error("unreadable results: {0}")]
    Results(String),
    #[error("{0}: {1}")]
    Io(PathBuf, std::io::Error),
}

/// What the solve measured besides the stresses.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CalculixReport {
    pub nodes: usize,
    pub elements: usize,
    /// largest support reaction of a unit force case, N per N applied (≈ 0 with inertia relief)
    pub largest_reaction_ratio: f64,
    /// largest support reaction of the unit spin² case over the scale `m ω² r_mean` of its
    /// (self-cancelling) centrifugal forces
    pub centrifugal_reaction_ratio: f64,
    /// largest distance of an evaluation node from its fillet arc mid-point, m
    pub largest_evaluation_offset: f64,
    /// hoop stress of the unit spin² case at the outside surface of rim 0 over the centre
    /// of pocket 0, far from the window corners, Pa/(rad/s)²
    pub rim_hoop_per_spin_squared: f64,
    pub mesh_seconds: f64,
    pub solve_seconds: f64,
}

/// Unit stresses and the report of their solve.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CalculixSolution {
    pub unit_stresses: UnitStresses,
    pub report: CalculixReport,
}

/// The unit stress table of `cage` by the solid model (model "calculix").
pub fn unit_stresses(
    cage: &CageGeometry,
    bar_station_z: f64,
    settings: &CalculixSettings,
    cache_dir: Option<&Path>,
) -> Result<UnitStresses, CalculixError> {
    solve(cage, bar_station_z, settings, cache_dir).map(|s| s.unit_stresses)
}

/// [`unit_stresses`] with its report; reads `cache_dir` first and stores what it solved there.
pub fn solve(
    cage: &CageGeometry,
    bar_station_z: f64,
    settings: &CalculixSettings,
    cache_dir: Option<&Path>,
) -> Result<CalculixSolution, CalculixError> {
    let problems = cage.problems();
    if !problems.is_empty() {
        return Err(CalculixError::Geometry(problems.join("; ")));
    }
    let key = cache::fingerprint(cage, bar_station_z, settings);
    if let Some(cached) = cache_dir.and_then(|dir| cache::load(dir, key)) {
        return Ok(cached);
    }
    let work = run::WorkDir::create(key, settings)?;
    let start = Instant::now();
    let script = geometry::geo_script(cage, settings);
    write(&work.path.join("cage.geo"), &script)?;
    run::run_gmsh(&work.path, settings)?;
    let sector = mesh::Mesh::parse_inp(&read(&work.path.join("cage.inp"))?)?;
    let mesh = mesh::Mesh::cyclic(&sector, cage.pockets)?;
    let mesh_seconds = start.elapsed().as_secs_f64();
    let model = Model::build(mesh, cage, bar_station_z, settings)?;
    write(
        &work.path.join("deck.inp"),
        &deck::write_deck(&model.deck_input(cage)),
    )?;
    run::run_ccx(&work.path, settings)?;
    let solution = model.read_results(
        &read(&work.path.join("deck.frd"))?,
        &read(&work.path.join("deck.dat"))?,
        cage,
        bar_station_z,
        (mesh_seconds, start.elapsed().as_secs_f64() - mesh_seconds),
    )?;
    if let Some(dir) = cache_dir {
        cache::store(dir, key, &solution)?;
    }
    Ok(solution)
}

fn write(path: &Path, text: &str) -> Result<(), CalculixError> {
    std::fs::write(path, text).map_err(|e| CalculixError::Io(path.to_path_buf(), e))
}

fn read(path: &Path) -> Result<String, CalculixError> {
    std::fs::read_to_string(path).map_err(|e| CalculixError::Io(path.to_path_buf(), e))
}

/// The meshed cage with its load cases, supports and evaluation nodes.
struct Model {
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
    fn build(
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
        let rim_z = -0.5 * (cage.pocket_axial + cage.rim_axial());
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

    fn deck_input<'a>(&'a self, cage: &'a CageGeometry) -> deck::DeckInput<'a> {
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
    fn read_results(
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A small 6-pocket cage.
    pub(crate) fn small_cage() -> CageGeometry {
        CageGeometry {
            pockets: 6,
            inner_radius: 20e-3,
            outer_radius: 25e-3,
            width: 12e-3,
            pocket_axial: 7e-3,
            pocket_circumferential: 7e-3,
            bar_contact_radius: 24.5e-3,
            fillet_radius: 0.8e-3,
            youngs_modulus: 211e9,
            poisson_ratio: 0.3,
            density: 7850.0,
        }
    }

    #[test]
    fn the_fingerprint_follows_the_inputs_that_change_the_result() {
        let cage = small_cage();
        let settings = CalculixSettings::default();
        let key = cache::fingerprint(&cage, 2e-3, &settings);
        let other_threads = CalculixSettings {
            threads: 1,
            ..settings.clone()
        };
        assert_eq!(key, cache::fingerprint(&cage, 2e-3, &other_threads));
        assert_ne!(key, cache::fingerprint(&cage, 2.1e-3, &settings));
        let finer = CalculixSettings {
            mesh_size: 4e-3,
            ..settings
        };
        assert_ne!(key, cache::fingerprint(&cage, 2e-3, &finer));
    }

    #[test]
    fn an_impossible_cage_is_refused_before_meshing() {
        let cage = CageGeometry {
            fillet_radius: 5e-3,
            ..small_cage()
        };
        let err = unit_stresses(&cage, 2e-3, &CalculixSettings::default(), None).unwrap_err();
        assert!(err.to_string().contains("fillet radius"), "{err}");
    }
}
