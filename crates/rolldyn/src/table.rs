//! A result's table as named columns, for a skin to show (Python builds a pandas DataFrame
//! from the columns; nothing goes through a file).

use serde::Serialize;

/// One column: its name (with its unit, `pressure_pa`) and its values.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Column {
    pub name: String,
    pub values: ColumnValues,
}

/// The values of a column: numbers, whole numbers (counts, indices) or text (names).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum ColumnValues {
    Real(Vec<f64>),
    Integer(Vec<i64>),
    Text(Vec<String>),
}

impl ColumnValues {
    pub fn len(&self) -> usize {
        match self {
            Self::Real(v) => v.len(),
            Self::Integer(v) => v.len(),
            Self::Text(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A named table of equally long columns.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Table {
    pub name: String,
    pub columns: Vec<Column>,
}

impl Table {
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            columns: Vec::new(),
        }
    }

    /// Adds a column of numbers.
    pub fn real(mut self, name: impl Into<String>, values: Vec<f64>) -> Self {
        self.columns.push(Column {
            name: name.into(),
            values: ColumnValues::Real(values),
        });
        self
    }

    /// Adds a column of whole numbers.
    pub fn integer(mut self, name: impl Into<String>, values: Vec<i64>) -> Self {
        self.columns.push(Column {
            name: name.into(),
            values: ColumnValues::Integer(values),
        });
        self
    }

    /// Adds a column of text.
    pub fn text(mut self, name: impl Into<String>, values: Vec<String>) -> Self {
        self.columns.push(Column {
            name: name.into(),
            values: ColumnValues::Text(values),
        });
        self
    }

    /// Row-major numbers (`rows × names.len()`, e.g. a dynamics table recorded in memory) as
    /// a table of real columns.
    pub fn from_rows(name: impl Into<String>, names: &[String], values: &[f64]) -> Self {
        let width = names.len().max(1);
        let columns = names
            .iter()
            .enumerate()
            .map(|(j, n)| Column {
                name: n.clone(),
                values: ColumnValues::Real(values.iter().skip(j).step_by(width).copied().collect()),
            })
            .collect();
        Self {
            name: name.into(),
            columns,
        }
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, |c| c.values.len())
    }
}

/// A result that carries tables (for Python's DataFrames).
pub trait Tables {
    /// The result's tables; none by default.
    fn tables(&self) -> Vec<Table> {
        Vec::new()
    }
}
