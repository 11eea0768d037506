//! `rolldyn simulate` on a double-row tapered bearing (seed 000 §3.2.1): the run, its table
//! and plots with `--out`, the summary.

use super::simulate::{Args, progress_bar};
use crate::failure::Failure;
use crate::output::{out_dir, print_json};
use rolldyn_dynamics::tapered::{
    SAMPLE_COLUMNS, TaperedRun, TaperedRunSettings, TaperedSample, run, sample_row, summary_entries,
};
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot};
use std::path::Path;

/// Runs the tapered model of `model` as `simulate` asks.
pub fn run_tapered(args: &Args, model: &rolldyn_model::Model) -> Result<(), Failure> {
    let tm = rolldyn_setup::prepare_tapered(model, &args.operating.overrides())?;
    let revolution = std::f64::consts::TAU / tm.epicyclic_cage_speed.abs();
    let t_end = args
        .duration
        .end_time(Some(revolution))
        .map_err(Failure::Input)?;
    let mut settings = TaperedRunSettings {
        duration_s: t_end,
        sample_interval_s: args.output_step.si(),
        ..TaperedRunSettings::default()
    };
    if let Some(tol) = args.tolerance {
        settings.integrator.tolerance = tol;
    }
    if let Some(method) = args.integrator {
        settings.integrator.method = method.method();
    }
    let dir = args.out.as_deref().map(out_dir).transpose()?;
    let bar = progress_bar(args.quiet, t_end);
    let wall = std::time::Instant::now();
    let result = run(&tm, &settings, |t| {
        bar.set_position((1000.0 * t / t_end).min(1000.0) as u64)
    });
    bar.finish_and_clear();
    let outcome = result.map_err(|e| Failure::Run(format!("the simulation stopped: {e}")))?;
    let wall_s = wall.elapsed().as_secs_f64();
    if let Some(dir) = &dir {
        write_outputs(dir, &outcome)?;
    }
    let mut entries = summary_entries(&outcome.summary);
    entries.push(("simulated_s".into(), t_end));
    entries.push(("wall_time_s".into(), wall_s));
    entries.push(("steps".into(), outcome.steps as f64));
    if args.json {
        let mut map = serde_json::Map::new();
        map.insert("model".into(), model.bearing.name().into());
        for (k, v) in &entries {
            map.insert(k.clone(), serde_json::json!(v));
        }
        if let Some(c) = &outcome.most_limiting {
            map.insert("most_limiting".into(), c.clone().into());
        }
        if let Some(d) = &dir {
            map.insert("out".into(), d.display().to_string().into());
        }
        return print_json(&serde_json::Value::Object(map));
    }
    println!(
        "{} — double-row tapered, {t_end:.4} s simulated",
        model.bearing.name()
    );
    for (k, v) in &entries {
        println!("  {k:32} {v:.6e}");
    }
    Ok(())
}

/// `tapered.csv`/`.parquet` and the plots of seed 000 Figs. 3.75–3.81.
fn write_outputs(dir: &Path, run: &TaperedRun) -> Result<(), Failure> {
    let names: Vec<String> = SAMPLE_COLUMNS.iter().map(|s| s.to_string()).collect();
    let fail = |e: rolldyn_output::OutputError| Failure::Run(e.to_string());
    let mut table =
        TableWriter::create(dir, "tapered", &names, Formats::default()).map_err(fail)?;
    for s in &run.samples {
        table.write_row(&sample_row(s)).map_err(fail)?;
    }
    table.finish().map_err(fail)?;
    let curve = |f: &dyn Fn(&TaperedSample) -> (f64, f64)| -> Vec<(f64, f64)> {
        run.samples.iter().map(f).collect()
    };
    let ms = 1e3;
    let um = 1e6;
    let plots: [(&str, &str, &str, Vec<(String, Vec<(f64, f64)>)>); 5] = [
        (
            "inner_ring_axial.svg",
            "Inner-ring axial displacement",
            "axial displacement, µm",
            vec![(
                "z".into(),
                curve(&|s| (s.time_s * ms, s.inner_ring[2] * um)),
            )],
        ),
        (
            "inner_ring_trajectory.svg",
            "Inner-ring centre trajectory",
            "y, µm",
            vec![(
                "centre".into(),
                curve(&|s| (s.inner_ring[0] * um, s.inner_ring[1] * um)),
            )],
        ),
        (
            "cage_speeds.svg",
            "Cage speeds",
            "cage speed, rad/s",
            (0..2)
                .map(|k| {
                    (
                        format!("cage {k}"),
                        curve(&|s| (s.time_s * ms, s.cage_speed[k])),
                    )
                })
                .collect(),
        ),
        (
            "rib_forces.svg",
            "Roller 0: large-end and small-end rib forces",
            "force, N",
            (0..2)
                .flat_map(|k| {
                    [
                        (
                            format!("row {k} large end"),
                            curve(&|s| (s.time_s * ms, s.tracked_large_rib[k])),
                        ),
                        (
                            format!("row {k} small end"),
                            curve(&|s| (s.time_s * ms, s.tracked_small_rib[k])),
                        ),
                    ]
                })
                .collect(),
        ),
        (
            "max_roller_loads.svg",
            "Largest roller load on the cone per row",
            "load, N",
            (0..2)
                .map(|k| {
                    (
                        format!("row {k}"),
                        curve(&|s| (s.time_s * ms, s.max_cone_load[k])),
                    )
                })
                .collect(),
        ),
    ];
    for (file, title, y, curves) in plots {
        let x = if file == "inner_ring_trajectory.svg" {
            "x, µm"
        } else {
            "time, ms"
        };
        line_plot(
            &dir.join(file),
            &Labels { title, x, y },
            &Series::from_pairs(&curves),
        )
        .map_err(|e| Failure::Run(e.to_string()))?;
    }
    Ok(())
}
