//! Release-mode timing harness: 2002834 (18 rollers × 10 slices, PAO VG 320 Muraki traction,
//! 500 N, cage drag 6.62e-4 N·m·s) at 6371 rpm.
//!
//! `cargo run --release -p rolldyn-dynamics --example speed -- [duration_s] [tolerance] [tilt_limit_rad] [pi_beta] [safety] [dopri5|rosw] [jacobian_interval]`
//! prints wall time, simulated/wall, step statistics and the run summary (`-` keeps a default).

use rolldyn_dynamics::*;
use rolldyn_lubrication::{TractionModel, lubricant_by_name};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dur: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0.03);
    let tol: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1e-6);
    let mut b = rolldyn_model::default_cylindrical_bearing();
    b.roller.slice_count = 10;
    let mut cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut set = DynamicsSettings {
        output_step_s: 0.0,
        ..DynamicsSettings::default()
    };
    set.integrator.tolerance = tol;
    if let Some(t) = args.get(3).and_then(|s| s.parse().ok()) {
        set.divergence_tilt_rad = t;
    }
    if let Some(bt) = args.get(4).and_then(|s| s.parse().ok()) {
        set.integrator.pi_beta = bt;
    }
    if let Some(sf) = args.get(5).and_then(|s| s.parse().ok()) {
        set.integrator.safety = sf;
    }
    if args.get(6).map(String::as_str) == Some("rosw") {
        set.integrator.method = IntegratorMethod::RosenbrockW;
    }
    if let Some(n) = args.get(7).and_then(|s| s.parse().ok()) {
        set.integrator.jacobian_interval = n;
    }
    let traction =
        TractionModel::muraki(lubricant_by_name("pao1-vg320").expect("oil")).expect("muraki");
    let mut s = Simulation::new(
        &b,
        cond,
        ContactParameters::for_bearing(&b),
        set,
        RacewayTraction::same(traction),
    )
    .expect("simulation");
    // run in 1 ms pieces (bit-identical to one call) and record the largest roller tilt
    let lay = s.layout();
    let mut max_tilt = 0.0_f64;
    let mut t = 0.0_f64;
    let r = loop {
        t = (t + 1e-3).min(dur);
        let r = s.run_until(t, &mut NullSink, &mut |_| {});
        for j in 0..lay.rollers {
            let b = lay.roller(j);
            let y = s.state();
            let a = &y[b + roller::AXIS..b + roller::AXIS + 3];
            max_tilt = max_tilt.max((a[0] * a[0] + a[1] * a[1]).sqrt().atan2(a[2]));
        }
        if r.is_err() || t >= dur {
            break r;
        }
    };
    println!("largest roller tilt at the 1 ms marks: {max_tilt:.5} rad");
    match r {
        Ok(r) => {
            println!(
                "{:?} tol {tol:e} dur {dur}: wall {:.3} s → simulated/wall {:.4}; {} steps ({} rejected), {} RHS, {} Jacobians, mean step {:.2} µs, RHS/step {:.2}, limiting {:?}",
                set.integrator.method,
                r.wall_time_s,
                r.simulated_time_s / r.wall_time_s,
                r.steps,
                r.rejected_steps,
                r.rhs_evaluations,
                s.stats().jacobian_evaluations,
                1e6 * r.simulated_time_s / r.steps as f64,
                r.rhs_evaluations as f64 / r.steps as f64,
                s.most_limiting_component()
            );
            println!(
                "slip {:.7} cage {:.4} fi {:.2} fo {:.2} bar {:.2} land {:.2} vs {:.4} srr {:.5}",
                r.cage_slip_mean,
                r.cage_speed_mean_rad_s,
                r.max_inner_contact_force_n,
                r.max_outer_contact_force_n,
                r.max_roller_cage_force_n,
                r.max_cage_land_force_n,
                r.max_inner_sliding_speed_m_s,
                r.max_relative_slip
            );
        }
        Err(e) => println!("error at t = {}: {e}", s.time()),
    }
}
