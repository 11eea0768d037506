//! Self-contained SVG plots (no fonts or scripts fetched at view time) for rolldyn results:
//! line plots of one or more series on axes that start near the data, orbits drawn to equal
//! aspect with their clearance circles, values per sweep variant against the varied parameter
//! (or the variant names), log–log plots of curves and scattered points, and heat maps of fields
//! on a regular grid with a colour bar.
//!
//! Every text is at least 12 px at the SVG's own size (720 × 450). A map's root element has the
//! class `heat-map` and its colour bar is the group `<g class="colour-bar">` (the report's
//! browser test counts both).

use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

mod axes;
mod colour_bar;

pub use axes::{data_range, nice_step, tick_label};

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

/// Size of every plot, px.
pub const SIZE: (u32, u32) = (720, 450);
/// Font sizes as plotters takes them; its SVG backend writes `size / 1.24` px, so the tick
/// labels (19) are 15.3 px, the axis labels 16.9 px and the title 21 px.
const TITLE_FONT: u32 = 26;
const AXIS_FONT: u32 = 21;
const TICK_FONT: u32 = 19;
/// Width kept on the right of a map for its colour bar, px.
const BAR_AREA: u32 = 130;

fn error(path: &Path, e: impl std::fmt::Display) -> PlotError {
    PlotError {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

type Root<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Draws onto an SVG of [`SIZE`] held in memory, then writes it to `path` with the root
/// element's `class` and `extra` markup appended (returned by `draw`).
fn write_svg(
    path: &Path,
    class: &str,
    draw: impl FnOnce(&Root) -> Result<String, String>,
) -> Result<(), PlotError> {
    let mut svg = String::new();
    let extra = {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| error(path, e))?;
        let extra = draw(&root).map_err(|e| error(path, e))?;
        root.present().map_err(|e| error(path, e))?;
        extra
    };
    let mut svg = svg.replacen("<svg ", &format!("<svg class=\"rolldyn-plot {class}\" "), 1);
    if let Some(end) = svg.rfind("</svg>") {
        svg.insert_str(end, &extra);
    }
    std::fs::write(path, svg).map_err(|e| error(path, e))
}

/// The chart frame of every plot: title, margins, label areas.
fn frame<'a, 'b>(area: &'a Root<'b>, title: &str) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(title, ("sans-serif", TITLE_FONT))
        .margin(12)
        .x_label_area_size(58)
        .y_label_area_size(92);
    builder
}

/// Draws the legend of a chart when there is one to draw.
macro_rules! legend {
    ($chart:expr, $position:expr) => {
        $chart
            .configure_series_labels()
            .position($position)
            .label_font(("sans-serif", TICK_FONT))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| e.to_string())
    };
}

/// Writes a line plot of `series` to `path` (SVG); the y axis starts near the data (at 0 only
/// when 0 is close to it), so curves a few percent apart stay apart.
pub fn line_plot(path: &Path, labels: &Labels, series: &[Series]) -> Result<(), PlotError> {
    write_svg(path, "line-plot", |root| {
        let (x0, x1) = axes::bounds(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
        let (y0, y1) = data_range(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
        let mut chart = linear_chart(root, labels, (x0, x1), (y0, y1))?;
        for (k, s) in series.iter().enumerate() {
            let color = Palette99::pick(k).to_rgba();
            chart
                .draw_series(LineSeries::new(
                    s.points.iter().copied().filter(|p| p.1.is_finite()),
                    color.stroke_width(2),
                ))
                .map_err(|e| e.to_string())?
                .label(s.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        if series.len() > 1 || !series.first().is_some_and(|s| s.label.is_empty()) {
            legend!(chart, SeriesLabelPosition::UpperRight)?;
        }
        Ok(String::new())
    })
}

/// A circle drawn on an orbit plot (a clearance or a guiding-land circle), in the plot's units.
pub struct ClearanceCircle<'a> {
    pub label: &'a str,
    pub centre: (f64, f64),
    pub radius: f64,
}

/// Writes the orbits `series` (x, y in the same unit) to `path` (SVG) at equal aspect, one unit
/// as long on both axes, with `circles` (e.g. the clearance circle the centre moves in) drawn
/// in grey; the frame holds the circles and the orbits.
pub fn orbit_plot(
    path: &Path,
    labels: &Labels,
    series: &[Series],
    circles: &[ClearanceCircle],
) -> Result<(), PlotError> {
    write_svg(path, "orbit-plot", |root| {
        let points = || series.iter().flat_map(|s| s.points.iter());
        let circle_x = circles
            .iter()
            .flat_map(|c| [c.centre.0 - c.radius, c.centre.0 + c.radius]);
        let circle_y = circles
            .iter()
            .flat_map(|c| [c.centre.1 - c.radius, c.centre.1 + c.radius]);
        let (x0, x1) = axes::bounds(points().map(|p| p.0).chain(circle_x));
        let (y0, y1) = axes::bounds(points().map(|p| p.1).chain(circle_y));
        // the pixel size of the plotting area, from a frame drawn on a scratch canvas
        let (width_px, height_px) = {
            let mut scratch = String::new();
            let area = SVGBackend::with_string(&mut scratch, SIZE).into_drawing_area();
            let chart = frame(&area, labels.title)
                .build_cartesian_2d(0.0..1.0, 0.0..1.0)
                .map_err(|e| e.to_string())?;
            let (xr, yr) = chart.plotting_area().get_pixel_range();
            (f64::from(xr.end - xr.start), f64::from(yr.end - yr.start))
        };
        let ((x0, x1), (y0, y1)) =
            axes::equal_aspect((x0, x1), (y0, y1), width_px / height_px, 0.06);
        let mut chart = linear_chart(root, labels, (x0, x1), (y0, y1))?;
        let grey = RGBColor(120, 120, 120);
        for c in circles {
            let outline: Vec<(f64, f64)> = (0..=180)
                .map(|k| {
                    let a = std::f64::consts::TAU * f64::from(k) / 180.0;
                    (
                        c.centre.0 + c.radius * a.cos(),
                        c.centre.1 + c.radius * a.sin(),
                    )
                })
                .collect();
            chart
                .draw_series(std::iter::once(PathElement::new(
                    outline,
                    grey.stroke_width(2),
                )))
                .map_err(|e| e.to_string())?
                .label(c.label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], grey));
        }
        for (k, s) in series.iter().enumerate() {
            let color = Palette99::pick(k).to_rgba();
            chart
                .draw_series(LineSeries::new(
                    s.points
                        .iter()
                        .copied()
                        .filter(|p| p.0.is_finite() && p.1.is_finite()),
                    color.stroke_width(1),
                ))
                .map_err(|e| e.to_string())?
                .label(s.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        let labelled = circles.iter().any(|c| !c.label.is_empty())
            || series.iter().any(|s| !s.label.is_empty());
        if labelled {
            legend!(chart, SeriesLabelPosition::UpperRight)?;
        }
        Ok(String::new())
    })
}

/// What a sweep varied, for [`variant_plot`]: the summary column of each varied model key
/// (`operating.inner_speed_rad_s`, `roller.count`), with its value per variant (NaN where a
/// variant has none).
pub struct Varied<'a> {
    pub column: &'a str,
    pub values: &'a [f64],
}

/// Writes `values` (one per variant, named `names`, NaN where missing) to `path` (SVG) against
/// the first varied column whose values are all finite numbers (points joined in its order),
/// else at the variant names on a categorical axis.
pub fn variant_plot(
    path: &Path,
    title: &str,
    y: &str,
    names: &[String],
    varied: &[Varied],
    values: &[f64],
) -> Result<(), PlotError> {
    let numeric = varied.iter().find(|v| {
        v.values.len() == values.len()
            && !v.values.is_empty()
            && v.values.iter().all(|x| x.is_finite())
    });
    match numeric {
        Some(axis) => {
            let mut points: Vec<(f64, f64)> = axis
                .values
                .iter()
                .zip(values)
                .map(|(&x, &v)| (x, v))
                .filter(|p| p.1.is_finite())
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            let labels = Labels {
                title,
                x: axis.column,
                y,
            };
            marked_plot(path, &labels, &points)
        }
        None => category_plot(path, title, y, names, values),
    }
}

/// The titled frame of `root` over `x` × `y` with its axes drawn: ticks labelled with the
/// digits that tell them apart, `labels.x` and `labels.y` as axis titles.
fn linear_chart<'a, 'b>(
    root: &'a Root<'b>,
    labels: &Labels,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Result<
    ChartContext<
        'a,
        SVGBackend<'b>,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    String,
> {
    let mut chart = frame(root, labels.title)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_label_formatter(&|v| tick_label(*v, x0, x1))
        .y_label_formatter(&|v| tick_label(*v, y0, y1))
        .label_style(("sans-serif", TICK_FONT))
        .axis_desc_style(("sans-serif", AXIS_FONT))
        .x_desc(labels.x)
        .y_desc(labels.y)
        .draw()
        .map_err(|e| e.to_string())?;
    Ok(chart)
}

/// A single series drawn as a line with a marker at each point.
fn marked_plot(path: &Path, labels: &Labels, points: &[(f64, f64)]) -> Result<(), PlotError> {
    write_svg(path, "line-plot", |root| {
        let (x0, x1) = data_range(points.iter().map(|p| p.0));
        let (y0, y1) = data_range(points.iter().map(|p| p.1));
        let mut chart = linear_chart(root, labels, (x0, x1), (y0, y1))?;
        let color = Palette99::pick(0).to_rgba();
        chart
            .draw_series(LineSeries::new(
                points.iter().copied(),
                color.stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(points.iter().map(|&p| Circle::new(p, 5, color.filled())))
            .map_err(|e| e.to_string())?;
        Ok(String::new())
    })
}

/// Writes `values` at the categories `names` (one tick each, in the given order) to `path`.
pub fn category_plot(
    path: &Path,
    title: &str,
    y: &str,
    names: &[String],
    values: &[f64],
) -> Result<(), PlotError> {
    write_svg(path, "category-plot", |root| {
        let n = names.len().max(1);
        let (y0, y1) = data_range(values.iter().copied());
        let mut chart = frame(root, title)
            .build_cartesian_2d((0..n - 1).into_segmented(), y0..y1)
            .map_err(|e| e.to_string())?;
        let name_of = |v: &SegmentValue<usize>| match v {
            SegmentValue::CenterOf(i) | SegmentValue::Exact(i) => names
                .get(*i)
                .map_or(String::new(), |s| shortened(s, 60 / n.min(60))),
            SegmentValue::Last => String::new(),
        };
        chart
            .configure_mesh()
            .y_label_formatter(&|v| tick_label(*v, y0, y1))
            .disable_x_mesh()
            .x_labels(n)
            .x_label_formatter(&name_of)
            .label_style(("sans-serif", TICK_FONT))
            .axis_desc_style(("sans-serif", AXIS_FONT))
            .x_desc("variant")
            .y_desc(y)
            .draw()
            .map_err(|e| e.to_string())?;
        let color = Palette99::pick(0).to_rgba();
        chart
            .draw_series(
                values
                    .iter()
                    .enumerate()
                    .filter(|(_, v)| v.is_finite())
                    .map(|(i, &v)| Circle::new((SegmentValue::CenterOf(i), v), 6, color.filled())),
            )
            .map_err(|e| e.to_string())?;
        Ok(String::new())
    })
}

/// `name` cut to `max` characters (at least 4) with an ellipsis.
fn shortened(name: &str, max: usize) -> String {
    let max = max.max(4);
    match name.chars().count() > max {
        true => name.chars().take(max - 1).chain(['…']).collect(),
        false => name.to_string(),
    }
}

/// A scalar field on a regular grid of `nx × ny` cells, x-fastest storage.
pub struct Field<'a> {
    pub values: &'a [f64],
    pub nx: usize,
    pub ny: usize,
    /// Extent of the grid: (x_min, x_max, y_min, y_max).
    pub extent: (f64, f64, f64, f64),
}

/// What a map shows beside its axes: the colour bar's label (quantity and unit) and line
/// segments drawn over the field in black (e.g. the boundary of a region).
pub struct MapLabels<'a> {
    pub value: &'a str,
    pub outline: &'a [[(f64, f64); 2]],
}

/// Writes a heat map of `field` (blue = 0 … red = max) to `path` (SVG) with a colour bar
/// labelled with the title (prefer [`map_plot`], which names the value and its unit).
pub fn heat_map(path: &Path, labels: &Labels, field: &Field) -> Result<(), PlotError> {
    heat_map_outlined(path, labels, field, &[])
}

/// [`heat_map`] with the line segments `outline` (in the field's coordinates) drawn over it.
pub fn heat_map_outlined(
    path: &Path,
    labels: &Labels,
    field: &Field,
    outline: &[[(f64, f64); 2]],
) -> Result<(), PlotError> {
    let value = labels.title.to_string();
    map_plot(
        path,
        labels,
        field,
        &MapLabels {
            value: &value,
            outline,
        },
    )
}

/// Writes a heat map of `field` to `path` (SVG): cells coloured blue (0) … red (the largest
/// value), cells ≤ 0 pale grey, and a colour bar labelled `map.value` from 0 to that value.
pub fn map_plot(
    path: &Path,
    labels: &Labels,
    field: &Field,
    map: &MapLabels,
) -> Result<(), PlotError> {
    write_svg(path, "heat-map", |root| {
        let (x0, x1, y0, y1) = field.extent;
        let (_, vmax) = axes::bounds(field.values.iter().copied());
        let vmax = vmax.max(0.0);
        let (plot_area, _) = root.split_horizontally(SIZE.0 - BAR_AREA);
        let mut chart = frame(&plot_area, labels.title)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_label_formatter(&|v| tick_label(*v, x0, x1))
            .y_label_formatter(&|v| tick_label(*v, y0, y1))
            .disable_mesh()
            .label_style(("sans-serif", TICK_FONT))
            .axis_desc_style(("sans-serif", AXIS_FONT))
            .x_desc(labels.x)
            .y_desc(labels.y)
            .draw()
            .map_err(|e| e.to_string())?;
        let dx = (x1 - x0) / field.nx as f64;
        let dy = (y1 - y0) / field.ny as f64;
        let cells = (0..field.ny).flat_map(|j| (0..field.nx).map(move |i| (i, j)));
        chart
            .draw_series(cells.map(|(i, j)| {
                let v = field.values[j * field.nx + i];
                let color = match v > 0.0 && vmax > 0.0 {
                    true => colour_bar::ramp((v / vmax).clamp(0.0, 1.0)),
                    false => colour_bar::EMPTY,
                };
                let (xa, ya) = (x0 + i as f64 * dx, y0 + j as f64 * dy);
                Rectangle::new([(xa, ya), (xa + dx, ya + dy)], color.filled())
            }))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(
                map.outline
                    .iter()
                    .map(|segment| PathElement::new(segment.to_vec(), BLACK.stroke_width(2))),
            )
            .map_err(|e| e.to_string())?;
        let (_, rows) = chart.plotting_area().get_pixel_range();
        let left = (SIZE.0 - BAR_AREA + 12) as i32;
        Ok(colour_bar::markup(
            left, rows.start, rows.end, vmax, map.value,
        ))
    })
}

/// Bounds of the positive values widened by a factor 1.25 each way (for a logarithmic axis).
fn log_bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = axes::bounds(values.filter(|v| *v > 0.0).map(f64::log10));
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
    write_svg(path, "log-log-plot", |root| {
        let all = || lines.iter().chain(markers).flat_map(|s| s.points.iter());
        let (x0, x1) = log_bounds(all().map(|p| p.0));
        let (y0, y1) = log_bounds(all().map(|p| p.1));
        let mut chart = frame(root, labels.title)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .label_style(("sans-serif", TICK_FONT))
            .axis_desc_style(("sans-serif", AXIS_FONT))
            .x_label_formatter(&|x| format!("{x:e}"))
            .y_label_formatter(&|y| format!("{y}"))
            .x_desc(labels.x)
            .y_desc(labels.y)
            .draw()
            .map_err(|e| e.to_string())?;
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
                .map_err(|e| e.to_string())?
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
                        .map(|p| Circle::new(p, 4, color.filled())),
                )
                .map_err(|e| e.to_string())?
                .label(s.label)
                .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
        }
        legend!(chart, SeriesLabelPosition::UpperRight)?;
        Ok(String::new())
    })
}
