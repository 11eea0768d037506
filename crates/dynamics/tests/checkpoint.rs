#![allow(clippy::field_reassign_with_default, clippy::needless_range_loop)]
//! Checkpoint / resume: a run interrupted at t₁, serialised, restored into a freshly built
//! simulation and continued to t₂ is bit-for-bit equal to an uninterrupted run (state vector,
//! statistics, summary, samples).

mod common;
use common::*;
use rolldyn_dynamics::*;

struct Hash(u64, usize);
impl OutputSink for Hash {
    fn sample(&mut self, t: f64, s: &Snapshot) {
        for x in [t, s.cage_speed_rad_s]
            .iter()
            .chain(s.rollers.inner.force_n)
            .chain(s.rollers.cage_bar_force_n)
        {
            self.0 = (self.0 ^ x.to_bits()).wrapping_mul(0x100000001b3);
        }
        self.1 += 1;
    }
}

fn build() -> Simulation {
    build_with(IntegratorMethod::Dopri5)
}

fn build_with(method: IntegratorMethod) -> Simulation {
    let mut b = bearing("obrien-taylor");
    b.roller.slice_count = 4;
    let cond = OperatingConditions::new(rpm(4000.0), 300.0);
    let params = ContactParameters::for_bearing(&b);
    let mut set = DynamicsSettings::default();
    set.output_step_s = 1e-4;
    set.integrator.method = method;
    if method == IntegratorMethod::RosenbrockW {
        set.integrator.tolerance = 1e-4;
        // short interval so that the resume point falls inside a Jacobian reuse cycle
        set.integrator.jacobian_interval = 7;
    }
    Simulation::new(
        &b,
        cond,
        params,
        set,
        // NVI 65 with the elastic term of (1.4) only, as V-06
        RacewayTraction::same(
            rolldyn_lubrication::TractionModel::lubricated(
                rolldyn_lubrication::lubricant_by_name("nvi65").unwrap(),
                rolldyn_lubrication::MurakiSettings {
                    rheology: rolldyn_lubrication::Rheology::LinearElastic { cap: 0.1 },
                    ..Default::default()
                },
            )
            .unwrap(),
        ),
    )
    .unwrap()
}

#[test]
fn resume_from_checkpoint_is_bit_for_bit() {
    resume(IntegratorMethod::Dopri5);
}

/// Same for the Rosenbrock-W method: the stale Jacobian, its age and the Hermite dense output
/// are part of the checkpoint (the LU factors are rebuilt from them).
#[test]
fn resume_from_checkpoint_is_bit_for_bit_rosenbrock_w() {
    resume(IntegratorMethod::RosenbrockW);
    // a checkpoint of one method is refused by a simulation using the other (with the same
    // settings otherwise: they are part of the checkpoint's set-up)
    let mut a = build_with(IntegratorMethod::RosenbrockW);
    a.run_until(5e-4, &mut NullSink, &mut |_| {}).unwrap();
    let mut d = build_with(IntegratorMethod::RosenbrockW);
    d.set_integrator_method(IntegratorMethod::Dopri5);
    assert!(matches!(
        d.restore(&a.checkpoint()),
        Err(DynError::Checkpoint(_))
    ));
    // switching to the checkpoint's method (the CLI's `--integrator`) makes it acceptable
    d.set_integrator_method(IntegratorMethod::RosenbrockW);
    d.restore(&a.checkpoint()).unwrap();
    assert_eq!(d.time().to_bits(), a.time().to_bits());
}

fn resume(method: IntegratorMethod) {
    let build = || build_with(method);
    let (t1, t2) = (2.05e-3, 4e-3);
    let mut a = build();
    let mut ha = Hash(0, 0);
    a.run_until(t1, &mut ha, &mut |_| {}).unwrap();
    let sa = a.run_until(t2, &mut ha, &mut |_| {}).unwrap();

    let mut b1 = build();
    let mut hb = Hash(0, 0);
    b1.run_until(t1, &mut hb, &mut |_| {}).unwrap();
    let bytes = b1.checkpoint();
    drop(b1);
    let mut b2 = build();
    b2.restore(&bytes).unwrap();
    let sb = b2.run_until(t2, &mut hb, &mut |_| {}).unwrap();

    assert_eq!(a.time().to_bits(), b2.time().to_bits());
    assert!(
        a.state()
            .iter()
            .zip(b2.state())
            .all(|(x, y)| x.to_bits() == y.to_bits()),
        "state differs"
    );
    assert_eq!((ha.0, ha.1), (hb.0, hb.1), "samples differ");
    assert_eq!(sa.steps, sb.steps);
    assert_eq!(sa.rhs_evaluations, sb.rhs_evaluations);
    assert_eq!(
        a.stats().jacobian_evaluations,
        b2.stats().jacobian_evaluations
    );
    assert_eq!(
        sa.max_roller_cage_force_n.to_bits(),
        sb.max_roller_cage_force_n.to_bits()
    );
    assert_eq!(sa.cage_slip_mean.to_bits(), sb.cage_slip_mean.to_bits());
    // a checkpoint of another bearing is refused
    let mut other = bearing("2002834");
    other.roller.slice_count = 3;
    let mut o = Simulation::new(
        &other,
        OperatingConditions::new(100.0, 100.0),
        ContactParameters::for_bearing(&other),
        DynamicsSettings::default(),
        RacewayTraction::same(pao()),
    )
    .unwrap();
    assert!(matches!(o.restore(&bytes), Err(DynError::Checkpoint(_))));
    assert!(matches!(
        o.restore(&bytes[..20]),
        Err(DynError::Checkpoint(_))
    ));
}

/// A checkpoint carries a format version and a checksum: a flipped byte, a truncated file or
/// another format version is refused with a reason (not restored into different results).
#[test]
fn damaged_or_foreign_checkpoint_is_refused() {
    let mut a = build();
    a.run_until(3e-4, &mut NullSink, &mut |_| {}).unwrap();
    let bytes = a.checkpoint();
    let refusal = |bytes: &[u8]| match build().restore(bytes) {
        Err(DynError::Checkpoint(reason)) => reason,
        other => panic!("restored: {other:?}"),
    };
    for k in [8, 20, bytes.len() / 2, bytes.len() - 9, bytes.len() - 1] {
        let mut flipped = bytes.clone();
        flipped[k] ^= 0x01;
        let reason = refusal(&flipped);
        assert!(
            reason.contains("damaged") || reason.contains("format version"),
            "byte {k}: {reason}"
        );
    }
    assert!(refusal(&bytes[..bytes.len() - 1]).contains("damaged"));
    assert!(refusal(b"[bearing]\nname = \"x\"\n").contains("not a rolldyn"));
    let mut older = bytes.clone();
    older[6..8].copy_from_slice(b"05");
    assert!(refusal(&older).contains("format version 05"));
    build().restore(&bytes).unwrap();
}

/// The caller's note travels with the checkpoint.
#[test]
fn checkpoint_note_is_given_back() {
    let mut a = build();
    a.run_until(2e-4, &mut NullSink, &mut |_| {}).unwrap();
    assert_eq!(
        build().restore(&a.checkpoint_with(b"tables")).unwrap(),
        b"tables"
    );
    assert!(build().restore(&a.checkpoint()).unwrap().is_empty());
}
