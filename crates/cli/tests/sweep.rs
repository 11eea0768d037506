//! `rolldyn sweep`: resume after edits (fingerprints) and after a killed run.

#[allow(dead_code)] // json(): these tests read files, not JSON answers
mod common;

use common::{example, rolldyn};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-sweep-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes a sweep of the O'Brien–Taylor bearing with one variant per radial load.
fn write_sweep(path: &Path, header: &str, loads: &[(&str, &str)]) {
    let variants: String = loads
        .iter()
        .map(|(name, load)| {
            format!("[[variant]]\nname = \"{name}\"\n\"operating.radial_load\" = \"{load}\"\n")
        })
        .collect();
    let model = example("obrien-taylor.toml").replace('\\', "/");
    std::fs::write(path, format!("model = \"{model}\"\n{header}\n{variants}")).unwrap();
}

fn sweep(file: &Path, out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "sweep",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ];
    args.extend_from_slice(extra);
    let output = rolldyn(&args);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// The rows of `summary.csv` without the timing columns (they differ from run to run).
fn summary_without_wall_time(out: &Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let rows: Vec<Vec<String>> = text
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let keep: Vec<usize> = (0..rows[0].len())
        .filter(|&i| {
            !["wall_time", "solve_time"]
                .iter()
                .any(|t| rows[0][i].contains(t))
        })
        .collect();
    rows.iter()
        .map(|r| keep.iter().map(|&i| r[i].clone()).collect())
        .collect()
}

#[test]
fn resume_reruns_a_variant_whose_inputs_changed() {
    let dir = scratch("edited");
    let file = dir.join("loads.toml");
    let header = "analysis = \"skid\"";
    write_sweep(&file, header, &[("light", "104 N"), ("heavy", "687 N")]);
    let out = dir.join("out");
    sweep(&file, &out, &[]);
    let again = sweep(&file, &out, &["--resume"]);
    assert!(String::from_utf8_lossy(&again.stdout).contains("ran 0 of 2"));

    write_sweep(&file, header, &[("light", "104 N"), ("heavy", "500 N")]);
    let resumed = sweep(&file, &out, &["--resume"]);
    let stdout = String::from_utf8_lossy(&resumed.stdout);
    assert!(
        stdout.contains("ran 1 of 2") && stdout.contains("inputs changed: heavy"),
        "{stdout}"
    );
    let fresh = dir.join("fresh");
    sweep(&file, &fresh, &[]);
    assert_eq!(
        summary_without_wall_time(&out),
        summary_without_wall_time(&fresh)
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn killed_sweep_resumes_without_lost_or_duplicated_rows() {
    let dir = scratch("killed");
    let file = dir.join("loads.toml");
    let loads = [
        ("a", "104 N"),
        ("b", "201 N"),
        ("c", "400 N"),
        ("d", "687 N"),
    ];
    write_sweep(&file, "analysis = \"simulate\"\nduration = \"2ms\"", &loads);
    let whole = dir.join("whole");
    sweep(&file, &whole, &["--jobs", "1"]);

    let killed = dir.join("killed");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(["sweep", file.to_str().unwrap(), "--out"])
        .arg(&killed)
        .args(["--jobs", "1", "--quiet"])
        .spawn()
        .unwrap();
    let finished = |dir: &Path| {
        std::fs::read_dir(dir.join("variants")).map_or(0, |entries| {
            entries
                .filter(|e| {
                    e.as_ref()
                        .is_ok_and(|e| e.path().extension().is_some_and(|x| x == "json"))
                })
                .count()
        })
    };
    let start = Instant::now();
    while finished(&killed) == 0 {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no variant finished"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    assert!(finished(&killed) < loads.len(), "killed before the end");

    sweep(&file, &killed, &["--jobs", "1", "--resume"]);
    assert_eq!(
        summary_without_wall_time(&killed),
        summary_without_wall_time(&whole)
    );
    std::fs::remove_dir_all(dir).ok();
}

/// `discard = "Nrev"` leaves the first revolutions out of the summary (the summary changes,
/// the run does not fail); a value that is not a revolution count is a one-line input error.
#[test]
fn discard_leaves_the_first_revolutions_out_of_the_summary() {
    let dir = scratch("discard");
    let loads = [("a", "201 N")];
    let run = |header: &str, out: &str| {
        let file = dir.join(format!("{out}.toml"));
        write_sweep(&file, header, &loads);
        sweep(&file, &dir.join(out), &[]);
        summary_without_wall_time(&dir.join(out))
    };
    let kept = run(
        "analysis = \"simulate\"\nduration = \"1.5rev\"\ndiscard = \"0rev\"",
        "keep",
    );
    let dropped = run(
        "analysis = \"simulate\"\nduration = \"1.5rev\"\ndiscard = \"1rev\"",
        "drop",
    );
    assert_ne!(
        kept[1], dropped[1],
        "discarding the first revolution changes the maxima"
    );
    for bad in [
        "discard = \"2 s\"",
        "duration = \"2rev\"\ndiscard = \"2rev\"",
    ] {
        let file = dir.join("bad.toml");
        write_sweep(&file, &format!("analysis = \"simulate\"\n{bad}"), &loads);
        let output = rolldyn(&["sweep", file.to_str().unwrap(), "--quiet"]);
        assert_eq!(output.status.code(), Some(2), "{bad}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("discard") && stderr.lines().count() == 1,
            "{stderr}"
        );
    }
}

#[test]
fn shards_without_collection_then_one_collection_equal_a_whole_sweep() {
    let dir = scratch("shards");
    let file = dir.join("loads.toml");
    write_sweep(
        &file,
        "analysis = \"skid\"",
        &[("light", "104 N"), ("medium", "300 N"), ("heavy", "687 N")],
    );
    let out = dir.join("sharded");
    for shard in ["1/3", "2/3", "3/3"] {
        let ran = sweep(&file, &out, &["--shard", shard, "--no-collect"]);
        assert!(String::from_utf8_lossy(&ran.stdout).contains("not collected"));
        assert!(!out.join("summary.csv").exists(), "shard {shard} collected");
    }
    let collected = sweep(&file, &out, &["--collect-only"]);
    assert!(String::from_utf8_lossy(&collected.stdout).contains("ran 0 of 3"));
    let whole = dir.join("whole");
    sweep(&file, &whole, &[]);
    assert_eq!(
        summary_without_wall_time(&out),
        summary_without_wall_time(&whole)
    );
    std::fs::remove_dir_all(dir).ok();
}
