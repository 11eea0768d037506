#![allow(dead_code)]
//! Shared helpers of the validation tests.
use rolldyn_lubrication::contact_state::{
    circular_load_for_max_pressure, line_load_for_max_pressure,
};
use rolldyn_lubrication::*;

pub const C0: f64 = 273.15;

/// E' of (1.13) for two identical steels.
pub fn e_reduced(e: f64, nu: f64) -> f64 {
    e / (1.0 - nu * nu)
}

/// SPEC V-10/V-12 ball-on-disc: ball Ø19 mm on the flat face of a disc, AISI 52100 assumed
/// E = 210 GPa, ν = 0.3 (SPEC V-12 derived cross-check), p_max, u, slip s, temperature in °C.
pub fn ball_on_disc(p_max: f64, u: f64, s: f64, t_c: f64) -> ContactState {
    let e = e_reduced(210e9, 0.3);
    let r = 0.0095;
    ContactState {
        normal_force_n: circular_load_for_max_pressure(p_max, r, e),
        geometry: ContactGeometry::Circular,
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: u,
        sliding_speed_m_s: s * u,
        temperature_k: t_c + C0,
        roughness_ra_m: [0.0, 0.0],
        film_thickness_m: None,
    }
}

/// Roller–inner-raceway line contact at a given p_max (load per length from Hertz).
/// Roller radius r_w, raceway radius r_i, length l; E = 210 GPa, ν = 0.3 (assumed).
pub fn roller_inner(
    p_max: f64,
    r_w: f64,
    r_i: f64,
    l: f64,
    u: f64,
    s: f64,
    t_c: f64,
) -> ContactState {
    let e = e_reduced(210e9, 0.3);
    let r = 1.0 / (1.0 / r_w + 1.0 / r_i);
    ContactState {
        normal_force_n: line_load_for_max_pressure(p_max, l, e, r),
        geometry: ContactGeometry::Line { length_m: l },
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: u,
        sliding_speed_m_s: s * u,
        temperature_k: t_c + C0,
        roughness_ra_m: [0.0, 0.0],
        film_thickness_m: None,
    }
}

/// Rolling speed in the cage frame of a roller on the inner raceway, rotating inner ring, fixed
/// outer ring, pure rolling: u = ω_i R_i (1 + D_w/d_m)/2 (ω_i − ω_c with ω_c = ω_i(1 − D_w/d_m)/2).
pub fn inner_rolling_speed(rpm: f64, r_i: f64, d_w: f64) -> f64 {
    let d_m = 2.0 * r_i + d_w;
    let w = rpm * std::f64::consts::PI / 30.0;
    w * r_i * (1.0 + d_w / d_m) / 2.0
}
