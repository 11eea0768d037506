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
        |_: &Variant, model: rolldyn_model::Model| -> Result<BTreeMap<String, Figure>, String> {
            calls.fetch_add(1, Ordering::SeqCst);
            let rolldyn_model::BearingModel::Cylindrical(b) = model.bearing else {
                return Err("no".into());
            };
            Ok(BTreeMap::from([(
                "clearance_m".to_string(),
                Figure::Real(b.clearance.radial),
            )]))
        };
    let options = |shard: Option<Shard>, resume: bool| RunOptions {
        out_dir: out.clone(),
        jobs: 2,
        shard,
        resume,
        settings: "stand-in".into(),
    };
    let first = run(
        &sweep,
        &options(Some("1/2".parse().unwrap()), false),
        &analysis,
        &|_, _, _| {},
        &|| false,
    )
    .unwrap();
    assert_eq!(
        first.iter().map(|o| o.index).collect::<Vec<_>>(),
        vec![0, 2, 4]
    );
    run(
        &sweep,
        &options(None, true),
        &analysis,
        &|_, _, _| {},
        &|| false,
    )
    .unwrap();
    assert_eq!(
        calls.load(Ordering::SeqCst),
        6,
        "resume skips the finished variants"
    );
    assert_eq!(collect(&sweep, &options(None, true)).unwrap().rows, 6);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert_eq!(csv.lines().count(), 7);
    assert!(
        csv.lines().nth(3).unwrap().starts_with("v2,1e-5,2,1e-5"),
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
    assert_eq!(sweep.duration.as_deref(), Some("20rev"));
    assert_eq!(sweep.discard.as_deref(), Some("10rev"));
}

#[test]
fn the_tapered_load_cases_sweep_has_the_seed_cases() {
    // seed 000 §3.2.1 (V-09): Fr 118 862 N; Fr 32 568 N + Fa 31 192 N; Fr 118 862 N + 4′
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/tapered-cassette-cases.toml");
    let sweep = SweepFile::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let loads: Vec<(f64, f64, f64)> = sweep
        .variants
        .iter()
        .map(|v| {
            let model = sweep.model_of(v).unwrap_or_else(|e| panic!("{e}"));
            let tilt = model.bearing.misalignment().inner_ring_tilt;
            let op = &model.operating;
            (op.radial_load.unwrap(), op.axial_load.unwrap(), tilt)
        })
        .collect();
    let arcmin = std::f64::consts::PI / 10_800.0;
    assert_eq!(loads.len(), 3);
    assert_eq!((loads[0].0, loads[0].1), (118_862.0, 0.0));
    assert_eq!((loads[1].0, loads[1].1), (32_568.0, 31_192.0));
    assert!((loads[2].2 - 4.0 * arcmin).abs() < 1e-15);
}

/// Options of a single-job run into `out`, without solver settings.
fn one_job(out: &std::path::Path, resume: bool) -> RunOptions {
    RunOptions {
        out_dir: out.to_path_buf(),
        jobs: 1,
        shard: None,
        resume,
        settings: String::new(),
    }
}

/// The stand-in analysis of these tests: the radial clearance of the variant's model.
fn clearance(model: rolldyn_model::Model) -> Result<BTreeMap<String, Figure>, String> {
    let rolldyn_model::BearingModel::Cylindrical(b) = model.bearing else {
        return Err("not cylindrical".into());
    };
    Ok(BTreeMap::from([(
        "clearance_m".to_string(),
        Figure::Real(b.clearance.radial),
    )]))
}

fn clearance_variants(clearances_um: &[u32]) -> String {
    clearances_um
        .iter()
        .enumerate()
        .map(|(i, c)| format!("[[variant]]\nname = \"v{i}\"\n\"clearance.radial\" = \"{c} um\"\n"))
        .collect()
}

#[test]
fn resume_recomputes_variants_whose_inputs_changed() {
    let dir = scratch("fingerprint");
    let out = dir.join("out");
    let options = |settings: &str| RunOptions {
        out_dir: out.clone(),
        jobs: 1,
        shard: None,
        resume: true,
        settings: settings.into(),
    };
    let analysis = |_: &Variant, model: rolldyn_model::Model| clearance(model);
    let names = |outcomes: &[VariantOutcome]| -> Vec<(String, bool)> {
        outcomes
            .iter()
            .map(|o| (o.name.clone(), o.inputs_changed))
            .collect()
    };
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5, 10]))).unwrap();
    assert_eq!(
        run(&sweep, &options("a"), &analysis, &|_, _, _| {}, &|| false)
            .unwrap()
            .len(),
        3
    );
    assert!(
        run(&sweep, &options("a"), &analysis, &|_, _, _| {}, &|| false)
            .unwrap()
            .is_empty()
    );

    let edited = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 7, 10]))).unwrap();
    let rerun = run(&edited, &options("a"), &analysis, &|_, _, _| {}, &|| false).unwrap();
    assert_eq!(names(&rerun), vec![("v1".to_string(), true)]);
    assert_eq!(collect(&edited, &options("a")).unwrap().rows, 3);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(
        csv.lines().nth(2).unwrap().starts_with("v1,7e-6,1,7e-6"),
        "{csv}"
    );

    let rerun = run(&edited, &options("b"), &analysis, &|_, _, _| {}, &|| false).unwrap();
    assert_eq!(
        rerun.len(),
        3,
        "changed settings (duration, tolerance) rerun every variant"
    );
    assert!(rerun.iter().all(|o| o.inputs_changed));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn collect_blanks_results_of_changed_inputs() {
    let dir = scratch("stale");
    let out = dir.join("out");
    let options = one_job(&out, false);
    let analysis = |_: &Variant, model: rolldyn_model::Model| clearance(model);
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5]))).unwrap();
    run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    let edited = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 6]))).unwrap();
    assert_eq!(collect(&edited, &options).unwrap().rows, 2);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let row = csv.lines().nth(2).unwrap();
    assert!(
        row.starts_with("v1,6e-6,1,,") && row.contains("inputs changed"),
        "{csv}"
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn an_unreadable_result_keeps_its_row_with_the_reason() {
    let dir = scratch("unreadable");
    let out = dir.join("out");
    let options = one_job(&out, true);
    let analysis = |_: &Variant, model: rolldyn_model::Model| clearance(model);
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5]))).unwrap();
    run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    std::fs::write(out.join("variants/v1.json"), "{\"name\": \"v1\", trunc").unwrap();
    assert_eq!(collect(&sweep, &options).unwrap().rows, 2);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let row = csv.lines().nth(2).unwrap();
    assert!(
        row.starts_with("v1,5e-6,1,,") && row.contains("cannot read"),
        "{csv}"
    );
    let rerun = run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    assert_eq!(rerun.len(), 1, "resume runs the variant again");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn summary_parquet_has_the_variant_and_error_columns_of_the_csv() {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::RowAccessor;
    let dir = scratch("parquet");
    let out = dir.join("out");
    let options = one_job(&out, false);
    let analysis = |v: &Variant, model: rolldyn_model::Model| {
        if v.name == "v1" {
            return Err("no solution".to_string());
        }
        clearance(model)
    };
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5]))).unwrap();
    run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    collect(&sweep, &options).unwrap();
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert_eq!(csv.lines().nth(2), Some("v1,5e-6,1,,no solution"), "{csv}");
    let reader =
        SerializedFileReader::new(std::fs::File::open(out.join("summary.parquet")).unwrap())
            .unwrap();
    let names: Vec<String> = reader
        .metadata()
        .file_metadata()
        .schema_descr()
        .columns()
        .iter()
        .map(|c| c.name().to_string())
        .collect();
    // Parquet names have no dots: `clearance.radial_m` of the CSV is `clearance_radial_m`
    assert_eq!(
        names,
        [
            "variant",
            "clearance_radial_m",
            "index",
            "clearance_m",
            "error"
        ]
    );
    let rows: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(|r| r.unwrap())
        .collect();
    assert_eq!(rows[0].get_string(0).unwrap(), "v0");
    assert!(rows[0].get_string(4).is_err(), "no error: null");
    assert_eq!(rows[1].get_string(0).unwrap(), "v1");
    assert_eq!(rows[1].get_double(1).unwrap(), 5e-6, "the varied key in SI");
    assert!(rows[1].get_double(3).is_err(), "failed: null value");
    assert_eq!(rows[1].get_string(4).unwrap(), "no solution");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_variant_starts_from_a_named_variant_of_another_file() {
    let dir = scratch("like");
    let library = write_sweep(
        &dir,
        "[[variant]]\nname = \"14\"\n\"roller.count\" = 24\n\"clearance.radial\" = \"0.005 mm\"\n",
    );
    std::fs::rename(&library, dir.join("library.toml")).unwrap();
    let path = write_sweep(
        &dir,
        "variants_from = \"library.toml\"\n[[variant]]\nname = \"14-smooth\"\nlike = \"14\"\n\"clearance.radial\" = \"0.009 mm\"\n",
    );
    let sweep = SweepFile::load(&path).unwrap();
    let v = &sweep.variants[0];
    assert_eq!(v.overrides.len(), 2);
    assert!(
        v.overrides
            .contains(&("roller.count".into(), toml::Value::Integer(24)))
    );
    assert!(v.overrides.contains(&(
        "clearance.radial".into(),
        toml::Value::String("0.009 mm".into())
    )));
    let bad = write_sweep(
        &dir,
        "variants_from = \"library.toml\"\n[[variant]]\nname = \"x\"\nlike = \"99\"\n",
    );
    assert!(
        SweepFile::load(&bad)
            .unwrap_err()
            .to_string()
            .contains("no variant '99'")
    );
}

/// The summary carries one column per varied model key after the variant name (SI with its
/// unit in the name, whole numbers as integers, the base model's value where a variant does
/// not override the key), and counts as integers.
#[test]
fn the_summary_has_the_varied_keys_as_columns() {
    let dir = scratch("varied");
    let out = dir.join("out");
    let options = one_job(&out, false);
    let sweep = SweepFile::load(&write_sweep(
        &dir,
        "[[variant]]\nname = \"a\"\n\"operating.inner_speed\" = \"4000 rpm\"\n\
         [[variant]]\nname = \"b\"\n\"roller.count\" = 16\n",
    ))
    .unwrap();
    let analysis = |_: &Variant, _: rolldyn_model::Model| {
        Ok(BTreeMap::from([("steps".to_string(), Figure::Integer(12))]))
    };
    run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    let summary = collect(&sweep, &options).unwrap();
    assert_eq!(
        summary.varied,
        ["operating.inner_speed_rad_s", "roller.count"]
    );
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "variant,operating.inner_speed_rad_s,roller.count,index,steps,error"
    );
    // the base model: 8163 rpm and 18 rollers
    assert!(lines[1].starts_with("a,4.18879"), "{csv}");
    assert!(lines[1].ends_with(",18,0,12,"), "{csv}");
    assert!(lines[2].starts_with("b,8.548"), "{csv}");
    assert!(lines[2].ends_with(",16,1,12,"), "{csv}");
    assert!(out.join("steps.svg").is_file());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_stop_request_starts_no_further_variant() {
    let dir = scratch("stop");
    let out = dir.join("out");
    let options = one_job(&out, false);
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5, 10]))).unwrap();
    let seen = AtomicUsize::new(0);
    let analysis = |_: &Variant, model: rolldyn_model::Model| clearance(model);
    let ran = run(
        &sweep,
        &options,
        &analysis,
        &|o, done, total| {
            assert_eq!((total, o.name.as_str()), (3, "v0"));
            seen.store(done, Ordering::SeqCst);
        },
        &|| seen.load(Ordering::SeqCst) >= 1,
    )
    .unwrap();
    assert_eq!(ran.len(), 1);
    let resumed = run(
        &sweep,
        &one_job(&out, true),
        &analysis,
        &|_, _, _| {},
        &|| false,
    )
    .unwrap();
    assert_eq!(resumed.len(), 2, "resume runs the variants not started");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn n11_an_edited_result_is_not_reused_by_resume_nor_collected() {
    let dir = scratch("checksum");
    let out = dir.join("out");
    let options = one_job(&out, true);
    let analysis = |_: &Variant, model: rolldyn_model::Model| clearance(model);
    let sweep = SweepFile::load(&write_sweep(&dir, &clearance_variants(&[0, 5]))).unwrap();
    run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    let stored = out.join("variants/v1.json");
    let text = std::fs::read_to_string(&stored).unwrap();
    let edited = text.replacen("\"wall_time_s\": ", "\"wall_time_s\": 1", 1);
    assert_ne!(edited, text);
    std::fs::write(&stored, edited).unwrap();

    assert_eq!(collect(&sweep, &options).unwrap().rows, 2);
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let row = csv.lines().nth(2).unwrap();
    assert!(
        row.starts_with("v1,5e-6,1,,") && row.contains("damaged: checksum mismatch"),
        "{csv}"
    );

    let rerun = run(&sweep, &options, &analysis, &|_, _, _| {}, &|| false).unwrap();
    assert_eq!(rerun.len(), 1, "resume runs the damaged variant again");
    assert!(
        rerun[0]
            .replaced_damaged
            .as_deref()
            .is_some_and(|why| why.contains("damaged: checksum mismatch")),
        "{:?}",
        rerun[0].replaced_damaged
    );
    collect(&sweep, &options).unwrap();
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let row = csv.lines().nth(2).unwrap();
    assert!(
        row.starts_with("v1,5e-6,1,") && !row.contains("damaged"),
        "{csv}"
    );
    std::fs::remove_dir_all(dir).ok();
}
