//! # rolldyn-quasistatic — quasi-static skidding model of cylindrical roller bearings
//!
//! Implements SPEC §5 (seed 001, Makarchuk & Zhilnikov 2012) for ordinary bearings (inner ring
//! rotating, outer at rest) and intershaft bearings (both rings rotating, outer ring driving):
//! operating geometry, frictionless load distribution with the slice contact model, roller
//! equilibria and cage equilibrium solved by safeguarded Newton iterations, with the raceway
//! friction of `rolldyn_lubrication` (seed 001 asperity/flash model or seed 000 Muraki/mixed).
//! Milliseconds per operating point: a design tool for maps over speed and load, and the
//! initial state / cross-check of the dynamics.
//!
//! | module | content | SPEC |
//! |---|---|---|
//! | [`mod@operating_geometry`] | operating clearance (fits, thermal, centrifugal), floating and rib clearances | §5.2 |
//! | [`load_distribution`] | roller loads with clearance/preload, centrifugal force, misalignment (slices) | §5.4, §2.1 |
//! | [`kinematics`] | cage-frame speeds, epicyclic speed, slips | §5.3 |
//! | [`roller_equilibrium`] | roller moment equation ΣT(ε_w) = 0 | §5.4, §4.9 |
//! | [`cage_equilibrium`] | cage moment equation Φ(ε₀) = 0 | §5.5 |
//! | [`cage_land`] | [`QuasiStaticLandModel`] trait, short-bearing (Ocvirk) land | §5.5 |
//! | [`drag`] | air–oil drag of the cage | §4.10, §5.5 |
//! | [`results`] | [`SkidResult`] | §5.6 |
//! | [`options`] / [`conditions`] | [`QuasiStaticOptions`], [`QuasiStaticConditions`] | §5.6 |
//! | [`mod@sweep`] | deterministic sweeps over speed, load, misalignment | |
//! | [`studies`] | O'Brien–Taylor (V-06) and intershaft (V-18) studies | V-06, V-18 |
//! | [`tapered`] | load distribution of the double-row tapered bearing (5 DOF, slices, rib) | §1.6 (c), §2.1 |
//!
//! ```no_run
//! use rolldyn_quasistatic::*;
//! # fn demo(bearing: &rolldyn_geometry::CylindricalRollerBearing) -> Result<(), QsError> {
//! let oil = rolldyn_lubrication::lubricant_by_name("nvi65").unwrap();
//! let mut cond = QuasiStaticConditions::new(rpm(4000.0), 0.0, 201.0, oil, celsius(54.5));
//! cond.friction = FrictionModel::seed000_nvi65();
//! let r = solve(bearing, &cond, &QuasiStaticOptions::default())?;
//! println!("cage slip {:.2} %", 100.0 * r.cage_slip);
//! # Ok(()) }
//! ```

#![warn(missing_docs)]

pub mod cage_equilibrium;
pub mod cage_land;
pub mod conditions;
pub mod drag;
mod error;
pub mod friction;
pub mod kinematics;
pub mod load_distribution;
pub mod load_integral;
mod model;
pub mod operating_geometry;
pub mod options;
pub mod results;
pub mod roller_equilibrium;
pub mod studies;
pub mod sweep;
pub mod tapered;

pub use cage_land::{
    CageLandInput, CageLandOutput, ContactLand, FiniteLand, QuasiStaticLandModel, ShortBearing,
};
pub use conditions::{
    BarFriction, CageLandInputs, DragCoefficient, DragInputs, EndFriction, FrictionModel,
    MixtureDensity, Mounting, PartMaterial, PartTemperatures, QuasiStaticConditions,
    QuasiStaticContactTemperatures, ThermalExpansion, celsius, rpm,
};
pub use error::{QsError, Residual};
pub use kinematics::KinematicCase;
pub use load_distribution::{LoadCase, LoadDistribution, LoadModel, RollerLoad};
pub use model::{rating_geometry, static_load_rating};
pub use operating_geometry::{OperatingGeometry, operating_geometry};
pub use options::{LandMomentArm, QuasiStaticOptions, SlipReference};
pub use results::{ContactResult, RollerResult, SkidResult, Zone};
pub use sweep::{SweepPoint, SweepVariable, sweep};

use rolldyn_geometry::CylindricalRollerBearing;

/// Solves one quasi-static operating point with the default short-bearing cage land
/// ([`ShortBearing`]). Non-convergence returns [`QsError::NotConverged`] with the last
/// residuals; a returned result contains no NaN.
pub fn solve(
    bearing: &CylindricalRollerBearing,
    conditions: &QuasiStaticConditions,
    options: &QuasiStaticOptions,
) -> Result<SkidResult, QsError> {
    model::run(bearing, conditions, options, &ShortBearing::default())
}

/// As [`solve`] with a caller-supplied cage–land model (e.g. a finite journal-bearing solver).
pub fn solve_with_land_model(
    bearing: &CylindricalRollerBearing,
    conditions: &QuasiStaticConditions,
    options: &QuasiStaticOptions,
    land_model: &dyn QuasiStaticLandModel,
) -> Result<SkidResult, QsError> {
    model::run(bearing, conditions, options, land_model)
}
