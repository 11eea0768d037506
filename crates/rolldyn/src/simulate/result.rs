//! What `simulate` answers: the run summary (serialised as the `--json` answer, shown as the
//! text summary), the step limits, the output folder and, when asked, the tables.

use crate::table::{Table, Tables};
use rolldyn_dynamics::SummaryValue;
use rolldyn_dynamics::output::RunSummary;
use serde::{Serialize, Serializer};
use std::fmt;
use std::path::PathBuf;

/// A kind of state component and its share of the steps it limited.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StepLimit {
    pub component: String,
    pub share: f64,
}

/// The three kinds of state component that limited the step most often (of
/// `Simulation::step_limits`), with their shares of all counted steps.
pub fn step_limits(counts: &[(String, u64)]) -> Vec<StepLimit> {
    let total: u64 = counts.iter().map(|(_, c)| c).sum();
    counts
        .iter()
        .take(3)
        .map(|(kind, c)| StepLimit {
            component: kind.clone(),
            share: *c as f64 / total.max(1) as f64,
        })
        .collect()
}

/// The run of a bearing kind.
#[derive(Clone, Debug)]
pub enum Run {
    /// A cylindrical bearing's run: its summary, the step limits, and the drag and land
    /// inputs the text shows.
    Cylindrical {
        summary: RunSummary,
        step_limited_by: Vec<StepLimit>,
        drag_and_land: Vec<(&'static str, String)>,
    },
    /// A double-row tapered bearing's run: the simulated time [s], the summary figures
    /// (`summary_entries`, then simulated time, wall time, steps) and the state component
    /// that limited the step most often.
    Tapered {
        duration_s: f64,
        entries: Vec<(String, f64)>,
        most_limiting: Option<String>,
    },
}

/// The result of `simulate`. Serialised, it is the `--json` answer: the model, every figure
/// of the run summary (SI units), the step limits (when counted) and the output folder, under
/// the non-finite policy of docs/outputs.md.
#[derive(Clone, Debug)]
pub struct SimulateResult {
    /// The bearing's name.
    pub model: String,
    pub run: Run,
    /// The output folder, when one was written.
    pub output_folder: Option<PathBuf>,
    /// With `keep_tables`: `bearing`, `rollers` and `revolutions` (cylindrical) or `tapered`.
    pub tables: Vec<Table>,
}

impl SimulateResult {
    /// The `--json` answer.
    pub fn answer(&self) -> serde_json::Value {
        let folder = self.output_folder.as_ref().map(|d| d.display().to_string());
        match &self.run {
            Run::Cylindrical {
                summary,
                step_limited_by,
                ..
            } => answer_json(&self.model, summary, step_limited_by, folder),
            Run::Tapered {
                entries,
                most_limiting,
                ..
            } => {
                let mut map = serde_json::Map::new();
                map.insert("model".into(), self.model.clone().into());
                for (k, v) in entries {
                    map.insert(k.clone(), serde_json::json!(v));
                }
                if let Some(c) = most_limiting {
                    map.insert("most_limiting".into(), c.clone().into());
                }
                if let Some(d) = folder {
                    map.insert("out".into(), d.into());
                }
                serde_json::Value::Object(map)
            }
        }
    }
}

impl Serialize for SimulateResult {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.answer().serialize(serializer)
    }
}

impl Tables for SimulateResult {
    fn tables(&self) -> Vec<Table> {
        self.tables.clone()
    }
}

impl fmt::Display for SimulateResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.run {
            Run::Cylindrical {
                summary,
                step_limited_by,
                drag_and_land,
            } => {
                write!(f, "{}", summary_text(&self.model, summary, step_limited_by))?;
                for (name, value) in drag_and_land {
                    write!(f, "\n  {name:<34} {value}")?;
                }
                Ok(())
            }
            Run::Tapered {
                duration_s,
                entries,
                ..
            } => {
                write!(
                    f,
                    "{} — double-row tapered, {duration_s:.4} s simulated",
                    self.model
                )?;
                for (k, v) in entries {
                    write!(f, "\n  {k:32} {v:.6e}")?;
                }
                Ok(())
            }
        }
    }
}

/// The JSON answer of a cylindrical run: the model, every figure of the run summary
/// (`RunSummary::fields`, SI units), the step limits (when counted) and the output folder, under
/// the non-finite policy of docs/outputs.md.
fn answer_json(
    model: &str,
    s: &RunSummary,
    step_limited_by: &[StepLimit],
    output_folder: Option<String>,
) -> serde_json::Value {
    let mut object = serde_json::Map::new();
    object.insert("model".into(), model.into());
    for (name, value) in s.fields() {
        let value = match value {
            SummaryValue::Real(v) => v.into(),
            SummaryValue::Count(n) => n.into(),
            SummaryValue::Flag(b) => b.into(),
        };
        object.insert(name.into(), value);
    }
    if !step_limited_by.is_empty() {
        let limits = serde_json::to_value(step_limited_by).unwrap_or_default();
        object.insert("step_limited_by".into(), limits);
    }
    object.insert("output_folder".into(), output_folder.into());
    rolldyn_output::mark_non_finite(&mut object, &s.columns(), |key, v| {
        non_finite_reason(key, v).to_string()
    });
    serde_json::Value::Object(object)
}

/// The JSON form of a run summary (used by `demo`).
pub fn summary_json(model: &str, s: &RunSummary) -> serde_json::Value {
    answer_json(model, s, &[], None)
}

/// Why a run-summary value is not a finite number (docs/outputs.md).
fn non_finite_reason(key: &str, value: f64) -> &'static str {
    match key {
        "min_scuffing_margin" => "no scuffing-margin maximum in the run",
        "whirl_ratio" if value.is_nan() => "the cage centre does not orbit (no whirl)",
        _ => rolldyn_output::default_reason(value),
    }
}

/// The text summary of a cylindrical run (lines without the last newline).
pub fn summary_text(model: &str, s: &RunSummary, limits: &[StepLimit]) -> String {
    let mut lines = vec![format!(
        "{model}: dynamics, {:.4} s simulated in {:.2} s",
        s.simulated_time_s, s.wall_time_s
    )];
    let mut line = |label: &str, value: String| lines.push(format!("  {label:<34} {value}"));
    line(
        "cage speed (mean)",
        format!("{:.2} rad/s", s.cage_speed_mean_rad_s),
    );
    line(
        "epicyclic cage speed",
        format!("{:.2} rad/s", s.epicyclic_cage_speed_rad_s),
    );
    line(
        "cage slip (mean)",
        format!("{:.6} (fraction of the epicyclic speed)", s.cage_slip_mean),
    );
    line(
        "max inner / outer contact force",
        format!(
            "{:.1} / {:.1} N",
            s.max_inner_contact_force_n, s.max_outer_contact_force_n
        ),
    );
    line(
        "max roller–cage force",
        format!("{:.2} N", s.max_roller_cage_force_n),
    );
    line(
        "max cage–land force",
        format!("{:.2} N", s.max_cage_land_force_n),
    );
    line(
        "max inner sliding speed",
        format!(
            "{:.3} m/s (rolling direction {:.3}, axial {:.3}; most loaded roller {:.3}, {:.3})",
            s.max_inner_sliding_speed_m_s,
            s.max_inner_sliding_rolling_direction_m_s,
            s.max_inner_sliding_axial_m_s,
            s.max_inner_sliding_rolling_direction_most_loaded_m_s,
            s.max_inner_sliding_axial_most_loaded_m_s
        ),
    );
    line("max relative slip", format!("{:.4}", s.max_relative_slip));
    line(
        "min scuffing margin s_cr/s",
        format!("{:.2}", s.min_scuffing_margin),
    );
    line(
        "whirl ratio",
        if s.whirl_ratio.is_finite() {
            format!(
                "{:.3}{}",
                s.whirl_ratio,
                if s.precession { " (precession)" } else { "" }
            )
        } else {
            format!(
                "— (the cage centre does not orbit; RMS offset {:.1} µm)",
                s.cage_orbit_radius_m * 1e6
            )
        },
    );
    line(
        "steps (rejected) / RHS evaluations",
        format!("{} ({}) / {}", s.steps, s.rejected_steps, s.rhs_evaluations),
    );
    if !limits.is_empty() {
        let shares: Vec<String> = limits
            .iter()
            .map(|l| format!("{} {:.0} %", l.component, 100.0 * l.share))
            .collect();
        line("step limited by", shares.join(", "));
    }
    lines.join("\n")
}
