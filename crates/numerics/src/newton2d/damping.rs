//! Scales `D` of the Levenberg–Marquardt term `λ D` of [`super::solve_2d`].

/// How the damping term `λ diag(D₁, D₂)` is scaled to the Jacobian `J`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Damping {
    /// Marquardt: `D_i = max(J_ii, relative_floor · tr J)`; suits a symmetric positive
    /// semi-definite `J` (a Hessian) whose diagonal entries differ widely.
    Diagonal {
        /// Floor of `D_i` relative to `tr J`.
        relative_floor: f64,
    },
    /// Levenberg on the trace: `D₁ = D₂ = max(tr J, floor)`; a direction without stiffness
    /// still gets a finite damped step.
    Trace {
        /// Absolute floor of `D_i`, in the units of `J`.
        floor: f64,
    },
}

impl Damping {
    /// `(D₁, D₂)` for the Jacobian `j`.
    pub fn scales(&self, j: [[f64; 2]; 2]) -> [f64; 2] {
        let trace = j[0][0] + j[1][1];
        match *self {
            Self::Diagonal { relative_floor } => {
                let floor = relative_floor * trace;
                [j[0][0].max(floor), j[1][1].max(floor)]
            }
            Self::Trace { floor } => {
                let d = trace.max(floor);
                [d, d]
            }
        }
    }
}
