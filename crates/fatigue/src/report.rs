//! The files of `rolldyn fatigue --out DIR` (docs/outputs.md "Cage fatigue"): the load export,
//! the stress history at the critical location, the fillet damage map, the rainflow matrix, the
//! S–N diagram with the counted cycles and the fillet stress map.

use crate::cage::FilletPoint;
use crate::loads::CageLoadExport;
use crate::plots::{rainflow_matrix, sn_diagram};
use crate::study::FatigueResult;
use crate::unit_stresses::signed_von_mises;
use rolldyn_output::non_finite::csv_field;
use rolldyn_plot::{Labels, Series, line_plot};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Bins of the rainflow matrix per axis.
const MATRIX_BINS: usize = 16;

fn write(path: PathBuf, text: &str, files: &mut Vec<PathBuf>) -> Result<(), String> {
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    files.push(path);
    Ok(())
}

/// Writes the report of `result` to `dir`; returns the files written.
pub fn write_report(
    dir: &Path,
    export: &CageLoadExport,
    result: &FatigueResult,
) -> Result<Vec<PathBuf>, String> {
    let mut files = Vec::new();
    let loads = dir.join("cage-loads.parquet");
    export.write(&loads)?;
    files.push(loads.clone());
    files.push(crate::loads::header_path(&loads));

    let mut history = String::from(
        "set,cage_angle_deg,sigma_rr_pa,sigma_tt_pa,sigma_zz_pa,tau_rt_pa,tau_tz_pa,tau_zr_pa,signed_von_mises_pa\n",
    );
    let mut signed = Vec::with_capacity(result.critical_history.len());
    for (i, (s, angle)) in result
        .critical_history
        .iter()
        .zip(&result.cage_angle_deg)
        .enumerate()
    {
        let vm = signed_von_mises(s);
        signed.push((*angle, vm * 1e-6));
        let fields: Vec<String> = s.iter().map(|&v| csv_field(v)).collect();
        let _ = writeln!(
            history,
            "{i},{},{},{}",
            csv_field(*angle),
            fields.join(","),
            csv_field(vm)
        );
    }
    write(dir.join("critical-history.csv"), &history, &mut files)?;
    let title = format!(
        "Signed von Mises stress at {}",
        result.answer.critical_location
    );
    let plot = dir.join("critical-history.svg");
    line_plot(
        &plot,
        &Labels {
            title: &title,
            x: "cage angle, deg",
            y: "stress, MPa",
        },
        &[Series {
            label: "signed von Mises",
            points: &signed,
        }],
    )
    .map_err(|e| e.to_string())?;
    files.push(plot);

    let mut map =
        String::from("location,x_m,y_m,z_m,max_stress_pa,min_stress_pa,damage_per_revolution\n");
    for p in &result.answer.points {
        let _ = writeln!(
            map,
            "{},{},{},{},{},{},{}",
            p.location,
            csv_field(p.point_m[0]),
            csv_field(p.point_m[1]),
            csv_field(p.point_m[2]),
            csv_field(p.max_stress_pa),
            csv_field(p.min_stress_pa),
            csv_field(p.damage_per_revolution)
        );
    }
    write(dir.join("damage-map.csv"), &map, &mut files)?;
    stress_map(dir, result, &mut files)?;

    let matrix = dir.join("rainflow-matrix.svg");
    rainflow_matrix(&matrix, &result.critical_cycles, MATRIX_BINS).map_err(|e| e.to_string())?;
    files.push(matrix);
    let sn = dir.join("sn-diagram.svg");
    sn_diagram(&sn, &result.answer.sn.curve, &result.critical_damage).map_err(|e| e.to_string())?;
    files.push(sn);
    Ok(files)
}

/// The largest |signed von Mises| of every fillet around the cage, one curve per kind of
/// fillet (rim, window side, face).
fn stress_map(dir: &Path, result: &FatigueResult, files: &mut Vec<PathBuf>) -> Result<(), String> {
    let pockets = result.answer.points.len() / 8;
    let mut curves: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for kind in 0..8 {
        let points: Vec<(f64, f64)> = (0..pockets)
            .map(|bar| {
                let p = &result.answer.points[8 * bar + kind];
                let peak = p.max_stress_pa.abs().max(p.min_stress_pa.abs());
                (bar as f64, peak * 1e-6)
            })
            .collect();
        let label = FilletPoint::all(1)[kind].label().replacen("bar0-", "", 1);
        curves.push((label, points));
    }
    let path = dir.join("fillet-stress-map.svg");
    line_plot(
        &path,
        &Labels {
            title: "Largest |signed von Mises| at the window-corner fillets",
            x: "bar",
            y: "stress, MPa",
        },
        &Series::from_pairs(&curves),
    )
    .map_err(|e| e.to_string())?;
    files.push(path);
    Ok(())
}
