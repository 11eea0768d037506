//! Boussinesq / modified-Hartnett normal contact-pressure solver (seed 004, SPEC §2.5).
//!
//! Two elastic half-spaces with an arbitrary initial gap `K(x, y)` (roller profile drop,
//! transverse curvature `y²/2R'`, skew term, … — built by the caller) are pressed together.
//! The candidate contact region is a structured [`Grid`] of `nx × ny` rectangular cells with
//! uniform pressure per cell (seed 004 eq. (4)); the surface displacement is
//! `u_i = Σ_j f_ij p_j` with the exact rectangular-cell influence coefficients of
//! seed 004 eq. (5) ([`influence`]).
//!
//! * [`influence`] — coefficients `f(x̄, ȳ)` (Love 1929, seed 004-5, flag F-07) and the
//!   `(2nx−1)×(2ny−1)` kernel table.
//! * [`convolution`] — exact, non-periodic FFT evaluation of `u = f * p` (zero padded), with
//!   a direct reference sum.
//! * [`solver`] — Polonsky & Keer (1999) constrained conjugate gradient, approach- and
//!   force-controlled ([`BoussinesqSolver`], [`BoussinesqOptions`], [`ContactSolution`]).
//! * [`dense`] — dense reference implementation of seed 004 Algorithms A and B (for tests).
//!
//! # Conventions (SI units everywhere: m, N, Pa)
//! * `x` runs along the roller axis (contact line), `y` in the rolling direction.
//! * Fields on the grid are stored **row-major with `x` fastest**: cell `(i, j)` (`i < nx`
//!   along `x`, `j < ny` along `y`) is at index `j * nx + i` ([`Grid::index`]).
//! * Gap: `g = K − α + u(p)`, with `K` the initial separation at the cell centres (may be
//!   negative), `α` the rigid approach, `u ≥ 0` the combined elastic displacement. Contact
//!   conditions (seed 004 (1)–(3)): `p ≥ 0`, `g ≥ 0`, `p·g = 0`.

pub mod convolution;
pub mod dense;
pub mod influence;
pub mod solver;

pub use convolution::{ConvolutionMode, Convolver, direct_convolution};
pub use influence::{InfluenceTable, combined_compliance, influence_coefficient};
pub use solver::{BoussinesqOptions, BoussinesqSolver, ContactSolution, StopRule};

use std::fmt;

/// Errors of the Boussinesq solver (invalid input or numerical breakdown).
///
/// A solve that merely fails to reach the tolerance is *not* an error: it returns a
/// [`ContactSolution`] with `converged == false`.
#[derive(Debug, Clone, PartialEq)]
pub enum BoussinesqError {
    /// Grid with zero cells or non-positive / non-finite cell size or origin.
    InvalidGrid(String),
    /// Combined compliance not finite and positive.
    InvalidCompliance(f64),
    /// A field has the wrong length (expected, got).
    LengthMismatch { expected: usize, got: usize },
    /// Non-finite entry in the gap (index of the first offending cell).
    NonFiniteGap(usize),
    /// Force or approach not finite (or negative force).
    InvalidLoad(f64),
    /// Invalid solver option.
    InvalidOption(String),
    /// NaN / infinity appeared during the iteration (should not happen for valid input).
    NumericalBreakdown { iteration: usize },
}

impl fmt::Display for BoussinesqError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidGrid(s) => write!(f, "invalid Boussinesq grid: {s}"),
            Self::InvalidCompliance(c) => write!(f, "invalid combined compliance {c} 1/Pa"),
            Self::LengthMismatch { expected, got } => {
                write!(
                    f,
                    "field length {got} does not match the grid ({expected} cells)"
                )
            }
            Self::NonFiniteGap(i) => write!(f, "non-finite initial gap at cell {i}"),
            Self::InvalidLoad(v) => write!(f, "invalid load or approach {v}"),
            Self::InvalidOption(s) => write!(f, "invalid Boussinesq option: {s}"),
            Self::NumericalBreakdown { iteration } => {
                write!(
                    f,
                    "numerical breakdown (non-finite value) at iteration {iteration}"
                )
            }
        }
    }
}

impl std::error::Error for BoussinesqError {}

/// Structured grid of `nx × ny` rectangular cells of size `dx × dy` (SPEC §2.5 "Discretisation").
///
/// Cell `(i, j)` has its centre at `(x_min + (i + ½)dx, y_min + (j + ½)dy)` and is stored at
/// index `j * nx + i` (x fastest). `dx = 2b`, `dy = 2a` in the notation of seed 004 eq. (5)
/// (flag F-07).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Cells along `x` (roller axis).
    pub nx: usize,
    /// Cells along `y` (rolling direction).
    pub ny: usize,
    /// Cell size along `x`, m.
    pub dx: f64,
    /// Cell size along `y`, m.
    pub dy: f64,
    /// Lower `x` edge of the grid, m.
    pub x_min: f64,
    /// Lower `y` edge of the grid, m.
    pub y_min: f64,
}

impl Grid {
    /// General grid with lower-left corner `(x_min, y_min)`.
    pub fn new(
        nx: usize,
        ny: usize,
        dx: f64,
        dy: f64,
        x_min: f64,
        y_min: f64,
    ) -> Result<Self, BoussinesqError> {
        if nx == 0 || ny == 0 {
            return Err(BoussinesqError::InvalidGrid(format!("{nx} x {ny} cells")));
        }
        if !(dx.is_finite() && dx > 0.0 && dy.is_finite() && dy > 0.0) {
            return Err(BoussinesqError::InvalidGrid(format!(
                "cell size {dx} x {dy} m"
            )));
        }
        if !(x_min.is_finite() && y_min.is_finite()) {
            return Err(BoussinesqError::InvalidGrid(format!(
                "origin ({x_min}, {y_min}) m"
            )));
        }
        Ok(Self {
            nx,
            ny,
            dx,
            dy,
            x_min,
            y_min,
        })
    }

    /// Grid of `nx × ny` cells of size `dx × dy` centred on the origin.
    pub fn centered(nx: usize, ny: usize, dx: f64, dy: f64) -> Result<Self, BoussinesqError> {
        Self::new(nx, ny, dx, dy, -0.5 * nx as f64 * dx, -0.5 * ny as f64 * dy)
    }

    /// Grid of `nx × ny` cells covering `[−lx/2, lx/2] × [−ly/2, ly/2]`.
    pub fn centered_extent(
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
    ) -> Result<Self, BoussinesqError> {
        if nx == 0 || ny == 0 {
            return Err(BoussinesqError::InvalidGrid(format!("{nx} x {ny} cells")));
        }
        Self::centered(nx, ny, lx / nx as f64, ly / ny as f64)
    }

    /// Number of cells `nx · ny`.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Always false for a valid grid.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Storage index of cell `(i, j)`: `j * nx + i` (x fastest).
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> usize {
        j * self.nx + i
    }

    /// `x` coordinate of the centre of column `i`, m.
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        self.x_min + (i as f64 + 0.5) * self.dx
    }

    /// `y` coordinate of the centre of row `j`, m.
    #[inline]
    pub fn y(&self, j: usize) -> f64 {
        self.y_min + (j as f64 + 0.5) * self.dy
    }

    /// Cell area `ΔS = dx·dy`, m² (seed 004 eq. (6)).
    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// Row `j` whose centre is nearest to `y = 0` (the central contact line; the lower one on
    /// a tie, e.g. for an even `ny` on a centred grid).
    pub fn central_row(&self) -> usize {
        nearest(self.ny, |j| self.y(j))
    }

    /// Column `i` whose centre is nearest to `x = 0` (middle of the contact line; lower on a tie).
    pub fn central_column(&self) -> usize {
        nearest(self.nx, |i| self.x(i))
    }

    /// Evaluate `f(x, y)` at every cell centre (e.g. the initial gap `K(x, y)`), in storage order.
    pub fn eval<F: Fn(f64, f64) -> f64>(&self, f: F) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.len());
        for j in 0..self.ny {
            let y = self.y(j);
            for i in 0..self.nx {
                out.push(f(self.x(i), y));
            }
        }
        out
    }
}

fn nearest(n: usize, coord: impl Fn(usize) -> f64) -> usize {
    let mut best = 0;
    for k in 1..n {
        if coord(k).abs() < coord(best).abs() {
            best = k;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_layout() {
        let g = Grid::centered(4, 3, 1.0, 2.0).unwrap();
        assert_eq!(g.index(1, 2), 9);
        assert_eq!(g.x(0), -1.5);
        assert_eq!(g.y(1), 0.0);
        assert_eq!(g.central_row(), 1);
        assert_eq!(g.central_column(), 1);
        let v = g.eval(|x, y| x + 10.0 * y);
        assert_eq!(v[g.index(3, 0)], 1.5 - 20.0);
        assert!(Grid::centered(0, 3, 1.0, 1.0).is_err());
        assert!(Grid::centered(2, 3, -1.0, 1.0).is_err());
    }
}
