//! Rainflow cycle counting, ASTM E1049-85 (2017) §5.4.4, the four-point form (equivalent to GOST
//! 25.101-83, which seed 000 §2.5 cites): on the turning points S₁…S₄ at the end of the stack, if
//! |S₂ − S₃| ≤ |S₁ − S₂| and |S₂ − S₃| ≤ |S₃ − S₄| the pair S₂, S₃ is one full cycle of range
//! |S₂ − S₃| and mean (S₂ + S₃)/2 and leaves the stack.
//!
//! A periodic history (one steady cage revolution repeated) closes every cycle: the turning
//! points are rotated to start at the largest value and closed with it, and the residue the
//! four-point rule leaves is counted again concatenated with itself — its closed cycles are the
//! full cycles the repetition completes. A non-periodic history counts its residue as half
//! cycles (ASTM E1049 §5.4.4.3).

use serde::Serialize;

/// One counted cycle: `count` 1 (a full cycle) or ½ (a half cycle of the residue).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Cycle {
    /// stress range Δσ = 2 σ_a (the unit of the history)
    pub range: f64,
    /// mean (σ_max + σ_min)/2
    pub mean: f64,
    pub count: f64,
}

/// Whether the history repeats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HistoryKind {
    /// one period of a repeating history (every cycle closes)
    Periodic,
    /// a record with a beginning and an end (the residue gives half cycles)
    NonPeriodic,
}

/// The peaks and valleys of `history`: repeated values and points between two monotone steps are
/// dropped; the ends are kept. NaN values are skipped.
pub fn turning_points(history: &[f64]) -> Vec<f64> {
    let mut points: Vec<f64> = Vec::new();
    for &x in history.iter().filter(|x| !x.is_nan()) {
        match points.len() {
            0 => points.push(x),
            _ if x == points[points.len() - 1] => {}
            1 => points.push(x),
            n => {
                let (a, b) = (points[n - 2], points[n - 1]);
                if (b - a) * (x - b) > 0.0 {
                    points[n - 1] = x; // still rising or falling: b was not a turning point
                } else {
                    points.push(x);
                }
            }
        }
    }
    points
}

fn full_cycle(a: f64, b: f64) -> Cycle {
    Cycle {
        range: (a - b).abs(),
        mean: 0.5 * (a + b),
        count: 1.0,
    }
}

/// The four-point rule over `points`: full cycles into `cycles`, the residue returned.
fn four_point(points: impl IntoIterator<Item = f64>, cycles: &mut Vec<Cycle>) -> Vec<f64> {
    let mut stack: Vec<f64> = Vec::new();
    for p in points {
        stack.push(p);
        while stack.len() >= 4 {
            let n = stack.len();
            let (s1, s2, s3, s4) = (stack[n - 4], stack[n - 3], stack[n - 2], stack[n - 1]);
            let inner = (s2 - s3).abs();
            if inner <= (s1 - s2).abs() && inner <= (s3 - s4).abs() {
                cycles.push(full_cycle(s2, s3));
                stack.drain(n - 3..n - 1);
            } else {
                break;
            }
        }
    }
    stack
}

/// The rainflow cycles of `history` (turning points are found here; any sampled signal will do).
pub fn rainflow(history: &[f64], kind: HistoryKind) -> Vec<Cycle> {
    let points = turning_points(history);
    let mut cycles = Vec::new();
    if points.len() < 2 {
        return cycles;
    }
    match kind {
        HistoryKind::NonPeriodic => {
            let residue = four_point(points, &mut cycles);
            cycles.extend(residue.windows(2).map(|w| Cycle {
                count: 0.5,
                ..full_cycle(w[0], w[1])
            }));
        }
        HistoryKind::Periodic => {
            // start at the largest value (the last index of a periodic sample may repeat the
            // first: the rotation and the closing point make that harmless)
            let start = (0..points.len())
                .max_by(|&i, &j| points[i].total_cmp(&points[j]))
                .unwrap_or(0);
            let rotated = points[start..].iter().chain(&points[..start]).copied();
            let closed = turning_points(&rotated.chain([points[start]]).collect::<Vec<_>>());
            let residue = four_point(closed, &mut cycles);
            let twice = turning_points(&[&residue[..], &residue[1..]].concat());
            four_point(twice, &mut cycles);
        }
    }
    cycles
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counts per range, sorted by range.
    fn by_range(cycles: &[Cycle]) -> Vec<(f64, f64)> {
        let mut out: Vec<(f64, f64)> = Vec::new();
        for c in cycles {
            match out.iter_mut().find(|(r, _)| (*r - c.range).abs() < 1e-12) {
                Some((_, n)) => *n += c.count,
                None => out.push((c.range, c.count)),
            }
        }
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        out
    }

    /// ASTM E1049-85 Fig. 6 / Table 4 (rainflow counting of the example history).
    const ASTM_EXAMPLE: [f64; 9] = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];

    #[test]
    fn astm_e1049_worked_example() {
        let counted = by_range(&rainflow(&ASTM_EXAMPLE, HistoryKind::NonPeriodic));
        assert_eq!(
            counted,
            vec![(3.0, 0.5), (4.0, 1.5), (6.0, 0.5), (8.0, 1.0), (9.0, 0.5)]
        );
    }

    #[test]
    fn turning_points_drop_plateaus_and_monotone_steps() {
        assert_eq!(
            turning_points(&[0.0, 1.0, 2.0, 2.0, 1.0, f64::NAN, 1.0, 3.0]),
            vec![0.0, 2.0, 1.0, 3.0]
        );
    }

    #[test]
    fn a_periodic_sine_with_a_ripple_closes_the_big_and_the_small_cycle() {
        // one period: 0 → 10 → 4 → 6 → −10 → 0 (the ripple 4 ↔ 6 rides on the big swing)
        let cycles = by_range(&rainflow(
            &[0.0, 10.0, 4.0, 6.0, -10.0, 0.0],
            HistoryKind::Periodic,
        ));
        assert_eq!(cycles, vec![(2.0, 1.0), (20.0, 1.0)]);
    }
}
