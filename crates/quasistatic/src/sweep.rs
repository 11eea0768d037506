//! Deterministic sweeps over one operating variable (plain loop, warm-started from the previous
//! converged point; the caller may parallelise independent sweeps).

use crate::cage_land::QuasiStaticLandModel;
use crate::conditions::QuasiStaticConditions;
use crate::error::QsError;
use crate::options::QuasiStaticOptions;
use crate::results::SkidResult;
use rolldyn_geometry::CylindricalRollerBearing;

/// The swept variable (values in SI).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepVariable {
    /// Inner-ring speed ω_в, rad/s.
    InnerSpeed,
    /// Outer-ring speed ω_н, rad/s.
    OuterSpeed,
    /// Radial load F_r, N.
    RadialLoad,
    /// Ring misalignment θ, rad.
    Misalignment,
}

/// One point of a sweep.
#[derive(Debug, Clone)]
pub struct SweepPoint {
    /// Value of the swept variable (SI).
    pub value: f64,
    /// Result or error of this point.
    pub result: Result<SkidResult, QsError>,
}

/// Conditions of one sweep point.
pub fn apply(
    base: &QuasiStaticConditions,
    variable: SweepVariable,
    value: f64,
) -> QuasiStaticConditions {
    let mut c = base.clone();
    match variable {
        SweepVariable::InnerSpeed => c.inner_speed_rad_s = value,
        SweepVariable::OuterSpeed => c.outer_speed_rad_s = value,
        SweepVariable::RadialLoad => c.radial_load_n = value,
        SweepVariable::Misalignment => c.misalignment_rad = Some(value),
    }
    c
}

/// Solves `values.len()` points in order with the cage–land model `land_model`. Each point
/// starts from the cage slip of the previous converged point (`options.initial_cage_slip` for
/// the first); a failed point does not stop the sweep.
pub fn sweep(
    bearing: &CylindricalRollerBearing,
    base: &QuasiStaticConditions,
    options: &QuasiStaticOptions,
    land_model: &dyn QuasiStaticLandModel,
    variable: SweepVariable,
    values: &[f64],
) -> Vec<SweepPoint> {
    let mut opts = options.clone();
    values
        .iter()
        .map(|&value| {
            let cond = apply(base, variable, value);
            let result = crate::solve_with_land_model(bearing, &cond, &opts, land_model);
            if let Ok(r) = &result {
                opts.initial_cage_slip = r.cage_slip;
            }
            SweepPoint { value, result }
        })
        .collect()
}

/// The error of the first point when every point of the sweep failed (the sweep then has no
/// result at all); `None` when some point solved or the sweep is empty.
pub fn all_failed(points: &[SweepPoint]) -> Option<&QsError> {
    if points.iter().all(|p| p.result.is_err()) {
        points.first().and_then(|p| p.result.as_ref().err())
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn failed(value: f64) -> SweepPoint {
        SweepPoint {
            value,
            result: Err(QsError::InvalidInput(format!("point {value}"))),
        }
    }

    /// Only a sweep without any solved point reports an error, that of its first point.
    #[test]
    fn all_failed_reports_the_first_error() {
        assert!(all_failed(&[]).is_none());
        let points = [failed(1.0), failed(2.0)];
        assert_eq!(
            all_failed(&points).unwrap().to_string(),
            "invalid input: point 1"
        );
    }
}
