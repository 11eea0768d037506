//! Reading ccx's results: the nodal stresses of the `.frd` file and the support reactions
//! printed in the `.dat` file, one block per step in step order.

use super::CalculixError;
use std::collections::HashMap;

/// Cartesian nodal stresses `[xx, yy, zz, xy, yz, zx]` by node number, Pa.
pub type NodalStresses = HashMap<usize, [f64; 6]>;

/// The `STRESS` blocks of a `.frd` file in order (one per step).
pub fn parse_frd_stresses(text: &str) -> Result<Vec<NodalStresses>, CalculixError> {
    let mut blocks = Vec::new();
    let mut current: Option<NodalStresses> = None;
    for line in text.lines() {
        if line.starts_with(" -4") {
            current = line.contains("STRESS").then(HashMap::new);
        } else if line.starts_with(" -3") {
            blocks.extend(current.take());
        } else if let (Some(block), true) = (current.as_mut(), line.starts_with(" -1")) {
            let (node, values) = frd_record(line)
                .ok_or_else(|| CalculixError::Results(format!("bad .frd record '{line}'")))?;
            block.insert(node, values);
        }
    }
    Ok(blocks)
}

/// A `-1` record: node number (10 characters after the key) and six 12-character values.
fn frd_record(line: &str) -> Option<(usize, [f64; 6])> {
    let node = line.get(3..13)?.trim().parse().ok()?;
    let mut values = [0.0; 6];
    for (k, v) in values.iter_mut().enumerate() {
        *v = line.get(13 + 12 * k..25 + 12 * k)?.trim().parse().ok()?;
    }
    Some((node, values))
}

/// The nodal force blocks of `*NODE PRINT … RF` in a `.dat` file, in order: per step the
/// `(node, [fx, fy, fz])` of the printed set, N.
pub fn parse_dat_forces(text: &str) -> Vec<Vec<(usize, [f64; 3])>> {
    let mut blocks = Vec::new();
    let mut current: Option<Vec<(usize, [f64; 3])>> = None;
    for line in text.lines() {
        if line.trim_start().starts_with("forces (fx,fy,fz)") {
            blocks.extend(current.take());
            current = Some(Vec::new());
            continue;
        }
        let Some(block) = current.as_mut() else {
            continue;
        };
        let fields: Vec<f64> = line
            .split_whitespace()
            .filter_map(|f| f.parse().ok())
            .collect();
        match fields.as_slice() {
            [node, fx, fy, fz] => block.push((*node as usize, [*fx, *fy, *fz])),
            [] if line.trim().is_empty() => {}
            _ => blocks.extend(current.take()),
        }
    }
    blocks.extend(current);
    blocks
}

#[cfg(test)]
mod tests {
    use super::*;

    const FRD: &str = r"    1PSTEP                         1           1           1
 -4  STRESS      6    1
 -5  SXX         1    4    1    1
 -1         1-6.67622E+06-1.73917E+06 2.89317E+03-5.60958E+05 4.64583E+05 1.65370E+06
 -1        12 4.06436E+06 8.38216E+05-5.88207E+05 3.57664E+05 3.45863E+05 9.86736E+05
 -3
 -4  ERROR       1    1
 -1         1 3.31055E+01
 -3
 -4  STRESS      6    1
 -1         1 1.00000E+00 2.00000E+00 3.00000E+00 4.00000E+00 5.00000E+00 6.00000E+00
 -3
";

    #[test]
    fn reads_the_stress_blocks_only() {
        let blocks = parse_frd_stresses(FRD).unwrap();
        assert_eq!(blocks.len(), 2);
        assert_eq!(blocks[0][&12][2], -5.88207e5);
        assert_eq!(blocks[0][&1][0], -6.67622e6);
        assert_eq!(blocks[1][&1], [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn reads_the_printed_reactions_per_step() {
        let dat = r"
 forces (fx,fy,fz) for set SUPPORT and time  0.1000000E+01

         1 -3.746182E+00 -5.327408E-01  4.834350E-01
         2  2.695903E+00  5.763533E-01  6.2E-08

 forces (fx,fy,fz) for set SUPPORT and time  0.2000000E+01

         1  1.0E-02 0.0 0.0
";
        let blocks = parse_dat_forces(dat);
        assert_eq!(blocks.len(), 2);
        assert_eq!(blocks[0].len(), 2);
        assert_eq!(blocks[0][1], (2, [2.695903, 0.5763533, 6.2e-8]));
        assert_eq!(blocks[1], vec![(1, [1e-2, 0.0, 0.0])]);
    }

    #[test]
    fn a_broken_record_is_an_error() {
        assert!(parse_frd_stresses(" -4  STRESS\n -1         1 garbage\n -3\n").is_err());
    }
}
