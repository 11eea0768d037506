//! Issue 25: `rolldyn simulate --cage-loads`, `rolldyn fatigue` on the embedded model and on a
//! load export, with its report files and JSON fields.

#[allow(dead_code)] // example(): these tests use the embedded model
mod common;

use common::{json, rolldyn};

#[test]
fn a_load_export_round_trips_through_fatigue() {
    let dir = std::env::temp_dir().join(format!("rolldyn-fatigue-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let loads = dir.join("loads.parquet");
    let loads_arg = loads.display().to_string();
    let sim = rolldyn(&[
        "simulate",
        "--duration",
        "2rev",
        "--cage-loads",
        &loads_arg,
        "--json",
        "--quiet",
    ]);
    json(&sim);
    assert!(dir.join("loads.json").exists());
    let out_dir = dir.join("report");
    let out_arg = out_dir.display().to_string();
    let answer = json(&rolldyn(&[
        "fatigue", "--loads", &loads_arg, "--out", &out_arg, "--json",
    ]));
    assert_eq!(answer["load_sets"], 180);
    assert_eq!(answer["stress_model"], "frame");
    for key in [
        "damage_per_revolution",
        "max_stress_pa",
        "critical_location",
        "wall_time_s",
        "extrapolated_life_revolutions",
    ] {
        assert!(!answer[key].is_null(), "{key}: {answer}");
    }
    // unlimited life is null in JSON, a finite one a number
    assert!(answer["life_revolutions"].is_null() || answer["life_revolutions"].is_number());
    for file in [
        "cage-loads.parquet",
        "critical-history.csv",
        "damage-map.csv",
        "rainflow-matrix.svg",
        "sn-diagram.svg",
        "fillet-stress-map.svg",
    ] {
        assert!(out_dir.join(file).exists(), "{file}");
    }
}

#[test]
fn fatigue_runs_the_dynamics_of_the_embedded_model_with_an_inclusion() {
    let answer = json(&rolldyn(&[
        "fatigue",
        "--revolutions",
        "1",
        "--inclusion",
        "--json",
    ]));
    assert_eq!(answer["load_sets"], 180);
    assert!(answer["inclusion_max_stress_pa"].as_f64().unwrap() > 0.0);
    assert!(answer["max_cage_land_force_n"].is_null());
    assert!(answer["maxima"]["max_cage_land_force_n"].as_f64().unwrap() >= 0.0);
}

#[test]
fn a_missing_load_export_exits_2() {
    let out = rolldyn(&["fatigue", "--loads", "/nonexistent/loads.parquet"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("/nonexistent/loads.json"), "{stderr}");
}

/// The done-when with the solid model: the embedded model's cage by gmsh + CalculiX
/// (about two minutes once; the unit cases are then cached) from a short run's load export.
#[test]
fn fatigue_by_the_calculix_solid_model() {
    let dir = std::env::temp_dir().join(format!("rolldyn-fatigue-ccx-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cache = dir.join("cache").display().to_string();
    let answer = json(&rolldyn(&[
        "fatigue",
        "--revolutions",
        "1",
        "--stress",
        "calculix",
        "--mesh-size",
        "16mm",
        "--fillet-mesh-size",
        "1.2mm",
        "--cache",
        &cache,
        "--json",
    ]));
    assert_eq!(answer["stress_model"], "calculix");
    assert_eq!(answer["solid_mesh"]["mesh_size_m"], 0.016);
    assert_eq!(answer["solid_mesh"]["fillet_mesh_size_m"], 0.0012);
    assert_eq!(answer["load_sets"], 180);
    assert!(answer["max_stress_pa"].as_f64().unwrap() > 0.0);
    assert!(std::fs::read_dir(&cache).unwrap().count() > 0);
}

#[test]
fn solid_mesh_sizes_are_checked_before_the_run() {
    let refused = [
        (
            &["--mesh-size", "6mm"][..],
            "--mesh-size: element sizes belong to the solid model",
        ),
        (
            &["--stress", "calculix", "--fillet-mesh-size", "0.01mm"][..],
            "--fillet-mesh-size 0.01 mm: at least 0.05 mm",
        ),
        (
            &[
                "--stress",
                "calculix",
                "--mesh-size",
                "2mm",
                "--fillet-mesh-size",
                "3mm",
            ][..],
            "--fillet-mesh-size 3 mm is larger than --mesh-size 2 mm",
        ),
    ];
    for (flags, reason) in refused {
        let out = rolldyn(&[&["fatigue", "--revolutions", "1"][..], flags].concat());
        assert_eq!(out.status.code(), Some(2), "{flags:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(reason), "{flags:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
}

#[test]
fn a_bad_sn_curve_file_exits_2_naming_the_line() {
    let dir = std::env::temp_dir().join(format!("rolldyn-fatigue-sn-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("sn.csv");
    std::fs::write(&path, "N,sigma_a_MPa\n1e3,600\n1e6,two hundred\n").unwrap();
    let file = path.display().to_string();
    let out = rolldyn(&["fatigue", "--revolutions", "1", "--sn-curve", &file]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains(&format!("{file}: line 3")), "{stderr}");
}

#[test]
fn fatigue_rainflow_counts_a_history_larger_than_the_input_file_cap() {
    // 20 periods of a sine, 32 000 samples each, 17 bytes a line: 10.9 MB, over the 8 MiB cap
    // of model files, which a history does not have
    let dir = std::env::temp_dir().join(format!("rolldyn-rainflow-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("history.csv");
    let n = 640_000;
    let text: String = (0..n)
        .map(|i| {
            let phase = std::f64::consts::TAU * (i % 32_000) as f64 / 32_000.0;
            format!("{:.9e}\n", phase.sin())
        })
        .collect();
    assert!(text.len() > 8 << 20);
    std::fs::write(&path, &text).unwrap();
    let answer = json(&rolldyn(&[
        "fatigue",
        "rainflow",
        &path.display().to_string(),
        "--json",
    ]));
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(answer["values"], n);
    let cycles = answer["cycles"].as_array().unwrap();
    let full_swings = cycles
        .iter()
        .filter(|c| c["range"].as_f64() == Some(2.0) && c["count"].as_f64() == Some(1.0))
        .count();
    // every period but the first closes one swing −1 ↔ 1; the first one's stays in the residue
    assert_eq!(full_swings, 19, "{cycles:?}");
}
