//! End-to-end checks of `rolldyn journal` and `rolldyn ehl-line` (SPEC §8, issue 4 item 6):
//! JSON fields, a Raimondi–Boyd point, the analytic (Martin) rigid line-contact load, load steps
//! and bad-input exit codes. Grids are kept coarse where the check allows (debug builds).

mod common;

use common::{example, json, rolldyn};
use std::path::PathBuf;
use std::process::Output;

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing or not a number in {v}"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "rolldyn-reynolds-cli-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

const BEARING: [&str; 11] = [
    "journal",
    "--radius",
    "25mm",
    "--length",
    "50mm",
    "--clearance",
    "50um",
    "--viscosity",
    "0.05Pas",
    "--speed",
    "3000rpm",
];

/// Runs `base` followed by `extra` arguments.
fn with(base: &[&str], extra: &[&str]) -> Output {
    let mut a: Vec<&str> = base.to_vec();
    a.extend_from_slice(extra);
    rolldyn(&a)
}

fn journal(extra: &[&str]) -> Output {
    with(&BEARING, extra)
}

/// Raimondi–Boyd chart point L/D = 1, ε = 0.6 (full bearing, Reynolds cavitation, film from the
/// maximum gap): S = 0.121, φ = 50.58°, (R/c)f = 3.22 — each within 1 % on the default 120×40
/// grid (the library reproduces them to 0.1 %). Every documented JSON field is present.
#[test]
fn journal_json_fields_and_raimondi_boyd_point() {
    let dir = scratch("journal");
    let v = json(&journal(&[
        "--eccentricity",
        "0.6",
        "--json",
        "--out",
        dir.to_str().unwrap(),
    ]));
    for key in [
        "eccentricity",
        "attitude_deg",
        "sommerfeld",
        "load_n",
        "max_pressure_pa",
        "friction_torque_nm",
        "friction_variable",
        "side_flow_m3_s",
        "min_film_m",
        "power_loss_w",
        "solve_time_s",
    ] {
        assert!(num(&v, key).is_finite(), "{key}");
    }
    assert!(v["iterations"].as_u64().unwrap() > 0);
    assert_eq!(v["converged"], true);
    assert!(v["limits"]["max_active_set_iterations"].as_u64().unwrap() > 0);
    for key in ["stiffness_n_per_m", "damping_ns_per_m"] {
        let m = v[key].as_array().expect(key);
        assert_eq!(m.len(), 2);
        for row in m {
            let r = row.as_array().unwrap();
            assert_eq!(r.len(), 2);
            assert!(r.iter().all(|x| x.as_f64().unwrap().is_finite()));
        }
    }
    // direct stiffness and damping are positive
    assert!(v["stiffness_n_per_m"][0][0].as_f64().unwrap() > 0.0);
    assert!(v["damping_ns_per_m"][0][0].as_f64().unwrap() > 0.0);
    let rel = |got: f64, want: f64| (got / want - 1.0).abs();
    assert!(rel(num(&v, "sommerfeld"), 0.121) < 0.01, "{v}");
    assert!(rel(num(&v, "attitude_deg"), 50.58) < 0.01, "{v}");
    assert!(rel(num(&v, "friction_variable"), 3.22) < 0.01, "{v}");
    // minimum film c(1 − ε)
    assert!(rel(num(&v, "min_film_m"), 50e-6 * 0.4) < 1e-6);
    for f in ["pressure.csv", "pressure_map.svg", "pressure_midplane.svg"] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Given-load mode: the equilibrium carries the load (1e-6), ε in (0, 1); coefficients can be
/// skipped (then null); JFO runs.
#[test]
fn journal_given_load_and_options() {
    let v = json(&journal(&[
        "--load",
        "2kN",
        "--grid",
        "60x20",
        "--no-coefficients",
        "--cavitation",
        "jfo",
        "--json",
    ]));
    assert!((num(&v, "load_n") / 2000.0 - 1.0).abs() < 1e-6, "{v}");
    let e = num(&v, "eccentricity");
    assert!(e > 0.0 && e < 1.0);
    assert!(v["load_iterations"].as_u64().unwrap() > 0);
    assert!(v["stiffness_n_per_m"].is_null() && v["damping_ns_per_m"].is_null());
    assert_eq!(v["cavitation"], "jfo");
    assert_eq!(v["grid"][0], 60);
}

/// The model-file form (seed 002 ch. 4: elastic liner + housing, Petrusevich law, thermal
/// model) runs; the film heats above the housing temperature and the liner deflects.
#[test]
fn journal_model_file() {
    let v = json(&rolldyn(&[
        "journal",
        "--file",
        &example("journal/seed002-ch4.toml"),
        "--grid",
        "60x16",
        "--no-coefficients",
        "--json",
    ]));
    assert_eq!(v["elastic_liner"], true);
    assert_eq!(v["thermal"], true);
    assert_eq!(v["converged"], true);
    assert!(num(&v, "max_deflection_m") > 0.0);
    assert!(num(&v, "mean_temperature_k") > 313.15 + 1.0);
    assert!(v["coupling_iterations"].as_u64().unwrap() > 1);
}

/// Bad input exits with code 2 and a message: ε ≥ 1, ε < 0, ε = 0, zero clearance, zero
/// speed, no mode, a load beyond the capacity, an unknown key in the model file (named).
#[test]
fn journal_bad_input() {
    for eps in ["1", "1.2", "-0.1", "0"] {
        let out = journal(&["--eccentricity", eps]);
        assert_eq!(out.status.code(), Some(2), "ε = {eps}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("ε"));
    }
    let out = rolldyn(&[
        "journal",
        "--radius",
        "25mm",
        "--length",
        "50mm",
        "--clearance",
        "0um",
        "--viscosity",
        "0.05Pas",
        "--speed",
        "3000rpm",
        "--eccentricity",
        "0.5",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("clearance"));
    let out = rolldyn(&[
        "journal",
        "--radius",
        "25mm",
        "--length",
        "50mm",
        "--clearance",
        "50um",
        "--viscosity",
        "0.05Pas",
        "--speed",
        "0rpm",
        "--eccentricity",
        "0.5",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("speed"));
    assert_eq!(journal(&[]).status.code(), Some(2));
    let out = journal(&["--load", "1e9N", "--grid", "40x10", "--no-coefficients"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("capacity"));
    let bad = std::env::temp_dir().join(format!("rolldyn-journal-bad-{}.toml", std::process::id()));
    let text = std::fs::read_to_string(example("journal/seed002-ch4.toml"))
        .unwrap()
        .replace("poisson = 0.34", "poisson = 0.34\nyoung = 1");
    std::fs::write(&bad, text).unwrap();
    let out = rolldyn(&["journal", "--file", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("liner.young") && err.contains("rolldyn-journal-bad"),
        "{err}"
    );
    let _ = std::fs::remove_file(&bad);
}

const CONTACT: [&str; 7] = [
    "ehl-line",
    "--radius",
    "5mm",
    "--viscosity",
    "0.024Pas",
    "--rolling-speed",
    "3.5m/s",
];

fn ehl(extra: &[&str]) -> Output {
    with(&CONTACT, extra)
}

/// Rigid isoviscous contact at h_m = 1 µm (seed 002 §3.5): the load per length equals the
/// analytic Martin value W = 6 W₀′ μ V R / h, W₀′ = 0.40791 (2055.9 N/m), within 0.5 %; the
/// damping λ = 6 W₁′ μ R^{3/2}/h^{3/2}, W₁′ = 1.0914, within 1 %. All JSON fields are present.
#[test]
fn ehl_line_rigid_isoviscous_matches_martin() {
    let dir = scratch("ehl");
    let v = json(&ehl(&[
        "--min-film",
        "1um",
        "--json",
        "--out",
        dir.to_str().unwrap(),
    ]));
    for key in [
        "load_per_length_n_per_m",
        "max_pressure_pa",
        "min_film_m",
        "central_film_m",
        "outlet_position_m",
        "damping_ns_per_m2",
        "solve_time_s",
    ] {
        assert!(num(&v, key).is_finite(), "{key}");
    }
    assert!(v["iterations"].as_u64().unwrap() > 0);
    assert_eq!(v["converged"], true);
    assert!(v["limits"]["max_newton_iterations"].as_u64().unwrap() > 0);
    let (mu, vs, r, h) = (0.024, 7.0, 0.005, 1e-6);
    let w = 6.0 * 0.40791 * mu * vs * r / h;
    let got = num(&v, "load_per_length_n_per_m");
    assert!((got / w - 1.0).abs() < 0.005, "{got} vs {w}");
    let lambda = 6.0 * 1.0914 * mu * r.powf(1.5) / h.powf(1.5);
    let got = num(&v, "damping_ns_per_m2");
    assert!((got / lambda - 1.0).abs() < 0.01, "{got} vs {lambda}");
    assert!((num(&v, "min_film_m") / h - 1.0).abs() < 1e-4);
    for f in ["profile.csv", "pressure.svg", "film.svg"] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Full EHL (half-space, Barus α = 7.5e-9/Pa) at 300 kN/m on a coarse grid converges, carries
/// the load, and has the EHL shape: h_min < h_c, p_max within 10 % of p_Hertz.
#[test]
fn ehl_line_elastic_piezoviscous() {
    let v = json(&ehl(&[
        "--load-per-length",
        "300kN/m",
        "--piezo",
        "7.5e-9/Pa",
        "--elastic",
        "half-space",
        "--nodes",
        "300",
        "--json",
    ]));
    assert_eq!(v["converged"], true);
    assert!((num(&v, "load_per_length_n_per_m") / 3e5 - 1.0).abs() < 1e-6);
    assert!(num(&v, "min_film_m") < num(&v, "central_film_m"));
    let ph = num(&v, "hertz_pressure_pa");
    assert!((num(&v, "max_pressure_pa") / ph - 1.0).abs() < 0.1, "{v}");
    assert!((num(&v, "piezo_per_pa") - 7.5e-9).abs() < 1e-15);
}

/// Load step 2 → 4 kN/m (rigid isoviscous): the film settles on the static film of the new
/// load (1 %), the history is written (CSV + SVG).
#[test]
fn ehl_line_load_step() {
    let dir = scratch("step");
    let v = json(&ehl(&[
        "--load-per-length",
        "2kN/m",
        "--step-to",
        "4kN/m",
        "--duration",
        "1ms",
        "--nodes",
        "200",
        "--json",
        "--out",
        dir.to_str().unwrap(),
    ]));
    let t = &v["transient"];
    let (hf, hs) = (num(t, "final_film_m"), num(t, "static_film_at_new_load_m"));
    assert!((hf / hs - 1.0).abs() < 0.01, "{t}");
    assert!(num(t, "initial_film_m") > 1.9 * hs);
    assert!(num(t, "peak_pressure_pa") > 0.0);
    for f in [
        "transient.csv",
        "transient_film.svg",
        "transient_pressure.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Bad input exits with code 2: no speed and no squeeze, both or neither of the modes, bad
/// elastic model, bad α unit, non-positive film.
#[test]
fn ehl_line_bad_input() {
    let out = rolldyn(&[
        "ehl-line",
        "--radius",
        "5mm",
        "--viscosity",
        "0.024Pas",
        "--rolling-speed",
        "0m/s",
        "--min-film",
        "1um",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("squeeze"));
    for extra in [
        &["--min-film", "1um", "--load-per-length", "3kN/m"][..],
        &[][..],
        &["--min-film", "1um", "--elastic", "rubber"][..],
        &["--min-film", "1um", "--piezo", "7.5e-9/K"][..],
        &["--min-film", "0um"][..],
        &["--load-per-length", "300kN"][..],
    ] {
        let out = ehl(extra);
        assert_eq!(out.status.code(), Some(2), "{extra:?}");
        assert!(!out.stderr.is_empty());
    }
}
