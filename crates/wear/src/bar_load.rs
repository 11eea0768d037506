//! How a roller's force on a flat cage bar spreads over its slices (docs/theory.md §8.5): the
//! slice line-contact law of the raceways (Palmgren, rescaled to E') at one common approach
//! δ of the roller toward the bar, F_s = F(δ − z_s) over the slice length, Σ F_s = F. At the
//! bar's few newtons the approach is a fraction of a micrometre: only the straight part of a
//! crowned roller touches.

use rolldyn_contact::hertz::{LineApproachModel, LineContact};
use rolldyn_numerics::brent::{BrentOptions, brent_root};

/// Slice forces `out[s]` of a roller pressed on a flat bar with `force_n`.
pub fn bar_slice_forces(
    force_n: f64,
    lengths_m: &[f64],
    drops_m: &[f64],
    reduced_radius_m: f64,
    reduced_modulus_pa: f64,
    out: &mut [f64],
) {
    out.fill(0.0);
    let loaded = force_n > 0.0; // false for NaN too
    if !loaded {
        return;
    }
    let contact = |l: f64| LineContact {
        reduced_radius: reduced_radius_m,
        reduced_modulus: reduced_modulus_pa,
        length: l,
    };
    let law = LineApproachModel::default();
    let total = |delta: f64| -> Result<f64, ()> {
        Ok(lengths_m
            .iter()
            .zip(drops_m)
            .map(|(&l, &z)| contact(l).force_from_approach(delta - z, law))
            .sum::<f64>()
            - force_n)
    };
    let z_min = drops_m.iter().copied().fold(f64::INFINITY, f64::min);
    let l_min = lengths_m.iter().copied().fold(f64::INFINITY, f64::min);
    // the whole force on the shortest slice at the lowest drop bounds the approach from above
    let upper = z_min + contact(l_min).approach(force_n, law);
    let options = BrentOptions {
        x_tol: 1e-13,
        f_tol: 1e-9 * force_n,
        max_iterations: 100,
    };
    let (f_lo, f_hi) = (-force_n, total(upper).unwrap_or(f64::NAN));
    let delta = brent_root(total, (z_min, f_lo), (upper, f_hi), &options)
        .map(|r| r.x)
        .unwrap_or(upper);
    for ((o, &l), &z) in out.iter_mut().zip(lengths_m).zip(drops_m) {
        *o = contact(l).force_from_approach(delta - z, law);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn forces_sum_to_the_bar_force_on_the_straight_part() {
        let lengths = [1e-3; 6];
        let drops = [5e-6, 0.0, 0.0, 0.0, 0.0, 5e-6];
        let mut out = [0.0; 6];
        bar_slice_forces(10.0, &lengths, &drops, 7.5e-3, 2.3e11, &mut out);
        assert!((out.iter().sum::<f64>() - 10.0).abs() < 1e-6);
        assert_eq!(out[0], 0.0);
        assert!((out[1] - 2.5).abs() < 1e-6);
    }
}
