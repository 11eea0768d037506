//! What a bearing engineer must see first, in three levels: errors (scuffing predicted, points
//! that did not converge, failed variants, values that diverged), warnings (a low scuffing
//! margin, a cage pressed on its land harder than its rollers drive it, edge loading, a finite
//! cage life, wear stopped early) and notes (a land-guided cage on its land, what was not
//! assessed, figures a variant has no value for).

use crate::RunKind;
use crate::folder::OutputFolder;
use crate::quantities::significant;
use serde::Serialize;
use serde_json::Value;
use std::fmt;

/// Scuffing margin s_cr/s below which scuffing is predicted: the slip is past the critical
/// slip, in the thermal zone of the traction curve (docs/theory.md §4.8).
pub const SCUFFING_PREDICTED_MARGIN: f64 = 1.0;
/// Scuffing margin below which the report warns: less than a third of the critical slip left
/// as reserve, within the scatter of the traction model's critical slip.
pub const SCUFFING_CAUTION_MARGIN: f64 = 1.5;
/// Largest cage–land force still read as "off the land" (contact forces are exactly zero out
/// of contact); above it a land-guided cage is on its land (a note).
pub const CAGE_LAND_FORCE_THRESHOLD_N: f64 = 0.0;
/// Ratio of the largest cage–land force to the largest roller–cage force above which a cage
/// is pressed on its land harder than its rollers drive it (a warning: land wear and heat, a
/// cage held by the land, not by the rollers).
pub const CAGE_LAND_TO_ROLLER_FORCE_RATIO: f64 = 1.0;

/// How much a finding matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// The result says the bearing fails or the run is not to be trusted.
    Error,
    /// Worth a look before using the bearing or the result.
    Warning,
    /// Context: expected behaviour, or what the report could not assess.
    Note,
}

impl Level {
    pub fn name(self) -> &'static str {
        match self {
            Self::Error => "error",
            Self::Warning => "warning",
            Self::Note => "note",
        }
    }
}

/// One finding, with where it was found (`""` for the run itself, else the variant).
pub struct Alert {
    pub level: Level,
    pub place: String,
    pub text: String,
}

impl fmt::Display for Alert {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.place.is_empty() {
            true => f.write_str(&self.text),
            false => write!(f, "{}: {}", self.place, self.text),
        }
    }
}

/// The findings of a folder, most severe first.
#[derive(Default)]
pub struct Warnings {
    pub alerts: Vec<Alert>,
}

impl Warnings {
    fn push(&mut self, level: Level, place: &str, text: String) {
        self.alerts.push(Alert {
            level,
            place: place.to_string(),
            text,
        });
    }

    /// The findings of `level`.
    pub fn at(&self, level: Level) -> impl Iterator<Item = &Alert> {
        self.alerts.iter().filter(move |a| a.level == level)
    }

    /// Errors and warnings (what the report's answer lists; notes are context).
    pub fn serious(&self) -> impl Iterator<Item = &Alert> {
        self.alerts.iter().filter(|a| a.level != Level::Note)
    }
}

/// The figures of one place (the run, or a sweep variant) as key and JSON value.
type Figures<'a> = Vec<(String, Value)>;

/// How the cage is guided, from the `[cage] guidance` of the model text (`None`: not stated
/// there, e.g. a sweep file or a folder without run.json).
fn cage_guidance(folder: &OutputFolder) -> Option<String> {
    let text = folder.manifest.as_ref()?.model_text.as_deref()?;
    let mut in_cage = false;
    for line in text.lines() {
        let line = line.split('#').next().unwrap_or_default().trim();
        if line.starts_with('[') {
            in_cage = line == "[cage]";
        } else if in_cage && let Some(value) = line.strip_prefix("guidance") {
            let value = value
                .trim_start()
                .strip_prefix('=')?
                .trim()
                .trim_matches('"');
            return Some(value.to_string());
        }
    }
    None
}

pub fn assess(folder: &OutputFolder) -> Warnings {
    let mut warnings = Warnings::default();
    let mut places: Vec<(String, Figures)> = Vec::new();
    if let Some(manifest) = &folder.manifest {
        places.push((String::new(), flattened(&manifest.summary)));
        for path in not_converged(&manifest.summary, "") {
            warnings.push(Level::Error, "", format!("not converged ({path})"));
        }
    } else {
        warnings.push(
            Level::Note,
            "",
            "inputs unknown: the folder has no run.json (written by rolldyn 0.1 runs with --out)"
                .into(),
        );
    }
    for skipped in &folder.skipped_plots {
        warnings.push(
            Level::Warning,
            "",
            format!("plot {} not shown: {}", skipped.name, skipped.reason),
        );
    }
    if let Some((table, variants)) = &folder.sweep {
        for variant in variants {
            let figures = table
                .header
                .iter()
                .zip(&variant.row)
                .map(|(k, v)| {
                    let value = v
                        .parse::<f64>()
                        .map_or(Value::from(v.as_str()), Value::from);
                    (k.clone(), value)
                })
                .collect();
            let blank: Vec<&str> = table
                .header
                .iter()
                .zip(&variant.row)
                .filter(|(k, v)| v.is_empty() && k.as_str() != "error")
                .map(|(k, _)| k.as_str())
                .collect();
            let place = format!("variant {}", variant.name);
            if !blank.is_empty() && table.field(&variant.row, "error").is_none_or(str::is_empty) {
                warnings.push(
                    Level::Note,
                    &place,
                    format!("no value (blank in summary.csv): {}", blank.join(", ")),
                );
            }
            places.push((place, figures));
        }
    }
    let guidance = cage_guidance(folder);
    let mut edge_assessed = false;
    for (place, figures) in &places {
        let number_of = |key: &str| {
            figures
                .iter()
                .find(|(k, _)| k == key)
                .and_then(|(_, v)| v.as_f64())
        };
        for (key, value) in figures {
            let last = key.rsplit('.').next().unwrap_or(key);
            let number = value.as_f64();
            let mut alert = |level, text| warnings.push(level, place, text);
            match (last, number) {
                ("min_scuffing_margin", Some(m)) if m < SCUFFING_PREDICTED_MARGIN => alert(
                    Level::Error,
                    format!(
                        "scuffing predicted: minimum scuffing margin s_cr/s = {} < {SCUFFING_PREDICTED_MARGIN}",
                        significant(m)
                    ),
                ),
                ("min_scuffing_margin", Some(m)) if m < SCUFFING_CAUTION_MARGIN => alert(
                    Level::Warning,
                    format!(
                        "scuffing margin low: minimum s_cr/s = {} < {SCUFFING_CAUTION_MARGIN}",
                        significant(m)
                    ),
                ),
                ("max_cage_land_force_n", Some(f)) if f > CAGE_LAND_FORCE_THRESHOLD_N => {
                    let sibling = key.replace("max_cage_land_force_n", "max_roller_cage_force_n");
                    let (level, text) = land_finding(f, number_of(&sibling), guidance.as_deref());
                    alert(level, text)
                }
                ("converged", Some(0.0)) => alert(Level::Error, "not converged".into()),
                ("error", _) if value.as_str().is_some_and(|e| !e.is_empty()) => alert(
                    Level::Error,
                    format!("failed: {}", value.as_str().unwrap_or_default()),
                ),
                ("endurance_margin", Some(m)) if m < 1.0 => alert(
                    Level::Warning,
                    format!(
                        "cage fatigue: endurance margin {} < 1, the cage has a finite life",
                        significant(m)
                    ),
                ),
                ("stop", _)
                    if value.as_str().is_some_and(|s| s != "life_reached") || value.is_object() =>
                {
                    alert(
                        Level::Warning,
                        format!("wear stopped before the life: {value}"),
                    )
                }
                _ => {}
            }
            // a value the run did not define (no whirl, no contact) is no finding; one that
            // diverged is an error
            if key.split('.').any(|part| part.starts_with("non_finite")) {
                let reason = text_of(value);
                if reason.contains("diverged") || reason.contains("infinite") {
                    let figure = key.replace("non_finite.", "");
                    alert(
                        Level::Error,
                        format!("not a finite number: {figure} — {reason}"),
                    );
                }
            }
            if key.contains("edge") {
                edge_assessed = true;
                if value == &Value::Bool(true) || number.is_some_and(|n| n > 0.0) {
                    alert(
                        Level::Warning,
                        format!("edge loading ({key} = {})", text_of(value)),
                    );
                }
            }
        }
    }
    if !edge_assessed {
        warnings.push(
            Level::Note,
            "",
            format!(
                "edge loading not assessed: the outputs of {} carry no edge-loading figure (the tapered load distribution, rolldyn loads, flags it per roller)",
                folder.kind.name()
            ),
        );
    }
    if folder.kind == RunKind::Sweep && folder.sweep.as_ref().is_none_or(|(t, _)| t.rows.is_empty())
    {
        warnings.push(
            Level::Warning,
            "",
            "no summary.csv rows: the sweep's variants were not collected".into(),
        );
    }
    warnings.alerts.sort_by_key(|a| a.level);
    warnings
}

/// The finding of a cage–land force `land` (N) beside the largest roller–cage force `rollers`
/// of the same run: a land-guided cage on its land is a note, one pressed on it harder than its
/// rollers drive it a warning (while they drive it at all: with no roller–cage force, as in the
/// first revolution, the land alone carries the cage), a cage guided by its rollers touching a
/// land a warning.
fn land_finding(land: f64, rollers: Option<f64>, guidance: Option<&str>) -> (Level, String) {
    if guidance == Some("rollers") {
        return (
            Level::Warning,
            format!(
                "roller-guided cage touches a ring land: force up to {} N",
                significant(land)
            ),
        );
    }
    match rollers {
        Some(r) if r > 0.0 && land > CAGE_LAND_TO_ROLLER_FORCE_RATIO * r => (
            Level::Warning,
            format!(
                "cage pressed on its land harder than its rollers drive it: land force up to {} N > largest roller–cage force {} N (land wear and heat)",
                significant(land),
                significant(r)
            ),
        ),
        _ => (
            Level::Note,
            format!(
                "cage runs on its guiding land{}: land force up to {} N{}",
                match guidance {
                    Some(g) => format!(" ({g} guided)"),
                    None => String::new(),
                },
                significant(land),
                match rollers {
                    Some(r) if r > 0.0 => format!(
                        ", up to the largest roller–cage force {} N",
                        significant(r)
                    ),
                    Some(_) => ", the rollers not yet driving the cage (no roller–cage force: a run too short?)".into(),
                    None => String::new(),
                }
            ),
        ),
    }
}

/// The paths of every `"converged": false` in a JSON answer, arrays included.
fn not_converged(value: &Value, path: &str) -> Vec<String> {
    match value {
        Value::Object(map) => map
            .iter()
            .flat_map(|(key, v)| match (key.as_str(), v) {
                ("converged", Value::Bool(false)) => vec![join(path, key)],
                _ => not_converged(v, &join(path, key)),
            })
            .collect(),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .flat_map(|(i, v)| not_converged(v, &format!("{path}[{i}]")))
            .collect(),
        _ => Vec::new(),
    }
}

fn join(path: &str, key: &str) -> String {
    match path.is_empty() {
        true => key.to_string(),
        false => format!("{path}.{key}"),
    }
}

fn text_of(value: &Value) -> String {
    match value {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Every scalar of a JSON answer under its dotted path (`maxima.max_cage_land_force_n`);
/// arrays are left out (per-period and per-point detail).
pub(crate) fn flattened(value: &Value) -> Figures<'static> {
    let mut figures = Vec::new();
    flatten_into("", value, &mut figures);
    figures
}

fn flatten_into(path: &str, value: &Value, figures: &mut Vec<(String, Value)>) {
    match value {
        Value::Object(map) => {
            if path.ends_with("stop") {
                figures.push((path.to_string(), value.clone()));
            }
            for (key, v) in map {
                flatten_into(&join(path, key), v, figures);
            }
        }
        Value::Array(_) => {}
        scalar => figures.push((path.to_string(), scalar.clone())),
    }
}
