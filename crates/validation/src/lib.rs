//! The seeds' validation studies, run on rolldyn's example models.
//!
//! Each module reproduces one seed's study and returns plain data; `rolldyn study` prints and
//! plots it, and the tests in `tests/` compare it with the seed's numbers (VALIDATION.md).

pub mod end_rib_limit;
pub mod model_consistency;
pub mod obrien_taylor;
pub mod rib_shape;
pub mod seed004;
pub mod table_3_2;
