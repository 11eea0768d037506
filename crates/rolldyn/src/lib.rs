//! rolldyn as a library: one typed entry per analysis — a request (the model and the options,
//! with their defaults; quantities in SI or as text with units) and a result (summary fields,
//! tables as columns, the files written) — and the orchestration around them: output folders,
//! checkpoints and resume, run manifests, cage-load export, reports, sweeps.
//!
//! The `rolldyn` program (crates/cli) parses its command line into a request, calls
//! [`Analysis::run`] and prints the result (`--json` prints it serialised); the Python package
//! (crates/python) builds the same request from keyword arguments through [`run_json`]. Both
//! therefore answer with the same numbers and the same schema.
//!
//! ```no_run
//! use rolldyn::{Analysis, Context, film};
//! let request: film::FilmRequest =
//!     serde_json::from_str(r#"{"load": "1000 N", "rolling_speed": 2.0}"#).unwrap();
//! let result = film::Film::run(&request, &Context::default()).unwrap();
//! println!("{result}");
//! ```

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod analysis;
pub mod bench;
pub mod check;
pub mod contact;
pub mod demo;
pub mod ehl_line;
pub mod failure;
pub mod fatigue;
pub mod film;
pub mod journal;
pub mod life;
pub mod loads;
pub mod model_source;
pub mod new_model;
pub mod observer;
pub mod oil;
pub mod oils;
pub mod operating;
pub mod output;
pub mod report;
pub mod run_record;
pub mod simulate;
pub mod skid;
pub mod startup;
pub mod study;
pub mod sweep;
pub mod table;
pub mod traction;
pub mod wear;

pub use analysis::{Analysis, Answer, Context};
pub use failure::Failure;
pub use model_source::ModelSource;
pub use observer::{Observer, Progress, Unobserved};
pub use run_record::Invocation;
pub use table::{Column, ColumnValues, Table, Tables};

/// The analyses [`run_json`] knows, by name.
pub const ANALYSES: &[&str] = &[
    film::Film::NAME,
    demo::Demo::NAME,
    check::Check::NAME,
    contact::Contact::NAME,
    oils::Oils::NAME,
    traction::Traction::NAME,
    report::Report::NAME,
    skid::Skid::NAME,
    loads::Loads::NAME,
    journal::Journal::NAME,
    ehl_line::EhlLine::NAME,
    simulate::Simulate::NAME,
    bench::Bench::NAME,
    startup::Startup::NAME,
    sweep::Sweep::NAME,
    wear::Wear::NAME,
    fatigue::Fatigue::NAME,
    fatigue::Rainflow::NAME,
    study::Study::NAME,
    life::Life::NAME,
    new_model::NewModel::NAME,
];

/// Runs the analysis `name` on a request given as JSON (a field the request does not have is
/// refused, naming it) and returns its answer.
pub fn run_json(name: &str, request: &str, context: &Context<'_>) -> Result<Answer, Failure> {
    match name {
        film::Film::NAME => analysis::answer::<film::Film>(request, context),
        demo::Demo::NAME => analysis::answer::<demo::Demo>(request, context),
        check::Check::NAME => analysis::answer::<check::Check>(request, context),
        contact::Contact::NAME => analysis::answer::<contact::Contact>(request, context),
        oils::Oils::NAME => analysis::answer::<oils::Oils>(request, context),
        traction::Traction::NAME => analysis::answer::<traction::Traction>(request, context),
        report::Report::NAME => analysis::answer::<report::Report>(request, context),
        skid::Skid::NAME => analysis::answer::<skid::Skid>(request, context),
        loads::Loads::NAME => analysis::answer::<loads::Loads>(request, context),
        journal::Journal::NAME => analysis::answer::<journal::Journal>(request, context),
        ehl_line::EhlLine::NAME => analysis::answer::<ehl_line::EhlLine>(request, context),
        simulate::Simulate::NAME => analysis::answer::<simulate::Simulate>(request, context),
        bench::Bench::NAME => analysis::answer::<bench::Bench>(request, context),
        startup::Startup::NAME => analysis::answer::<startup::Startup>(request, context),
        sweep::Sweep::NAME => analysis::answer::<sweep::Sweep>(request, context),
        wear::Wear::NAME => analysis::answer::<wear::Wear>(request, context),
        fatigue::Fatigue::NAME => analysis::answer::<fatigue::Fatigue>(request, context),
        fatigue::Rainflow::NAME => analysis::answer::<fatigue::Rainflow>(request, context),
        study::Study::NAME => analysis::answer::<study::Study>(request, context),
        life::Life::NAME => analysis::answer::<life::Life>(request, context),
        new_model::NewModel::NAME => analysis::answer::<new_model::NewModel>(request, context),
        _ => Err(Failure::Input(format!(
            "no analysis named '{name}' (known: {})",
            ANALYSES.join(", ")
        ))),
    }
}
