//! Axis ranges: near the data, and equal aspect for orbits.

/// The finite minimum and maximum of `values`; (0, 1) when there is none, ±0.5 around a
/// single value.
pub(crate) fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-12 * hi.abs().max(lo.abs()) || hi - lo < 1e-300 {
        let half = match lo == 0.0 {
            true => 0.5,
            false => 0.05 * lo.abs(),
        };
        return (lo - half, hi + half);
    }
    (lo, hi)
}

/// The range of an axis showing `values`: the data padded by 5 % of their span each way, from
/// 0 only when 0 lies within a quarter of the span below the data (a cage speed of 390…410
/// rad/s is drawn from about 389, a force of 30…700 N from 0).
pub fn data_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = bounds(values);
    let span = hi - lo;
    let pad = 0.05 * span;
    let lo = match lo >= 0.0 && lo <= 0.25 * span {
        true => 0.0,
        false => lo - pad,
    };
    let hi = match hi <= 0.0 && -hi <= 0.25 * span {
        true => 0.0,
        false => hi + pad,
    };
    (lo, hi)
}

/// `x` and `y` ranges widened (by `pad` of the larger span each way, then on the shorter side)
/// so that one unit is as long on both axes of a plotting area `aspect` = width / height.
pub(crate) fn equal_aspect(
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    aspect: f64,
    pad: f64,
) -> ((f64, f64), (f64, f64)) {
    let margin = pad * (x1 - x0).max(y1 - y0);
    let (mut x0, mut x1, mut y0, mut y1) = (x0 - margin, x1 + margin, y0 - margin, y1 + margin);
    let (width, height) = (x1 - x0, y1 - y0);
    if width / height < aspect {
        let grow = 0.5 * (height * aspect - width);
        x0 -= grow;
        x1 += grow;
    } else {
        let grow = 0.5 * (width / aspect - height);
        y0 -= grow;
        y1 += grow;
    }
    ((x0, x1), (y0, y1))
}

/// A round tick step (1, 2 or 5 × 10ⁿ) giving about `ticks` intervals over `span`.
pub fn nice_step(span: f64, ticks: usize) -> f64 {
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return 1.0;
    }
    let raw = span / ticks.max(1) as f64;
    let decade = 10f64.powf(raw.log10().floor());
    let mantissa = raw / decade;
    let nice = match mantissa {
        m if m <= 1.0 => 1.0,
        m if m <= 2.0 => 2.0,
        m if m <= 5.0 => 5.0,
        _ => 10.0,
    };
    nice * decade
}

/// Text of a tick at `value` on an axis from `lo` to `hi` (about ten ticks): as many digits as
/// tell neighbouring ticks apart, trailing zeros dropped, exponent form for magnitudes below
/// 10⁻³ or from 10⁶.
pub fn tick_label(value: f64, lo: f64, hi: f64) -> String {
    let step = ((hi - lo) / 10.0).abs();
    if value == 0.0 || !value.is_finite() || step.is_nan() || step <= 0.0 {
        return if value == 0.0 {
            "0".into()
        } else {
            format!("{value}")
        };
    }
    if value.abs() < step * 1e-6 {
        return "0".into();
    }
    let magnitude = lo.abs().max(hi.abs());
    if !(1e-3..1e6).contains(&magnitude) {
        let digits = ((magnitude / step).log10().ceil() as i32 + 1).clamp(1, 8) as usize;
        let text = format!("{value:.prec$e}", prec = digits - 1);
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        return format!("{}e{exponent}", trimmed(mantissa));
    }
    let decimals = (-step.log10().floor() as i32 + 1).clamp(0, 12) as usize;
    trimmed(&format!("{value:.decimals$}"))
}

/// A decimal number without trailing zeros (nor a trailing point).
fn trimmed(text: &str) -> String {
    match text.contains('.') {
        true => text.trim_end_matches('0').trim_end_matches('.').to_string(),
        false => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_start_near_the_data_and_from_zero_only_close_to_it() {
        let (lo, hi) = data_range([392.0, 398.0, 410.0].into_iter());
        assert!(
            lo > 385.0 && lo < 392.0 && hi > 410.0 && hi < 412.0,
            "{lo} {hi}"
        );
        assert_eq!(data_range([30.0, 700.0].into_iter()).0, 0.0);
        let (lo, hi) = data_range([-0.005, -0.003].into_iter());
        assert!(lo < -0.005 && hi > -0.003 && hi < 0.0, "{lo} {hi}");
        assert_eq!(data_range([-700.0, -30.0].into_iter()).1, 0.0);
        let (lo, hi) = data_range([5.0, 5.0].into_iter());
        assert!(lo < 5.0 && hi > 5.0);
        assert_eq!(data_range(std::iter::empty()), (0.0, 1.05));
    }

    #[test]
    fn equal_aspect_gives_one_unit_the_same_length_on_both_axes() {
        let ((x0, x1), (y0, y1)) = equal_aspect((-1.0, 1.0), (-3.0, 3.0), 1.5, 0.0);
        assert!(((x1 - x0) / (y1 - y0) - 1.5).abs() < 1e-12);
        assert!(y0 <= -3.0 && y1 >= 3.0 && x0 <= -1.0 && x1 >= 1.0);
    }

    #[test]
    fn tick_labels_tell_neighbours_apart() {
        assert_eq!(tick_label(392.5, 391.0, 394.0), "392.5");
        assert_eq!(tick_label(200.0, 0.0, 700.0), "200");
        assert_eq!(tick_label(2.5e-5, 0.0, 5.5e-5), "2.5e-5");
        assert_eq!(tick_label(3e-5, 0.0, 5.5e-5), "3e-5");
        assert_eq!(tick_label(0.0035, -0.005, 0.0), "0.0035");
        assert_eq!(tick_label(1e-18, -1.0, 1.0), "0");
        assert_eq!(tick_label(1.5e6, 0.0, 2e6), "1.5e6");
    }

    #[test]
    fn tick_steps_are_round() {
        assert_eq!(nice_step(100.0, 5), 20.0);
        assert_eq!(nice_step(1.3, 5), 0.5);
        assert!((nice_step(0.07, 5) - 0.02).abs() < 1e-15);
    }
}
