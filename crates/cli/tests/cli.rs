//! End-to-end checks of the `rolldyn` binary: JSON answers and bad-input exit codes.

mod common;

use common::{example, json, rolldyn};

#[test]
fn contact_json_has_the_documented_fields() {
    for cells in ["350x9", "1000x30"] {
        let out = rolldyn(&[
            "contact",
            &example("contact/32206-crowned-3.2um.toml"),
            "--load",
            "1167N",
            "--cells",
            cells,
            "--json",
        ]);
        let v = json(&out);
        for key in [
            "approach_m",
            "max_pressure_pa",
            "mid_pressure_pa",
            "mean_pressure_pa",
            "concentration_factor",
            "contact_length_m",
            "max_half_width_m",
            "cells_in_contact",
            "iterations",
            "solve_time_s",
        ] {
            assert!(v[key].is_number(), "{cells}: {key} missing in {v}");
        }
        // SPEC F-08: ≈ 5.93 µm at 1167 N for these grids.
        let approach = v["approach_m"].as_f64().unwrap();
        assert!((approach / 5.93e-6 - 1.0).abs() < 0.01, "{approach}");
    }
}

#[test]
fn contact_methods_and_outputs() {
    let dir = std::env::temp_dir().join(format!("rolldyn-cli-test-{}", std::process::id()));
    for method in ["slices", "hertz", "boussinesq"] {
        let out = rolldyn(&[
            "contact",
            &example("2002834.toml"),
            "--load",
            "2kN",
            "--tilt",
            "4arcmin",
            "--method",
            method,
            "--json",
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert_eq!(json(&out)["method"], method);
    }
    for file in [
        "central_line.csv",
        "central_line.svg",
        "pressure_map.csv",
        "pressure_map.svg",
    ] {
        assert!(dir.join(file).is_file(), "{file}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn check_prints_derived_quantities() {
    let v = json(&rolldyn(&[
        "check",
        &example("2002834.toml"),
        "--speed",
        "6371rpm",
        "--json",
    ]));
    assert!((v["pitch_diameter_m"].as_f64().unwrap() - 0.18).abs() < 1e-12);
    let cage = v["epicyclic_cage_speed_rad_s"].as_f64().unwrap();
    // ω_i d_i/(d_i + D_o) on the rolling diameters 165 and 165 + 30 + 0.009 mm
    assert!((cage - 305.778).abs() < 0.001, "{cage}");
    // the pocket as built: lips on Ø192.5 mm 11.25 mm apart stop a centred roller after
    // w_L + r_t − √((R_w + r_t)² − (ρ_L + r_t − r_m)²) with ρ_L = √(96.25² − 5.625²) mm
    let p = &v["cage_pocket"];
    assert_eq!(p["circumferential_stop"], "outer lip");
    assert_eq!(p["fits"], true);
    let (w, rt, rw, rm) = (5.625e-3, 0.2e-3, 7.5e-3, 90e-3);
    let rho = (96.25e-3f64.powi(2) - w * w).sqrt();
    let hand = w + rt - ((rw + rt).powi(2) - (rho + rt - rm).powi(2)).sqrt();
    let play = p["circumferential_play_per_side_m"].as_f64().unwrap();
    assert!((play - hand).abs() < 1e-9, "{play} vs {hand}");
    assert!(p["bar_area_m2"].as_f64().unwrap() > 0.0);
    let text =
        String::from_utf8_lossy(&rolldyn(&["check", &example("2002834.toml")]).stdout).to_string();
    for line in [
        "cage pocket faces",
        "cage pocket outer lip",
        "roller play in its pocket",
        "pocket fit",
        "cage bar section",
    ] {
        assert!(text.contains(line), "{line}: {text}");
    }
}

#[test]
fn bad_model_exits_2_with_one_line_naming_file_line_key() {
    let dir = std::env::temp_dir().join(format!("rolldyn-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = std::fs::read_to_string(example("2002834.toml")).unwrap();
    let cases = [
        ("slices = 10", "slices = 10\nspeed = 1", "roller.speed"),
        (
            "diameter = \"15 mm\"",
            "diameter = \"15 N\"",
            "roller.diameter",
        ),
        ("count = 18", "count = 40", "roller.count"),
        ("length = \"11 mm\"", "length = nan", "roller.length"),
        (
            "pocket_axial = \"11.25 mm\"",
            "pocket_axial = \"-1 mm\"",
            "cage.pocket_axial",
        ),
        (
            "window = \"11.25 mm\"",
            "window = \"8 mm\"",
            "cage.pocket.outer_lip.window",
        ),
        (
            "face_clearance = \"4 mm\"",
            "face_clearance = \"-0.2 mm\"",
            "cage.pocket.face_clearance",
        ),
    ];
    for (k, (from, to, key)) in cases.iter().enumerate() {
        let path = dir.join(format!("bad{k}.toml"));
        std::fs::write(&path, good.replacen(from, to, 1)).unwrap();
        let out = rolldyn(&["check", path.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{key}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
        assert!(
            stderr.contains(&format!("bad{k}.toml:")) && stderr.contains(key),
            "{stderr}"
        );
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn missing_file_and_bad_flags_exit_2() {
    let out = rolldyn(&["check", "no/such/model.toml"]);
    assert_eq!(out.status.code(), Some(2));
    let out = rolldyn(&["contact", &example("2002834.toml"), "--load", "10mm"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("a force"));
    let out = rolldyn(&["contact", &example("2002834.toml"), "--load", "-5N"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn traction_json_reproduces_the_seed_critical_slip_range() {
    let v = json(&rolldyn(&[
        "traction",
        "--oil",
        "pao1-vg320",
        "--temperature",
        "40C",
        "--max-pressure",
        "1GPa",
        "--rolling-speed",
        "2.5m/s",
        "--json",
    ]));
    // Seed 000 §2.2: computed 0.16, measured 0.19 (SPEC V-12).
    let s = v["critical_slip"].as_f64().unwrap();
    assert!((0.14..=0.19).contains(&s), "{s}");
    assert!(v["max_traction"].is_number() && v["film_thickness_m"].is_number());
    let curve = v["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 101);
    assert_eq!(curve[0]["traction"].as_f64(), Some(0.0));
    assert!((curve[100]["slip"].as_f64().unwrap() - 0.5).abs() < 1e-12);
}

#[test]
fn traction_overlays_and_pressure_sweep_write_plots() {
    let dir = std::env::temp_dir().join(format!("rolldyn-traction-{}", std::process::id()));
    let out = rolldyn(&[
        "traction",
        "--temperatures",
        "40C,60C",
        "--max-pressures",
        "0.8GPa,1GPa,1.2GPa",
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(json(&out)["cases"].as_array().unwrap().len(), 6);
    for file in [
        "traction.csv",
        "traction.svg",
        "critical_slip_vs_pressure.svg",
    ] {
        assert!(dir.join(file).is_file(), "{file}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn film_json_fields() {
    let v = json(&rolldyn(&[
        "film",
        "--oil",
        "pao1-vg320",
        "--temperature",
        "60C",
        "--load",
        "500N",
        "--contact",
        "line",
        "--radius",
        "6.5mm",
        "--length",
        "10mm",
        "--rolling-speed",
        "10m/s",
        "--roughness",
        "0.32um,0.16um",
        "--json",
    ]));
    for key in [
        "central_film_m",
        "min_film_m",
        "lambda",
        "regime",
        "formula",
    ] {
        assert!(!v[key].is_null(), "{key} in {v}");
    }
}

#[test]
fn oils_list_and_bad_oil_input() {
    let v = json(&rolldyn(&["oils", "--temperature", "60C", "--json"]));
    assert!(v.as_array().unwrap().iter().any(|o| o["name"] == "nvi65"));
    let out = rolldyn(&["traction", "--oil", "castor-oil"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("pao1-vg320"),
        "known oils listed"
    );
    let out = rolldyn(&["traction", "--temperature", "150C", "--strict"]);
    assert_eq!(out.status.code(), Some(2));
    let out = rolldyn(&["traction", "--temperature", "150C", "--json"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("warning"));
    let zero = json(&rolldyn(&["traction", "--rolling-speed", "0m/s", "--json"]));
    assert!(zero["critical_slip"].is_null() && zero["no_maximum_reason"].is_string());
    assert!(
        zero["curve"]
            .as_array()
            .unwrap()
            .iter()
            .all(|p| p["traction"].is_number())
    );
}

#[test]
fn user_oil_file_is_listed_and_usable() {
    let file = example("oils/iso-vg68-mineral.toml");
    let v = json(&rolldyn(&[
        "oils",
        "--oil-file",
        &file,
        "--temperature",
        "40C",
        "--json",
    ]));
    let user = v
        .as_array()
        .unwrap()
        .iter()
        .find(|o| o["name"] == "iso-vg68-mineral")
        .unwrap();
    // Walther fit through the catalogue point 68 mm²/s at 40 °C.
    let nu = user["kinematic_viscosity_m2_s"].as_f64().unwrap();
    assert!((nu / 68e-6 - 1.0).abs() < 1e-3, "{nu}");
    let t = json(&rolldyn(&[
        "traction",
        "--oil-file",
        &file,
        "--temperature",
        "60C",
        "--json",
    ]));
    assert!(t["curve"].as_array().unwrap().len() == 101);
    let bad = std::env::temp_dir().join(format!("rolldyn-bad-oil-{}.toml", std::process::id()));
    std::fs::write(&bad, "name = \"x\"\ncolour = 1\n").unwrap();
    let out = rolldyn(&["oils", "--oil-file", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("colour"));
    std::fs::remove_file(bad).ok();
}

#[test]
fn oil_database_lists_grades_with_provenance() {
    let v = json(&rolldyn(&["oils", "--json"]));
    let oils = v.as_array().unwrap();
    assert_eq!(oils.len(), 35);
    let vg68 = oils
        .iter()
        .find(|o| o["name"] == "iso-vg-68-mineral")
        .unwrap();
    assert!((vg68["nu40_m2_s"].as_f64().unwrap() / 68e-6 - 1.0).abs() < 1e-9);
    assert!((vg68["viscosity_index"].as_f64().unwrap() - 95.0).abs() < 1e-6);
    assert!(
        vg68["estimated"]
            .as_array()
            .unwrap()
            .contains(&"pressure_viscosity".into())
    );
    let jet = oils.iter().find(|o| o["name"] == "mil-prf-23699").unwrap();
    assert_eq!(jet["measured"], serde_json::json!(["viscosity"]));
    assert!((jet["nu100_m2_s"].as_f64().unwrap() / 5.1e-6 - 1.0).abs() < 1e-9);
    let text = String::from_utf8_lossy(&rolldyn(&["oils"]).stdout).to_string();
    assert!(
        text.contains("mil-prf-7808") && text.contains("measured") && text.contains("estimated")
    );
}

#[test]
fn oil_file_with_a_bad_unit_names_file_and_key() {
    let text = std::fs::read_to_string(example("oils/iso-vg68-mineral.toml")).unwrap();
    let bad = std::env::temp_dir().join(format!("rolldyn-bad-unit-{}.toml", std::process::id()));
    std::fs::write(&bad, text.replace("\"20 1/GPa\"", "\"20 GPa\"")).unwrap();
    let out = rolldyn(&["oils", "--oil-file", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(
        err.contains(bad.file_name().unwrap().to_str().unwrap())
            && err.contains("pressure_viscosity")
            && err.contains("GPa"),
        "{err}"
    );
    std::fs::remove_file(bad).ok();
}

#[test]
fn skid_point_and_sweep() {
    let v = json(&rolldyn(&[
        "skid",
        &example("obrien-taylor.toml"),
        "--json",
    ]));
    for key in [
        "cage_slip",
        "cage_speed_rad_s",
        "epicyclic_cage_speed_rad_s",
        "max_roller_load_n",
        "operating_clearance_m",
        "power_loss_w",
        "solve_time_s",
    ] {
        assert!(v[key].is_number(), "{key} in skid JSON");
    }
    assert!(v["rollers"].as_array().unwrap().len() == 13);
    let dir = std::env::temp_dir().join(format!("rolldyn-skid-{}", std::process::id()));
    let sweep = json(&rolldyn(&[
        "skid",
        &example("obrien-taylor.toml"),
        "--radial-load",
        "100N..700N:200N",
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]));
    assert_eq!(sweep["points"].as_array().unwrap().len(), 4);
    assert!(dir.join("skid_sweep.csv").is_file() && dir.join("cage_slip.svg").is_file());
    std::fs::remove_dir_all(dir).ok();
    let out = rolldyn(&["skid", &example("contact/32206-straight.toml")]);
    assert_eq!(out.status.code(), Some(2));
}

/// Issue 21: `--cage-land` reaches the single-point solve (it used to take the short land
/// whatever the flag said).
#[test]
fn skid_point_uses_the_cage_land_flag() {
    let point = |land: &str| {
        json(&rolldyn(&[
            "skid",
            &example("obrien-taylor.toml"),
            "--cage-land",
            land,
            "--json",
        ]))
    };
    let (short, finite) = (point("short"), point("finite"));
    assert_eq!(short["cage_land_model"], "short (Ocvirk) journal bearing");
    assert_eq!(
        finite["cage_land_model"],
        "finite journal bearing (Reynolds crate table)"
    );
    assert_ne!(short["cage_slip"], finite["cage_slip"]);
}

#[test]
fn bench_reports_each_run_and_identical_results() {
    let v = json(&rolldyn(&[
        "bench",
        "--duration",
        "0.5ms",
        "--repeat",
        "2",
        "--json",
    ]));
    let runs = v["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 2);
    for run in runs {
        for key in [
            "setup_s",
            "integration_s",
            "simulated_over_wall",
            "simulated_over_wall_with_setup",
            "rhs_evaluations",
            "us_per_rhs",
        ] {
            assert!(run[key].is_number(), "{key} in bench JSON");
        }
    }
    assert_eq!(runs[0]["rhs_evaluations"], runs[1]["rhs_evaluations"]);
    assert_eq!(v["deterministic"], true);
    assert!(v["median_simulated_over_wall"].as_f64().unwrap() > 0.0);
    let out = rolldyn(&["bench", "--repeat", "0"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn simulate_short_run_writes_series_and_json() {
    let dir = std::env::temp_dir().join(format!("rolldyn-sim-{}", std::process::id()));
    let out = rolldyn(&[
        "simulate",
        &example("obrien-taylor.toml"),
        "--duration",
        "1ms",
        "--output-step",
        "0.1ms",
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--quiet",
    ]);
    let v = json(&out);
    for key in [
        "cage_slip_mean",
        "cage_speed_mean_rad_s",
        "epicyclic_cage_speed_rad_s",
        "max_inner_contact_force_n",
        "simulated_time_s",
        "wall_time_s",
        "steps",
        "rejected_steps",
        "rhs_evaluations",
    ] {
        assert!(v[key].is_number(), "{key} in simulate JSON");
    }
    // The integrator may finish its last step up to one step (a few µs) past the end time.
    assert!((v["simulated_time_s"].as_f64().unwrap() - 1e-3).abs() < 1e-5);
    let limits = v["step_limited_by"].as_array().unwrap();
    assert!(!limits.is_empty() && limits.len() <= 3);
    assert!(
        limits[0]["component"]
            .as_str()
            .unwrap()
            .starts_with("roller ")
    );
    let shares: f64 = limits.iter().map(|l| l["share"].as_f64().unwrap()).sum();
    assert!(shares > 0.0 && shares <= 1.0 + 1e-12);
    for file in [
        "bearing.csv",
        "bearing.parquet",
        "rollers.parquet",
        "cage_speed.svg",
        "cage_orbit.svg",
    ] {
        assert!(dir.join(file).is_file(), "{file}");
    }
    let rows = std::fs::read_to_string(dir.join("bearing.csv"))
        .unwrap()
        .lines()
        .count();
    assert!((10..=12).contains(&rows), "{rows} lines for 1 ms at 0.1 ms");
    std::fs::remove_dir_all(dir).ok();
    let out = rolldyn(&["simulate", &example("contact/32206-straight.toml")]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn simulate_checkpoint_and_resume_equal_an_uninterrupted_run() {
    let dir = std::env::temp_dir().join(format!("rolldyn-ckpt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ckpt = dir.join("state.bin");
    let model = example("obrien-taylor.toml");
    let run = |extra: &[&str]| {
        let mut args = vec!["simulate", model.as_str(), "--json", "--quiet"];
        args.extend_from_slice(extra);
        json(&rolldyn(&args))
    };
    let whole = run(&["--duration", "0.6ms"]);
    run(&[
        "--duration",
        "0.3ms",
        "--checkpoint",
        ckpt.to_str().unwrap(),
    ]);
    let resumed = run(&["--duration", "0.6ms", "--resume", ckpt.to_str().unwrap()]);
    for key in [
        "cage_speed_mean_rad_s",
        "max_inner_contact_force_n",
        "steps",
        "rhs_evaluations",
    ] {
        assert_eq!(whole[key], resumed[key], "{key}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn sweep_runs_variants_with_shards_and_resume() {
    let dir = std::env::temp_dir().join(format!("rolldyn-sweep-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let sweep = dir.join("loads.toml");
    std::fs::write(
        &sweep,
        format!(
            "model = \"{}\"\nanalysis = \"skid\"\n\
             [[variant]]\nname = \"light\"\n\"operating.radial_load\" = \"104 N\"\n\
             [[variant]]\nname = \"heavy\"\n\"operating.radial_load\" = \"687 N\"\n",
            example("obrien-taylor.toml").replace('\\', "/")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    let o = out.to_str().unwrap();
    let first = rolldyn(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        o,
        "--shard",
        "2/2",
        "--quiet",
    ]);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert!(out.join("variants/heavy.json").is_file() && !out.join("variants/light.json").exists());
    let rest = rolldyn(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        o,
        "--resume",
        "--quiet",
    ]);
    assert!(
        String::from_utf8_lossy(&rest.stdout).contains("ran 1 of 2"),
        "resume skips the finished variant"
    );
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3);
    assert!(out.join("summary.parquet").is_file() && out.join("cage_slip.svg").is_file());
    std::fs::remove_dir_all(dir).ok();
}
