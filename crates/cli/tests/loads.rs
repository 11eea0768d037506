//! `rolldyn loads`: the tapered load distribution end to end (text, JSON, files, exit codes).

mod common;

use common::{example, json, rolldyn};

#[test]
fn seed_case_1_balances_and_writes_its_files() {
    let dir = std::env::temp_dir().join(format!("rolldyn-loads-{}", std::process::id()));
    let out = rolldyn(&[
        "loads",
        &example("tapered-cassette.toml"),
        "--radial-load",
        "118862N",
        "--json",
        "--out",
        &dir.display().to_string(),
    ]);
    let v = json(&out);
    let result = &v["result"];
    assert_eq!(result["converged"], true);
    assert!(result["checks"]["relative"].as_f64().unwrap() < 1e-8);
    for row in result["rows"].as_array().unwrap() {
        let q = row["max_cup_n"].as_f64().unwrap();
        // the dynamics' ≈ 14.9 kN per row for seed 000 case 1
        assert!((q / 14_900.0 - 1.0).abs() < 0.02, "{q}");
    }
    for file in [
        "tapered_loads.csv",
        "tapered_loads.parquet",
        "roller_loads.svg",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
}

#[test]
fn bad_input_exits_2_in_one_line() {
    let cylindrical = example("2002834.toml");
    let tapered = example("tapered-cassette.toml");
    for (args, names) in [
        (vec!["loads", cylindrical.as_str()], "bearing.kind"),
        (
            vec![
                "loads",
                tapered.as_str(),
                "--moment",
                "1kNm",
                "--misalignment",
                "4arcmin",
            ],
            "--moment, --misalignment",
        ),
        (
            vec!["loads", tapered.as_str(), "--misalignment", "3deg"],
            "--misalignment",
        ),
        (
            vec!["loads", tapered.as_str(), "--radial-load=-1N"],
            "--radial-load",
        ),
        (
            vec!["loads", tapered.as_str(), "--row-offset", "1.5"],
            "--row-offset",
        ),
    ] {
        let out = rolldyn(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.contains(names), "{stderr}");
    }
}
