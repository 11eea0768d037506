//! Validation of the finite journal bearing (SPEC §8.6, V-39…V-41, flags F-72…F-79).
//! Every tolerance is stated and justified next to its assertion.

use rolldyn_reynolds::compliance::liner::{AnalyticLinerKernel, LinerKernel, Material, two_layer};
use rolldyn_reynolds::journal::{
    FeedGroove, FilmStart, JournalBearing, JournalOperating, JournalOptions, limits,
    solve_eccentricity, solve_load, solve_state,
};
use rolldyn_reynolds::thermal::ThermalModel;
use rolldyn_reynolds::{Cavitation, Isoviscous, Petrusevich, ReynoldsError};

const R: f64 = 0.025;
const C: f64 = 50e-6;
const MU: f64 = 0.05;

fn op() -> JournalOperating {
    JournalOperating::rpm(3000.0, 313.15)
}

fn no_coeff() -> JournalOptions {
    JournalOptions {
        coefficients: false,
        ..Default::default()
    }
}

/// Raimondi–Boyd (1958) full 360° bearing, L/D = 1 (standard chart values as tabulated in
/// Shigley, not in the seeds): ε = 0.2 / 0.6 / 0.9 → S = 0.631 / 0.121 / 0.0188,
/// φ = 74.02° / 50.58° / 26.45°, (R/c)f = 12.8 / 3.22 / 1.05, Q_s/(RcNL) = 1.005 / 2.944 / 4.356,
/// P/p_max = 0.529 / 0.415 / 0.247. Raimondi–Boyd start the film at the maximum gap and take full
/// film shear, the defaults here. Obtained on the default 120 × 40 grid: within 1.5 % in S, 0.6°
/// in φ, 1.5 % in the friction variable, 2 % in side flow, 1.5 % in P/p_max except S and P/p_max at
/// ε = 0.9 (grid error 2–3 % at this resolution, 240 × 80 halves it); tolerances 3 % / 1° /
/// 3 % / 4 % / 3 % cover the chart reading accuracy (3 significant digits) and that grid error.
#[test]
fn raimondi_boyd_l_over_d_1() {
    let b = JournalBearing::new(R, 2.0 * R, C);
    let rows = [
        (0.2, 0.631, 74.02, 12.8, 1.005, 0.529),
        (0.6, 0.121, 50.58, 3.22, 2.944, 0.415),
        (0.9, 0.0188, 26.45, 1.05, 4.356, 0.247),
    ];
    let n = 50.0;
    for (eps, s, phi, fv, qs, pr) in rows {
        let res = solve_eccentricity(&b, &Isoviscous { mu: MU }, &op(), eps, &no_coeff()).unwrap();
        assert!(res.converged);
        assert!(
            (res.sommerfeld / s - 1.0).abs() < 0.03,
            "ε {eps}: S {}",
            res.sommerfeld
        );
        assert!(
            (res.attitude_deg - phi).abs() < 1.0,
            "ε {eps}: φ {}",
            res.attitude_deg
        );
        assert!(
            (res.friction_variable / fv - 1.0).abs() < 0.03,
            "ε {eps}: f {}",
            res.friction_variable
        );
        let qv = res.side_flow_m3_s / (R * C * n * b.length);
        assert!((qv / qs - 1.0).abs() < 0.04, "ε {eps}: Qs {qv}");
        let p = res.load_n / (2.0 * R * b.length * res.max_pressure_pa);
        assert!((p / pr - 1.0).abs() < 0.03, "ε {eps}: P/pmax {p}");
    }
}

/// V-41 / F-77: the seed's Sommerfeld number Z = 0.123 vs 0.121 "in the reference works" is
/// reproduced at L/D = 1, ε = 0.6 (resultant load, F-78): S = 0.1211 (film start at the maximum
/// gap) and 0.1216 (free film start, the seed's scheme). At the dimensions of the seed's COMSOL
/// case (L = 0.125 m, R = 0.25 m, L/D = 0.25, ε = 0.5) S = 1.79 (SPEC derived 1.80) and at
/// L/D = 1, ε = 0.5 S = 0.179 (SPEC 0.180): the seed's 0.121 cannot belong to those dimensions.
/// Tolerance 1 % (grid error at 120 × 40 ≈ 0.5 %).
#[test]
fn v41_sommerfeld_number() {
    let v = Isoviscous { mu: MU };
    let b = JournalBearing::new(R, 2.0 * R, C);
    let s1 = solve_eccentricity(&b, &v, &op(), 0.6, &no_coeff())
        .unwrap()
        .sommerfeld;
    let free = JournalOptions {
        film_start: FilmStart::Free,
        ..no_coeff()
    };
    let s2 = solve_eccentricity(&b, &v, &op(), 0.6, &free)
        .unwrap()
        .sommerfeld;
    for s in [s1, s2] {
        assert!(s > 0.121 * 0.995 && s < 0.123, "{s}");
    }
    let short = JournalBearing::new(0.25, 0.125, 0.25e-3);
    let s3 = solve_eccentricity(
        &short,
        &Isoviscous { mu: 0.19 },
        &JournalOperating::rpm(1000.0, 313.15),
        0.5,
        &free,
    )
    .unwrap()
    .sommerfeld;
    assert!((s3 / 1.80 - 1.0).abs() < 0.01, "{s3}");
    let s4 = solve_eccentricity(&b, &v, &op(), 0.5, &free)
        .unwrap()
        .sommerfeld;
    assert!((s4 / 0.180 - 1.0).abs() < 0.01, "{s4}");
}

/// V-40 (seed §4.7): "with cavitation the pressure maximum is 17 % higher than COMSOL without
/// cavitation (6 % with the cavitation block off)", i.e. cavitation raises p_max by ≈ 10 % in the
/// seed's own solver. Not reproducible: at the COMSOL dimensions (L/D = 0.25, ε = 0.5) the
/// Reynolds-cavitation and full-Sommerfeld maxima differ by 0.2 % (a short bearing's positive
/// pressure lobe is hardly affected by the cavitation condition); at L/D = 1 the difference is
/// 8.6 %. Asserted: ratios 1.002 ± 0.005 and 1.086 ± 0.01.
#[test]
fn v40_cavitation_effect_on_the_pressure_maximum() {
    let free = JournalOptions {
        film_start: FilmStart::Free,
        ..no_coeff()
    };
    let none = JournalOptions {
        cavitation: Cavitation::None,
        ..free
    };
    for (ld, want, tol) in [(0.25, 1.002, 0.005), (1.0, 1.086, 0.01)] {
        let b = JournalBearing::new(R, 2.0 * R * ld, C);
        let v = Isoviscous { mu: MU };
        let pc = solve_eccentricity(&b, &v, &op(), 0.5, &free)
            .unwrap()
            .max_pressure_pa;
        let pn = solve_eccentricity(&b, &v, &op(), 0.5, &none)
            .unwrap()
            .max_pressure_pa;
        assert!((pc / pn - want).abs() < tol, "L/D {ld}: {}", pc / pn);
    }
}

/// Long-bearing limit (Sommerfeld 1904, full film): the finite solution without cavitation
/// approaches W = 12πμωR³Lε/(c²(2+ε²)√(1−ε²)) as L/D grows, with the 1/L end-leakage
/// deficit: W/W∞ = 0.794 / 0.896 / 0.947 at L/D = 4 / 8 / 16, and the Richardson extrapolation
/// 2·W(16) − W(8) reaches the closed form within 1 % (the attitude is 90° exactly). The 1-D
/// periodic solver reproduces the closed-form pressure to 10⁻³ (unit test in `reynolds1d`).
#[test]
fn long_bearing_limit() {
    let v = Isoviscous { mu: MU };
    let opt = JournalOptions {
        cavitation: Cavitation::None,
        n_axial: 81,
        ..no_coeff()
    };
    let mut ratios = Vec::new();
    for ld in [8.0, 16.0] {
        let b = JournalBearing::new(R, 2.0 * R * ld, C);
        let res = solve_eccentricity(&b, &v, &op(), 0.6, &opt).unwrap();
        assert!((res.attitude_deg - 90.0).abs() < 1e-6);
        ratios.push(
            res.load_n / limits::long_full_sommerfeld(MU, op().journal_speed, R, b.length, C, 0.6),
        );
    }
    assert!(ratios[0] < ratios[1] && ratios[1] < 1.0);
    assert!(
        ((2.0 * ratios[1] - ratios[0]) - 1.0).abs() < 0.01,
        "{ratios:?}"
    );
}

/// Short-bearing limit (Dubois–Ocvirk): at L/D = 1/8 the finite solution (Reynolds cavitation)
/// carries 99.3 % (ε = 0.1) and 97.9 % (ε = 0.6) of the Ocvirk load, and its attitude is within
/// 1° of tan ψ = π√(1−ε²)/(4ε) at ε = 0.6 — the expected O((L/D)²) finite-length deficit.
/// Tolerances: 1.5 % / 3 % and 1.5°.
#[test]
fn short_bearing_limit() {
    let b = JournalBearing::new(R, 2.0 * R / 8.0, C);
    let v = Isoviscous { mu: MU };
    for (eps, tol) in [(0.1, 0.015), (0.6, 0.03)] {
        let res = solve_eccentricity(&b, &v, &op(), eps, &no_coeff()).unwrap();
        let (wr, wt) = limits::short_ocvirk(MU, op().journal_speed, R, b.length, C, eps);
        assert!(
            (res.load_n / wr.hypot(wt) - 1.0).abs() < tol,
            "ε {eps}: {}",
            res.load_n / wr.hypot(wt)
        );
        if eps == 0.6 {
            let psi = (std::f64::consts::PI * (1.0f64 - eps * eps).sqrt() / (4.0 * eps))
                .atan()
                .to_degrees();
            assert!(
                (res.attitude_deg - psi).abs() < 1.5,
                "{} {psi}",
                res.attitude_deg
            );
        }
    }
}

/// Grid convergence over ε = 0.1 … 0.95 and L/D = 0.25 … 2 (corners of the range): the
/// Sommerfeld number on 120 × 41 differs from 240 × 81 by < 0.1 % at ε = 0.1 and < 1.5 % at
/// ε = 0.95 (the film is 0.05c thick there and the pressure peak spans few cells); the
/// second-order convergence ratio (60×21 → 120×41 → 240×81 changes) is ≥ 2.5.
/// The full study is `journal::study::grid_convergence`.
#[test]
fn grid_convergence_corners() {
    let v = Isoviscous { mu: MU };
    for (ld, eps, tol) in [(0.25, 0.1, 1e-3), (2.0, 0.95, 0.015)] {
        let b = JournalBearing::new(R, 2.0 * R * ld, C);
        let s: Vec<f64> = [(60, 21), (120, 41), (240, 81)]
            .iter()
            .map(|&(nt, nz)| {
                let o = JournalOptions {
                    n_circumferential: nt,
                    n_axial: nz,
                    ..no_coeff()
                };
                solve_eccentricity(&b, &v, &op(), eps, &o)
                    .unwrap()
                    .sommerfeld
            })
            .collect();
        let (d1, d2) = ((s[0] - s[1]).abs(), (s[1] - s[2]).abs());
        assert!(d2 / s[2] < tol, "L/D {ld} ε {eps}: {s:?}");
        assert!(d1 / d2 > 2.5, "L/D {ld} ε {eps}: {s:?}");
    }
}

/// Load mode: the equilibrium for the load found at ε = 0.6 returns ε = 0.6 and the same attitude
/// (Brent on ln W, tolerance 10⁻⁸ on the load → ε to ~10⁻⁸).
#[test]
fn load_mode_round_trip() {
    let b = JournalBearing::new(R, 2.0 * R, C);
    let v = Isoviscous { mu: MU };
    let a = solve_eccentricity(&b, &v, &op(), 0.6, &no_coeff()).unwrap();
    let l = solve_load(&b, &v, &op(), a.load_n, &no_coeff()).unwrap();
    assert!(
        l.converged
            && (l.eccentricity - 0.6).abs() < 1e-6
            && (l.attitude_deg - a.attitude_deg).abs() < 1e-4
    );
    assert!(l.load_iterations < 20);
    // a load beyond the capacity at the eccentricity limit is an error, not a NaN
    let too_much = solve_load(&b, &v, &op(), 1e12, &no_coeff());
    assert!(matches!(too_much, Err(ReynoldsError::NoSolution(_))));
}

/// Stiffness and damping by perturbation: the damping matrix is symmetric (a property of the
/// Reynolds-condition film for small perturbations; asserted to 0.1 %), K and C do not depend on
/// the perturbation size (10⁻⁴ vs 10⁻³ of the clearance: 0.1 %), the direct stiffness terms are
/// positive, and the load-frame K_xx agrees with −ΔW/Δe along the load line from two
/// eccentricity solutions (1 %).
#[test]
fn stiffness_and_damping() {
    let b = JournalBearing::new(R, 2.0 * R, C);
    let v = Isoviscous { mu: MU };
    let a = solve_eccentricity(&b, &v, &op(), 0.6, &JournalOptions::default()).unwrap();
    let a3 = solve_eccentricity(
        &b,
        &v,
        &op(),
        0.6,
        &JournalOptions {
            perturbation: 1e-3,
            ..Default::default()
        },
    )
    .unwrap();
    let (k, d) = (a.stiffness_n_per_m, a.damping_ns_per_m);
    assert!((d[0][1] - d[1][0]).abs() < 1e-3 * d[0][0]);
    assert!(k[0][0] > 0.0 && k[1][1] > 0.0 && d[0][0] > 0.0 && d[1][1] > 0.0);
    for i in 0..2 {
        for j in 0..2 {
            assert!((a3.stiffness_n_per_m[i][j] - k[i][j]).abs() < 1e-3 * k[0][0]);
            assert!((a3.damping_ns_per_m[i][j] - d[i][j]).abs() < 1e-3 * d[0][0]);
        }
    }
    // state solves: F at e and at e + Δe along the load direction (load frame x′)
    let st = |e: [f64; 2]| {
        solve_state(&b, &v, &op(), e, [0.0, 0.0], &no_coeff(), None)
            .unwrap()
            .force
    };
    let e0 = [0.6 * C, 0.0];
    let f0 = st(e0);
    let beta = (-f0[1]).atan2(-f0[0]);
    let de = 1e-4 * C;
    let f1 = st([e0[0] + de * beta.cos(), e0[1] + de * beta.sin()]);
    let fm = st([e0[0] - de * beta.cos(), e0[1] - de * beta.sin()]);
    let kxx = -((f1[0] - fm[0]) * beta.cos() + (f1[1] - fm[1]) * beta.sin()) / (2.0 * de);
    assert!((kxx / k[0][0] - 1.0).abs() < 0.01, "{kxx} {}", k[0][0]);
}

/// Mass-conserving JFO cavitation: with the film starting at the maximum gap there is no film
/// reformation inside the bearing and JFO equals the Reynolds solution (same load to 10⁻⁶).
/// With an axial feed groove in the diverging zone (90° after the minimum film) the JFO film
/// leaves the groove, ruptures and re-forms before the load zone; the Reynolds condition ignores
/// this history: the two loads differ by a few per cent (asserted < 10 %, both converged).
/// Without any supply line (free film start) JFO has no lubricant source at all (ambient = cavity
/// pressure at the ends) and correctly carries no load — reported as an error, not NaN.
#[test]
fn jfo_cavitation() {
    let b = JournalBearing::new(R, 2.0 * R, C);
    let v = Isoviscous { mu: MU };
    let rey = solve_eccentricity(&b, &v, &op(), 0.6, &no_coeff()).unwrap();
    let jfo_o = JournalOptions {
        cavitation: Cavitation::Jfo,
        ..no_coeff()
    };
    let jfo = solve_eccentricity(&b, &v, &op(), 0.6, &jfo_o).unwrap();
    assert!(jfo.converged);
    assert!((jfo.load_n / rey.load_n - 1.0).abs() < 1e-6);
    let mut bg = b.clone();
    bg.feed = Some(FeedGroove {
        angle: std::f64::consts::FRAC_PI_2,
        pressure: 0.0,
    });
    let with = |cav| JournalOptions {
        cavitation: cav,
        ..no_coeff()
    };
    let r2 = solve_eccentricity(&bg, &v, &op(), 0.6, &with(Cavitation::Reynolds)).unwrap();
    let j2 = solve_eccentricity(&bg, &v, &op(), 0.6, &with(Cavitation::Jfo)).unwrap();
    assert!(r2.converged && j2.converged);
    assert!(
        (j2.load_n / r2.load_n - 1.0).abs() < 0.10,
        "{} {}",
        j2.load_n,
        r2.load_n
    );
    let free = JournalOptions {
        film_start: FilmStart::Free,
        ..with(Cavitation::Jfo)
    };
    assert!(solve_eccentricity(&b, &v, &op(), 0.6, &free).is_err());
}

/// V-39 (seed §4.2–4.6): bronze liner R₁ = 30 mm, R₂ = 35 mm, steel housing to R₃ = 100 mm,
/// d = 130 µm, μ = 0.024 Pa·s, ω = 314.16 1/s, L = 2R₁; compliance K₀ of (4.15) with the
/// corrected material indices (F-73) = 2.60×10⁻¹³ m/Pa and the analytic kernel (4.36)
/// (a = 5, α = 1.7, β = 1.4). Seed: "at η̃ = 0.95 elastic deformation lowers the pressure
/// maximum ≈ 1.5 ×". Obtained: 1.545 (ε = 0.95), 1.13 (0.9), 1.02 (0.8). Tolerance ±0.1 on the
/// ratio (the seed gives one significant digit). The coupled iteration converges in ≈ 12 steps
/// (the seed's ADI needs ≈ 200).
#[test]
fn v39_elastic_liner() {
    let (r1, r2, r3, d) = (0.03, 0.035, 0.1, 1.3e-4);
    let k0 = two_layer(
        r1,
        r2,
        r3,
        Material {
            e: 1.08e11,
            nu: 0.34,
        },
        Material { e: 2.1e11, nu: 0.3 },
    );
    assert!((k0 / 2.600e-13 - 1.0).abs() < 1e-3, "{k0}");
    let mut b = JournalBearing::new(r1 - d, 2.0 * r1, d);
    let op = JournalOperating {
        journal_speed: 314.16,
        bearing_speed: 0.0,
        temperature: 313.15,
    };
    let v = Isoviscous { mu: 0.024 };
    let o = JournalOptions {
        film_start: FilmStart::Free,
        ..no_coeff()
    };
    let rigid = solve_eccentricity(&b, &v, &op, 0.95, &o).unwrap();
    b.liner = Some(LinerKernel::Analytic(AnalyticLinerKernel::seed(k0)));
    let el = solve_eccentricity(&b, &v, &op, 0.95, &o).unwrap();
    assert!(el.converged && el.coupling_iterations < 40);
    let ratio = rigid.max_pressure_pa / el.max_pressure_pa;
    assert!((ratio - 1.5).abs() < 0.1, "{ratio}");
}

/// Thermal model (4.16)–(4.30) coupled through the Petrusevich law: converges, heats the film
/// above the housing temperature, lowers the load relative to the isothermal solution at the
/// housing temperature, and the heat put into the bush equals the dissipated power (energy
/// balance of the model, 2 %: the heat flux uses central pressure gradients, the power the wall
/// tractions). χ and T₀ are not given in the seed (F-75): χ = 50 W/(m·K), T₀ = 40 °C here;
/// the seed's "T = 221.7 K, i.e. 58.7 °C" is self-contradictory (58.7 °C = 331.85 K).
#[test]
fn thermal_model() {
    let (r1, r3, d) = (0.03, 0.1, 1.3e-4);
    let mut b = JournalBearing::new(r1 - d, 2.0 * r1, d);
    let op = JournalOperating {
        journal_speed: 314.16,
        bearing_speed: 0.0,
        temperature: 313.15,
    };
    let pv = Petrusevich {
        mu0: 0.024,
        alpha: 2e-8,
        omega0: 0.03,
        t_ref_k: 313.15,
    };
    let iso = solve_eccentricity(&b, &pv, &op, 0.8, &no_coeff()).unwrap();
    b.thermal = Some(ThermalModel {
        conductivity: 50.0,
        ambient_temperature: 313.15,
        outer_radius: r3,
        harmonics: 10,
    });
    let th = solve_eccentricity(&b, &pv, &op, 0.8, &no_coeff()).unwrap();
    assert!(th.converged);
    assert!(th.mean_temperature_k > 313.15 + 1.0 && th.max_temperature_k > th.mean_temperature_k);
    assert!(th.load_n < iso.load_n);
    // heat into the bush: ∫ Q dA from the temperature field is not exposed; the mean bore
    // temperature rise of the k = 0 harmonic is Q̄·R₁ ln(R₃/R₁)/χ
    let area = std::f64::consts::TAU * r1 * b.length;
    let qbar = th.power_loss_w / area;
    let rise = qbar * r1 * (r3 / r1).ln() / 50.0;
    assert!(
        ((th.mean_temperature_k - 313.15) / rise - 1.0).abs() < 0.02,
        "{} {rise}",
        th.mean_temperature_k - 313.15
    );
}

/// Bad input: ε ≥ 1, ε < 0, ε = 0, zero clearance, zero speed without squeeze → errors.
#[test]
fn bad_input_is_rejected() {
    let b = JournalBearing::new(R, 2.0 * R, C);
    let v = Isoviscous { mu: MU };
    for eps in [1.0, 1.2, -0.1, 0.0, f64::NAN] {
        assert!(matches!(
            solve_eccentricity(&b, &v, &op(), eps, &no_coeff()),
            Err(ReynoldsError::InvalidInput {
                what: "eccentricity",
                ..
            })
        ));
    }
    let b0 = JournalBearing::new(R, 2.0 * R, 0.0);
    assert!(solve_eccentricity(&b0, &v, &op(), 0.5, &no_coeff()).is_err());
    let still = JournalOperating::rpm(0.0, 313.15);
    assert!(matches!(
        solve_eccentricity(&b, &v, &still, 0.5, &no_coeff()),
        Err(ReynoldsError::InvalidInput { what: "speed", .. })
    ));
    // but a pure squeeze film is fine
    let sq = solve_state(
        &b,
        &v,
        &still,
        [0.3 * C, 0.0],
        [-0.01, 0.0],
        &no_coeff(),
        None,
    )
    .unwrap();
    assert!(sq.force[0] > 0.0 && sq.force[0].is_finite());
}
