//! Checkpoints: restoring arbitrary bytes into a simulation of the default model must be
//! rejected or accepted, never panic. One simulation is set up once and restored into again
//! and again (setting it up per input would cost seconds).
#![no_main]

use rolldyn_dynamics::Simulation;
use std::sync::{Mutex, OnceLock};

fn simulation() -> &'static Mutex<Simulation> {
    static SIMULATION: OnceLock<Mutex<Simulation>> = OnceLock::new();
    SIMULATION.get_or_init(|| {
        let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml")
            .expect("default model");
        let (simulation, ..) =
            rolldyn_setup::prepare(&model, &rolldyn_setup::Overrides::default(), 1e-4, None)
                .expect("the default model sets up");
        Mutex::new(simulation)
    })
}

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let mut simulation = simulation().lock().unwrap_or_else(|e| e.into_inner());
    let _ = simulation.restore(bytes);
});
