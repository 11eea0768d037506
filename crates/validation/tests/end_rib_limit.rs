//! Seed 000 §3.2.2 (SPEC §6.7): the end–rib limit force of the cassette bearing
//! (VALIDATION.md, "End–rib limit force").

use rolldyn_geometry::{BearingModel, DoubleRowTaperedBearing, TaperedRibFace};
use rolldyn_validation::end_rib_limit::{
    EndRibPair, RibSurface, Settings, hertz_check, limit_force, limit_row, pressure_map,
};

const CONICAL: TaperedRibFace = TaperedRibFace::Conical;
const CONCAVE_800: TaperedRibFace = TaperedRibFace::ConcaveTorus { radius: 0.8 };

fn cassette() -> DoubleRowTaperedBearing {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/tapered-cassette.toml"
    );
    match rolldyn_model::load(std::path::Path::new(path))
        .unwrap()
        .bearing
    {
        BearingModel::Tapered(b) => b,
        _ => panic!("the cassette model is a tapered bearing"),
    }
}

/// Seed 000 §3.2.2: "at the reduced curvature 0.3125 m⁻¹ the contact force [5000 N] exceeds
/// the limit value" (Fig. 3.87).
#[test]
fn concave_800_mm_rib_is_beyond_its_limit_at_5000_n() {
    let settings = Settings::default();
    let map = pressure_map(&cassette(), CONCAVE_800, 5000.0, &settings).unwrap();
    assert!((map.pair.reduced_curvature() - 0.3125).abs() < 1e-12);
    assert!(map.reaches_boundary);
    let row = limit_row(&cassette(), CONCAVE_800, &settings).unwrap();
    assert!(row.limit.above_n < 5000.0, "{row:?}");
}

/// Seed 000 §3.2.2: "at the reduced curvature 1.5625 m⁻¹ this contact force [5000 N] is below
/// the limit value" (Fig. 3.86). Not reproduced by the cassette model: its roller end face
/// ends at the 1 mm chamfer 1.75 mm below the contact point, and the patch reaches that edge
/// at ≈ 1.5 kN (VALIDATION.md, "End–rib limit force").
#[test]
#[ignore = "seed statement not reproduced with the cassette's assumed rib and chamfer (VALIDATION.md)"]
fn conical_rib_is_within_its_limit_at_5000_n() {
    let row = limit_row(&cassette(), CONICAL, &Settings::default()).unwrap();
    assert!((row.reduced_curvature - 1.5625).abs() < 1e-12);
    assert!(row.limit.below_n > 5000.0, "{row:?}");
}

/// The ordering behind both seed statements: the flatter the pair, the lower the limit.
#[test]
fn limit_force_falls_with_the_reduced_curvature_of_the_concave_ribs() {
    let settings = Settings::default();
    let b = cassette();
    let conical = limit_row(&b, CONICAL, &settings).unwrap();
    let concave = limit_row(&b, CONCAVE_800, &settings).unwrap();
    assert!(concave.limit.above_n < conical.limit.below_n);
    assert!(concave.limit_axial_profile.above_n < conical.limit_axial_profile.below_n);
}

/// Far from the projection edges the Boussinesq patch of the true gap is the Hertz ellipse of
/// the end sphere on the rib face (curvatures of the axial section and of the parallel
/// circle): p_max within 2 %, semi-axes within 4 % (one cell of 0.05 mm at 0.5 kN).
#[test]
fn small_force_patch_is_the_hertz_ellipse() {
    let check = hertz_check(&cassette(), CONICAL, 500.0, &Settings::default()).unwrap();
    assert!(!check.map.reaches_boundary);
    let (s, hertz) = (&check.map.solution, &check.hertz);
    let (along_circle, up_the_rib) = check.semi_axes_m();
    let err = |a: f64, b: f64| (a - b).abs() / b;
    assert!(
        err(s.max_pressure_pa, hertz.max_pressure) < 0.02,
        "{check:?}"
    );
    // the parallel circle is the flatter direction: the major axis runs along it
    assert!(err(along_circle, hertz.semi_major) < 0.04, "{check:?}");
    assert!(err(up_the_rib, hertz.semi_minor) < 0.04, "{check:?}");
    assert!(err(s.approach_m, hertz.approach) < 0.02, "{check:?}");
}

/// The force-controlled solve carries exactly the requested force (seed 004 eq. (6)).
#[test]
fn solved_force_is_the_requested_force() {
    let map = pressure_map(&cassette(), CONICAL, 16000.0, &Settings::default()).unwrap();
    assert!(map.solution.converged);
    assert!((map.solution.force_n - 16000.0).abs() < 1e-6 * 16000.0);
}

/// The bracket is tight and lies on the two sides of the criterion.
#[test]
fn limit_bracket_straddles_the_boundary_contact() {
    let settings = Settings::default();
    let pair = EndRibPair::new(
        &cassette(),
        CONICAL,
        RibSurface::Revolution,
        settings.cell_m,
    )
    .unwrap();
    let limit = limit_force(&pair, 1000.0, &settings).unwrap();
    assert!(limit.above_n / limit.below_n <= 1.0 + settings.force_tolerance);
    let below = pressure_map(&cassette(), CONICAL, limit.below_n, &settings).unwrap();
    let above = pressure_map(&cassette(), CONICAL, limit.above_n, &settings).unwrap();
    assert!(!below.reaches_boundary && above.reaches_boundary);
}
