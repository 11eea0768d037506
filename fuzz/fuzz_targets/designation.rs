//! Designations (`rolldyn new NU2215`): parsing one and designing its bearing must not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = rolldyn::run_json(
        "new",
        &serde_json::json!({ "designation": text }).to_string(),
        &rolldyn::Context::default(),
    );
});
