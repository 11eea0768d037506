//! Self-contained SVG plots (no fonts or scripts fetched at view time) for rolldyn results:
//! line plots of one or more series, log–log plots of curves and scattered points, and heat maps
//! of fields on a regular grid.

use plotters::prelude::*;
use std::path::Path;

/// Plotting failed (file system or drawing backend).
#[derive(Debug, thiserror::Error)]
#[error("cannot write plot {path}: {reason}")]
pub struct PlotError {
    pub path: String,
    pub reason: String,
}

/// One named curve.
pub struct Series<'a> {
    pub label: &'a str,
    pub points: &'a [(f64, f64)],
}

impl<'a> Series<'a> {
    /// Borrows `(label, points)` pairs as series.
    pub fn from_pairs<S: AsRef<str>>(curves: &'a [(S, Vec<(f64, f64)>)]) -> Vec<Series<'a>> {
        curves
            .iter()
            .map(|(label, points)| Series {
                label: label.as_ref(),
                points,
            })
            .collect()
    }
}

/// Axis labels and title of a plot.
pub struct Labels<'a> {
    pub title: &'a str,
    pub x: &'a str,
    pub y: &'a str,
}

const SIZE: (u32, u32) = (900, 560);

fn error(path: &Path, e: impl std::fmt::Display) -> PlotError {
    PlotError {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo < 1e-300 {
        return (lo - 0.5, hi + 0.5);
    }
    (lo, hi)
}

/// Writes a line plot of `series` to `path` (SVG).
pub fn line_plot(path: &Path, labels: &Labels, series: &[Series]) -> Result<(), PlotError> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| error(path, e))?;
    let (x0, x1) = bounds(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let (y0, y1) = bounds(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let pad = 0.05 * (y1 - y0);
    let mut chart = ChartBuilder::on(&root)
        .caption(labels.title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, if y0 >= 0.0 { 0.0 } else { y0 - pad }..(y1 + pad))
        .map_err(|e| error(path, e))?;
    chart
        .configure_mesh()
        .x_desc(labels.x)
        .y_desc(labels.y)
        .draw()
        .map_err(|e| error(path, e))?;
    for (k, s) in series.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(
                s.points.iter().copied(),
                color.stroke_width(2),
            ))
            .map_err(|e| error(path, e))?
            .label(s.label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    if series.len() > 1 || !series.first().is_some_and(|s| s.label.is_empty()) {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| error(path, e))?;
    }
    root.present().map_err(|e| error(path, e))
}

/// A scalar field on a regular grid of `nx × ny` cells, x-fastest storage.
pub struct Field<'a> {
    pub values: &'a [f64],
    pub nx: usize,
    pub ny: usize,
    /// Extent of the grid: (x_min, x_max, y_min, y_max).
    pub extent: (f64, f64, f64, f64),
}

/// Writes a heat map of `field` (blue = 0 … red = max) to `path` (SVG).
pub fn heat_map(path: &Path, labels: &Labels, field: &Field) -> Result<(), PlotError> {
    heat_map_outlined(path, labels, field, &[])
}

/// [`heat_map`] with the line segments `outline` (e.g. the boundary of a region, in the
/// field's coordinates) drawn over it in black.
pub fn heat_map_outlined(
    path: &Path,
    labels: &Labels,
    field: &Field,
    outline: &[[(f64, f64); 2]],
) -> Result<(), PlotError> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| error(path, e))?;
    let (x0, x1, y0, y1) = field.extent;
    let (_, vmax) = bounds(field.values.iter().copied());
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("{} (max {:.4})", labels.title, vmax),
            ("sans-serif", 22),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| error(path, e))?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(labels.x)
        .y_desc(labels.y)
        .draw()
        .map_err(|e| error(path, e))?;
    let dx = (x1 - x0) / field.nx as f64;
    let dy = (y1 - y0) / field.ny as f64;
    let cells = (0..field.ny).flat_map(|j| (0..field.nx).map(move |i| (i, j)));
    chart
        .draw_series(cells.map(|(i, j)| {
            let v = field.values[j * field.nx + i];
            let t = if vmax > 0.0 {
                (v / vmax).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let color = if v <= 0.0 {
                RGBColor(235, 235, 245)
            } else {
                ramp(t)
            };
            let (xa, ya) = (x0 + i as f64 * dx, y0 + j as f64 * dy);
            Rectangle::new([(xa, ya), (xa + dx, ya + dy)], color.filled())
        }))
        .map_err(|e| error(path, e))?;
    chart
        .draw_series(
            outline
                .iter()
                .map(|segment| PathElement::new(segment.to_vec(), BLACK.stroke_width(2))),
        )
        .map_err(|e| error(path, e))?;
    root.present().map_err(|e| error(path, e))
}

/// Blue → cyan → yellow → red colour ramp for `t ∈ [0, 1]`.
fn ramp(t: f64) -> RGBColor {
    let stops = [
        (0.0, (40, 60, 200)),
        (0.35, (40, 200, 220)),
        (0.7, (250, 220, 40)),
        (1.0, (220, 30, 30)),
    ];
    let k = stops
        .iter()
        .rposition(|s| s.0 <= t)
        .unwrap_or(0)
        .min(stops.len() - 2);
    let (ta, a) = stops[k];
    let (tb, b) = stops[k + 1];
    let f = ((t - ta) / (tb - ta)).clamp(0.0, 1.0);
    let mix = |u: u8, v: u8| (u as f64 + f * (v as f64 - u as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Bounds of the positive values widened by a factor 1.25 each way (for a logarithmic axis).
fn log_bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = bounds(values.filter(|v| *v > 0.0).map(f64::log10));
    let pad = 1.25f64.log10();
    (10f64.powf(lo - pad), 10f64.powf(hi + pad))
}

/// Writes a plot with logarithmic x and y axes to `path` (SVG): `lines` drawn as curves,
/// `markers` as unconnected points (a scatter); non-positive values are left out.
pub fn log_log_plot(
    path: &Path,
    labels: &Labels,
    lines: &[Series],
    markers: &[Series],
) -> Result<(), PlotError> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| error(path, e))?;
    let all = || lines.iter().chain(markers).flat_map(|s| s.points.iter());
    let (x0, x1) = log_bounds(all().map(|p| p.0));
    let (y0, y1) = log_bounds(all().map(|p| p.1));
    let mut chart = ChartBuilder::on(&root)
        .caption(labels.title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(|e| error(path, e))?;
    chart
        .configure_mesh()
        .x_label_formatter(&|x| format!("{x:e}"))
        .y_label_formatter(&|y| format!("{y}"))
        .x_desc(labels.x)
        .y_desc(labels.y)
        .draw()
        .map_err(|e| error(path, e))?;
    let positive = |s: &Series| -> Vec<(f64, f64)> {
        s.points
            .iter()
            .copied()
            .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
            .collect()
    };
    for (k, s) in lines.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(positive(s), color.stroke_width(2)))
            .map_err(|e| error(path, e))?
            .label(s.label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    for (k, s) in markers.iter().enumerate() {
        let color = Palette99::pick(lines.len() + k).to_rgba();
        chart
            .draw_series(
                positive(s)
                    .into_iter()
                    .map(|p| Circle::new(p, 3, color.filled())),
            )
            .map_err(|e| error(path, e))?
            .label(s.label)
            .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| error(path, e))?;
    root.present().map_err(|e| error(path, e))
}
