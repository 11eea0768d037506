//! Sweep files, overrides, sharding, resume and collection (with a stand-in analysis).

use rolldyn_sweep::*;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-sweep-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write_sweep(dir: &std::path::Path, body: &str) -> PathBuf {
    let model = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/2002834.toml");
    std::fs::copy(model, dir.join("model.toml")).unwrap();
    let path = dir.join("sweep.toml");
    std::fs::write(
        &path,
        format!("model = \"model.toml\"\nduration = \"1rev\"\n{body}"),
    )
    .unwrap();
    path
}

#[test]
fn overrides_reach_nested_keys_and_arrays() {
    let text = include_str!("../../../examples/2002834.toml");
    let out = apply_overrides(
        text,
        &[
            ("roller.count".into(), toml::Value::Integer(24)),
            (
                "roller.profile.drop".into(),
                toml::Value::String("0.0075 mm".into()),
            ),
            (
                "inner_ring.ribs.0.face".into(),
                toml::Value::Table(toml::toml! { kind = "convex-torus"
                radius = "430 mm" }),
            ),
        ],
    )
    .unwrap();
    let model = rolldyn_model::parse(&out, "x.toml").unwrap();
    let rolldyn_model::BearingModel::Cylindrical(b) = model.bearing else {
        panic!()
    };
    assert_eq!(b.roller_count, 24);
    assert!(matches!(
        b.inner_ring.ribs[0].face,
        rolldyn_geometry::RibFace::ConvexTorus { .. }
    ));
    assert!(
        apply_overrides(
            text,
            &[("inner_ring.ribs.7.diameter".into(), toml::Value::Integer(1))]
        )
        .is_err()
    );
}

#[test]
fn bad_variants_are_rejected_with_file_and_key() {
    let dir = scratch("bad");
    let path = write_sweep(&dir, "[[variant]]\nname = \"a\"\n\"roller.count\" = 40\n");
    let err = SweepFile::load(&path).unwrap_err().to_string();
    assert!(
        err.contains("sweep.toml") && err.contains("variant[0] (a)") && err.contains("overlap"),
        "{err}"
    );
    let path = write_sweep(&dir, "[[variant]]\nname = \"a\"\n\"roller.colour\" = 1\n");
    assert!(
        SweepFile::load(&path)
            .unwrap_err()
            .to_string()
            .contains("colour")
    );
    let path = write_sweep(&dir, "speed = 1\n[[variant]]\nname = \"a\"\n");
    assert!(
        SweepFile::load(&path)
            .unwrap_err()
            .to_string()
            .contains("speed")
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn shards_resume_and_collect() {
    let dir = scratch("run");
    let body: String = (0..6)
        .map(|i| {
            format!(
                "[[variant]]\nname = \"v{i}\"\n\"clearance.radial\" = \"{} um\"\n",
                i * 5
            )
        })
        .collect();
    let sweep = SweepFile::load(&write_sweep(&dir, &body)).unwrap();
    let out = dir.join("out");
    let calls = AtomicUsize::new(0);
    let analysis =
        |_: &Variant, model: rolldyn_model::Model| -> Result<BTreeMap<String, f64>, String> {
            calls.fetch_add(1, Ordering::SeqCst);
            let rolldyn_model::BearingModel::Cylindrical(b) = model.bearing else {
                return Err("no".into());
            };
            Ok(BTreeMap::from([(
                "clearance_m".to_string(),
                b.clearance.radial,
            )]))
        };
    let options = |shard: Option<Shard>, resume: bool| RunOptions {
        out_dir: out.clone(),
        jobs: 2,
        shard,
        resume,
    };
    let first = run(
        &sweep,
        &options(Some("1/2".parse().unwrap()), false),
        &analysis,
        &|_| {},
    )
    .unwrap();
    assert_eq!(
        first.iter().map(|o| o.index).collect::<Vec<_>>(),
        vec![0, 2, 4]
    );
    run(&sweep, &options(None, true), &analysis, &|_| {}).unwrap();
    assert_eq!(
        calls.load(Ordering::SeqCst),
        6,
        "resume skips the finished variants"
    );
    assert_eq!(collect(&sweep, &out).unwrap(), 6);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert_eq!(csv.lines().count(), 7);
    assert!(
        csv.lines().nth(3).unwrap().starts_with("v2,2,1e-5"),
        "{csv}"
    );
    assert!(out.join("summary.parquet").is_file() && out.join("clearance_m.svg").is_file());
    assert!("0/3".parse::<Shard>().is_err() && "4/3".parse::<Shard>().is_err());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn seed000_table_3_1_sweep_has_21_valid_variants() {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/2002834/table-3.1.toml");
    let sweep = SweepFile::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(sweep.variants.len(), 21);
    let v36 = sweep.variants.iter().find(|v| v.name == "36").unwrap();
    let model = sweep.model_of(v36).unwrap();
    assert!(
        (model.bearing.misalignment().inner_ring_tilt - 12.0 * std::f64::consts::PI / 10_800.0)
            .abs()
            < 1e-12
    );
    let rolldyn_model::BearingModel::Cylindrical(b) = model.bearing else {
        panic!()
    };
    assert!((b.clearance.radial - 0.044e-3).abs() < 1e-12);
    assert_eq!(sweep.duration.as_deref(), Some("10rev"));
}
