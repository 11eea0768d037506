//! The life loop end to end on the embedded 2002834 (short dynamics runs): periods, outputs,
//! worn model.

use rolldyn_setup::Overrides;
use rolldyn_wear::study::run_wear;
use rolldyn_wear::{PeriodControl, StopReason, Surface, WearSettings};

#[test]
fn two_periods_wear_every_surface_and_write_a_worn_model_that_loads() {
    let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
    let hour = 3600.0;
    let settings = WearSettings {
        life_s: 2000.0 * hour,
        period: PeriodControl::Fixed(1000.0 * hour),
        revolutions: 1,
        settle_revolutions: 1,
        ..WearSettings::default()
    };
    let dir = std::env::temp_dir().join(format!("rolldyn-wear-life-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut seen = Vec::new();
    let answer = run_wear(
        &model,
        &Overrides::default(),
        &settings,
        Some(&dir),
        false,
        &mut |p| {
            seen.push(p.time_h);
            std::ops::ControlFlow::Continue(())
        },
    )
    .unwrap();
    assert_eq!(seen, vec![1000.0, 2000.0]);
    assert_eq!(answer.stop, StopReason::LifeReached);
    assert!((answer.life_h - 2000.0).abs() < 1e-9);
    for s in [
        Surface::Roller,
        Surface::InnerRaceway,
        Surface::OuterRaceway,
        Surface::RollerEnd,
        Surface::Rib,
    ] {
        let d = answer.max_depth_m.get(s);
        assert!(d > 0.0 && d < 1e-3, "{}: {d}", s.name());
    }
    // depths only grow
    let first = &answer.periods[0].max_depth_m;
    assert!(
        Surface::ALL
            .iter()
            .all(|&s| answer.max_depth_m.get(s) >= first.get(s))
    );
    for f in [
        "periods.csv",
        "periods.parquet",
        "roller-profile.csv",
        "inner-raceway-map.csv",
        "rates.svg",
        "inner-raceway-map.svg",
        "worn.toml",
        "worn-inner-raceway.csv",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let worn = rolldyn_model::load(&dir.join("worn.toml")).unwrap();
    let rolldyn_geometry::BearingModel::Cylindrical(b) = &worn.bearing else {
        panic!()
    };
    let map = b.inner_ring.raceway_wear.as_ref().unwrap();
    assert!((map.max_depth() - answer.max_depth_m.get(Surface::InnerRaceway)).abs() < 1e-12);
    let json = serde_json::to_value(&answer).unwrap();
    for key in [
        "life_h",
        "periods",
        "max_depth_m",
        "clearance_increase_m",
        "wall_time_s",
    ] {
        assert!(json.get(key).is_some(), "{key}");
    }
    assert!(json["max_depth_m"].get("cage_bar").is_some());
    std::fs::remove_dir_all(&dir).ok();
}
