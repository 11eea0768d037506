//! `SliceBatch` (the dynamics' traction path) gives the per-slice `traction_prepared` /
//! `traction` coefficients bit for bit, for every friction law.

use rolldyn_lubrication::traction::{
    FrictionLaw, LubricatedFriction, Rheology, SliceBatch, TractionConfig, TwoLevelLaw,
};
use rolldyn_lubrication::*;

fn whole(q: f64, u: f64, t_c: f64) -> ContactState {
    ContactState {
        normal_force_n: q,
        geometry: ContactGeometry::Line { length_m: 8e-3 },
        reduced_radius_m: 1.0 / (1.0 / 0.0075 + 1.0 / 0.0825),
        reduced_modulus_pa: 210e9 / 0.91,
        rolling_speed_m_s: u,
        sliding_speed_m_s: 0.0,
        temperature_k: 273.15 + t_c,
        roughness_ra_m: [0.2e-6, 0.16e-6],
        film_thickness_m: None,
    }
}

fn models() -> Vec<(&'static str, TractionModel)> {
    let pao = lubricant_by_name("pao1-vg320").unwrap();
    let lubricated = |rheology, mixed, reg| {
        TractionModel::new(TractionConfig {
            oil: Some(pao.clone()),
            law: FrictionLaw::Lubricated(LubricatedFriction {
                hydrodynamic: Hydrodynamic::Muraki(MurakiSettings {
                    rheology,
                    ..MurakiSettings::default()
                }),
                boundary: BoundaryFriction::Kragelsky,
                mixed,
            }),
            regularisation_speed_m_s: reg,
            ..TractionConfig::default()
        })
        .unwrap()
    };
    vec![
        (
            "muraki + mixed (literature limits)",
            lubricated(Rheology::ViscoElastic, Some(MixedLimits::LITERATURE), 0.0),
        ),
        (
            "muraki + mixed (NVI 65 limits, regularised)",
            lubricated(Rheology::ViscoElastic, Some(MixedLimits::NVI65), 1e-3),
        ),
        (
            "isothermal, no blend",
            lubricated(Rheology::Isothermal, None, 0.0),
        ),
        (
            "linear elastic",
            lubricated(Rheology::LinearElastic { cap: 0.1 }, None, 0.0),
        ),
        (
            "seed 001",
            TractionModel::new(TractionConfig {
                oil: Some(pao.clone()),
                law: FrictionLaw::Seed001(Default::default()),
                ..TractionConfig::default()
            })
            .unwrap(),
        ),
        (
            "two-level",
            TractionModel::new(TractionConfig {
                law: FrictionLaw::TwoLevel(TwoLevelLaw {
                    mu_s: 0.1,
                    mu_d: 0.08,
                    v_s: 1e-3,
                    v_d: 2e-3,
                }),
                ..TractionConfig::default()
            })
            .unwrap(),
        ),
    ]
}

/// One round of [`batch_equals_single_slice_evaluation`]: fills `batch` (cleared first) with
/// `contacts` (load N, rolling speed m/s, temperature °C) of ten slices each, evaluates it and
/// compares every film and coefficient with the single-slice path.
fn check_round(
    name: &str,
    model: &TractionModel,
    batch: &mut SliceBatch,
    contacts: &[(f64, f64, f64)],
) {
    batch.clear();
    let mut expected = Vec::new();
    let mut films = Vec::new();
    for (c, &(q, u, t_c)) in contacts.iter().enumerate() {
        let w = whole(q, u, t_c);
        let contact = batch.add_contact(model, &w);
        let prepared = model.prepare_contact(&w, None);
        films.push((contact, prepared.map(|p| p.film())));
        for s in 0..10 {
            let share = q * (0.02 + 0.03 * s as f64);
            let q_s = if s == 9 { 0.0 } else { share };
            let u_s = u * (1.0 + 0.01 * s as f64) * if c == 2 { -1.0 } else { 1.0 };
            let v_s = [-0.5, -1e-4, 0.0, 1e-5, 3e-4, 0.01, 0.2, 1.0, 5.0, 0.3][s];
            let i = batch.push(contact, q_s, 0.8e-3, u_s, v_s);
            let st = batch.state(i);
            let reference = match &prepared {
                Some(p) => model.traction_prepared(p, &st).coefficient,
                None => traction(&st, model).coefficient,
            };
            expected.push(reference);
        }
    }
    batch.evaluate(model);
    for (contact, film) in films {
        let (central, minimum, _) = batch.film(contact);
        if let Some((hc, hm)) = film {
            assert_eq!(
                (central.to_bits(), minimum.to_bits()),
                (hc.to_bits(), hm.to_bits())
            );
        } else {
            assert!(
                central.is_nan() && minimum.is_nan(),
                "{name}: film without a law"
            );
        }
    }
    assert_eq!(batch.len(), expected.len());
    for (i, e) in expected.iter().enumerate() {
        let got = batch.coefficient(i);
        assert!(
            got.to_bits() == e.to_bits() || (got == 0.0 && *e == 0.0),
            "{name}, slice {i}: batch {got} vs single {e}"
        );
    }
}

#[test]
fn batch_equals_single_slice_evaluation() {
    // contacts over loads, speeds (incl. below the rolling-speed floor) and temperatures;
    // consecutive contacts at one temperature share the oil preparation, and columns that are
    // the same for every contact of a round are kept from the round before when unchanged
    let mixed = [
        (400.0, 30.0, 100.0),
        (20.0, 5.0, 60.0),
        (150.0, 1e-4, 100.0),
        (1e-3, 30.0, 120.0),
        (250.0, 12.0, 120.0),
    ];
    let hot = [
        (400.0, 30.0, 100.0),
        (20.0, 5.0, 100.0),
        (150.0, 1e-4, 100.0),
    ];
    let hotter = [
        (300.0, 20.0, 120.0),
        (90.0, 25.0, 120.0),
        (150.0, 1e-4, 120.0),
        (60.0, 2.0, 120.0),
        (10.0, 30.0, 120.0),
        (250.0, 12.0, 120.0),
    ];
    for (name, model) in models() {
        let mut batch = SliceBatch::default();
        for round in [
            &mixed[..],
            &hot[..2],
            &hot,
            &hot[..2],
            &hotter,
            &hot,
            &mixed,
        ] {
            check_round(name, &model, &mut batch, round);
        }
    }
}

/// `push_block` stores the same slices as one `push` per slice: same states and coefficients.
#[test]
fn block_equals_slice_by_slice_push() {
    for (name, model) in models() {
        let (mut by_slice, mut by_block) = (SliceBatch::default(), SliceBatch::default());
        let w = whole(300.0, 20.0, 90.0);
        let q = [30.0, 45.0, 0.0, 60.0, 12.0];
        let len = [0.8e-3, 0.8e-3, 0.8e-3, 0.8e-3, 0.4e-3];
        let u = [20.0, 20.1, 20.2, 19.9, 20.0];
        let v = [0.01, -0.02, 0.0, 0.3, 1e-4];
        let a = by_slice.add_contact(&model, &w);
        for s in 0..q.len() {
            by_slice.push(a, q[s], len[s], u[s], v[s]);
        }
        let b = by_block.add_contact(&model, &w);
        assert_eq!(by_block.push_block(b, &q, &len, &u, &v), 0, "{name}");
        by_slice.evaluate(&model);
        by_block.evaluate(&model);
        assert_eq!(by_block.len(), q.len());
        for s in 0..q.len() {
            assert_eq!(by_block.state(s), by_slice.state(s), "{name}, slice {s}");
            assert_eq!(
                by_block.coefficient(s).to_bits(),
                by_slice.coefficient(s).to_bits(),
                "{name}, slice {s}"
            );
            assert_eq!(by_block.normal_force(s), q[s]);
            assert_eq!(by_block.rolling_speed(s), u[s]);
            assert_eq!(by_block.sliding_speed(s), v[s]);
        }
        assert_eq!(by_block.coefficient(2), 0.0, "{name}: unloaded slice");
    }
}
