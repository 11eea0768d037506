//! `--jobs N`: the parallel jobs of the commands that run independent analyses (`sweep`,
//! `startup`).

#[derive(clap::Args)]
pub struct JobsArgs {
    /// Parallel jobs, at least 1 (default: the number of cores).
    #[arg(long, value_parser = parse_jobs)]
    pub jobs: Option<usize>,
}

fn parse_jobs(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("'{text}': expected a whole number of at least 1")),
    }
}

impl JobsArgs {
    /// The jobs asked for, or the number of cores.
    pub fn count(&self) -> usize {
        self.jobs
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
    }
}
