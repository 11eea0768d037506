//! Journal bearing files: `rolldyn_model::journal::parse_journal` must not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = rolldyn_model::journal::parse_journal(text, "fuzz.toml", 323.15);
});
