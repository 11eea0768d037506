//! Rainflow counting against an independent implementation: ASTM E1049-85 §5.4.4's
//! three-point range-counting procedure written from the standard's text (a different algorithm
//! from the crate's four-point rule), on pseudo-random histories; and the periodic mode against
//! that procedure on the history rotated to start and end at its largest value; and the
//! periodic count against what one more repetition of the period adds.

use rolldyn_fatigue::{Cycle, HistoryKind, rainflow, turning_points};

/// ASTM E1049-85 §5.4.4 (rainflow counting): read peaks and valleys one by one; let X be the
/// range of the two latest points and Y the one before it. While X ≥ Y: if Y contains the
/// starting point S, count Y as a half cycle and drop its first point (S moves on); else count Y
/// as one cycle and drop its two points. At the end every remaining range is a half cycle.
fn astm_three_point(history: &[f64]) -> Vec<Cycle> {
    let mut stack: Vec<f64> = Vec::new();
    let mut out = Vec::new();
    let cycle = |a: f64, b: f64, count: f64| Cycle {
        range: (a - b).abs(),
        mean: 0.5 * (a + b),
        count,
    };
    for p in turning_points(history) {
        stack.push(p);
        while stack.len() >= 3 {
            let n = stack.len();
            let x = (stack[n - 1] - stack[n - 2]).abs();
            let y = (stack[n - 2] - stack[n - 3]).abs();
            if x < y {
                break;
            }
            // the starting point S is always the first point left on the stack
            if n == 3 {
                out.push(cycle(stack[n - 3], stack[n - 2], 0.5));
                stack.remove(n - 3);
            } else {
                out.push(cycle(stack[n - 3], stack[n - 2], 1.0));
                stack.drain(n - 3..n - 1);
            }
        }
    }
    for w in stack.windows(2) {
        out.push(cycle(w[0], w[1], 0.5));
    }
    out
}

/// Total count per (range, mean) rounded to 1e-9, sorted — two countings agree when these do.
fn histogram(cycles: &[Cycle]) -> Vec<(i64, i64, i64)> {
    let key = |v: f64| (v * 1e9).round() as i64;
    let mut map = std::collections::BTreeMap::new();
    for c in cycles {
        *map.entry((key(c.range), key(c.mean))).or_insert(0.0) += c.count;
    }
    map.into_iter()
        .filter(|(_, n)| *n != 0.0)
        .map(|((r, m), n)| (r, m, (2.0 * n) as i64))
        .collect()
}

fn random_history(seed: u64, n: usize) -> Vec<f64> {
    let mut state = seed;
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((state >> 33) as f64 / (1u64 << 31) as f64 * 200.0 - 100.0).round()
        })
        .collect()
}

#[test]
fn non_periodic_counts_match_the_standards_procedure() {
    for seed in 1..=200 {
        let h = random_history(seed, 5 + (seed as usize % 60));
        assert_eq!(
            histogram(&rainflow(&h, HistoryKind::NonPeriodic)),
            histogram(&astm_three_point(&h)),
            "seed {seed}: {h:?}"
        );
    }
}

#[test]
fn periodic_counts_match_the_procedure_on_the_history_closed_at_its_maximum() {
    for seed in 1..=200 {
        let h = random_history(seed, 5 + (seed as usize % 60));
        let top = (0..h.len()).max_by(|&a, &b| h[a].total_cmp(&h[b])).unwrap();
        let mut closed: Vec<f64> = h[top..].iter().chain(&h[..top]).copied().collect();
        closed.push(h[top]);
        // started and ended at the maximum, the procedure leaves only the half cycles of the
        // residue, which pair into full cycles of the same range and mean
        assert_eq!(
            histogram(&rainflow(&h, HistoryKind::Periodic)),
            histogram(&astm_three_point(&closed)),
            "seed {seed}: {h:?}"
        );
    }
}

#[test]
fn a_period_counts_what_its_repetition_adds() {
    // counting r repetitions non-periodically, every repetition after the first adds the
    // periodic count of one period (only the ends' residue differs)
    for seed in 1..20 {
        let one = random_history(seed, 60);
        let periodic = rainflow(&one, HistoryKind::Periodic);
        assert!(periodic.iter().all(|c| c.count == 1.0));
        let full = |reps: usize| -> f64 {
            let h: Vec<f64> = (0..reps).flat_map(|_| one.iter().copied()).collect();
            rainflow(&h, HistoryKind::NonPeriodic)
                .iter()
                .filter(|c| c.count == 1.0)
                .map(|c| c.range * c.range)
                .sum()
        };
        let per_period: f64 = periodic.iter().map(|c| c.range * c.range).sum();
        let added = full(6) - full(5);
        assert!(
            (added / per_period - 1.0).abs() < 1e-9,
            "seed {seed}: {added} vs {per_period}"
        );
    }
}
