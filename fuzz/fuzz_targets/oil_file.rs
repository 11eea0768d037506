//! Oil files (`--oil-file`, `lubricant.file`): deserialising and validating a lubricant must
//! not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let Ok(oil) = toml::from_str::<rolldyn_lubrication::Lubricant>(text) {
        let _ = oil.validate();
    }
});
