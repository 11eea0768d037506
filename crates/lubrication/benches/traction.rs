//! Cost of one `traction()` call (budget: ≤ 200 ns per call, dynamics calls it per slice per stage).
use criterion::{Criterion, criterion_group, criterion_main};
use rolldyn_lubrication::traction::{FrictionLaw, LubricatedFriction, SliceBatch, TractionConfig};
use rolldyn_lubrication::*;
use std::hint::black_box;

fn slice_state(t_c: f64) -> ContactState {
    // roller Ø15 mm on inner raceway Ø165 mm, 1 mm slice, 60 N, u = 30 m/s (2002834-like)
    ContactState {
        normal_force_n: 60.0,
        geometry: ContactGeometry::Line { length_m: 1e-3 },
        reduced_radius_m: 1.0 / (1.0 / 0.0075 + 1.0 / 0.0825),
        reduced_modulus_pa: 210e9 / 0.91,
        rolling_speed_m_s: 30.0,
        sliding_speed_m_s: 0.3,
        temperature_k: 273.15 + t_c,
        roughness_ra_m: [0.2e-6, 0.16e-6],
        film_thickness_m: None,
    }
}

fn bench(c: &mut Criterion) {
    let pao = lubricant_by_name("pao1-vg320").unwrap();
    // DYN default path: Muraki visco-elastic + Kragelsky + (1.3) blend, film (2.17) computed
    let mixed = TractionModel::new(TractionConfig {
        oil: Some(pao.clone()),
        law: FrictionLaw::Lubricated(LubricatedFriction {
            hydrodynamic: Hydrodynamic::Muraki(MurakiSettings::default()),
            boundary: BoundaryFriction::Kragelsky,
            mixed: Some(MixedLimits::LITERATURE),
        }),
        regularisation_speed_m_s: 1e-3,
        ..TractionConfig::default()
    })
    .unwrap();
    let st = slice_state(60.0);
    let mut k = 0u32;
    c.bench_function("traction/line_muraki_mixed_pao1", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let mut s = st;
            s.sliding_speed_m_s = 0.01 + (k % 64) as f64 * 0.02; // vary the slip
            traction(black_box(&s), black_box(&mixed))
        })
    });

    // 18 roller–raceway contacts × 10 slices, per slice (`traction_prepared`) and batched
    // (`SliceBatch`, the dynamics' path)
    let wholes: Vec<ContactState> = (0..18)
        .map(|j| ContactState {
            normal_force_n: 50.0 + 20.0 * j as f64,
            geometry: ContactGeometry::Line { length_m: 8e-3 },
            ..st
        })
        .collect();
    let slice_of = |j: usize, s: usize| ContactState {
        normal_force_n: (5.0 + 2.0 * j as f64) * (0.8 + 0.04 * s as f64),
        geometry: ContactGeometry::Line { length_m: 0.8e-3 },
        sliding_speed_m_s: 0.01 + 0.003 * (j * 10 + s) as f64,
        ..st
    };
    c.bench_function("traction/180_slices_per_slice", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (j, w) in wholes.iter().enumerate() {
                let prep = mixed.prepare_contact(black_box(w), None).unwrap();
                for s in 0..10 {
                    sum += mixed.traction_prepared(&prep, &slice_of(j, s)).coefficient;
                }
            }
            sum
        })
    });
    c.bench_function("traction/18_contacts_prepare", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for w in wholes.iter() {
                sum += mixed.prepare_contact(black_box(w), None).unwrap().film().0;
            }
            sum
        })
    });
    let mut batch = SliceBatch::with_capacity(180);
    c.bench_function("traction/180_slices_batch", |b| {
        b.iter(|| {
            batch.clear();
            for (j, w) in wholes.iter().enumerate() {
                let contact = batch.add_contact(&mixed, black_box(w));
                for s in 0..10 {
                    let sl = slice_of(j, s);
                    batch.push(
                        contact,
                        sl.normal_force_n,
                        0.8e-3,
                        sl.rolling_speed_m_s,
                        sl.sliding_speed_m_s,
                    );
                }
            }
            batch.evaluate(&mixed);
            batch.coefficient(17)
        })
    });

    let point = TractionModel::muraki(pao.clone()).unwrap();
    let e = 210e9 / 0.91;
    let ball = ContactState {
        normal_force_n: 35.0,
        geometry: ContactGeometry::Circular,
        reduced_radius_m: 0.0095,
        reduced_modulus_pa: e,
        rolling_speed_m_s: 2.5,
        sliding_speed_m_s: 0.1,
        temperature_k: 313.15,
        roughness_ra_m: [0.0; 2],
        film_thickness_m: None,
    };
    c.bench_function("traction/point_muraki_pao1_film_2_19", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let mut s = ball;
            s.sliding_speed_m_s = 0.01 + (k % 64) as f64 * 0.01;
            traction(black_box(&s), black_box(&point))
        })
    });

    let given_film = ContactState {
        film_thickness_m: Some(0.5e-6),
        ..st
    };
    c.bench_function("traction/line_muraki_mixed_pao1_film_given", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let mut s = given_film;
            s.sliding_speed_m_s = 0.01 + (k % 64) as f64 * 0.02;
            traction(black_box(&s), black_box(&mixed))
        })
    });

    let nvi = TractionModel::lubricated(
        lubricant_by_name("nvi65").unwrap(),
        MurakiSettings {
            rheology: Rheology::LinearElastic { cap: 0.1 },
            ..Default::default()
        },
    )
    .unwrap();
    let st_nvi = ContactState {
        temperature_k: 273.15 + 50.0,
        rolling_speed_m_s: 3.0,
        ..slice_state(50.0)
    };
    c.bench_function("traction/line_elastic_mixed_nvi65", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let mut s = st_nvi;
            s.sliding_speed_m_s = 1e-4 + (k % 64) as f64 * 1e-4;
            traction(black_box(&s), black_box(&nvi))
        })
    });

    let q = TractionModel::new(TractionConfig {
        oil: Some(pao),
        law: FrictionLaw::Seed001(Seed001Settings::default()),
        ..TractionConfig::default()
    })
    .unwrap();
    c.bench_function("traction/line_seed001_flash_iteration_pao1", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let mut s = st;
            s.sliding_speed_m_s = 0.01 + (k % 64) as f64 * 0.02;
            traction(black_box(&s), black_box(&q))
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
