//! `rolldyn fatigue` on the cage's own material: a coating factor on an unplated cage and a cage
//! material without an S–N curve exit 2 naming the model key, before any dynamics run.

#[allow(dead_code)] // json(), example(): not needed here
mod common;

use common::rolldyn;

/// The embedded model with `edits` applied, written to a file named `name`.
fn model_file(name: &str, edits: &[(&str, &str)]) -> String {
    let mut text = rolldyn_model::DEFAULT_MODEL.to_string();
    for (from, to) in edits {
        assert!(text.contains(from), "test setup: '{from}'");
        text = text.replacen(from, to, 1);
    }
    let dir = std::env::temp_dir().join(format!("rolldyn-cli-cage-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn stderr_of_exit_2(args: &[&str]) -> String {
    let out = rolldyn(args);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    stderr
}

#[test]
fn a_coating_factor_on_an_unplated_brass_cage_exits_2_naming_cage_plating() {
    let file = model_file(
        "brass.toml",
        &[
            ("material = \"cage-steel\"", "material = \"cuzn40pb2\""),
            ("plating = \"silver\"", ""),
        ],
    );
    let stderr = stderr_of_exit_2(&["fatigue", &file, "--coating-factor", "1.5"]);
    assert!(stderr.contains("cage.plating"), "{stderr}");
}

#[test]
fn a_cage_material_without_sn_data_exits_2_naming_its_table() {
    let file = model_file(
        "no-sn.toml",
        &[("fatigue_like = \"40khn2ma-sh\"", "# no S–N curve")],
    );
    let stderr = stderr_of_exit_2(&["fatigue", &file]);
    assert!(
        stderr.contains("cage.material") && stderr.contains("[materials.cage-steel]"),
        "{stderr}"
    );
}
