//! [001] asperity + film-shear + Blok flash-temperature model (SPEC §4.9).
mod common;
use common::*;
use rolldyn_lubrication::traction::flash::laplace_phi;
use rolldyn_lubrication::traction::{Seed001Inputs, seed001_friction};
use rolldyn_lubrication::*;

fn inputs(v: f64) -> Seed001Inputs {
    // intershaft-like roller: R' = 4.5 mm, l = 10 mm, 500 N, u = 20 m/s, ring at 80 °C (assumed case)
    let e = e_reduced(210e9, 0.3);
    let r = 0.0045;
    let st = ContactState {
        normal_force_n: 500.0,
        geometry: ContactGeometry::Line { length_m: 0.01 },
        reduced_radius_m: r,
        reduced_modulus_pa: e,
        rolling_speed_m_s: 20.0,
        sliding_speed_m_s: v,
        temperature_k: 80.0 + C0,
        roughness_ra_m: [0.16e-6, 0.2e-6],
        film_thickness_m: None,
    };
    let hz = st.hertz();
    Seed001Inputs {
        normal_force: 500.0,
        length: 0.01,
        reduced_radius: r,
        reduced_modulus: e,
        half_width: hz.half_width_m,
        max_pressure: hz.max_pressure_pa,
        rolling_speed: 20.0,
        sliding_speed: v,
        ring_temperature: 80.0 + C0,
        roughness: [0.16e-6, 0.2e-6],
    }
}

/// Without the thermal iteration the film-shear coefficient equals the Newtonian Couette shear
/// with Barus viscosity integrated over the Hertz pressure, (μ0 U_S/h0)∫e^{αp(x)}dx / (F/Δl):
/// the F-37 reading J = ½∫exp[αp0(1 − x²/b²)]dx is checked against Simpson quadrature (2000 panels,
/// error ≪ 1e-8 relative) — tolerance 1e-6 covers the erf approximation (1.2e-7).
#[test]
fn film_shear_matches_quadrature() {
    let oil = lubricant_by_name("pao1-vg320").unwrap();
    let st = Seed001Settings {
        thermal_iteration: false,
        ..Default::default()
    };
    let inp = inputs(0.5);
    let r = seed001_friction(&inp, &oil, &st);
    let t = inp.ring_temperature;
    let (eta0, alpha) = (
        oil.dynamic_viscosity(t).unwrap(),
        oil.pressure_viscosity(t).unwrap(),
    );
    let (b, p0) = (inp.half_width, inp.max_pressure);
    let n = 2000;
    let hstep = 2.0 * b / n as f64;
    let g = |x: f64| (alpha * p0 * (1.0 - x * x / (b * b)).max(0.0)).exp();
    let mut sum = g(-b) + g(b);
    for k in 1..n {
        let x = -b + k as f64 * hstep;
        sum += if k % 2 == 1 { 4.0 } else { 2.0 } * g(x);
    }
    let integral = sum * hstep / 3.0;
    let f_expect =
        eta0 * inp.sliding_speed.abs() / r.film * integral / (inp.normal_force / inp.length);
    assert!(
        (r.f_film / f_expect - 1.0).abs() < 1e-6,
        "{} vs {}",
        r.f_film,
        f_expect
    );
    assert!(r.asperity_fraction >= 0.0 && r.asperity_fraction <= 0.25);
    let eta_expect = 0.25 - laplace_phi(r.lambda) / 2.0;
    assert!((r.asperity_fraction - eta_expect).abs() < 1e-15);
}

/// The Blok iteration converges to the fixed point t_c = t_n + ⅔Δt(t_c) (tolerance 0.01 K, the
/// default), heats the oil and lowers f; f → 0 with the slip (Kragelsky asperity friction).
#[test]
fn flash_iteration_fixed_point() {
    let oil = lubricant_by_name("pao1-vg320").unwrap();
    let cold = seed001_friction(
        &inputs(1.0),
        &oil,
        &Seed001Settings {
            thermal_iteration: false,
            ..Default::default()
        },
    );
    let hot = seed001_friction(&inputs(1.0), &oil, &Seed001Settings::default());
    assert!(hot.converged, "{hot:?}");
    let tn = 80.0 + C0;
    assert!((hot.contact_temperature_k - tn - 2.0 / 3.0 * hot.flash_rise_k).abs() < 0.01 + 1e-9);
    assert!(hot.contact_temperature_k > tn && hot.f < cold.f);
    assert!(hot.iterations < 20);
    let tiny = seed001_friction(&inputs(1e-7), &oil, &Seed001Settings::default());
    assert!(tiny.f < 1e-4);
    // the rolling term ±p0h0 is reported separately and not in f by default (F-40)
    assert!((hot.rolling_term_n_per_m - inputs(1.0).max_pressure * hot.film).abs() < 1e-9);
}
