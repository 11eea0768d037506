//! What a bearing engineer must see first: scuffing, the cage on its land, edge loading,
//! points that did not converge, values that are not finite numbers.

use crate::RunKind;
use crate::folder::OutputFolder;
use crate::quantities::significant;
use serde_json::Value;
use std::fmt;

/// Scuffing margin s_cr/s below which scuffing is predicted: the slip is past the critical
/// slip, in the thermal zone of the traction curve (docs/theory.md §4.8).
pub const SCUFFING_PREDICTED_MARGIN: f64 = 1.0;
/// Scuffing margin below which the report warns: less than a third of the critical slip left
/// as reserve, within the scatter of the traction model's critical slip.
pub const SCUFFING_CAUTION_MARGIN: f64 = 1.5;
/// Largest cage–land force still read as "off the land" (contact forces are exactly zero out
/// of contact).
pub const CAGE_LAND_FORCE_THRESHOLD_N: f64 = 0.0;

/// One finding, with where it was found (`""` for the run itself, else the variant).
pub struct Alert {
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

/// The alerts, and notes on what could not be assessed.
#[derive(Default)]
pub struct Warnings {
    pub alerts: Vec<Alert>,
    pub notes: Vec<String>,
}

/// The figures of one place (the run, or a sweep variant) as key and JSON value.
type Figures<'a> = Vec<(String, Value)>;

pub fn assess(folder: &OutputFolder) -> Warnings {
    let mut warnings = Warnings::default();
    let mut places: Vec<(String, Figures)> = Vec::new();
    if let Some(manifest) = &folder.manifest {
        places.push((String::new(), flattened(&manifest.summary)));
        for path in not_converged(&manifest.summary, "") {
            warnings.alerts.push(Alert {
                place: String::new(),
                text: format!("not converged ({path})"),
            });
        }
    } else {
        warnings.notes.push(
            "inputs unknown: the folder has no run.json (written by rolldyn 0.1 runs with --out)"
                .into(),
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
                warnings.alerts.push(Alert {
                    place: place.clone(),
                    text: format!(
                        "not a finite number (blank in summary.csv): {}",
                        blank.join(", ")
                    ),
                });
            }
            places.push((place, figures));
        }
    }
    let mut edge_assessed = false;
    for (place, figures) in &places {
        let mut alert = |text: String| {
            warnings.alerts.push(Alert {
                place: place.clone(),
                text,
            })
        };
        for (key, value) in figures {
            let last = key.rsplit('.').next().unwrap_or(key);
            let number = value.as_f64();
            match (last, number) {
                ("min_scuffing_margin", Some(m)) if m < SCUFFING_PREDICTED_MARGIN => {
                    alert(format!(
                        "scuffing predicted: minimum scuffing margin s_cr/s = {} < {SCUFFING_PREDICTED_MARGIN}",
                        significant(m)
                    ))
                }
                ("min_scuffing_margin", Some(m)) if m < SCUFFING_CAUTION_MARGIN => alert(format!(
                    "scuffing margin low: minimum s_cr/s = {} < {SCUFFING_CAUTION_MARGIN}",
                    significant(m)
                )),
                ("max_cage_land_force_n", Some(f)) if f > CAGE_LAND_FORCE_THRESHOLD_N => {
                    alert(format!(
                        "cage on its land: guiding-land contact force up to {} N",
                        significant(f)
                    ))
                }
                ("converged", Some(0.0)) => alert("not converged".into()),
                ("error", _) if value.as_str().is_some_and(|e| !e.is_empty()) => {
                    alert(format!("failed: {}", value.as_str().unwrap_or_default()))
                }
                ("endurance_margin", Some(m)) if m < 1.0 => alert(format!(
                    "cage fatigue: endurance margin {} < 1, the cage has a finite life",
                    significant(m)
                )),
                ("stop", _)
                    if value.as_str().is_some_and(|s| s != "life_reached") || value.is_object() =>
                {
                    alert(format!("wear stopped before the life: {value}"))
                }
                _ => {}
            }
            if key.split('.').any(|part| part.starts_with("non_finite")) {
                let figure = key.replace("non_finite.", "");
                alert(format!(
                    "not a finite number: {figure} — {}",
                    text_of(value)
                ));
            }
            if key.contains("edge") {
                edge_assessed = true;
                if value == &Value::Bool(true) || number.is_some_and(|n| n > 0.0) {
                    alert(format!("edge loading ({key} = {})", text_of(value)));
                }
            }
        }
    }
    if !edge_assessed {
        warnings.notes.push(format!(
            "edge loading not assessed: the outputs of {} carry no edge-loading figure (the tapered load distribution, rolldyn loads, flags it per roller)",
            folder.kind.name()
        ));
    }
    if folder.kind == RunKind::Sweep && folder.sweep.as_ref().is_none_or(|(t, _)| t.rows.is_empty())
    {
        warnings
            .notes
            .push("no summary.csv rows: the sweep's variants were not collected".into());
    }
    warnings
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
