//! SPEC V-06 with the dynamics through the `rolldyn simulate` set-up; prints one line per point.
//!
//! `cargo run --release -p rolldyn-validation --example obrien_taylor_dynamic -- [slices]
//! [speeds,…] [loads,…] [misalignments in arcmin,…]` (defaults: 5 slices, 1500 and 4000 rpm,
//! 104, 201, 450, 687 N, no misalignment series).

use rolldyn_validation::obrien_taylor::{StudySettings, dynamic_point};

fn list(s: Option<&String>) -> Option<Vec<f64>> {
    s.map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
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
    let mut points: Vec<(f64, f64, f64)> = Vec::new();
    for &n in &speeds {
        for &f in &loads {
            points.push((n, f, 0.0));
        }
    }
    for &m in &misalignments {
        points.push((4000.0, 201.0, (m / 60.0_f64).to_radians()));
    }
    println!("rpm\tload_N\tmis_arcmin\tT_C\tcage_slip_%\trevs\tsteady\twall_s");
    for (n, f, m) in points {
        match dynamic_point(&model, n, f, m, &settings) {
            Ok(p) => println!(
                "{n}\t{f}\t{:.1}\t{:.1}\t{:.4}\t{}\t{}\t{:.1}",
                m.to_degrees() * 60.0,
                p.temperature_k - 273.15,
                100.0 * p.slip.cage_slip,
                p.slip.revolutions_averaged,
                p.slip.steady,
                p.wall_s
            ),
            Err(e) => println!("{n}\t{f}\t{m}\terror: {e}"),
        }
    }
}
