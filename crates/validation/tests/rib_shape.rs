//! Seed 000 §3.1.1.7 (SPEC V-21, §1.2 "Ribs"): a convex inner-ring rib face (patent RU 2815566,
//! R 430 mm and R 37.5 mm) moves the roller-end contact away from the rib edge ("the contact
//! spots lie far from the edge of the rib"), which lowers the sliding speed at the contact,
//! compared with the flat rib whose contact "reaches the edge break even at a small pitch".
//!
//! Bearing 2002834 at Table 3.1 variant 12 conditions (4′, clearance 0.044 mm), one cage
//! revolution collected after one discarded (VALIDATION.md "V-21 (part)" has the 4 + 4
//! revolution release run of both misalignments).

use rolldyn_validation::rib_shape::{self, RibShapeRow, Settings};
use std::path::PathBuf;

fn describe(r: &RibShapeRow) -> String {
    format!(
        "{}: edge distance mean {:.3} mm, min {:.3} mm, force share at the edge {:.3}; \
         sliding mean {:.2} m/s, max {:.2} m/s",
        r.face_label(),
        r.mean_edge_distance_m * 1e3,
        r.min_edge_distance_m * 1e3,
        r.edge_force_share,
        r.mean_sliding_m_s,
        r.max_sliding_m_s
    )
}

#[test]
fn convex_rib_moves_the_contact_off_the_edge_and_slides_slower() {
    let sweep = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rib_shape::SWEEP_FILE);
    let settings = Settings {
        revolutions: 2.0,
        discard_revolutions: 1.0,
        ..Settings::default()
    };
    let keep = |n: &str| n.ends_with("-4arcmin") && !n.contains("crest");
    let rows = rib_shape::run(&sweep, &settings, &keep, &mut |r| {
        println!("{}", describe(r))
    })
    .unwrap();
    let [flat, r430, r37] = rows.as_slice() else {
        panic!(
            "expected flat, R 430 mm, R 37.5 mm; got {} rows",
            rows.len()
        )
    };
    for r in [flat, r430, r37] {
        assert!(r.max_force_n > 1.0, "no rib contact: {}", describe(r));
    }
    // Contact position. The flat rib carries most of its force on the edge (release run: 70 %);
    // the convex faces carry a small share (R 430 mm, 8 %) or none (R 37.5 mm: the crest at
    // mid-height, 1.85 mm from the edge, and 4.6 µm of drop over the remaining 1.85 mm, more
    // than the end's yaw lever moves). Margins of 2× and 0.5 mm are far outside the
    // revolution-to-revolution scatter of these shares and means (≈ 10 % in the runs).
    assert!(flat.edge_force_share > 0.4, "{}", describe(flat));
    assert!(
        r430.edge_force_share < 0.5 * flat.edge_force_share,
        "{}",
        describe(r430)
    );
    assert!(
        r430.mean_edge_distance_m > flat.mean_edge_distance_m,
        "{}",
        describe(r430)
    );
    assert_eq!(r37.edge_force_share, 0.0, "{}", describe(r37));
    assert!(r37.min_edge_distance_m > 1e-3, "{}", describe(r37));
    assert!(
        r37.mean_edge_distance_m > flat.mean_edge_distance_m + 0.5e-3,
        "{}",
        describe(r37)
    );
    // Sliding speed: it grows linearly with the height of the contact point above the raceway
    // (the roller–ring relative rotation about the raceway contact line), so moving the spot
    // 1 mm down lowers it by 6–7 m/s (29 m/s at the edge). Release run: mean −17 %, max −26 %
    // for R 37.5 mm; R 430 mm −2 % (mean) because it still touches the edge at times (the max is unchanged); that
    // difference is within the scatter of a one-revolution window, so it is not asserted.
    assert!(
        r37.mean_sliding_m_s < 0.9 * flat.mean_sliding_m_s,
        "{}",
        describe(r37)
    );
    assert!(
        r37.max_sliding_m_s < 0.85 * flat.max_sliding_m_s,
        "{}",
        describe(r37)
    );
}
