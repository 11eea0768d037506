//! Wear-line patches of a roller–raceway contact from the Boussinesq solver (seed 004; docs/theory.md
//! §2.6, §8.5), for contacts where the edges matter: the pressure field of the roller under a
//! force, and on each slice's wear line the load per unit length over the loaded width.

use crate::WearError;
use crate::wear_line::{LinePatch, slice_patch};
use rolldyn_contact::boussinesq::BoussinesqOptions;
use rolldyn_contact::roller_raceway::RollerRacewayContact;

/// Cells of the pressure grid along each slice: a crowned edge (11 µm over 2.5 mm in 2002834)
/// is resolved to a tenth of a slice.
const CELLS_PER_SLICE: usize = 10;
/// Cells across the patch; the grid spans `WIDTH_IN_HALF_WIDTHS` Hertz half-widths of the mean
/// load per length, so an edge load of several times the mean still fits.
const CELLS_ACROSS: usize = 32;
const WIDTH_IN_HALF_WIDTHS: f64 = 8.0;

/// Patches on the wear lines (one per slice of `lengths_m`) of `contact` under `force_n`.
pub fn boussinesq_patches(
    contact: &RollerRacewayContact,
    force_n: f64,
    lengths_m: &[f64],
) -> Result<Vec<LinePatch>, WearError> {
    let slices = lengths_m.len();
    let loaded = force_n > 0.0; // false for NaN too
    if !loaded {
        return Ok(vec![LinePatch::NONE; slices]);
    }
    let length: f64 = lengths_m.iter().sum();
    let mean = slice_patch(
        force_n,
        length,
        contact.reduced_radius,
        contact.reduced_modulus,
    );
    let nx = slices * CELLS_PER_SLICE;
    let width = WIDTH_IN_HALF_WIDTHS * mean.half_width_m;
    let report = contact
        .boussinesq(
            force_n,
            nx,
            CELLS_ACROSS,
            Some(width),
            BoussinesqOptions::default(),
        )
        .map_err(|e| WearError::Numerical(format!("Boussinesq wear-line pressures: {e}")))?;
    if !report.converged {
        return Err(WearError::Numerical(format!(
            "Boussinesq wear-line pressures did not converge at {force_n:.1} N"
        )));
    }
    let map = report
        .map
        .ok_or_else(|| WearError::Numerical("Boussinesq gave no pressure map".into()))?;
    let dy = (map.extent.3 - map.extent.2) / map.ny as f64;
    // per column: load per unit length and loaded width
    let column = |i: usize| {
        (0..map.ny).fold((0.0, 0.0), |(q, w), j| {
            let p = map.pressure[j * map.nx + i];
            if p > 0.0 {
                (q + p * dy, w + dy)
            } else {
                (q, w)
            }
        })
    };
    Ok((0..slices)
        .map(|s| {
            let (q, w) = (s * CELLS_PER_SLICE..(s + 1) * CELLS_PER_SLICE)
                .map(column)
                .fold((0.0, 0.0), |(q, w), (qi, wi)| (q + qi, w + wi));
            if w > 0.0 {
                LinePatch {
                    half_width_m: 0.5 * w / CELLS_PER_SLICE as f64,
                    mean_pressure_pa: q / w,
                }
            } else {
                LinePatch::NONE
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rolldyn_geometry::BearingModel;

    #[test]
    fn the_lines_carry_the_force_and_match_hertz_on_the_straight_part() {
        let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
        let BearingModel::Cylindrical(b) = &model.bearing else {
            panic!()
        };
        let contact = RollerRacewayContact::from_model(&model.bearing, true, 0.0).unwrap();
        let stack = b.roller.slices();
        let force = 400.0;
        let patches = boussinesq_patches(&contact, force, &stack.length).unwrap();
        let carried: f64 = patches
            .iter()
            .zip(&stack.length)
            .map(|(p, l)| p.mean_pressure_pa * 2.0 * p.half_width_m * l)
            .sum();
        assert!(
            (carried / force - 1.0).abs() < 0.02,
            "carried {carried} N of {force} N"
        );
        // the middle line against the Hertz line contact of its own load per length
        let mid = stack.length.len() / 2;
        let p = patches[mid];
        let q = p.mean_pressure_pa * 2.0 * p.half_width_m;
        let hertz = slice_patch(
            q * stack.length[mid],
            stack.length[mid],
            contact.reduced_radius,
            contact.reduced_modulus,
        );
        assert!(
            (p.mean_pressure_pa / hertz.mean_pressure_pa - 1.0).abs() < 0.1,
            "{p:?} vs {hertz:?}"
        );
        // the unloaded chamfer slices carry nothing
        assert_eq!(patches[0], LinePatch::NONE);
    }
}
