//! One file per subcommand.

pub mod check;
pub mod contact;
pub mod demo;
pub mod film;
mod oil_args;
pub mod oils;
mod rig_args;
pub mod simulate;
pub mod skid;
pub mod study;
pub mod traction;
