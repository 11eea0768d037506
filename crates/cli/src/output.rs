//! How the program asks the library and shows its answers: the context of a run (model file,
//! command line, progress bar, Ctrl-C-free stop), JSON on stdout, text on stdout.

use crate::failure::Failure;
use clap::CommandFactory;
use clap::parser::ValueSource;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rolldyn::{Analysis, Context, Invocation, ModelSource, Observer, Progress};
use serde::Serialize;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::Path;

/// Options that change where, how or how fast the answer is given, not what is computed; the
/// run manifest does not record them.
const PRESENTATION_FLAGS: [&str; 5] = ["out", "json", "quiet", "report", "jobs"];

/// Prints `value` as pretty JSON on stdout ([`print_text`]).
pub fn print_json<T: Serialize>(value: &T) -> Result<(), Failure> {
    let text = serde_json::to_string_pretty(value)?;
    print_text(&text)
}

/// Prints `text` and a newline on stdout. A reader that went away (`| head`) is not an error:
/// the output ends quietly. Any other write error (a full disk) is a failed run.
pub fn print_text(text: &str) -> Result<(), Failure> {
    let mut stdout = std::io::stdout().lock();
    match writeln!(stdout, "{text}").and_then(|()| stdout.flush()) {
        Err(e) if !is_closed_pipe(&e) => Err(Failure::Run(write_failure(&e))),
        _ => Ok(()),
    }
}

/// Prints `line` and a newline on stderr; a stderr that cannot be written (closed, full) loses
/// the line, and nothing else happens (there is nowhere left to say so).
pub fn print_error_line(line: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

/// Prints `value` and a newline on stdout as [`print_text`] does, formatted straight into a
/// buffered stdout (a long answer, such as a rainflow count's cycles, is not first copied into
/// one string).
pub fn print_display(value: &impl std::fmt::Display) -> Result<(), Failure> {
    let mut stdout = std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock());
    match writeln!(stdout, "{value}").and_then(|()| stdout.flush()) {
        Err(e) if !is_closed_pipe(&e) => Err(Failure::Run(write_failure(&e))),
        _ => Ok(()),
    }
}

/// Whether a write failed because its reader went away (`rolldyn … | head`).
pub fn is_closed_pipe(e: &std::io::Error) -> bool {
    e.kind() == std::io::ErrorKind::BrokenPipe
}

/// The message of a failed write on stdout.
pub fn write_failure(e: &std::io::Error) -> String {
    format!("cannot write output: {e}")
}

/// Runs analysis `A` and prints its result: as JSON with `json`, else as text.
pub fn run_and_print<A: Analysis>(
    request: &A::Request,
    model: Option<&Path>,
    json: bool,
) -> Result<(), Failure> {
    let observer = Bar::hidden();
    let result = A::run(request, &context(model, &observer))?;
    if json {
        print_json(&result)
    } else {
        print_display(&result)
    }
}

/// The context of a run on the model file `model` (the embedded model when `None`).
pub fn context<'a>(model: Option<&Path>, observer: &'a dyn Observer) -> Context<'a> {
    Context {
        model: ModelSource::file_or_embedded(model),
        invocation: invocation(),
        observer,
    }
}

/// The model file `model` (the embedded model when `None`), parsed.
pub fn load_model(model: Option<&Path>) -> Result<rolldyn_model::Model, Failure> {
    ModelSource::file_or_embedded(model).load()
}

/// This process' command line and the options given on it.
pub fn invocation() -> Invocation {
    let command: Vec<String> = std::env::args().collect();
    Invocation {
        given: given_flags(&command),
        command,
    }
}

/// The flags of `command_line` given on it, as typed (`"--speed": "4000rpm"`), without the
/// presentation flags.
fn given_flags(command_line: &[String]) -> BTreeMap<String, String> {
    let cli = crate::Cli::command();
    let Ok(matches) = cli.clone().try_get_matches_from(command_line) else {
        return BTreeMap::new();
    };
    let Some((name, given)) = matches.subcommand() else {
        return BTreeMap::new();
    };
    let Some(command) = cli.find_subcommand(name) else {
        return BTreeMap::new();
    };
    command
        .get_arguments()
        .filter_map(|arg| {
            let long = arg.get_long()?;
            let id = arg.get_id().as_str();
            if PRESENTATION_FLAGS.contains(&long)
                || given.value_source(id) != Some(ValueSource::CommandLine)
            {
                return None;
            }
            let values: Vec<String> = given
                .try_get_raw(id)
                .ok()
                .flatten()
                .map(|raw| raw.map(|v| v.to_string_lossy().into_owned()).collect())
                .unwrap_or_default();
            Some((format!("--{long}"), values.join(",")))
        })
        .collect()
}

/// A progress bar on stderr that watches a long run (hidden with `--quiet`).
pub struct Bar {
    bar: ProgressBar,
}

impl Bar {
    /// A bar for a run described by `what` ("simulating", "wear", "sweep").
    pub fn new(quiet: bool, what: &str) -> Self {
        let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::stderr());
        if quiet {
            bar.set_draw_target(ProgressDrawTarget::hidden());
        }
        bar.set_style(
            ProgressStyle::with_template(&format!(
                "{{spinner}} {what} {{msg}} [{{bar:40}}] {{percent}}% ({{elapsed}}, eta {{eta}})"
            ))
            .expect("valid template")
            .progress_chars("=> "),
        );
        Self { bar }
    }

    /// A bar that is never drawn.
    pub fn hidden() -> Self {
        Self::new(true, "")
    }

    /// Removes the bar from the terminal.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

impl Observer for Bar {
    fn progress(&self, progress: &Progress) {
        self.bar.set_position((progress.fraction() * 1000.0) as u64);
        let message = progress.message.clone().unwrap_or_else(|| {
            format!(
                "{:.4} of {:.4} {}",
                progress.done, progress.total, progress.unit
            )
        });
        self.bar.set_message(message);
    }

    fn warning(&self, message: &str) {
        self.bar
            .suspend(|| print_error_line(&format!("rolldyn: warning: {message}")));
    }
}
