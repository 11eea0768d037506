//! Checkpoints: restoring arbitrary bytes into a simulation of the default model must be
//! rejected or accepted, never panic.
#![no_main]

use rolldyn_dynamics::Simulation;
use std::sync::OnceLock;

fn simulation() -> Simulation {
    static MODEL: OnceLock<rolldyn_model::Model> = OnceLock::new();
    let model = MODEL.get_or_init(|| {
        rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").expect("default model")
    });
    rolldyn_setup::prepare(model, &rolldyn_setup::Overrides::default(), 1e-4, None)
        .expect("the default model sets up")
        .0
}

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let mut sim = simulation();
    let _ = sim.restore(bytes);
});
