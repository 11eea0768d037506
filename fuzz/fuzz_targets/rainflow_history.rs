//! Rainflow history files (`rolldyn rainflow`): reading a history and counting its cycles must
//! not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    for column in [None, Some("stress")] {
        if let Ok(history) = rolldyn_fatigue::read_history_csv(text, column) {
            let _ = rolldyn_fatigue::rainflow(&history, rolldyn_fatigue::HistoryKind::NonPeriodic);
        }
    }
});
