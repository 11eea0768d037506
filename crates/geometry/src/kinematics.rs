//! Epicyclic (pure-rolling) kinematics of a roller between two raceways (SPEC §5.3, seed 001).
//!
//! A roller rolling without sliding on both raceways has its centre velocity
//! (ω_i r_i + ω_o r_o)/2 at the radius (r_i + r_o)/2 midway between them, so the cage turns at
//! ω_c = (d_i ω_i + D_o ω_o)/(d_i + D_o). This is the exact form for a bearing with clearance:
//! the pitch-diameter form ½[ω_i(1 − D_w/d_m) + ω_o(1 + D_w/d_m)] places the roller centre G/2
//! off that radius and is wrong by about G/(2 d_m). The two forms agree at zero clearance.

/// Epicyclic cage speed ω_c = (d_i ω_i + D_o ω_o)/(d_i + D_o) [rad/s] for raceway diameters
/// d_i, D_o [m] and ring speeds ω_i, ω_o [rad/s] (seed 001: ω₀₀, with the roller touching both
/// raceways). In the frame of this cage both raceway surfaces move at the same speed in opposite
/// senses: (ω_i − ω_c) d_i/2 = (ω_c − ω_o) D_o/2.
#[inline]
pub fn epicyclic_cage_speed(
    inner_raceway_diameter: f64,
    outer_raceway_diameter: f64,
    inner_speed: f64,
    outer_speed: f64,
) -> f64 {
    (inner_raceway_diameter * inner_speed + outer_raceway_diameter * outer_speed)
        / (inner_raceway_diameter + outer_raceway_diameter)
}

/// Roller spin about its own axis when it rolls without sliding on both raceways at the
/// [`epicyclic_cage_speed`] [rad/s], positive opposite to the inner ring:
/// ω_r = d_i D_o (ω_i − ω_o) / ((d_i + D_o) D_w), the raceway surface speed in the cage frame
/// over the roller radius. At zero clearance (d_i = d_m − D_w, D_o = d_m + D_w) this is
/// (d_m/D_w)(1 − γ²)(ω_i − ω_o)/2 with γ = D_w/d_m.
#[inline]
pub fn epicyclic_roller_speed(
    inner_raceway_diameter: f64,
    outer_raceway_diameter: f64,
    roller_diameter: f64,
    inner_speed: f64,
    outer_speed: f64,
) -> f64 {
    inner_raceway_diameter * outer_raceway_diameter * (inner_speed - outer_speed)
        / ((inner_raceway_diameter + outer_raceway_diameter) * roller_diameter)
}

/// Cage slip ε₀ = 1 − ω_c/ω_epicyclic (SPEC §5.3, seed 001: ω₀ = ω₀₀(1 − ε₀)), negative when the
/// cage runs faster than epicyclic; 0 when the epicyclic speed is 0.
#[inline]
pub fn cage_slip(cage_speed: f64, epicyclic_cage_speed: f64) -> f64 {
    if epicyclic_cage_speed != 0.0 {
        1.0 - cage_speed / epicyclic_cage_speed
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_raceways_roll_without_sliding() {
        let (di, do_, dw) = (0.160, 0.200 + 40e-6, 0.020);
        for (wi, wo) in [(100.0, 0.0), (0.0, 80.0), (100.0, -40.0), (50.0, 120.0)] {
            let wc = epicyclic_cage_speed(di, do_, wi, wo);
            let wr = epicyclic_roller_speed(di, do_, dw, wi, wo);
            let inner_surface = (wi - wc) * 0.5 * di;
            let outer_surface = (wo - wc) * 0.5 * do_;
            assert!((inner_surface + outer_surface).abs() < 1e-12);
            assert!((wr * 0.5 * dw - inner_surface).abs() < 1e-12);
        }
    }

    #[test]
    fn pitch_diameter_form_at_zero_clearance() {
        let (dm, dw, wi, wo) = (0.180, 0.015, 300.0, -20.0);
        let (di, do_) = (dm - dw, dm + dw);
        let gamma = dw / dm;
        let cage = 0.5 * (wi * (1.0 - gamma) + wo * (1.0 + gamma));
        let spin = 0.5 * (wi - wo) * (1.0 - gamma * gamma) / gamma;
        assert!((epicyclic_cage_speed(di, do_, wi, wo) - cage).abs() < 1e-12 * cage.abs());
        assert!((epicyclic_roller_speed(di, do_, dw, wi, wo) - spin).abs() < 1e-12 * spin.abs());
    }
}
