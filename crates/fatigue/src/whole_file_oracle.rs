//! The whole-file path of `rolldyn fatigue rainflow` before the history was streamed (main
//! cc0be90), kept as the test oracle of [`crate::history::rainflow_csv`]: the file read whole
//! under the input-file cap, parsed into a vector, its turning points and four-point stack
//! built over the vector.

use crate::rainflow::{Cycle, HistoryKind};

/// The values of `column` (the first column when `None`) of `text`; the error names the 1-based
/// line and the reason.
fn read_history_csv(text: &str, column: Option<&str>) -> Result<Vec<f64>, String> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let Some((first_n, first)) = lines.next() else {
        return Err("the file has no values".into());
    };
    let fields = |l: &str| {
        l.split(',')
            .map(str::trim)
            .map(String::from)
            .collect::<Vec<_>>()
    };
    let header = fields(first);
    let has_header = header[0].parse::<f64>().is_err();
    let index = match (column, has_header) {
        (None, _) => 0,
        (Some(name), true) => header.iter().position(|h| h == name).ok_or_else(|| {
            format!(
                "line {}: no column '{name}' (columns: {})",
                first_n + 1,
                header.join(", ")
            )
        })?,
        (Some(name), false) => return Err(format!("--column {name}: the file has no header row")),
    };
    let rows = std::iter::once((first_n, first))
        .filter(|_| !has_header)
        .chain(lines);
    let mut values = Vec::new();
    for (n, line) in rows {
        let f = fields(line);
        let field = f
            .get(index)
            .ok_or_else(|| format!("line {}: no field {}", n + 1, index + 1))?;
        let v: f64 = field
            .parse()
            .map_err(|_| format!("line {}: `{field}` is not a number", n + 1))?;
        if !v.is_finite() {
            return Err(format!("line {}: `{field}` is not a finite number", n + 1));
        }
        values.push(v);
    }
    if values.is_empty() {
        return Err("the file has no values".into());
    }
    Ok(values)
}

/// The peaks and valleys of `history`: repeated values and points between two monotone steps are
/// dropped; the ends are kept. NaN values are skipped.
fn turning_points(history: &[f64]) -> Vec<f64> {
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
fn rainflow(history: &[f64], kind: HistoryKind) -> Vec<Cycle> {
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

/// The old path: the file read whole under the cap, parsed, counted.
fn whole_file(
    path: &std::path::Path,
    column: Option<&str>,
    kind: HistoryKind,
) -> Result<(usize, Vec<Cycle>), String> {
    let text = rolldyn_model::read_input_file(path)?;
    let values = read_history_csv(&text, column)?;
    Ok((values.len(), rainflow(&values, kind)))
}

mod tests {
    use super::*;
    use crate::history::rainflow_csv;

    /// A deterministic sequence in [0, 1) (64-bit LCG, Knuth's MMIX constants).
    fn uniform(seed: u64) -> impl Iterator<Item = f64> {
        let mut state = seed;
        std::iter::repeat_with(move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        })
    }

    /// The generated histories (CSV text, name): random, random walks, coarse values with
    /// ties and plateaus, signed zeros, and the edge cases.
    fn histories() -> Vec<(String, Vec<u8>)> {
        let lines =
            |values: &mut dyn Iterator<Item = String>| values.map(|v| v + "\n").collect::<String>();
        let mut cases: Vec<(String, String)> = vec![
            ("constant".into(), "3\n3\n3\n3\n".into()),
            ("one point".into(), "3\n".into()),
            ("two points".into(), "1\n-2\n".into()),
            ("two equal points".into(), "1\n1\n".into()),
            (
                "monotone".into(),
                lines(&mut (0..100).map(|i| i.to_string())),
            ),
            (
                "blank lines, header, CRLF, no final newline".into(),
                "\n  \nstress\r\n-2\r\n\r\n1\n-3\n\n5\n-1\n3\n-4\n4\n-2".into(),
            ),
            (
                "signed zeros".into(),
                "0\n-0\n1\n-0\n0\n-1\n0\n-0\n1\n0\n".into(),
            ),
            ("astm".into(), "-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n".into()),
            ("empty".into(), String::new()),
            ("header only".into(), "stress\n\n".into()),
            ("nan".into(), "1\n2\nNaN\n3\n".into()),
            ("inf".into(), "1\n2\n-inf\n3\n".into()),
            ("not a number".into(), "1\n2\n3x\n".into()),
        ];
        for (seed, n) in [(1, 10), (2, 1000), (3, 100_000)] {
            let random = lines(&mut uniform(seed).take(n).map(|u| (2.0 * u - 1.0).to_string()));
            cases.push((format!("random {n}"), random));
            let mut level = 0.0;
            let walk = uniform(seed + 10).take(n).map(|u| {
                level += (u * 9.0).floor() - 4.0;
                format!("{level}")
            });
            cases.push((
                format!("integer walk {n} (ties, plateaus)"),
                lines(&mut walk.into_iter()),
            ));
            let coarse = uniform(seed + 20)
                .take(n)
                .map(|u| format!("{:.1e}", 1e8 * (u - 0.5)));
            cases.push((format!("coarse {n}"), lines(&mut coarse.into_iter())));
        }
        let columns = uniform(7)
            .take(5000)
            .enumerate()
            .map(|(i, u)| format!("{i}, {:.6e} ,x", 3e8 * (u - 0.3)));
        cases.push((
            "named column".into(),
            "t,stress,note\n".to_string() + &lines(&mut columns.into_iter()),
        ));
        // the largest history the whole-file path takes: just under its cap
        let mut big = String::new();
        for u in uniform(9) {
            let line = format!("{:.17e}\n", 1e9 * (u - 0.5));
            if (big.len() + line.len()) as u64 > rolldyn_model::MAX_INPUT_FILE_BYTES {
                break;
            }
            big.push_str(&line);
        }
        cases.push(("just under 8 MiB".into(), big));
        let mut cases: Vec<(String, Vec<u8>)> = cases
            .into_iter()
            .map(|(n, t)| (n, t.into_bytes()))
            .collect();
        cases.push(("not UTF-8".into(), b"1\n2\n\xe9\n".to_vec()));
        cases
    }

    /// The bits of each cycle, so that −0 and 0 differ.
    fn bits(cycles: &[Cycle]) -> Vec<[u64; 3]> {
        cycles
            .iter()
            .map(|c| [c.range.to_bits(), c.mean.to_bits(), c.count.to_bits()])
            .collect()
    }

    #[test]
    fn streaming_counts_what_the_whole_file_path_counted() {
        let dir =
            std::env::temp_dir().join(format!("rolldyn-rainflow-oracle-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("history.csv");
        for (name, text) in histories() {
            std::fs::write(&path, &text).unwrap();
            let column = name.starts_with("named").then_some("stress");
            for kind in [HistoryKind::NonPeriodic, HistoryKind::Periodic] {
                let old = whole_file(&path, column, kind);
                let new = rainflow_csv(&path, column, kind);
                match (old, new) {
                    (Ok((values, cycles)), Ok(counted)) => {
                        assert_eq!(values, counted.values, "{name} {kind:?}");
                        assert_eq!(bits(&cycles), bits(&counted.cycles), "{name} {kind:?}");
                    }
                    (Err(old), Err(new)) => {
                        // the same line, now with the column
                        let line = |e: &str| e.split([',', ':']).next().unwrap().to_string();
                        if old.starts_with("line ") {
                            assert_eq!(line(&old), line(&new), "{name}: {old} / {new}");
                        }
                        let with_column = new.starts_with("line ") && new.contains(", column ");
                        assert!(!new.contains(" number") || with_column, "{name}: {new}");
                    }
                    (old, new) => panic!("{name} {kind:?}: {old:?} / {new:?}"),
                }
            }
        }
        std::fs::remove_dir_all(dir).ok();
    }
}
