//! S–N curve files (`fatigue --sn-curve`): `SnCurve::from_csv_text` returns a curve or an error,
//! never panics, and a curve it returns answers every amplitude.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let Ok(curve) = rolldyn_fatigue::sn::SnCurve::from_csv_text(text) {
        for amplitude in [1e6, 1e8, 1e9] {
            assert!(!curve.cycles_to_failure(amplitude).is_nan());
        }
    }
});
