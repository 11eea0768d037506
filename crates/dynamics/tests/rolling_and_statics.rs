#![allow(clippy::field_reassign_with_default, clippy::needless_range_loop)]
//! Pure-rolling limit and static equilibrium.

mod common;
use common::*;
use rolldyn_contact::slices::SliceLaw;
use rolldyn_dynamics::*;
use rolldyn_lubrication::TractionModel;
use rolldyn_lubrication::traction::{FrictionLaw, TractionConfig, TwoLevelLaw};

fn two_level(mu: f64, v_s: f64) -> TractionModel {
    TractionModel::new(TractionConfig {
        oil: None,
        law: FrictionLaw::TwoLevel(TwoLevelLaw {
            mu_s: mu,
            mu_d: mu,
            v_s,
            v_d: 2.0 * v_s,
        }),
        ..TractionConfig::default()
    })
    .unwrap()
}

/// High traction (μ = 0.1 from 5 mm/s of sliding on), no cage drag: the cage runs at the
/// epicyclic speed within 0.1 % (issue 6 figure). The only losses left are the lubricated cage
/// contacts (μ ≤ 0.02), which a 0.1 traction coefficient overcomes with sliding speeds of
/// mm/s, i.e. slip ~1e-4.
#[test]
fn pure_rolling_limit_gives_epicyclic_cage_speed() {
    let mut b = bearing("obrien-taylor");
    b.roller.slice_count = 5;
    let cond = OperatingConditions::new(rpm(2500.0), 300.0);
    let params = ContactParameters::for_bearing(&b);
    let mut set = DynamicsSettings::default();
    set.discard_revolutions = 0;
    set.scuffing_check = false;
    set.output_step_s = 0.0;
    let mut sim = Simulation::new(
        &b,
        cond,
        params,
        set,
        RacewayTraction::same(two_level(0.1, 5e-3)),
    )
    .unwrap();
    let w0 = sim.epicyclic_cage_speed();
    let t_rev = std::f64::consts::TAU / w0;
    let s = sim
        .run_until(0.5 * t_rev, &mut NullSink, &mut |_| {})
        .unwrap();
    let err = (s.cage_speed_mean_rad_s / w0 - 1.0).abs();
    eprintln!(
        "cage {:.4} rad/s vs epicyclic {:.4} rad/s: {:.2e}; {} steps",
        s.cage_speed_mean_rad_s, w0, err, s.steps
    );
    assert!(err < 1e-3, "relative error {err:e}");
}

/// Classical load distribution (Stribeck/Harris, e.g. Harris & Kotzalas ch. 7) written
/// independently of the crate: roller `j` at `ψ_j` from the load line is squeezed by
/// `δ_j = e cos ψ_j − G_r/2`, shared by the inner and outer slice laws in series
/// (`Q_i(δ_i) = Q_o(δ_o)`, `δ_i + δ_o = δ_j`), and `Σ Q_j cos ψ_j = F_r`.
fn classical(b: &rolldyn_geometry::CylindricalRollerBearing, f_r: f64) -> Vec<f64> {
    let p = ContactParameters::for_bearing(b);
    let st = b.roller.slices();
    let law = |l: SliceLaw, delta: f64| -> f64 {
        st.length
            .iter()
            .zip(&st.drop)
            .map(|(&ls, &z)| {
                let pf = l.power_form(ls).unwrap();
                pf.force(delta - z).0
            })
            .sum()
    };
    let series = |d: f64| -> f64 {
        if d <= 0.0 {
            return 0.0;
        }
        // split d so that the inner and outer forces agree (bisection on δ_i)
        let (mut lo, mut hi) = (0.0, d);
        for _ in 0..100 {
            let m = 0.5 * (lo + hi);
            if law(p.inner_raceway.law, m) > law(p.outer_raceway.law, d - m) {
                hi = m;
            } else {
                lo = m;
            }
        }
        law(p.inner_raceway.law, 0.5 * (lo + hi))
    };
    let z = b.roller_count;
    // rollers at θ_j = 2πj/Z, load along +x (through roller 0, symmetric load zone): ψ_j = θ_j
    let loads = |e: f64| -> Vec<f64> {
        (0..z)
            .map(|j| {
                let psi = std::f64::consts::TAU * j as f64 / z as f64;
                series(e * psi.cos() - 0.5 * b.clearance.radial)
            })
            .collect()
    };
    let resultant = |e: f64| -> f64 {
        loads(e)
            .iter()
            .enumerate()
            .map(|(j, q)| q * (std::f64::consts::TAU * j as f64 / z as f64).cos())
            .sum()
    };
    let (mut lo, mut hi) = (0.0, 1e-3);
    for _ in 0..100 {
        let m = 0.5 * (lo + hi);
        if resultant(m) > f_r {
            hi = m;
        } else {
            lo = m;
        }
    }
    loads(0.5 * (lo + hi))
}

/// Static equilibrium: the bearing at rest (ω = 0), no friction, damped contacts, started with
/// the inner ring centred and the rollers on the pitch circle; after the transient has decayed
/// the roller loads agree with the classical load distribution within 2 % of the largest load
/// and the same rollers are loaded (same clearance and load-zone extent).
#[test]
fn static_equilibrium_matches_classical_load_distribution() {
    let mut b = bearing("obrien-taylor");
    b.roller.slice_count = 6;
    let f_r = 400.0;
    let mut cond = OperatingConditions::new(0.0, f_r);
    cond.gravity_m_s2 = [0.0; 3];
    cond.loads = vec![InnerRingLoad::Fixed {
        force_n: [f_r, 0.0, 0.0],
    }];
    let mut params = ContactParameters::for_bearing(&b);
    // stronger raceway damping: settle within a few ms
    params.inner_raceway.damping_n_s_m = 2000.0;
    params.outer_raceway.damping_n_s_m = 2000.0;
    let mut set = DynamicsSettings::default();
    set.output_step_s = 0.0;
    set.scuffing_check = false;
    let traction = RacewayTraction::same(two_level(0.0, 1e-3));
    let mut init =
        Simulation::default_initial_state(&b, cond.clone(), params, traction.clone()).unwrap();
    let rm = 0.5 * b.pitch_diameter();
    for r in &mut init.rollers {
        r.radius_m = rm;
        r.orbital_speed_rad_s = 0.0;
        r.spin_speed_rad_s = 0.0;
    }
    init.cage_speed_rad_s = 0.0;
    init.inner_ring_center_m = [0.0; 3];
    init.cage_center_m = [0.0; 3];
    let mut sim = Simulation::with_initial_state(&b, cond, params, set, traction, &init).unwrap();
    sim.run_until(0.06, &mut NullSink, &mut |_| {}).unwrap();
    let mut last = Last(Vec::new());
    sim.sample_now(&mut last);
    let dynamic = last.0;
    let reference = classical(&b, f_r);
    let qmax = reference.iter().cloned().fold(0.0, f64::max);
    eprintln!("dynamic  {dynamic:.1?}\nclassical {reference:.1?}");
    for (j, (d, r)) in dynamic.iter().zip(&reference).enumerate() {
        assert!(
            (d - r).abs() <= 0.02 * qmax,
            "roller {j}: dynamic {d:.2} N vs classical {r:.2} N"
        );
        assert_eq!(
            *d > 0.01 * qmax,
            *r > 0.01 * qmax,
            "load zone differs at roller {j}"
        );
    }
}

struct Last(Vec<f64>);
impl OutputSink for Last {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        self.0 = s.rollers.inner.force_n.to_vec();
    }
}
