//! The worn bearing: the unworn geometry with the accumulated depths subtracted along the
//! surface normals (seed 000 §2.4.1 step 6; docs/theory.md §8.7). Always rebuilt from the
//! unworn bearing and the total depth, so no rounding accumulates over the periods.

use crate::WearError;
use crate::rates::SurfaceWear;
use crate::surface::Surface;
use rolldyn_geometry::{
    CylindricalRollerBearing, Profile, ProfileShape, RacewayWearMap, Ring, angle_bin_centre_rad,
};
use rolldyn_numerics::table::interpolate_held;

/// Points of the worn roller generatrix per slice: the crown between slice centres stays
/// resolved to a tenth of a slice.
const PROFILE_POINTS_PER_SLICE: usize = 10;

/// The axial lines of a raceway wear map: the roller's slice centres, with a line of zero wear
/// at each roller end (the raceway beyond the roller is not worn).
pub fn raceway_lines(slice_positions_m: &[f64], roller_length_m: f64) -> Vec<f64> {
    let h = 0.5 * roller_length_m;
    let mut lines = Vec::with_capacity(slice_positions_m.len() + 2);
    lines.push(-h);
    lines.extend_from_slice(slice_positions_m);
    lines.push(h);
    lines
}

/// The raceway map of `ring` worn further by `depth` (lines × bins at the slice centres),
/// padded with the zero lines of [`raceway_lines`]; the ring's own map (a worn model) is
/// sampled at the same lines and bin centres and added.
pub fn raceway_map(
    ring: &Ring,
    slice_positions_m: &[f64],
    roller_length_m: f64,
    bins: usize,
    depth: &[f64],
) -> Result<RacewayWearMap, WearError> {
    let axial = raceway_lines(slice_positions_m, roller_length_m);
    let added = |line: usize, bin: usize| match line {
        0 => 0.0,
        l if l == axial.len() - 1 => 0.0,
        l => depth[(l - 1) * bins + bin],
    };
    let values = (0..axial.len())
        .flat_map(|l| (0..bins).map(move |b| (l, b)))
        .map(|(l, b)| {
            let before = ring
                .raceway_wear
                .as_ref()
                .map_or(0.0, |m| m.depth(axial[l], angle_bin_centre_rad(b, bins)));
            before + added(l, b)
        })
        .collect();
    RacewayWearMap::new(axial.clone(), bins, values).map_err(|e| WearError::Input(e.to_string()))
}

/// The roller generatrix worn by `depth` on the slice centres `positions`.
fn worn_roller_profile(profile: &Profile, positions: &[f64], depth: &[f64]) -> Profile {
    let xe = profile.chamfer_start();
    let n = positions.len() * PROFILE_POINTS_PER_SLICE;
    // the slice centres themselves are points: the slices see the worn drop exactly
    let mut xs: Vec<f64> = (0..=n)
        .map(|i| -xe + 2.0 * xe * i as f64 / n as f64)
        .chain(positions.iter().copied().filter(|x| x.abs() < xe))
        .collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let wear: Vec<(f64, f64)> = positions
        .iter()
        .copied()
        .zip(depth.iter().copied())
        .collect();
    let points = xs
        .into_iter()
        .map(|x| (x, profile.drop(x) + interpolate_held(&wear, x)))
        .collect();
    Profile {
        shape: ProfileShape::Polyline { points },
        ..profile.clone()
    }
}

/// `bearing` worn by `depth`, whose roller lines sit at `positions` (the unworn slice centres).
pub fn worn_bearing(
    bearing: &CylindricalRollerBearing,
    positions: &[f64],
    depth: &SurfaceWear,
) -> Result<CylindricalRollerBearing, WearError> {
    let mut worn = bearing.clone();
    let length = bearing.roller.length;
    worn.roller.profile =
        worn_roller_profile(&bearing.roller.profile, positions, &depth.roller_total());
    worn.inner_ring.raceway_wear = Some(raceway_map(
        &bearing.inner_ring,
        positions,
        length,
        depth.bins,
        &depth.inner_map,
    )?);
    worn.outer_ring.raceway_wear = Some(raceway_map(
        &bearing.outer_ring,
        positions,
        length,
        depth.bins,
        &depth.outer_map,
    )?);
    if let Some(cage) = worn.cage.as_mut() {
        // the roller wears the wall it pushes on: the pocket widens by that depth
        cage.pocket = cage.pocket.worn(depth.max(Surface::CageBar));
    }
    // both ends and both ribs share the end wear (the recorder halves it per end and per rib)
    worn.roller.length -= 2.0 * depth.roller_end;
    let ribbed = if crate::bearing_data::ribs_on_inner_ring(bearing) {
        &mut worn.inner_ring
    } else {
        &mut worn.outer_ring
    };
    if let Some(spacing) = ribbed.rib_spacing.as_mut() {
        *spacing += 2.0 * depth.rib;
    }
    Ok(worn)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn raceway_lines_close_with_the_roller_ends() {
        let lines = raceway_lines(&[-1.0, 0.0, 1.0], 3.0);
        assert_eq!(lines, vec![-1.5, -1.0, 0.0, 1.0, 1.5]);
    }
}
