//! Cage high-cycle fatigue (seed 000 §2.5, §3.1.1.8): the cycle counting of stress histories
//! ([`rainflow`]) and reading a history ([`history`]).

pub mod history;
pub mod rainflow;

pub use history::read_history_csv;
pub use rainflow::{Cycle, HistoryKind, rainflow, turning_points};
