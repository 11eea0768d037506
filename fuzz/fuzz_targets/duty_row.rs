//! Duty-cycle rows (`rolldyn life --duty time=0.3,speed=5000rpm,radial-load=15kN`): parsing a
//! row and rating the embedded model with it must not panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let Ok(row) = text.parse::<rolldyn::life::DutyRow>() {
        let request = rolldyn::life::LifeRequest {
            duty: vec![row],
            ..Default::default()
        };
        let _ = <rolldyn::life::Life as rolldyn::Analysis>::run(
            &request,
            &rolldyn::Context::default(),
        );
    }
});
