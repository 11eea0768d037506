//! A stress history from a CSV text: one value per row, in the first column or in a named one;
//! a header row is recognised by a first field that is not a number.

/// The values of `column` (the first column when `None`) of `text`; the error names the 1-based
/// line and the reason.
pub fn read_history_csv(text: &str, column: Option<&str>) -> Result<Vec<f64>, String> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headers_columns_and_errors() {
        assert_eq!(
            read_history_csv("1\n-2\n3\n", None).unwrap(),
            vec![1.0, -2.0, 3.0]
        );
        let text = "time_s,stress_pa\n0,1e6\n1,-2e6\n";
        assert_eq!(
            read_history_csv(text, Some("stress_pa")).unwrap(),
            vec![1e6, -2e6]
        );
        assert!(
            read_history_csv(text, Some("x"))
                .unwrap_err()
                .contains("no column 'x'")
        );
        assert!(
            read_history_csv("1\nabc\n", None)
                .unwrap_err()
                .starts_with("line 2:")
        );
        assert!(read_history_csv("", None).is_err());
    }
}
