//! `rolldyn life`: rating life end to end (text, JSON, units on flags, exit codes).

mod common;

use common::{example, json, rolldyn};
use std::process::Command;

#[test]
fn cylindrical_and_tapered_examples() {
    let v = json(&rolldyn(&[
        "life",
        &example("2002834.toml"),
        "--speed",
        "5000rpm",
        "--radial-load",
        "15kN",
        "--contamination",
        "typical-contamination",
        "--reliability",
        "95",
        "--json",
    ]));
    assert_eq!(v["a1"], 0.64);
    assert_eq!(v["e_c"], 0.2);
    let c = &v["conditions"][0];
    assert_eq!(c["equivalent_load"]["load_n"], 15e3);
    for key in ["l10_h", "l_nm_h", "l10r_h", "kappa", "a_iso", "s0"] {
        assert!(c[key].as_f64().unwrap() > 0.0, "{key}");
    }
    let tapered = json(&rolldyn(&[
        "life",
        &example("tapered-cassette.toml"),
        "--axial-load",
        "30kN",
        "--json",
    ]));
    assert_eq!(tapered["ratings"]["rows"], 2);
    assert_eq!(tapered["defaults"].as_array().unwrap().len(), 2);
}

#[test]
fn text_names_the_defaults_and_a_duty_cycle_combines() {
    let out = rolldyn(&[
        "life",
        &example("2002834.toml"),
        "--duty",
        "time=0.7,speed=4000rpm,radial-load=5kN",
        "--duty",
        "time=0.3,speed=8000rpm,radial-load=12kN",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("default: contamination normal-cleanliness"),
        "{text}"
    );
    assert!(text.contains("default: reliability 90 %"), "{text}");
    assert!(text.contains("duty cycle (Palmgren–Miner)"), "{text}");
}

#[test]
fn bad_input_exits_2_in_one_line() {
    let model = example("2002834.toml");
    for (args, names) in [
        (vec!["--reliability", "93"], "Table 12"),
        (vec!["--contamination", "dirty"], "contamination"),
        (vec!["--duty", "time=1,radial-load=15"], "unit"),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .arg("life")
            .arg(&model)
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert!(stderr.contains(names), "{args:?}: {stderr}");
    }
}
