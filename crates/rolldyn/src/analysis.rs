//! The shape every analysis has: a request in, a result out, run in a [`Context`]; and
//! [`run_json`], which runs any analysis by name from a JSON request (the Python package's
//! door: a keyword argument that is no field of the request is refused by name).

use crate::failure::Failure;
use crate::model_source::ModelSource;
use crate::observer::{Observer, Unobserved};
use crate::run_record::Invocation;
use crate::table::{Table, Tables};
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt;

/// What an analysis runs with besides its request: the bearing model (for the analyses that
/// take one), how it was asked for (recorded in `run.json`), and who watches it.
pub struct Context<'a> {
    pub model: ModelSource,
    pub invocation: Invocation,
    pub observer: &'a dyn Observer,
}

impl Default for Context<'_> {
    /// The embedded model, no invocation recorded, nobody watching.
    fn default() -> Self {
        Self {
            model: ModelSource::Embedded,
            invocation: Invocation::default(),
            observer: &Unobserved,
        }
    }
}

impl<'a> Context<'a> {
    /// A context for `model`, watched by `observer`.
    pub fn new(model: ModelSource, observer: &'a dyn Observer) -> Self {
        Self {
            model,
            invocation: Invocation::default(),
            observer,
        }
    }
}

/// One analysis: its request (options with their defaults, quantities in SI or as text with
/// units), its result (serialised as the `--json` answer, shown as text by `Display`, with its
/// tables as columns) and how to run it.
pub trait Analysis {
    /// The analysis' name: the command's (`"film"`, `"ehl-line"`).
    const NAME: &'static str;
    type Request: DeserializeOwned;
    type Result: Serialize + fmt::Display + Tables;
    fn run(request: &Self::Request, context: &Context<'_>) -> Result<Self::Result, Failure>;
}

/// A result as a skin that knows no Rust types sees it.
#[derive(Clone, Debug)]
pub struct Answer {
    /// The result serialised as JSON text (what `--json` prints, in the result's field order).
    pub summary: String,
    /// The result as the command line prints it.
    pub text: String,
    /// The result's tables.
    pub tables: Vec<Table>,
}

/// Runs analysis `A` on a request given as JSON.
pub fn answer<A: Analysis>(request: &str, context: &Context<'_>) -> Result<Answer, Failure> {
    let request: A::Request = parse_request(A::NAME, request)?;
    let result = A::run(&request, context)?;
    Ok(Answer {
        summary: serde_json::to_string(&result)?,
        text: result.to_string(),
        tables: result.tables(),
    })
}

/// A JSON request, or the reason it is none, naming the field (`simulate: operating.speed —
/// 'fast' does not start with a number`).
fn parse_request<T: DeserializeOwned>(analysis: &str, text: &str) -> Result<T, Failure> {
    let mut json = serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(&mut json).map_err(|e| {
        let path = e.path().to_string();
        let reason = e.inner().to_string();
        // serde_json appends the position in the request's text, which the caller never wrote
        let reason = reason.split(" at line ").next().unwrap_or(&reason);
        if path == "." || path.is_empty() {
            Failure::Input(format!("{analysis}: {reason}"))
        } else {
            Failure::Input(format!("{analysis}: {path} — {reason}"))
        }
    })
}
