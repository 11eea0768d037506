//! `rolldyn simulate --out`: the output-size guard, resume of the tables after an interruption
//! (also after `kill -9` at several points) and the integrity of checkpoints.

mod common;

use common::{example, json, rolldyn};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A fresh temporary folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn model() -> String {
    example("obrien-taylor.toml")
}

/// `rolldyn simulate` of the O'Brien–Taylor bearing with `extra` arguments.
fn simulate(extra: &[&str]) -> Output {
    let model = model();
    let mut args = vec!["simulate", model.as_str(), "--quiet"];
    args.extend_from_slice(extra);
    rolldyn(&args)
}

fn spawn_simulate(extra: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .arg("simulate")
        .arg(model())
        .arg("--quiet")
        .args(extra)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("rolldyn starts")
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn assert_success(out: &Output) {
    assert!(out.status.success(), "{}", stderr(out));
}

fn text(path: &Path) -> &str {
    path.to_str().unwrap()
}

const OUTPUTS: [&str; 11] = [
    "bearing.csv",
    "rollers.csv",
    "revolutions.csv",
    "bearing.parquet",
    "rollers.parquet",
    "revolutions.parquet",
    "cage_speed.svg",
    "cage_slip.svg",
    "cage_orbit.svg",
    "inner_ring_orbit.svg",
    "roller_1_forces.svg",
];

/// Every table and plot of `b` equals that of `a` byte for byte.
fn assert_same_outputs(a: &Path, b: &Path) {
    for file in OUTPUTS {
        let x = std::fs::read(a.join(file)).unwrap();
        let y = std::fs::read(b.join(file)).unwrap();
        assert!(
            x == y,
            "{file}: {} bytes uninterrupted, {} bytes resumed",
            x.len(),
            y.len()
        );
    }
}

#[test]
fn zero_output_step_is_refused() {
    let dir = scratch("zero-step");
    let out = simulate(&[
        "--duration",
        "0.1ms",
        "--output-step",
        "0ms",
        "--out",
        text(&dir),
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--output-step"), "{}", stderr(&out));
    std::fs::remove_dir_all(dir).ok();
}

/// The size of the tables is estimated before the run: far beyond the limit, the run is refused
/// at once (exit 2, with the estimate) instead of filling the disk; `--max-output` raises it.
#[test]
fn oversized_output_is_refused_with_its_estimate() {
    let dir = scratch("huge-output");
    let mut child = spawn_simulate(&[
        "--duration",
        "1rev",
        "--output-step",
        "1e-12s",
        "--out",
        text(&dir.join("huge")),
    ]);
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(10) {
            child.kill().ok();
            child.wait().ok();
            let written = std::fs::metadata(dir.join("huge/rollers.csv")).map_or(0, |m| m.len());
            std::fs::remove_dir_all(&dir).ok();
            panic!("still writing after 10 s ({written} bytes of rollers.csv)");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    assert_eq!(status.code(), Some(2));
    assert!(!dir.join("huge/rollers.csv").exists());
    let small = [
        "--duration",
        "0.2ms",
        "--output-step",
        "0.01ms",
        "--out",
        text(&dir),
    ];
    let mut refused = small.to_vec();
    refused.extend_from_slice(&["--max-output", "10kB"]);
    let out = simulate(&refused);
    assert_eq!(out.status.code(), Some(2));
    let message = stderr(&out);
    assert!(
        message.contains("estimated") && message.contains("--max-output"),
        "{message}"
    );
    let mut allowed = small.to_vec();
    allowed.extend_from_slice(&["--max-output", "100MB"]);
    assert_success(&simulate(&allowed));
    std::fs::remove_dir_all(dir).ok();
}

/// A run stopped at a checkpoint and resumed into the same folder leaves the tables of an
/// uninterrupted run, row for row.
#[test]
fn resume_continues_the_tables() {
    let dir = scratch("resume-tables");
    let (whole, split) = (dir.join("whole"), dir.join("split"));
    let ckpt = dir.join("state.ckpt");
    let step = ["--output-step", "0.02ms"];
    let mut args = vec!["--duration", "0.6ms", "--out", text(&whole), "--json"];
    args.extend_from_slice(&step);
    let uninterrupted = json(&simulate(&args));
    let mut first = vec!["--duration", "0.3ms", "--out", text(&split)];
    first.extend_from_slice(&["--checkpoint", text(&ckpt)]);
    first.extend_from_slice(&step);
    assert_success(&simulate(&first));
    let mut rest = vec!["--duration", "0.6ms", "--out", text(&split), "--json"];
    rest.extend_from_slice(&["--resume", text(&ckpt)]);
    rest.extend_from_slice(&step);
    let resumed = json(&simulate(&rest));
    assert_same_outputs(&whole, &split);
    assert_eq!(uninterrupted["steps"], resumed["steps"]);
    // another output step would give tables with two spacings
    let mut other_step = vec!["--duration", "0.9ms", "--out", text(&split)];
    other_step.extend_from_slice(&["--resume", text(&ckpt), "--output-step", "0.05ms"]);
    let out = simulate(&other_step);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--output-step"), "{}", stderr(&out));
    std::fs::remove_dir_all(dir).ok();
}

/// Waits until the checkpoint file has been (re)written `times` times since `last`.
fn wait_for_checkpoints(path: &Path, times: usize, last: &mut Vec<u8>, child: &mut Child) {
    let started = Instant::now();
    let mut seen = 0;
    while seen < times {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it was killed"
        );
        assert!(started.elapsed() < Duration::from_secs(60), "no checkpoint");
        if let Ok(bytes) = std::fs::read(path)
            && bytes != *last
        {
            *last = bytes;
            seen += 1;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// `kill -9` at several points (right after a checkpoint, and between checkpoints while rows
/// are being written), resume each time into the same folder: the tables equal those of an
/// uninterrupted run, row for row.
#[test]
fn kill_and_resume_equals_an_uninterrupted_run() {
    let dir = scratch("kill-resume");
    let (whole, killed) = (dir.join("whole"), dir.join("killed"));
    let ckpt = dir.join("state.ckpt");
    let common = ["--duration", "3ms", "--output-step", "0.01ms"];
    let mut args = common.to_vec();
    args.extend_from_slice(&["--out", text(&whole)]);
    assert_success(&simulate(&args));
    let mut run = common.to_vec();
    run.extend_from_slice(&["--out", text(&killed), "--checkpoint", text(&ckpt)]);
    run.extend_from_slice(&["--checkpoint-interval", "0.1ms"]);
    let mut last = Vec::new();
    let kill = |mut child: Child| {
        child.kill().unwrap();
        let status = child.wait().unwrap();
        assert!(!status.success(), "the run ended before it was killed");
        let parquet = std::fs::read(killed.join("rollers.parquet")).unwrap();
        assert!(
            !parquet.ends_with(b"PAR1"),
            "a killed run wrote a Parquet footer"
        );
    };
    // killed right after its first checkpoint
    let mut child = spawn_simulate(&run);
    wait_for_checkpoints(&ckpt, 1, &mut last, &mut child);
    kill(child);
    let mut resumed = run.clone();
    resumed.extend_from_slice(&["--resume", text(&ckpt)]);
    // killed twice between checkpoints, while rows are being written
    for delay_ms in [7, 15] {
        let mut child = spawn_simulate(&resumed);
        wait_for_checkpoints(&ckpt, 2, &mut last, &mut child);
        std::thread::sleep(Duration::from_millis(delay_ms));
        kill(child);
    }
    assert_success(&simulate(&resumed));
    assert_same_outputs(&whole, &killed);
    std::fs::remove_dir_all(dir).ok();
}

/// Makes a checkpoint at 0.3 ms of the test model in `dir`.
fn checkpoint_at_0_3ms(dir: &Path) -> PathBuf {
    let ckpt = dir.join("state.ckpt");
    assert_success(&simulate(&[
        "--duration",
        "0.3ms",
        "--checkpoint",
        text(&ckpt),
    ]));
    ckpt
}

#[test]
fn damaged_or_foreign_checkpoint_is_refused() {
    let dir = scratch("damaged-ckpt");
    let ckpt = checkpoint_at_0_3ms(&dir);
    let good = std::fs::read(&ckpt).unwrap();
    let resume = |bytes: &[u8]| {
        std::fs::write(&ckpt, bytes).unwrap();
        simulate(&["--duration", "0.4ms", "--resume", text(&ckpt)])
    };
    let mut flipped = good.clone();
    let middle = flipped.len() / 2;
    flipped[middle] ^= 0x10;
    let out = resume(&flipped);
    assert_eq!(out.status.code(), Some(2), "a flipped byte is accepted");
    assert!(stderr(&out).contains("damaged"), "{}", stderr(&out));
    let out = resume(&good[..good.len() - 3]);
    assert_eq!(out.status.code(), Some(2), "a truncated file is accepted");
    let out = resume(std::fs::read(model()).unwrap().as_slice());
    assert_eq!(out.status.code(), Some(2), "a model file is accepted");
    assert!(stderr(&out).contains("not a rolldyn"), "{}", stderr(&out));
    assert_success(&resume(&good));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn resume_past_the_duration_says_so() {
    let dir = scratch("resume-past");
    let ckpt = checkpoint_at_0_3ms(&dir);
    let out = simulate(&["--duration", "0.2ms", "--resume", text(&ckpt)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--duration"), "{}", stderr(&out));
    std::fs::remove_dir_all(dir).ok();
}

/// A checkpoint belongs to its model, operating point and integrator settings: resuming it
/// under another load, oil temperature or tolerance would mix two runs.
#[test]
fn checkpoint_of_another_set_up_is_refused() {
    let dir = scratch("foreign-ckpt");
    let ckpt = checkpoint_at_0_3ms(&dir);
    for other in [
        ["--radial-load", "500N"],
        ["--oil-temperature", "90C"],
        ["--tolerance", "1e-7"],
    ] {
        let mut args = vec!["--duration", "0.4ms", "--resume", text(&ckpt)];
        args.extend_from_slice(&other);
        let out = simulate(&args);
        assert_eq!(out.status.code(), Some(2), "{other:?} accepted");
        assert!(stderr(&out).contains("different"), "{}", stderr(&out));
    }
    std::fs::remove_dir_all(dir).ok();
}

/// `--resume` into the `--out` folder of another run (same tables, enough rows) is refused and
/// leaves that folder as it was: the checkpoint knows a digest of the rows its run wrote.
#[test]
fn resume_into_another_runs_folder_is_refused() {
    let dir = scratch("resume-foreign-folder");
    let (own, other) = (dir.join("own"), dir.join("other"));
    let ckpt = dir.join("state.ckpt");
    assert_success(&simulate(&[
        "--duration",
        "0.3ms",
        "--out",
        text(&own),
        "--checkpoint",
        text(&ckpt),
    ]));
    let other_run = ["--duration", "0.6ms", "--out", text(&other)];
    let mut args = other_run.to_vec();
    args.extend_from_slice(&["--radial-load", "500N"]);
    assert_success(&simulate(&args));
    let before = std::fs::read(other.join("bearing.csv")).unwrap();
    let out = simulate(&[
        "--duration",
        "0.6ms",
        "--out",
        text(&other),
        "--resume",
        text(&ckpt),
    ]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "resumed into another run's folder"
    );
    assert!(stderr(&out).contains("rows differ"), "{}", stderr(&out));
    assert!(std::fs::read(other.join("bearing.csv")).unwrap() == before);
    std::fs::remove_dir_all(dir).ok();
}
