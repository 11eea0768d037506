//! SPEC V-06 with the dynamics through the `rolldyn simulate` set-up; prints one line per point
//! and, with an output folder, writes `v06-dynamic.csv`, `v06-dynamic-load.svg` (cage slip
//! against radial load, one curve per speed) and `v06-dynamic-misalignment.svg` (against
//! misalignment at 4000 rpm, 201 N). Points are independent and run in parallel (rayon); each
//! point is deterministic, so the results do not depend on the thread count.
//!
//! `cargo run --release -p rolldyn-validation --example obrien_taylor_dynamic -- [slices]
//! [speeds,…] [loads,…] [misalignments in arcmin,…] [output folder]` (defaults: 5 slices, 1500
//! and 4000 rpm, 104, 201, 450, 687 N, no misalignment series, no files).

use rayon::prelude::*;
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_validation::obrien_taylor::{DynamicPoint, StudySettings, dynamic_point};
use std::path::Path;

fn list(s: Option<&String>) -> Option<Vec<f64>> {
    s.map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
}

fn arcmin(rad: f64) -> f64 {
    rad.to_degrees() * 60.0
}

fn write_outputs(dir: &Path, points: &[DynamicPoint]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut csv = String::from(
        "inner_speed_rpm,radial_load_n,misalignment_arcmin,oil_temperature_c,cage_slip,revolutions_averaged,steady,wall_s\n",
    );
    for p in points {
        csv.push_str(&format!(
            "{},{},{},{},{},{},{},{:.1}\n",
            p.speed_rpm,
            p.radial_load_n,
            arcmin(p.misalignment_rad),
            p.temperature_k - 273.15,
            p.slip.cage_slip,
            p.slip.revolutions_averaged,
            p.slip.steady,
            p.wall_s
        ));
    }
    let csv_path = dir.join("v06-dynamic.csv");
    std::fs::write(&csv_path, csv).map_err(|e| format!("{}: {e}", csv_path.display()))?;
    let mut speeds: Vec<f64> = points.iter().map(|p| p.speed_rpm).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let by_load: Vec<(String, Vec<(f64, f64)>)> = speeds
        .iter()
        .map(|&n| {
            let curve = points
                .iter()
                .filter(|p| p.speed_rpm == n && p.misalignment_rad == 0.0)
                .map(|p| (p.radial_load_n, 100.0 * p.slip.cage_slip))
                .collect();
            (format!("{n:.0} rpm"), curve)
        })
        .filter(|(_, c): &(String, Vec<(f64, f64)>)| c.len() > 1)
        .collect();
    let misaligned: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.speed_rpm == 4000.0 && p.radial_load_n == 201.0)
        .map(|p| (arcmin(p.misalignment_rad), 100.0 * p.slip.cage_slip))
        .collect();
    let plot = |stem: &str, labels: Labels, curves: &[(String, Vec<(f64, f64)>)]| {
        line_plot(&dir.join(stem), &labels, &Series::from_pairs(curves)).map_err(|e| e.to_string())
    };
    plot(
        "v06-dynamic-load.svg",
        Labels {
            title: "O'Brien–Taylor bearing, dynamics: cage slip vs radial load",
            x: "radial load, N",
            y: "cage slip, %",
        },
        &by_load,
    )?;
    if misaligned.len() > 1 {
        let mut misaligned = misaligned;
        misaligned.sort_by(|a, b| a.0.total_cmp(&b.0));
        plot(
            "v06-dynamic-misalignment.svg",
            Labels {
                title: "O'Brien–Taylor bearing, dynamics: cage slip vs misalignment (4000 rpm, 201 N)",
                x: "misalignment, arcmin",
                y: "cage slip, %",
            },
            &[("4000 rpm, 201 N".to_string(), misaligned)],
        )?;
    }
    Ok(())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/obrien-taylor.toml"
    );
    let model = match rolldyn_model::load(std::path::Path::new(path)) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let settings = StudySettings {
        slices: Some(args.get(1).and_then(|s| s.parse().ok()).unwrap_or(5)),
        ..StudySettings::default()
    };
    let speeds = list(args.get(2)).unwrap_or(vec![1500.0, 4000.0]);
    let loads = list(args.get(3)).unwrap_or(vec![104.0, 201.0, 450.0, 687.0]);
    let misalignments = list(args.get(4)).unwrap_or_default();
    let mut cases: Vec<(f64, f64, f64)> = Vec::new();
    for &n in &speeds {
        for &f in &loads {
            cases.push((n, f, 0.0));
        }
    }
    for &m in &misalignments {
        let case = (4000.0, 201.0, (m / 60.0_f64).to_radians());
        if !cases.contains(&case) {
            cases.push(case);
        }
    }
    let results: Vec<Result<DynamicPoint, String>> = cases
        .par_iter()
        .map(|&(n, f, m)| dynamic_point(&model, n, f, m, &settings))
        .collect();
    println!("rpm\tload_N\tmis_arcmin\tT_C\tcage_slip_%\trevs\tsteady\twall_s");
    let mut points = Vec::new();
    for ((n, f, m), r) in cases.iter().zip(results) {
        match r {
            Ok(p) => {
                println!(
                    "{n}\t{f}\t{:.1}\t{:.1}\t{:.4}\t{}\t{}\t{:.1}",
                    arcmin(*m),
                    p.temperature_k - 273.15,
                    100.0 * p.slip.cage_slip,
                    p.slip.revolutions_averaged,
                    p.slip.steady,
                    p.wall_s
                );
                points.push(p);
            }
            Err(e) => println!("{n}\t{f}\t{:.1}\terror: {e}", arcmin(*m)),
        }
    }
    if let Some(dir) = args.get(5)
        && let Err(e) = write_outputs(Path::new(dir), &points)
    {
        eprintln!("{e}");
        std::process::exit(1);
    }
}
