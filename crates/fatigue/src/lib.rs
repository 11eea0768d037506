//! Cage high-cycle fatigue (seed 000 §2.5, §3.1.1.8): the cage and its load stations
//! ([`cage`]), the unit stress cases of a stress model ([`unit_stresses`]), the cycle counting
//! of stress histories ([`rainflow`]) and reading a history ([`history`]).

pub mod cage;
pub mod cage_material;
pub mod calculix;
pub mod damage;
pub mod frame;
pub mod history;
pub mod inclusion;
pub mod loads;
pub mod mean_stress;
pub mod plots;
pub mod rainflow;
pub mod recorder;
pub mod report;
pub mod sn;
pub mod study;
pub mod superpose;
pub mod unit_stresses;
#[cfg(test)]
mod whole_file_oracle;

pub use cage::{CageGeometry, Face, FilletPoint, PocketSide, STATIONS, Station};
pub use history::{CountedHistory, rainflow_csv, read_history_values};
pub use loads::{CageLoadExport, ContactKind, ContactLoad, ExportHeader, LoadSet};
pub use rainflow::{
    Cycle, FourPointStack, HistoryKind, TurningPointFilter, rainflow, rainflow_streamed,
    turning_points,
};
pub use recorder::{CageLoadRecorder, SETS_PER_REVOLUTION, export_output_step};
pub use unit_stresses::{Stress, UnitStresses, principal_extremes, signed_von_mises};
