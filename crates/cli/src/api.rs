//! The commands called from another program (the Python package) instead of a shell: the
//! arguments are the command line's, the answer is the JSON object `--json` prints, and the
//! model may be given in memory (a model with overrides that has no file of its own).
//!
//! A command runs on the calling thread; its answer and its given model are kept per thread
//! for the duration of one [`answer`] call.

use crate::failure::Failure;
use crate::{Cli, execute};
use clap::Parser;
use std::cell::RefCell;

thread_local! {
    static CALL: RefCell<Option<Call>> = const { RefCell::new(None) };
}

/// The state of one [`answer`] call on this thread.
struct Call {
    model: Option<rolldyn_model::Model>,
    answer: Option<serde_json::Value>,
    /// The command line, program name first.
    command_line: Vec<String>,
}

/// Runs the command of `args` (without the program name, e.g. `["film", "--oil", …]`), with
/// `model` in place of the model file when given, and returns the JSON answer it would print
/// with `--json` (`None` for a command that prints none, e.g. `sweep`). A bad argument is
/// [`Failure::Input`] with clap's message.
pub fn answer(
    args: &[String],
    model: Option<rolldyn_model::Model>,
) -> Result<Option<serde_json::Value>, Failure> {
    let command = parse(args)?;
    in_call(args, model, || execute(command))
}

/// `args` (without the program name) as a command line.
fn with_program_name(args: &[String]) -> Vec<String> {
    std::iter::once("rolldyn".to_string())
        .chain(args.iter().cloned())
        .collect()
}

/// The command of `args` (without the program name).
fn parse(args: &[String]) -> Result<crate::Command, Failure> {
    Cli::try_parse_from(with_program_name(args))
        .map(|cli| cli.command)
        .map_err(|e| Failure::Input(first_line(&e.to_string())))
}

/// Runs `command` (parsed from `args`) as one call on this thread, with `model` given, and
/// returns its answer.
fn in_call(
    args: &[String],
    model: Option<rolldyn_model::Model>,
    command: impl FnOnce() -> Result<(), Failure>,
) -> Result<Option<serde_json::Value>, Failure> {
    CALL.with(|c| {
        *c.borrow_mut() = Some(Call {
            model,
            answer: None,
            command_line: with_program_name(args),
        })
    });
    let result = command();
    let call = CALL.with(|c| c.borrow_mut().take());
    result.map(|()| call.and_then(|c| c.answer))
}

/// clap's error without its usage lines.
fn first_line(message: &str) -> String {
    message
        .lines()
        .next()
        .unwrap_or_default()
        .trim_start_matches("error: ")
        .to_string()
}

/// Whether a command runs under [`answer`] on this thread.
pub(crate) fn capturing() -> bool {
    CALL.with(|c| c.borrow().is_some())
}

/// Keeps the command's JSON answer for [`answer`].
pub(crate) fn capture(value: serde_json::Value) {
    CALL.with(|c| {
        if let Some(call) = c.borrow_mut().as_mut() {
            call.answer = Some(value);
        }
    });
}

/// The model given to [`answer`], if any.
pub(crate) fn given_model() -> Option<rolldyn_model::Model> {
    CALL.with(|c| c.borrow().as_ref().and_then(|call| call.model.clone()))
}

/// The command line of the running command: the one given to [`answer`], else the process's.
pub(crate) fn command_line() -> Vec<String> {
    CALL.with(|c| c.borrow().as_ref().map(|call| call.command_line.clone()))
        .unwrap_or_else(|| std::env::args().collect())
}

/// [`answer`] for `simulate` (`args` start with `"simulate"`), with its tables and progress
/// handed to `observer` (a tapered bearing's run hands over no tables).
pub fn simulate(
    args: &[String],
    model: Option<rolldyn_model::Model>,
    observer: crate::commands::simulate::Observer<'_>,
) -> Result<serde_json::Value, Failure> {
    let crate::Command::Simulate(simulate) = parse(args)? else {
        return Err(Failure::Input("expected the arguments of simulate".into()));
    };
    in_call(args, model, || {
        crate::commands::simulate::run_observed(simulate, observer)
    })?
    .ok_or_else(|| Failure::Run("simulate gave no answer (give --json)".into()))
}
