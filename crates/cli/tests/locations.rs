//! Issue 39, "Locations" and the wear/cage-load items: every refused input names its file,
//! line and key (or its flag), and no absurd value passes as a result — N3, N7, N8, N9, N13,
//! N16.

mod common;

use common::{example, json, rolldyn};
use std::path::{Path, PathBuf};
use std::process::Output;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-locations-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).to_string()
}

/// Asserts exit 2 with one line that contains every one of `parts`.
fn refused(output: &Output, parts: &[&str]) -> String {
    let message = stderr(output);
    assert_eq!(output.status.code(), Some(2), "{message}");
    assert_eq!(message.trim().lines().count(), 1, "{message}");
    for part in parts {
        assert!(message.contains(part), "'{part}' missing: {message}");
    }
    message
}

/// The 1-based line of `text` that starts with `start`.
fn line_of(text: &str, start: &str) -> usize {
    text.lines()
        .position(|l| l.trim_start().starts_with(start))
        .unwrap_or_else(|| panic!("no line starts with {start}"))
        + 1
}

/// Writes `sweep.toml` (the embedded cylindrical model beside it) into `dir`.
fn write_sweep(dir: &Path, body: &str) -> (PathBuf, String) {
    std::fs::copy(example("2002834.toml"), dir.join("model.toml")).unwrap();
    let path = dir.join("sweep.toml");
    let text = format!("model = \"model.toml\"\n{body}");
    std::fs::write(&path, &text).unwrap();
    (path, text)
}

fn run_sweep(path: &Path, out: &Path) -> Output {
    rolldyn(&[
        "sweep",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ])
}

#[test]
fn n8_a_wear_sweep_with_a_life_not_positive_is_refused_at_its_line() {
    let dir = scratch("n8");
    for life in ["-5h", "0h"] {
        let body = format!(
            "analysis = \"wear\"\nduration = \"{life}\"\n[[variant]]\nname = \"a\"\n\"operating.radial_load\" = \"5 kN\"\n"
        );
        let (path, text) = write_sweep(&dir, &body);
        let line = line_of(&text, "duration");
        let out = run_sweep(&path, &dir.join("out"));
        refused(
            &out,
            &[&format!("sweep.toml:{line}:1: duration"), "positive"],
        );
        assert!(
            !dir.join("out/summary.csv").exists(),
            "{life}: a row was written"
        );
    }
    // the same check as the wear command's
    let out = rolldyn(&["wear", "--life=-5h"]);
    refused(&out, &["--life", "positive"]);
}

#[test]
fn n9_the_number_of_wear_periods_is_bounded() {
    let out = rolldyn(&["wear", "--period", "1e-308h"]);
    let message = refused(&out, &["--period", "--max-periods", "periods"]);
    assert!(message.contains("e312"), "{message}");
    let out = rolldyn(&["wear", "--period", "1h", "--life", "20000h"]);
    refused(&out, &["--period", "20000", "10000"]);
    let dir = scratch("n9");
    let body = "analysis = \"wear\"\nperiod = \"1e-308h\"\n[[variant]]\nname = \"a\"\n\"operating.radial_load\" = \"5 kN\"\n";
    let (path, text) = write_sweep(&dir, body);
    let line = line_of(&text, "period");
    refused(
        &run_sweep(&path, &dir.join("out")),
        &[&format!("sweep.toml:{line}:1: period"), "periods"],
    );
}

#[test]
fn n13_sweep_file_errors_name_line_column_and_key() {
    let dir = scratch("n13");
    let variant = "[[variant]]\nname = \"a\"\n\"operating.radial_load\" = \"5 kN\"\n";
    let cases: [(String, &str, &str); 6] = [
        (
            format!("duration = \"1rev\nx = 1\n{variant}"),
            "duration",
            "",
        ),
        (format!("speed = 1\n{variant}"), "speed", "speed"),
        (
            format!("analysis = \"nothing\"\n{variant}"),
            "analysis",
            "analysis",
        ),
        (
            format!("{variant}[[variant]]\nname = \"a\"\n"),
            "name",
            "variant[1].name",
        ),
        (format!("discard = \"x\"\n{variant}"), "discard", "discard"),
        (
            "[[variant]]\nname = \"a b\"\n".to_string(),
            "name",
            "variant[0].name",
        ),
    ];
    for (body, at, key) in &cases {
        let (path, text) = write_sweep(&dir, body);
        // the last occurrence: the second of two variants named alike
        let line = match text.rfind(at) {
            Some(offset) => text[..offset].matches('\n').count() + 1,
            None => panic!("{at}"),
        };
        let message = refused(&run_sweep(&path, &dir.join("out")), &[key]);
        assert!(
            message.contains(&format!("sweep.toml:{line}:")),
            "line {line} expected: {message}"
        );
    }
}

#[test]
fn n3_an_override_error_names_the_sweep_line_and_the_override_key() {
    let dir = scratch("n3");
    let body = "duration = \"1rev\"\n[[variant]]\nname = \"fine\"\n\"operating.radial_load\" = \"5 kN\"\n[[variant]]\nname = \"wide\"\n\"cage.width\" = \"1e308 mm\"\n";
    let (path, text) = write_sweep(&dir, body);
    let line = line_of(&text, "\"cage.width\"");
    let message = refused(
        &run_sweep(&path, &dir.join("out")),
        &[
            &format!("sweep.toml:{line}:1: variant[1] (wide) \"cage.width\""),
            "implausible",
        ],
    );
    assert!(!message.contains("model.toml"), "{message}");
}

#[test]
fn n16_collect_only_into_a_missing_folder_names_the_folder() {
    let dir = scratch("n16-collect");
    let (path, _) = write_sweep(
        &dir,
        "[[variant]]\nname = \"a\"\n\"operating.radial_load\" = \"5 kN\"\n",
    );
    let missing = dir.join("missing");
    let out = rolldyn(&[
        "sweep",
        path.to_str().unwrap(),
        "--collect-only",
        "--out",
        missing.to_str().unwrap(),
    ]);
    refused(&out, &["--out", missing.to_str().unwrap()]);
    assert!(!missing.exists());
}

#[test]
fn n16_skid_at_one_point_writes_its_rollers_table_to_out() {
    let dir = scratch("n16-skid");
    let out = dir.join("point");
    let answer = json(&rolldyn(&[
        "skid",
        "--out",
        out.to_str().unwrap(),
        "--json",
    ]));
    let text = std::fs::read_to_string(out.join("rollers.csv")).expect("rollers.csv written");
    let mut lines = text.lines();
    assert!(lines.next().unwrap().starts_with("roller,azimuth_rad,zone"));
    let rollers = answer["rollers"].as_array().map_or(0, Vec::len);
    assert_eq!(lines.count(), rollers, "{text}");
}

/// An edit of a load export's JSON header.
type Edit = fn(&mut serde_json::Value);

/// A load export of the embedded model (two simulated revolutions) in `dir`: its table.
fn load_export(dir: &Path) -> PathBuf {
    let loads = dir.join("loads.parquet");
    json(&rolldyn(&[
        "simulate",
        "--duration",
        "2rev",
        "--cage-loads",
        loads.to_str().unwrap(),
        "--json",
        "--quiet",
    ]));
    loads
}

#[test]
fn n7_cage_load_values_out_of_bounds_are_refused_at_their_line() {
    let dir = scratch("n7");
    let loads = load_export(&dir);
    let header = dir.join("loads.json");
    let original = std::fs::read_to_string(&header).unwrap();
    let edits: [(&str, Edit); 5] = [
        ("sets[5].angular_velocity_rad_s", |v| {
            v["sets"][5]["angular_velocity_rad_s"][2] = 1e308.into()
        }),
        ("sets[5].angular_velocity_rad_s", |v| {
            v["sets"][5]["angular_velocity_rad_s"][2] = 1e30.into()
        }),
        ("sets[7].angular_acceleration_rad_s2", |v| {
            v["sets"][7]["angular_acceleration_rad_s2"][0] = 1e300.into()
        }),
        ("sets[0].acceleration_m_s2", |v| {
            v["sets"][0]["acceleration_m_s2"][1] = (-1e30).into()
        }),
        ("header.cage_speed_rpm", |v| {
            v["header"]["cage_speed_rpm"] = 1e30.into()
        }),
    ];
    for (key, edit) in edits {
        let mut value: serde_json::Value = serde_json::from_str(&original).unwrap();
        edit(&mut value);
        let text = serde_json::to_string_pretty(&value).unwrap();
        std::fs::write(&header, &text).unwrap();
        let out = rolldyn(&["fatigue", "--loads", loads.to_str().unwrap(), "--json"]);
        let message = refused(&out, &["loads.json:", key, "implausible"]);
        let line: usize = message
            .split("loads.json:")
            .nth(1)
            .and_then(|rest| rest.split(':').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("no line: {message}"));
        let name = key.rsplit('.').next().unwrap();
        assert!(
            text.lines().nth(line - 1).unwrap().contains(name),
            "line {line} is not {key}: {message}"
        );
    }
}

/// The numeric keys of the journal example with a bad value each (0, negative, NaN, 1e308)
/// are refused with exit 2 naming the file, the line and the key.
#[test]
fn n13_journal_file_values_are_bounded_at_their_line() {
    let dir = scratch("n13-journal");
    let seed = std::fs::read_to_string(example("journal/seed002-ch4.toml")).unwrap();
    // values that are valid at 0 or below: α = 0 and Ω₀ = 0 (no pressure or temperature
    // dependence), ν = 0 (cork), a journal turning backwards
    let valid = [
        ("alpha", "0"),
        ("omega0_per_k", "0"),
        ("poisson", "0"),
        ("speed", "-1"),
    ];
    let mut section = String::new();
    let mut checked = 0;
    for (index, line) in seed.lines().enumerate() {
        if line.starts_with('[') {
            section = line.trim_matches(['[', ']']).to_string();
            continue;
        }
        if line.starts_with('#') || section == "solver" {
            continue; // comments; the solver's choices are names and a grid, not numbers
        }
        let Some((key, rest)) = line.split_once('=') else {
            continue;
        };
        let key = key.trim();
        let value = rest.split('#').next().unwrap().trim();
        let quoted = value.starts_with('"');
        let inner = value.trim_matches('"');
        let number_end = inner
            .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
            .unwrap_or(inner.len());
        if number_end == 0 || (quoted && number_end == inner.len()) {
            continue; // a name (law, kernel, grid …), not a number
        }
        // temperatures in kelvin so that 0 and −1 are below absolute zero
        let unit = match &inner[number_end..] {
            "C" => "K",
            unit => unit,
        };
        for bad in ["0", "-1", "nan", "1e308"] {
            if valid.contains(&(key, bad)) {
                continue;
            }
            let written = if quoted {
                format!("\"{bad}{unit}\"")
            } else {
                bad.to_string()
            };
            let text: String = seed
                .lines()
                .enumerate()
                .map(|(i, l)| {
                    if i == index {
                        format!("{key} = {written}\n")
                    } else {
                        format!("{l}\n")
                    }
                })
                .collect();
            let path = dir.join("journal.toml");
            std::fs::write(&path, text).unwrap();
            let out = rolldyn(&["journal", "--file", path.to_str().unwrap(), "--json"]);
            refused(
                &out,
                &[
                    &format!("journal.toml:{}:", index + 1),
                    &format!("{section}.{key}"),
                ],
            );
            checked += 1;
        }
    }
    assert!(checked >= 70, "only {checked} values checked");
}
