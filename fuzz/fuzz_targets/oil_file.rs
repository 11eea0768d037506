//! Oil files (`--oil-file`, `lubricant.file`): parsing, unit conversion and validation of a
//! lubricant must not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = rolldyn_model::parse_oil_file(text, "fuzz.toml");
});
