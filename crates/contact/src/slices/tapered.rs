//! The slice laws of the double-row tapered bearing's raceways (seed 000 §3.2 "rollers divided
//! into slices"; the laws of SPEC §2.1): shared by the dynamics and the quasi-static load
//! distribution so that both use one definition.

use super::SliceLaw;
use rolldyn_geometry::DoubleRowTaperedBearing;

/// Cone (inner raceway) and cup (outer raceway) slice laws of `b`: seed 000 eq. (2.3) with the
/// pitch diameter d_m and eq. (2.4) with the cup wall t_b = ½(D − (d_m + D_w)), both with the
/// roller material's E and ν.
pub fn tapered_raceway_laws(b: &DoubleRowTaperedBearing) -> [SliceLaw; 2] {
    let steel = &b.roller.material;
    let dm = b.pitch_diameter;
    let cup_wall = 0.5 * (b.outside_diameter - (dm + b.roller.mean_diameter));
    [
        SliceLaw::InnerRing {
            pitch_diameter: dm,
            youngs_modulus: steel.youngs_modulus,
            poisson_ratio: steel.poisson_ratio,
        },
        SliceLaw::OuterRing {
            ring_wall_thickness: cup_wall,
            outside_diameter: b.outside_diameter,
            pitch_diameter: dm,
            youngs_modulus: steel.youngs_modulus,
            poisson_ratio: steel.poisson_ratio,
        },
    ]
}
