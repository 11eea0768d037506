//! The tables and plots of a tapered life run (`rolldyn wear examples/tapered-cassette.toml
//! --out DIR`, docs/outputs.md "wear"): one row per dynamics window (the rates of the geometry
//! at the start of a period, the depths at its end; the last row is the window at the end of
//! the life), one row per period and wear line.

use crate::rates::ContactDiagnostics;
use crate::report::{UM, UM_PER_KH, WearReportError};
use crate::settings::WearMethod;
use crate::tapered::life::{TaperedLife, WindowRates};
use rolldyn_geometry::TaperedWear;
use rolldyn_output::{Formats, TableWriter};
use rolldyn_plot::{Labels, Series, line_plot};
use std::path::{Path, PathBuf};

/// Column names of the windows table.
pub fn window_columns() -> Vec<String> {
    let mut names: Vec<String> = [
        "period",
        "time_h",
        "period_h",
        "wall_s",
        "steps",
        "depth_roller_max_um",
        "depth_cone_max_um",
        "depth_cup_max_um",
        "depth_roller_end_um",
        "depth_rib_um",
        "rate_roller_max_um_per_1000h",
        "rate_cone_max_um_per_1000h",
        "rate_cup_max_um_per_1000h",
        "rate_roller_end_um_per_1000h",
        "rate_rib_um_per_1000h",
        "direct_end_in_contact_m_s",
        "direct_rib_in_contact_m_s",
        "averaged_end_in_contact_m_s",
        "averaged_rib_in_contact_m_s",
        "max_pressure_line",
        "direct_cone_line_in_contact_m_s",
        "averaged_cone_line_in_contact_m_s",
        "yaw_max_deg",
        "yaw_mean_deg",
        "pitch_max_deg",
        "pitch_mean_deg",
        "rib_force_mean_n",
        "rib_force_max_n",
        "cage_speed_rad_s",
    ]
    .map(String::from)
    .into();
    for kind in ["cone", "cup", "rib"] {
        let change = ["half_window_force_change", "half_window_sliding_change"];
        for q in ContactDiagnostics::NAMES.into_iter().chain(change) {
            names.push(format!("{kind}_{q}"));
        }
    }
    names
}

/// Named curves of one plot.
type Curves = Vec<(String, Vec<(f64, f64)>)>;

/// A plot: file name, title, y label and its curves.
type Plot<'a> = (&'a str, &'a str, &'a str, Curves);

/// Draws `plots` against the x label `x` into `dir`, appending the files to `written`.
fn draw(
    dir: &Path,
    x: &str,
    plots: Vec<Plot>,
    written: &mut Vec<PathBuf>,
) -> Result<(), WearReportError> {
    for (name, title, y, curves) in plots {
        let path = dir.join(name);
        line_plot(&path, &Labels { title, x, y }, &Series::from_pairs(&curves))?;
        written.push(path);
    }
    Ok(())
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

fn max_depth(lines: &[(f64, f64)]) -> f64 {
    lines.iter().map(|p| p.1).fold(0.0, f64::max)
}

/// Depth on line `s` of a line table, µm.
fn depth_um(lines: &[(f64, f64)], s: usize) -> f64 {
    lines.get(s).map_or(0.0, |p| p.1) * UM
}

/// One window's row: `period`, the time at the end of the period, the depth `wear` there.
fn window_row(
    period: usize,
    (time_h, period_h): (f64, f64),
    w: &WindowRates,
    wear: &TaperedWear,
    method: WearMethod,
) -> Vec<f64> {
    let r = w.of(method);
    let d = &w.diagnostics;
    let line = w.direct.max_pressure_line();
    let mut row = vec![
        period as f64,
        time_h,
        period_h,
        w.wall_s,
        w.steps as f64,
        max_depth(&wear.roller) * UM,
        max_depth(&wear.cone) * UM,
        max_depth(&wear.cup) * UM,
        wear.large_end * UM,
        wear.large_rib * UM,
        max(&r.roller) * UM_PER_KH,
        max(&r.cone) * UM_PER_KH,
        max(&r.cup) * UM_PER_KH,
        r.roller_end * UM_PER_KH,
        r.rib * UM_PER_KH,
        w.direct.end_in_contact,
        w.direct.rib_in_contact,
        w.averaged.end_in_contact,
        w.averaged.rib_in_contact,
        (line + 1) as f64,
        w.direct.cone_in_contact[line],
        w.averaged.cone_in_contact[line],
        d.yaw_max_rad.to_degrees(),
        d.yaw_mean_rad.to_degrees(),
        d.pitch_max_rad.to_degrees(),
        d.pitch_mean_rad.to_degrees(),
        d.rib_force_mean_n,
        d.rib_force_max_n,
        d.cage_speed_rad_s,
    ];
    for (c, change) in d.contacts.iter().zip(&d.half_window_change) {
        row.extend(c.values());
        row.extend([change.0, change.1]);
    }
    row
}

/// Column names of the lines table.
fn line_columns() -> Vec<String> {
    [
        "period",
        "time_h",
        "line",
        "x_mm",
        "depth_roller_um",
        "depth_cone_um",
        "depth_cup_um",
        "rate_roller_um_per_1000h",
        "rate_cone_um_per_1000h",
        "rate_cup_um_per_1000h",
    ]
    .map(String::from)
    .into()
}

/// Writes the tables `tapered-windows` and `tapered-lines`.
fn write_tables(dir: &Path, life: &TaperedLife, method: WearMethod) -> Result<(), WearReportError> {
    let f = Formats::default();
    let mut windows = TableWriter::create(dir, "tapered-windows", &window_columns(), f)?;
    let mut lines = TableWriter::create(dir, "tapered-lines", &line_columns(), f)?;
    for p in &life.periods {
        let row = window_row(p.index, (p.time_h, p.period_h), &p.rates, &p.wear, method);
        windows.write_row(&row)?;
        let r = p.rates.of(method);
        for (s, &x) in life.positions_m.iter().enumerate() {
            lines.write_row(&[
                p.index as f64,
                p.time_h,
                (s + 1) as f64,
                x * 1e3,
                depth_um(&p.wear.roller, s),
                depth_um(&p.wear.cone, s),
                depth_um(&p.wear.cup, s),
                r.roller[s] * UM_PER_KH,
                r.cone[s] * UM_PER_KH,
                r.cup[s] * UM_PER_KH,
            ])?;
        }
    }
    let final_wear = life
        .periods
        .last()
        .map(|p| p.wear.clone())
        .unwrap_or_default();
    windows.write_row(&window_row(
        life.periods.len() + 1,
        (life.life_h, 0.0),
        &life.last_window,
        &final_wear,
        method,
    ))?;
    windows.finish()?;
    lines.finish()?;
    Ok(())
}

/// Writes the tables `tapered-windows` and `tapered-lines` and the plots of `life` into `dir`;
/// returns the plots written.
pub fn write_tapered_report(
    dir: &Path,
    life: &TaperedLife,
    method: WearMethod,
) -> Result<Vec<PathBuf>, WearReportError> {
    write_tables(dir, life, method)?;
    let mut written = Vec::new();
    let p = &life.periods;
    // per line over time: depth of the roller and the cone, rate of the roller (the stability
    // picture of seed 000 Figs. 3.96–3.98)
    let per_line = |pick: &dyn Fn(usize, usize) -> f64| -> Curves {
        (0..life.positions_m.len())
            .map(|s| {
                let pts = (0..p.len()).map(|i| (p[i].time_h, pick(i, s))).collect();
                (format!("line {}", s + 1), pts)
            })
            .collect()
    };
    let plots = vec![
        (
            "tapered-roller-lines.svg",
            "Roller wear on the wear lines",
            "wear depth, µm",
            per_line(&|i, s| depth_um(&p[i].wear.roller, s)),
        ),
        (
            "tapered-cone-lines.svg",
            "Cone raceway wear on the wear lines",
            "wear depth, µm",
            per_line(&|i, s| depth_um(&p[i].wear.cone, s)),
        ),
        (
            "tapered-roller-rates.svg",
            "Roller wear rate on the wear lines during each period",
            "rate, µm per 1000 h",
            per_line(&|i, s| p[i].rates.of(method).roller[s] * UM_PER_KH),
        ),
    ];
    draw(
        dir,
        "operating time at the end of the period, h",
        plots,
        &mut written,
    )?;
    // the windows from the unworn start to the end of the life
    let windows: Vec<(f64, &WindowRates)> = std::iter::once(0.0)
        .chain(p.iter().map(|q| q.time_h))
        .zip(p.iter().map(|q| &q.rates).chain([&life.last_window]))
        .collect();
    let series =
        |f: &dyn Fn(&WindowRates) -> f64| windows.iter().map(|(t, w)| (*t, f(w))).collect();
    let trends = vec![
        (
            "tapered-rib-force.svg",
            "Large-end–rib force of a roller against the wear time",
            "force, N",
            vec![
                (
                    "time mean".into(),
                    series(&|w| w.diagnostics.rib_force_mean_n),
                ),
                (
                    "equivalent (2.36)".into(),
                    series(&|w| w.diagnostics.contacts[2].equivalent_force_n),
                ),
            ],
        ),
        (
            "tapered-yaw-pitch.svg",
            "Roller yaw and pitch against the wear time",
            "angle, deg",
            vec![
                (
                    "yaw max".into(),
                    series(&|w| w.diagnostics.yaw_max_rad.to_degrees()),
                ),
                (
                    "yaw mean".into(),
                    series(&|w| w.diagnostics.yaw_mean_rad.to_degrees()),
                ),
                (
                    "pitch max".into(),
                    series(&|w| w.diagnostics.pitch_max_rad.to_degrees()),
                ),
                (
                    "pitch mean".into(),
                    series(&|w| w.diagnostics.pitch_mean_rad.to_degrees()),
                ),
            ],
        ),
    ];
    draw(dir, "wear time, h", trends, &mut written)?;
    Ok(written)
}
