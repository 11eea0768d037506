//! The sweep file and model-key overrides.

use rolldyn_model::{KeySegment, LocatedToml, ModelError, Source};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// A sweep could not be read or run. Displayed as one line naming the file, the line and
/// column when known, the key and the reason.
#[derive(Debug)]
pub struct SweepError {
    pub file: String,
    /// 1-based line and column of the offending key or value, when known.
    pub position: Option<(usize, usize)>,
    pub key: String,
    pub reason: String,
}

impl SweepError {
    pub(crate) fn new(file: &Path, key: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            file: file.display().to_string(),
            position: None,
            key: key.into(),
            reason: reason.into(),
        }
    }

    /// The error as a model-file error (`file:line:column: key — reason`).
    fn located(&self) -> ModelError {
        ModelError {
            file: self.file.clone(),
            position: self.position,
            key: self.key.clone(),
            reason: self.reason.clone(),
        }
    }
}

impl std::fmt::Display for SweepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.located().fmt(f)
    }
}

impl std::error::Error for SweepError {}

impl From<ModelError> for SweepError {
    fn from(e: ModelError) -> Self {
        Self {
            file: e.file,
            position: e.position,
            key: e.key,
            reason: e.reason,
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
    /// The text of the sweep file, to name the line of a key in later errors.
    text: String,
}

impl SweepFile {
    /// Reads and checks a sweep file (every variant must produce a valid model). Every error
    /// names the file, the line and column of the key at fault, and the key.
    pub fn load(path: &Path) -> Result<Self, SweepError> {
        let text =
            rolldyn_model::read_input_file(path).map_err(|e| SweepError::new(path, "", e))?;
        let file = path.display().to_string();
        let located = LocatedToml::parse(&text, &file)?;
        let error = |key: &str, reason: String| SweepError::from(located.error(key, reason));
        let mut table: Table = text
            .parse()
            .map_err(|e: toml::de::Error| error("", e.message().trim().replace('\n', " ")))?;
        let take_str = |table: &mut Table, key: &str| -> Result<Option<String>, SweepError> {
            match table.remove(key) {
                None => Ok(None),
                Some(Value::String(s)) => Ok(Some(s)),
                Some(_) => Err(error(key, "must be a string".into())),
            }
        };
        let model =
            take_str(&mut table, "model")?.ok_or_else(|| error("model", "missing key".into()))?;
        let analysis = match take_str(&mut table, "analysis")?.as_deref() {
            None | Some("simulate") => Analysis::Simulate,
            Some("skid") => Analysis::Skid,
            Some("wear") => Analysis::Wear,
            Some("fatigue") => Analysis::Fatigue,
            Some(other) => {
                return Err(error(
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
            Some(from) => {
                let from = path.parent().unwrap_or(Path::new(".")).join(&from);
                SweepFile::load(&from)
                    .map_err(|e| error("variants_from", e.to_string()))?
                    .variants
            }
        };
        let variants = match table.remove("variant") {
            Some(Value::Array(items)) => items,
            None => return Err(error("variant", "missing: give [[variant]] tables".into())),
            Some(_) => {
                return Err(error(
                    "variant",
                    "must be an array of tables ([[variant]])".into(),
                ));
            }
        };
        if let Some(key) = table.keys().next() {
            return Err(error(
                key,
                "unknown key (expected model, analysis, duration, discard, period, method, variants_from, variant)".into(),
            ));
        }
        let model_path = path.parent().unwrap_or(Path::new(".")).join(&model);
        let model_text = rolldyn_model::read_input_file(&model_path)
            .map_err(|e| error("model", format!("{}: {e}", model_path.display())))?;
        let model_file = model_path.display().to_string();
        let mut parsed = Vec::new();
        for (i, item) in variants.into_iter().enumerate() {
            let key = format!("variant[{i}]");
            let at = |segments: &[&str], key: &str, reason: String| {
                let mut path = vec![KeySegment::Key("variant".into()), KeySegment::Index(i)];
                path.extend(segments.iter().map(|s| KeySegment::Key(s.to_string())));
                SweepError::from(located.error_at(&path, key, reason))
            };
            let Value::Table(mut t) = item else {
                return Err(at(&[], &key, "must be a table".into()));
            };
            let name_key = format!("{key}.name");
            let name = match t.remove("name") {
                Some(Value::String(s)) if is_file_safe(&s) => s,
                Some(Value::String(s)) => {
                    return Err(at(
                        &["name"],
                        &name_key,
                        format!("'{s}' must use only letters, digits, '-', '_' and '.'"),
                    ));
                }
                Some(Value::Integer(n)) => n.to_string(),
                _ => return Err(at(&["name"], &name_key, "missing or not a string".into())),
            };
            if parsed.iter().any(|v: &Variant| v.name == name) {
                return Err(at(&["name"], &name_key, format!("'{name}' is used twice")));
            }
            let mut overrides = match t.remove("like") {
                None => Vec::new(),
                Some(Value::String(like)) => library
                    .iter()
                    .find(|v| v.name == like)
                    .map(|v| v.overrides.clone())
                    .ok_or_else(|| {
                        at(
                            &["like"],
                            &format!("{key}.like"),
                            format!("no variant '{like}' in the variants_from file"),
                        )
                    })?,
                Some(_) => {
                    return Err(at(
                        &["like"],
                        &format!("{key}.like"),
                        "must be a string".into(),
                    ));
                }
            };
            let own: Vec<String> = t.keys().cloned().collect();
            for (k, v) in t {
                overrides.retain(|(old, _)| *old != k);
                overrides.push((k, v));
            }
            model_with_overrides(&model_text, &model_file, &overrides).map_err(|e| match e {
                OverrideError::Override { key: k, reason } => {
                    let segment = if own.contains(&k) { k.as_str() } else { "like" };
                    at(&[segment], &format!("{key} ({name}) \"{k}\""), reason)
                }
                OverrideError::Base(e) => at(&[], &format!("{key} ({name})"), e.to_string()),
            })?;
            parsed.push(Variant { name, overrides });
        }
        Ok(Self {
            path: path.to_path_buf(),
            text,
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

    /// The error `reason` at the sweep file's top-level `key` (at its line when the key is in
    /// the file), for the checks of the analysis's settings (`duration`, `period`, …).
    pub fn error(&self, key: &str, reason: impl Into<String>) -> SweepError {
        let file = self.path.display().to_string();
        match LocatedToml::parse(&self.text, &file) {
            Ok(located) => located.error(key, reason).into(),
            Err(_) => SweepError::new(&self.path, key, reason),
        }
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
        model_with_overrides(
            &self.model_text,
            &self.model.display().to_string(),
            &variant.overrides,
        )
        .map(|(_, model)| model)
        .map_err(|e| match e {
            OverrideError::Override { key, reason } => self.error(
                "variant",
                format!("variant {} \"{key}\" — {reason}", variant.name),
            ),
            OverrideError::Base(e) => e.into(),
        })
    }
}

fn is_file_safe(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
}

/// A model with overrides could not be built.
#[derive(Debug, Clone, PartialEq)]
pub enum OverrideError {
    /// The override of `key` (as written, `inner_ring.ribs.0.diameter`) is at fault.
    Override { key: String, reason: String },
    /// The model fails at a key no override sets: the error located in the base model's text.
    Base(ModelError),
}

/// The text and model of the base model `base_text` (named `base_file`) with `overrides` set:
/// an error at an overridden key (or inside an overridden table) names that override, any
/// other names the key's line in the base file (not in the rewritten text).
pub fn model_with_overrides(
    base_text: &str,
    base_file: &str,
    overrides: &[(String, Value)],
) -> Result<(String, rolldyn_model::Model), OverrideError> {
    LocatedToml::parse(base_text, base_file).map_err(OverrideError::Base)?;
    let text = set_keys(base_text, overrides)?;
    let model = rolldyn_model::parse(&text, base_file).map_err(|e| {
        let key = overrides
            .iter()
            .rev()
            .map(|(key, _)| key)
            .find(|key| overlaps(&model_key(key), &e.key));
        match key {
            Some(key) => OverrideError::Override {
                key: key.clone(),
                reason: e.reason,
            },
            None => OverrideError::Base(Source::new(base_file, base_text).error(&e.key, e.reason)),
        }
    })?;
    Ok((text, model))
}

/// An override key as the model's errors spell it: `inner_ring.ribs.0.diameter` →
/// `inner_ring.ribs[0].diameter`.
fn model_key(key: &str) -> String {
    let mut out = String::new();
    for part in key.split('.') {
        if part.parse::<usize>().is_ok() {
            out.push_str(&format!("[{part}]"));
        } else {
            if !out.is_empty() {
                out.push('.');
            }
            out.push_str(part);
        }
    }
    out
}

/// Whether model keys `a` and `b` are the same item or one lies inside the other.
fn overlaps(a: &str, b: &str) -> bool {
    let inside = |inner: &str, outer: &str| {
        inner
            .strip_prefix(outer)
            .is_some_and(|rest| rest.is_empty() || rest.starts_with(['.', '[']))
    };
    !a.is_empty() && !b.is_empty() && (inside(a, b) || inside(b, a))
}

/// Sets dotted keys (`roller.profile.drop`, `inner_ring.ribs.0.face.radius`) in a model text.
/// Tables on the path are created when missing; an index into an array must exist.
pub fn apply_overrides(model_text: &str, overrides: &[(String, Value)]) -> Result<String, String> {
    set_keys(model_text, overrides).map_err(|e| match e {
        OverrideError::Override { key, reason } => format!("{key}: {reason}"),
        OverrideError::Base(e) => e.to_string(),
    })
}

/// [`apply_overrides`] naming the override at fault.
fn set_keys(model_text: &str, overrides: &[(String, Value)]) -> Result<String, OverrideError> {
    let mut doc: Table = model_text.parse().map_err(|e: toml::de::Error| {
        OverrideError::Base(ModelError {
            file: String::new(),
            position: None,
            key: String::new(),
            reason: e.message().trim().to_string(),
        })
    })?;
    for (key, value) in overrides {
        set_key(&mut doc, key, value).map_err(|reason| OverrideError::Override {
            key: key.clone(),
            reason,
        })?;
    }
    toml::to_string(&doc).map_err(|e| {
        OverrideError::Base(ModelError {
            file: String::new(),
            position: None,
            key: String::new(),
            reason: e.to_string(),
        })
    })
}

/// Sets the dotted `key` of `doc` to `value`.
fn set_key(doc: &mut Table, key: &str, value: &Value) -> Result<(), String> {
    let parts: Vec<&str> = key.split('.').collect();
    let (last, path) = parts.split_last().ok_or_else(|| "empty key".to_string())?;
    let mut node: &mut Value = doc
        .entry(path.first().copied().unwrap_or(last).to_string())
        .or_insert_with(|| Value::Table(Table::new()));
    if path.is_empty() {
        *node = value.clone();
        return Ok(());
    }
    for part in &path[1..] {
        node = match node {
            Value::Table(t) => t
                .entry(part.to_string())
                .or_insert_with(|| Value::Table(Table::new())),
            Value::Array(items) => {
                let i: usize = part
                    .parse()
                    .map_err(|_| format!("'{part}' is not an index of an array"))?;
                let len = items.len();
                items
                    .get_mut(i)
                    .ok_or_else(|| format!("index {i} beyond the {len} items"))?
            }
            _ => return Err(format!("'{part}' is inside a value, not a table")),
        };
    }
    match node {
        Value::Table(t) => {
            t.insert(last.to_string(), value.clone());
        }
        Value::Array(items) => {
            let i: usize = last
                .parse()
                .map_err(|_| format!("'{last}' is not an index"))?;
            let len = items.len();
            *items
                .get_mut(i)
                .ok_or_else(|| format!("index {i} beyond the {len} items"))? = value.clone();
        }
        _ => return Err("the parent is a value, not a table".into()),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sweep file `body` beside the embedded model, in a fresh folder named `name`.
    fn sweep_file(name: &str, body: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rolldyn-sweep-file-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("model.toml"), rolldyn_model::DEFAULT_MODEL).unwrap();
        let path = dir.join("sweep.toml");
        std::fs::write(&path, format!("model = \"model.toml\"\n{body}")).unwrap();
        path
    }

    #[test]
    fn n13_a_toml_syntax_error_names_its_line() {
        let path = sweep_file("syntax", "duration = \"1rev\"\n[[variant]\nname = \"a\"\n");
        let e = SweepFile::load(&path).unwrap_err();
        assert_eq!(e.position.map(|p| p.0), Some(3), "{e}");
        assert!(e.to_string().contains("sweep.toml:3:"), "{e}");
    }

    #[test]
    fn n13_key_errors_name_line_and_key() {
        let path = sweep_file(
            "keys",
            "[[variant]]\nname = \"a\"\n[[variant]]\nname = \"b\"\nlike = \"x\"\n",
        );
        let e = SweepFile::load(&path).unwrap_err();
        assert_eq!(
            (e.position.map(|p| p.0), e.key.as_str()),
            (Some(6), "variant[1].like")
        );
        let path = sweep_file("unknown", "speed = 3\n[[variant]]\nname = \"a\"\n");
        let e = SweepFile::load(&path).unwrap_err();
        assert_eq!((e.position, e.key.as_str()), (Some((2, 1)), "speed"));
    }

    #[test]
    fn n3_an_override_error_names_the_sweep_line_and_the_override_key() {
        let body = "[[variant]]\nname = \"a\"\n\"operating.radial_load\" = \"5 kN\"\n\
                    [[variant]]\nname = \"wide\"\n\"cage.width\" = \"1e308 mm\"\n";
        let path = sweep_file("override", body);
        let e = SweepFile::load(&path).unwrap_err();
        assert!(e.file.ends_with("sweep.toml"), "{e}");
        assert_eq!(e.position, Some((7, 1)), "{e}");
        assert_eq!(e.key, "variant[1] (wide) \"cage.width\"");
        assert!(!e.reason.contains("model.toml"), "{e}");
    }

    #[test]
    fn n3_override_errors_blame_the_override_or_the_base_line() {
        let set = |key: &str, value: &str| vec![(key.to_string(), Value::String(value.into()))];
        let base = rolldyn_model::DEFAULT_MODEL;
        match model_with_overrides(base, "base.toml", &set("cage.width", "1e308 mm")) {
            Err(OverrideError::Override { key, .. }) => assert_eq!(key, "cage.width"),
            other => panic!("{other:?}"),
        }
        let nested = set("inner_ring.ribs.0.diameter", "fast");
        match model_with_overrides(base, "base.toml", &nested) {
            Err(OverrideError::Override { key, .. }) => {
                assert_eq!(key, "inner_ring.ribs.0.diameter")
            }
            other => panic!("{other:?}"),
        }
        // a rib rim beyond the cage fails at the cage's key: its line in the base file
        let huge_rib = set("inner_ring.ribs.0.diameter", "1e308 mm");
        match model_with_overrides(base, "base.toml", &huge_rib) {
            Err(OverrideError::Base(e)) => {
                let (line, _) = e.position.expect("a line of the base file");
                let text = base.lines().nth(line - 1).unwrap();
                let name = e.key.rsplit('.').next().unwrap();
                assert!(text.contains(name), "{e}: line {line} is '{text}'");
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            model_key("inner_ring.ribs.0.diameter"),
            "inner_ring.ribs[0].diameter"
        );
        assert!(overlaps("roller", "roller.count") && overlaps("a.b[0]", "a.b"));
        assert!(!overlaps("roller.count", "roller.count_x"));
    }
}
