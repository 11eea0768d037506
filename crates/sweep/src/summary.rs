//! The summary of a sweep: one row per variant with a stored result — its name, the value of
//! every varied model key, its index and its figures — written as `summary.csv`,
//! `summary.parquet` and one SVG per figure.

use crate::file::{SweepError, SweepFile, Variant};
use crate::run::{Figure, RunOptions, fingerprint, stored};
use rolldyn_output::{Column, Values, csv_field, write_parquet_table};
use rolldyn_plot::{Varied, variant_plot};
use rolldyn_units::{Dimension, Quantity, UnitError};
use std::collections::BTreeMap;
use std::path::Path;
use toml::Value;

/// The values of a summary column.
#[derive(Debug, Clone, PartialEq)]
pub enum SummaryValues {
    /// Names, notes, varied keys whose values are text; `None` is blank.
    Text(Vec<Option<String>>),
    /// Counts, indices, flags (0/1), whole-number model keys; `None` is blank.
    Integer(Vec<Option<i64>>),
    /// Real numbers (SI); NaN is blank.
    Real(Vec<f64>),
}

/// A named column of the summary.
#[derive(Debug, Clone, PartialEq)]
pub struct SummaryColumn {
    pub name: String,
    pub values: SummaryValues,
}

/// The summary table: `variant`, one column per varied model key, `index`, the figures in
/// name order, `error`.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub columns: Vec<SummaryColumn>,
    /// The names of the varied-key columns (`operating.radial_load_n`, `roller.count`), in the
    /// order of the sweep file.
    pub varied: Vec<String>,
    /// The number of rows.
    pub rows: usize,
}

/// A row of the summary: a stored outcome, or why its values are blank.
struct SummaryRow<'a> {
    variant: &'a Variant,
    index: usize,
    figures: Option<BTreeMap<String, Figure>>,
    error: Option<String>,
}

/// The summary rows of the variants that have a result file in `options.out_dir`, in the order
/// of the sweep file. A result computed from other inputs than the variant's current ones
/// ([`fingerprint`]) or an unreadable file gives a row without values that says so.
fn summary_rows<'a>(sweep: &'a SweepFile, options: &RunOptions) -> Vec<SummaryRow<'a>> {
    let blank = |variant, index, error: String| SummaryRow {
        variant,
        index,
        figures: None,
        error: Some(error),
    };
    sweep
        .variants
        .iter()
        .enumerate()
        .filter_map(|(index, variant)| {
            match stored(&options.out_dir, &variant.name) {
            Ok(None) => None,
            Err(e) => Some(blank(variant, index, e)),
            Ok(Some(o)) if o.fingerprint != fingerprint(sweep, variant, &options.settings) => {
                Some(blank(
                    variant,
                    index,
                    "stale: the inputs changed since this result; run the sweep again with --resume"
                        .into(),
                ))
            }
            Ok(Some(o)) => Some(SummaryRow {
                variant,
                index,
                figures: o.summary,
                error: o.error,
            }),
        }
        })
        .collect()
}

/// A model value as a summary cell: a whole number, a number in SI with its dimension (when
/// written with a unit), or text.
#[derive(Debug, Clone, PartialEq)]
enum Cell {
    Integer(i64),
    Real(f64, Option<Dimension>),
    Text(String),
}

/// Parses `text` as a quantity of the dimension of its unit: `(SI value, dimension)`, the
/// dimension `None` for a plain number.
fn quantity(text: &str) -> Option<(f64, Option<Dimension>)> {
    let got = match Quantity::<rolldyn_units::Dimensionless>::parse(text) {
        Ok(q) => return Some((q.si(), None)),
        Err(UnitError::WrongDimension { got, .. }) => got,
        Err(_) => return None,
    };
    macro_rules! parse_as {
        ($($d:ident),*) => {
            match got {
                $(Dimension::$d => Quantity::<rolldyn_units::$d>::parse(text).ok().map(|q| q.si()),)*
                _ => None,
            }
        };
    }
    let si = parse_as!(
        Length,
        Area,
        Mass,
        Time,
        Force,
        Moment,
        Pressure,
        Angle,
        AngularSpeed,
        Speed,
        Acceleration,
        Temperature,
        DynamicViscosity,
        KinematicViscosity,
        Density,
        Stiffness,
        LoadPerLength,
        Damping,
        Power,
        Energy,
        Frequency,
        ThermalConductivity,
        SpecificHeat,
        RotationalDamping,
        PerTemperature,
        PerPressure,
        PerArea,
        Inertia,
        Unbalance
    )?;
    Some((round_to_input(si), Some(got)))
}

/// `x` to 12 significant digits: the SI value of an input such as `5 um` without the noise of
/// its unit conversion (`4.9999999999999996e-6`).
fn round_to_input(x: f64) -> f64 {
    format!("{x:.11e}").parse().unwrap_or(x)
}

fn cell(value: &Value) -> Cell {
    match value {
        Value::Integer(n) => Cell::Integer(*n),
        Value::Float(x) => Cell::Real(*x, None),
        Value::String(s) => match quantity(s) {
            Some((si, dimension)) => Cell::Real(si, dimension),
            None => Cell::Text(s.clone()),
        },
        other => Cell::Text(other.to_string()),
    }
}

/// A column name's unit suffix from an SI symbol: `rad/s` → `rad_s`, `Pa s` → `pa_s`,
/// `kg m²` → `kg_m2`.
fn unit_slug(symbol: &str) -> String {
    let mut slug = String::new();
    for c in symbol.chars() {
        match c {
            '²' => slug.push('2'),
            '³' => slug.push('3'),
            c if c.is_ascii_alphanumeric() => slug.push(c.to_ascii_lowercase()),
            _ if !slug.ends_with('_') => slug.push('_'),
            _ => {}
        }
    }
    slug.trim_matches('_').to_string()
}

/// The column of model key `key` over the rows: whole numbers as integers, numbers (with units
/// of one dimension) in SI named `<key>_<SI unit>`, anything else as written.
fn varied_column(key: &str, cells: &[Option<Cell>]) -> SummaryColumn {
    let present = || cells.iter().flatten();
    if present().all(|c| matches!(c, Cell::Integer(_))) {
        return SummaryColumn {
            name: key.to_string(),
            values: SummaryValues::Integer(
                cells
                    .iter()
                    .map(|c| match c {
                        Some(Cell::Integer(n)) => Some(*n),
                        _ => None,
                    })
                    .collect(),
            ),
        };
    }
    let mut dimensions: Vec<Dimension> = present()
        .filter_map(|c| match c {
            Cell::Real(_, d) => *d,
            _ => None,
        })
        .collect();
    dimensions.dedup();
    let numeric = present().all(|c| !matches!(c, Cell::Text(_)));
    if numeric && dimensions.len() <= 1 {
        let unit = dimensions
            .first()
            .map(|d| unit_slug(d.si_symbol()))
            .filter(|s| !s.is_empty());
        return SummaryColumn {
            name: unit.map_or(key.to_string(), |u| format!("{key}_{u}")),
            values: SummaryValues::Real(
                cells
                    .iter()
                    .map(|c| match c {
                        Some(Cell::Integer(n)) => *n as f64,
                        Some(Cell::Real(x, _)) => *x,
                        _ => f64::NAN,
                    })
                    .collect(),
            ),
        };
    }
    SummaryColumn {
        name: key.to_string(),
        values: SummaryValues::Text(
            cells
                .iter()
                .map(|c| {
                    c.as_ref().map(|c| match c {
                        Cell::Integer(n) => n.to_string(),
                        Cell::Real(x, _) => x.to_string(),
                        Cell::Text(t) => t.clone(),
                    })
                })
                .collect(),
        ),
    }
}

/// The column of figure `name`: integers when every value is one, else real numbers.
fn figure_column(name: &str, rows: &[SummaryRow]) -> SummaryColumn {
    let values: Vec<Option<Figure>> = rows
        .iter()
        .map(|r| r.figures.as_ref().and_then(|f| f.get(name)).copied())
        .collect();
    let values = if values
        .iter()
        .flatten()
        .all(|f| matches!(f, Figure::Integer(_)))
    {
        SummaryValues::Integer(
            values
                .iter()
                .map(|v| match v {
                    Some(Figure::Integer(n)) => Some(*n),
                    _ => None,
                })
                .collect(),
        )
    } else {
        SummaryValues::Real(
            values
                .iter()
                .map(|v| v.map_or(f64::NAN, Figure::as_f64))
                .collect(),
        )
    };
    SummaryColumn {
        name: name.to_string(),
        values,
    }
}

/// One column per model key any variant of `sweep` overrides, one value per variant of the
/// sweep file (the base model's where a variant does not override the key): whole numbers as
/// integers, numbers in SI named `<key>_<SI unit>` when given with units, else text.
pub fn varied_columns(sweep: &SweepFile) -> Vec<SummaryColumn> {
    sweep
        .varied_keys()
        .iter()
        .map(|key| {
            let cells: Vec<Option<Cell>> = sweep
                .variants
                .iter()
                .map(|v| sweep.value_of(v, key).as_ref().map(cell))
                .collect();
            varied_column(key, &cells)
        })
        .collect()
}

impl Summary {
    /// The summary of the variants stored in `options.out_dir`.
    pub fn of(sweep: &SweepFile, options: &RunOptions) -> Self {
        let rows = summary_rows(sweep, options);
        let mut columns = vec![SummaryColumn {
            name: "variant".into(),
            values: SummaryValues::Text(
                rows.iter().map(|r| Some(r.variant.name.clone())).collect(),
            ),
        }];
        let mut varied = Vec::new();
        for column in varied_columns(sweep) {
            varied.push(column.name.clone());
            let indices = rows.iter().map(|r| r.index);
            let values = match column.values {
                SummaryValues::Text(v) => {
                    SummaryValues::Text(indices.map(|i| v[i].clone()).collect())
                }
                SummaryValues::Integer(v) => {
                    SummaryValues::Integer(indices.map(|i| v[i]).collect())
                }
                SummaryValues::Real(v) => SummaryValues::Real(indices.map(|i| v[i]).collect()),
            };
            columns.push(SummaryColumn {
                name: column.name,
                values,
            });
        }
        columns.push(SummaryColumn {
            name: "index".into(),
            values: SummaryValues::Integer(rows.iter().map(|r| Some(r.index as i64)).collect()),
        });
        let mut names: Vec<&String> = rows
            .iter()
            .filter_map(|r| r.figures.as_ref())
            .flat_map(|f| f.keys())
            .collect();
        names.sort();
        names.dedup();
        columns.extend(names.iter().map(|n| figure_column(n, &rows)));
        columns.push(SummaryColumn {
            name: "error".into(),
            values: SummaryValues::Text(rows.iter().map(|r| r.error.clone()).collect()),
        });
        Self {
            columns,
            varied,
            rows: rows.len(),
        }
    }

    /// The column named `name`.
    pub fn column(&self, name: &str) -> Option<&SummaryColumn> {
        self.columns.iter().find(|c| c.name == name)
    }

    /// `summary.csv`: integers as integers, numbers as `csv_field` (blank when missing).
    pub fn write_csv(&self, path: &Path) -> Result<(), String> {
        let mut csv = csv::Writer::from_path(path).map_err(|e| e.to_string())?;
        let header: Vec<&str> = self.columns.iter().map(|c| c.name.as_str()).collect();
        csv.write_record(&header).map_err(|e| e.to_string())?;
        for row in 0..self.rows {
            let record: Vec<String> = self
                .columns
                .iter()
                .map(|c| match &c.values {
                    SummaryValues::Text(v) => v[row].clone().unwrap_or_default(),
                    SummaryValues::Integer(v) => v[row].map(|n| n.to_string()).unwrap_or_default(),
                    SummaryValues::Real(v) => csv_field(v[row]),
                })
                .collect();
            csv.write_record(&record).map_err(|e| e.to_string())?;
        }
        csv.flush().map_err(|e| e.to_string())
    }

    /// `summary.parquet`, with the columns of the CSV (whole numbers as INT64).
    pub fn write_parquet(&self, path: &Path) -> Result<(), String> {
        let table: Vec<Column> = self
            .columns
            .iter()
            .map(|c| Column {
                name: &c.name,
                values: match &c.values {
                    SummaryValues::Text(v) => Values::Text(v),
                    SummaryValues::Integer(v) => Values::Integers(v),
                    SummaryValues::Real(v) => Values::Numbers(v),
                },
            })
            .collect();
        write_parquet_table(path, &table).map_err(|e| e.to_string())
    }

    /// A column's values as numbers (NaN where missing); none for a text column.
    fn numbers(column: &SummaryColumn) -> Option<Vec<f64>> {
        match &column.values {
            SummaryValues::Real(v) => Some(v.clone()),
            SummaryValues::Integer(v) => {
                Some(v.iter().map(|n| n.map_or(f64::NAN, |n| n as f64)).collect())
            }
            SummaryValues::Text(_) => None,
        }
    }

    /// `<column>.svg` in `dir` for every figure: its value per variant, against the first
    /// numeric varied key when there is one, else at the variant names.
    pub fn plot(&self, dir: &Path) -> Result<(), String> {
        let names: Vec<String> = match self.column("variant").map(|c| &c.values) {
            Some(SummaryValues::Text(v)) => {
                v.iter().map(|n| n.clone().unwrap_or_default()).collect()
            }
            _ => Vec::new(),
        };
        let varied_values: Vec<(&str, Vec<f64>)> = self
            .varied
            .iter()
            .filter_map(|name| Some((name.as_str(), Self::numbers(self.column(name)?)?)))
            .collect();
        let varied: Vec<Varied> = varied_values
            .iter()
            .map(|(column, values)| Varied { column, values })
            .collect();
        let figures = self
            .columns
            .iter()
            .filter(|c| c.name != "index" && !self.varied.contains(&c.name));
        for column in figures {
            let Some(y) = Self::numbers(column) else {
                continue;
            };
            if y.iter().all(|v| !v.is_finite()) {
                continue;
            }
            variant_plot(
                &dir.join(format!("{}.svg", column.name)),
                &format!("{} per variant", column.name),
                &column.name,
                &names,
                &varied,
                &y,
            )
            .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}

/// Collects every variant with a result in `options.out_dir` into `summary.csv` and
/// `summary.parquet` (variant, the varied model keys, index, the summary figures, error) and
/// one SVG per figure (value per variant, like seed 000 Figs 3.13–3.30). Returns the summary.
pub fn collect(sweep: &SweepFile, options: &RunOptions) -> Result<Summary, SweepError> {
    let dir = &options.out_dir;
    let summary = Summary::of(sweep, options);
    summary
        .write_csv(&dir.join("summary.csv"))
        .and_then(|_| summary.write_parquet(&dir.join("summary.parquet")))
        .and_then(|_| summary.plot(dir))
        .map_err(|e| SweepError::new(&sweep.path, "", e))?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_name_the_column_and_convert_to_si() {
        let cells: Vec<Option<Cell>> = ["8163 rpm", "4000 rpm"]
            .iter()
            .map(|s| Some(cell(&Value::String(s.to_string()))))
            .collect();
        let c = varied_column("operating.inner_speed", &cells);
        assert_eq!(c.name, "operating.inner_speed_rad_s");
        let SummaryValues::Real(v) = c.values else {
            panic!("real column expected")
        };
        assert!((v[0] - 8163.0 * std::f64::consts::PI / 30.0).abs() < 1e-9);
        let counts = [Some(Cell::Integer(14)), None, Some(Cell::Integer(16))];
        let c = varied_column("roller.count", &counts);
        assert_eq!(c.name, "roller.count");
        assert_eq!(
            c.values,
            SummaryValues::Integer(vec![Some(14), None, Some(16)])
        );
        let text = [Some(cell(&Value::String("pao1-vg320".into())))];
        assert!(matches!(
            varied_column("lubricant.oil", &text).values,
            SummaryValues::Text(_)
        ));
        assert_eq!(unit_slug("kg m²"), "kg_m2");
        assert_eq!(unit_slug("W/(m K)"), "w_m_k");
        let temperature = [Some(cell(&Value::String("100 C".into())))];
        assert_eq!(
            varied_column("operating.temperatures.oil", &temperature).name,
            "operating.temperatures.oil_k"
        );
    }
}
