//! General 1-D thin-film Reynolds solver on a non-uniform grid (SPEC §8.1):
//!
//! d/dx(S dp/dx) = dq_C/dx + s,
//!
//! with the same finite-volume discretisation, cavitation models and active-set iterations as
//! [`crate::reynolds2d`] (the 2-D machinery with one node across, tridiagonal band). Used for the
//! infinitely long journal bearing (periodic) and as a general building block; the EHL line
//! contact has its own coupled Newton solver in [`crate::line_contact`].

use crate::error::{Result, ReynoldsError};
use crate::grid::{Axis, AxisInfo, EdgeBc, Grid1d, Grid2d};
use crate::reynolds2d::{Fields2d, ReynoldsOptions, Solution2d, solve_with_axes};

/// End conditions of a 1-D problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ends1d {
    /// Periodic with the given period (the last node neighbours the first across
    /// x₀ + period − x_{n−1}).
    Periodic {
        /// Period length, in the grid's units.
        period: f64,
    },
    /// Prescribed pressures at the first and last node.
    Pressures {
        /// Pressure at x₀.
        inlet: f64,
        /// Pressure at x_{n−1}.
        outlet: f64,
    },
}

/// Nodal fields of the 1-D equation.
#[derive(Debug, Clone, Default)]
pub struct Fields1d {
    /// Flow coefficient S (e.g. ρh³/12μ).
    pub flow: Vec<f64>,
    /// Full-film Couette flux (e.g. ρh(u₁+u₂)/2).
    pub couette: Vec<f64>,
    /// Source ∂(ρh)/∂t (empty = zero).
    pub squeeze: Vec<f64>,
    /// Prescribed pressures (feed), NaN = free (empty = none).
    pub prescribed: Vec<f64>,
}

/// Solution of a 1-D problem (same layout as the 2-D one, one node across).
pub type Solution1d = Solution2d;

/// Solves the 1-D Reynolds equation with the chosen cavitation model.
pub fn solve(
    grid: &Grid1d,
    ends: Ends1d,
    fields: &Fields1d,
    options: &ReynoldsOptions,
    warm: Option<&Solution1d>,
) -> Result<Solution1d> {
    let n = grid.len();
    if n < 3 || !grid.x.windows(2).all(|w| w[1] > w[0]) {
        return Err(ReynoldsError::InvalidInput {
            what: "1-D grid",
            reason: "needs ≥ 3 strictly increasing nodes".into(),
        });
    }
    let (xi, x_axis) = match ends {
        Ends1d::Periodic { period } => {
            if period.is_nan() || period <= grid.x[n - 1] - grid.x[0] {
                return Err(ReynoldsError::InvalidInput {
                    what: "period",
                    reason: format!("{period} does not exceed the node span"),
                });
            }
            (
                AxisInfo::from_nodes(&grid.x, Some(period), None, None),
                Axis::Periodic,
            )
        }
        Ends1d::Pressures { inlet, outlet } => (
            AxisInfo::from_nodes(&grid.x, None, Some(inlet), Some(outlet)),
            Axis::Ends(EdgeBc::Pressure(inlet), EdgeBc::Pressure(outlet)),
        ),
    };
    let g = Grid2d {
        nx: n,
        ny: 1,
        dx: (grid.x[n - 1] - grid.x[0]) / (n - 1) as f64,
        dy: 1.0,
        x_axis,
        y_axis: Axis::Ends(EdgeBc::SymmetryFace, EdgeBc::SymmetryFace),
    };
    let yi = AxisInfo::new(1, 1.0, g.y_axis);
    let f2 = Fields2d {
        flow_x: fields.flow.clone(),
        flow_y: fields.flow.clone(),
        couette_x: fields.couette.clone(),
        couette_y: Vec::new(),
        squeeze: fields.squeeze.clone(),
        prescribed: fields.prescribed.clone(),
    };
    solve_with_axes(&g, &xi, &yi, &f2, options, warm)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cavitation::Cavitation;
    use std::f64::consts::PI;

    /// Infinitely long journal bearing, full Sommerfeld (Sommerfeld 1904, standard form, not in
    /// the seeds): with H = 1 + ε cosθ, S = H³/12, q_C = H/2 the solution is
    /// P(θ) − P(0) = 6 ε sinθ (2 + ε cosθ)/((2 + ε²)(1 + ε cosθ)²).
    #[test]
    fn long_bearing_full_sommerfeld() {
        let n = 720;
        let eps: f64 = 0.6;
        let x: Vec<f64> = (0..n).map(|i| 2.0 * PI * i as f64 / n as f64).collect();
        let h: Vec<f64> = x.iter().map(|t| 1.0 + eps * t.cos()).collect();
        let mut prescribed = vec![f64::NAN; n];
        prescribed[0] = 0.0;
        let f = Fields1d {
            flow: h.iter().map(|v| v * v * v / 12.0).collect(),
            couette: h.iter().map(|v| 0.5 * v).collect(),
            squeeze: vec![],
            prescribed,
        };
        let o = ReynoldsOptions {
            cavitation: Cavitation::None,
            ..Default::default()
        };
        let s = solve(
            &Grid1d { x: x.clone() },
            Ends1d::Periodic { period: 2.0 * PI },
            &f,
            &o,
            None,
        )
        .unwrap();
        let exact = |t: f64| {
            6.0 * eps * t.sin() * (2.0 + eps * t.cos())
                / ((2.0 + eps * eps) * (1.0 + eps * t.cos()).powi(2))
        };
        let pmax = x.iter().map(|&t| exact(t).abs()).fold(0.0, f64::max);
        let err = x
            .iter()
            .zip(&s.pressure)
            .map(|(&t, p)| (exact(t) - p).abs())
            .fold(0.0, f64::max);
        // second-order FV: error ~ (Δθ)² × O(10) relative at ε = 0.6, 720 nodes → < 1e-3
        assert!(err < 1e-3 * pmax, "err {err} pmax {pmax}");
        // Reynolds cavitation with the ambient supply at the maximum gap (θ = 0): non-negative,
        // converged, fewer than 10 active-set solves on the finest grid (nested start)
        let o = ReynoldsOptions::default();
        let f2 = f;
        let r = solve(
            &Grid1d { x },
            Ends1d::Periodic { period: 2.0 * PI },
            &f2,
            &o,
            None,
        )
        .unwrap();
        assert!(r.converged && r.iterations < 10, "{}", r.iterations);
        assert!(r.pressure.iter().all(|&p| p >= 0.0));
    }
}
