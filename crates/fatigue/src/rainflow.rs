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
    let mut filter = TurningPointFilter::default();
    let mut points: Vec<f64> = history.iter().filter_map(|&x| filter.push(x)).collect();
    points.extend(filter.finish());
    points
}

/// The turning-point rule of [`turning_points`] fed one value at a time: the latest value is a
/// candidate until the next distinct value shows whether it was a peak or a valley (then it is
/// passed on) or a point of a monotone step (then the new value replaces it).
#[derive(Debug, Clone, Copy, Default)]
pub struct TurningPointFilter {
    /// the last turning point passed on
    last: Option<f64>,
    /// the latest value, not yet known to be a turning point
    candidate: Option<f64>,
}

impl TurningPointFilter {
    /// Feeds `x` (NaN is skipped); returns the candidate it shows to be a turning point.
    pub fn push(&mut self, x: f64) -> Option<f64> {
        if x.is_nan() {
            return None;
        }
        let Some(b) = self.candidate else {
            self.candidate = Some(x);
            return None;
        };
        if x == b {
            return None;
        }
        self.candidate = Some(x);
        match self.last {
            // still rising or falling: b was not a turning point
            Some(a) if (b - a) * (x - b) > 0.0 => None,
            _ => {
                self.last = Some(b);
                Some(b)
            }
        }
    }

    /// The end of the history: the last candidate is kept as a turning point.
    pub fn finish(self) -> Option<f64> {
        self.candidate
    }
}

fn full_cycle(a: f64, b: f64) -> Cycle {
    Cycle {
        range: (a - b).abs(),
        mean: 0.5 * (a + b),
        count: 1.0,
    }
}

/// The four-point rule fed one turning point at a time. The stack holds the reversals not
/// closed yet (the residue so far); no four consecutive ones satisfy the rule, so their ranges
/// rise strictly, then fall strictly (at most two equal at the top): a value appears at most
/// once while they rise and once while they fall, so the stack is at most twice the number of
/// distinct values of the history plus one long.
#[derive(Debug, Clone, Default)]
pub struct FourPointStack {
    stack: Vec<f64>,
}

impl FourPointStack {
    /// Pushes turning point `p`; the full cycles it closes go to `cycles`.
    pub fn push(&mut self, p: f64, cycles: &mut Vec<Cycle>) {
        self.stack.push(p);
        while let [.., s1, s2, s3, s4] = self.stack[..] {
            let inner = (s2 - s3).abs();
            if inner <= (s1 - s2).abs() && inner <= (s3 - s4).abs() {
                cycles.push(full_cycle(s2, s3));
                let n = self.stack.len();
                self.stack.drain(n - 3..n - 1);
            } else {
                break;
            }
        }
    }

    /// The reversals left open.
    pub fn residue(self) -> Vec<f64> {
        self.stack
    }
}

/// The four-point rule over `points`: full cycles into `cycles`, the residue returned.
fn four_point(points: impl IntoIterator<Item = f64>, cycles: &mut Vec<Cycle>) -> Vec<f64> {
    let mut stack = FourPointStack::default();
    for p in points {
        stack.push(p, cycles);
    }
    stack.residue()
}

/// Turning points, then the four-point rule, fed one value at a time.
#[derive(Debug, Clone, Default)]
struct StreamingFourPoint {
    filter: TurningPointFilter,
    stack: FourPointStack,
    cycles: Vec<Cycle>,
}

impl StreamingFourPoint {
    fn push(&mut self, x: f64) {
        if let Some(p) = self.filter.push(x) {
            self.stack.push(p, &mut self.cycles);
        }
    }

    /// The full cycles and the residue.
    fn finish(mut self) -> (Vec<Cycle>, Vec<f64>) {
        if let Some(p) = self.filter.finish() {
            self.stack.push(p, &mut self.cycles);
        }
        (self.cycles, self.stack.residue())
    }
}

/// The rainflow cycles of `history` (turning points are found here; any sampled signal will do).
pub fn rainflow(history: &[f64], kind: HistoryKind) -> Vec<Cycle> {
    let each = |feed: &mut dyn FnMut(f64)| {
        history.iter().for_each(|&x| feed(x));
        Ok::<(), std::convert::Infallible>(())
    };
    match rainflow_streamed(kind, each) {
        Ok(cycles) => cycles,
        Err(never) => match never {},
    }
}

/// The rainflow cycles of a history whose values `each` streams (in order, once per call; a
/// periodic history is streamed twice, a non-periodic one once). The memory is the open
/// reversals ([`FourPointStack`]) and the cycles, whatever the length of the history.
pub fn rainflow_streamed<E>(
    kind: HistoryKind,
    mut each: impl FnMut(&mut dyn FnMut(f64)) -> Result<(), E>,
) -> Result<Vec<Cycle>, E> {
    match kind {
        HistoryKind::NonPeriodic => {
            let mut counter = StreamingFourPoint::default();
            each(&mut |x| counter.push(x))?;
            let (mut cycles, residue) = counter.finish();
            cycles.extend(residue.windows(2).map(|w| Cycle {
                count: 0.5,
                ..full_cycle(w[0], w[1])
            }));
            Ok(cycles)
        }
        HistoryKind::Periodic => rainflow_periodic(each),
    }
}

/// The rainflow cycles of one period of a repeating history whose values `each` streams (it is
/// called twice). The turning points are counted from the largest
/// value (the last of equal largest ones), on to the end, then from the beginning up to it and
/// closed with it; the residue is counted again concatenated with itself.
fn rainflow_periodic<E>(
    mut each: impl FnMut(&mut dyn FnMut(f64)) -> Result<(), E>,
) -> Result<Vec<Cycle>, E> {
    // first pass: count from the largest turning point so far, restarting at a new largest one
    let mut largest: Option<(usize, f64)> = None;
    let mut rotated = StreamingFourPoint::default();
    let mut index = 0;
    let mut from_largest = |p: f64| {
        if largest.is_none_or(|(_, max)| p.total_cmp(&max).is_ge()) {
            largest = Some((index, p));
            rotated = StreamingFourPoint::default();
        }
        rotated.push(p);
        index += 1;
    };
    let mut filter = TurningPointFilter::default();
    each(&mut |x| filter.push(x).into_iter().for_each(&mut from_largest))?;
    filter.finish().into_iter().for_each(&mut from_largest);
    let (Some((start, max)), true) = (largest, index >= 2) else {
        return Ok(Vec::new());
    };
    // second pass: the turning points before the largest one, then the largest one again
    let mut filter = TurningPointFilter::default();
    let mut index = 0;
    each(&mut |x| {
        if let Some(p) = filter.push(x) {
            if index < start {
                rotated.push(p);
            }
            index += 1;
        }
    })?;
    rotated.push(max);
    let (mut cycles, residue) = rotated.finish();
    let twice = turning_points(&[&residue[..], &residue[1..]].concat());
    four_point(twice, &mut cycles);
    Ok(cycles)
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
    fn the_open_reversals_stay_within_twice_the_distinct_values() {
        let mut state = 12345u64;
        let mut stack = FourPointStack::default();
        let (mut cycles, mut longest) = (Vec::new(), 0);
        let mut filter = TurningPointFilter::default();
        for _ in 0..200_000 {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let level = ((state >> 33) % 50) as f64; // 50 distinct values
            if let Some(p) = filter.push(level) {
                stack.push(p, &mut cycles);
                longest = longest.max(stack.stack.len());
            }
        }
        assert!(longest <= 2 * 50 + 1, "{longest}");
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
