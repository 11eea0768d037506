//! Compliance functions (SPEC §8.3, V-29…V-31, flags F-59…F-61, F-69, F-73).
//! Every tolerance is stated and justified next to its assertion.

use rolldyn_reynolds::compliance::LineKernel;
use rolldyn_reynolds::compliance::fourier::{FourierKernel, Smoothing};
use rolldyn_reynolds::compliance::layer::ElasticLayer;
use rolldyn_reynolds::compliance::liner::{
    AnalyticLinerKernel, LinerKernel, Material, two_layer, winkler,
};

/// V-30 / F-73: the two-layer K₀ with the corrected material indices (liner thickness with
/// bronze, housing thickness with steel) for R₁ = 30, R₂ = 35, R₃ = 100 mm is 2.600×10⁻¹³ m/Pa;
/// the seed's swapped indices give 4.087×10⁻¹³ (+57 %). The non-local kernel (4.36) deflects the
/// bore where the pressure is zero, Winkler does not (the seed's qualitative FE finding).
#[test]
fn v30_two_layer_and_non_locality() {
    let (br, st) = (
        Material {
            e: 1.08e11,
            nu: 0.34,
        },
        Material { e: 2.1e11, nu: 0.3 },
    );
    let k0 = two_layer(0.03, 0.035, 0.1, br, st);
    assert!((k0 / 2.600e-13 - 1.0).abs() < 1e-3, "{k0}");
    let swapped = winkler(0.005, st.e, st.nu) + winkler(0.065, br.e, br.nu);
    assert!((swapped / 4.087e-13 - 1.0).abs() < 1e-3, "{swapped}");
    let n = 72;
    let kan = LinerKernel::Analytic(AnalyticLinerKernel::seed(k0))
        .circulant(n)
        .unwrap();
    let win = LinerKernel::Winkler { k0 }.circulant(n).unwrap();
    // pressure on the first quarter only; deflection at the opposite side
    let p: Vec<f64> = (0..n).map(|i| if i < n / 4 { 1e6 } else { 0.0 }).collect();
    let defl = |c: &[f64], i: usize| -> f64 { (0..n).map(|k| c[(i + n - k) % n] * p[k]).sum() };
    assert!(defl(&kan, n / 2) > 0.0 && defl(&win, n / 2) == 0.0);
    // uniform pressure: the analytic kernel integrates to 1.041 K₀ (its 1.2 prefactor against the
    // decay; the seed does not normalise it, SPEC §8.3)
    let s: f64 = kan.iter().sum();
    assert!((s / k0 - 1.041).abs() < 0.002, "{}", s / k0);
}

/// Regularised identification (3.68)–(3.71), journal setting (n = 10, γ = 10⁻⁴): with 1 %
/// random noise on the FE-like deflection, the regularised kernel is closer to the true one than
/// the unregularised 30-harmonic identification (RMS over the circle), which the seed describes as
/// "small-scale errors in the FE data cause large oscillations".
#[test]
fn regularisation_suppresses_noise() {
    let k = AnalyticLinerKernel::seed(1e-12);
    let n = 360;
    let tau = std::f64::consts::TAU;
    let phi: Vec<f64> = (0..n).map(|i| tau * i as f64 / n as f64).collect();
    let p: Vec<f64> = phi
        .iter()
        .map(|&t| (2.0 * (t - 2.0).sin()).max(0.0) + 0.05)
        .collect();
    let h = tau / n as f64;
    let mut seed = 12345u64;
    let mut noise = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
    };
    let delta: Vec<f64> = (0..n)
        .map(|i| {
            let d: f64 = (0..n).map(|j| p[j] * k.value(phi[i] - phi[j]) * h).sum();
            d * (1.0 + 0.02 * noise())
        })
        .collect();
    let rms = |fk: &FourierKernel| -> f64 {
        let s: f64 = phi
            .iter()
            .map(|&t| (fk.value(t) - k.value(t)).powi(2))
            .sum();
        (s / n as f64).sqrt() / k.k0
    };
    let raw = FourierKernel::identify_periodic(&phi, &p, &delta, 30, Smoothing::None).unwrap();
    let reg =
        FourierKernel::identify_periodic(&phi, &p, &delta, 10, Smoothing::Uniform { gamma: 1e-4 })
            .unwrap();
    assert!(rms(&reg) < rms(&raw), "{} {}", rms(&reg), rms(&raw));
    // and the identified kernel reproduces the deflection it came from (within the noise, 2 %)
    let lk = LinerKernel::Fourier(reg).circulant(n).unwrap();
    for i in (0..n).step_by(45) {
        let d: f64 = (0..n).map(|j| lk[(i + n - j) % n] * p[j]).sum();
        assert!((d / delta[i] - 1.0).abs() < 0.05, "{i}: {d} {}", delta[i]);
    }
}

/// Finite-thickness plate (bonded layer, L_y = 50 mm, steel): near the load it behaves as a
/// half-space (checked in the unit tests); far away its deflection vanishes (K(8 L_y) = 0) and a
/// uniform pressure over a width ≫ L_y gives the Winkler value (unit tests). Here: plane
/// identification (3.67)–(3.72) of the plate kernel from one rigid-roller pressure
/// (h_m = 10 µm, V-31 conditions) on a 6 mm window with n = 20 and the seed's zonal smoothing
/// predicts the deflection for the h_m = 5 µm pressure within 4 % (the seed reports its FE
/// re-check 4 % above the prediction).
#[test]
fn plane_identification_of_the_plate_kernel() {
    use rolldyn_reynolds::line_contact::analytic;
    let plate = ElasticLayer::bonded(0.05, 2.1e11, 0.3);
    let (r, mu, v) = (0.005, 0.024, 7.0);
    let window = 0.006;
    let m = 601;
    let x: Vec<f64> = (0..m)
        .map(|i| -0.5 * window + window * i as f64 / (m - 1) as f64)
        .collect();
    let pressure = |h: f64| -> Vec<f64> {
        let c = analytic::exit_parameter(0.0).unwrap();
        let lh = (r * h).sqrt();
        let p0 = analytic::pressure_scale(mu, v, r, h);
        x.iter()
            .map(|&xi| {
                let t = xi / lh;
                if t < c {
                    analytic::q0(t, c).max(0.0) * p0
                } else {
                    0.0
                }
            })
            .collect()
    };
    let dx = window / (m - 1) as f64;
    let deflect = |p: &[f64]| -> Vec<f64> {
        x.iter()
            .map(|&xi| {
                (0..m)
                    .map(|j| p[j] * plate.integral(xi - x[j] - 0.5 * dx, xi - x[j] + 0.5 * dx))
                    .sum()
            })
            .collect()
    };
    let p1 = pressure(1e-5);
    let d1 = deflect(&p1);
    let zonal = Smoothing::Zonal {
        gamma_centre: 0.0002,
        gamma_outer: 0.0008,
        half_width: 0.03 * 0.05,
        blend: 0.1,
    };
    let fk = FourierKernel::identify_plane(&x, &p1, &d1, window, 20, zonal).unwrap();
    let p2 = pressure(5e-6);
    let d2 = deflect(&p2);
    let pred: Vec<f64> = x
        .iter()
        .map(|&xi| {
            (0..m)
                .map(|j| p2[j] * fk.integral(xi - x[j] - 0.5 * dx, xi - x[j] + 0.5 * dx))
                .sum()
        })
        .collect();
    let dmax = d2.iter().fold(0.0f64, |a, &b| a.max(b));
    let pmax = pred.iter().fold(0.0f64, |a, &b| a.max(b));
    assert!((pmax / dmax - 1.0).abs() < 0.04, "{pmax} {dmax}");
}
