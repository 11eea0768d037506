//! The general 1-D/2-D thin-film solvers (SPEC §8.1) against closed forms.
//! Every tolerance is stated and justified next to its assertion.

use rolldyn_reynolds::Cavitation;
use rolldyn_reynolds::grid::{Axis, EdgeBc, Grid1d, Grid2d};
use rolldyn_reynolds::reynolds1d::{self, Ends1d, Fields1d};
use rolldyn_reynolds::reynolds2d::{self, Fields2d, ReynoldsOptions};

/// Infinitely wide inclined slider (standard closed form, not in the seeds): h = h₂(1 + K(1 − x/L)),
/// moving surface speed U, W = 6μUL²/(K²h₂²)·[ln(1 + K) − 2K/(2 + K)] per unit width. The 1-D
/// solver (400 nodes, no cavitation needed: the pressure is positive) and the 2-D solver with
/// closed side faces (no axial flow) agree with it to 10⁻⁴ (second-order FV, smooth solution).
#[test]
fn inclined_slider() {
    let (mu, u, l, h2, k): (f64, f64, f64, f64, f64) = (0.05, 2.0, 0.02, 20e-6, 1.2);
    let exact = 6.0 * mu * u * l * l / (k * k * h2 * h2) * ((1.0 + k).ln() - 2.0 * k / (2.0 + k));
    let n = 400;
    let g = Grid1d::uniform(0.0, l, n).unwrap();
    let h: Vec<f64> = g.x.iter().map(|x| h2 * (1.0 + k * (1.0 - x / l))).collect();
    let f = Fields1d {
        flow: h.iter().map(|h| h * h * h / (12.0 * mu)).collect(),
        couette: h.iter().map(|h| 0.5 * u * h).collect(),
        ..Default::default()
    };
    let o = ReynoldsOptions {
        cavitation: Cavitation::None,
        ..Default::default()
    };
    let s = reynolds1d::solve(
        &g,
        Ends1d::Pressures {
            inlet: 0.0,
            outlet: 0.0,
        },
        &f,
        &o,
        None,
    )
    .unwrap();
    let w = g.integrate(&s.pressure);
    assert!((w / exact - 1.0).abs() < 1e-4, "{w} {exact}");
    // 2-D with three closed y rows equals the 1-D answer
    let g2 = Grid2d {
        nx: n,
        ny: 3,
        dx: l / (n - 1) as f64,
        dy: 1e-3,
        x_axis: Axis::Ends(EdgeBc::Pressure(0.0), EdgeBc::Pressure(0.0)),
        y_axis: Axis::Ends(EdgeBc::SymmetryFace, EdgeBc::SymmetryFace),
    };
    let rep = |v: &Vec<f64>| v.iter().flat_map(|a| [*a, *a, *a]).collect::<Vec<f64>>();
    let f2 = Fields2d {
        flow_x: rep(&f.flow),
        flow_y: rep(&f.flow),
        couette_x: rep(&f.couette),
        ..Default::default()
    };
    let s2 = reynolds2d::solve(&g2, &f2, &o, None).unwrap();
    for i in (0..n).step_by(37) {
        assert!((s2.pressure[3 * i + 1] - s.pressure[i]).abs() < 1e-9 * exact / l);
    }
    // with Reynolds cavitation the (all-positive) solution is unchanged
    let r = reynolds1d::solve(
        &g,
        Ends1d::Pressures {
            inlet: 0.0,
            outlet: 0.0,
        },
        &f,
        &ReynoldsOptions::default(),
        None,
    )
    .unwrap();
    assert!(
        r.converged
            && r.pressure
                .iter()
                .zip(&s.pressure)
                .all(|(a, b)| (a - b).abs() < 1e-9 * exact / l)
    );
}

/// Squeeze film between parallel plates of width L approaching at ḣ < 0 (2-D, long in y by
/// closed side faces): p = −6μḣ(L²/4 − x²)/h³ — quadratic, so the finite-volume solution is exact
/// to round-off (10⁻¹⁰). Separating plates (ḣ > 0) cavitate entirely with the Reynolds model.
#[test]
fn squeeze_film() {
    let (mu, h, hdot, l) = (0.1, 50e-6, -1e-3, 0.01);
    let n = 101;
    let g = Grid2d {
        nx: n,
        ny: 2,
        dx: l / (n - 1) as f64,
        dy: 1.0,
        x_axis: Axis::Ends(EdgeBc::Pressure(0.0), EdgeBc::Pressure(0.0)),
        y_axis: Axis::Ends(EdgeBc::SymmetryFace, EdgeBc::SymmetryFace),
    };
    let m = g.len();
    let f = Fields2d {
        flow_x: vec![h * h * h / (12.0 * mu); m],
        flow_y: vec![h * h * h / (12.0 * mu); m],
        couette_x: vec![0.0; m],
        squeeze: vec![hdot; m],
        ..Default::default()
    };
    let s = reynolds2d::solve(&g, &f, &ReynoldsOptions::default(), None).unwrap();
    for i in 0..n {
        let x = -0.5 * l + i as f64 * g.dx;
        let exact = -6.0 * mu * hdot * (0.25 * l * l - x * x) / (h * h * h);
        assert!(
            (s.pressure[2 * i] - exact).abs() < 1e-10 * 6.0 * mu * hdot.abs() * l * l / (h * h * h)
        );
    }
    let f2 = Fields2d {
        squeeze: vec![-hdot; m],
        ..f
    };
    let s2 = reynolds2d::solve(&g, &f2, &ReynoldsOptions::default(), None).unwrap();
    assert!(s2.pressure.iter().all(|&p| p == 0.0));
}
