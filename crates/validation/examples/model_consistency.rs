//! Issue 23 "one answer from both models": the one-at-a-time switch table of the quasi-static
//! model and the dynamics ([`rolldyn_validation::model_consistency`]) for O'Brien–Taylor at
//! 4000 rpm / 201 N (fixed load) and 2002834 at the operating point of its example (8163 rpm,
//! 1860 N rotating with the inner ring). Prints one line per row and writes the CSV.
//!
//! `cargo run --release -p rolldyn-validation --example model_consistency -- [cases]
//! [revolutions] [skipped] [csv]` (cases `ot`, `ot-tight-pocket`, `ot-preload`, `2002834`, each optionally `@<load N>`, e.g.
//! `2002834@7000`; defaults: `ot,2002834`, 10, 4,
//! `docs/validation/model-consistency.csv`). Rows run in parallel (rayon); each is
//! deterministic.

use rayon::prelude::*;
use rolldyn_geometry::BearingModel;
use rolldyn_setup::LoadDirection;
use rolldyn_validation::model_consistency::{
    CSV_HEADER, Case, RowResult, RunLength, csv_line, dynamic, quasi_static, rows,
};

const RPM: f64 = std::f64::consts::PI / 30.0;

fn load_model(path: &str) -> rolldyn_model::Model {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    rolldyn_model::parse(&text, path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// `ot`, `ot-tight-pocket`, `ot-preload`, `2002834`, or one of them with `@<load in N>` (e.g. `2002834@7000`).
fn case(spec: &str) -> Case {
    let (name, load) = spec.split_once('@').unwrap_or((spec, ""));
    let mut case = named_case(name);
    if let Ok(load) = load.parse::<f64>() {
        case.radial_load_n = load;
        case.name = format!("{name} at {load} N");
    }
    case
}

fn named_case(name: &str) -> Case {
    match name {
        "ot" => Case {
            name: "obrien-taylor 4000 rpm 201 N fixed".into(),
            model: load_model("examples/obrien-taylor.toml"),
            speed_rad_s: 4000.0 * RPM,
            radial_load_n: 201.0,
            load_direction: LoadDirection::Fixed,
            oil_temperature_k: None,
        },
        "ot-tight-pocket" => {
            // pocket play 0.05 mm instead of the model's 0.3 mm: how much of the dynamic slip
            // is the rollers running ahead of the cage through their play in the load zone
            let mut case = named_case("ot");
            if let BearingModel::Cylindrical(b) = &mut case.model.bearing
                && let Some(cage) = b.cage.as_mut()
            {
                cage.pocket.face_clearance = 0.05e-3;
            }
            case.name = "obrien-taylor pocket 15.05 mm".into();
            case
        }
        "ot-preload" => {
            // 20 µm radial preload: every roller loaded, no unloaded zone to re-enter
            let mut case = named_case("ot");
            if let BearingModel::Cylindrical(b) = &mut case.model.bearing {
                b.clearance.radial = -20e-6;
                b.clearance.allow_preload = true;
            }
            case.name = "obrien-taylor preload 20 um".into();
            case
        }
        "2002834" => {
            // the example's operating point (8163 rpm, its radial load, rotating)
            let model = load_model("examples/2002834.toml");
            let radial_load_n = model
                .operating
                .radial_load
                .expect("[operating] radial_load");
            Case {
                name: format!("2002834 8163 rpm {radial_load_n:.0} N rotating"),
                model,
                speed_rad_s: 8163.0 * RPM,
                radial_load_n,
                load_direction: LoadDirection::Rotating,
                oil_temperature_k: None,
            }
        }
        other => panic!("unknown case {other} (ot, ot-tight-pocket, ot-preload, 2002834)"),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let names = args.get(1).map_or("ot,2002834", String::as_str);
    let arg = |i: usize, default: u32| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(default);
    let length = RunLength {
        revolutions: arg(2, 10),
        skipped_revolutions: arg(3, 4),
        ..RunLength::default()
    };
    let csv_path = args
        .get(4)
        .map_or("docs/validation/model-consistency.csv", String::as_str);
    let cases: Vec<Case> = names.split(',').map(case).collect();
    let jobs: Vec<(usize, usize)> = (0..cases.len())
        .flat_map(|c| (0..rows().len()).map(move |r| (c, r)))
        .collect();
    let all_rows = rows();
    let results: Vec<(usize, RowResult)> = jobs
        .par_iter()
        .map(|&(c, r)| {
            let row = all_rows[r];
            let result = RowResult {
                row,
                quasi_static: quasi_static(&cases[c], &row.switches),
                dynamic: dynamic(&cases[c], &row.switches, &length),
            };
            eprintln!("{}", csv_line(&cases[c].name, &result));
            (c, result)
        })
        .collect();
    let mut csv = format!("{CSV_HEADER}\n");
    for (c, r) in &results {
        csv.push_str(&csv_line(&cases[*c].name, r));
        csv.push('\n');
    }
    std::fs::write(csv_path, &csv).unwrap_or_else(|e| panic!("{csv_path}: {e}"));
    println!("{csv}");
}
