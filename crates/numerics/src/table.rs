//! Linear interpolation in a table of points.

/// Value at `x` of the piecewise-linear function through `table` (sorted by its first column),
/// the end values held beyond the ends; 0 for an empty table.
pub fn interpolate_held(table: &[(f64, f64)], x: f64) -> f64 {
    let k = table.partition_point(|p| p.0 <= x);
    match k {
        0 => table.first().map_or(0.0, |p| p.1),
        k if k >= table.len() => table.last().map_or(0.0, |p| p.1),
        k => {
            let (a, b) = (table[k - 1], table[k]);
            a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_holds_the_ends() {
        let t = [(0.0, 1.0), (1.0, 3.0), (2.0, 2.0)];
        assert_eq!(interpolate_held(&t, -1.0), 1.0);
        assert_eq!(interpolate_held(&t, 0.5), 2.0);
        assert_eq!(interpolate_held(&t, 1.0), 3.0);
        assert_eq!(interpolate_held(&t, 5.0), 2.0);
        assert_eq!(interpolate_held(&[], 5.0), 0.0);
    }
}
