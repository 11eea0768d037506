//! `rolldyn._native`: the Rust side of the Python package `rolldyn` (python/rolldyn). It runs the
//! commands of the `rolldyn` program in-process (`rolldyn_cli::api`), so a Python call and the
//! command line give the same numbers; the Python side turns the answers into dicts, numpy
//! arrays and pandas DataFrames.
//!
//! Every run releases the GIL. Bad input raises `InputError` (a `ValueError`) with the command's
//! one-line message (`file:line:column: key — reason`); a failed run raises `RunError`.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use rolldyn_cli::commands::simulate::Observer;
use rolldyn_cli::failure::Failure;
use rolldyn_dynamics::output_columns::{
    BEARING_COLUMNS, MemoryTables, REVOLUTION_COLUMNS, ROLLER_COLUMNS, column_names,
};
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

create_exception!(
    _native,
    InputError,
    PyValueError,
    "Bad input: a model key, a file or an argument."
);
create_exception!(
    _native,
    RunError,
    PyRuntimeError,
    "An analysis failed while running."
);

/// How often a long run hands control back to Python (progress callback, Ctrl-C).
const CALLBACK_INTERVAL: Duration = Duration::from_millis(100);

fn raise(failure: Failure) -> PyErr {
    match failure {
        Failure::Input(m) => InputError::new_err(m),
        Failure::Run(m) => RunError::new_err(m),
    }
}

/// A bearing model: its source (file name, or the embedded 2002834), its TOML text with any
/// overrides applied, and the parsed model.
#[pyclass(frozen, module = "rolldyn._native")]
struct Model {
    #[pyo3(get)]
    source: String,
    #[pyo3(get)]
    text: String,
    model: rolldyn_model::Model,
}

#[pymethods]
impl Model {
    /// A copy with model keys set: `overrides` is a JSON object of dotted keys
    /// (`{"roller.count": 22, "operating.inner_speed": "8163 rpm"}`).
    fn with_overrides(&self, overrides: &str) -> PyResult<Model> {
        let keys: serde_json::Map<String, serde_json::Value> = serde_json::from_str(overrides)
            .map_err(|e| InputError::new_err(format!("overrides: {e}")))?;
        let keys = keys
            .into_iter()
            .map(|(key, value)| Ok((key.clone(), toml_value(&key, value)?)))
            .collect::<PyResult<Vec<_>>>()?;
        let text = rolldyn_sweep::apply_overrides(&self.text, &keys)
            .map_err(|reason| InputError::new_err(format!("{}: {reason}", self.source)))?;
        let model = rolldyn_model::parse(&text, &self.source)
            .map_err(|e| InputError::new_err(e.to_string()))?;
        Ok(Model {
            source: self.source.clone(),
            text,
            model,
        })
    }

    /// The bearing's name (`model` in the answers).
    #[getter]
    fn name(&self) -> String {
        self.model.bearing.name().to_string()
    }
}

/// A JSON override value as TOML (numbers, strings, booleans, arrays, tables).
fn toml_value(key: &str, value: serde_json::Value) -> PyResult<toml::Value> {
    toml::Value::try_from(value).map_err(|e| InputError::new_err(format!("overrides: {key} — {e}")))
}

/// Loads a model file; the embedded 2002834 model when `path` is None.
#[pyfunction]
#[pyo3(signature = (path=None))]
fn load_model(path: Option<&str>) -> PyResult<Model> {
    let (source, text) = match path {
        Some(path) => (
            path.to_string(),
            rolldyn_model::read_input_file(std::path::Path::new(path))
                .map_err(|reason| InputError::new_err(format!("{path}: {reason}")))?,
        ),
        None => (
            "<embedded 2002834.toml>".to_string(),
            rolldyn_model::DEFAULT_MODEL.to_string(),
        ),
    };
    let model =
        rolldyn_model::parse(&text, &source).map_err(|e| InputError::new_err(e.to_string()))?;
    Ok(Model {
        source,
        text,
        model,
    })
}

/// Runs a command (`args` as on the command line, without `rolldyn`; give `--json` for an
/// answer) with `model` in place of its model file; returns the JSON answer's text, or None.
#[pyfunction]
#[pyo3(signature = (args, model=None))]
fn answer(py: Python<'_>, args: Vec<String>, model: Option<&Model>) -> PyResult<Option<String>> {
    let model = model.map(|m| m.model.clone());
    py.detach(|| rolldyn_cli::api::answer(&args, model))
        .map(|value| value.map(|v| v.to_string()))
        .map_err(raise)
}

/// Runs `simulate` (`args` start with "simulate"). Returns the JSON answer's text and, with
/// `tables`, the bearing, rollers and revolutions tables as little-endian f64 bytes (row-major,
/// the columns of [`table_columns`]). `progress(fraction, simulated_time_s)` is called every 0.1 s; Ctrl-C (or
/// an exception in `progress`) stops the run at its last accepted step and is raised.
#[pyfunction]
#[pyo3(signature = (args, model=None, tables=true, progress=None))]
fn simulate<'py>(
    py: Python<'py>,
    args: Vec<String>,
    model: Option<&Model>,
    tables: bool,
    progress: Option<Py<PyAny>>,
) -> PyResult<(String, Option<[Bound<'py, PyBytes>; 3]>)> {
    let model = model.map(|m| m.model.clone());
    let mut recorded = MemoryTables::default();
    let mut stopped: Option<PyErr> = None;
    let answer = py.detach(|| {
        let mut last = Instant::now();
        let mut observe = |t: f64, t_end: f64| {
            if last.elapsed() < CALLBACK_INTERVAL {
                return ControlFlow::Continue(());
            }
            last = Instant::now();
            let checked = Python::attach(|py| {
                if let Some(callback) = &progress {
                    callback.call1(py, ((t / t_end).min(1.0), t))?;
                }
                py.check_signals()
            });
            match checked {
                Ok(()) => ControlFlow::Continue(()),
                Err(e) => {
                    stopped = Some(e);
                    ControlFlow::Break(())
                }
            }
        };
        let observer = Observer {
            tables: tables.then_some(&mut recorded as _),
            progress: &mut observe,
        };
        rolldyn_cli::api::simulate(&args, model, observer)
    });
    if let Some(e) = stopped {
        return Err(e);
    }
    let answer = answer.map_err(raise)?.to_string();
    let bytes = |values: &[f64]| {
        let raw: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
        PyBytes::new(py, &raw)
    };
    let tables = tables.then(|| {
        [
            bytes(&recorded.bearing),
            bytes(&recorded.rollers),
            bytes(&recorded.revolutions),
        ]
    });
    Ok((answer, tables))
}

/// The column names of the bearing, rollers and revolutions tables.
#[pyfunction]
fn table_columns() -> [Vec<String>; 3] {
    [
        column_names(&BEARING_COLUMNS),
        column_names(&ROLLER_COLUMNS),
        column_names(&REVOLUTION_COLUMNS),
    ]
}

/// The variant names of a sweep file, in its order.
#[pyfunction]
fn sweep_variants(path: &str) -> PyResult<Vec<String>> {
    let sweep = rolldyn_sweep::SweepFile::load(std::path::Path::new(path))
        .map_err(|e| InputError::new_err(e.to_string()))?;
    Ok(sweep.variants.into_iter().map(|v| v.name).collect())
}

/// The version of the Rust library (the `rolldyn` program's version).
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Model>()?;
    m.add_function(wrap_pyfunction!(load_model, m)?)?;
    m.add_function(wrap_pyfunction!(answer, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(table_columns, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_variants, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add("RunError", m.py().get_type::<RunError>())?;
    Ok(())
}
