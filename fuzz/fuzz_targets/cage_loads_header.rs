//! Cage-load export headers (`fatigue --loads`, the JSON beside the Parquet table): reading one
//! must not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = serde_json::from_str::<rolldyn_fatigue::CageLoadExport>(text);
});
