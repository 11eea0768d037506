//! The colour ramp of the maps and the colour bar drawn beside them.

use plotters::style::RGBColor;
use std::fmt::Write;

/// Colour of cells with no value (≤ 0).
pub(crate) const EMPTY: RGBColor = RGBColor(235, 235, 245);

/// Blue → cyan → yellow → red colour ramp for `t ∈ [0, 1]`.
pub(crate) fn ramp(t: f64) -> RGBColor {
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

/// Text with `& < >` escaped for SVG.
fn escaped(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A tick value in at most four significant digits.
fn tick(value: f64, max: f64) -> String {
    crate::tick_label(value, 0.0, 2.0 * max)
}

/// SVG markup of a vertical colour bar from `top` to `bottom` (px) whose left edge is at
/// `left`: the ramp from 0 (bottom) to `max` (top), round ticks, and `label` written upwards
/// beside it; the group has the class `colour-bar`.
pub(crate) fn markup(left: i32, top: i32, bottom: i32, max: f64, label: &str) -> String {
    const WIDTH: i32 = 22;
    const STEPS: i32 = 64;
    let height = (bottom - top).max(1);
    let mut svg = format!(
        "<g class=\"colour-bar\" data-label=\"{}\" data-max=\"{max}\">\n",
        escaped(label).replace('"', "&quot;")
    );
    for k in 0..STEPS {
        let y0 = top + height * k / STEPS;
        let y1 = top + height * (k + 1) / STEPS;
        let t = 1.0 - (f64::from(k) + 0.5) / f64::from(STEPS);
        let RGBColor(r, g, b) = ramp(t);
        let _ = writeln!(
            svg,
            "<rect x=\"{left}\" y=\"{y0}\" width=\"{WIDTH}\" height=\"{}\" fill=\"rgb({r},{g},{b})\" stroke=\"none\"/>",
            y1 - y0 + 1
        );
    }
    let _ = writeln!(
        svg,
        "<rect x=\"{left}\" y=\"{top}\" width=\"{WIDTH}\" height=\"{height}\" fill=\"none\" stroke=\"#000\"/>"
    );
    if max > 0.0 {
        let step = crate::nice_step(max, 5);
        let mut value = 0.0;
        while value <= max * (1.0 + 1e-9) {
            let y = f64::from(bottom) - f64::from(height) * value / max;
            let _ = writeln!(
                svg,
                "<line x1=\"{}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#000\"/>\
                 <text x=\"{}\" y=\"{y:.1}\" dy=\"0.35em\" font-family=\"sans-serif\" font-size=\"15\">{}</text>",
                left + WIDTH,
                left + WIDTH + 5,
                left + WIDTH + 8,
                tick(value, max)
            );
            value += step;
        }
    }
    let x = left + WIDTH + 78;
    let y = (top + bottom) / 2;
    let _ = writeln!(
        svg,
        "<text x=\"{x}\" y=\"{y}\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"16\" \
         transform=\"rotate(-90 {x} {y})\">{}</text>\n</g>",
        escaped(label)
    );
    svg
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_has_its_label_and_round_ticks() {
        let svg = markup(600, 40, 400, 1234.0, "pressure, MPa");
        assert!(svg.starts_with("<g class=\"colour-bar\""));
        assert!(svg.contains(">pressure, MPa</text>"));
        assert!(svg.contains(">0</text>") && svg.contains(">1000</text>"));
        assert!(!svg.contains(">1400</text>"));
        assert_eq!(tick(0.25, 0.3), "0.25");
        assert_eq!(tick(0.0, 6e-5), "0");
        assert_eq!(tick(4e-5, 6e-5), "4e-5");
    }
}
