//! Raceway wear maps: the `[inner_ring.raceway_wear]` / `[outer_ring.raceway_wear]` key of a
//! model file and the CSV file it names (docs/model-format.md "Raceway wear").
//!
//! CSV long format, header `axial_mm,angle_deg,depth_um`: one row per (axial line, angle bin)
//! of a complete grid, axial-major, the angles at the bin centres (k + ½)·360/bins.

use crate::schema::{ModelFile, RingSection};
use rolldyn_geometry::{BearingModel, GeometryError, RacewayWearMap, Ring};
use std::io::{self, Write};
use std::path::Path;

/// The header of a raceway wear CSV file.
pub const RACEWAY_WEAR_HEADER: &str = "axial_mm,angle_deg,depth_um";

/// How far a row's angle may lie from its bin centre, degrees (hand-written files round).
const ANGLE_TOLERANCE_DEG: f64 = 1e-3;

/// A wear depth may be at most this fraction of the roller diameter: a raceway worn deeper than
/// 5 % of D_w (hundreds of µm on any bearing, where service wear limits are tens of µm and the
/// radial clearance is ≈ 0.1–0.5 % of D_w) no longer guides its rollers — not the wear map of a
/// working bearing.
pub const MAX_WEAR_DEPTH_PER_ROLLER_DIAMETER: f64 = 0.05;

const M_PER_MM: f64 = 1e-3;
const M_PER_UM: f64 = 1e-6;

/// Writes `map` as a raceway wear CSV file (the format [`read_raceway_wear_csv`] reads).
pub fn write_raceway_wear_csv(map: &RacewayWearMap, mut w: impl Write) -> io::Result<()> {
    writeln!(w, "{RACEWAY_WEAR_HEADER}")?;
    let bins = map.angle_bins();
    for (i, &x) in map.axial_m().iter().enumerate() {
        for k in 0..bins {
            let angle_deg = map.bin_centre_rad(k).to_degrees();
            let depth = map.depth_m()[i * bins + k];
            writeln!(w, "{},{},{}", x / M_PER_MM, angle_deg, depth / M_PER_UM)?;
        }
    }
    Ok(())
}

/// Reads a raceway wear CSV text whose depths are at most `max_depth_m` (see
/// [`MAX_WEAR_DEPTH_PER_ROLLER_DIAMETER`]); the error names the 1-based line and the reason.
pub fn read_raceway_wear_csv(text: &str, max_depth_m: f64) -> Result<RacewayWearMap, String> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(n, l)| (n + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty());
    match lines.next() {
        Some((_, header)) if header.replace(' ', "") == RACEWAY_WEAR_HEADER => {}
        _ => {
            return Err(format!(
                "line 1: the header must be `{RACEWAY_WEAR_HEADER}`"
            ));
        }
    }
    let rows = lines
        .map(|(n, l)| {
            parse_row(l)
                .map(|r| (n, r))
                .map_err(|e| format!("line {n}: {e}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let Some(&(_, [x0, _, _])) = rows.first() else {
        return Err("no data rows".into());
    };
    let bins = rows.iter().take_while(|(_, r)| r[0] == x0).count();
    if rows.len() % bins != 0 {
        return Err(format!(
            "{} rows are not a complete grid of {bins} angle bins per axial line",
            rows.len()
        ));
    }
    let mut axial = Vec::with_capacity(rows.len() / bins);
    let mut depth = Vec::with_capacity(rows.len());
    for (r, &(n, [x_mm, angle_deg, depth_um])) in rows.iter().enumerate() {
        let (i, k) = (r / bins, r % bins);
        if k == 0 {
            if axial.last().is_some_and(|&last| x_mm * M_PER_MM <= last) {
                return Err(format!(
                    "line {n}: axial_mm must increase from one line to the next"
                ));
            }
            axial.push(x_mm * M_PER_MM);
        } else if x_mm * M_PER_MM != axial[i] {
            return Err(format!(
                "line {n}: axial_mm {x_mm} differs from {} of its axial line ({bins} rows each)",
                axial[i] / M_PER_MM
            ));
        }
        let centre = rolldyn_geometry::angle_bin_centre_rad(k, bins).to_degrees();
        if (angle_deg - centre).abs() > ANGLE_TOLERANCE_DEG {
            return Err(format!(
                "line {n}: angle_deg {angle_deg} is not the centre {centre} of bin {k} of {bins}"
            ));
        }
        if depth_um < 0.0 {
            return Err(format!(
                "line {n}: depth_um {depth_um} must not be negative"
            ));
        }
        if depth_um * M_PER_UM > max_depth_m {
            return Err(format!(
                "line {n}: depth_um {depth_um:.4e} is implausible: deeper than {:.1} µm, 5 % of \
                 the roller diameter (not the wear of a working bearing)",
                max_depth_m / M_PER_UM
            ));
        }
        depth.push(depth_um * M_PER_UM);
    }
    RacewayWearMap::new(axial, bins, depth).map_err(|e| e.reason)
}

/// The three finite numbers of a data row.
fn parse_row(line: &str) -> Result<[f64; 3], String> {
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    let [a, b, c] = fields[..] else {
        return Err(format!("{} fields, expected 3", fields.len()));
    };
    let number = |s: &str| match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("`{s}` is not a finite number")),
    };
    Ok([number(a)?, number(b)?, number(c)?])
}

/// Reads the wear maps the rings of `file` name (paths relative to the model file's directory)
/// into the rings of `bearing`.
pub(crate) fn attach(
    bearing: &mut BearingModel,
    file: &ModelFile,
    model_file: &str,
) -> Result<(), GeometryError> {
    let max_depth_m = bearing
        .roller()
        .map_or(0.0, |r| MAX_WEAR_DEPTH_PER_ROLLER_DIAMETER * r.diameter);
    let mut rings: Vec<(&mut Ring, Option<&RingSection>, &str)> = match bearing {
        BearingModel::Cylindrical(b) => vec![
            (&mut b.inner_ring, file.inner_ring.as_ref(), "inner_ring"),
            (&mut b.outer_ring, file.outer_ring.as_ref(), "outer_ring"),
        ],
        BearingModel::RollerRaceway(p) => {
            let (section, key) = if p.raceway_is_inner {
                (file.inner_ring.as_ref(), "inner_ring")
            } else {
                (file.outer_ring.as_ref(), "outer_ring")
            };
            vec![(&mut p.raceway, section, key)]
        }
        BearingModel::Tapered(_) => vec![],
    };
    for (ring, section, key) in &mut rings {
        if let Some(wear) = section.and_then(|s| s.raceway_wear.as_ref()) {
            ring.raceway_wear = Some(load(&wear.file, model_file, key, max_depth_m)?);
        }
    }
    Ok(())
}

/// The map in `csv_file` (relative to the directory of `model_file`), depths at most
/// `max_depth_m`; errors at `<key>.raceway_wear.file` name the CSV file.
fn load(
    csv_file: &str,
    model_file: &str,
    key: &str,
    max_depth_m: f64,
) -> Result<RacewayWearMap, GeometryError> {
    let path = Path::new(model_file)
        .parent()
        .unwrap_or(Path::new("."))
        .join(csv_file);
    let fail = |e: String| {
        GeometryError::new(
            format!("{key}.raceway_wear.file"),
            format!("{}: {e}", path.display()),
        )
    };
    let text = crate::read_input_file(&path).map_err(fail)?;
    read_raceway_wear_csv(&text, max_depth_m).map_err(fail)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_by_three() -> RacewayWearMap {
        RacewayWearMap::new(
            vec![-0.005, 0.005],
            3,
            vec![1e-6, 2e-6, 3e-6, 4e-6, 5e-6, 6.5e-6],
        )
        .unwrap()
    }

    #[test]
    fn written_maps_read_back() {
        let map = two_by_three();
        let mut csv = Vec::new();
        write_raceway_wear_csv(&map, &mut csv).unwrap();
        let back = read_raceway_wear_csv(std::str::from_utf8(&csv).unwrap(), 1e-3).unwrap();
        assert_eq!(back.axial_m(), map.axial_m());
        assert_eq!(back.angle_bins(), 3);
        for (a, b) in back.depth_m().iter().zip(map.depth_m()) {
            assert!((a - b).abs() < 1e-18);
        }
    }

    #[test]
    fn bad_rows_are_named() {
        let head = RACEWAY_WEAR_HEADER;
        let cases = [
            ("x,y,z\n0,180,1\n", "line 1: the header"),
            (&*format!("{head}\n0,180\n"), "line 2: 2 fields"),
            (&*format!("{head}\n0,90,1\n"), "line 2: angle_deg 90"),
            (&*format!("{head}\n0,180,-1\n"), "line 2: depth_um -1"),
            (&*format!("{head}\n0,90,1\n0,270,x\n"), "line 3: `x`"),
            (&*format!("{head}\n0,90,1\n0,270,1\n1,90,1\n"), "3 rows"),
            (
                &*format!("{head}\n1,180,1\n0,180,1\n"),
                "line 3: axial_mm must",
            ),
            (&*format!("{head}\n"), "no data rows"),
            (
                &*format!("{head}\n0,180,1e308\n"),
                "line 2: depth_um 1.0000e308 is implausible",
            ),
        ];
        for (text, expected) in cases {
            let e = read_raceway_wear_csv(text, 1e-3).unwrap_err();
            assert!(e.starts_with(expected), "{e} ≠ {expected}…");
        }
    }
}
