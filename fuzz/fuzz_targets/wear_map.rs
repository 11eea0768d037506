//! Raceway wear maps (`raceway_wear.file`): `read_raceway_wear_csv` returns a map or an error,
//! never panics.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = rolldyn_model::read_raceway_wear_csv(text);
});
