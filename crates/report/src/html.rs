//! The report page: one HTML file with its style, plots (inline SVG) and table-sorting script.

use crate::folder::{CsvContent, OutputFolder, Plot, Table};
use crate::quantities::{display, significant};
use crate::warnings::{Warnings, flattened};
use crate::{
    CAGE_LAND_FORCE_THRESHOLD_N, RunKind, SCUFFING_CAUTION_MARGIN, SCUFFING_PREDICTED_MARGIN,
};
use serde_json::Value;
use std::fmt::Write;

const STYLE: &str = include_str!("report.css");
const SORT_SCRIPT: &str = include_str!("sort.js");

/// The figures of a cylindrical `simulate` summary grouped as seed 000 Table 3.2.
const SEED_TABLE: [(&str, &[(&str, &str)]); 6] = [
    (
        "Cage",
        &[
            ("cage_slip_mean", "cage slip (mean)"),
            ("cage_speed_mean_rad_s", "cage speed (mean)"),
            ("epicyclic_cage_speed_rad_s", "epicyclic cage speed"),
        ],
    ),
    (
        "Maximum contact forces",
        &[
            ("max_inner_contact_force_n", "roller – inner raceway"),
            ("max_outer_contact_force_n", "roller – outer raceway"),
            ("max_roller_cage_force_n", "roller – cage bar"),
            ("max_cage_land_force_n", "cage – guiding land"),
            ("max_roller_end_rib_force_n", "roller end – rib"),
            ("max_roller_end_cage_force_n", "roller end – pocket"),
        ],
    ),
    (
        "Sliding on the inner raceway",
        &[
            ("max_inner_sliding_speed_m_s", "sliding speed (max)"),
            (
                "max_inner_sliding_rolling_direction_m_s",
                "  rolling direction",
            ),
            ("max_inner_sliding_axial_m_s", "  axial"),
            (
                "max_inner_sliding_rolling_direction_most_loaded_m_s",
                "  rolling direction, most loaded roller",
            ),
            (
                "max_inner_sliding_axial_most_loaded_m_s",
                "  axial, most loaded roller",
            ),
            ("max_relative_slip", "relative slip v/u (max)"),
        ],
    ),
    (
        "Scuffing",
        &[("min_scuffing_margin", "scuffing margin s_cr/s (min)")],
    ),
    (
        "Whirl",
        &[
            ("whirl_ratio", "whirl ratio"),
            ("precession", "precession"),
            ("cage_orbit_radius_m", "cage orbit radius (RMS)"),
        ],
    ),
    (
        "Run",
        &[
            ("simulated_time_s", "simulated time"),
            ("wall_time_s", "wall time"),
            ("steps", "accepted steps"),
            ("rejected_steps", "rejected steps"),
        ],
    ),
];

/// HTML text with `& < > " '` escaped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

pub fn page(folder: &OutputFolder, warnings: &Warnings) -> String {
    let kind = folder.kind.name();
    let model = folder.model_name().unwrap_or("");
    let title = format!(
        "rolldyn {kind} report{}",
        if model.is_empty() {
            String::new()
        } else {
            format!(" — {model}")
        }
    );
    let mut html = String::new();
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n<header><h1>{}</h1>\
         <p>Output folder <code>{}</code></p></header>\n",
        escape(&title),
        escape(&title),
        escape(&folder.dir.display().to_string())
    );
    html.push_str(&navigation(folder));
    html.push_str(&warnings_section(warnings));
    html.push_str(&inputs_section(folder));
    html.push_str(&summary_section(folder));
    if let Some((table, variants)) = &folder.sweep {
        html.push_str(&variants_section(table, variants));
    }
    html.push_str(&plots_section("plots", "Plots", &folder.plots));
    html.push_str(&tables_section(folder));
    let _ = write!(html, "<script>\n{SORT_SCRIPT}</script>\n</body>\n</html>\n");
    html
}

fn navigation(folder: &OutputFolder) -> String {
    let mut links = vec![
        ("warnings", "Warnings"),
        ("inputs", "Inputs"),
        ("summary", "Summary"),
    ];
    if folder.sweep.is_some() {
        links.push(("variants", "Variants"));
    }
    links.extend([("plots", "Plots"), ("tables", "Tables")]);
    let items: Vec<String> = links
        .iter()
        .map(|(id, label)| format!("<a href=\"#{id}\">{label}</a>"))
        .collect();
    format!("<nav>{}</nav>\n", items.join(" · "))
}

fn warnings_section(warnings: &Warnings) -> String {
    let class = if warnings.alerts.is_empty() {
        "warnings clear"
    } else {
        "warnings"
    };
    let mut html = format!("<section id=\"warnings\" class=\"{class}\">\n<h2>Warnings</h2>\n");
    if warnings.alerts.is_empty() {
        html.push_str("<p>No warning: no scuffing, no cage–land contact, every point converged and finite.</p>\n");
    } else {
        html.push_str("<ul>\n");
        for alert in &warnings.alerts {
            let _ = writeln!(html, "<li>{}</li>", escape(&alert.to_string()));
        }
        html.push_str("</ul>\n");
    }
    for note in &warnings.notes {
        let _ = writeln!(html, "<p class=\"note\">{}</p>", escape(note));
    }
    let _ = writeln!(
        html,
        "<p class=\"note\">Thresholds: scuffing predicted when the minimum scuffing margin s_cr/s is below \
         {SCUFFING_PREDICTED_MARGIN} (slip past the critical slip), a warning below {SCUFFING_CAUTION_MARGIN}; \
         cage on its land when the cage–land force exceeds {CAGE_LAND_FORCE_THRESHOLD_N} N \
         (docs/outputs.md, \"Run manifest and HTML report\").</p>\n</section>"
    );
    html
}

fn inputs_section(folder: &OutputFolder) -> String {
    let mut html = String::from("<section id=\"inputs\">\n<h2>Inputs</h2>\n");
    let Some(m) = &folder.manifest else {
        html.push_str(
            "<p>Inputs unknown: the folder has no <code>run.json</code>.</p>\n</section>\n",
        );
        return html;
    };
    let file_label = match m.kind {
        RunKind::Sweep => "sweep file",
        _ => "model file",
    };
    let rows = [
        ("kind", m.kind.name().to_string()),
        ("rolldyn version", m.rolldyn_version.clone()),
        ("command", m.command.join(" ")),
        (
            file_label,
            m.model_file
                .clone()
                .unwrap_or_else(|| "embedded model (2002834) or given in memory".into()),
        ),
    ];
    html.push_str("<table class=\"figures\">\n");
    for (label, value) in rows {
        let _ = writeln!(
            html,
            "<tr><th>{label}</th><td><code>{}</code></td></tr>",
            escape(&value)
        );
    }
    html.push_str("</table>\n<h3>Flags given</h3>\n");
    if m.overrides.is_empty() {
        html.push_str("<p>None: the model's own operating point and the defaults.</p>\n");
    } else {
        html.push_str("<table class=\"figures\">\n");
        for (flag, value) in &m.overrides {
            let _ = writeln!(
                html,
                "<tr><th><code>{}</code></th><td>{}</td></tr>",
                escape(flag),
                escape(value)
            );
        }
        html.push_str("</table>\n");
    }
    if let Some(text) = &m.model_text {
        let _ = writeln!(
            html,
            "<details><summary>Text of the {file_label}</summary><pre>{}</pre></details>",
            escape(text)
        );
    }
    html.push_str("</section>\n");
    html
}

fn summary_section(folder: &OutputFolder) -> String {
    let mut html = String::from("<section id=\"summary\">\n<h2>Summary</h2>\n");
    let Some(m) = &folder.manifest else {
        html.push_str("<p>No run summary (no <code>run.json</code>); see the tables and plots below.</p>\n</section>\n");
        return html;
    };
    let figures = flattened(&m.summary);
    let is_cylindrical_simulate =
        folder.kind == RunKind::Simulate && figures.iter().any(|(k, _)| k == "cage_slip_mean");
    if is_cylindrical_simulate {
        html.push_str("<h3>As seed 000 Table 3.2</h3>\n");
        html.push_str(&seed_table(&m.summary));
    }
    let _ = writeln!(
        html,
        "<details{}><summary>Every figure of the answer ({} values)</summary>",
        if is_cylindrical_simulate { "" } else { " open" },
        figures.len()
    );
    html.push_str("<table class=\"figures\">\n");
    for (key, value) in &figures {
        let _ = writeln!(
            html,
            "<tr><th><code>{}</code></th><td>{}</td></tr>",
            escape(key),
            escape(&value_text(key, value))
        );
    }
    html.push_str("</table>\n</details>\n</section>\n");
    html
}

fn value_text(key: &str, value: &Value) -> String {
    match value {
        Value::Number(n) => n.as_f64().map_or(n.to_string(), |v| display(key, v)),
        Value::String(s) => s.clone(),
        Value::Null => "—".into(),
        other => other.to_string(),
    }
}

fn seed_table(summary: &Value) -> String {
    let mut html = String::from("<table class=\"figures seed\">\n");
    for (group, rows) in SEED_TABLE {
        let _ = writeln!(
            html,
            "<tr class=\"group\"><th colspan=\"2\">{group}</th></tr>"
        );
        for (key, label) in rows {
            let value = summary.get(key).unwrap_or(&Value::Null);
            let _ = writeln!(
                html,
                "<tr><th>{}</th><td>{}</td></tr>",
                escape(label.trim_start()),
                escape(&value_text(key, value))
            );
        }
    }
    html.push_str("</table>\n");
    html
}

/// A table sortable by its headers; numbers shown to four significant digits, sorted by value.
fn sortable_table(
    id: &str,
    table: &Table,
    first_column_link: Option<&dyn Fn(usize) -> String>,
) -> String {
    let mut html =
        format!("<div class=\"scroll\"><table id=\"{id}\" class=\"sortable\">\n<thead><tr>");
    for name in &table.header {
        let _ = write!(html, "<th title=\"sort by {0}\">{0}</th>", escape(name));
    }
    html.push_str("</tr></thead>\n<tbody>\n");
    for (i, row) in table.rows.iter().enumerate() {
        html.push_str("<tr>");
        for (column, field) in row.iter().enumerate() {
            let shown = match field.parse::<f64>() {
                Ok(v) => significant(v),
                Err(_) => field.clone(),
            };
            let content = match (column, first_column_link) {
                (0, Some(anchor)) => format!("<a href=\"#{}\">{}</a>", anchor(i), escape(&shown)),
                _ => escape(&shown),
            };
            let _ = write!(html, "<td data-sort=\"{}\">{content}</td>", escape(field));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody>\n</table></div>\n");
    html
}

fn variant_anchor(index: usize) -> String {
    format!("variant-{index}")
}

fn variants_section(table: &Table, variants: &[crate::folder::Variant]) -> String {
    let mut html = String::from(
        "<section id=\"variants\">\n<h2>Variants</h2>\n<p>Click a column header to sort; click a variant for its section. \
         Figures in SI units as in the column names.</p>\n",
    );
    html.push_str(&sortable_table(
        "variants-table",
        table,
        Some(&variant_anchor),
    ));
    for (i, variant) in variants.iter().enumerate() {
        let _ = writeln!(
            html,
            "<section id=\"{}\" class=\"variant\">\n<h3>Variant {}</h3>",
            variant_anchor(i),
            escape(&variant.name)
        );
        if let Some(error) = table.field(&variant.row, "error").filter(|e| !e.is_empty()) {
            let _ = writeln!(html, "<p class=\"error\">Failed: {}</p>", escape(error));
        }
        html.push_str("<table class=\"figures\">\n");
        for (key, field) in table.header.iter().zip(&variant.row) {
            if field.is_empty() || key == "error" || key == "variant" {
                continue;
            }
            let shown = field
                .parse::<f64>()
                .map_or(field.clone(), |v| display(key, v));
            let _ = writeln!(
                html,
                "<tr><th><code>{}</code></th><td>{}</td></tr>",
                escape(key),
                escape(&shown)
            );
        }
        html.push_str("</table>\n");
        html.push_str(&plot_grid(&variant.plots));
        html.push_str("<p><a href=\"#variants\">back to the variants</a></p>\n</section>\n");
    }
    html.push_str("</section>\n");
    html
}

fn figure(plot: &Plot) -> String {
    format!(
        "<figure>\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
        plot.svg,
        escape(&plot.name)
    )
}

/// The plots side by side, as many per row as the page is wide (each scaled to its column).
fn plot_grid(plots: &[Plot]) -> String {
    let figures: String = plots.iter().map(figure).collect();
    format!("<div class=\"plots\">\n{figures}</div>\n")
}

fn plots_section(id: &str, title: &str, plots: &[Plot]) -> String {
    let mut html = format!("<section id=\"{id}\">\n<h2>{title}</h2>\n");
    if plots.is_empty() {
        html.push_str("<p>No plots in this folder.</p>\n");
    }
    html.push_str(&plot_grid(plots));
    html.push_str("</section>\n");
    html
}

fn tables_section(folder: &OutputFolder) -> String {
    let mut html = String::from("<section id=\"tables\">\n<h2>Tables</h2>\n");
    if folder.csv_files.is_empty() {
        html.push_str("<p>No CSV tables in this folder.</p>\n");
    }
    for (i, file) in folder.csv_files.iter().enumerate() {
        match &file.content {
            CsvContent::Table(table) => {
                let _ = writeln!(
                    html,
                    "<details><summary><code>{}</code> ({} rows)</summary>",
                    escape(&file.name),
                    table.rows.len()
                );
                html.push_str(&sortable_table(&format!("table-{i}"), table, None));
                html.push_str("</details>\n");
            }
            CsvContent::TooLarge { bytes } => {
                let _ = writeln!(
                    html,
                    "<p><code>{}</code>: {:.1} MB, not shown (a time series: open it with pandas, polars or a spreadsheet; the Parquet file beside it has the same columns)</p>",
                    escape(&file.name),
                    *bytes as f64 / 1e6
                );
            }
        }
    }
    html.push_str("</section>\n");
    html
}
