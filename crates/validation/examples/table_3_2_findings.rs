//! Seed 000 §3.1.1.1 findings checked on a rolldyn run (validation case V-07): where the rollers
//! touch the cage bars (in the load zone or outside it, pressed or in impacts), how the inner- and
//! outer-raceway sliding compare in the load zone, and how often the roller yaw changes sign.
//!
//! Run on the `rollers.csv` of `rolldyn simulate … --out DIR` (a fine `--output-step`, e.g.
//! 0.01ms): `cargo run --release -p rolldyn-validation --example table_3_2_findings --
//! DIR/rollers.csv FROM_S REVOLUTIONS` — samples before `FROM_S` are skipped, `REVOLUTIONS` is the
//! number of cage revolutions after it (for the yaw rate).

use rolldyn_validation::table_3_2::read_columns;
use std::collections::BTreeMap;

/// A roller is in the load zone while its inner-raceway force exceeds this, N.
const LOAD_ZONE_FORCE_N: f64 = 1.0;

/// Contact events (runs of consecutive samples with a bar force) of one kind.
#[derive(Default)]
struct Events {
    durations_s: Vec<f64>,
    contact_samples: usize,
    samples: usize,
}

impl Events {
    fn report(&mut self, label: &str) {
        self.durations_s.sort_by(f64::total_cmp);
        let n = self.durations_s.len();
        let share = self.contact_samples as f64 / self.samples.max(1) as f64;
        if n == 0 {
            println!("{label}: bar contact in {share:.4} of the samples, no events");
            return;
        }
        println!(
            "{label}: bar contact in {share:.4} of the samples; {n} events, median {:.0} µs, longest {:.0} µs",
            self.durations_s[n / 2] * 1e6,
            self.durations_s[n - 1] * 1e6
        );
    }
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().collect();
    let [_, path, from, revolutions] = &args[..] else {
        return Err("usage: table_3_2_findings ROLLERS.csv FROM_S REVOLUTIONS".into());
    };
    let from: f64 = from.parse().map_err(|_| "FROM_S: a number")?;
    let revolutions: f64 = revolutions.parse().map_err(|_| "REVOLUTIONS: a number")?;
    let table = read_columns(std::path::Path::new(path))?;
    let col = |name: &str| table.get(name).ok_or(format!("{path}: no column {name}"));
    let (time, roller) = (col("time_s")?, col("roller")?);
    let (inner, bar, yaw) = (
        col("inner_force_n")?,
        col("cage_bar_force_n")?,
        col("yaw_rad")?,
    );
    let (slide_in, slide_out) = (
        col("inner_sliding_speed_m_s")?,
        col("outer_sliding_speed_m_s")?,
    );
    let mut rows_of: BTreeMap<i64, Vec<usize>> = BTreeMap::new();
    for i in (0..time.len()).filter(|&i| time[i] >= from) {
        rows_of.entry(roller[i] as i64).or_default().push(i);
    }
    let step = rows_of
        .values()
        .next()
        .filter(|r| r.len() > 1)
        .map(|r| time[r[1]] - time[r[0]])
        .ok_or("fewer than two samples per roller")?;
    let (mut in_zone, mut outside) = (Events::default(), Events::default());
    let (mut sum_in, mut sum_out, mut max_in, mut max_out) = (0.0, 0.0, 0.0_f64, 0.0_f64);
    let mut yaw_sign_changes = 0;
    for rows in rows_of.values() {
        let (mut run, mut run_in_zone, mut last_sign) = (0usize, false, 0.0);
        for &i in rows {
            let zone = inner[i] > LOAD_ZONE_FORCE_N;
            let events = if zone { &mut in_zone } else { &mut outside };
            events.samples += 1;
            if bar[i] > 0.0 {
                events.contact_samples += 1;
                if run == 0 {
                    run_in_zone = zone;
                }
                run += 1;
            } else if run > 0 {
                let started = if run_in_zone {
                    &mut in_zone
                } else {
                    &mut outside
                };
                started.durations_s.push(run as f64 * step);
                run = 0;
            }
            if zone {
                sum_in += slide_in[i];
                sum_out += slide_out[i];
                max_in = max_in.max(slide_in[i]);
                max_out = max_out.max(slide_out[i]);
            }
            let sign = yaw[i].signum();
            if yaw[i] != 0.0 && last_sign != 0.0 && sign != last_sign {
                yaw_sign_changes += 1;
            }
            if yaw[i] != 0.0 {
                last_sign = sign;
            }
        }
    }
    in_zone.report("events starting in the load zone");
    outside.report("events starting outside it");
    println!(
        "load-zone sliding: inner mean / max {:.3} / {:.3} m/s, outer {:.3} / {:.3} m/s; inner/outer: means {:.2}, maxima {:.2}",
        sum_in / in_zone.samples.max(1) as f64,
        max_in,
        sum_out / in_zone.samples.max(1) as f64,
        max_out,
        sum_in / sum_out,
        max_in / max_out
    );
    println!(
        "yaw sign changes per roller and cage revolution: {:.1}",
        yaw_sign_changes as f64 / rows_of.len() as f64 / revolutions
    );
    Ok(())
}
