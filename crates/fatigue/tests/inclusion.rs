//! Validation of the inclusion micro-model (theory §10.6, VALIDATION "Inclusion micro-model"):
//! the sphere's Eshelby tensor, Goodier's (1933) sphere solutions, the elliptic-hole limit and
//! the seed's Al₂O₃ ellipsoid in the cage steel.

use rolldyn_fatigue::inclusion::{
    EshelbyTensor, InclusionModel, InclusionSettings, Interface, QuadratureSettings,
};
use rolldyn_fatigue::{principal_extremes, signed_von_mises};

const STEEL_E: f64 = 211e9;
const STEEL_NU: f64 = 0.3;

fn uniaxial(axis: usize, stress: f64) -> [f64; 6] {
    let mut s = [0.0; 6];
    s[axis] = stress;
    s
}

fn settings(semi_axes_m: [f64; 3], youngs_modulus: f64, interface: Interface) -> InclusionSettings {
    InclusionSettings {
        semi_axes_m,
        youngs_modulus,
        interface,
        ..InclusionSettings::default()
    }
}

/// The matrix stress at the sample point whose normal is `normal`.
fn stress_at(model: &InclusionModel, normal: [f64; 3], remote: [f64; 6]) -> [f64; 6] {
    let maps = model
        .points
        .iter()
        .find(|m| (0..3).all(|i| (m.point.normal[i] - normal[i]).abs() < 1e-12))
        .expect("sample point");
    maps.matrix_stress(&remote, model.settings.interface)
}

#[test]
fn sphere_eshelby_tensor_matches_the_closed_form() {
    for nu in [0.0, 0.25, 0.3, 0.45] {
        let s = EshelbyTensor::new([3e-6; 3], nu, &QuadratureSettings::default());
        let d = 15.0 * (1.0 - nu);
        let expected = [
            (7.0 - 5.0 * nu) / d,
            (5.0 * nu - 1.0) / d,
            (4.0 - 5.0 * nu) / d,
        ];
        let got = [s.normal[0][0], s.normal[0][1], s.shear[0]];
        for k in 0..3 {
            assert!(
                (got[k] - expected[k]).abs() < 1e-13,
                "ν {nu}: {got:?} vs {expected:?}"
            );
        }
        println!(
            "sphere ν = {nu}: S1111 {:.15} S1122 {:.15} S1212 {:.15}",
            got[0], got[1], got[2]
        );
    }
}

#[test]
fn homogeneous_inclusion_leaves_the_remote_stress() {
    let mut s = settings([2e-6, 3e-6, 7e-6], STEEL_E, Interface::Bonded);
    s.poisson_ratio = STEEL_NU;
    let model = InclusionModel::new(&s, STEEL_E, STEEL_NU).unwrap();
    let remote = [100e6, -40e6, 25e6, 30e6, -10e6, 5e6];
    for (_, history) in model.matrix_stress_histories(&[remote]) {
        for k in 0..6 {
            assert!((history[0][k] - remote[k]).abs() < 1e-6);
        }
    }
}

/// Goodier (1933): spherical cavity under uniaxial tension σ₀ along z: at the equator
/// σ_zz = (27 − 15ν)/(2(7 − 5ν)) σ₀ and the circumferential σ_φφ = (15ν − 3)/(2(7 − 5ν)) σ₀, at
/// the pole σ_θθ = σ_φφ = −(3 + 15ν)/(2(7 − 5ν)) σ₀; the surface tractions vanish.
#[test]
fn goodier_spherical_cavity() {
    let nu = STEEL_NU;
    let model =
        InclusionModel::new(&settings([3e-6; 3], 0.0, Interface::Bonded), STEEL_E, nu).unwrap();
    let equator = stress_at(&model, [1.0, 0.0, 0.0], uniaxial(2, 1.0));
    let pole = stress_at(&model, [0.0, 0.0, 1.0], uniaxial(2, 1.0));
    let equator_expected = (27.0 - 15.0 * nu) / (2.0 * (7.0 - 5.0 * nu));
    let pole_expected = -(3.0 + 15.0 * nu) / (2.0 * (7.0 - 5.0 * nu));
    println!(
        "cavity equator σzz/σ0 {:.12} (Goodier {equator_expected:.12})",
        equator[2]
    );
    println!(
        "cavity pole σxx/σ0 {:.12} (Goodier {pole_expected:.12})",
        pole[0]
    );
    assert!((equator[2] - equator_expected).abs() < 1e-10);
    assert!((pole[0] - pole_expected).abs() < 1e-10 && (pole[1] - pole_expected).abs() < 1e-10);
    let hoop_expected = (15.0 * nu - 3.0) / (2.0 * (7.0 - 5.0 * nu));
    println!(
        "cavity equator σyy/σ0 {:.12} (Goodier {hoop_expected:.12})",
        equator[1]
    );
    assert!((equator[1] - hoop_expected).abs() < 1e-10);
    for k in [0, 3, 5] {
        assert!(equator[k].abs() < 1e-10, "free surface: {equator:?}");
    }
    for k in [2, 4, 5] {
        assert!(pole[k].abs() < 1e-10, "free surface: {pole:?}");
    }
}

/// Spherical inhomogeneity (Goodier 1933; Eshelby 1957): the interior stress is uniform,
/// σ_m = K₁/(K + α(K₁ − K)) σ⁰_m and s = μ₁/(μ + β(μ₁ − μ)) s⁰ (mean and deviatoric parts),
/// α = (1 + ν)/(3(1 − ν)), β = 2(4 − 5ν)/(15(1 − ν)); traction continuity makes the matrix's
/// radial stress at the pole equal the interior σ_zz. Rigid limit (K₁, μ₁ → ∞):
/// σ_rr(pole)/σ₀ = (1 − ν)/(1 + ν) + 5(1 − ν)/(4 − 5ν).
#[test]
fn goodier_spherical_inhomogeneity_hard_and_rigid() {
    let nu = STEEL_NU;
    let alpha = (1.0 + nu) / (3.0 * (1.0 - nu));
    let beta = 2.0 * (4.0 - 5.0 * nu) / (15.0 * (1.0 - nu));
    let bulk = |e: f64, v: f64| e / (3.0 * (1.0 - 2.0 * v));
    let shear = |e: f64, v: f64| e / (2.0 * (1.0 + v));
    for (e1, nu1) in [(375e9, 0.25), (211e12, 0.25)] {
        let mut s = settings([3e-6; 3], e1, Interface::Bonded);
        s.poisson_ratio = nu1;
        let model = InclusionModel::new(&s, STEEL_E, nu).unwrap();
        let (k, k1) = (bulk(STEEL_E, nu), bulk(e1, nu1));
        let (mu, mu1) = (shear(STEEL_E, nu), shear(e1, nu1));
        let mean_factor = k1 / (k + alpha * (k1 - k));
        let deviatoric_factor = mu1 / (mu + beta * (mu1 - mu));
        let expected_zz = mean_factor / 3.0 + deviatoric_factor * 2.0 / 3.0;
        let interior = model.interior_stress(&uniaxial(2, 1.0));
        let pole = stress_at(&model, [0.0, 0.0, 1.0], uniaxial(2, 1.0));
        println!(
            "E1 {e1:.3e}: interior σzz {:.12}, pole σrr {:.12}, closed form {expected_zz:.12}",
            interior[2], pole[2]
        );
        assert!((interior[2] - expected_zz).abs() < 1e-10);
        assert!((pole[2] - expected_zz).abs() < 1e-10);
    }
    let rigid = (1.0 - nu) / (1.0 + nu) + 5.0 * (1.0 - nu) / (4.0 - 5.0 * nu);
    println!("rigid sphere σrr(pole)/σ0 = {rigid:.6}");
}

/// A long elliptic cavity (a₃ ≫ a₁, a₂) under tension across it tends to the 2-D elliptic hole:
/// σ_max = σ₀ (1 + 2a/b) at the end of the axis a normal to the load (Inglis 1913).
#[test]
fn elliptic_hole_limit() {
    for (a, b) in [(1e-6, 1e-6), (2e-6, 1e-6), (1e-6, 2e-6)] {
        let expected = 1.0 + 2.0 * a / b;
        let model = InclusionModel::new(
            &settings([a, b, 1e4 * a.max(b)], 0.0, Interface::Bonded),
            STEEL_E,
            STEEL_NU,
        )
        .unwrap();
        let got = stress_at(&model, [1.0, 0.0, 0.0], uniaxial(1, 1.0))[1];
        println!("a/b {:.1}: σyy(a)/σ0 {got:.8} (2-D {expected})", a / b);
        assert!((got / expected - 1.0).abs() < 1e-3, "{got} vs {expected}");
    }
}

/// Largest von Mises and principal stress over the sample points, per unit remote stress, and
/// the normal of the point of the largest von Mises stress.
fn concentration(model: &InclusionModel, remote: [f64; 6]) -> (f64, f64, [f64; 3]) {
    let mut worst = (0.0, f64::NEG_INFINITY, [0.0; 3]);
    for (point, history) in model.matrix_stress_histories(&[remote]) {
        let vm = signed_von_mises(&history[0]).abs();
        let (_, largest) = principal_extremes(&history[0]);
        if vm > worst.0 {
            worst.0 = vm;
            worst.2 = point.normal;
        }
        worst.1 = f64::max(worst.1, largest);
    }
    worst
}

/// The seed's Al₂O₃ ellipsoid (2, 3.5, 5 µm; 375 GPa, 0.25) in the cage steel (211 GPa, 0.3)
/// under uniaxial stress along each axis: the concentration factors of VALIDATION.md.
#[test]
fn seed_alumina_ellipsoid_concentration_factors() {
    let defaults = InclusionSettings::default();
    for interface in [Interface::Bonded, Interface::Debonded] {
        let s = InclusionSettings {
            interface,
            ..defaults.clone()
        };
        let model = InclusionModel::new(&s, STEEL_E, STEEL_NU).unwrap();
        for axis in 0..3 {
            for sign in [1.0, -1.0] {
                let (vm, principal, at) = concentration(&model, uniaxial(axis, sign));
                println!(
                    "{interface:?} axis {} σ0 {sign:+}: max vM/|σ0| {vm:.4}, max σ1/|σ0| {principal:.4}, at n = [{:.2}, {:.2}, {:.2}]",
                    axis + 1,
                    at[0],
                    at[1],
                    at[2]
                );
                assert!(vm > 1.0 && vm < 4.0);
            }
        }
    }
}

/// Debonded interface under tension along axis 3: the poles of axis 3 open (the bonded normal
/// traction there is tensile) and carry the cavity's traction-free stress; in compression the
/// interface stays closed there and the stress is the bonded one.
#[test]
fn debonded_poles_open_in_tension_only() {
    let bonded = InclusionModel::new(
        &settings([2e-6, 3.5e-6, 5e-6], 375e9, Interface::Bonded),
        STEEL_E,
        STEEL_NU,
    )
    .unwrap();
    let debonded = InclusionModel::new(&InclusionSettings::default(), STEEL_E, STEEL_NU).unwrap();
    let pole = [0.0, 0.0, 1.0];
    let tension = stress_at(&debonded, pole, uniaxial(2, 100e6));
    assert!(tension[2].abs() < 1e-3 && stress_at(&bonded, pole, uniaxial(2, 100e6))[2] > 100e6);
    let compression = stress_at(&debonded, pole, uniaxial(2, -100e6));
    assert_eq!(compression, stress_at(&bonded, pole, uniaxial(2, -100e6)));
    let maps = &debonded.points[4];
    assert_eq!(maps.point.normal, pole);
    assert_eq!(maps.contact_pressure(&uniaxial(2, 100e6)), 0.0);
    assert!((maps.contact_pressure(&uniaxial(2, -100e6)) + compression[2]).abs() < 1e-3);
}

#[test]
fn a_revolution_of_remote_stresses_maps_point_by_point() {
    let model = InclusionModel::new(&InclusionSettings::default(), STEEL_E, STEEL_NU).unwrap();
    let remote: Vec<[f64; 6]> = (0..180)
        .map(|k| {
            let phase = (2.0 * k as f64).to_radians();
            [0.0, 50e6 * phase.sin(), 200e6 * phase.cos(), 20e6, 0.0, 0.0]
        })
        .collect();
    let histories = model.matrix_stress_histories(&remote);
    assert_eq!(histories.len(), model.points.len());
    assert!(histories.iter().all(|(_, h)| h.len() == 180));
    let cylindrical = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    assert_eq!(model.remote_from_cylindrical(&cylindrical), cylindrical);
}

/// The 3 × 3 tensor of `[xx, yy, zz, xy, yz, zx]`.
fn tensor(s: &[f64; 6]) -> [[f64; 3]; 3] {
    [[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]]
}

/// Strain tensor of the stress `s` in an isotropic material: ε = ((1 + ν) σ − ν tr σ I)/E.
fn strain(s: &[f64; 6], e: f64, nu: f64) -> [[f64; 3]; 3] {
    let t = tensor(s);
    let trace = s[0] + s[1] + s[2];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| ((1.0 + nu) * t[i][j] - if i == j { nu * trace } else { 0.0 }) / e)
    })
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn contract(u: [f64; 3], t: &[[f64; 3]; 3], v: [f64; 3]) -> f64 {
    (0..3)
        .map(|i| (0..3).map(|j| u[i] * t[i][j] * v[j]).sum::<f64>())
        .sum()
}

/// The bonded seed ellipsoid under a general remote stress: at every sample point the matrix
/// stress and the inclusion's uniform stress carry the same traction (σ_out n = σ_in n) and the
/// same tangential strains (t·ε_out·t′ = t·ε_in·t′): the interface conditions the jump map
/// is built from, checked on the assembled stress-component maps.
#[test]
fn bonded_interface_conditions_hold_on_the_general_ellipsoid() {
    let s = InclusionSettings {
        interface: Interface::Bonded,
        ..InclusionSettings::default()
    };
    let model = InclusionModel::new(&s, STEEL_E, STEEL_NU).unwrap();
    let remote = [120e6, -35e6, 210e6, 40e6, -25e6, 60e6];
    let inside = model.interior_stress(&remote);
    let strain_in = strain(&inside, s.youngs_modulus, s.poisson_ratio);
    let stress_in = tensor(&inside);
    for (point, history) in model.matrix_stress_histories(&[remote]) {
        let n = point.normal;
        let stress_out = tensor(&history[0]);
        let strain_out = strain(&history[0], STEEL_E, STEEL_NU);
        let helper = if n[0].abs() < 0.9 {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 1.0, 0.0]
        };
        let t1 = cross(n, helper);
        let t1 = t1.map(|x| x / t1.iter().map(|y| y * y).sum::<f64>().sqrt());
        let t2 = cross(n, t1);
        for direction in [n, t1, t2] {
            let jump = contract(direction, &stress_out, n) - contract(direction, &stress_in, n);
            assert!(jump.abs() < 1e-6 * 210e6, "traction jump {jump} at {n:?}");
        }
        for (u, v) in [(t1, t1), (t2, t2), (t1, t2)] {
            let jump = contract(u, &strain_out, v) - contract(u, &strain_in, v);
            assert!(
                jump.abs() < 1e-9 * 1e-3,
                "tangential strain jump {jump} at {n:?}"
            );
        }
    }
}

/// The cavity maps of a general ellipsoid leave its surface traction-free (σ_out n = 0) at
/// every sample point.
#[test]
fn cavity_surface_is_traction_free_on_the_general_ellipsoid() {
    let model = InclusionModel::new(&InclusionSettings::default(), STEEL_E, STEEL_NU).unwrap();
    let remote = [120e6, -35e6, 210e6, 40e6, -25e6, 60e6];
    for maps in &model.points {
        let stress = tensor(&maps.matrix_stress(&remote, Interface::Debonded));
        let cavity: [f64; 6] =
            std::array::from_fn(|i| (0..6).map(|k| maps.cavity[i][k] * remote[k]).sum::<f64>());
        let cavity = tensor(&cavity);
        let n = maps.point.normal;
        for row in &cavity {
            let traction: f64 = (0..3).map(|j| row[j] * n[j]).sum();
            assert!(traction.abs() < 1e-6 * 210e6, "{traction} at {n:?}");
        }
        let open = stress == cavity;
        assert!(open || contract(n, &stress, n) <= 0.0);
    }
}
