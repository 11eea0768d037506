//! The worn geometry and the worn model file: what `rolldyn wear` writes is what
//! `rolldyn simulate` reads back.

use rolldyn_geometry::BearingModel;
use rolldyn_wear::bearing_data::ribs_on_inner_ring;
use rolldyn_wear::worn::worn_bearing;
use rolldyn_wear::worn_model::write_worn_model;
use rolldyn_wear::{Surface, SurfaceWear};

fn default_model() -> rolldyn_model::Model {
    rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap()
}

/// Depths with a shape: the roller and raceways deepest at line 3, a bar, end and rib depth.
fn some_wear(lines: usize, bins: usize, z: usize) -> SurfaceWear {
    let mut w = SurfaceWear::zero(lines, bins, z);
    for s in 0..lines {
        w.roller[s] = 1e-6 * s as f64;
        for b in 0..bins {
            w.inner_map[s * bins + b] = if b < bins / 4 { 2e-6 } else { 0.5e-6 };
        }
    }
    w.roller_at_bar[3] = 0.5e-6;
    for j in 0..z {
        w.bar_by_pocket[j * lines + 5] = 30e-6;
    }
    w.roller_end = 10e-6;
    w.rib = 20e-6;
    w
}

#[test]
fn worn_bearing_moves_every_surface_by_its_depth() {
    let model = default_model();
    let BearingModel::Cylindrical(b) = &model.bearing else {
        panic!()
    };
    let stack = b.roller.slices();
    let w = some_wear(stack.position.len(), 72, b.roller_count);
    let worn = worn_bearing(b, &stack.position, &w).unwrap();
    let total = w.roller_total();
    for (s, &x) in stack.position.iter().enumerate() {
        let added = worn.roller.profile.drop(x) - b.roller.profile.drop(x);
        assert!(
            (added - total[s]).abs() < 1e-12,
            "slice {s}: {added} vs {}",
            total[s]
        );
    }
    let cage = |b: &rolldyn_geometry::CylindricalRollerBearing| {
        b.cage.as_ref().unwrap().pocket.face_clearance
    };
    assert!((cage(&worn) - cage(b) - 30e-6).abs() < 1e-15);
    assert!((worn.roller.length - (b.roller.length - 20e-6)).abs() < 1e-15);
    let spacing =
        |b: &rolldyn_geometry::CylindricalRollerBearing| b.inner_ring.rib_spacing.unwrap();
    assert!((spacing(&worn) - spacing(b) - 40e-6).abs() < 1e-15);
    let map = worn.inner_ring.raceway_wear.as_ref().unwrap();
    assert!((map.depth(stack.position[4], 0.1) - 2e-6).abs() < 1e-15);
    assert!((map.depth(stack.position[4], 3.0) - 0.5e-6).abs() < 1e-15);
    assert_eq!(map.depth(0.5 * b.roller.length, 0.1), 0.0);
    // wear of a worn bearing adds to its map
    let again = worn_bearing(&worn, &stack.position, &w).unwrap();
    let map = again.inner_ring.raceway_wear.as_ref().unwrap();
    assert!((map.depth(stack.position[4], 0.1) - 4e-6).abs() < 1e-15);
    assert!((w.max(Surface::CageBar) - 30e-6).abs() < 1e-18);
}

#[test]
fn the_worn_model_file_reads_back_as_the_worn_bearing() {
    let model = default_model();
    let BearingModel::Cylindrical(b) = &model.bearing else {
        panic!()
    };
    let stack = b.roller.slices();
    let w = some_wear(stack.position.len(), 72, b.roller_count);
    let worn = worn_bearing(b, &stack.position, &w).unwrap();
    let dir = std::env::temp_dir().join(format!("rolldyn-worn-model-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let files = write_worn_model(
        model.source.text(),
        &worn,
        ribs_on_inner_ring(b),
        &dir,
        "test",
    )
    .unwrap();
    assert_eq!(files.len(), 3);
    let back = rolldyn_model::load(&files[0]).unwrap();
    let BearingModel::Cylindrical(r) = &back.bearing else {
        panic!()
    };
    assert!((r.roller.length - worn.roller.length).abs() < 1e-12);
    for &x in &r.roller.slices().position {
        assert!((r.roller.profile.drop(x) - worn.roller.profile.drop(x)).abs() < 1e-12);
    }
    assert!(
        (r.inner_ring.rib_spacing.unwrap() - worn.inner_ring.rib_spacing.unwrap()).abs() < 1e-12
    );
    let pocket = |b: &rolldyn_geometry::CylindricalRollerBearing| {
        b.cage.as_ref().unwrap().pocket.face_clearance
    };
    assert!((pocket(r) - pocket(&worn)).abs() < 1e-12);
    let (m, n) = (
        r.inner_ring.raceway_wear.as_ref().unwrap(),
        worn.inner_ring.raceway_wear.as_ref().unwrap(),
    );
    for &x in &stack.position {
        for a in [0.05, 1.0, 4.0] {
            assert!((m.depth(x, a) - n.depth(x, a)).abs() < 1e-12);
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
