//! Stability of the wear–dynamics loop against its recalculation period (seed 000 §3.2.3,
//! docs/theory.md §8.8; VALIDATION.md "Wear", §6.6 study): the embedded 2002834 over 25 000 h
//! with fixed periods of 12 500 … 952.5 h and with the automatic period, the depth of every
//! surface at the end and its history.
//!
//! Run: `cargo run --release -p rolldyn-validation --example wear_period_stability -- OUT_DIR`
//! (about 8 min on 2 cores; two lives at a time).

use rolldyn_geometry::BearingModel;
use rolldyn_plot::{Labels, Series, line_plot};
use rolldyn_wear::life::{LifeInputs, LifeRun, halved_period_check, run_life};
use rolldyn_wear::{PeriodControl, Surface, WearSettings};
use std::fmt::Write as _;
use std::path::PathBuf;

const HOUR: f64 = 3600.0;

/// Labelled depth histories (time h, depth µm), one per period control.
type Curves = Vec<(String, Vec<(f64, f64)>)>;
const PERIODS_H: [f64; 5] = [12_500.0, 6_250.0, 3_810.0, 1_905.0, 952.5];

fn main() -> Result<(), String> {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .ok_or("usage: wear_period_stability OUT_DIR")?,
    );
    std::fs::create_dir_all(&out).map_err(|e| e.to_string())?;
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml")
        .map_err(|e| e.to_string())?;
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Err("not cylindrical".into());
    };
    let lubrication = model.lubrication.as_ref().ok_or("no lubricant")?;
    let conditions = rolldyn_setup::conditions(&Default::default(), &model).map_err(|e| e.0)?;
    let inputs = LifeInputs {
        bearing,
        lubrication,
        dynamics: &model.dynamics,
        conditions: &conditions,
    };
    let settings = |period| WearSettings {
        period,
        ..WearSettings::default()
    };
    let controls: Vec<(String, PeriodControl)> = PERIODS_H
        .iter()
        .map(|&p| (format!("{p} h"), PeriodControl::Fixed(p * HOUR)))
        .chain([("auto".to_string(), PeriodControl::auto(1905.0 * HOUR))])
        .collect();
    let run = |control: PeriodControl| -> Result<(LifeRun, f64), String> {
        let wall = std::time::Instant::now();
        let label = format!("{control:?}");
        let life = run_life(&inputs, &settings(control), None, &mut |state| {
            eprintln!("{label}: {:.0} h", state.time_s / HOUR);
            std::ops::ControlFlow::Continue(())
        })
        .map_err(|e| e.to_string())?;
        Ok((life, wall.elapsed().as_secs_f64()))
    };
    // two lives at a time: the even and the odd controls
    let (even, odd): (Vec<(usize, PeriodControl)>, Vec<_>) = controls
        .iter()
        .map(|(_, c)| c.clone())
        .enumerate()
        .partition(|(i, _)| i % 2 == 0);
    let results: Vec<Result<(LifeRun, f64), String>> = std::thread::scope(|scope| {
        let run = &run;
        let spawn = |part: Vec<(usize, PeriodControl)>| {
            scope.spawn(move || {
                part.into_iter()
                    .map(|(i, c)| (i, run(c)))
                    .collect::<Vec<_>>()
            })
        };
        let (a, b) = (spawn(even), spawn(odd));
        let mut all: Vec<_> = a
            .join()
            .unwrap()
            .into_iter()
            .chain(b.join().unwrap())
            .collect();
        all.sort_by_key(|(i, _)| *i);
        all.into_iter().map(|(_, r)| r).collect()
    });
    let mut csv = String::from("period,periods,halvings,wall_s");
    for s in Surface::ALL {
        write!(csv, ",{}_um", s.name()).unwrap();
    }
    csv.push_str(",clearance_increase_um\n");
    let mut curves: Vec<(Surface, Curves)> =
        Surface::ALL.iter().map(|&s| (s, Vec::new())).collect();
    for ((label, _), result) in controls.iter().zip(&results) {
        let (life, wall) = result.as_ref().map_err(|e| format!("{label}: {e}"))?;
        let halvings: u32 = life.periods.iter().map(|p| p.halvings).sum();
        write!(csv, "{label},{},{halvings},{wall:.1}", life.periods.len()).unwrap();
        for s in Surface::ALL {
            write!(csv, ",{:.4}", life.depth.max(s) * 1e6).unwrap();
        }
        writeln!(csv, ",{:.4}", life.depth.clearance_increase() * 1e6).unwrap();
        for (s, c) in curves.iter_mut() {
            let points = std::iter::once((0.0, 0.0))
                .chain(
                    life.periods
                        .iter()
                        .map(|p| (p.time_h, p.max_depth_m.get(*s) * 1e6)),
                )
                .collect();
            c.push((label.clone(), points));
        }
    }
    // the automatic period's own evidence: the life again with half its shortest period
    let auto = results
        .last()
        .and_then(|r| r.as_ref().ok())
        .map(|(l, _)| l)
        .ok_or("auto run missing")?;
    let (check, difference) =
        halved_period_check(&inputs, &settings(PeriodControl::auto(1905.0 * HOUR)), auto)
            .map_err(|e| e.to_string())?;
    write!(
        csv,
        "auto halved ({} h),{},0,",
        check.periods[0].period_h,
        check.periods.len()
    )
    .unwrap();
    for s in Surface::ALL {
        write!(csv, ",{:.4}", check.depth.max(s) * 1e6).unwrap();
    }
    writeln!(csv, ",{:.4}", check.depth.clearance_increase() * 1e6).unwrap();
    write!(csv, "auto vs halved,,,").unwrap();
    for s in Surface::ALL {
        write!(csv, ",{:+.2}%", difference.get(s) * 100.0).unwrap();
    }
    csv.push_str(",\n");
    std::fs::write(out.join("period-stability.csv"), &csv).map_err(|e| e.to_string())?;
    print!("{csv}");
    for (s, c) in &curves {
        let title = format!(
            "2002834, {} wear over the life by recalculation period",
            s.name().replace('_', " ")
        );
        line_plot(
            &out.join(format!(
                "period-stability-{}.svg",
                s.name().replace('_', "-")
            )),
            &Labels {
                title: &title,
                x: "operating time, h",
                y: "largest depth, µm",
            },
            &Series::from_pairs(c),
        )
        .map_err(|e| e.to_string())?;
    }
    Ok(())
}
