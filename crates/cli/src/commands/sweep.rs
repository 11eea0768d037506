//! `rolldyn sweep SWEEP.toml`: a table of model variants run in parallel, one summary row per
//! variant (CSV + Parquet) and one plot per summary column (docs/sweep-format.md; library:
//! `rolldyn::sweep`).

use super::jobs_args::JobsArgs;
use crate::failure::Failure;
use crate::output::{Bar, context, print_text};
use rolldyn::Analysis;
use rolldyn::sweep::{Sweep, SweepRequest};
use rolldyn_sweep::Shard;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Sweep file (TOML): base model, analysis and [[variant]] tables (docs/sweep-format.md).
    pub sweep: PathBuf,
    #[command(flatten)]
    pub jobs: JobsArgs,
    /// Output folder (default `out/<sweep file name>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Run every n-th variant only (`k/n`), e.g. one cluster array job of n.
    #[arg(long)]
    pub shard: Option<Shard>,
    /// Skip variants already finished in the output folder from the same inputs (model,
    /// overrides, duration, solver settings, program version); rerun the others.
    #[arg(long)]
    pub resume: bool,
    /// Run the variants but leave `summary.*` alone: for shards running at the same time (a
    /// Slurm array, Dask tasks), collected afterwards with `--collect-only`.
    #[arg(long, conflicts_with = "collect_only")]
    pub no_collect: bool,
    /// Run nothing: collect the variants stored in the output folder into `summary.*` (a stored
    /// result whose inputs changed is marked stale).
    #[arg(long)]
    pub collect_only: bool,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Write the HTML report of the output folder (`report.html`) at the end of the run.
    #[arg(long)]
    pub report: bool,
}

pub fn run(args: Args) -> Result<(), Failure> {
    let request = SweepRequest {
        sweep: args.sweep,
        jobs: args.jobs.jobs,
        out: args.out,
        shard: args.shard,
        resume: args.resume,
        no_collect: args.no_collect,
        collect_only: args.collect_only,
        report: args.report,
    };
    let bar = Bar::new(args.quiet, "sweep");
    let result = Sweep::run(&request, &context(None, &bar));
    bar.finish();
    print_text(&result?.to_string())
}
