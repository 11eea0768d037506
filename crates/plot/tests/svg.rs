//! The SVGs as people read them: fonts of at least 12 px, a colour bar on every map, orbits at
//! equal aspect, sweep plots against the varied parameter or the variant names.

use rolldyn_plot::*;
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-plot-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Removes `dir`, unless `ROLLDYN_PLOT_KEEP` is set (to look at the plots).
fn done(dir: PathBuf) {
    if std::env::var_os("ROLLDYN_PLOT_KEEP").is_none() {
        std::fs::remove_dir_all(dir).unwrap();
    }
}

/// Every `font-size` of the SVG, px.
fn font_sizes(svg: &str) -> Vec<f64> {
    svg.split("font-size=\"")
        .skip(1)
        .map(|rest| rest[..rest.find('"').unwrap()].parse().unwrap())
        .collect()
}

/// Whether the SVG writes `text` as a whole text element (plotters puts it on its own line).
fn has_text(svg: &str, text: &str) -> bool {
    svg.contains(&format!(">\n{text}\n</text>")) || svg.contains(&format!(">{text}</text>"))
}

fn assert_readable(svg: &str) {
    let sizes = font_sizes(svg);
    assert!(!sizes.is_empty());
    assert!(sizes.iter().all(|&s| s >= 12.0), "{sizes:?}");
}

#[test]
fn line_plots_have_readable_fonts_and_axes_near_the_data() {
    let dir = scratch("line");
    let path = dir.join("cage_speed.svg");
    let cage: Vec<(f64, f64)> = (0..100)
        .map(|k| (k as f64 * 1e-3, 392.0 + (k % 7) as f64))
        .collect();
    let epicyclic: Vec<(f64, f64)> = (0..100).map(|k| (k as f64 * 1e-3, 391.8)).collect();
    line_plot(
        &path,
        &Labels {
            title: "Cage speed",
            x: "time, s",
            y: "rad/s",
        },
        &[
            Series {
                label: "cage",
                points: &cage,
            },
            Series {
                label: "epicyclic",
                points: &epicyclic,
            },
        ],
    )
    .unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    assert_readable(&svg);
    assert!(svg.contains("class=\"rolldyn-plot line-plot\""));
    // no tick at 0 or 100: the axis starts near 390
    assert!(!has_text(&svg, "200") && has_text(&svg, "395"), "{svg}");
    done(dir);
}

#[test]
fn every_map_has_a_labelled_colour_bar() {
    let dir = scratch("map");
    let values: Vec<f64> = (0..200).map(|k| (k % 20) as f64 * 50.0).collect();
    let field = Field {
        values: &values,
        nx: 20,
        ny: 10,
        extent: (0.0, 10.0, -1.0, 1.0),
    };
    let labels = Labels {
        title: "Contact pressure",
        x: "x, mm",
        y: "y, mm",
    };
    map_plot(
        &dir.join("pressure.svg"),
        &labels,
        &field,
        &MapLabels {
            value: "pressure, MPa",
            outline: &[],
        },
    )
    .unwrap();
    heat_map(&dir.join("old.svg"), &labels, &field).unwrap();
    for (file, label) in [
        ("pressure.svg", "pressure, MPa"),
        ("old.svg", "Contact pressure"),
    ] {
        let svg = std::fs::read_to_string(dir.join(file)).unwrap();
        assert_readable(&svg);
        assert!(
            svg.starts_with("<svg class=\"rolldyn-plot heat-map\""),
            "{svg}"
        );
        assert_eq!(svg.matches("<g class=\"colour-bar\"").count(), 1);
        assert!(has_text(&svg, label));
    }
    done(dir);
}

#[test]
fn orbits_are_drawn_to_equal_aspect_with_their_circle() {
    let dir = scratch("orbit");
    let path = dir.join("cage_orbit.svg");
    let orbit: Vec<(f64, f64)> = (0..50)
        .map(|k| ((k as f64 * 0.3).cos() * 40.0, (k as f64 * 0.3).sin() * 10.0))
        .collect();
    orbit_plot(
        &path,
        &Labels {
            title: "Cage centre orbit",
            x: "x, µm",
            y: "y, µm",
        },
        &[Series {
            label: "cage centre",
            points: &orbit,
        }],
        &[ClearanceCircle {
            label: "land clearance",
            centre: (0.0, 0.0),
            radius: 200.0,
        }],
    )
    .unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    assert_readable(&svg);
    assert!(has_text(&svg, "land clearance"), "{svg}");
    done(dir);
}

#[test]
fn sweep_plots_use_the_varied_parameter_or_the_variant_names() {
    let dir = scratch("variants");
    let names: Vec<String> = ["n18", "n24", "n28"].map(String::from).to_vec();
    let count = [18.0, 24.0, 28.0];
    let slip = [0.01, 0.02, 0.025];
    variant_plot(
        &dir.join("numeric.svg"),
        "cage_slip_mean per variant",
        "cage_slip_mean",
        &names,
        &[Varied {
            column: "roller.count",
            values: &count,
        }],
        &slip,
    )
    .unwrap();
    let svg = std::fs::read_to_string(dir.join("numeric.svg")).unwrap();
    assert!(has_text(&svg, "roller.count"), "{svg}");
    assert!(!svg.contains("order in the sweep file"));
    variant_plot(
        &dir.join("names.svg"),
        "slip",
        "cage_slip_mean",
        &names,
        &[],
        &slip,
    )
    .unwrap();
    let svg = std::fs::read_to_string(dir.join("names.svg")).unwrap();
    assert_readable(&svg);
    for name in &names {
        assert!(has_text(&svg, name), "{svg}");
    }
    done(dir);
}
