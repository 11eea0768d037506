//! Model files: `rolldyn_model::parse` must return a model or an error, never panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = rolldyn_model::parse(text, "fuzz.toml");
});
