//! Structured grids for the 1-D and 2-D Reynolds solvers (finite volumes centred on nodes).

use crate::error::{Result, ReynoldsError};

/// Boundary condition at one end of a grid axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EdgeBc {
    /// Prescribed pressure (Pa, or the caller's pressure unit) at the boundary node.
    Pressure(f64),
    /// Symmetry plane through the boundary node (half cell, zero flux through the plane).
    SymmetryNode,
    /// Symmetry plane half a spacing beyond the boundary node (full cell, closed face).
    SymmetryFace,
}

/// One axis of a 2-D grid: periodic or with two boundary conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axis {
    /// Periodic: `n` nodes spaced `d`, node n−1 neighbours node 0.
    Periodic,
    /// Open axis with conditions at node 0 and node n−1.
    Ends(EdgeBc, EdgeBc),
}

/// Uniform 2-D grid, nodes (i, j) at (i·dx, j·dy) relative to the grid origin, stored
/// index = i·ny + j (second coordinate fastest: it becomes the bandwidth of the direct solver).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid2d {
    /// Nodes along x (the sliding / circumferential direction).
    pub nx: usize,
    /// Nodes along y (the axial direction).
    pub ny: usize,
    /// Spacing along x.
    pub dx: f64,
    /// Spacing along y.
    pub dy: f64,
    /// x-axis boundary treatment.
    pub x_axis: Axis,
    /// y-axis boundary treatment.
    pub y_axis: Axis,
}

/// Per-axis finite-volume data: cell widths and the fixed value of boundary nodes.
#[derive(Debug, Clone)]
pub(crate) struct AxisInfo {
    pub width: Vec<f64>,
    /// Distance from node k to its next neighbour (k+1, or node 0 across the period).
    pub face_dist: Vec<f64>,
    pub fixed: Vec<Option<f64>>,
    pub periodic: bool,
}

impl AxisInfo {
    pub fn new(n: usize, d: f64, axis: Axis) -> Self {
        let mut width = vec![d; n];
        let mut fixed = vec![None; n];
        let face_dist = vec![d; n];
        match axis {
            Axis::Periodic => AxisInfo {
                width,
                face_dist,
                fixed,
                periodic: true,
            },
            Axis::Ends(lo, hi) => {
                for (k, bc) in [(0usize, lo), (n - 1, hi)] {
                    match bc {
                        EdgeBc::Pressure(v) => fixed[k] = Some(v),
                        EdgeBc::SymmetryNode => width[k] = 0.5 * d,
                        EdgeBc::SymmetryFace => {}
                    }
                }
                AxisInfo {
                    width,
                    face_dist,
                    fixed,
                    periodic: false,
                }
            }
        }
    }

    /// Axis data of a non-uniform 1-D grid; `period` = Some(P) for a periodic axis.
    pub fn from_nodes(x: &[f64], period: Option<f64>, lo: Option<f64>, hi: Option<f64>) -> Self {
        let n = x.len();
        let mut face_dist: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let wrap = period.map(|p| x[0] + p - x[n - 1]).unwrap_or(0.0);
        face_dist.push(wrap);
        let width: Vec<f64> = (0..n)
            .map(|k| {
                let before = if k > 0 { face_dist[k - 1] } else { wrap };
                0.5 * (before + face_dist[k])
            })
            .collect();
        let mut fixed = vec![None; n];
        if period.is_none() {
            fixed[0] = lo;
            fixed[n - 1] = hi;
        }
        AxisInfo {
            width,
            face_dist,
            fixed,
            periodic: period.is_some(),
        }
    }

    /// Neighbour index below/above node k along the axis, if a face exists.
    #[inline]
    pub fn prev(&self, k: usize, n: usize) -> Option<usize> {
        if k > 0 {
            Some(k - 1)
        } else if self.periodic {
            Some(n - 1)
        } else {
            None
        }
    }

    #[inline]
    pub fn next(&self, k: usize, n: usize) -> Option<usize> {
        if k + 1 < n {
            Some(k + 1)
        } else if self.periodic {
            Some(0)
        } else {
            None
        }
    }
}

impl Grid2d {
    /// Checks sizes and spacings.
    pub fn validate(&self) -> Result<()> {
        let min_x = if self.x_axis == Axis::Periodic { 3 } else { 2 };
        if self.nx < min_x || self.ny < 1 {
            return Err(ReynoldsError::InvalidInput {
                what: "grid",
                reason: format!("{}×{} nodes is too small", self.nx, self.ny),
            });
        }
        if !(self.dx > 0.0 && self.dy > 0.0 && self.dx.is_finite() && self.dy.is_finite()) {
            return Err(ReynoldsError::InvalidInput {
                what: "grid spacing",
                reason: format!("dx = {}, dy = {}", self.dx, self.dy),
            });
        }
        if self.ny == 1 && self.y_axis != Axis::Ends(EdgeBc::SymmetryFace, EdgeBc::SymmetryFace) {
            return Err(ReynoldsError::InvalidInput {
                what: "grid",
                reason: "a single y node needs SymmetryFace at both ends (1-D problem)".into(),
            });
        }
        Ok(())
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// True for an empty grid.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Flat index of node (i, j).
    #[inline]
    pub fn idx(&self, i: usize, j: usize) -> usize {
        i * self.ny + j
    }
}

/// Non-uniform 1-D grid (strictly increasing node coordinates).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid1d {
    /// Node coordinates.
    pub x: Vec<f64>,
}

impl Grid1d {
    /// `n` equally spaced nodes on [a, b].
    pub fn uniform(a: f64, b: f64, n: usize) -> Result<Self> {
        if n < 3 || b.partial_cmp(&a) != Some(std::cmp::Ordering::Greater) {
            return Err(ReynoldsError::InvalidInput {
                what: "1-D grid",
                reason: format!("need n ≥ 3 and b > a (n = {n}, a = {a}, b = {b})"),
            });
        }
        let d = (b - a) / (n - 1) as f64;
        Ok(Self {
            x: (0..n).map(|i| a + d * i as f64).collect(),
        })
    }

    /// `n` nodes on [a, b] clustered around `focus` by a sinh map so that the spacing at the
    /// focus is about `spacing` (uniform if `spacing` ≥ (b − a)/(n − 1)).
    pub fn clustered(a: f64, b: f64, n: usize, focus: f64, spacing: f64) -> Result<Self> {
        let uni = Self::uniform(a, b, n)?;
        let h_uni = (b - a) / (n - 1) as f64;
        if spacing >= h_uni || !(focus > a && focus < b) || spacing <= 0.0 {
            return Ok(uni);
        }
        let r = (focus - a) / (b - focus);
        // ξc(β): sinh(β ξc) / sinh(β (1 − ξc)) = r
        let xi_c = |beta: f64| {
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..100 {
                let m = 0.5 * (lo + hi);
                let f = (beta * m).sinh() / (beta * (1.0 - m)).sinh();
                if f < r {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            0.5 * (lo + hi)
        };
        let central = |beta: f64| {
            let xc = xi_c(beta);
            let amp = (b - focus) / (beta * (1.0 - xc)).sinh();
            (amp * beta / (n - 1) as f64, xc, amp)
        };
        let (mut lo, mut hi) = (1e-6, 60.0);
        if central(hi).0 > spacing {
            lo = hi;
        } else {
            for _ in 0..200 {
                let m = 0.5 * (lo + hi);
                if central(m).0 > spacing {
                    lo = m;
                } else {
                    hi = m;
                }
            }
        }
        let beta = 0.5 * (lo + hi);
        let (_, xc, amp) = central(beta);
        let mut x: Vec<f64> = (0..n)
            .map(|i| {
                let xi = i as f64 / (n - 1) as f64;
                focus + amp * (beta * (xi - xc)).sinh()
            })
            .collect();
        x[0] = a;
        x[n - 1] = b;
        Ok(Self { x })
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// True when empty.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Control-volume widths (half cells at the ends).
    pub fn cell_widths(&self) -> Vec<f64> {
        let n = self.x.len();
        (0..n)
            .map(|i| {
                let lo = if i > 0 {
                    0.5 * (self.x[i] + self.x[i - 1])
                } else {
                    self.x[0]
                };
                let hi = if i + 1 < n {
                    0.5 * (self.x[i] + self.x[i + 1])
                } else {
                    self.x[n - 1]
                };
                hi - lo
            })
            .collect()
    }

    /// Cell faces: face k lies between node k−1 and k (k = 1..n−1); face 0 = x₀, face n = x_{n−1}.
    pub fn faces(&self) -> Vec<f64> {
        let n = self.x.len();
        let mut f = Vec::with_capacity(n + 1);
        f.push(self.x[0]);
        for i in 1..n {
            f.push(0.5 * (self.x[i - 1] + self.x[i]));
        }
        f.push(self.x[n - 1]);
        f
    }

    /// True when all spacings are equal to within 10⁻⁹ relative.
    pub fn is_uniform(&self) -> bool {
        let n = self.x.len();
        let d = (self.x[n - 1] - self.x[0]) / (n - 1) as f64;
        self.x
            .windows(2)
            .all(|w| ((w[1] - w[0]) - d).abs() <= 1e-9 * d.abs())
    }

    /// Trapezoidal integral of nodal values.
    pub fn integrate(&self, v: &[f64]) -> f64 {
        self.x
            .windows(2)
            .zip(v.windows(2))
            .map(|(x, y)| 0.5 * (x[1] - x[0]) * (y[0] + y[1]))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clustered_grid_hits_ends_and_spacing() {
        let g = Grid1d::clustered(-100.0, 5.0, 801, 0.0, 0.01).unwrap();
        assert_eq!(g.x[0], -100.0);
        assert_eq!(g.x[800], 5.0);
        assert!(g.x.windows(2).all(|w| w[1] > w[0]));
        let k = g.x.iter().position(|&v| v >= 0.0).unwrap();
        let h = g.x[k] - g.x[k - 1];
        assert!((h - 0.01).abs() < 0.002, "{h}");
        let w: f64 = g.cell_widths().iter().sum();
        assert!((w - 105.0).abs() < 1e-9);
    }
}
