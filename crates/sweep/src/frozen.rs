//! Quasi-steady start-up analysis at frozen time points (seed 000 §3.1.2, SPEC §3.1, V-08).
//!
//! A start-up (speed, loads, clearance and temperature varying over minutes) is evaluated at a
//! few frozen times: at each the schedules are taken as constants and a constant-condition run
//! is taken to steady state. SPEC §3.1: step-change transients of the 1032930 start-up settle
//! within ≈ 2.5 s, which justifies the frozen points. This module runs the points in parallel
//! (the analysis of one point is supplied by the caller, e.g. the dynamics of `rolldyn
//! startup`) and writes the table `startup.csv` / `startup.parquet` and the plots.

use rayon::prelude::*;
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot};
use serde::Serialize;
use std::path::Path;

/// A start-up run could not be completed (thread pool, files).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct StartupError(pub String);

/// The figures of one frozen point (SI units; NaN where a value is not available).
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct FrozenPointRow {
    /// Label of the point (e.g. the seed's point number).
    pub label: String,
    /// Frozen time of the start-up, s.
    pub time_s: f64,
    /// Inner-ring speed at that time, rad/s.
    pub inner_speed_rad_s: f64,
    /// Magnitude of the loads fixed in space (weight share, gearbox load…), N.
    pub fixed_load_n: f64,
    /// Magnitude of the loads rotating with the shaft (unbalance U ω²), N.
    pub rotating_load_n: f64,
    /// Operating radial (diametral) clearance, m (negative: preload).
    pub clearance_m: f64,
    /// Oil temperature of the inner-raceway contacts, K.
    pub oil_temperature_k: f64,
    /// Dynamic cage slip 1 − ω_c/ω_epicyclic, mean over the last revolutions.
    pub cage_slip_dynamic: f64,
    /// Quasi-static cage slip (seed 001 model) at the same conditions.
    pub cage_slip_quasi_static: f64,
    /// Largest roller–raceway normal force over the averaged revolutions (dynamics), N.
    pub max_roller_load_n: f64,
    /// Largest roller–raceway normal force of the quasi-static solution, N.
    pub max_roller_load_quasi_static_n: f64,
    /// Cage revolutions completed by the dynamic run.
    pub revolutions: f64,
    /// Cage revolutions averaged for `cage_slip_dynamic`.
    pub averaged_revolutions: f64,
    /// Whether the last revolution met the steady-state criterion of the dynamics.
    pub steady: bool,
    /// Remaining drift of the dynamic slip: mean over the second half of the averaged
    /// revolutions minus the mean over their first half (NaN with fewer than 2).
    pub slip_drift: f64,
    /// Mean cage slip of every completed revolution, in order (the convergence history).
    pub slip_history: Vec<f64>,
    /// Wall time of the point, s.
    pub wall_time_s: f64,
    /// Why the point was skipped or failed (empty when it ran).
    pub note: String,
}

impl FrozenPointRow {
    /// A row with the frozen conditions only, every result NaN, and a note (a skipped point,
    /// e.g. the start at zero speed, or a failed one).
    pub fn conditions_only(label: &str, time_s: f64, note: impl Into<String>) -> Self {
        Self {
            label: label.to_string(),
            time_s,
            inner_speed_rad_s: f64::NAN,
            fixed_load_n: f64::NAN,
            rotating_load_n: f64::NAN,
            clearance_m: f64::NAN,
            oil_temperature_k: f64::NAN,
            cage_slip_dynamic: f64::NAN,
            cage_slip_quasi_static: f64::NAN,
            max_roller_load_n: f64::NAN,
            max_roller_load_quasi_static_n: f64::NAN,
            revolutions: 0.0,
            averaged_revolutions: 0.0,
            steady: false,
            slip_drift: f64::NAN,
            slip_history: Vec::new(),
            wall_time_s: 0.0,
            note: note.into(),
        }
    }

    /// Whether the dynamic run gave a slip.
    pub fn ran(&self) -> bool {
        self.cage_slip_dynamic.is_finite()
    }
}

/// A numeric column of `startup.parquet` (and of `startup.csv` after `point`): its name and
/// how its value is read from a row (a flag as 0 or 1).
#[derive(Clone, Copy)]
pub struct NumericColumn {
    /// column name in the header
    pub name: &'static str,
    /// reads the value from a row
    pub value: fn(&FrozenPointRow) -> f64,
}

/// The numeric columns of the start-up table, in order.
pub const NUMERIC_COLUMNS: [NumericColumn; 16] = [
    NumericColumn {
        name: "time_s",
        value: |r| r.time_s,
    },
    NumericColumn {
        name: "inner_speed_rad_s",
        value: |r| r.inner_speed_rad_s,
    },
    NumericColumn {
        name: "inner_speed_rpm",
        value: |r| r.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
    },
    NumericColumn {
        name: "fixed_load_n",
        value: |r| r.fixed_load_n,
    },
    NumericColumn {
        name: "rotating_load_n",
        value: |r| r.rotating_load_n,
    },
    NumericColumn {
        name: "clearance_m",
        value: |r| r.clearance_m,
    },
    NumericColumn {
        name: "oil_temperature_k",
        value: |r| r.oil_temperature_k,
    },
    NumericColumn {
        name: "cage_slip_dynamic",
        value: |r| r.cage_slip_dynamic,
    },
    NumericColumn {
        name: "slip_drift",
        value: |r| r.slip_drift,
    },
    NumericColumn {
        name: "cage_slip_quasi_static",
        value: |r| r.cage_slip_quasi_static,
    },
    NumericColumn {
        name: "max_roller_load_n",
        value: |r| r.max_roller_load_n,
    },
    NumericColumn {
        name: "max_roller_load_quasi_static_n",
        value: |r| r.max_roller_load_quasi_static_n,
    },
    NumericColumn {
        name: "revolutions",
        value: |r| r.revolutions,
    },
    NumericColumn {
        name: "averaged_revolutions",
        value: |r| r.averaged_revolutions,
    },
    NumericColumn {
        name: "steady",
        value: |r| f64::from(u8::from(r.steady)),
    },
    NumericColumn {
        name: "wall_time_s",
        value: |r| r.wall_time_s,
    },
];

fn numeric(row: &FrozenPointRow) -> Vec<f64> {
    NUMERIC_COLUMNS.iter().map(|c| (c.value)(row)).collect()
}

/// Runs `analyse` on every point with `jobs` threads (results in the order of `points`);
/// `progress` is called as each point finishes. `analyse` must be single-threaded inside.
pub fn run_points<P: Sync>(
    points: &[P],
    jobs: usize,
    analyse: &(dyn Fn(&P) -> FrozenPointRow + Sync),
    progress: &(dyn Fn(&FrozenPointRow) + Sync),
) -> Result<Vec<FrozenPointRow>, StartupError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.max(1))
        .build()
        .map_err(|e| StartupError(e.to_string()))?;
    Ok(pool.install(|| {
        points
            .par_iter()
            .map(|p| {
                let row = analyse(p);
                progress(&row);
                row
            })
            .collect()
    }))
}

/// Mean of the last `n` values (all of them when fewer; NaN when empty).
pub fn mean_of_last(values: &[f64], n: usize) -> f64 {
    let tail = &values[values.len().saturating_sub(n.max(1))..];
    if tail.is_empty() {
        return f64::NAN;
    }
    tail.iter().sum::<f64>() / tail.len() as f64
}

/// Drift of the last `n` values: mean of their second half minus mean of their first half
/// (NaN with fewer than 2 values).
pub fn drift_of_last(values: &[f64], n: usize) -> f64 {
    let tail = &values[values.len().saturating_sub(n)..];
    if tail.len() < 2 {
        return f64::NAN;
    }
    let (first, second) = tail.split_at(tail.len() / 2);
    mean_of_last(second, second.len()) - mean_of_last(first, first.len())
}

/// Writes `startup.csv` (with the point labels and notes), `startup.parquet` (numeric columns),
/// `startup_revolutions.csv` (slip of every cage revolution of every point),
/// `startup_cage_slip.svg` (dynamic and quasi-static cage slip vs start-up time),
/// `startup_slip_history.svg` (slip vs revolution per point) and `startup_conditions.svg`
/// (speed and loads vs time) into `dir`.
pub fn write_outputs(dir: &Path, model: &str, rows: &[FrozenPointRow]) -> Result<(), StartupError> {
    let fail = |e: String| StartupError(format!("{}: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(|e| fail(e.to_string()))?;
    let mut csv =
        csv::Writer::from_path(dir.join("startup.csv")).map_err(|e| fail(e.to_string()))?;
    let mut header = vec!["point".to_string()];
    header.extend(NUMERIC_COLUMNS.iter().map(|c| c.name.to_string()));
    header.push("note".to_string());
    csv.write_record(&header).map_err(|e| fail(e.to_string()))?;
    let names: Vec<String> = NUMERIC_COLUMNS.iter().map(|c| c.name.to_string()).collect();
    let mut parquet = TableWriter::create(
        dir,
        "startup",
        &names,
        Formats {
            csv: false,
            parquet: true,
        },
    )
    .map_err(|e| fail(e.to_string()))?;
    for row in rows {
        let values = numeric(row);
        let mut record = vec![row.label.clone()];
        // docs/outputs.md: an empty field for a value that is not finite
        record.extend(values.iter().map(|v| {
            if v.is_finite() {
                v.to_string()
            } else {
                String::new()
            }
        }));
        record.push(row.note.clone());
        csv.write_record(&record).map_err(|e| fail(e.to_string()))?;
        parquet
            .write_row(&values)
            .map_err(|e| fail(e.to_string()))?;
    }
    csv.flush().map_err(|e| fail(e.to_string()))?;
    parquet.finish().map_err(|e| fail(e.to_string()))?;
    let mut history = csv::Writer::from_path(dir.join("startup_revolutions.csv"))
        .map_err(|e| fail(e.to_string()))?;
    history
        .write_record(["point", "time_s", "revolution", "cage_slip"])
        .map_err(|e| fail(e.to_string()))?;
    for row in rows {
        for (i, slip) in row.slip_history.iter().enumerate() {
            history
                .write_record([
                    row.label.clone(),
                    format!("{}", row.time_s),
                    format!("{}", i + 1),
                    format!("{slip}"),
                ])
                .map_err(|e| fail(e.to_string()))?;
        }
    }
    history.flush().map_err(|e| fail(e.to_string()))?;
    let curves: Vec<(String, Vec<(f64, f64)>)> = rows
        .iter()
        .filter(|r| !r.slip_history.is_empty())
        .map(|r| {
            (
                format!("{} ({} s)", r.label, r.time_s),
                r.slip_history
                    .iter()
                    .enumerate()
                    .map(|(i, s)| ((i + 1) as f64, *s))
                    .collect(),
            )
        })
        .collect();
    line_plot(
        &dir.join("startup_slip_history.svg"),
        &Labels {
            title: &format!("{model}: cage slip per revolution at each frozen point"),
            x: "cage revolution",
            y: "cage slip (fraction)",
        },
        &Series::from_pairs(&curves),
    )
    .map_err(|e| fail(e.to_string()))?;

    let curve = |y: fn(&FrozenPointRow) -> f64| -> Vec<(f64, f64)> {
        rows.iter()
            .map(|r| (r.time_s, y(r)))
            .filter(|p| p.1.is_finite())
            .collect()
    };
    let dynamic = curve(|r| r.cage_slip_dynamic);
    let quasi_static = curve(|r| r.cage_slip_quasi_static);
    line_plot(
        &dir.join("startup_cage_slip.svg"),
        &Labels {
            title: &format!("{model}: cage slip at the frozen start-up points"),
            x: "start-up time, s",
            y: "cage slip (fraction)",
        },
        &[
            Series {
                label: "dynamics",
                points: &dynamic,
            },
            Series {
                label: "quasi-static",
                points: &quasi_static,
            },
        ],
    )
    .map_err(|e| fail(e.to_string()))?;
    let speed = curve(|r| r.inner_speed_rad_s * 30.0 / std::f64::consts::PI / 10.0);
    let fixed = curve(|r| r.fixed_load_n);
    let rotating = curve(|r| r.rotating_load_n);
    line_plot(
        &dir.join("startup_conditions.svg"),
        &Labels {
            title: &format!("{model}: conditions at the frozen start-up points"),
            x: "start-up time, s",
            y: "N; rpm/10",
        },
        &[
            Series {
                label: "speed, rpm/10",
                points: &speed,
            },
            Series {
                label: "fixed load, N",
                points: &fixed,
            },
            Series {
                label: "rotating load U ω², N",
                points: &rotating,
            },
        ],
    )
    .map_err(|e| fail(e.to_string()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(label: &str, t: f64, slip: f64) -> FrozenPointRow {
        FrozenPointRow {
            inner_speed_rad_s: 600.0,
            fixed_load_n: 4287.6,
            rotating_load_n: 1376.0,
            clearance_m: 10e-6,
            oil_temperature_k: 322.15,
            cage_slip_dynamic: slip,
            cage_slip_quasi_static: 0.5 * slip,
            max_roller_load_n: 900.0,
            max_roller_load_quasi_static_n: 850.0,
            revolutions: 2.0,
            averaged_revolutions: 1.0,
            steady: true,
            slip_drift: 1e-4,
            slip_history: vec![0.5 * slip, slip],
            wall_time_s: 0.1,
            note: String::new(),
            ..FrozenPointRow::conditions_only(label, t, "")
        }
    }

    #[test]
    fn points_keep_their_order_in_parallel() {
        let times = [0.0, 82.0988, 85.2988, 101.8988];
        let seen = std::sync::atomic::AtomicUsize::new(0);
        let rows = run_points(
            &times,
            2,
            &|t: &f64| row(&format!("{t}"), *t, t * 1e-4),
            &|_| {
                seen.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
            },
        )
        .unwrap();
        assert_eq!(seen.into_inner(), 4);
        let got: Vec<f64> = rows.iter().map(|r| r.time_s).collect();
        assert_eq!(got, times);
    }

    #[test]
    fn tail_mean_and_drift() {
        assert_eq!(mean_of_last(&[1.0, 2.0, 3.0, 5.0], 2), 4.0);
        assert_eq!(mean_of_last(&[1.0, 3.0], 5), 2.0);
        assert!(mean_of_last(&[], 3).is_nan());
        assert_eq!(drift_of_last(&[9.0, 1.0, 2.0, 3.0, 5.0], 4), 2.5);
        assert!(drift_of_last(&[1.0], 4).is_nan());
    }

    #[test]
    fn outputs_are_written() {
        let dir = std::env::temp_dir().join(format!("rolldyn-frozen-{}", std::process::id()));
        let rows = vec![
            FrozenPointRow::conditions_only("1", 0.0, "zero speed: skipped"),
            row("2", 82.0988, 0.01),
            row("3", 85.2988, 0.03),
        ];
        write_outputs(&dir, "1032930", &rows).unwrap();
        let csv = std::fs::read_to_string(dir.join("startup.csv")).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 4);
        assert!(lines[0].starts_with("point,time_s,inner_speed_rad_s"));
        assert!(lines[1].ends_with("zero speed: skipped"));
        assert!(lines[3].starts_with("3,85.2988,600,"));
        let history = std::fs::read_to_string(dir.join("startup_revolutions.csv")).unwrap();
        assert_eq!(history.lines().count(), 5);
        assert_eq!(history.lines().nth(4), Some("3,85.2988,2,0.03"));
        for file in [
            "startup.parquet",
            "startup_cage_slip.svg",
            "startup_conditions.svg",
            "startup_slip_history.svg",
        ] {
            assert!(dir.join(file).exists(), "{file}");
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
