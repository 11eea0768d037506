//! The coupled Rosenbrock-W Jacobian of the tapered bearing (the roller blocks, each roller's
//! coupling with its cage and the inner ring from the coloured differences and the rollers'
//! shares of the cage and ring rates) against its test oracle: the dense column-by-column
//! forward-difference Jacobian of the whole right-hand side.

use rolldyn_dynamics::tapered::{TaperedModel, TaperedRunSettings, TaperedSimulation};
use rolldyn_setup::Overrides;
use std::ops::ControlFlow;
use std::path::Path;

fn cassette() -> TaperedModel {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/tapered-cassette.toml");
    let model = rolldyn_model::load(&path).unwrap();
    rolldyn_setup::prepare_tapered(&model, &Overrides::default()).unwrap()
}

#[test]
fn coupled_jacobian_matches_the_dense_difference_jacobian() {
    let model = cassette();
    let settings = TaperedRunSettings::default();
    let mut sim = TaperedSimulation::new(&model, &settings, false);
    // 0.2 ms from the seated start: rollers loaded on both raceways and the large rib
    sim.run_until(2e-4, None, &mut |_| ControlFlow::Continue(()))
        .unwrap();
    let (coloured, dense) = sim.jacobian_against_oracle().unwrap();
    let n = (dense.len() as f64).sqrt() as usize;
    let (mut worst, mut at) = (0.0_f64, 0);
    let mut nonzero = 0;
    for r in 0..n {
        let row = &dense[r * n..(r + 1) * n];
        let row_scale = row.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for k in 0..n {
            let (a, d) = (coloured[r * n + k], row[k]);
            nonzero += usize::from(d != 0.0);
            let gap = (a - d).abs() / row_scale.max(f64::MIN_POSITIVE);
            if gap > worst {
                (worst, at) = (gap, r * n + k);
            }
        }
    }
    println!(
        "{nonzero} non-zero entries; worst gap {worst:.3e} of the row's largest entry at row {} column {}",
        at / n,
        at % n
    );
    assert!(worst < 1e-6, "worst gap {worst:.3e}");
}

#[test]
fn bordered_run_restored_from_a_checkpoint_is_the_same_run() {
    // the checkpoint carries the coupling blocks and the rollers' shares at the state
    let model = cassette();
    let settings = TaperedRunSettings::default();
    let mut go = |_| ControlFlow::Continue(());
    let mut whole = TaperedSimulation::new(&model, &settings, false);
    whole.run_until(3e-4, None, &mut go).unwrap();
    let mut first = TaperedSimulation::new(&model, &settings, false);
    first.run_until(1.5e-4, None, &mut go).unwrap();
    let bytes = first.checkpoint_with(b"");
    let mut resumed = TaperedSimulation::new(&model, &settings, false);
    resumed.restore(&bytes).unwrap();
    resumed.run_until(3e-4, None, &mut go).unwrap();
    let (a, b) = (whole.finish(), resumed.finish());
    assert_eq!(a.samples, b.samples);
    assert_eq!(
        (a.steps, a.rejected_steps, a.rhs_evaluations),
        (b.steps, b.rejected_steps, b.rhs_evaluations)
    );
}
