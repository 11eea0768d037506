//! `rolldyn demo`: the most complete analysis available, on the embedded default model
//! (bearing 2002834, SPEC §1.6 a / F-02): geometry check, then the inner-raceway roller
//! contact by Hertz, slices and Boussinesq at three roller loads and three tilts.

use super::check::{describe, summarise};
use super::contact::{LawName, Method, solve};
use crate::failure::Failure;
use crate::output::{load_model, out_dir, print_json};
use rolldyn_contact::roller_raceway::RollerRacewayContact;
use rolldyn_units::{ARCMIN, RPM};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
    /// Also write the contact plots and CSV files of the Boussinesq solutions to this folder.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Seed 000 Fig. 3.1 operating speed of 2002834.
const SPEED_RPM: f64 = 6371.0;
const LOADS_N: [f64; 3] = [500.0, 1000.0, 2000.0];
const TILTS_ARCMIN: [f64; 3] = [0.0, 4.0, 8.0];
const CELLS: (usize, usize) = (150, 9);

pub fn run(args: Args) -> Result<(), Failure> {
    let model = load_model(None)?.bearing;
    let summary = summarise(&model, SPEED_RPM * RPM, 0.0);
    if !args.json {
        describe(&summary).iter().for_each(|l| println!("{l}"));
        println!(
            "\nInner-raceway roller contact (Boussinesq grid {}×{} over the roller length × 0.4 mm):",
            CELLS.0, CELLS.1
        );
    }
    let mut rows = Vec::new();
    for tilt in TILTS_ARCMIN {
        let contact = RollerRacewayContact::from_model(&model, true, tilt * ARCMIN)
            .map_err(|e| Failure::Run(e.to_string()))?;
        for load in LOADS_N {
            for method in [Method::Hertz, Method::Slices, Method::Boussinesq] {
                let report = solve(&contact, method, load, CELLS, Some(0.4e-3), LawName::Seed)?;
                if let (Some(dir), Method::Boussinesq) = (&args.out, method) {
                    let dir = out_dir(&dir.join(format!("{load:.0}N-{tilt:.0}arcmin")))?;
                    super::contact::write_outputs(&dir, &report)?;
                }
                rows.push(super::contact::to_json(model.name(), &report, Some(CELLS)));
                if !args.json {
                    print_row(tilt, load, &report);
                }
            }
        }
    }
    if args.json {
        return print_json(&serde_json::json!({ "model": summary, "inner_raceway_contact": rows }));
    }
    Ok(())
}

fn print_row(tilt: f64, load: f64, r: &rolldyn_contact::roller_raceway::ContactReport) {
    if r.method == rolldyn_contact::roller_raceway::ContactMethod::Hertz && load == LOADS_N[0] {
        println!(
            "\n  tilt {tilt:.0}′  {:>7} {:>10} {:>11} {:>11} {:>10} {:>8} {:>9}",
            "load N", "method", "approach µm", "p_max MPa", "p_mid MPa", "K_conc", "time ms"
        );
    }
    println!(
        "          {:>7.0} {:>10} {:>11.3} {:>11.0} {:>10.0} {:>8.3} {:>9.2}",
        load,
        r.method.name(),
        r.approach_m * 1e6,
        r.max_pressure_pa * 1e-6,
        r.mid_pressure_pa * 1e-6,
        r.concentration_factor,
        r.solve_time_s * 1e3
    );
}
