//! The solid-model cage stresses (theory §10.4): the cage meshed by gmsh with quadratic
//! tetrahedra and solved by CalculiX ccx for every unit case of [`UnitStresses`], with inertia
//! relief, read back at the fillet points and cached per model fingerprint.

mod cache;
mod deck;
mod geometry;
mod loads;
mod mesh;
mod model;
mod points;
mod results;
mod run;

use crate::cage::CageGeometry;
use crate::unit_stresses::UnitStresses;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::Instant;

pub use geometry::{geo_script, window_bands};
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
    let model = model::Model::build(mesh, cage, bar_station_z, settings)?;
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
            pocket: rolldyn_geometry::CagePocket {
                faces: rolldyn_geometry::PocketFaces::Flat,
                face_clearance: 1e-3,
                outer_lip: None,
                inner_lip: None,
                axial: 7e-3,
                fillet_radius: 0.8e-3,
            },
            roller_radius: 3e-3,
            pitch_radius: 22.5e-3,
            bar_contact: [22.5e-3, 3.5e-3],
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
        let mut cage = small_cage();
        cage.pocket.fillet_radius = 5e-3;
        let err = unit_stresses(&cage, 2e-3, &CalculixSettings::default(), None).unwrap_err();
        assert!(err.to_string().contains("fillet radius"), "{err}");
    }
}
