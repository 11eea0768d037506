//! Issue 23: the quasi-static rows of the consistency table are the dynamics' own start, the
//! switches act on them, and a short dynamic row runs and records its revolutions and powers.
//! The full table is `examples/model_consistency.rs` (VALIDATION.md, "Model consistency").

use rolldyn_geometry::BearingModel;
use rolldyn_setup::{LoadDirection, Overrides};
use rolldyn_validation::model_consistency::{Case, RunLength, Switches, dynamic, quasi_static};

fn obrien_taylor() -> Case {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/obrien-taylor.toml"
    );
    let mut model = rolldyn_model::load(std::path::Path::new(path)).unwrap();
    if let BearingModel::Cylindrical(b) = &mut model.bearing {
        b.roller.slice_count = 4;
    }
    Case {
        name: "obrien-taylor".into(),
        model,
        speed_rad_s: 4000.0 * std::f64::consts::PI / 30.0,
        radial_load_n: 201.0,
        load_direction: LoadDirection::Fixed,
        oil_temperature_k: None,
    }
}

#[test]
fn quasi_static_row_is_the_dynamics_start() {
    let case = obrien_taylor();
    let today = Switches::today();
    let q = quasi_static(&case, &today).unwrap();
    let overrides = Overrides {
        speed: Some(case.speed_rad_s),
        radial_load: Some(case.radial_load_n),
        axial_load: None,
        load_direction: Some(case.load_direction),
        ..Overrides::default()
    };
    let conditions = rolldyn_setup::conditions(&overrides, &case.model).unwrap();
    let BearingModel::Cylindrical(bearing) = &case.model.bearing else {
        panic!("cylindrical bearing");
    };
    let lubrication = case.model.lubrication.as_ref().unwrap();
    let prepared = rolldyn_setup::prepare_with(
        bearing,
        lubrication,
        &case.model.dynamics,
        conditions,
        1e-3,
        None,
    )
    .unwrap();
    let start = prepared.quasi_static.unwrap();
    let reference = bearing.epicyclic_cage_speed(case.speed_rad_s, 0.0);
    assert!((1.0 - start.cage_speed_rad_s / reference - q.slip_on_dynamic_reference).abs() < 1e-12);
    // the land film is the largest cage torque of this point: without it the cage lags less
    let no_land = quasi_static(
        &case,
        &Switches {
            land_film: false,
            ..today
        },
    )
    .unwrap();
    assert!(
        no_land.slip < 0.5 * q.slip,
        "{} vs {}",
        no_land.slip,
        q.slip
    );
    assert_eq!(no_land.powers.land_w, 0.0);
}

#[test]
fn short_dynamic_row() {
    let case = obrien_taylor();
    let length = RunLength {
        revolutions: 3,
        skipped_revolutions: 1,
        samples_per_revolution: 20,
    };
    let d = dynamic(&case, &Switches::today(), &length).unwrap();
    eprintln!("{d:?}");
    assert!(d.revolutions >= 1);
    assert!(d.slip.abs() < 0.01);
    assert!(d.powers.land_w > 0.0 && d.powers.drag_w > 0.0);
}
