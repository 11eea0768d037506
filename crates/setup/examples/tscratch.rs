use rolldyn_dynamics::tapered::*;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let model = rolldyn_model::load(std::path::Path::new(&a[1])).unwrap();
    let mut ov = rolldyn_setup::Overrides::default();
    ov.radial_load = a.get(2).map(|s| s.parse().unwrap());
    ov.axial_load = a.get(3).map(|s| s.parse().unwrap());
    let mut m = rolldyn_setup::prepare_tapered(&model, &ov).unwrap();
    let dur: f64 = a.get(4).map_or(0.0005, |s| s.parse().unwrap());
    let mut set = TaperedRunSettings {
        duration_s: dur,
        ..Default::default()
    };
    if let Some(t) = a.get(5) {
        set.integrator.tolerance = t.parse().unwrap();
    }
    if let Some(j) = a.get(6) {
        if !j.is_empty() {
            set.integrator.method = rolldyn_dynamics::settings::IntegratorMethod::RosenbrockW;
            set.integrator.jacobian_interval = j.parse().unwrap();
        }
    }
    if let Some(x) = a.get(7) {
        if x == "boundary" {
            m.parameters.end_rib.friction = rolldyn_dynamics::EndFriction::Boundary;
        }
    }
    eprintln!("{:?}", m.traction_model());
    let t0 = std::time::Instant::now();
    let r = run(&m, &set, |_| {}).unwrap();
    println!(
        "steps {} rhs {} wall {:.1}s limit {:?}",
        r.steps,
        r.rhs_evaluations,
        t0.elapsed().as_secs_f64(),
        r.most_limiting
    );
}
