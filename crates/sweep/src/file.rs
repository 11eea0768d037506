//! The sweep file and model-key overrides.

use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// A sweep could not be read or run. Displayed as one line naming the file and key.
#[derive(Debug, thiserror::Error)]
#[error("{file}: {key}{sep}{reason}", sep = if key.is_empty() { "" } else { " — " })]
pub struct SweepError {
    pub file: String,
    pub key: String,
    pub reason: String,
}

impl SweepError {
    pub(crate) fn new(file: &Path, key: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            file: file.display().to_string(),
            key: key.into(),
            reason: reason.into(),
        }
    }
}

/// What each variant runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analysis {
    /// 6-DOF dynamics (`rolldyn simulate`).
    Simulate,
    /// Quasi-static skidding (`rolldyn skid`).
    Skid,
    /// Wear over the bearing's life (`rolldyn wear`): `duration` is the life, `period` the
    /// recalculation period.
    Wear,
    /// Cage fatigue from one steady revolution (`rolldyn fatigue`): `method` is the stress
    /// model ("frame" or "calculix").
    Fatigue,
}

/// One variant: a name and the model keys it overrides (dotted paths, TOML values with units).
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    pub name: String,
    pub overrides: Vec<(String, Value)>,
}

/// A parsed sweep file.
#[derive(Debug, Clone)]
pub struct SweepFile {
    pub path: PathBuf,
    /// Base model file, resolved against the sweep file's folder.
    pub model: PathBuf,
    pub model_text: String,
    pub analysis: Analysis,
    /// Simulated duration for `simulate` (`"20rev"` or a time), as written.
    pub duration: Option<String>,
    /// Cage revolutions of a `simulate` run left out of its summary (`"5rev"`), as written; the
    /// dynamics' default (one) when absent.
    pub discard: Option<String>,
    /// Recalculation period of a `wear` sweep (`"1905h"` or `"auto"`), as written.
    pub period: Option<String>,
    /// Wear method of a `wear` sweep (`"direct"` or `"averaged"`) or stress model of a `fatigue`
    /// sweep (`"frame"` or `"calculix"`), as written.
    pub method: Option<String>,
    pub variants: Vec<Variant>,
}

impl SweepFile {
    /// Reads and checks a sweep file (every variant must produce a valid model).
    pub fn load(path: &Path) -> Result<Self, SweepError> {
        let text =
            rolldyn_model::read_input_file(path).map_err(|e| SweepError::new(path, "", e))?;
        let mut table: Table = text.parse().map_err(|e: toml::de::Error| {
            SweepError::new(path, "", e.message().trim().replace('\n', " "))
        })?;
        let take_str = |table: &mut Table, key: &str| -> Result<Option<String>, SweepError> {
            match table.remove(key) {
                None => Ok(None),
                Some(Value::String(s)) => Ok(Some(s)),
                Some(_) => Err(SweepError::new(path, key, "must be a string")),
            }
        };
        let model = take_str(&mut table, "model")?
            .ok_or_else(|| SweepError::new(path, "model", "missing key"))?;
        let analysis = match take_str(&mut table, "analysis")?.as_deref() {
            None | Some("simulate") => Analysis::Simulate,
            Some("skid") => Analysis::Skid,
            Some("wear") => Analysis::Wear,
            Some("fatigue") => Analysis::Fatigue,
            Some(other) => {
                return Err(SweepError::new(
                    path,
                    "analysis",
                    format!("'{other}' is not simulate, skid, wear or fatigue"),
                ));
            }
        };
        let duration = take_str(&mut table, "duration")?;
        let discard = take_str(&mut table, "discard")?;
        let period = take_str(&mut table, "period")?;
        let method = take_str(&mut table, "method")?;
        let library = match take_str(&mut table, "variants_from")? {
            None => Vec::new(),
            Some(file) => {
                let from = path.parent().unwrap_or(Path::new(".")).join(&file);
                SweepFile::load(&from)
                    .map_err(|e| SweepError::new(path, "variants_from", e.to_string()))?
                    .variants
            }
        };
        let variants = match table.remove("variant") {
            Some(Value::Array(items)) => items,
            None => {
                return Err(SweepError::new(
                    path,
                    "variant",
                    "missing: give [[variant]] tables",
                ));
            }
            Some(_) => {
                return Err(SweepError::new(
                    path,
                    "variant",
                    "must be an array of tables ([[variant]])",
                ));
            }
        };
        if let Some(key) = table.keys().next() {
            return Err(SweepError::new(
                path,
                key.clone(),
                "unknown key (expected model, analysis, duration, discard, period, method, variants_from, variant)",
            ));
        }
        let model_path = path.parent().unwrap_or(Path::new(".")).join(&model);
        let model_text = rolldyn_model::read_input_file(&model_path).map_err(|e| {
            SweepError::new(path, "model", format!("{}: {e}", model_path.display()))
        })?;
        let mut parsed = Vec::new();
        for (i, item) in variants.into_iter().enumerate() {
            let key = format!("variant[{i}]");
            let Value::Table(mut t) = item else {
                return Err(SweepError::new(path, key, "must be a table"));
            };
            let name = match t.remove("name") {
                Some(Value::String(s)) if is_file_safe(&s) => s,
                Some(Value::String(s)) => {
                    return Err(SweepError::new(
                        path,
                        format!("{key}.name"),
                        format!("'{s}' must use only letters, digits, '-', '_' and '.'"),
                    ));
                }
                Some(Value::Integer(n)) => n.to_string(),
                _ => {
                    return Err(SweepError::new(
                        path,
                        format!("{key}.name"),
                        "missing or not a string",
                    ));
                }
            };
            if parsed.iter().any(|v: &Variant| v.name == name) {
                return Err(SweepError::new(
                    path,
                    format!("{key}.name"),
                    format!("'{name}' is used twice"),
                ));
            }
            let mut overrides = match t.remove("like") {
                None => Vec::new(),
                Some(Value::String(like)) => library
                    .iter()
                    .find(|v| v.name == like)
                    .map(|v| v.overrides.clone())
                    .ok_or_else(|| {
                        SweepError::new(
                            path,
                            format!("{key}.like"),
                            format!("no variant '{like}' in the variants_from file"),
                        )
                    })?,
                Some(_) => {
                    return Err(SweepError::new(
                        path,
                        format!("{key}.like"),
                        "must be a string",
                    ));
                }
            };
            for (k, v) in t {
                overrides.retain(|(old, _)| *old != k);
                overrides.push((k, v));
            }
            let variant_text = apply_overrides(&model_text, &overrides)
                .map_err(|reason| SweepError::new(path, format!("{key} ({name})"), reason))?;
            rolldyn_model::parse(&variant_text, &model_path.display().to_string())
                .map_err(|e| SweepError::new(path, format!("{key} ({name})"), e.to_string()))?;
            parsed.push(Variant { name, overrides });
        }
        Ok(Self {
            path: path.to_path_buf(),
            model: model_path,
            model_text,
            analysis,
            duration,
            discard,
            period,
            method,
            variants: parsed,
        })
    }

    /// The model keys any variant overrides, in the order they first appear.
    pub fn varied_keys(&self) -> Vec<String> {
        let mut keys: Vec<String> = Vec::new();
        for (key, _) in self.variants.iter().flat_map(|v| &v.overrides) {
            if !keys.contains(key) {
                keys.push(key.clone());
            }
        }
        keys
    }

    /// The value of the dotted model key `key` for `variant`: its override, else the base
    /// model's value (`None` when the base model leaves it to its default).
    pub fn value_of(&self, variant: &Variant, key: &str) -> Option<Value> {
        if let Some((_, v)) = variant.overrides.iter().rev().find(|(k, _)| k == key) {
            return Some(v.clone());
        }
        let doc: Table = self.model_text.parse().ok()?;
        let mut parts = key.split('.');
        let mut node = doc.get(parts.next()?)?;
        for part in parts {
            node = match node {
                Value::Table(t) => t.get(part)?,
                Value::Array(items) => items.get(part.parse::<usize>().ok()?)?,
                _ => return None,
            };
        }
        Some(node.clone())
    }

    /// The model of `variant` (base model with its overrides).
    pub fn model_of(&self, variant: &Variant) -> Result<rolldyn_model::Model, SweepError> {
        let text = apply_overrides(&self.model_text, &variant.overrides)
            .map_err(|reason| SweepError::new(&self.path, variant.name.clone(), reason))?;
        rolldyn_model::parse(&text, &self.model.display().to_string())
            .map_err(|e| SweepError::new(&self.path, variant.name.clone(), e.to_string()))
    }
}

fn is_file_safe(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
}

/// Sets dotted keys (`roller.profile.drop`, `inner_ring.ribs.0.face.radius`) in a model text.
/// Tables on the path are created when missing; an index into an array must exist.
pub fn apply_overrides(model_text: &str, overrides: &[(String, Value)]) -> Result<String, String> {
    let mut doc: Table = model_text
        .parse()
        .map_err(|e: toml::de::Error| e.message().trim().to_string())?;
    for (key, value) in overrides {
        let parts: Vec<&str> = key.split('.').collect();
        let (last, path) = parts.split_last().ok_or_else(|| "empty key".to_string())?;
        let mut node: &mut Value = doc
            .entry(path.first().copied().unwrap_or(last).to_string())
            .or_insert_with(|| Value::Table(Table::new()));
        if path.is_empty() {
            *node = value.clone();
            continue;
        }
        for part in &path[1..] {
            node = match node {
                Value::Table(t) => t
                    .entry(part.to_string())
                    .or_insert_with(|| Value::Table(Table::new())),
                Value::Array(items) => {
                    let i: usize = part
                        .parse()
                        .map_err(|_| format!("{key}: '{part}' is not an index of an array"))?;
                    let len = items.len();
                    items
                        .get_mut(i)
                        .ok_or_else(|| format!("{key}: index {i} beyond the {len} items"))?
                }
                _ => return Err(format!("{key}: '{part}' is inside a value, not a table")),
            };
        }
        match node {
            Value::Table(t) => {
                t.insert(last.to_string(), value.clone());
            }
            Value::Array(items) => {
                let i: usize = last
                    .parse()
                    .map_err(|_| format!("{key}: '{last}' is not an index"))?;
                let len = items.len();
                *items
                    .get_mut(i)
                    .ok_or_else(|| format!("{key}: index {i} beyond the {len} items"))? =
                    value.clone();
            }
            _ => return Err(format!("{key}: the parent is a value, not a table")),
        }
    }
    toml::to_string(&doc).map_err(|e| e.to_string())
}
