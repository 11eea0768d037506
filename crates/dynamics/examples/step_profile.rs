//! Which state components limit the step on the 2002834 benchmark case (the `cargo bench`
//! model): histogram of the limiting components, grouped by name.
//! `cargo run --release -p rolldyn-dynamics --example step_profile [duration_s] [tolerance]
//! [safety] [pi_beta] [dopri5|rosenbrock-w]` (the method name may stand anywhere; the
//! numbers keep their order; default DOPRI5)

use rolldyn_dynamics::*;
use rolldyn_lubrication::{TractionModel, lubricant_by_name};

fn main() {
    let method = |a: &str| match a {
        "dopri5" => Some(IntegratorMethod::Dopri5),
        "rosenbrock-w" => Some(IntegratorMethod::RosenbrockW),
        _ => None,
    };
    let (names, numbers): (Vec<String>, Vec<String>) =
        std::env::args().skip(1).partition(|a| method(a).is_some());
    let arg = |i: usize| numbers.get(i - 1).and_then(|a| a.parse::<f64>().ok());
    let duration = arg(1).unwrap_or(0.02);
    let b = rolldyn_model::default_cylindrical_bearing();
    let mut cond = OperatingConditions::new(6371.0 * std::f64::consts::TAU / 60.0, 500.0);
    cond.cage_drag_n_m_s = CAGE_DRAG_2002834_100C;
    let mut settings = DynamicsSettings {
        output_step_s: 0.0,
        ..DynamicsSettings::default()
    };
    if let Some(m) = names.last().and_then(|a| method(a)) {
        settings.integrator.method = m;
    }
    if let Some(tol) = arg(2) {
        settings.integrator.tolerance = tol;
    }
    if let Some(safety) = arg(3) {
        settings.integrator.safety = safety;
    }
    if let Some(beta) = arg(4) {
        settings.integrator.pi_beta = beta;
    }
    let traction = TractionModel::muraki(lubricant_by_name("pao1-vg320").expect("built-in oil"))
        .expect("valid oil");
    let mut sim = Simulation::new(
        &b,
        cond,
        ContactParameters::for_bearing(&b),
        settings,
        RacewayTraction::same(traction),
    )
    .expect("valid model");
    let wall = std::time::Instant::now();
    sim.run_until(duration, &mut NullSink, &mut |_| {})
        .expect("run completes");
    let wall = wall.elapsed().as_secs_f64();
    let stats = sim.stats();
    println!(
        "{:?}: simulated {duration} s in {wall:.3} s: ratio {:.4}; steps {} rejected {} rhs {} → {:.1} µs/rhs, mean step {:.2} µs",
        settings.integrator.method,
        duration / wall,
        stats.accepted,
        stats.rejected,
        stats.rhs_evaluations,
        wall / stats.rhs_evaluations as f64 * 1e6,
        duration / stats.accepted as f64 * 1e6
    );
    let v = sim.step_limits();
    for (name, c) in v.iter().take(12) {
        println!("{c:8}  {name}");
    }
}
