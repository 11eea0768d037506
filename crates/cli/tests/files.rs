//! Issue 39, the files rolldyn writes: output on a full disk or into a closed pipe (N1), a
//! checkpoint path that is not a regular file (N2), two runs on one output folder (N4), an
//! edited stored sweep result (N11) and SVG files the report must not inline (N5).

mod common;

use clap::CommandFactory;
use common::{example, rolldyn};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A fresh scratch folder for test `name`.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `rolldyn` with `args`, from the crate folder, its stdout (and with `full_stderr` its stderr
/// too) written to `/dev/full`.
fn to_full_disk(args: &[&str], full_stderr: bool) -> Output {
    let full = || {
        std::fs::File::options()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(full())
        .stderr(match full_stderr {
            true => Stdio::from(full()),
            false => Stdio::piped(),
        })
        .output()
        .expect("rolldyn runs")
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// A short run of every command that prints its answer on stdout (writing its output folders
/// under `dir`), by command name.
fn one_run_of_every_command(dir: &Path) -> Vec<(&'static str, Vec<String>)> {
    let model = example("2002834.toml");
    let sweep = dir.join("sweep.toml");
    std::fs::write(
        &sweep,
        format!("model = {model:?}\nanalysis = \"skid\"\n[[variant]]\nname = \"a\"\n"),
    )
    .unwrap();
    let out = |name: &str| dir.join(name).display().to_string();
    let runs: Vec<(&str, Vec<&str>)> = vec![
        ("demo", vec![]),
        ("check", vec![&model]),
        ("new", vec!["NU2215"]),
        ("contact", vec![&model, "--load", "1000N"]),
        ("oils", vec![]),
        ("traction", vec![]),
        ("film", vec!["--load", "1000N", "--rolling-speed", "5m/s"]),
        ("skid", vec![&model]),
        ("loads", vec![]),
        ("life", vec![&model]),
        ("simulate", vec![&model, "--duration", "0.2rev", "--quiet"]),
        ("sweep", vec![]),
        (
            "bench",
            vec![&model, "--duration", "0.2rev", "--repeat", "1", "--quiet"],
        ),
        ("startup", vec![]),
        (
            "wear",
            vec![
                "--life",
                "2h",
                "--period",
                "1h",
                "--revolutions",
                "1",
                "--settle",
                "1",
                "--quiet",
            ],
        ),
        ("fatigue", vec!["--revolutions", "1"]),
        ("study", vec!["skidding"]),
        (
            "journal",
            vec![
                "--radius",
                "50mm",
                "--length",
                "50mm",
                "--clearance",
                "0.05mm",
                "--viscosity",
                "0.05Pa s",
                "--speed",
                "3000rpm",
                "--eccentricity",
                "0.5",
            ],
        ),
        (
            "ehl-line",
            vec![
                "--radius",
                "10mm",
                "--viscosity",
                "0.1Pa s",
                "--rolling-speed",
                "1m/s",
                "--load-per-length",
                "1e5N/m",
            ],
        ),
        ("report", vec![]),
    ];
    let with_out: [(&str, Vec<String>); 6] = [
        ("loads", vec![example("tapered-cassette.toml")]),
        (
            "sweep",
            vec![
                sweep.display().to_string(),
                "--out".into(),
                out("sweep"),
                "--quiet".into(),
            ],
        ),
        (
            "startup",
            vec![
                example("1032930.toml"),
                "--points".into(),
                "1".into(),
                "--quiet".into(),
                "--out".into(),
                out("startup"),
            ],
        ),
        ("wear", vec!["--out".into(), out("wear")]),
        ("fatigue", vec!["--out".into(), out("fatigue")]),
        ("study", vec!["--out".into(), out("study")]),
    ];
    let mut runs: Vec<(&str, Vec<String>)> = runs
        .into_iter()
        .map(|(name, args)| {
            let mut all: Vec<String> = std::iter::once(name.to_string())
                .chain(args.into_iter().map(String::from))
                .collect();
            if let Some((_, more)) = with_out.iter().find(|(n, _)| *n == name) {
                all.extend(more.iter().cloned());
            }
            (name, all)
        })
        .collect();
    // `report` reads the folder the sweep wrote (the sweep runs before it)
    runs.iter_mut()
        .find(|(name, _)| *name == "report")
        .unwrap()
        .1
        .push(out("sweep"));
    runs
}

#[test]
fn n1_every_command_on_a_full_disk_says_so_in_one_line_and_exits_1() {
    let dir = scratch("full-disk");
    let runs = one_run_of_every_command(&dir);
    let commands: Vec<String> = rolldyn_cli::Cli::command()
        .get_subcommands()
        .map(|c| c.get_name().to_string())
        .collect();
    for command in &commands {
        assert!(
            runs.iter().any(|(name, _)| name == command),
            "no run of `{command}` in this test"
        );
    }
    for (name, args) in &runs {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let output = to_full_disk(&args, false);
        let text = stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{name}: {text}");
        let last = text.lines().last().unwrap_or_default();
        assert!(
            last.starts_with("rolldyn: cannot write output: No space left on device"),
            "{name}: {text}"
        );
        assert!(!text.contains("panicked"), "{name}: {text}");
        let output = to_full_disk(&args, true);
        assert_eq!(output.status.code(), Some(1), "{name}, stderr full too");
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn n1_bad_input_keeps_exit_2_when_stderr_is_full_and_help_on_a_full_disk_fails() {
    let output = to_full_disk(&["check", "no/such/model.toml"], true);
    assert_eq!(output.status.code(), Some(2));
    let output = to_full_disk(&["check", "--no-such-flag"], true);
    assert_eq!(output.status.code(), Some(2));
    for args in [&["--help"][..], &["--version"], &["check", "--help"]] {
        let output = to_full_disk(args, false);
        assert_eq!(output.status.code(), Some(1), "{args:?}");
        assert!(
            stderr(&output).starts_with("rolldyn: cannot write output: "),
            "{args:?}: {}",
            stderr(&output)
        );
    }
}

#[test]
fn n1_a_reader_that_goes_away_ends_the_output_quietly_with_exit_0() {
    for args in [&["skid", &example("2002834.toml")][..], &["oils", "--json"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // the reader goes away before the answer is printed
        drop(child.stdout.take());
        let output = child.wait_with_output().unwrap();
        assert_eq!(output.status.code(), Some(0), "{args:?}: {output:?}");
        assert_eq!(stderr(&output), "", "{args:?}");
    }
}

/// `simulate` of the default model for `duration` with `more` arguments.
fn simulate(duration: &str, more: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_rolldyn"));
    command
        .args([
            "simulate",
            &example("2002834.toml"),
            "--duration",
            duration,
            "--quiet",
        ])
        .args(more);
    command
}

#[cfg(unix)]
#[test]
fn n2_a_checkpoint_replaces_only_a_regular_file() {
    let dir = scratch("checkpoint");
    let precious = dir.join("precious.txt");
    std::fs::write(&precious, "keep").unwrap();
    let link = dir.join("link.ckpt");
    std::os::unix::fs::symlink(&precious, &link).unwrap();
    let fifo = dir.join("fifo.ckpt");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    for (path, what) in [
        (&link, "a symbolic link"),
        (&fifo, "a named pipe"),
        (&dir, "a folder"),
    ] {
        let output = simulate("0.2rev", &["--checkpoint", path.to_str().unwrap()])
            .output()
            .unwrap();
        let text = stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{what}: {text}");
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(
            text.contains("--checkpoint") && text.contains(what),
            "{text}"
        );
    }
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(std::fs::read_to_string(&precious).unwrap(), "keep");
    {
        use std::os::unix::fs::FileTypeExt;
        assert!(
            std::fs::symlink_metadata(&fifo)
                .unwrap()
                .file_type()
                .is_fifo()
        );
    }
    let regular = dir.join("run.ckpt");
    let output = simulate("0.2rev", &["--checkpoint", regular.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(regular.is_file());
    std::fs::remove_dir_all(dir).unwrap();
}

/// A child process killed when the test ends, also when it fails.
struct Running(std::process::Child);

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// Waits until the lock file of `out` names a holder.
fn wait_for_lock(out: &Path) -> String {
    let start = Instant::now();
    loop {
        let holder = std::fs::read_to_string(out.join(".rolldyn.lock")).unwrap_or_default();
        if holder.starts_with("pid ") {
            return holder;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no lock in {}",
            out.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn n4_a_second_writer_of_an_output_folder_is_refused_until_the_first_ends() {
    let dir = scratch("lock");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    // long enough to be running while the others try, with small tables
    let first = Running(
        simulate("50rev", &["--out", out_arg, "--output-step", "1ms"])
            .spawn()
            .unwrap(),
    );
    let pid = first.0.id();
    let holder = wait_for_lock(&out);
    assert!(holder.contains(&format!("pid {pid}")), "{holder}");
    let second = simulate("0.2rev", &["--out", out_arg]).output().unwrap();
    let text = stderr(&second);
    assert_eq!(second.status.code(), Some(2), "{text}");
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(
        text.contains(&format!(
            "--out {out_arg}: being written by another rolldyn run (pid {pid}"
        )),
        "{text}"
    );
    let report = rolldyn(&["report", out_arg]);
    assert_eq!(report.status.code(), Some(2), "{}", stderr(&report));
    // a killed holder leaves the lock file but not the lock
    drop(first);
    let third = simulate("0.2rev", &["--out", out_arg]).output().unwrap();
    assert_eq!(third.status.code(), Some(0), "{}", stderr(&third));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn n11_resume_reruns_an_edited_stored_result_and_says_so() {
    let dir = scratch("checksum");
    let sweep = dir.join("sweep.toml");
    std::fs::write(
        &sweep,
        format!(
            "model = {:?}\nanalysis = \"skid\"\n[[variant]]\nname = \"a\"\n",
            example("2002834.toml")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    let args = [
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ];
    let first = rolldyn(&args);
    assert_eq!(first.status.code(), Some(0), "{}", stderr(&first));
    let stored = out.join("variants/a.json");
    let text = std::fs::read_to_string(&stored).unwrap();
    let edited = text.replacen("\"wall_time_s\": ", "\"wall_time_s\": 1", 1);
    assert_ne!(edited, text);
    std::fs::write(&stored, edited).unwrap();
    let collected = rolldyn(&[&args[..], &["--collect-only"]].concat());
    assert_eq!(collected.status.code(), Some(0), "{}", stderr(&collected));
    let summary = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(summary.contains("damaged: checksum mismatch"), "{summary}");
    let resumed = rolldyn(&[&args[..], &["--resume"]].concat());
    let text = stderr(&resumed);
    assert_eq!(resumed.status.code(), Some(0), "{text}");
    assert!(
        text.contains("variant a: the stored result was not reused")
            && text.contains("damaged: checksum mismatch"),
        "{text}"
    );
    let summary = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(!summary.contains("damaged"), "{summary}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn n5_the_report_inlines_only_the_plots_the_run_wrote() {
    let dir = scratch("svg");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    let run = simulate("0.2rev", &["--out", out_arg]).output().unwrap();
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run.json")).unwrap()).unwrap();
    let files = manifest["files"]
        .as_object()
        .expect("run.json lists its files");
    let svg: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".svg"))
        .collect();
    assert!(!svg.is_empty());
    for name in &svg {
        assert_eq!(files[name].as_str().map(str::len), Some(16), "{name}");
    }
    let hostile = "<svg xmlns=\"http://www.w3.org/2000/svg\" onload=\"alert(1)\"><script>alert(2)</script>\
                   <foreignObject><iframe src=\"https://example.org\"></iframe></foreignObject></svg>";
    std::fs::write(out.join(&svg[0]), hostile).unwrap();
    std::fs::write(out.join("added.svg"), hostile).unwrap();
    let answer = common::json(&rolldyn(&["report", out_arg, "--json"]));
    let warnings = answer["warnings"].to_string();
    assert!(
        warnings.contains(&format!(
            "plot {} not shown: changed since the run wrote it",
            svg[0]
        )),
        "{warnings}"
    );
    assert!(
        warnings.contains("plot added.svg not shown: not written by the run"),
        "{warnings}"
    );
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    for markup in ["<script>alert", "onload=", "<iframe", "foreignObject"] {
        assert!(!html.contains(markup), "{markup} in the report");
    }
    assert!(html.contains("<svg"), "the other plots are shown");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn n4_shards_that_do_not_collect_share_the_folder_and_a_collecting_sweep_waits() {
    let dir = scratch("shards");
    let sweep = dir.join("sweep.toml");
    std::fs::write(
        &sweep,
        format!(
            "model = {:?}\nanalysis = \"skid\"\n[[variant]]\nname = \"a\"\n[[variant]]\nname = \"b\"\n",
            example("2002834.toml")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    // another shard running now
    let shard = rolldyn_output::FolderLock::acquire_shared(&out).unwrap();
    let args = [
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ];
    let this_shard = rolldyn(&[&args[..], &["--shard", "1/2", "--no-collect"]].concat());
    assert_eq!(this_shard.status.code(), Some(0), "{}", stderr(&this_shard));
    let collecting = rolldyn(&[&args[..], &["--collect-only"]].concat());
    assert_eq!(collecting.status.code(), Some(2), "{}", stderr(&collecting));
    drop(shard);
    let collecting = rolldyn(&[&args[..], &["--collect-only"]].concat());
    assert_eq!(collecting.status.code(), Some(0), "{}", stderr(&collecting));
    std::fs::remove_dir_all(dir).unwrap();
}
