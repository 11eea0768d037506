//! Quasi-static load distribution of the double-row tapered roller bearing (seed 000 §3.2,
//! SPEC §1.6 (c)) under radial load, axial load and a tilting moment or an imposed
//! misalignment, after Jones' five-degree-of-freedom analysis as Harris & Kotzalas present it
//! for tapered roller bearings (Advanced Concepts of Bearing Technology, 5th ed., ch. 1):
//!
//! * unknowns: the displacement (δx, δy, δz) and tilt (θx, θy) of the inner-ring assembly
//!   (both cones and the spacer, one rigid body) against the fixed double cup;
//! * per roller, its equilibrium in its axial plane under the cone, cup and large-rib forces
//!   and its centrifugal force ([`roller`]: rigid rib, lift and tilt solved, line contacts by
//!   slices so that a tilt between the raceways loads the roller's edge);
//! * the two rows share the axial clearance: the geometry places each row's cup at the normal
//!   gap ½ c_a sin α_o from its seated rollers, and δz closes one row's gap while opening the
//!   other's.
//!
//! | module | content |
//! |---|---|
//! | [`case`] | [`TaperedLoadCase`], [`TiltCondition`] |
//! | [`settings`] | [`TaperedLoadSettings`] |
//! | `plane` | in-plane motion of the ring at a roller's azimuth |
//! | `roller` | roller equilibrium in its axial plane |
//! | `ring` | inner-ring equilibrium (Newton, forward-difference Jacobian) |
//! | [`results`] | [`TaperedLoads`] |

pub mod case;
mod plane;
pub mod results;
mod ring;
mod roller;
pub mod settings;
mod summary;
#[cfg(test)]
mod tests;

pub use case::{TaperedLoadCase, TiltCondition};
pub use results::{
    ROLLER_COLUMNS, TaperedLoads, TaperedRollerLoad, TaperedRowLoads, TaperedSumChecks, roller_row,
};
pub use settings::TaperedLoadSettings;

use crate::QsError;
use ring::RingProblem;
use rolldyn_contact::slices::{SliceLaw, tapered_raceway_laws};
use rolldyn_geometry::DoubleRowTaperedBearing;
use roller::RowRoller;

/// The two rows' rollers of a bearing with their slice laws, ready to solve load cases.
#[derive(Debug, Clone)]
pub struct TaperedLoadModel {
    bearing: DoubleRowTaperedBearing,
    rows: [RowRoller; 2],
}

impl TaperedLoadModel {
    /// The model of `bearing` with the cone and cup slice laws of the dynamics
    /// ([`tapered_raceway_laws`]: seed 000 eqs. (2.3)/(2.4)).
    pub fn new(bearing: &DoubleRowTaperedBearing) -> Result<Self, QsError> {
        Self::with_laws(bearing, &tapered_raceway_laws(bearing))
    }

    /// The model with the cone and cup slice laws `laws`.
    pub fn with_laws(
        bearing: &DoubleRowTaperedBearing,
        laws: &[SliceLaw; 2],
    ) -> Result<Self, QsError> {
        bearing
            .validate()
            .map_err(|e| QsError::Geometry(e.to_string()))?;
        Ok(Self {
            bearing: bearing.clone(),
            rows: [
                RowRoller::new(bearing, 0, laws)?,
                RowRoller::new(bearing, 1, laws)?,
            ],
        })
    }

    /// Solves `case`. A returned result passed the residual test; otherwise
    /// [`QsError::NotConverged`] carries the scaled residuals.
    pub fn solve(
        &self,
        case: &TaperedLoadCase,
        settings: &TaperedLoadSettings,
    ) -> Result<TaperedLoads, QsError> {
        case.validate()?;
        let problem = RingProblem::new(&self.bearing, &self.rows, case, *settings);
        let start = summary::start_point(&self.bearing, &self.rows[0], case);
        let (state, iterations) = problem.solve(start)?;
        Ok(summary::summarise(
            &self.bearing,
            &problem,
            &state,
            iterations,
        ))
    }
}

/// Solves `case` on `bearing` with the default slice laws ([`TaperedLoadModel::new`]).
pub fn solve_tapered_loads(
    bearing: &DoubleRowTaperedBearing,
    case: &TaperedLoadCase,
    settings: &TaperedLoadSettings,
) -> Result<TaperedLoads, QsError> {
    TaperedLoadModel::new(bearing)?.solve(case, settings)
}
