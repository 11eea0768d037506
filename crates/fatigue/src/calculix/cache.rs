//! The cache of solved unit stresses: one JSON file per model fingerprint.

use super::{CalculixError, CalculixSettings, CalculixSolution};
use crate::cage::CageGeometry;
use std::path::{Path, PathBuf};

/// Version of the model and of the cached format: bump it when either changes.
const FORMAT_VERSION: u32 = 1;

/// FNV-1a fingerprint of everything the unit stresses depend on: the cage, the bar stations,
/// the mesh and patch settings and [`FORMAT_VERSION`].
pub fn fingerprint(cage: &CageGeometry, bar_station_z: f64, settings: &CalculixSettings) -> u64 {
    let key = serde_json::json!({
        "version": FORMAT_VERSION,
        "cage": cage,
        "bar_station_z": bar_station_z,
        "mesh_size": settings.mesh_size,
        "fillet_mesh_size": settings.fillet_mesh_size,
        "refinement_growth": settings.refinement_growth,
        "patch_radius": settings.patch_radius,
        "patch_min_nodes": settings.patch_min_nodes,
    });
    rolldyn_numerics::hash::fnv1a(key.to_string().as_bytes())
}

/// File of a fingerprint in the cache directory.
pub fn path(dir: &Path, fingerprint: u64) -> PathBuf {
    dir.join(format!("calculix-{fingerprint:016x}.json"))
}

/// The cached solution, if a readable one exists.
pub fn load(dir: &Path, fingerprint: u64) -> Option<CalculixSolution> {
    let text = std::fs::read_to_string(path(dir, fingerprint)).ok()?;
    serde_json::from_str(&text).ok()
}

/// Stores `solution` under `fingerprint`.
pub fn store(
    dir: &Path,
    fingerprint: u64,
    solution: &CalculixSolution,
) -> Result<(), CalculixError> {
    let file = path(dir, fingerprint);
    std::fs::create_dir_all(dir).map_err(|e| CalculixError::Io(dir.to_path_buf(), e))?;
    let text = serde_json::to_string(solution).expect("plain data serializes");
    std::fs::write(&file, text).map_err(|e| CalculixError::Io(file, e))
}
