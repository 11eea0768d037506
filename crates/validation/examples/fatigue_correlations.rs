//! Cage-fatigue trends against seed 000 §3.1.1.8 (VALIDATION.md "Cage fatigue", V-27 and V-28)
//! from the summaries of the two fatigue sweeps:
//!
//! * V-27: over Table 3.1's bearings at 11′, the correlation of lg(life) with the revolution's
//!   largest cage–land, roller–cage and roller–raceway forces (seed −0.94, −0.46, −0.32), over
//!   all variants and over the distinct bearings (variants that differ only in misalignment in
//!   Table 3.1 coincide at 11′);
//! * V-28: lg(life) against misalignment for the base bearing and variant 19's.
//!
//! The life is `extrapolated_life_revolutions` (the S–N slope continued below the knee): with the
//! knee every variant's life is unlimited.
//!
//! Run: `rolldyn sweep examples/2002834/fatigue-variants.toml --out V27` and
//! `rolldyn sweep examples/2002834/fatigue-misalignment.toml --out V28`, then
//! `cargo run --release -p rolldyn-validation --example fatigue_correlations -- V27 V28 OUT_DIR`.

use rolldyn_numerics::statistics::pearson;
use rolldyn_plot::{Labels, Series, line_plot, log_log_plot};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The rows of a sweep's `summary.csv`: variant name → column → value.
fn summary(dir: &Path) -> Result<BTreeMap<String, BTreeMap<String, f64>>, String> {
    let path = dir.join("summary.csv");
    let mut reader =
        csv::Reader::from_path(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let headers = reader.headers().map_err(|e| e.to_string())?.clone();
    let mut rows = BTreeMap::new();
    for record in reader.records() {
        let record = record.map_err(|e| e.to_string())?;
        let name = record.get(0).unwrap_or_default().to_string();
        let values = headers
            .iter()
            .zip(record.iter())
            .skip(1)
            .filter_map(|(h, v)| v.parse::<f64>().ok().map(|v| (h.to_string(), v)))
            .collect();
        rows.insert(name, values);
    }
    Ok(rows)
}

const LIFE: &str = "lg_extrapolated_life_revolutions";
const FORCES: [(&str, &str, f64); 3] = [
    ("max_cage_land_force_n", "cage–land", -0.94),
    ("max_roller_cage_force_n", "roller–cage", -0.46),
    ("max_roller_raceway_force_n", "roller–raceway", -0.32),
];

fn correlations(dir: &Path, out: &Path, report: &mut String) -> Result<(), String> {
    let rows = summary(dir)?;
    let mut distinct: Vec<&BTreeMap<String, f64>> = Vec::new();
    for row in rows.values() {
        let key = |r: &BTreeMap<String, f64>| FORCES.map(|(c, _, _)| r.get(c).copied());
        if !distinct.iter().any(|d| key(d) == key(row)) {
            distinct.push(row);
        }
    }
    let _ = writeln!(
        report,
        "V-27: {} variants ({} distinct bearings at 11′)\n| force | seed r | r (all) | r (distinct) |\n|---|---|---|---|",
        rows.len(),
        distinct.len()
    );
    for (column, label, seed) in FORCES {
        let pairs = |set: &[&BTreeMap<String, f64>]| -> (Vec<f64>, Vec<f64>) {
            set.iter()
                .filter_map(|r| Some((*r.get(column)?, *r.get(LIFE)?)))
                .unzip()
        };
        let all: Vec<&BTreeMap<String, f64>> = rows.values().collect();
        let (x, y) = pairs(&all);
        let (xd, yd) = pairs(&distinct);
        let _ = writeln!(
            report,
            "| {label} | {seed:+.2} | {:+.2} | {:+.2} |",
            pearson(&x, &y),
            pearson(&xd, &yd)
        );
        let points: Vec<(f64, f64)> = x
            .iter()
            .zip(&y)
            .map(|(&f, &l)| (f, 10f64.powf(l)))
            .collect();
        let title = format!("V-27: cage life against the largest {label} force (11′)");
        log_log_plot(
            &out.join(format!("v27-life-vs-{}.svg", column.trim_end_matches("_n"))),
            &Labels {
                title: &title,
                x: "force, N",
                y: "life (S–N slope continued below the knee), revolutions",
            },
            &[],
            &[Series {
                label: "Table 3.1 bearings at 11′",
                points: &points,
            }],
        )
        .map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn misalignment(dir: &Path, out: &Path, report: &mut String) -> Result<(), String> {
    let rows = summary(dir)?;
    let mut curves: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let _ = writeln!(
        report,
        "\nV-28: lg(life) against misalignment\n| bearing | misalignment ′ | lg life | largest stress MPa | cage–land N | roller–cage N |\n|---|---|---|---|---|---|"
    );
    for bearing in ["base", "19"] {
        let mut points = Vec::new();
        let mut runs: Vec<(f64, &BTreeMap<String, f64>)> = rows
            .iter()
            .filter_map(|(name, row)| {
                let arcmin = name
                    .strip_prefix(&format!("{bearing}-"))?
                    .strip_suffix("arcmin")?
                    .parse::<f64>()
                    .ok()?;
                Some((arcmin, row))
            })
            .collect();
        runs.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (arcmin, row) in runs {
            let get = |c: &str| row.get(c).copied().unwrap_or(f64::NAN);
            points.push((arcmin, get(LIFE)));
            let _ = writeln!(
                report,
                "| {bearing} | {arcmin} | {:.2} | {:.1} | {:.0} | {:.0} |",
                get(LIFE),
                get("max_stress_pa") * 1e-6,
                get("max_cage_land_force_n"),
                get("max_roller_cage_force_n")
            );
        }
        curves.push((format!("{bearing} bearing"), points));
    }
    line_plot(
        &out.join("v28-life-vs-misalignment.svg"),
        &Labels {
            title: "V-28: cage life against inner-ring misalignment",
            x: "misalignment, arcmin",
            y: "lg life (S–N slope continued below the knee)",
        },
        &Series::from_pairs(&curves),
    )
    .map_err(|e| e.to_string())
}

fn main() -> Result<(), String> {
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let [v27, v28, out] = args.as_slice() else {
        return Err("usage: fatigue_correlations V27_SWEEP_DIR V28_SWEEP_DIR OUT_DIR".into());
    };
    std::fs::create_dir_all(out).map_err(|e| e.to_string())?;
    let mut report = String::new();
    correlations(v27, out, &mut report)?;
    misalignment(v28, out, &mut report)?;
    print!("{report}");
    std::fs::write(out.join("fatigue-trends.md"), report).map_err(|e| e.to_string())
}
