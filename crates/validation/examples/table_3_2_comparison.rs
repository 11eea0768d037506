//! Seed 000 Table 3.2 against a rolldyn sweep of its Table 3.1 variants (validation case V-07):
//! one SVG per column (seed and rolldyn per variant) and the Markdown table of VALIDATION.md.
//!
//! Run: `cargo run --release -p rolldyn-validation --example table_3_2_comparison -- SUMMARY.csv OUT_DIR`
//! with the `summary.csv` of `rolldyn sweep examples/2002834/table-3.1.toml`.

use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_validation::table_3_2::{COMPARED_COLUMNS, SEED_TABLE_3_2, read_summary};
use std::path::PathBuf;

/// A value in the table's precision (three significant digits, "—" if absent).
fn cell(v: f64) -> String {
    if !v.is_finite() {
        "—".into()
    } else if v == 0.0 {
        "0".into()
    } else {
        let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    }
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().collect();
    let (summary, out) = match &args[1..] {
        [s, o] => (PathBuf::from(s), PathBuf::from(o)),
        _ => return Err("usage: table_3_2_comparison SUMMARY.csv OUT_DIR".into()),
    };
    let rolldyn = read_summary(&summary)?;
    std::fs::create_dir_all(&out).map_err(|e| e.to_string())?;
    let value = |variant: &str, column: &str| {
        rolldyn
            .get(variant)
            .and_then(|r| r.get(column))
            .copied()
            .unwrap_or(f64::NAN)
    };
    for c in &COMPARED_COLUMNS {
        let points = |f: &dyn Fn(usize, &str) -> f64| -> Vec<(f64, f64)> {
            SEED_TABLE_3_2
                .iter()
                .enumerate()
                .map(|(i, r)| (i as f64 + 1.0, f(i, r.variant)))
                .filter(|p| p.1.is_finite())
                .collect()
        };
        let seed = points(&|i, _| (c.seed)(&SEED_TABLE_3_2[i]));
        let ours = points(&|_, v| value(v, c.rolldyn_column));
        line_plot(
            &out.join(format!("{}.svg", c.file_stem)),
            &Labels {
                title: &format!("Seed 000 Table 3.2 vs rolldyn: {}", c.title),
                x: "Table 3.1 variant (1 = No. 6 … 21 = No. 75)",
                y: c.title,
            },
            &[
                Series {
                    label: "seed 000",
                    points: &seed,
                },
                Series {
                    label: "rolldyn",
                    points: &ours,
                },
            ],
        )
        .map_err(|e| e.to_string())?;
    }
    let titles: Vec<&str> = COMPARED_COLUMNS.iter().map(|c| c.title).collect();
    println!(
        "| No. | {} | rolldyn cage orbit radius µm | rolldyn cage slip % |",
        titles.join(" | ")
    );
    println!("|{}", "---|".repeat(titles.len() + 3));
    for r in &SEED_TABLE_3_2 {
        let cells: Vec<String> = COMPARED_COLUMNS
            .iter()
            .map(|c| {
                format!(
                    "{} / {}",
                    cell((c.seed)(r)),
                    cell(value(r.variant, c.rolldyn_column))
                )
            })
            .collect();
        println!(
            "| {} | {} | {} | {} |",
            r.variant,
            cells.join(" | "),
            cell(value(r.variant, "cage_orbit_radius_m") * 1e6),
            cell(value(r.variant, "cage_slip_mean") * 100.0),
        );
    }
    Ok(())
}
