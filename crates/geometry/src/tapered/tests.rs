//! Tests of the tapered geometry on the bearing of seed 000 §3.2.

use super::*;
use crate::{Material, Misalignment};

const ARCMIN: f64 = std::f64::consts::PI / 10_800.0;

fn polyamide() -> Material {
    Material {
        name: "PA66-GF25".into(),
        youngs_modulus: 3e9,
        poisson_ratio: 0.35,
        density: 1320.0,
        meyer_hardness: None,
        fatigue: None,
    }
}

fn seed_roller() -> TaperedRoller {
    TaperedRoller {
        mean_diameter: 21.4e-3,
        length: 49.87e-3,
        half_angle: 53.0 * ARCMIN,
        large_end_sphere_radius: 0.640,
        end_chamfer: 1.0e-3,
        slice_count: DEFAULT_TAPERED_SLICES,
        material: Material::bearing_steel(),
        profile: None,
    }
}

fn seed_bearing(arrangement: Arrangement) -> DoubleRowTaperedBearing {
    let roller = seed_roller();
    let cage = TaperedCage {
        pocket_clearance: 0.4e-3,
        end_clearance: 0.6e-3,
        bar_contact_diameter: 0.205,
        inner_diameter: 0.198,
        outer_diameter: 0.212,
        width: 0.060,
        mass: 0.0,
        inertia_axial: 0.0,
        inertia_transverse: 0.0,
        material: polyamide(),
        roller_friction: 0.06,
    }
    .with_computed_mass(&roller, 23);
    DoubleRowTaperedBearing {
        name: "seed 000 §3.2".into(),
        bore: 0.150,
        outside_diameter: 0.250,
        pitch_diameter: 0.200,
        roller,
        rollers_per_row: 23,
        arrangement,
        row_spacing: 0.090,
        axial_clearance: 0.34e-3,
        large_rib: LargeRib {
            face: TaperedRibFace::Conical,
            height: 5.5e-3,
            undercut: 1.0e-3,
        },
        small_rib_gap: 0.3e-3,
        cage,
        inner_material: Material::bearing_steel(),
        outer_material: Material::bearing_steel(),
        misalignment: Misalignment::default(),
        wear: Default::default(),
    }
}

/// Intersection of two lines given by point and direction.
fn intersection(p: Rz, u: Rz, q: Rz, v: Rz) -> Rz {
    let det = u.r * (-v.z) - u.z * (-v.r);
    let d = q - p;
    let t = (d.r * (-v.z) - d.z * (-v.r)) / det;
    p + t * u
}

/// A direction turned by `angle` from +z toward +r.
fn rotated(v: Rz, angle: f64) -> Rz {
    let (s, c) = angle.sin_cos();
    Rz::new(v.r * c + v.z * s, v.z * c - v.r * s)
}

#[test]
fn derived_angles_of_the_seed_bearing() {
    let b = seed_bearing(Arrangement::O);
    b.validate().unwrap();
    assert!((b.roller_axis_angle().to_degrees() - 8.285).abs() < 5e-4);
    assert!((b.cone_angle().to_degrees() - 7.402).abs() < 5e-4);
    assert!((b.cup_angle().to_degrees() - 9.168).abs() < 5e-4);
    let r = &b.roller;
    let t = r.half_angle.tan();
    assert!((r.large_diameter() - (r.mean_diameter + r.length * t)).abs() < 1e-15);
    assert!((r.small_diameter() - (r.mean_diameter - r.length * t)).abs() < 1e-15);
}

/// The roller's two generatrices, extended, meet on the bearing axis at the cone apex; the cup
/// line shifted back by the normal gap passes there too.
#[test]
fn apex_condition() {
    for arrangement in [Arrangement::O, Arrangement::X] {
        let b = seed_bearing(arrangement);
        assert!(b.apex_mismatch() < 1e-12, "{}", b.apex_mismatch());
        for k in 0..2 {
            let row = b.row(k);
            let s = row.large_end_sign;
            let beta = b.roller.half_angle;
            let half = 0.5 * b.roller.mean_diameter;
            let out = row.roller_axis.perpendicular();
            let out = if out.r > 0.0 { out } else { -out };
            let lower = row.roller_mid - half * out;
            let upper = row.roller_mid + half * out;
            let apex = intersection(
                lower,
                rotated(row.roller_axis, -s * beta),
                upper,
                rotated(row.roller_axis, s * beta),
            );
            assert!(apex.r.abs() < 1e-12, "apex r = {}", apex.r);
            assert!((apex.z - row.apex_z).abs() < 1e-12);
            let shift = b.normal_gap() / b.cup_angle().sin();
            assert!(((row.cup_apex_z - row.apex_z).abs() - shift).abs() < 1e-12);
            assert!((shift - 0.5 * b.axial_clearance).abs() < 1e-15);
        }
    }
}

/// SPEC §1.3 / seed 002 eq. (5.5): centre of mass of a truncated cone measured from the large
/// end; closed-form frustum volume and axial inertia 3m/10 (R⁵ − r⁵)/(R³ − r³).
#[test]
fn mass_properties_of_a_plain_truncated_cone() {
    let roller = TaperedRoller {
        large_end_sphere_radius: f64::INFINITY,
        end_chamfer: 0.0,
        ..seed_roller()
    };
    let (big, small, l) = (
        0.5 * roller.large_diameter(),
        0.5 * roller.small_diameter(),
        roller.length,
    );
    let rho = roller.material.density;
    let volume = std::f64::consts::PI * l / 3.0 * (big * big + big * small + small * small);
    let m = roller.mass_properties();
    assert!((m.mass / (rho * volume) - 1.0).abs() < 1e-10);
    let axial = 0.3 * m.mass * (big.powi(5) - small.powi(5)) / (big.powi(3) - small.powi(3));
    assert!((m.axial_inertia / axial - 1.0).abs() < 1e-10);
    let lc = l * (big * big + 2.0 * big * small + 3.0 * small * small)
        / (4.0 * (big * big + big * small + small * small));
    assert!((roller.centre_of_mass_offset() - (0.5 * l - lc)).abs() < 1e-12);
}

#[test]
fn end_cap_and_chamfers_take_little_mass() {
    let plain = TaperedRoller {
        large_end_sphere_radius: f64::INFINITY,
        end_chamfer: 0.0,
        ..seed_roller()
    };
    let seed = seed_roller().mass_properties();
    let ratio = seed.mass / plain.mass_properties().mass;
    assert!(ratio < 1.0 && ratio > 0.98, "{ratio}");
}

#[test]
fn slice_stack_volume_is_the_cone_volume() {
    let roller = TaperedRoller {
        end_chamfer: 0.0,
        ..seed_roller()
    };
    let t = roller.half_angle.tan();
    let slices = roller.slices();
    assert_eq!(slices.position.len(), DEFAULT_TAPERED_SLICES);
    let frustum =
        |r0: f64, r1: f64, h: f64| std::f64::consts::PI * h / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
    let stacked: f64 = (0..slices.position.len())
        .map(|k| {
            let (r, h) = (slices.radius[k], slices.length[k]);
            frustum(r - 0.5 * h * t, r + 0.5 * h * t, h)
        })
        .sum();
    let whole = frustum(
        0.5 * roller.small_diameter(),
        0.5 * roller.large_diameter(),
        roller.length,
    );
    assert!((stacked / whole - 1.0).abs() < 1e-12);
}

fn mirrored_point(p: Rz, about: f64) -> Rz {
    Rz::new(p.r, 2.0 * about - p.z)
}

fn mirrored_direction(v: Rz) -> Rz {
    Rz::new(v.r, -v.z)
}

fn assert_close(a: Rz, b: Rz) {
    assert!((a - b).norm() < 1e-13, "{a:?} vs {b:?}");
}

/// Row 1 of an O bearing is row 0 mirrored in the mid-plane; row 0 of an X bearing is row 0
/// of the O bearing mirrored about its own mid-point circle.
#[test]
fn o_and_x_are_mirror_images() {
    let o = seed_bearing(Arrangement::O);
    let x = seed_bearing(Arrangement::X);
    let (o0, o1, x0) = (o.row(0), o.row(1), x.row(0));
    assert_eq!(o0.large_end_sign, -1.0);
    assert_eq!(x0.large_end_sign, 1.0);
    for (mirror, about) in [(&o1, 0.0), (&x0, o0.mid_z)] {
        assert_close(mirror.roller_mid, mirrored_point(o0.roller_mid, about));
        assert_close(mirror.cone.point, mirrored_point(o0.cone.point, about));
        assert_close(mirror.cup.point, mirrored_point(o0.cup.point, about));
        assert_close(mirror.cup.normal, mirrored_direction(o0.cup.normal));
        assert_close(
            mirror.large_rib.point,
            mirrored_point(o0.large_rib.point, about),
        );
        assert_close(
            mirror.large_rib.normal,
            mirrored_direction(o0.large_rib.normal),
        );
        assert_close(
            mirror.small_rib.point,
            mirrored_point(o0.small_rib.point, about),
        );
        assert!((mirror.apex_z - (2.0 * about - o0.apex_z)).abs() < 1e-13);
    }
    // O: the large ends and large ribs face outward, X: inward.
    assert!(o0.large_rib.point.z < o0.roller_mid.z && o1.large_rib.point.z > o1.roller_mid.z);
    assert!(x0.large_rib.point.z > x0.roller_mid.z);
}

/// The large-rib contact lies on the end sphere, at mid rib height along the face, with the
/// face normal through the sphere centre.
#[test]
fn large_rib_contact_at_mid_height() {
    for face in [
        TaperedRibFace::Conical,
        TaperedRibFace::ConcaveTorus { radius: 0.8 },
        TaperedRibFace::ConvexTorus { radius: 1.1 },
    ] {
        let mut b = seed_bearing(Arrangement::O);
        b.large_rib.face = face;
        for k in 0..2 {
            let row = b.row(k);
            let rib = row.large_rib;
            let radius = b.roller.large_end_sphere_radius;
            assert!(((rib.point - rib.end_sphere_centre).norm() - radius).abs() < 1e-12);
            let to_centre = rib.end_sphere_centre - rib.point;
            assert_close((1.0 / radius) * to_centre, rib.normal);
            let foot = intersection(rib.point, rib.tangent, row.cone.point, row.cone.direction);
            let height = (rib.point - foot).norm();
            assert!(
                (height - b.large_rib.contact_height()).abs() < 1e-12,
                "{height} {k} {face:?} {:?}",
                rib
            );
            assert!(rib.tangent.dot(row.cone.normal) > 0.0);
            assert_close(rib.face_base, foot);
            if let Some(c) = rib.face_centre {
                let r = 1.0 / face.curvature().abs();
                assert!(((c - rib.point).norm() - r).abs() < 1e-12);
            }
        }
    }
}

#[test]
fn pass_frequencies_are_epicyclic() {
    let b = seed_bearing(Arrangement::O);
    let wi = 663.0 * std::f64::consts::TAU / 60.0;
    let (fo, fi) = b.pass_frequencies(wi);
    let z = b.rollers_per_row as f64;
    assert!((fo + fi - z * 663.0 / 60.0).abs() < 1e-10);
    let wc = b.epicyclic_cage_speed(wi);
    let (si, so) = (b.cone_angle().sin(), b.cup_angle().sin());
    assert!(((wi - wc) * si - wc * so).abs() < 1e-12);
    assert!(
        fo > 110.0 && fo < 120.0 && fi > 134.0 && fi < 144.0,
        "{fo} {fi}"
    );
}

#[test]
fn validation_rejects_bad_data() {
    let mut b = seed_bearing(Arrangement::O);
    b.rollers_per_row = 30;
    assert_eq!(b.validate().unwrap_err().key, "bearing.rollers_per_row");
    let mut b = seed_bearing(Arrangement::O);
    b.axial_clearance = -1e-4;
    assert_eq!(b.validate().unwrap_err().key, "bearing.axial_clearance");
    let mut b = seed_bearing(Arrangement::O);
    b.pitch_diameter = 0.249;
    assert!(b.validate().is_err());
    let mut b = seed_bearing(Arrangement::O);
    b.large_rib.height = 25e-3;
    assert_eq!(b.validate().unwrap_err().key, "large_rib.height");
    let mut b = seed_bearing(Arrangement::O);
    b.row_spacing = 0.03;
    assert_eq!(b.validate().unwrap_err().key, "bearing.row_spacing");
}
