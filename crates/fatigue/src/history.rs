//! A stress history from a CSV file: one value per row, in the first column or in a named one;
//! a header row is recognised by a first field that is not a number. The file is read line by
//! line (no size limit): the memory is one line, whatever the length of the history.

use crate::rainflow::{Cycle, HistoryKind, rainflow_streamed};
use std::io::BufRead;
use std::path::Path;

/// Feeds the values of `column` (the first column when `None`) of the CSV text `reader` to
/// `sink`, in order, and returns their number; the error names the 1-based line, the column
/// and the reason (`line 3, column 2 (stress): `x` is not a number`).
pub fn read_history_values(
    mut reader: impl BufRead,
    column: Option<&str>,
    mut sink: impl FnMut(f64),
) -> Result<usize, String> {
    let mut bytes = Vec::new();
    let mut line_number = 0;
    // the column counted and how a row's error names it; None until the first non-blank line
    let mut counted: Option<(usize, String)> = None;
    let mut values = 0;
    loop {
        bytes.clear();
        let read = reader
            .read_until(b'\n', &mut bytes)
            .map_err(|e| format!("cannot read the file: {e}"))?;
        if read == 0 {
            break;
        }
        line_number += 1;
        let line = std::str::from_utf8(&bytes).map_err(|e| {
            format!(
                "line {line_number}: not UTF-8 text (invalid byte at byte {} of the line)",
                e.valid_up_to() + 1
            )
        })?;
        if line.trim().is_empty() {
            continue;
        }
        let (index, name) = match &counted {
            Some(c) => c,
            None => {
                let header: Vec<&str> = line.split(',').map(str::trim).collect();
                let has_header = header[0].parse::<f64>().is_err();
                let index = header_index(&header, has_header, column, line_number)?;
                let name = if has_header {
                    format!("column {} ({})", index + 1, header[index])
                } else {
                    format!("column {}", index + 1)
                };
                let c = counted.insert((index, name));
                if has_header {
                    continue;
                }
                c
            }
        };
        let field = line.split(',').nth(*index).map(str::trim).ok_or_else(|| {
            format!(
                "line {line_number}, {name}: no such field (the row has {})",
                line.split(',').count()
            )
        })?;
        let v: f64 = field
            .parse()
            .map_err(|_| format!("line {line_number}, {name}: `{field}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!(
                "line {line_number}, {name}: `{field}` is not a finite number"
            ));
        }
        sink(v);
        values += 1;
    }
    if values == 0 {
        return Err("the file has no values".into());
    }
    Ok(values)
}

/// The index of the counted column among the first row's fields `header`.
fn header_index(
    header: &[&str],
    has_header: bool,
    column: Option<&str>,
    line_number: usize,
) -> Result<usize, String> {
    match (column, has_header) {
        (None, _) => Ok(0),
        (Some(name), true) => header.iter().position(|h| *h == name).ok_or_else(|| {
            format!(
                "line {line_number}: no column '{name}' (columns: {})",
                header.join(", ")
            )
        }),
        (Some(name), false) => Err(format!("--column {name}: the file has no header row")),
    }
}

/// A history counted by rainflow.
#[derive(Debug, Clone, PartialEq)]
pub struct CountedHistory {
    /// number of values read
    pub values: usize,
    pub cycles: Vec<Cycle>,
}

/// The rainflow cycles of `column` of the CSV file `path`, streamed: the memory is one line,
/// the open reversals ([`crate::rainflow::FourPointStack`]) and the cycles. A periodic history
/// is read twice (from its largest value); the error says why not (without the path, which
/// the caller names).
pub fn rainflow_csv(
    path: &Path,
    column: Option<&str>,
    kind: HistoryKind,
) -> Result<CountedHistory, String> {
    let read = |sink: &mut dyn FnMut(f64)| {
        let file = std::fs::File::open(path).map_err(|e| format!("cannot read the file: {e}"))?;
        read_history_values(
            std::io::BufReader::with_capacity(1 << 16, file),
            column,
            sink,
        )
    };
    let mut passes: Vec<usize> = Vec::with_capacity(2);
    let cycles = rainflow_streamed(kind, |sink| read(sink).map(|n| passes.push(n)))?;
    if passes.windows(2).any(|w| w[0] != w[1]) {
        return Err("the file changed while it was read".into());
    }
    Ok(CountedHistory {
        values: passes[0],
        cycles,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(text: &str, column: Option<&str>) -> Result<Vec<f64>, String> {
        let mut values = Vec::new();
        read_history_values(text.as_bytes(), column, |v| values.push(v))?;
        Ok(values)
    }

    #[test]
    fn headers_columns_and_errors() {
        assert_eq!(values("1\n-2\n3\n", None).unwrap(), vec![1.0, -2.0, 3.0]);
        let text = "time_s,stress_pa\n0,1e6\n1,-2e6\n";
        assert_eq!(values(text, Some("stress_pa")).unwrap(), vec![1e6, -2e6]);
        assert!(
            values(text, Some("x"))
                .unwrap_err()
                .contains("no column 'x'")
        );
        assert_eq!(
            values("1\nabc\n", None).unwrap_err(),
            "line 2, column 1: `abc` is not a number"
        );
        assert_eq!(
            values("t,s\n0,1\n1,inf\n", Some("s")).unwrap_err(),
            "line 3, column 2 (s): `inf` is not a finite number"
        );
        assert_eq!(
            values("t,s\n0,1\n1\n", Some("s")).unwrap_err(),
            "line 3, column 2 (s): no such field (the row has 1)"
        );
        assert!(values("", None).is_err());
    }
}
