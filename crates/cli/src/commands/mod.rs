//! One file per subcommand.

pub mod bench;
pub mod check;
pub mod contact;
pub mod demo;
pub mod ehl_line;
pub mod fatigue;
pub mod film;
mod jobs_args;
pub mod journal;
pub mod life;
pub mod loads;
pub mod new;
mod oil_args;
pub mod oils;
mod operating_args;
mod progress_lines;
pub mod report;
mod rig_args;
pub mod simulate;
pub mod skid;
pub mod startup;
pub mod study;
pub mod sweep;
pub mod traction;
pub mod wear;
