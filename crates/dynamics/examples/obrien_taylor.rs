//! Runs the O'Brien–Taylor cage-slip study (SPEC V-06) and prints one line per point.
//!
//! `cargo run --release -p rolldyn-dynamics --example obrien_taylor -- [slices] [speeds,…] [loads,…]`
//! (defaults: the model's slices, the full study of [`rolldyn_dynamics::study::StudySettings`]).

use rolldyn_dynamics::study::{StudySettings, obrien_taylor};

fn list(s: Option<&String>) -> Option<Vec<f64>> {
    s.map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/obrien-taylor.toml"
    );
    let rolldyn_model::BearingModel::Cylindrical(b) =
        rolldyn_model::load(std::path::Path::new(path))
            .expect("O'Brien–Taylor model")
            .bearing
    else {
        panic!("not a bearing")
    };
    let mut set = StudySettings {
        slices: args.get(1).and_then(|s| s.parse().ok()),
        ..StudySettings::default()
    };
    if let Some(v) = list(args.get(2)) {
        set.speeds_rpm = v;
    }
    if let Some(v) = list(args.get(3)) {
        set.loads_n = v;
    }
    if args.len() > 2 {
        set.misalignments_rad.clear();
    }
    set.dynamics.output_step_s = 0.0;
    set.dynamics.scuffing_check = false;
    println!("rpm\tload_N\tmis_rad\tT_C\tcage_slip\trevs\tsteady\twindow_s\tmax_srr\twall_s");
    obrien_taylor(&b, &set, &mut |p| {
        println!(
            "{}\t{}\t{:.5}\t{:.1}\t{:.6}\t{}\t{}\t{:.4}\t{:.4}\t{:.1}",
            p.speed_rpm,
            p.radial_load_n,
            p.misalignment_rad,
            p.temperature_k - 273.15,
            p.cage_slip,
            p.revolutions_averaged,
            p.steady,
            p.window_start_s,
            p.summary.max_relative_slip,
            p.summary.wall_time_s
        );
    })
    .expect("study");
}
