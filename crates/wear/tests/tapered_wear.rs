//! Wear of the tapered cassette bearing from its dynamics (SPEC §6.8 V-23…V-25). The short test
//! runs a 1 ms window; the validation runs are `#[ignore]`d (minutes of wall time), reproduce
//! them with (the workspace's test profile is optimised)
//!     cargo test -p rolldyn-wear --test tapered_wear -- --ignored --nocapture <name>
//! and their measured results are in VALIDATION.md "Tapered wear (V-23…V-25)".

use rolldyn_dynamics::tapered::{
    ContactRecorder, RollerContacts, TaperedModel, TaperedRunSettings, TaperedSample, run_recorded,
};
use rolldyn_setup::Overrides;
use rolldyn_wear::WearMethod;
use rolldyn_wear::tapered::{
    TaperedLife, TaperedWearSettings, WindowRates, run_tapered_life, tapered_rates,
};
use rolldyn_wear::wear_line::slice_patch;
use std::path::Path;

const HOUR: f64 = 3600.0;

fn cassette(overrides: &Overrides) -> TaperedModel {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/tapered-cassette.toml");
    let model = rolldyn_model::load(&path).unwrap();
    rolldyn_setup::prepare_tapered(&model, overrides).unwrap()
}

/// Seed 000 §3.2.3: "the dynamics was computed at an inner-ring speed of 387 rpm".
fn at_387_rpm() -> Overrides {
    Overrides {
        speed: Some(387.0 * std::f64::consts::TAU / 60.0),
        ..Overrides::default()
    }
}

fn um(x: f64) -> f64 {
    x * 1e6
}

fn print_window(label: &str, w: &WindowRates) {
    let d = &w.diagnostics;
    println!("== {label}: wall {:.1} s, {} steps", w.wall_s, w.steps);
    for (name, c, change) in [
        ("cone", &d.contacts[0], d.half_window_change[0]),
        ("cup", &d.contacts[1], d.half_window_change[1]),
        ("rib", &d.contacts[2], d.half_window_change[2]),
    ] {
        println!(
            "  {name}: Q_e {:.1} N, v̄ {:.4e} m/s, contact fraction {:.3}, Λ̄ {:.3}, boundary \
             {:.3}; half-window change Q_e {:+.2e}, v̄ {:+.2e}",
            c.equivalent_force_n,
            c.mean_sliding_speed_m_s,
            c.contact_fraction,
            c.mean_lambda,
            c.boundary_fraction,
            change.0,
            change.1
        );
    }
    println!(
        "  yaw max/mean {:.4}°/{:.4}°, pitch max/mean {:.4}°/{:.4}°, rib force mean/max {:.1}/{:.1} N, cage {:.3} rad/s",
        d.yaw_max_rad.to_degrees(),
        d.yaw_mean_rad.to_degrees(),
        d.pitch_max_rad.to_degrees(),
        d.pitch_mean_rad.to_degrees(),
        d.rib_force_mean_n,
        d.rib_force_max_n,
        d.cage_speed_rad_s
    );
    let line = w.direct.max_pressure_line();
    for (method, r) in [("direct", &w.direct), ("averaged", &w.averaged)] {
        println!(
            "  {method}: end/rib in contact {:.3e}/{:.3e} m/s, surface {:.3e}/{:.3e} m/s; cone \
             line {} (max pressure {:.3e} Pa) in contact {:.3e} m/s",
            r.end_in_contact,
            r.rib_in_contact,
            r.roller_end,
            r.rib,
            line + 1,
            r.cone_pressure_pa[line],
            r.cone_in_contact[line]
        );
        let fmt = |v: &[f64]| {
            v.iter()
                .map(|x| format!("{x:.3e}"))
                .collect::<Vec<_>>()
                .join(" ")
        };
        println!("    roller {}", fmt(&r.roller));
        println!("    cone   {}", fmt(&r.cone));
        println!("    cup    {}", fmt(&r.cup));
        let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
        println!(
            "    cone/roller {:.3}, cup/cone {:.3e}",
            max(&r.cone) / max(&r.roller),
            max(&r.cup) / max(&r.cone)
        );
    }
}

fn print_life(label: &str, life: &TaperedLife) {
    println!(
        "== {label}: {} periods, {:.0} h",
        life.periods.len(),
        life.life_h
    );
    println!(
        "period | time h | roller max µm | cone max µm | end µm | rib µm | roller rates per line (m/s)"
    );
    for p in &life.periods {
        let max = |v: &[(f64, f64)]| v.iter().map(|x| x.1).fold(0.0, f64::max);
        let r = &p.rates.averaged;
        println!(
            "{} | {:.0} | {:.4} | {:.4} | {:.4} | {:.4} | {}",
            p.index,
            p.time_h,
            um(max(&p.wear.roller)),
            um(max(&p.wear.cone)),
            um(p.wear.large_end),
            um(p.wear.large_rib),
            r.roller
                .iter()
                .map(|x| format!("{x:.3e}"))
                .collect::<Vec<_>>()
                .join(" ")
        );
        print_window(&format!("period {}", p.index), &p.rates);
    }
    print_window("end of life", &life.last_window);
}

#[test]
fn a_short_window_wears_every_surface_by_both_methods() {
    let settings = TaperedWearSettings {
        settle_s: 5e-4,
        window_s: 1e-3,
        ..TaperedWearSettings::default()
    };
    let base = cassette(&Overrides::default());
    let w = tapered_rates(&base, &Default::default(), &settings).unwrap();
    print_window("1 ms", &w);
    for r in [&w.direct, &w.averaged] {
        assert_eq!(r.roller.len(), 9);
        let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
        assert!(max(&r.roller) > 0.0 && max(&r.cone) > 0.0, "{r:?}");
        assert!(r.roller_end > 0.0 && r.rib > 0.0, "{r:?}");
        assert!(r.roller.iter().chain(&r.cone).all(|x| x.is_finite()));
    }
    // the averaged method reproduces the direct raceway rates on the max-pressure line to
    // within a factor (Hertz-like contact, seed 000 §3.2.3)
    let line = w.direct.max_pressure_line();
    let ratio = w.averaged.cone_in_contact[line] / w.direct.cone_in_contact[line];
    assert!((0.3..3.0).contains(&ratio), "{ratio}");
}

#[test]
#[ignore = "validation run: 2 dynamics windows, about 10 minutes of wall time"]
fn v23_v24_initial_rates() {
    let settings = TaperedWearSettings::default();
    for (label, overrides) in [
        ("663 rpm (load case 1)", Overrides::default()),
        ("387 rpm (seed 000 §3.2.3)", at_387_rpm()),
    ] {
        let w = tapered_rates(&cassette(&overrides), &Default::default(), &settings).unwrap();
        print_window(label, &w);
    }
}

/// Writes the tables and plots of `life` into docs/validation/tapered-wear/`name`.
fn write_report(name: &str, life: &TaperedLife, method: WearMethod) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs/validation/tapered-wear")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    rolldyn_wear::tapered::write_tapered_report(&dir, life, method).unwrap();
}

/// V-24 stability: the averaged method (seed 000 §3.2.3 continues with it) at 387 rpm with a
/// fixed period, 11 430 h.
fn v24_period(period_h: f64) {
    let settings = TaperedWearSettings {
        period_s: period_h * HOUR,
        life_s: 11_430.0 * HOUR,
        method: WearMethod::Averaged,
        ..TaperedWearSettings::default()
    };
    let life = run_tapered_life(&cassette(&at_387_rpm()), &settings, &mut |p| {
        println!("period {} done at {:.0} h", p.index, p.time_h);
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    print_life(&format!("period {period_h} h"), &life);
    write_report(&format!("v24-period-{period_h}h"), &life, settings.method);
}

#[test]
#[ignore = "validation run: 4 dynamics windows, about 20 minutes of wall time"]
fn v24_period_3810h() {
    v24_period(3810.0);
}

#[test]
#[ignore = "validation run: 7 dynamics windows, about 35 minutes of wall time"]
fn v24_period_1905h() {
    v24_period(1905.0);
}

#[test]
#[ignore = "validation run: 7 dynamics windows, about 35 minutes of wall time"]
fn v25_misalignment_4_arcmin() {
    let overrides = Overrides {
        misalignment: Some((4.0_f64 / 60.0).to_radians()),
        ..Overrides::default()
    };
    let settings = TaperedWearSettings::default();
    let life = run_tapered_life(&cassette(&overrides), &settings, &mut |p| {
        println!("period {} done at {:.0} h", p.index, p.time_h);
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    print_life("4′, 11 429 h", &life);
    write_report("v25-misalignment-4arcmin", &life, settings.method);
}

/// V-25 with one period over the whole 11 429 h: the unworn and the worn window only (the
/// shortest run that answers V-25; the wear of 11 429 h is applied at once).
#[test]
#[ignore = "validation run: 2 dynamics windows, about 15 minutes of wall time"]
fn v25_misalignment_4_arcmin_one_period() {
    let overrides = Overrides {
        misalignment: Some((4.0_f64 / 60.0).to_radians()),
        ..Overrides::default()
    };
    let settings = TaperedWearSettings {
        period_s: 11_429.0 * HOUR,
        ..TaperedWearSettings::default()
    };
    let life = run_tapered_life(&cassette(&overrides), &settings, &mut |p| {
        print_window(&format!("period {} (unworn)", p.index), &p.rates);
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    print_life("4′, 11 429 h in one period", &life);
    write_report(
        "v25-misalignment-4arcmin-one-period",
        &life,
        settings.method,
    );
}

#[test]
fn one_period_writes_the_tables_and_plots() {
    let settings = TaperedWearSettings {
        settle_s: 2e-4,
        window_s: 4e-4,
        life_s: 1000.0 * HOUR,
        period_s: 1000.0 * HOUR,
        ..TaperedWearSettings::default()
    };
    let life = run_tapered_life(&cassette(&Overrides::default()), &settings, &mut |_| {
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(life.periods.len(), 1);
    let wear = &life.periods[0].wear;
    assert_eq!(wear.roller.len(), 9);
    assert!(wear.large_end > 0.0 && wear.large_rib > 0.0);
    let dir = std::env::temp_dir().join(format!("rolldyn-tapered-wear-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plots = rolldyn_wear::tapered::write_tapered_report(&dir, &life, settings.method).unwrap();
    assert_eq!(plots.len(), 5);
    let windows = std::fs::read_to_string(dir.join("tapered-windows.csv")).unwrap();
    assert_eq!(windows.lines().count(), 3, "{windows}");
    let lines = std::fs::read_to_string(dir.join("tapered-lines.csv")).unwrap();
    assert_eq!(lines.lines().count(), 10);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The last recorded step's contacts.
struct LastStep(Vec<RollerContacts>);

impl ContactRecorder for LastStep {
    fn record(&mut self, _: &TaperedSample, rollers: &[RollerContacts]) {
        self.0 = rollers.to_vec();
    }
}

#[test]
fn the_recorded_half_widths_are_those_of_the_wear_lines() {
    // the dynamics' traction half-width of every loaded slice equals the wear line's Hertz
    // half-width (docs/theory.md §8.5) at the recorded force and reduced radius
    let model = cassette(&Overrides::default());
    let settings = TaperedRunSettings {
        duration_s: 6e-4,
        sample_interval_s: 6e-4,
        ..TaperedRunSettings::default()
    };
    let mut last = LastStep(Vec::new());
    run_recorded(&model, &settings, Some(&mut last), |_| {
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    let lengths = model.bearing().roller.slices().length;
    let mut loaded = 0;
    for roller in &last.0 {
        for c in [&roller.cone, &roller.cup] {
            for (s, &length) in lengths.iter().enumerate() {
                if c.force_n[s] > 0.0 {
                    loaded += 1;
                    let patch = slice_patch(
                        c.force_n[s],
                        length,
                        c.reduced_radius_m[s],
                        model.reduced_modulus(),
                    );
                    let b = c.half_width_m[s];
                    assert!((patch.half_width_m / b - 1.0).abs() < 1e-9, "{b} {patch:?}");
                    assert!(c.lambda[s] > 0.0 && c.ring_radius_m[s] > 0.05);
                }
            }
        }
    }
    assert!(loaded > 50, "{loaded}");
}
