//! `rolldyn._native`: the Rust side of the Python package `rolldyn` (python/rolldyn). It runs the
//! analyses of the `rolldyn` library (crates/rolldyn) in-process: a request built from keyword
//! arguments (JSON, quantities in SI or as text with units), the result's summary (JSON), its
//! text, and its tables as columns, from which the Python side builds pandas DataFrames.
//!
//! Every run releases the GIL and runs on its own thread while the calling thread hands the
//! progress to Python and watches for Ctrl-C every 0.1 s. Bad input raises `InputError` (a
//! `ValueError`) with the library's one-line message (`file:line:column: key — reason`); a
//! failed run raises `RunError`.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyList};
use rolldyn::{ColumnValues, Context, Failure, Invocation, ModelSource, Observer, Progress};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

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
    source: ModelSource,
}

impl Model {
    fn parts(&self) -> (&str, &str, &rolldyn_model::Model) {
        match &self.source {
            ModelSource::Given {
                source,
                text,
                model,
            } => (source, text, model),
            _ => unreachable!("a Python model is always read"),
        }
    }
}

#[pymethods]
impl Model {
    /// A copy with model keys set: `overrides` is a JSON object of dotted keys
    /// (`{"roller.count": 22, "operating.inner_speed": "8163 rpm"}`).
    fn with_overrides(&self, overrides: &str) -> PyResult<Model> {
        let (source, text, _) = self.parts();
        let keys: serde_json::Map<String, serde_json::Value> = serde_json::from_str(overrides)
            .map_err(|e| InputError::new_err(format!("overrides: {e}")))?;
        let keys = keys
            .into_iter()
            .map(|(key, value)| Ok((key.clone(), toml_value(&key, value)?)))
            .collect::<PyResult<Vec<_>>>()?;
        let (text, model) =
            rolldyn_sweep::model_with_overrides(text, source, &keys).map_err(|e| match e {
                // the override is the user's line: no line of the base file
                rolldyn_sweep::OverrideError::Override { key, reason } => {
                    InputError::new_err(format!("overrides: {key} — {reason}"))
                }
                rolldyn_sweep::OverrideError::Base(e) => InputError::new_err(e.to_string()),
            })?;
        Ok(Model {
            source: ModelSource::Given {
                source: source.to_string(),
                text,
                model: Box::new(model),
            },
        })
    }

    /// The model file, or `<embedded 2002834.toml>`.
    #[getter]
    fn source(&self) -> String {
        self.parts().0.to_string()
    }

    /// The model's TOML text, overrides applied.
    #[getter]
    fn text(&self) -> String {
        self.parts().1.to_string()
    }

    /// The bearing's name (`model` in the answers).
    #[getter]
    fn name(&self) -> String {
        self.parts().2.bearing.name().to_string()
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
    let source = ModelSource::read(path.map(std::path::Path::new)).map_err(raise)?;
    Ok(Model { source })
}

/// What the run's thread tells the calling thread: the latest progress, the warnings, and
/// whether Python asked it to stop.
#[derive(Default)]
struct Watch {
    progress: Mutex<Option<Progress>>,
    warnings: Mutex<Vec<String>>,
    stop: AtomicBool,
}

impl Observer for Watch {
    fn progress(&self, progress: &Progress) {
        *self.progress.lock().expect("not poisoned") = Some(progress.clone());
    }

    fn warning(&self, message: &str) {
        self.warnings
            .lock()
            .expect("not poisoned")
            .push(message.to_string());
    }

    fn stop_requested(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }
}

/// Runs analysis `analysis` on `request` (a JSON object) with `model` (the embedded model when
/// None). `progress(done, total, unit, message)` is called every 0.1 s from this thread;
/// Ctrl-C (or an exception in `progress`) asks the run to stop, and is raised once it has
/// stopped. `invocation` is recorded in an output folder's `run.json`.
///
/// Returns `(summary JSON, text, tables, warnings)`: tables as a list of `(name, columns)`,
/// each column `(name, kind, values)` with kind "f8"/"i8" and little-endian bytes, or "str"
/// and a list of strings.
#[pyfunction]
#[pyo3(signature = (analysis, request, model=None, progress=None, invocation=Vec::new()))]
fn run<'py>(
    py: Python<'py>,
    analysis: &str,
    request: &str,
    model: Option<&Model>,
    progress: Option<Py<PyAny>>,
    invocation: Vec<String>,
) -> PyResult<(String, String, Bound<'py, PyList>, Vec<String>)> {
    let watch = Watch::default();
    let context = Context {
        model: model.map_or(ModelSource::Embedded, |m| m.source.clone()),
        invocation: Invocation {
            given: invocation
                .iter()
                .skip(1)
                .filter_map(|a| a.split_once('='))
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            command: invocation,
        },
        observer: &watch,
    };
    let mut interrupted: Option<PyErr> = None;
    let answer = py.detach(|| {
        std::thread::scope(|scope| {
            let worker = scope.spawn(|| rolldyn::run_json(analysis, request, &context));
            while !worker.is_finished() {
                std::thread::sleep(CALLBACK_INTERVAL);
                if interrupted.is_some() {
                    continue;
                }
                let latest = watch.progress.lock().expect("not poisoned").take();
                let checked = Python::attach(|py| {
                    if let (Some(callback), Some(p)) = (&progress, latest) {
                        callback.call1(py, (p.done, p.total, p.unit, p.message))?;
                    }
                    py.check_signals()
                });
                if let Err(e) = checked {
                    interrupted = Some(e);
                    watch.stop.store(true, Ordering::Relaxed);
                }
            }
            worker.join().expect("the run's thread does not panic")
        })
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let answer = answer.map_err(raise)?;
    let tables = PyList::empty(py);
    for table in &answer.tables {
        let columns = PyList::empty(py);
        for column in &table.columns {
            let values: (&str, Bound<'py, PyAny>) = match &column.values {
                ColumnValues::Real(v) => ("f8", bytes(py, v.iter().map(|x| x.to_le_bytes()))),
                ColumnValues::Integer(v) => ("i8", bytes(py, v.iter().map(|x| x.to_le_bytes()))),
                ColumnValues::Text(v) => ("str", PyList::new(py, v)?.into_any()),
            };
            columns.append((column.name.as_str(), values.0, values.1))?;
        }
        tables.append((table.name.as_str(), columns))?;
    }
    let warnings = watch.warnings.into_inner().expect("not poisoned");
    Ok((answer.summary, answer.text, tables, warnings))
}

/// Little-endian numbers as Python bytes.
fn bytes<'py>(py: Python<'py>, values: impl Iterator<Item = [u8; 8]>) -> Bound<'py, PyAny> {
    let raw: Vec<u8> = values.flatten().collect();
    PyBytes::new(py, &raw).into_any()
}

/// The names of the analyses `run` knows.
#[pyfunction]
fn analyses() -> Vec<&'static str> {
    rolldyn::ANALYSES.to_vec()
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
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(analyses, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_variants, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add("RunError", m.py().get_type::<RunError>())?;
    Ok(())
}
