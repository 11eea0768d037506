//! SI figures of the outputs in engineering units, chosen by the key's unit suffix.

use std::f64::consts::PI;

/// `value` of the figure `key` (SI, unit in the name) as text in an engineering unit. A dotted
/// key (`max_depth_m.roller`) takes the unit of its innermost part that names one.
pub fn display(key: &str, value: f64) -> String {
    if !value.is_finite() {
        return "—".into();
    }
    let (scale, unit) = key
        .rsplit('.')
        .map(engineering_unit)
        .find(|(_, unit)| !unit.is_empty())
        .unwrap_or((1.0, ""));
    format!("{} {unit}", significant(value * scale))
        .trim_end()
        .to_string()
}

/// The factor from SI and the unit a figure named `key` is shown in.
fn engineering_unit(key: &str) -> (f64, &'static str) {
    const SUFFIXES: [(&str, f64, &str); 16] = [
        ("_rad_s", 30.0 / PI, "rpm"),
        ("_m_s", 1.0, "m/s"),
        ("_m_s2", 1.0, "m/s²"),
        ("_n", 1.0, "N"),
        ("_pa", 1e-6, "MPa"),
        ("_um", 1.0, "µm"),
        ("_m", 1e6, "µm"),
        ("_s", 1.0, "s"),
        ("_h", 1.0, "h"),
        ("_hours", 1.0, "h"),
        ("_revolutions", 1.0, "rev"),
        ("_hz", 1.0, "Hz"),
        ("_deg", 1.0, "°"),
        ("_rpm", 1.0, "rpm"),
        ("_rad", 180.0 / PI, "°"),
        ("_um_per_1000h", 1.0, "µm/1000 h"),
    ];
    SUFFIXES
        .iter()
        .filter(|(suffix, _, _)| key.ends_with(suffix))
        .max_by_key(|(suffix, _, _)| suffix.len())
        .map_or((1.0, ""), |&(_, scale, unit)| (scale, unit))
}

/// Four significant digits, plain for ordinary magnitudes, else in exponent form.
pub fn significant(value: f64) -> String {
    let magnitude = value.abs();
    if value.fract() == 0.0 && magnitude < 1e15 {
        format!("{value:.0}")
    } else if (1e-3..1e6).contains(&magnitude) {
        let decimals = (3 - magnitude.log10().floor() as i32).max(0) as usize;
        format!("{value:.decimals$}")
    } else {
        format!("{value:.3e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_follow_the_key_suffix() {
        assert_eq!(display("cage_speed_mean_rad_s", PI), "30 rpm");
        assert_eq!(display("cage_speed_mean_rad_s", 1.0), "9.549 rpm");
        assert_eq!(display("max_inner_sliding_speed_m_s", 0.25), "0.2500 m/s");
        assert_eq!(display("max_cage_land_force_n", 12.5), "12.50 N");
        // a slip is a fraction, as in the JSON answer and the CSV tables
        assert_eq!(display("cage_slip_mean", 0.0123), "0.01230");
        assert_eq!(display("max_stress_pa", 4.8e8), "480 MPa");
        assert_eq!(display("whirl_ratio", 1.25), "1.250");
        assert_eq!(display("steps", 123456.0), "123456");
        assert_eq!(display("rejected_steps", 2.0), "2");
        assert_eq!(display("max_roller_cage_force_n", 0.0), "0 N");
        assert_eq!(significant(1.5e-7), "1.500e-7");
        assert_eq!(display("x", f64::NAN), "—");
        assert_eq!(display("life_hours", 25000.0), "25000 h");
        assert_eq!(display("max_depth_m.roller", 1.5e-6), "1.500 µm");
        assert_eq!(display("initial_contacts.rib.mean_lambda", 1.5), "1.500");
    }
}
