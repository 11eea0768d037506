//! The integrator of a [`crate::Simulation`]: either method of [`crate::IntegratorMethod`]
//! behind one interface, with its checkpoint serialisation.

use crate::checkpoint::{Reader, Writer};
use crate::error::DynError;
use crate::integrator::{Dopri5, OdeSystem, StepError, StepStats};
use crate::rosenbrock::RosenbrockW;
use crate::settings::IntegratorSettings;

/// One stepper per simulation, so the size difference of the variants costs nothing worth a box.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub(crate) enum Stepper {
    Dopri5(Dopri5),
    RosenbrockW(RosenbrockW),
}

impl Stepper {
    #[inline]
    pub fn t(&self) -> f64 {
        match self {
            Self::Dopri5(i) => i.t,
            Self::RosenbrockW(i) => i.t,
        }
    }
    #[inline]
    pub fn y(&self) -> &[f64] {
        match self {
            Self::Dopri5(i) => &i.y,
            Self::RosenbrockW(i) => &i.y,
        }
    }
    pub fn stats(&self) -> &StepStats {
        match self {
            Self::Dopri5(i) => &i.stats,
            Self::RosenbrockW(i) => &i.stats,
        }
    }
    pub fn stats_mut(&mut self) -> &mut StepStats {
        match self {
            Self::Dopri5(i) => &mut i.stats,
            Self::RosenbrockW(i) => &mut i.stats,
        }
    }
    /// Dense output of a step is available.
    pub fn has_dense(&self) -> bool {
        match self {
            Self::Dopri5(i) => i.dense_h > 0.0,
            Self::RosenbrockW(i) => i.dense_h > 0.0,
        }
    }
    pub fn dense_start(&self) -> f64 {
        match self {
            Self::Dopri5(i) => i.dense_start(),
            Self::RosenbrockW(i) => i.dense_start(),
        }
    }
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        match self {
            Self::Dopri5(i) => i.interpolate(t, out),
            Self::RosenbrockW(i) => i.interpolate(t, out),
        }
    }
    /// The system changed: re-evaluate `f(t, y)` (and the Jacobian) before the next step.
    pub fn invalidate(&mut self) {
        match self {
            Self::Dopri5(i) => i.k1_valid = false,
            Self::RosenbrockW(i) => i.invalidate(),
        }
    }
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        set: &IntegratorSettings,
    ) -> Result<(), StepError> {
        match self {
            Self::Dopri5(i) => i.step(sys, set),
            Self::RosenbrockW(i) => i.step(sys, set),
        }
    }

    /// Appends the integrator state (method tag first).
    pub fn save(&self, w: &mut Writer) {
        let stats = self.stats();
        match self {
            Self::Dopri5(ig) => {
                w.u64(0);
                w.f64(ig.t);
                w.f64(ig.h);
                w.f64(ig.err_old);
                w.u64(u64::from(ig.last_rejected));
                w.u64(u64::from(ig.k1_valid));
                w.slice(&ig.y);
                w.slice(&ig.k[0]);
                w.f64(ig.dense_t);
                w.f64(ig.dense_h);
                for d in ig.dense_parts() {
                    w.slice(d);
                }
            }
            Self::RosenbrockW(ig) => {
                w.u64(1);
                w.f64(ig.t);
                w.f64(ig.h);
                w.f64(ig.err_old);
                w.f64(ig.h_prev);
                w.u64(u64::from(ig.last_rejected));
                w.u64(u64::from(ig.f0_valid));
                w.slice(&ig.y);
                w.slice(&ig.f0);
                w.f64(ig.dense_t);
                w.f64(ig.dense_h);
                w.slice(&ig.dense_y0);
                w.slice(&ig.dense_f0);
                w.u64(u64::from(ig.jac_valid));
                w.u64(ig.jac_age);
                w.f64(ig.factor_step());
                w.slice(&ig.jac);
                if let Some(bd) = &ig.border {
                    w.slice(&bd.jac_rows);
                    w.slice(&bd.jac_cols);
                    w.u64(u64::from(bd.shares0_valid));
                    w.slice(&bd.shares0);
                }
            }
        }
        w.u64(stats.accepted);
        w.u64(stats.rejected);
        w.u64(stats.rhs_evaluations);
        w.u64(stats.jacobian_evaluations);
        w.u64(stats.limiting.len() as u64);
        for &c in &stats.limiting {
            w.u64(c);
        }
    }

    /// Reads the state written by [`Stepper::save`] into a copy of `self` (same method and
    /// dimension) and returns it.
    pub fn load(&self, r: &mut Reader) -> Result<Self, DynError> {
        let tag = r.u64()?;
        let mut out = self.clone();
        let stats = match (&mut out, tag) {
            (Self::Dopri5(ig), 0) => {
                ig.t = r.f64()?;
                ig.h = r.f64()?;
                ig.err_old = r.f64()?;
                ig.last_rejected = r.u64()? != 0;
                ig.k1_valid = r.u64()? != 0;
                r.slice_into(&mut ig.y)?;
                r.slice_into(&mut ig.k[0])?;
                ig.dense_t = r.f64()?;
                ig.dense_h = r.f64()?;
                for d in ig.dense_parts_mut().iter_mut() {
                    r.slice_into(d)?;
                }
                &mut ig.stats
            }
            (Self::RosenbrockW(ig), 1) => {
                ig.t = r.f64()?;
                ig.h = r.f64()?;
                ig.err_old = r.f64()?;
                ig.h_prev = r.f64()?;
                ig.last_rejected = r.u64()? != 0;
                ig.f0_valid = r.u64()? != 0;
                r.slice_into(&mut ig.y)?;
                r.slice_into(&mut ig.f0)?;
                ig.dense_t = r.f64()?;
                ig.dense_h = r.f64()?;
                r.slice_into(&mut ig.dense_y0)?;
                r.slice_into(&mut ig.dense_f0)?;
                ig.jac_valid = r.u64()? != 0;
                ig.jac_age = r.u64()?;
                let factor_step = r.f64()?;
                r.slice_into(&mut ig.jac)?;
                if let Some(bd) = &mut ig.border {
                    r.slice_into(&mut bd.jac_rows)?;
                    r.slice_into(&mut bd.jac_cols)?;
                    bd.shares0_valid = r.u64()? != 0;
                    r.slice_into(&mut bd.shares0)?;
                }
                ig.after_restore(factor_step);
                &mut ig.stats
            }
            _ => {
                return Err(DynError::Checkpoint(
                    "the checkpoint was written with another integrator method".into(),
                ));
            }
        };
        stats.accepted = r.u64()?;
        stats.rejected = r.u64()?;
        stats.rhs_evaluations = r.u64()?;
        stats.jacobian_evaluations = r.u64()?;
        let n = r.u64()? as usize;
        if n != stats.limiting.len() {
            return Err(DynError::Checkpoint("state dimension differs".into()));
        }
        for c in stats.limiting.iter_mut() {
            *c = r.u64()?;
        }
        Ok(out)
    }
}
