//! The worn model file: the original model with the worn geometry written into it, so that
//! `rolldyn simulate` and `check` run the worn bearing (seed 000 §3.1.1.7: the dynamics of worn
//! roller ends). The raceway wear maps go beside it as CSV files (docs/model-format.md,
//! `raceway_wear`).

use crate::WearError;
use rolldyn_geometry::{CylindricalRollerBearing, ProfileShape, Ring};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// File names of the worn model and its raceway maps.
pub const WORN_MODEL: &str = "worn.toml";
pub const INNER_MAP: &str = "worn-inner-raceway.csv";
pub const OUTER_MAP: &str = "worn-outer-raceway.csv";

fn mm(x: f64) -> Value {
    Value::String(format!("{:.9} mm", x * 1e3))
}

fn um(x: f64) -> Value {
    Value::String(format!("{:.6} um", x * 1e6))
}

fn section<'t>(doc: &'t mut Table, key: &str) -> Result<&'t mut Table, WearError> {
    doc.get_mut(key)
        .and_then(Value::as_table_mut)
        .ok_or_else(|| {
            WearError::Input(format!(
                "the model has no [{key}] to write the worn geometry into"
            ))
        })
}

/// The worn roller profile as a `polyline` section, keeping the original chamfer.
fn roller_profile(
    worn: &CylindricalRollerBearing,
    original: Option<&Value>,
) -> Result<Value, WearError> {
    let ProfileShape::Polyline { points } = &worn.roller.profile.shape else {
        return Err(WearError::Input(
            "the worn roller profile is not a polyline".into(),
        ));
    };
    let mut t = Table::new();
    t.insert("kind".into(), Value::String("polyline".into()));
    t.insert(
        "x".into(),
        Value::Array(points.iter().map(|p| mm(p.0)).collect()),
    );
    t.insert(
        "drop".into(),
        Value::Array(points.iter().map(|p| um(p.1)).collect()),
    );
    if let Some(chamfer) = original.and_then(|p| p.get("chamfer")) {
        t.insert("chamfer".into(), chamfer.clone());
    }
    Ok(Value::Table(t))
}

fn write_map(ring: &Ring, dir: &Path, name: &str) -> Result<Option<PathBuf>, WearError> {
    let Some(map) = &ring.raceway_wear else {
        return Ok(None);
    };
    let path = dir.join(name);
    let io =
        |e: std::io::Error| WearError::Numerical(format!("cannot write {}: {e}", path.display()));
    let file = std::fs::File::create(&path).map_err(io)?;
    rolldyn_model::write_raceway_wear_csv(map, std::io::BufWriter::new(file)).map_err(io)?;
    Ok(Some(path))
}

/// Writes `worn.toml` and its map files into `dir` from the original model text and the worn
/// bearing; `note` becomes the file's first comment line. Returns the files written.
pub fn write_worn_model(
    original_text: &str,
    worn: &CylindricalRollerBearing,
    ribs_on_inner: bool,
    dir: &Path,
    note: &str,
) -> Result<Vec<PathBuf>, WearError> {
    let mut doc: Table = original_text
        .parse()
        .map_err(|e| WearError::Input(format!("the model text does not parse again: {e}")))?;
    let roller = section(&mut doc, "roller")?;
    let profile = roller_profile(worn, roller.get("profile"))?;
    roller.insert("profile".into(), profile);
    roller.insert("length".into(), mm(worn.roller.length));
    let cage = section(&mut doc, "cage")?;
    if let Some(c) = &worn.cage {
        let pocket = cage
            .entry("pocket")
            .or_insert_with(|| Value::Table(Table::new()))
            .as_table_mut()
            .ok_or_else(|| WearError::Input("cage.pocket is not a table".into()))?;
        pocket.insert("face_clearance".into(), mm(c.pocket.face_clearance));
        for (key, lip) in [
            ("outer_lip", c.pocket.outer_lip),
            ("inner_lip", c.pocket.inner_lip),
        ] {
            if let (Some(lip), Some(Value::Table(t))) = (lip, pocket.get_mut(key)) {
                t.insert("window".into(), mm(lip.window));
            }
        }
    }
    let mut written = Vec::new();
    for (key, ring, map) in [
        ("inner_ring", &worn.inner_ring, INNER_MAP),
        ("outer_ring", &worn.outer_ring, OUTER_MAP),
    ] {
        let table = section(&mut doc, key)?;
        if let Some(path) = write_map(ring, dir, map)? {
            let mut wear = Table::new();
            wear.insert("file".into(), Value::String(map.into()));
            table.insert("raceway_wear".into(), Value::Table(wear));
            written.push(path);
        }
        if (key == "inner_ring") == ribs_on_inner
            && let Some(spacing) = ring.rib_spacing
        {
            table.insert("rib_spacing".into(), mm(spacing));
        }
    }
    let text =
        toml::to_string(&doc).map_err(|e| WearError::Numerical(format!("worn model: {e}")))?;
    let path = dir.join(WORN_MODEL);
    std::fs::write(&path, format!("# {note}\n{text}"))
        .map_err(|e| WearError::Numerical(format!("cannot write {}: {e}", path.display())))?;
    written.insert(0, path);
    Ok(written)
}
