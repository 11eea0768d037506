//! The sweep analysis through `rolldyn::run_json`: the summary carries the varied model key as
//! a column (SI, unit in the name), a stop request starts no variant, an unknown field is refused.

use rolldyn::{Context, Failure, ModelSource, Observer, Unobserved, run_json};
use std::path::{Path, PathBuf};

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

fn example(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
        .display()
        .to_string()
        .replace('\\', "/")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-lib-sweep-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A skid sweep of the O'Brien–Taylor bearing over the radial load.
fn write_sweep(dir: &Path) -> PathBuf {
    let file = dir.join("loads.toml");
    std::fs::write(
        &file,
        format!(
            "model = \"{}\"\nanalysis = \"skid\"\n\
             [[variant]]\nname = \"light\"\n\"operating.radial_load\" = \"104 N\"\n\
             [[variant]]\nname = \"heavy\"\n\"operating.radial_load\" = \"0.687 kN\"\n",
            example("obrien-taylor.toml")
        ),
    )
    .unwrap();
    file
}

fn request(file: &Path, out: &Path) -> String {
    serde_json::json!({"sweep": file, "out": out, "jobs": 1, "shard": "1/1"}).to_string()
}

#[test]
fn the_summary_has_the_varied_key_as_a_column() {
    let dir = scratch("varied");
    let (file, out) = (write_sweep(&dir), dir.join("out"));
    let context = Context::new(ModelSource::Embedded, &Unobserved);
    let answer = run_json("sweep", &request(&file, &out), &context).unwrap();
    assert_eq!(summary(&answer)["ran"], 2);
    assert_eq!(
        summary(&answer)["varied"],
        serde_json::json!(["operating.radial_load_n"])
    );
    let table = &answer.tables[0];
    assert_eq!(table.name, "summary");
    let names: Vec<&str> = table.columns.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names[..3], ["variant", "operating.radial_load_n", "index"]);
    assert_eq!(
        table.columns[1].values,
        rolldyn::ColumnValues::Real(vec![104.0, 687.0])
    );
    assert_eq!(
        table.columns[2].values,
        rolldyn::ColumnValues::Integer(vec![0, 1])
    );
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(
        csv.starts_with("variant,operating.radial_load_n,index,"),
        "{csv}"
    );
    assert!(
        csv.lines().nth(2).unwrap().starts_with("heavy,6.87e2,1,"),
        "{csv}"
    );
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run.json")).unwrap()).unwrap();
    assert_eq!(manifest["summary"]["varied"][0], "operating.radial_load_n");
    std::fs::remove_dir_all(dir).ok();
}

struct Stop;

impl Observer for Stop {
    fn stop_requested(&self) -> bool {
        true
    }
}

#[test]
fn a_stop_request_starts_no_variant_and_says_interrupted() {
    let dir = scratch("stop");
    let (file, out) = (write_sweep(&dir), dir.join("out"));
    let context = Context::new(ModelSource::Embedded, &Stop);
    let Err(Failure::Run(message)) = run_json("sweep", &request(&file, &out), &context) else {
        panic!("an interrupted sweep is a failed run")
    };
    assert!(
        message.contains("interrupted") && message.contains("--resume"),
        "{message}"
    );
    assert!(!out.join("variants/light.json").exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn an_unknown_field_is_refused_by_name() {
    let context = Context::default();
    let Err(Failure::Input(message)) =
        run_json("sweep", r#"{"sweep": "x.toml", "resmue": true}"#, &context)
    else {
        panic!("an unknown field is bad input")
    };
    assert!(message.contains("resmue"), "{message}");
}
