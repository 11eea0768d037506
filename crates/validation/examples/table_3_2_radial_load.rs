//! The radial load of seed 000 Table 3.2 bounded through the load distribution (issue 23).
//!
//! Seed 000 does not give the radial load of its 2002834 runs. Its Table 3.2 does give, per
//! variant, the largest roller force on the inner ring over a steady revolution. For each variant
//! of `examples/2002834/table-3.1.toml` (its roller count, clearance, misalignment and profile)
//! this program finds the radial load whose quasi-static load distribution (the workspace's slice
//! model, roller centrifugal force at the model's speed, load line through a roller) carries that
//! largest inner-ring force. The dynamic maxima also contain impact and load-zone-entry peaks, so
//! each value is an upper bound of the quasi-static load of that variant.
//!
//! Run: `cargo run --release -p rolldyn-validation --example table_3_2_radial_load`
//! (optionally a sweep file as the first argument).

use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use rolldyn_numerics::brent::{BrentOptions, brent_root};
use rolldyn_quasistatic::load_distribution::{LoadCase, LoadModel};
use rolldyn_quasistatic::options::QuasiStaticOptions;
use rolldyn_validation::table_3_2::SEED_TABLE_3_2;

/// Tilt from which the crown no longer covers the misalignment (seed 000 §3.1.1.1: at 12′ the
/// roller force jumps to 1435 N, variant 36): the roller force then measures edge loading, not
/// the radial load, and the 12′ variants are left out of the summary.
const EDGE_LOADING_TILT_RAD: f64 = 12.0 / 60.0 * std::f64::consts::PI / 180.0 - 1e-9;

/// Largest inner-ring roller force at radial load `fr` over the roller phases 0 and π/Z.
fn max_inner_force(
    bearing: &CylindricalRollerBearing,
    model: &LoadModel,
    fr: f64,
    centrifugal_n: f64,
) -> f64 {
    let options = QuasiStaticOptions::default();
    [0.0, std::f64::consts::PI / bearing.roller_count as f64]
        .iter()
        .map(|&phase| {
            let case = LoadCase {
                radial_load_n: fr,
                diametral_clearance_m: bearing.clearance.radial,
                misalignment_rad: bearing.misalignment.inner_ring_tilt,
                misalignment_azimuth_rad: 0.0,
                centrifugal_force_n: centrifugal_n,
                roller_phase_rad: phase,
            };
            model
                .solve(&case, None, &options)
                .expect("load distribution")
                .max_inner_load_n
        })
        .fold(0.0, f64::max)
}

/// Radial load at which the largest inner-ring roller force is `target` (Brent's root finder on
/// the monotonic load–force relation, bracket 0 … 20 × target).
fn radial_load_for(bearing: &CylindricalRollerBearing, target: f64, centrifugal_n: f64) -> f64 {
    let model =
        LoadModel::new(bearing, QuasiStaticOptions::default().slice_law).expect("slice model");
    let excess = |fr: f64| max_inner_force(bearing, &model, fr, centrifugal_n) - target;
    let options = BrentOptions {
        x_tol: 1e-3,
        f_tol: 1e-6,
        max_iterations: 100,
    };
    let hi = 20.0 * target;
    brent_root(
        |fr| Ok::<_, std::convert::Infallible>(excess(fr)),
        (0.0, excess(0.0)),
        (hi, excess(hi)),
        &options,
    )
    .expect("the largest roller force grows with the radial load")
    .x
}

fn main() {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "examples/2002834/table-3.1.toml".into());
    let sweep = rolldyn_sweep::SweepFile::load(std::path::Path::new(&path)).expect("sweep file");
    println!(
        "variant,rollers,clearance_mm,misalignment_arcmin,seed_inner_force_n,radial_load_bound_n"
    );
    let mut bounds = Vec::new();
    for variant in &sweep.variants {
        let Some(target) = SEED_TABLE_3_2
            .iter()
            .find(|r| r.variant == variant.name)
            .map(|r| r.roller_inner_ring_force_n)
        else {
            continue;
        };
        let model = sweep.model_of(variant).expect("variant model");
        let BearingModel::Cylindrical(bearing) = &model.bearing else {
            panic!("cylindrical bearing expected");
        };
        let inner_speed = model
            .operating
            .inner_speed
            .expect("[operating] inner_speed");
        let cage_speed = bearing.epicyclic_cage_speed(inner_speed, 0.0);
        // roller centrifugal force m ω_c² d_m/2, pressing the roller on the outer raceway
        let centrifugal = bearing.roller.mass_properties.mass
            * cage_speed
            * cage_speed
            * 0.5
            * bearing.pitch_diameter();
        let fr = radial_load_for(bearing, target, centrifugal);
        println!(
            "{},{},{:.3},{:.0},{target},{fr:.0}",
            variant.name,
            bearing.roller_count,
            bearing.clearance.radial * 1e3,
            bearing.misalignment.inner_ring_tilt.to_degrees() * 60.0,
        );
        if bearing.misalignment.inner_ring_tilt < EDGE_LOADING_TILT_RAD {
            bounds.push(fr);
        }
    }
    bounds.sort_by(f64::total_cmp);
    let n = bounds.len();
    println!(
        "# variants below 12′: {n}, bound min {:.0} N, median {:.0} N, max {:.0} N",
        bounds[0],
        bounds[n / 2],
        bounds[n - 1]
    );
}
