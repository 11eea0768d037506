//! One file per subcommand.

pub mod check;
pub mod contact;
pub mod demo;
pub mod study;
