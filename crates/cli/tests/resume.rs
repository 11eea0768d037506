//! N10: every long command survives `kill -9` and resumes with nothing lost or duplicated. Each
//! test runs a command to the end in one folder; runs it again in another, kills it (SIGKILL)
//! once it has stored its first unit of work, resumes it there, and compares the two folders
//! file by file — the timing columns of the tables aside.

#[allow(dead_code)] // json(): not needed here
mod common;
use common::{example, rolldyn};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A scratch folder of this test process.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-resume-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs `rolldyn args` to the end, successfully.
fn run_to_end(args: &[&str]) {
    let out = rolldyn(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "rolldyn {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Starts `rolldyn args`, waits until `stored` exists (the first unit of work is stored),
/// and kills the process with SIGKILL; fails when the run ends before.
fn kill_after_first_unit(args: &[&str], stored: &Path) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("rolldyn starts");
    let start = Instant::now();
    while !stored.exists() {
        assert!(
            child.try_wait().unwrap().is_none(),
            "rolldyn {args:?} ended before storing {}",
            stored.display()
        );
        assert!(start.elapsed() < Duration::from_secs(300), "no stored unit");
        std::thread::sleep(Duration::from_millis(5));
    }
    assert!(
        child.try_wait().unwrap().is_none(),
        "rolldyn {args:?} ended before it could be killed: make the run longer"
    );
    child.kill().unwrap();
    child.wait().unwrap();
}

/// The fields of a CSV file without the columns `timing`, line by line.
fn csv_without(path: &Path, timing: &[&str]) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let keep: Vec<usize> = (0..header.len())
        .filter(|&k| !timing.contains(&header[k]))
        .collect();
    std::iter::once(text.lines().next().unwrap_or_default())
        .chain(lines)
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            keep.iter()
                .map(|&k| fields.get(k).unwrap_or(&"<missing>").to_string())
                .collect()
        })
        .collect()
}

/// Every file of `reference` is in `resumed` with the same content: CSV tables without the
/// `timing` columns, Parquet files complete (both closed by their footer), other files byte
/// for byte; the run record, the report, the stored state and checkpoints (timings) are left
/// out.
fn same_outputs(reference: &Path, resumed: &Path, timing: &[&str]) {
    let mut names: Vec<String> = std::fs::read_dir(reference)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let resumed_names: Vec<String> = std::fs::read_dir(resumed)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".partial"))
        .collect();
    for name in &resumed_names {
        assert!(names.contains(name), "{name}: only in the resumed run");
    }
    for name in &names {
        let (a, b) = (reference.join(name), resumed.join(name));
        assert!(b.exists(), "{name}: missing after the resume");
        match name.rsplit_once('.').map(|(_, ext)| ext) {
            // the lock names its holder: the process id and command line differ
            _ if ["run.json", "report.html", ".rolldyn.lock"].contains(&name.as_str()) => {}
            Some("state" | "checkpoint") => {}
            Some("csv") => assert_eq!(
                csv_without(&a, timing),
                csv_without(&b, timing),
                "{name} differs"
            ),
            Some("parquet") => {
                let bytes = std::fs::read(&b).unwrap();
                assert!(
                    bytes.len() > 8 && bytes.ends_with(b"PAR1"),
                    "{name}: not a complete Parquet file"
                );
                assert!(std::fs::read(&a).unwrap().ends_with(b"PAR1"));
            }
            _ => assert!(
                std::fs::read(&a).unwrap() == std::fs::read(&b).unwrap(),
                "{name} differs"
            ),
        }
    }
}

/// The flag that resumes a command run in an output folder.
fn resume_folder(_dir: &str) -> Vec<String> {
    vec!["--resume".to_string()]
}

/// Runs `args(out)` into two folders, the second killed after it stored `stored` (a path in
/// its folder) and resumed with `resume(out)` added, and compares them.
fn killed_and_resumed(
    name: &str,
    args: &dyn Fn(&str) -> Vec<String>,
    stored: &str,
    resume: &dyn Fn(&str) -> Vec<String>,
    timing: &[&str],
) {
    let (reference, resumed) = (scratch(&format!("{name}-ref")), scratch(name));
    let command = |dir: &Path, resuming: bool| -> Vec<String> {
        let dir = dir.display().to_string();
        let mut all = args(&dir);
        all.push("--quiet".to_string());
        if resuming {
            all.extend(resume(&dir));
        }
        all
    };
    let run = |v: Vec<String>| run_to_end(&v.iter().map(String::as_str).collect::<Vec<_>>());
    run(command(&reference, false));
    let killed = command(&resumed, false);
    kill_after_first_unit(
        &killed.iter().map(String::as_str).collect::<Vec<_>>(),
        &resumed.join(stored),
    );
    run(command(&resumed, true));
    same_outputs(&reference, &resumed, timing);
    for dir in [reference, resumed] {
        std::fs::remove_dir_all(dir).unwrap();
    }
}

/// `words` and then `--out DIR`.
fn with_out(words: &[&str], dir: &str) -> Vec<String> {
    words
        .iter()
        .map(|w| w.to_string())
        .chain(["--out".to_string(), dir.to_string()])
        .collect()
}

#[test]
fn n10_wear_killed_resumes_to_the_outputs_of_an_uninterrupted_run() {
    let model = example("2002834.toml");
    let args = |dir: &str| {
        with_out(
            &[
                "wear",
                &model,
                "--radial-load",
                "2kN",
                "--life",
                "1500h",
                "--period",
                "500h",
                "--settle",
                "0",
                "--revolutions",
                "1",
            ],
            dir,
        )
    };
    killed_and_resumed(
        "wear",
        &args,
        "wear.state",
        &resume_folder,
        &["dynamics_wall_s", "wear_wall_s"],
    );
}

#[test]
fn n10_tapered_wear_killed_resumes_to_the_outputs_of_an_uninterrupted_run() {
    let model = example("tapered-cassette.toml");
    let args = |dir: &str| {
        with_out(
            &[
                "wear",
                &model,
                "--life",
                "2000h",
                "--period",
                "500h",
                "--window-settle",
                "0.1ms",
                "--window",
                "0.2ms",
            ],
            dir,
        )
    };
    killed_and_resumed(
        "wear-tapered",
        &args,
        "wear.state",
        &resume_folder,
        &["wall_s"],
    );
}

#[test]
fn n10_startup_killed_resumes_to_the_outputs_of_an_uninterrupted_run() {
    let model = example("1032930.toml");
    let args = |dir: &str| {
        with_out(
            &[
                "startup",
                &model,
                "--points",
                "1,3",
                "--revolutions",
                "1",
                "--jobs",
                "1",
            ],
            dir,
        )
    };
    killed_and_resumed(
        "startup",
        &args,
        "startup.state",
        &resume_folder,
        &["wall_time_s"],
    );
}

#[test]
fn n10_fatigue_killed_resumes_to_the_outputs_of_an_uninterrupted_run() {
    let args = |dir: &str| with_out(&["fatigue", "--revolutions", "2"], dir);
    killed_and_resumed("fatigue", &args, "fatigue.state", &resume_folder, &[]);
}

#[test]
fn n10_tapered_simulate_killed_resumes_to_the_outputs_of_an_uninterrupted_run() {
    let model = example("tapered-cassette.toml");
    let args = |dir: &str| {
        let checkpoint = format!("{dir}/run.checkpoint");
        let mut words = with_out(
            &[
                "simulate",
                &model,
                "--duration",
                "0.3ms",
                "--output-step",
                "0.05ms",
                "--checkpoint-interval",
                "0.1ms",
                "--checkpoint",
            ],
            dir,
        );
        words.insert(words.len() - 2, checkpoint);
        words
    };
    killed_and_resumed(
        "simulate-tapered",
        &args,
        "run.checkpoint",
        &|dir| vec!["--resume".into(), format!("{dir}/run.checkpoint")],
        &[],
    );
}
