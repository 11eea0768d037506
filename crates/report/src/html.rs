//! The report page: one HTML file with its style, plots (inline SVG) and table-sorting script.

use crate::folder::{CsvContent, OutputFolder, Plot, Table};
use crate::quantities::{display, significant};
use crate::warnings::{Level, Warnings, flattened};
use crate::{
    CAGE_LAND_TO_ROLLER_FORCE_RATIO, RunKind, SCUFFING_CAUTION_MARGIN, SCUFFING_PREDICTED_MARGIN,
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
            (
                "cage_slip_mean",
                "cage slip (mean), fraction 1 − ω_c/ω_epicyclic",
            ),
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
    html.push_str(&headline_section(folder));
    html.push_str(&warnings_section(warnings));
    html.push_str(&summary_section(folder));
    if let Some((table, variants)) = &folder.sweep {
        html.push_str(&variants_section(
            &ordered(table, &varied_columns(folder)),
            variants,
        ));
    }
    html.push_str(&plots_section("plots", "Plots", &folder.plots));
    html.push_str(&inputs_section(folder));
    html.push_str(&tables_section(folder));
    let _ = write!(html, "<script>\n{SORT_SCRIPT}</script>\n</body>\n</html>\n");
    html
}

fn navigation(folder: &OutputFolder) -> String {
    let mut links = vec![
        ("headline", "Results"),
        ("warnings", "Findings"),
        ("summary", "Summary"),
    ];
    if folder.sweep.is_some() {
        links.push(("variants", "Variants"));
    }
    links.extend([
        ("plots", "Plots"),
        ("inputs", "Inputs"),
        ("tables", "Tables"),
    ]);
    let items: Vec<String> = links
        .iter()
        .map(|(id, label)| format!("<a href=\"#{id}\">{label}</a>"))
        .collect();
    format!("<nav>{}</nav>\n", items.join(" · "))
}

/// The figures that answer a run of each kind, in this order, where the answer has them.
const HEADLINES: [(RunKind, &[(&str, &str)]); 4] = [
    (
        RunKind::Simulate,
        &[
            ("cage_slip_mean", "cage slip (mean), fraction"),
            ("cage_speed_mean_rad_s", "cage speed (mean)"),
            ("epicyclic_cage_speed_rad_s", "epicyclic cage speed"),
            (
                "max_inner_contact_force_n",
                "largest roller – inner raceway force",
            ),
            ("max_roller_cage_force_n", "largest roller – cage force"),
            ("max_cage_land_force_n", "largest cage – land force"),
            ("min_scuffing_margin", "scuffing margin s_cr/s (min)"),
            ("whirl_ratio", "whirl ratio"),
        ],
    ),
    (
        RunKind::Wear,
        &[
            ("life_h", "operating time worn"),
            ("stop", "stopped by"),
            ("clearance_increase_m", "radial clearance increase"),
            (
                "max_depth_m.inner_raceway",
                "largest wear depth, inner raceway",
            ),
            (
                "max_depth_m.outer_raceway",
                "largest wear depth, outer raceway",
            ),
            ("max_depth_m.roller", "largest wear depth, roller"),
            ("max_depth_m.cage_bar", "largest wear depth, cage bar"),
        ],
    ),
    (
        RunKind::Fatigue,
        &[
            ("life_hours", "cage life"),
            ("endurance_margin", "endurance margin"),
            ("max_stress_pa", "largest fillet stress"),
            ("critical_location", "critical fillet"),
            (
                "extrapolated_life_revolutions",
                "extrapolated life, revolutions",
            ),
            ("cage_speed_rpm", "cage speed"),
        ],
    ),
    (RunKind::Sweep, &[("varied", "varied")]),
];

/// The headline: the few figures that answer the run, before anything else.
fn headline_section(folder: &OutputFolder) -> String {
    let mut html = String::from("<section id=\"headline\">\n<h2>Results</h2>\n");
    let Some(m) = &folder.manifest else {
        html.push_str("<p>No run summary (no <code>run.json</code>); see the plots and tables below.</p>\n</section>\n");
        return html;
    };
    let figures = flattened(&m.summary);
    let keys = HEADLINES
        .iter()
        .find(|(kind, _)| *kind == folder.kind)
        .map_or(&[][..], |(_, keys)| *keys);
    let mut cards = String::new();
    for (key, label) in keys {
        let value = match m.summary.pointer(&format!("/{}", key.replace('.', "/"))) {
            Some(Value::Array(items)) => Value::from(
                items
                    .iter()
                    .map(|v| v.as_str().map_or(v.to_string(), String::from))
                    .collect::<Vec<_>>()
                    .join(", "),
            ),
            Some(v) => v.clone(),
            None => continue,
        };
        let text = match (&value, m.summary.get("damage_per_revolution")) {
            (Value::Null, Some(d)) if key.starts_with("life_") && d.as_f64() == Some(0.0) => {
                "∞ (no damaging cycle)".to_string()
            }
            (Value::Null, _) => match m
                .summary
                .get("non_finite")
                .and_then(|n| n.get(*key))
                .and_then(Value::as_str)
            {
                Some(reason) => format!("— ({reason})"),
                None => "—".into(),
            },
            _ => value_text(key, &value),
        };
        let _ = writeln!(
            cards,
            "<div class=\"figure-card\"><div class=\"value\">{}</div><div class=\"label\">{}</div></div>",
            escape(&text),
            escape(label)
        );
    }
    if let Some((table, _)) = &folder.sweep {
        let failed = table
            .rows
            .iter()
            .filter(|r| table.field(r, "error").is_some_and(|e| !e.is_empty()))
            .count();
        let _ = writeln!(
            cards,
            "<div class=\"figure-card\"><div class=\"value\">{}</div><div class=\"label\">variants ({failed} failed)</div></div>",
            table.rows.len()
        );
    }
    if cards.is_empty() {
        for (key, value) in figures.iter().filter(|(_, v)| v.is_number()).take(6) {
            let _ = writeln!(
                cards,
                "<div class=\"figure-card\"><div class=\"value\">{}</div><div class=\"label\"><code>{}</code></div></div>",
                escape(&value_text(key, value)),
                escape(key)
            );
        }
    }
    let _ = write!(
        html,
        "<div class=\"headline\">\n{cards}</div>\n</section>\n"
    );
    html
}

/// The findings: errors (red) and warnings (amber) open, notes (grey) folded; a run with
/// neither shows one green line.
fn warnings_section(warnings: &Warnings) -> String {
    let mut html = String::from("<section id=\"warnings\">\n<h2>Findings</h2>\n");
    if warnings.serious().next().is_none() {
        html.push_str(
            "<p class=\"all-clear\">No error or warning: no scuffing, no cage pressed on its land, every point converged, every figure finite.</p>\n",
        );
    }
    for (level, title, open) in [
        (Level::Error, "Errors", true),
        (Level::Warning, "Warnings", true),
        (Level::Note, "Notes", false),
    ] {
        let alerts: Vec<_> = warnings.at(level).collect();
        if alerts.is_empty() {
            continue;
        }
        let _ = writeln!(
            html,
            "<details class=\"finding {}\"{}><summary>{title} ({})</summary>\n<ul>",
            level.name(),
            if open { " open" } else { "" },
            alerts.len()
        );
        for alert in alerts {
            let _ = writeln!(html, "<li>{}</li>", escape(&alert.to_string()));
        }
        html.push_str("</ul>\n</details>\n");
    }
    let _ = writeln!(
        html,
        "<p class=\"thresholds\">Thresholds: scuffing predicted (error) when the minimum scuffing margin s_cr/s is below \
         {SCUFFING_PREDICTED_MARGIN} (slip past the critical slip), a warning below {SCUFFING_CAUTION_MARGIN}; \
         a land-guided cage on its land is a note, a warning when the cage–land force exceeds \
         {CAGE_LAND_TO_ROLLER_FORCE_RATIO} × the largest roller–cage force \
         (docs/outputs.md, \"Run manifest and HTML report\").</p>\n</section>"
    );
    html
}

/// The varied parameters of a sweep: the `varied` list of its answer, else none.
fn varied_columns(folder: &OutputFolder) -> Vec<String> {
    folder
        .manifest
        .as_ref()
        .and_then(|m| m.summary.get("varied"))
        .and_then(Value::as_array)
        .map(|items| {
            items
                .iter()
                .filter_map(|v| v.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default()
}

/// `table` with the `variant` column first, the `varied` columns next, then the others.
fn ordered(table: &Table, varied: &[String]) -> Table {
    let rank = |name: &str| match name {
        "variant" => 0,
        n if varied.iter().any(|v| v == n) => 1,
        _ => 2,
    };
    let mut order: Vec<usize> = (0..table.header.len()).collect();
    order.sort_by_key(|&k| rank(&table.header[k]));
    let pick = |row: &[String]| -> Vec<String> {
        order
            .iter()
            .map(|&k| row.get(k).cloned().unwrap_or_default())
            .collect()
    };
    Table {
        header: pick(&table.header),
        rows: table.rows.iter().map(|r| pick(r)).collect(),
        varied: table
            .header
            .iter()
            .filter(|h| varied.contains(h))
            .cloned()
            .collect(),
    }
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
    let reasons: Vec<(String, String)> = figures
        .iter()
        .filter_map(|(key, value)| {
            let figure = key
                .strip_prefix("non_finite.")
                .map(String::from)
                .or_else(|| {
                    key.find(".non_finite.")
                        .map(|at| format!("{}.{}", &key[..at], &key[at + 12..]))
                })?;
            Some((figure, value.as_str().unwrap_or_default().to_string()))
        })
        .collect();
    for (key, value) in figures.iter().filter(|(k, _)| !k.contains("non_finite")) {
        let mut text = value_text(key, value);
        if let Some((_, reason)) = reasons.iter().find(|(figure, _)| figure == key) {
            text = format!("{text} ({reason})");
        }
        let _ = writeln!(
            html,
            "<tr><th><code>{}</code></th><td>{}</td></tr>",
            escape(key),
            escape(&text)
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
            let mut text = value_text(key, value);
            if let Some(reason) = summary
                .get("non_finite")
                .and_then(|n| n.get(key))
                .and_then(Value::as_str)
            {
                text = format!("{text} ({reason})");
            }
            let _ = writeln!(
                html,
                "<tr><th>{}</th><td>{}</td></tr>",
                escape(label.trim_start()),
                escape(&text)
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
        let class = match table.varied.contains(name) {
            true => " class=\"varied\"",
            false => "",
        };
        let _ = write!(
            html,
            "<th{class} title=\"sort by {0}\">{0}</th>",
            escape(name)
        );
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
         Figures in SI units as in the column names; the varied parameters come first, marked.</p>\n",
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
        if let Some(error) = table
            .field(&table.rows[i], "error")
            .filter(|e| !e.is_empty())
        {
            let _ = writeln!(html, "<p class=\"error\">Failed: {}</p>", escape(error));
        }
        html.push_str("<table class=\"figures\">\n");
        for (key, field) in table.header.iter().zip(&table.rows[i]) {
            if field.is_empty() || key == "error" || key == "variant" {
                continue;
            }
            let shown = field
                .parse::<f64>()
                .map_or(field.clone(), |v| display(key, v));
            let class = match table.varied.contains(key) {
                true => " class=\"varied\"",
                false => "",
            };
            let _ = writeln!(
                html,
                "<tr{class}><th><code>{}</code></th><td>{}</td></tr>",
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
