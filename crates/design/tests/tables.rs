//! The tables against the catalogue rows they transcribe, the designations read, and the design
//! rules on issue 38's bearing.

use rolldyn_design::iso15::{self, DimensionSeries};
use rolldyn_design::iso5753::{self, ClearanceGroup};
use rolldyn_design::{
    Boundary, CageMaterial, DesignInput, RibArrangement, design, designation, model_file,
};

/// ISO 15 rows as a manufacturer lists them (SKF *Rolling bearings* catalogue, cylindrical
/// roller bearings: NU 1010, NU 206, NU 2215, NU 310, NU 2320; d, D, B, r_1,2 min in mm).
#[test]
fn iso_15_rows_match_the_catalogue() {
    let rows = [
        (DimensionSeries::S10, 50.0, 80.0, 16.0, 1.0),
        (DimensionSeries::S02, 30.0, 62.0, 16.0, 1.0),
        (DimensionSeries::S22, 75.0, 130.0, 31.0, 1.5),
        (DimensionSeries::S03, 50.0, 110.0, 27.0, 2.0),
        (DimensionSeries::S23, 100.0, 215.0, 73.0, 3.0),
    ];
    for (series, d, outside, width, chamfer) in rows {
        let row = iso15::boundary(series, d).unwrap();
        assert_eq!(
            (row.outside_mm, row.width_mm, row.chamfer_min_mm),
            (outside, width, chamfer),
            "{series:?} d = {d}"
        );
    }
    assert!(iso15::boundary(DimensionSeries::S22, 115.0).is_none());
}

/// ISO 5753-1 Table 4: d over 65 up to 80 mm, and the edges of a row.
#[test]
fn iso_5753_clearance_by_bore() {
    assert_eq!(
        iso5753::radial_clearance_um(ClearanceGroup::CN, 75.0),
        Some([40.0, 75.0])
    );
    assert_eq!(
        iso5753::radial_clearance_um(ClearanceGroup::C3, 80.0),
        Some([65.0, 100.0])
    );
    assert_eq!(
        iso5753::radial_clearance_um(ClearanceGroup::C3, 80.5),
        Some([75.0, 110.0])
    );
    assert_eq!(
        iso5753::radial_clearance_um(ClearanceGroup::C2, 20.0),
        Some([0.0, 25.0])
    );
    assert_eq!(
        iso5753::radial_clearance_um(ClearanceGroup::CN, 300.0),
        None
    );
}

#[test]
fn designations_are_read_with_or_without_spaces() {
    let nu = designation::parse("NU 2215").unwrap();
    assert_eq!(nu.text, "NU2215");
    assert_eq!(
        (nu.ribs, nu.series, nu.bore_code),
        (RibArrangement::Nu, DimensionSeries::S22, 15)
    );
    assert_eq!(designation::parse("nj310").unwrap().row.outside_mm, 110.0);
    assert_eq!(designation::parse("N 1012").unwrap().row.bore_mm, 60.0);
    assert_eq!(designation::parse("NUP 204").unwrap().row.width_mm, 14.0);
}

#[test]
fn unknown_designations_say_what_is_read() {
    for (text, expected) in [
        ("32215", "double-row-tapered"),
        ("NU2215ECP", "suffix 'ECP'"),
        ("NN3015", "type 'NN'"),
        ("NU4215", "series '42'"),
        ("NU2202", "bore code 02"),
        ("NU2223", "bore code 23"),
    ] {
        let err = designation::parse(text).unwrap_err();
        assert!(err.contains(expected), "{text}: {err}");
    }
}

fn boundary_form(roller: Option<(f64, f64, usize)>) -> DesignInput {
    DesignInput {
        name: "issue-38".into(),
        ribs: RibArrangement::Nu,
        boundary: Boundary {
            bore: 0.075,
            outside: 0.130,
            width: 0.031,
            chamfer_min: None,
            source: "given".into(),
        },
        roller_diameter: roller.map(|r| r.0),
        roller_length: roller.map(|r| r.1),
        rollers: roller.map(|r| r.2),
        cage: CageMaterial::Brass,
        clearance_group: ClearanceGroup::CN,
        oil: Some("iso-vg-68-mineral".into()),
        operating: None,
    }
}

/// The raceways imply the ISO 5753 clearance, the cage lies inside the rib rims and the land,
/// and catalogue values replace the rules.
#[test]
fn the_design_of_issue_38s_bearing_is_consistent() {
    let d = design(&boundary_form(Some((0.015, 0.022, 16)))).unwrap();
    let implied = d.outer_raceway.value - d.inner_raceway.value - 2.0 * d.roller_diameter.value;
    assert!((implied - d.clearance.value).abs() < 1e-12);
    assert!((d.clearance.value - 57.5e-6).abs() < 1e-12);
    assert!(d.cage_outside.value + d.floating_clearance.value <= d.guiding_rib.value + 1e-12);
    assert!(d.cage_bore.value > d.inner_raceway.value);
    assert!(d.pocket_axial.value > d.rib_spacing.value);
    assert!(d.cage_width.value < 0.031);
    assert_eq!(d.chamfer_min.value, 1.5e-3, "r_s of NU 2215's row");
    let text = model_file::write(&d);
    assert!(text.contains("count = 16"));
    assert!(text.contains("material = \"cuzn40pb2\""));
    assert!(text.contains("oil = \"iso-vg-68-mineral\""));
    assert!(text.contains("No [operating] section"));
}

#[test]
fn a_roller_too_long_for_the_cage_names_the_flag() {
    let err = design(&boundary_form(Some((0.015, 0.029, 16)))).unwrap_err();
    assert_eq!(err.input, "--roller-length");
}
