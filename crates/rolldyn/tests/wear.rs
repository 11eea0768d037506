//! The wear analysis through `rolldyn::run_json`: a two-period life of the embedded model from
//! a request with unit strings, a stop request after the first period, an unknown field.

use rolldyn::{Context, Failure, ModelSource, Observer, Progress, Unobserved, run_json};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The answer's summary, parsed.
fn summary(answer: &rolldyn::Answer) -> serde_json::Value {
    serde_json::from_str(&answer.summary).expect("the summary is JSON")
}

fn scratch(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("rolldyn-lib-wear-{name}-{}", std::process::id()))
}

fn request(out: &std::path::Path) -> serde_json::Value {
    serde_json::json!({
        "life": "2 h",
        "period": "1h",
        "revolutions": 1,
        "settle": 1,
        "operating": {"radial_load": "1.6 kN"},
        "out": out,
    })
}

#[test]
fn a_two_period_life_from_unit_strings() {
    let out = scratch("life");
    let context = Context::new(ModelSource::Embedded, &Unobserved);
    let answer = run_json("wear", &request(&out).to_string(), &context).unwrap();
    assert_eq!(summary(&answer)["life_h"], 2.0);
    assert_eq!(summary(&answer)["periods"].as_array().unwrap().len(), 2);
    assert!(summary(&answer)["max_depth_m"]["roller"].as_f64().unwrap() > 0.0);
    assert_eq!(answer.tables[0].name, "periods");
    assert_eq!(answer.tables[0].rows(), 2);
    assert!(out.join("run.json").is_file() && out.join("worn.toml").is_file());
    std::fs::remove_dir_all(out).ok();
}

/// Stops after the first period it sees.
#[derive(Default)]
struct StopAfterOnePeriod {
    periods: AtomicUsize,
}

impl Observer for StopAfterOnePeriod {
    fn progress(&self, progress: &Progress) {
        assert_eq!(progress.unit, "h");
        self.periods.fetch_add(1, Ordering::SeqCst);
    }
    fn stop_requested(&self) -> bool {
        self.periods.load(Ordering::SeqCst) >= 1
    }
}

#[test]
fn a_stop_request_ends_the_life_after_the_period() {
    let out = scratch("stop");
    let observer = StopAfterOnePeriod::default();
    let context = Context::new(ModelSource::Embedded, &observer);
    let Err(Failure::Run(message)) = run_json("wear", &request(&out).to_string(), &context) else {
        panic!("an interrupted life is a failed run")
    };
    assert!(message.contains("interrupted after 1 periods"), "{message}");
    assert!(
        out.join("periods.csv").is_file(),
        "the first period is kept"
    );
    std::fs::remove_dir_all(out).ok();
}

#[test]
fn an_unknown_field_is_refused_by_name() {
    let Err(Failure::Input(message)) = run_json("wear", r#"{"lief": "2 h"}"#, &Context::default())
    else {
        panic!("an unknown field is bad input")
    };
    assert!(message.contains("lief"), "{message}");
}
